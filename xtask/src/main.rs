//! `cargo xtask <task>`: the project's maintenance commands.
//!
//! - `test`: everything CI runs: prerequisites, rustfmt, clippy, `cargo test`
//!   (which includes the snapshot tests), every chapter in a window under
//!   Xvfb driven by xdotool, the book, and every chapter's page in headless
//!   Chromium.
//! - `snapshot [CHAPTER[/VIEW]...]`: compare with the reference images;
//!   `snapshot --bless CHAPTER[/VIEW]... --reason "..."`: rewrite the ones
//!   that changed, each recorded in `tests/snapshots/BLESSINGS.md`.
//! - `book`: check snapshots, copy them in as figures, check anchors, build
//!   every chapter for the browser and the HTML, check links.
//! - `serve [PORT]`: the built book on http://127.0.0.1:PORT/.
//! - `browser [CHAPTER...]`: only the browser test, on the built book.
//! - `window [CHAPTER...]`: only the window test.
//! - `bench [CHAPTER...]`: release build, frame times per view, written into the book
//!   (`bench sizes`: every default view at three sizes; `bench web`: in Chromium;
//!   `bench saved RAW OUT`: the tables of a run `xtask/gpu-bench.sh` saved).
//! - `figures [PAGE...]`: check every page's figures against their sources
//!   (the book's build and `test` do too), print PAGE with them written.
//! - `assets`: paint every texture under `assets/` from code (deterministic).

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use anyhow::{Context as _, bail, ensure};

mod assets;
mod bench_tables;
mod book;
mod figures;
mod plan;
mod prerequisites;
mod web;
mod window_test;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("test") => test(),
        Some("snapshot") => snapshot(&args[1..]),
        Some("book") => book::build(true, web::Profile::Published),
        Some("bench") => bench(&args[1..]),
        Some("window") => window_test::run(&args[1..]),
        Some("assets") => assets::generate(),
        Some("figures") => figures::run(&args[1..]),
        Some("serve") => web::serve(&args[1..]),
        Some("web") => web::build(&root().join("book/book"), web::Profile::Published),
        Some("browser") => web::browser_test(&args[1..]),
        Some("help" | "--help" | "-h") | None => {
            print!("{}", USAGE);
            return ExitCode::SUCCESS;
        }
        Some(other) => Err(anyhow::anyhow!(
            "unknown task '{other}'; the tasks are: test, snapshot, book, serve, web, browser, window, bench, figures, assets"
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("xtask: error: {error:#}");
            ExitCode::FAILURE
        }
    }
}

const USAGE: &str = "\
cargo xtask test                           everything CI runs (prerequisites, fmt, clippy, tests, snapshots, book)
cargo xtask snapshot [CHAPTER[/VIEW]..]    compare every view (or these) with its reference
cargo xtask snapshot --bless CHAPTER[/VIEW].. --reason \"..\"
                                           rewrite the references that changed, each logged with the reason
cargo xtask book                           check snapshots, copy figures, build the chapters for the browser and book/book/
cargo xtask serve [PORT]                   serve book/book on http://127.0.0.1:PORT/ (default 3000)
cargo xtask web                            only rebuild the chapters' browser pages, book/book/live/
cargo xtask browser [CHAPTER..]            open every chapter's page in headless Chromium and check it
cargo xtask window [CHAPTER..]             drive every chapter's window under Xvfb with xdotool
cargo xtask bench [CHAPTER..]              release build; frame times at 1280x720 into book/src/bench/
cargo xtask bench web                      wasm sizes, first frames and frame times in Chromium into book/src/bench/web.md
cargo xtask bench sizes                    every default view at 1280x720, 1920x1080, 2560x1440 into book/src/bench/sizes.md
cargo xtask bench saved RAW OUT            tables from what xtask/gpu-bench.sh saved in RAW (no toolchain there) into OUT
cargo xtask figures [PAGE..]               check every page's figures against their sources; print PAGE with them written
cargo xtask assets                         paint every texture under assets/ from code
";

/// The workspace root (xtask lives one folder below it).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("xtask is inside the workspace").to_path_buf()
}

/// Where cargo puts its builds: `CARGO_TARGET_DIR` if set (relative to the
/// workspace root, where xtask runs cargo), else `target/`.
fn target_dir() -> PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(dir) => root().join(dir),
        None => root().join("target"),
    }
}

/// Runs cargo with `args` in the workspace root, echoing the command.
fn cargo(args: &[&str]) -> anyhow::Result<()> {
    println!("\n$ cargo {}", args.join(" "));
    let status = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(args)
        .current_dir(root())
        .envs(quiet_env())
        .status()
        .context("cannot run cargo")?;
    ensure!(status.success(), "`cargo {}` failed", args.join(" "));
    Ok(())
}

/// Mesa's Vulkan driver warns when XDG_RUNTIME_DIR is unset (servers, CI).
fn quiet_env() -> Vec<(String, String)> {
    match std::env::var_os("XDG_RUNTIME_DIR") {
        Some(_) => vec![],
        None => vec![("XDG_RUNTIME_DIR".into(), std::env::temp_dir().display().to_string())],
    }
}

/// `cargo clippy -- -D warnings`, as clippy's driver reads it from the
/// environment (what `cargo clippy` itself passes).
const LINTS_AS_ERRORS: &str = "-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__";

/// The CPU time, in seconds, of every program this process has run and
/// waited for, and theirs (user and system time, from `/proc/self/stat`):
/// what `cargo xtask test`'s steps cost the machine, beside how long they
/// took. A program nobody waits for is not in it: the browser step's
/// Chromium, whose processes outlive the test's own, is missing from its
/// count. `None` where there is no `/proc` (macOS, Windows).
fn children_cpu_seconds() -> Option<f64> {
    cpu_of_waited_children(&std::fs::read_to_string("/proc/self/stat").ok()?)
}

/// The `cutime` and `cstime` fields of a `/proc/PID/stat` line, in seconds:
/// fields 16 and 17, counted after the program's name in parentheses
/// (which may hold spaces and parentheses itself), in the kernel's
/// `USER_HZ` ticks, 100 a second on Linux (proc(5)).
fn cpu_of_waited_children(stat: &str) -> Option<f64> {
    let after_name = &stat[stat.rfind(')')? + 1..];
    let fields: Vec<&str> = after_name.split_whitespace().collect();
    // `after_name` starts at field 3, the state.
    let ticks = |field: usize| fields.get(field - 3)?.parse::<u64>().ok();
    Some((ticks(16)? + ticks(17)?) as f64 / 100.0)
}

fn test() -> anyhow::Result<()> {
    let started = std::time::Instant::now();
    let mut times: Vec<(&str, f64)> = Vec::new();
    let mut step = |name: &'static str, run: &dyn Fn() -> anyhow::Result<()>| -> anyhow::Result<()> {
        let begun = std::time::Instant::now();
        let cpu_before = children_cpu_seconds();
        let result = run();
        times.push((name, begun.elapsed().as_secs_f64()));
        let so_far: Vec<String> = times.iter().map(|(n, s)| format!("{n} {s:.0} s")).collect();
        // What the step cost the machine: on two cores, twice its wall time
        // means both were busy throughout.
        let cpu = match (cpu_before, children_cpu_seconds()) {
            (Some(before), Some(after)) => format!(", {:.0} s of CPU", after - before),
            _ => String::new(),
        };
        println!(
            "\nxtask test: {name} {} after {:.0} s{cpu} ({})",
            if result.is_ok() { "passed" } else { "FAILED" },
            begun.elapsed().as_secs_f64(),
            so_far.join(", ")
        );
        result
    };
    // Lint while building: cargo runs the workspace's own crates through
    // clippy's driver, which lints and then compiles them as rustc would,
    // so the course is compiled once, not checked by `cargo clippy` and
    // then built (its dependencies alone took clippy 145 s of a cold run
    // before the build's 197). Dependencies still go to plain rustc, so
    // their artifacts are the ones `cargo run -p CHAPTER` uses; the
    // course's own crates get their own (the wrapper is part of their
    // hash), and `cargo run` afterwards compiles only those.
    let clippy_driver = prerequisites::clippy_driver()?;
    // SAFETY: no other thread runs yet; every later command inherits these.
    unsafe {
        std::env::set_var("RUSTC_WORKSPACE_WRAPPER", clippy_driver);
        std::env::set_var("CLIPPY_ARGS", LINTS_AS_ERRORS);
    }
    // What this system can run of the steps that need Linux's tools.
    let plan = plan::plan(plan::this_system());
    if matches!(plan.opengl, plan::Decision::Skip(_)) {
        // SAFETY: as above, before any other thread.
        unsafe { std::env::set_var("SNAPSHOTS_SKIP_OPENGL", "1") };
    }
    let runs = |decision: &plan::Decision| !matches!(decision, plan::Decision::Skip(_));
    step("prerequisites", &|| prerequisites::ensure_adapters(&plan))?;
    step("fmt", &|| cargo(&["fmt", "--all", "--", "--check"]))?;
    // One build of everything the later steps run (libraries, the tests,
    // every binary), linted as it compiles: one cargo invocation keeps both
    // cores busy through the links that two invocations would each end
    // with alone. xtask is built alone (`cargo xtask` resolves its features
    // alone); in a workspace-wide build its dependencies (mdbook,
    // wasm-bindgen) would get other features and compile a second time.
    // Every target but benches: `--all-targets` also builds each library
    // and binary a second time as a bench harness (bench = true is cargo's
    // default for both), which nothing runs: 43 s of a cold build's CPU.
    step("build and clippy", &|| {
        cargo(&["build", "--workspace", "--exclude", "xtask", "--lib", "--bins", "--tests", "--examples"])?;
        cargo(&["build", "-p", "xtask", "--bins", "--tests"])
    })?;
    step("cargo test", &|| {
        // Every test executable runs even after one fails, so that a CI
        // log names every failure at once.
        cargo(&["test", "--workspace", "--exclude", "xtask", "--no-fail-fast"])?;
        cargo(&["test", "-p", "xtask"])
    })?;
    step("shared builds", &chapters_reuse_the_test_build)?;
    // The build step built every chapter. (Run side by side with the
    // book's build, both took as long as one after the other: both keep the
    // two cores busy.)
    if runs(&plan.window) {
        step("window", &|| window_test::run_built(&[]))?;
    }
    // `cargo test` has just compared every snapshot; the book only copies them.
    // Its browser program without link-time optimisation (`web::Profile`).
    step("book", &|| book::build(false, web::Profile::Test))?;
    if runs(&plan.browser) {
        step("browser", &|| web::browser_test(&[]))?;
    }
    let cpu = children_cpu_seconds().map_or(String::new(), |cpu| format!(", {cpu:.0} s of CPU"));
    println!("\nxtask test: all checks passed in {:.0} s{cpu}", started.elapsed().as_secs_f64());
    for line in plan.skipped() {
        println!("xtask test: {line}");
    }
    Ok(())
}

/// After the workspace build, `cargo run -p CHAPTER` (the
/// README's first command) must find its dependencies built: a chapter
/// built alone gets the same dependency features as the workspace build
/// (see the list at the end of common's desktop dependencies), or it would
/// rebuild naga, wgpu and egui first. Asks cargo, per chapter and with the
/// test's lint wrapper still set, which of its artifacts are fresh: all
/// must be. (Without the wrapper, only the course's own crates differ.)
fn chapters_reuse_the_test_build() -> anyhow::Result<()> {
    for chapter in chapter_names()? {
        let output = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
            .args(["build", "--quiet", "--message-format=json", "-p", &chapter])
            .current_dir(root())
            .output()
            .context("cannot run cargo")?;
        ensure!(output.status.success(), "`cargo build -p {chapter}` failed");
        let stale: Vec<String> = String::from_utf8_lossy(&output.stdout)
            .lines()
            .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
            .filter(|m| m["reason"] == "compiler-artifact" && m["fresh"] == false)
            .map(|m| m["target"]["name"].as_str().unwrap_or("?").to_string())
            .collect();
        ensure!(
            stale.is_empty(),
            "`cargo run -p {chapter}` would rebuild {} after the workspace build: its features differ \
             (compare `cargo tree -e features -p {chapter}` with the workspace's and add what differs to the \
             list at the end of common's desktop dependencies)",
            stale.join(", ")
        );
    }
    println!("every chapter alone reuses the workspace build (`cargo run -p NAME` compiles nothing)");
    Ok(())
}

fn snapshot(args: &[String]) -> anyhow::Result<()> {
    prerequisites::ensure_adapter()?;
    let mut cargo_args = vec!["run", "--quiet", "-p", "snapshots", "--"];
    cargo_args.extend(args.iter().map(String::as_str));
    cargo(&cargo_args)
}

/// Runs a chapter's bench makes besides its views, as (what it shows,
/// extra flags): chapter 09 loads models given with `--model`.
fn extra_bench_runs(chapter: &str) -> anyhow::Result<Vec<(String, Vec<String>)>> {
    if chapter != "textures" {
        return Ok(Vec::new());
    }
    let million = target_dir().join("bench/million.obj");
    std::fs::create_dir_all(million.parent().expect("a folder"))?;
    assets::models::million_triangles(&million)?;
    let boat = root().join("assets/models/boat/boat.obj");
    // Paths relative to the repository (where the runs start), for the book.
    let relative = |path: &Path| path.strip_prefix(root()).unwrap_or(path).display().to_string();
    let run = |model: &Path| vec!["--view".into(), "car".into(), "--model".into(), relative(model)];
    Ok(vec![
        ("The largest of the project's models, the boat".into(), run(&boat)),
        ("A sphere of 1,002,528 triangles written by the bench".into(), run(&million)),
    ])
}

/// The sizes the seed projects measured their frame rates at (seed 001:
/// 1280 × 720 and 1920 × 1080), and one larger, 2560 × 1440.
const SEED_SIZES: [(u32, u32); 3] = [(1280, 720), (1920, 1080), (2560, 1440)];

/// Every chapter's default view at each of [`SEED_SIZES`], median frame
/// and frames per second, from the release binaries already built, written
/// to `book/src/bench/sizes.md` for the book's page on frame rates.
fn bench_sizes() -> anyhow::Result<()> {
    let mut runs = Vec::new();
    for chapter in chapter_names()? {
        let binary = target_dir().join("release").join(&chapter);
        // The first view listed is the default.
        let views = run_bench(&binary, &["--list-views"])?;
        let view = views.split_whitespace().next().context("no views listed")?.to_string();
        for (width, height) in SEED_SIZES {
            let size = format!("{width}x{height}");
            println!("$ {chapter} --bench --frames 10 --view {view} --size {size}");
            let printed = run_bench(&binary, &["--bench", "--frames", "10", "--view", &view, "--size", &size])?;
            runs.push(bench_tables::SizeRun { chapter: chapter.clone(), view: view.clone(), size, printed });
        }
    }
    let (adapter, table) = bench_tables::sizes_table(&runs)?;
    let page = format!(
        "Measured by `cargo xtask bench sizes` (release build, each chapter's first view, 10 frames at each \
         size; median frame): {adapter}.\n\n{table}"
    );
    let path = root().join("book/src/bench/sizes.md");
    std::fs::write(&path, page)?;
    println!("wrote {}", path.display());
    Ok(())
}

/// `cargo xtask bench saved RAW OUT`: the tables of a bench run where no
/// Rust toolchain is (a lent GPU machine), from the files
/// `xtask/gpu-bench.sh` saved in `RAW` (`gpu.txt`, `sizes.txt`,
/// `CHAPTER.txt`): `OUT/sizes.md` and `OUT/CHAPTER.md` for each chapter saved.
fn bench_saved(raw: &Path, out: &Path) -> anyhow::Result<()> {
    let shown = |path: &Path| path.strip_prefix(root()).unwrap_or(path).display().to_string();
    let pages = saved_tables(raw, &format!("cargo xtask bench saved {} {}", shown(raw), shown(out)))?;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    for (name, page) in &pages {
        std::fs::write(out.join(name), page)?;
    }
    println!("wrote {} tables into {}", pages.len(), out.display());
    Ok(())
}

/// The pages `cargo xtask bench saved` writes from the files in `raw`, as
/// (file name, text): `sizes.md`, then `CHAPTER.md` for each chapter saved.
/// `command` is how their headings say they were made.
fn saved_tables(raw: &Path, command: &str) -> anyhow::Result<Vec<(String, String)>> {
    let read = |name: &str| {
        let path = raw.join(name);
        std::fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))
    };
    let gpu_txt = read("gpu.txt")?;
    let cpu = bench_tables::saved_cpu(&gpu_txt, &raw.join("gpu.txt"))?;
    // What the GPU is for drawing, said under every table it measured.
    let about = bench_tables::what_the_gpu_is(&gpu_txt).map(|about| format!("\n\n{about}")).unwrap_or_default();
    let runs = bench_tables::parse_size_runs(&read("sizes.txt")?, &raw.join("sizes.txt"))?;
    let (adapter, table) = bench_tables::sizes_table(&runs)?;
    let mut pages = vec![(
        "sizes.md".to_string(),
        format!(
            "Measured by `xtask/gpu-bench.sh` (release build, each chapter's first view, 10 frames at each size; \
             median frame), tabulated by `{command}`: {adapter}; CPU: {cpu}.{about}\n\n{table}"
        ),
    )];
    for chapter in chapter_names()? {
        let name = format!("{chapter}.txt");
        if !raw.join(&name).exists() {
            continue;
        }
        let (heading, tables) = bench_tables::chapter_tables(&chapter, &read(&name)?, &raw.join(&name))?;
        let page = format!(
            "Measured by `xtask/gpu-bench.sh` (release build, `{chapter} --bench --size 1280x720`), tabulated by \
             `{command}`: {heading}; CPU: {cpu}.{about}\n\n{tables}"
        );
        pages.push((format!("{chapter}.md"), page));
    }
    Ok(pages)
}

/// Runs a chapter binary with `args` and returns what it printed.
fn run_bench(binary: &Path, args: &[&str]) -> anyhow::Result<String> {
    let output = Command::new(binary)
        .current_dir(root())
        .args(args)
        .envs(quiet_env())
        .output()
        .with_context(|| format!("cannot run {}", binary.display()))?;
    ensure!(output.status.success(), "{} failed: {}", binary.display(), String::from_utf8_lossy(&output.stderr));
    Ok(String::from_utf8(output.stdout)?)
}

/// Package names of `chapters/*`, in book order.
fn chapter_names() -> anyhow::Result<Vec<String>> {
    let mut dirs: Vec<PathBuf> =
        std::fs::read_dir(root().join("chapters"))?.map(|e| Ok(e?.path())).collect::<anyhow::Result<_>>()?;
    dirs.sort();
    dirs.iter()
        .map(|dir| {
            let manifest = std::fs::read_to_string(dir.join("Cargo.toml"))?;
            let name = manifest.lines().find_map(|l| l.strip_prefix("name = ")).context("no package name")?;
            Ok(name.trim_matches('"').to_string())
        })
        .collect()
}

fn bench(args: &[String]) -> anyhow::Result<()> {
    if args.first().map(String::as_str) == Some("web") {
        return web::bench(args.get(1).map(String::as_str) == Some("--tabulate"));
    }
    if args.first().map(String::as_str) == Some("sizes") {
        prerequisites::ensure_adapter()?;
        let mut build = vec!["build", "--release"];
        let chapters = chapter_names()?;
        for chapter in &chapters {
            build.extend(["-p", chapter.as_str()]);
        }
        cargo(&build)?;
        return bench_sizes();
    }
    if args.first().map(String::as_str) == Some("saved") {
        let [_, raw, out] = args else {
            bail!("usage: cargo xtask bench saved RAW OUT (RAW: the folder `xtask/gpu-bench.sh` saved)");
        };
        return bench_saved(&root().join(raw), &root().join(out));
    }
    prerequisites::ensure_adapter()?;
    let all = chapter_names()?;
    let chosen: Vec<String> = if args.is_empty() { all.clone() } else { args.to_vec() };
    if let Some(bad) = chosen.iter().find(|c| !all.contains(c)) {
        bail!("unknown chapter '{bad}'; the chapters are: {}", all.join(", "));
    }
    let mut build = vec!["build", "--release"];
    for c in &chosen {
        build.extend(["-p", c.as_str()]);
    }
    cargo(&build)?;
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find_map(|l| l.strip_prefix("model name").map(|m| m.trim_start_matches([' ', '\t', ':']).to_string()))
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let out_dir = root().join("book/src/bench");
    std::fs::create_dir_all(&out_dir)?;
    for chapter in &chosen {
        let binary = target_dir().join("release").join(chapter);
        let command = format!("{chapter} --bench --size 1280x720");
        println!("\n$ {command}");
        let output = Command::new(&binary)
            .args(["--bench", "--size", "1280x720"])
            .envs(quiet_env())
            .output()
            .with_context(|| format!("cannot run {}", binary.display()))?;
        ensure!(output.status.success(), "{chapter} --bench failed: {}", String::from_utf8_lossy(&output.stderr));
        let table = String::from_utf8(output.stdout)?;
        print!("{table}");
        let (heading, rows) = table.split_once('\n').unwrap_or((&table, ""));
        let page = format!(
            "Measured by `cargo xtask bench {chapter}` (release build, `{command}`): {heading}; \
             CPU: {cpu}, {cores} threads.\n\n{rows}"
        );
        let mut page = page;
        for (what, args) in extra_bench_runs(chapter)? {
            let command = format!("{chapter} --bench {}", args.join(" "));
            println!("\n$ {command}");
            let output = Command::new(&binary)
                .current_dir(root())
                .args(["--bench", "--size", "1280x720"])
                .args(&args)
                .envs(quiet_env())
                .output()
                .with_context(|| format!("cannot run {}", binary.display()))?;
            ensure!(output.status.success(), "{command} failed: {}", String::from_utf8_lossy(&output.stderr));
            let table = String::from_utf8(output.stdout)?;
            print!("{table}");
            let rows = table.split_once('\n').map_or("", |(_, rows)| rows);
            page.push_str(&format!("\n{what} (`{command}`):\n\n{rows}"));
        }
        std::fs::write(out_dir.join(format!("{chapter}.md")), page)?;
    }
    println!("\nwrote {}", out_dir.display());
    // The whole course measured: its default views at the seeds' sizes too.
    if args.is_empty() {
        bench_sizes()?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fields are found after the name whatever the name holds, and a
    /// child that burns CPU shows in the count once it has been waited for
    /// (measured the other way: the shell's loop takes a tenth of a second
    /// or more on these machines).
    #[test]
    fn the_cpu_of_waited_children_is_counted() {
        let line = "4242 (odd) name) S 1 4242 4242 0 -1 4194560 100 200 0 0 7 3 250 125 20 0 1 0 99 0 0";
        assert_eq!(cpu_of_waited_children(line), Some(3.75));
        assert_eq!(cpu_of_waited_children("4242 (cut"), None);
        let Some(before) = children_cpu_seconds() else { return };
        let status = Command::new("sh")
            .args(["-c", "i=0; while [ $i -lt 300000 ]; do i=$((i+1)); done"])
            .status()
            .expect("sh runs");
        assert!(status.success());
        let after = children_cpu_seconds().expect("read before, so readable after");
        assert!(after - before >= 0.1, "{before} s then {after} s");
    }

    /// The GPU tables in the book are what `cargo xtask bench saved` makes
    /// of the raw files kept beside them: made again into a temporary
    /// folder, every file must be the same, and no table may be left over.
    #[test]
    fn the_gpu_tables_are_made_from_their_raw_files() {
        let (raw, tables) = (root().join("book/src/bench/gpu/raw"), root().join("book/src/bench/gpu"));
        let scratch = std::env::temp_dir().join(format!("xtask-gpu-tables-{}", std::process::id()));
        let remake = "cargo xtask bench saved book/src/bench/gpu/raw book/src/bench/gpu";
        std::fs::create_dir_all(&scratch).unwrap();
        for (name, page) in saved_tables(&raw, remake).unwrap() {
            std::fs::write(scratch.join(name), page).unwrap();
        }
        let remake = format!("run `{remake}`");
        let mut problems = Vec::new();
        let names = |dir: &Path| -> Vec<String> {
            let mut names: Vec<String> = std::fs::read_dir(dir)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
                .filter(|n| n.ends_with(".md"))
                .collect();
            names.sort();
            names
        };
        for name in names(&scratch) {
            let made = std::fs::read_to_string(scratch.join(&name)).unwrap();
            match std::fs::read_to_string(tables.join(&name)) {
                Ok(kept) if kept == made => {}
                Ok(kept) => {
                    let line = kept.lines().zip(made.lines()).position(|(a, b)| a != b).map_or(0, |l| l + 1);
                    problems
                        .push(format!("book/src/bench/gpu/{name} differs from its raw file at line {line}; {remake}"))
                }
                Err(_) => problems.push(format!("book/src/bench/gpu/{name} is missing; {remake}")),
            }
        }
        for name in names(&tables) {
            if !scratch.join(&name).exists() {
                problems.push(format!("book/src/bench/gpu/{name} has no raw file in book/src/bench/gpu/raw"));
            }
        }
        std::fs::remove_dir_all(&scratch).unwrap();
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }
}
