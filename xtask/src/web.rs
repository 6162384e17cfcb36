//! The browser build: one WebAssembly program with every chapter in it
//! (`course`'s `live`), bound to JavaScript by `wasm-bindgen` (as a
//! library, the same version the chapters link), and a page per chapter
//! under the book's `live/`;
//! a static server on 127.0.0.1 for reading it (WebGPU needs a secure
//! context, and localhost is one); and headless Chromium to test it.

use std::io::Read as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context as _, bail, ensure};

use crate::{cargo, chapter_names, root, target_dir};

const WASM_TARGET: &str = "wasm32-unknown-unknown";
/// How the browser program is compiled (the profiles are in the workspace
/// Cargo.toml).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    /// As the book is published: small downloads first (`web`: fat LTO,
    /// one codegen unit, `opt-level = "z"`). `cargo xtask book` and the
    /// browser bench.
    Published,
    /// For `cargo xtask test`: the same program without link-time
    /// optimisation (`web-test`), which took most of the browser build's
    /// time and changes what the pages download, not what they do.
    Test,
}

impl Profile {
    fn name(self) -> &'static str {
        match self {
            Profile::Published => "web",
            Profile::Test => "web-test",
        }
    }
}

/// Rust's WebAssembly target, installed with rustup when it is missing (as
/// the Vulkan driver is installed for the tests), or the command to run.
fn ensure_wasm_target() -> anyhow::Result<()> {
    let installed = Command::new("rustup").args(["target", "list", "--installed"]).output();
    let Ok(installed) = installed else {
        bail!(
            "building the chapters for the browser needs Rust's {WASM_TARGET} target, and rustup is not here to \
             install it; install it the way your Rust came (https://rustup.rs)"
        );
    };
    if String::from_utf8_lossy(&installed.stdout).lines().any(|l| l.trim() == WASM_TARGET) {
        return Ok(());
    }
    println!("the browser build needs the {WASM_TARGET} target: installing\n$ rustup target add {WASM_TARGET}");
    let status = Command::new("rustup").args(["target", "add", WASM_TARGET]).status()?;
    ensure!(status.success(), "installing failed; run: rustup target add {WASM_TARGET}");
    Ok(())
}

/// Compiles the book's one browser program (`course`'s `live`: every
/// chapter) and writes `live/` under `out`: the program and its script
/// once, and a page per chapter, `live/<chapter>/index.html`, that loads
/// them and names its chapter.
pub fn build(out: &Path, profile: Profile) -> anyhow::Result<()> {
    ensure_wasm_target()?;
    let chapters = chapter_names()?;
    cargo(&[
        "build",
        "--quiet",
        "--target",
        WASM_TARGET,
        "--profile",
        profile.name(),
        "-p",
        "course",
        "--bin",
        PROGRAM,
        "--features",
        "live",
    ])?;
    let live = out.join("live");
    if live.exists() {
        std::fs::remove_dir_all(&live)?;
    }
    std::fs::create_dir_all(&live)?;
    let wasm = target_dir().join(WASM_TARGET).join(profile.name()).join(format!("{PROGRAM}.wasm"));
    wasm_bindgen_cli_support::Bindgen::new()
        .input_path(&wasm)
        .out_name(PROGRAM)
        .web(true)
        .map_err(|e| anyhow::anyhow!("{e:#}"))?
        .typescript(false)
        .remove_name_section(true)
        .remove_producers_section(true)
        .generate(&live)
        .map_err(|e| anyhow::anyhow!("wasm-bindgen on {}: {e:#}", wasm.display()))?;
    for chapter in &chapters {
        let dir = live.join(chapter);
        std::fs::create_dir_all(&dir)?;
        // The picture behind the page's button must be in the book: a page
        // would show a dark box without it, and no test would notice.
        let picture = readme_picture(chapter).with_context(|| format!("README.md shows no picture of {chapter}"))?;
        let figure = root().join("tests/snapshots").join(chapter).join(&picture);
        ensure!(figure.exists(), "{chapter}'s page would show {}, which does not exist", figure.display());
        std::fs::write(dir.join("index.html"), page(chapter, &picture))?;
    }
    println!("browser build: {} chapters' pages and one program in {}", chapters.len(), live.display());
    Ok(())
}

/// The browser program's name: `live/live.js` and `live/live_bg.wasm`.
const PROGRAM: &str = "live";

/// The program every page loads, as served.
pub fn program_wasm(html: &Path) -> PathBuf {
    html.join("live").join(format!("{PROGRAM}_bg.wasm"))
}

/// A chapter's page. Opened on its own it starts at once; inside the book's
/// iframe it waits for a click, so that reading a page never starts GPU
/// work unasked (and the book's arrow keys stay the book's until then).
fn page(chapter: &str, picture: &str) -> String {
    // The chapter's picture behind the button, dimmed, before anyone clicks.
    let poster = format!(
        "body.waiting {{ background: linear-gradient(#15171cb0, #15171cb0), url(../../figures/{chapter}/{picture}) \
         center / cover no-repeat #15171c; }}"
    );
    PAGE.replace("{poster}", &poster).replace("{chapter}", chapter)
}

/// The picture of `chapter` the README shows (its snapshot, which the book
/// copies into `figures/`): the README's table is written from the course's
/// records, so the choice is made once, there.
fn readme_picture(chapter: &str) -> Option<String> {
    let readme = std::fs::read_to_string(root().join("README.md")).ok()?;
    let start = format!("tests/snapshots/{chapter}/");
    let after = &readme[readme.find(&start)? + start.len()..];
    Some(after[..after.find(".png")? + 4].to_string())
}

const PAGE: &str = r#"<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{chapter} — From Triangle to Ocean</title>
<link rel="icon" href="data:,">
<style>
  html, body { margin: 0; height: 100%; overflow: hidden; background: #15171c; color: #d8dbe2;
               font: 15px/1.4 system-ui, sans-serif; }
  canvas#chapter { display: block; width: 100%; height: 100%; outline: none; touch-action: none; }
  #message { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
             text-align: center; padding: 2em; white-space: pre-wrap; }
  #message.hidden { display: none; }
  #message.error { background: #15171ce8; color: #ffb4a6; font-family: ui-monospace, monospace; font-size: 13px; }
  button { font: inherit; font-size: 1.15em; padding: 0.6em 1.4em; border-radius: 6px; border: 1px solid #8894a8;
           background: #262a33; color: inherit; cursor: pointer; }
  {poster}
  #edited { position: absolute; left: 0; right: 0; bottom: 0; padding: 0.35em 0.8em; background: #3a2a10e8;
            color: #ffd9a0; font-size: 13px; }
  #edited button { font-size: 13px; padding: 0.15em 0.7em; margin-left: 0.6em; }
</style>
</head>
<body data-chapter="{chapter}">
<canvas id="chapter" tabindex="0"></canvas>
<div id="message">loading {chapter}…</div>
<div id="edited" hidden>This page runs a changed shader: <span></span><button type="button">show the original</button></div>
<script type="module">
  import init from "../live.js";
  const message = document.getElementById("message");
  // The chapter reports through data-status: starting, running, picture or error.
  new MutationObserver(() => {
    const status = document.body.dataset.status;
    if (status === "running" || status === "picture") message.className = "hidden";
  }).observe(document.body, { attributes: true, attributeFilter: ["data-status"] });

  // Shader edits: the program keeps the reader's in the page's storage, one
  // key per file (`shader-edit:CHAPTER:PATH`); a link carries them in its
  // fragment, `#edits=`, as deflated JSON in URL-safe base64.
  const prefix = "shader-edit:{chapter}:";
  const editKeys = () => Object.keys(localStorage).filter(key => key.startsWith(prefix));
  const toBase64 = bytes => btoa(String.fromCharCode(...bytes)).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
  const fromBase64 = text => Uint8Array.from(atob(text.replace(/-/g, "+").replace(/_/g, "/")), c => c.charCodeAt(0));
  const through = async (bytes, stream) => new Uint8Array(await new Response(new Blob([bytes]).stream().pipeThrough(stream)).arrayBuffer());
  // A shared link's edits replace the reader's own before the program starts.
  async function takeLinkEdits() {
    const found = location.hash.match(/^#edits=([A-Za-z0-9_-]+)$/);
    if (!found) return;
    try {
      const json = new TextDecoder().decode(await through(fromBase64(found[1]), new DecompressionStream("deflate-raw")));
      const edits = JSON.parse(json);
      editKeys().forEach(key => localStorage.removeItem(key));
      for (const [path, text] of Object.entries(edits)) localStorage.setItem(prefix + path, text);
    } catch (error) {
      message.textContent = `this link's shader edits could not be read (${error}); showing the original`;
    }
  }
  // Called by the shader panel's "share" button.
  window.shareShaderEdits = async () => {
    const edits = Object.fromEntries(editKeys().map(key => [key.slice(prefix.length), localStorage.getItem(key)]));
    const packed = await through(new TextEncoder().encode(JSON.stringify(edits)), new CompressionStream("deflate-raw"));
    history.replaceState(null, "", `${location.pathname}${location.search}#edits=${toBase64(packed)}`);
    document.body.dataset.shareUrl = location.href;
    navigator.clipboard?.writeText(location.href).catch(() => {});
  };
  // The banner names the changed files while there are any.
  const banner = document.getElementById("edited");
  new MutationObserver(() => {
    const edited = document.body.dataset.edited || "";
    banner.hidden = edited === "";
    banner.querySelector("span").textContent = edited;
  }).observe(document.body, { attributes: true, attributeFilter: ["data-edited"] });
  banner.querySelector("button").addEventListener("click", () => {
    editKeys().forEach(key => localStorage.removeItem(key));
    location.replace(`${location.pathname}${location.search}`);
  });

  async function start() {
    document.body.classList.remove("waiting");
    message.className = "";
    message.textContent = "starting {chapter}…";
    try {
      await takeLinkEdits();
      await init({ module_or_path: "../live_bg.wasm" });
      document.getElementById("chapter").focus();
    } catch (error) {
      // A panic has already put its own message in the page.
      if (document.body.dataset.status !== "error") {
        message.className = "error";
        message.textContent = `the chapter could not start: ${error}`;
        document.body.dataset.status = "error";
      }
      console.error(error);
    }
  }
  const embedded = window.self !== window.top;
  if (embedded) {
    document.body.classList.add("waiting");
    message.innerHTML = '<button type="button">▶ click to run {chapter}</button>';
    message.querySelector("button").addEventListener("click", start, { once: true });
  } else {
    start();
  }
</script>
</body>
</html>
"#;

/// Serves `dir` on 127.0.0.1 from a thread; returns the port. Files only,
/// with the content types browsers insist on (`application/wasm` for
/// streaming compilation).
pub fn serve_in_background(dir: &Path, port: u16) -> anyhow::Result<u16> {
    let server = tiny_http::Server::http(("127.0.0.1", port))
        .map_err(|e| anyhow::anyhow!("cannot serve on 127.0.0.1:{port}: {e}"))?;
    let port = server.server_addr().to_ip().map_or(port, |a| a.port());
    let dir = dir.to_path_buf();
    std::thread::spawn(move || {
        for request in server.incoming_requests() {
            // A thread each: a response the browser stops reading (a
            // lazy frame's program, a page closed mid-way) must not hold
            // up the requests behind it.
            let dir = dir.clone();
            std::thread::spawn(move || respond(&dir, request));
        }
    });
    Ok(port)
}

fn respond(dir: &Path, request: tiny_http::Request) -> std::io::Result<()> {
    let path = request.url().split(['?', '#']).next().unwrap_or("/").to_string();
    let relative = path.trim_start_matches('/');
    // No climbing out of the served folder.
    let mut file = dir.to_path_buf();
    for part in relative.split('/').filter(|p| !p.is_empty()) {
        if part == ".." {
            return request.respond(tiny_http::Response::empty(403));
        }
        file.push(part);
    }
    if file.is_dir() {
        file.push("index.html");
    }
    let Ok(bytes) = std::fs::read(&file) else {
        return request.respond(tiny_http::Response::from_string("not found").with_status_code(404));
    };
    let content_type = match file.extension().and_then(|e| e.to_str()).unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "wasm" => "application/wasm",
        "css" => "text/css; charset=utf-8",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "json" => "application/json",
        "woff2" => "font/woff2",
        "woff" => "font/woff",
        "ttf" => "font/ttf",
        "ico" => "image/x-icon",
        _ => "application/octet-stream",
    };
    let header = tiny_http::Header::from_bytes("Content-Type", content_type).expect("a valid header");
    // As GitHub Pages serves: a page opened next finds the program cached.
    let cache = tiny_http::Header::from_bytes("Cache-Control", "max-age=600").expect("a valid header");
    request.respond(tiny_http::Response::from_data(bytes).with_header(header).with_header(cache))
}

/// `cargo xtask serve [PORT]`: the built book on http://127.0.0.1:PORT/.
pub fn serve(args: &[String]) -> anyhow::Result<()> {
    let port = match args.first() {
        Some(text) => {
            text.parse().with_context(|| format!("the port must be a number from 1 to 65535, not '{text}'"))?
        }
        None => 3000,
    };
    let html = root().join("book/book");
    ensure!(html.join("live").is_dir(), "{} has no live chapters yet: run `cargo xtask book` first", html.display());
    let port = serve_in_background(&html, port)?;
    println!("serving {} on http://127.0.0.1:{port}/ (Ctrl-C stops)", html.display());
    loop {
        std::thread::park();
    }
}

/// The Chromium the browser test drives: `CHROMIUM`, or Debian's.
pub fn chromium() -> Option<PathBuf> {
    let given = std::env::var_os("CHROMIUM").map(PathBuf::from);
    given.into_iter().chain(["/usr/bin/chromium", "/usr/bin/chromium-browser"].map(PathBuf::from)).find(|p| p.exists())
}

/// [`chromium`], or Debian's installed as the Vulkan driver is, or the
/// command to run.
pub fn ensure_chromium() -> anyhow::Result<PathBuf> {
    if let Some(path) = chromium() {
        return Ok(path);
    }
    crate::prerequisites::apt_install("the browser test needs Chromium", &["chromium"])?;
    chromium().context("installed chromium but /usr/bin/chromium is missing")
}

/// Bytes of `path`, and of it compressed by gzip at the level static hosts use.
pub fn sizes(path: &Path) -> anyhow::Result<(u64, u64)> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut gz = flate2::read::GzEncoder::new(&bytes[..], flate2::Compression::new(9));
    let mut compressed = Vec::new();
    gz.read_to_end(&mut compressed)?;
    Ok((bytes.len() as u64, compressed.len() as u64))
}

/// The browser test (the `browser` package) on the built book, served
/// on a free port of 127.0.0.1 for as long as it runs.
pub fn browser_test(chapters: &[String]) -> anyhow::Result<()> {
    let chromium = ensure_chromium()?;
    let html = root().join("book/book");
    ensure!(html.join("live").is_dir(), "{} has no live chapters: run `cargo xtask book` first", html.display());
    let port = serve_in_background(&html, 0)?;
    let url = format!("http://127.0.0.1:{port}");
    let mut args = vec![url.as_str()];
    args.extend(chapters.iter().map(String::as_str));
    run_browser_bin(&args, &chromium)
}

/// Runs the browser test's binary with `args`. It is built as part of the
/// workspace's binaries, as the window test builds them: built alone
/// (`cargo run -p browser`), cargo would pick other features for the
/// crates it shares with the rest and compile headless_chrome and its
/// protocol code a second time (70 s of a cold `cargo xtask test`).
fn run_browser_bin(args: &[&str], chromium: &Path) -> anyhow::Result<()> {
    cargo(&["build", "--quiet", "--workspace", "--exclude", "xtask", "--bins"])?;
    let binary = target_dir().join("debug").join("browser");
    println!("\n$ {} {}", binary.display(), args.join(" "));
    let status = Command::new(&binary)
        .args(args)
        .current_dir(root())
        .env("CHROMIUM", chromium)
        .status()
        .with_context(|| format!("cannot run {}", binary.display()))?;
    ensure!(status.success(), "the browser test failed");
    Ok(())
}

// ANCHOR: bench
/// `cargo xtask bench web`: for every chapter of the built book, its wasm's
/// size (raw and gzip), the time from opening its page in headless
/// Chromium to its first frame, its live frame time there, the native
/// release build's frame time at the same size on the same machine, and
/// whether it renders on WebGL2. Written to `book/src/bench/web.md`.
pub fn bench(tabulate_only: bool) -> anyhow::Result<()> {
    crate::prerequisites::ensure_adapter()?;
    let chromium = ensure_chromium()?;
    let html = root().join("book/book");
    ensure!(html.join("live").is_dir(), "{} has no live chapters: run `cargo xtask book` first", html.display());
    // The pages as published: `cargo xtask test` leaves its own build there.
    build(&html, Profile::Published)?;
    let chapters = chapter_names()?;
    let port = serve_in_background(&html, 0)?;
    let url = format!("http://127.0.0.1:{port}");
    let rows_file = target_dir().join("bench-web.tsv");
    let rows_path = rows_file.display().to_string();
    // `--tabulate`: write the page again from the last run's browser figures.
    if !tabulate_only {
        run_browser_bin(&[&url, "--bench", &rows_path], &chromium)?;
    }
    let rows = std::fs::read_to_string(&rows_file)?;
    let mut build = vec!["build", "--quiet", "--release"];
    for chapter in &chapters {
        build.extend(["-p", chapter.as_str()]);
    }
    cargo(&build)?;

    let mut table = String::from(
        "| chapter | page to first frame | longest task | frame in Chromium | native frame | a shader edit to its frame | WebGL2 |\n\
         |---|---:|---:|---:|---:|---:|---|\n",
    );
    let mut adapter = String::new();
    let mut edits = String::from(
        "| chapter | file edited | on the desktop (lavapipe) | in Chromium (SwiftShader) |\n|---|---|---:|---:|\n",
    );
    for row in rows.lines() {
        let fields: Vec<&str> = row.split('\t').collect();
        let [chapter, first_ms, longest_task_ms, frame_ms, surface, webgl2, browser_adapter, edited, edit_ms] =
            fields[..]
        else {
            bail!("unexpected bench row: {row}");
        };
        adapter = browser_adapter.to_string();
        let native = native_frame_ms(chapter, surface)?;
        let (native_file, native_edit) = native_edit_ms(chapter)?;
        ensure!(native_file == edited, "{chapter}: the desktop edited {native_file}, the page {edited}");
        edits.push_str(&format!("| {chapter} | `{edited}` | {native_edit} ms | {edit_ms} ms |\n"));
        let webgl2 = webgl2_cell(webgl2);
        table.push_str(&format!(
            "| {chapter} | {first_ms} ms | {longest_task_ms} ms | {frame_ms} ms | {native} | {edit_ms} ms (`{edited}`) | {webgl2} |\n"
        ));
    }
    let adapter = adapter.trim();
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find_map(|l| l.strip_prefix("model name").map(|m| m.trim_start_matches([' ', '\t', ':']).to_string()))
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let (raw, gzip) = sizes(&program_wasm(&html))?;
    let (raw, gzip) = (raw as f64 / 1e6, gzip as f64 / 1e6);
    let page = format!(
        "Measured by `cargo xtask bench web` on {cpu} ({} threads), no GPU: the browser is headless Chromium \
         with WebGPU on SwiftShader (wgpu names it `{adapter}`), the native build runs on lavapipe. Every page loads the book's one program, \
         {raw:.2} MB of WebAssembly, {gzip:.2} MB gzipped (as served: `opt-level = \"z\"`, fat LTO, one codegen unit, `panic = \"abort\"`, WebAssembly SIMD, no debug \
         info or symbol names; gzip at level 9). The chapters were opened in book order in one browser, \
         as a reader goes through the book: the first page downloads and compiles the program, the later \
         ones find it in the browser's cache (the test server says it may be kept ten minutes, as GitHub \
         Pages does). \"Page to first frame\" is `performance.now()` at the live runner's first frame; \"longest \
         task\" the longest the page's thread was busy at a stretch before it (by the browser's Long Tasks API, \
         which reports tasks over 50 ms; 0 when there was none): for that long the page neither painted nor \
         answered input. Frame \
         times are the live page's, from the start of one frame to the start of another at least five \
         seconds later, over the frames between (the page keeps one frame in flight, so each was finished \
         on the GPU; its canvas fills the test browser's window), and the native release build's median `--bench` frame at the same size. WebGL2: the first \
         view rendered with `backend=webgl2`, its FLIP mean against the snapshot, or why it failed.\n\n{table}",
        std::thread::available_parallelism().map_or(0, |n| n.get())
    );
    let out = root().join("book/src/bench/web.md");
    std::fs::write(&out, page)?;
    println!("wrote {}", out.display());
    let edits = format!(
        "A shader edit to the first frame drawn with it, median of 5 edits of each chapter's main file (a \
         change built with Ctrl+Enter), on {cpu}: on the desktop by `cargo xtask bench` (release build, \
         headless, until the GPU has finished the frame), in the page by `cargo xtask bench web` (the page's \
         own `data-edit-to-frame-ms`, until the frame is handed to the browser).\n\n{edits}"
    );
    let out = root().join("book/src/bench/edits.md");
    std::fs::write(&out, edits)?;
    println!("wrote {}", out.display());
    Ok(())
}

/// The file and median of `cargo xtask bench`'s shader-edit line for
/// `chapter`, from its table in `book/src/bench/`.
fn native_edit_ms(chapter: &str) -> anyhow::Result<(String, String)> {
    let path = root().join(format!("book/src/bench/{chapter}.md"));
    let text = std::fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
    let line = text
        .lines()
        .find(|l| l.contains("a shader edit to the frame"))
        .with_context(|| format!("{} has no shader-edit line: run `cargo xtask bench {chapter}`", path.display()))?;
    let file = line.split('`').nth(1).context("no file in the shader-edit line")?;
    let median = line.split("median ").nth(1).and_then(|rest| rest.split(' ').next()).context("no median")?;
    Ok((file.to_string(), median.to_string()))
}

/// The native release build's median frame for `chapter`'s first view at
/// `surface` (`WxH`), as `--bench` measures it.
fn native_frame_ms(chapter: &str, surface: &str) -> anyhow::Result<String> {
    let binary = target_dir().join("release").join(chapter);
    let output = Command::new(&binary)
        .args(["--bench", "--frames", "10", "--size", surface, "--view"])
        .arg(first_view(&binary)?)
        .envs(crate::quiet_env())
        .output()
        .with_context(|| format!("cannot run {}", binary.display()))?;
    ensure!(output.status.success(), "{chapter} --bench failed: {}", String::from_utf8_lossy(&output.stderr));
    let text = String::from_utf8(output.stdout)?;
    // | view | frame (CPU+GPU) | min | median | p95 |
    let median = text
        .lines()
        .find(|l| l.contains("frame (CPU+GPU)"))
        .and_then(|l| l.split('|').nth(4))
        .map(|m| m.trim().to_string())
        .context("no frame row in the native bench")?;
    Ok(format!("{median} ms"))
}

/// The browser's WebGL2 verdict, short enough for a table cell: the FLIP
/// figure, or the part of wgpu's error after "Caused by:".
fn webgl2_cell(verdict: &str) -> String {
    let Some(error) = verdict.strip_prefix("fails: ") else { return format!("runs ({verdict})") };
    let cause = error.split_once("Caused by:").map_or(error, |(_, cause)| cause);
    let cause = cause.split("This is not").next().unwrap_or(cause).split_whitespace().collect::<Vec<_>>().join(" ");
    format!("fails: {}", cause.replace('|', "/"))
}

fn first_view(binary: &Path) -> anyhow::Result<String> {
    let output = Command::new(binary).arg("--list-views").output()?;
    let text = String::from_utf8(output.stdout)?;
    text.split_whitespace().next().map(str::to_string).context("the chapter lists no views")
}
// ANCHOR_END: bench
