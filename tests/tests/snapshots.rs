//! Every chapter in the course's records (`course::chapters()`), checked
//! view by view: against its reference image, for purity (a live instance
//! after every other view draws what a fresh one draws), and against its
//! bench table; its first view once on OpenGL, once on OpenGL 3.3 (in a
//! child process) and once on a device with none of its optional
//! features; then the checks on the records themselves: every chapter
//! crate has one, no reference is left over, every reference is in the
//! bless log, the README and the book's summary follow them, and no
//! chapter uses another's `Chapter` type.

use std::collections::BTreeSet;
use std::path::Path;

use libtest_mimic::{Arguments, Failed, Trial};
use snapshots::Snapshots as _;

/// The flag a child of this harness is run with to draw one chapter on
/// OpenGL 3.3 (see [`on_opengl_3_3`]).
const OPENGL_3_3_CHILD: &str = "--opengl-3.3-child";

/// The chapters that must draw on OpenGL 3.3, as on WebGL2; the others may
/// refuse there in one line.
const MUST_DRAW_ON_OPENGL_3_3: [&str; 2] = ["triangle", "camera"];

fn main() {
    common::gpu::quiet_driver_warnings();
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some(OPENGL_3_3_CHILD) {
        std::process::exit(opengl_3_3_child(args.get(2).map_or("", String::as_str)));
    }
    let mut trials: Vec<Trial> = snapshots::chapters()
        .into_iter()
        .map(|entry| {
            Trial::test(format!("views::{}", entry.name), move || {
                let problems = entry.check_purity().map_err(|e| Failed::from(format!("{e:#}")))?;
                if problems.is_empty() { Ok(()) } else { Err(problems.join("\n").into()) }
            })
        })
        .collect();
    // Every chapter once on OpenGL: drawn, or refused in one line (left
    // out where `cargo xtask test` found no EGL: macOS, Windows).
    let no_opengl = std::env::var_os("SNAPSHOTS_SKIP_OPENGL").is_some();
    trials.extend(snapshots::chapters().into_iter().map(|entry| {
        Trial::test(format!("opengl::{}", entry.name), move || match snapshots::draw_on_gl(&entry) {
            Ok(_) => Ok(()),
            Err(e) => Err(format!("{e:#}").into()),
        })
        .with_ignored_flag(no_opengl)
    }));
    // Every chapter once on an OpenGL 3.3 driver: drawn,
    // or refused in one line.
    trials.extend(snapshots::chapters().into_iter().map(|entry| {
        Trial::test(format!("opengl-3.3::{}", entry.name), move || on_opengl_3_3(entry.name).map_err(Failed::from))
            .with_ignored_flag(no_opengl)
    }));
    // Every chapter once with none of its optional features: each fallback draws.
    trials.extend(snapshots::chapters().into_iter().map(|entry| {
        Trial::test(format!("fallbacks::{}", entry.name), move || {
            match snapshots::draw_without_optional_features(&entry) {
                Ok(snapshots::OnGl::Drawn(_)) => Ok(()),
                Ok(snapshots::OnGl::Refused(line)) => Err(format!("refused without optional features: {line}").into()),
                Err(e) => Err(format!("{e:#}").into()),
            }
        })
    }));
    trials.push(Trial::test("every_chapter_crate_is_registered", every_chapter_crate_is_registered));
    trials.push(Trial::test("no_unit_test_goes_unrun", no_unit_test_goes_unrun));
    trials.push(Trial::test("no_stale_references", no_stale_references));
    trials.push(Trial::test("every_reference_is_in_the_bless_log", every_reference_is_in_the_bless_log));
    trials.push(Trial::test("readme_and_summary_follow_the_records", readme_and_summary_follow_the_records));
    trials.push(Trial::test("chapters_compose_pieces_not_chapters", chapters_compose_pieces_not_chapters));
    libtest_mimic::run(&Arguments::from_args(), trials).exit();
}

/// A chapter crate missing from the registry would never be snapshot-tested.
fn every_chapter_crate_is_registered() -> Result<(), Failed> {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("../chapters");
    let mut on_disk = BTreeSet::new();
    for dir in std::fs::read_dir(&chapters).map_err(|e| e.to_string())? {
        let manifest = std::fs::read_to_string(dir.map_err(|e| e.to_string())?.path().join("Cargo.toml"))
            .map_err(|e| e.to_string())?;
        let name = manifest.lines().find_map(|l| l.strip_prefix("name = ")).ok_or("a manifest without a name")?;
        on_disk.insert(name.trim_matches('"').to_string());
    }
    let registered: BTreeSet<String> = snapshots::chapters().iter().map(|e| e.name.to_string()).collect();
    if on_disk == registered {
        Ok(())
    } else {
        Err(format!("chapters/ holds {on_disk:?} but course::chapters() registers {registered:?}").into())
    }
}

/// A chapter library built with `test = false` never runs its unit tests
/// in `cargo test --workspace`: one that has some must not say so.
fn no_unit_test_goes_unrun() -> Result<(), Failed> {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("../chapters");
    let mut unrun = Vec::new();
    for dir in std::fs::read_dir(&chapters).map_err(|e| e.to_string())? {
        let dir = dir.map_err(|e| e.to_string())?.path();
        let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).map_err(|e| e.to_string())?;
        let lib = manifest.split("[lib]").nth(1).map(|rest| rest.split("\n[").next().unwrap_or(rest));
        if !lib.is_some_and(|lib| lib.lines().any(|l| l.trim() == "test = false")) {
            continue;
        }
        let mut sources = vec![dir.join("src")];
        while let Some(path) = sources.pop() {
            if path.is_dir() {
                for entry in std::fs::read_dir(&path).map_err(|e| e.to_string())? {
                    sources.push(entry.map_err(|e| e.to_string())?.path());
                }
            } else if std::fs::read_to_string(&path).is_ok_and(|text| text.contains("#[cfg(test)]")) {
                unrun.push(path.display().to_string());
            }
        }
    }
    if unrun.is_empty() {
        Ok(())
    } else {
        Err(format!("unit tests that `cargo test` never runs (their library says `test = false`): {unrun:?}").into())
    }
}

/// A reference for a view that no longer exists is a figure nobody checks.
fn no_stale_references() -> Result<(), Failed> {
    for dir in std::fs::read_dir(snapshots::snapshot_dir()).map_err(|e| e.to_string())? {
        let dir = dir.map_err(|e| e.to_string())?.path();
        if !dir.is_dir() {
            continue; // the bless log
        }
        let chapter = dir.file_name().unwrap_or_default().to_string_lossy().to_string();
        let entry = snapshots::find(&chapter).ok_or_else(|| format!("{} belongs to no chapter", dir.display()))?;
        for file in std::fs::read_dir(&dir).map_err(|e| e.to_string())? {
            let path = file.map_err(|e| e.to_string())?.path();
            let stem = path.file_stem().unwrap_or_default().to_string_lossy().to_string();
            if stem.ends_with("-actual") || stem.ends_with("-diff") || stem.ends_with("-old") {
                continue; // left by a failing run or a bless, ignored by git
            }
            if !entry.views.iter().any(|v| v.name == stem && v.snapshot) {
                return Err(format!("{} is not a view of {chapter}", path.display()).into());
            }
        }
    }
    Ok(())
}

/// A reference changes only by a bless, which records its bytes' hash in
/// the log: a picture edited by hand, copied in from elsewhere or written
/// by a bless that was not recorded fails here, named.
fn every_reference_is_in_the_bless_log() -> Result<(), Failed> {
    let log = snapshots::blessings::Log::read().map_err(|e| format!("{e:#}"))?;
    let problems = snapshots::blessings::unlogged_references(&log).map_err(|e| format!("{e:#}"))?;
    if problems.is_empty() { Ok(()) } else { Err(problems.join("\n").into()) }
}

/// The README's chapter table and the book's summary are written from the
/// chapter records; a hand edit or a new chapter without `cargo xtask book`
/// shows here.
fn readme_and_summary_follow_the_records() -> Result<(), Failed> {
    for (path, expected) in snapshots::course_docs().map_err(|e| format!("{e:#}"))? {
        let actual = std::fs::read_to_string(&path).map_err(|e| e.to_string())?;
        if actual != expected {
            return Err(format!(
                "{} does not list the chapters as course::chapters() does: run `cargo xtask book` (or `cargo run -p \
                 snapshots -- --docs`) and look at the diff",
                path.display()
            )
            .into());
        }
    }
    Ok(())
}

/// A later chapter reuses an earlier one's pieces (a renderer, a post
/// chain), never the earlier chapter itself: no chapter's source names
/// another chapter's `Chapter` type, and no piece uses its own chapter's
/// demo module.
fn chapters_compose_pieces_not_chapters() -> Result<(), Failed> {
    let chapters_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../chapters");
    let records = snapshots::chapters();
    let mut problems = Vec::new();
    for dir in std::fs::read_dir(&chapters_dir).map_err(|e| e.to_string())? {
        let dir = dir.map_err(|e| e.to_string())?.path();
        for file in rust_files(&dir.join("src")).map_err(|e| e.to_string())? {
            let text = std::fs::read_to_string(&file).map_err(|e| e.to_string())?;
            // A piece stands without its chapter's demo: a later chapter
            // composing it must not need the demo's settings.
            let is_demo = file.file_name().is_some_and(|f| f == "demo.rs" || f == "lib.rs" || f == "main.rs");
            if !is_demo && text.contains("crate::demo") {
                problems.push(format!("{} is a piece but uses its chapter's demo", file.display()));
            }
            for record in &records {
                let (krate, type_name) = (
                    record.type_name.split("::").next().unwrap_or_default(),
                    record.type_name.rsplit("::").next().unwrap_or_default(),
                );
                // `chapters/NN-name`
                let own = dir
                    .file_name()
                    .is_some_and(|d| d.to_string_lossy().split_once('-').map(|(_, name)| name) == Some(record.name));
                let names_it = text.split(|c: char| !c.is_alphanumeric() && c != '_').any(|word| word == type_name);
                if !own && names_it && text.contains(&format!("{krate}::")) {
                    problems.push(format!("{} uses {}, another chapter's Chapter type", file.display(), type_name));
                }
            }
        }
    }
    if problems.is_empty() { Ok(()) } else { Err(problems.join("\n").into()) }
}

fn rust_files(dir: &Path) -> std::io::Result<Vec<std::path::PathBuf>> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            files.extend(rust_files(&path)?);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
    Ok(files)
}

/// `chapter`'s first view drawn on llvmpipe posing as an OpenGL 3.3 driver
/// (`MESA_GL_VERSION_OVERRIDE=3.3`, GLSL 3.30: no compute stage, no
/// storage buffers), in a child process, since Mesa reads
/// the override when it makes a context and this process already holds
/// GL 4.5 ones. It must draw within the GL tolerance of the reference, or
/// (except [`MUST_DRAW_ON_OPENGL_3_3`]) be refused in one line.
fn on_opengl_3_3(chapter: &str) -> Result<(), String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let output = std::process::Command::new(exe)
        .args([OPENGL_3_3_CHILD, chapter])
        .env("WGPU_BACKEND", "gl")
        .env("MESA_GL_VERSION_OVERRIDE", "3.3")
        .env("MESA_GLSL_VERSION_OVERRIDE", "330")
        // Mesa still offers its 4.x extensions under the override; a real
        // 3.3 driver has no compute. wgpu 30 takes GL_ARB_compute_shader
        // for GLSL that binds by `layout(binding = …)` (its
        // SHADER_BINDING_LAYOUT), which GLSL 3.30 cannot write, and every
        // uniform block then reads binding 0 (chapter 02 drew sky only).
        .env("MESA_EXTENSION_OVERRIDE", "-GL_ARB_compute_shader")
        .output()
        .map_err(|e| format!("cannot run the harness as a child: {e}"))?;
    let (stdout, stderr) = (String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
    if !output.status.success() {
        return Err(format!("on OpenGL 3.3 ({}): {stdout}{stderr}", output.status));
    }
    let said = |prefix: &str| stdout.lines().find_map(|l| l.strip_prefix(prefix)).map(str::to_string);
    let version = said("version: ").unwrap_or_default();
    if !version.starts_with("3.3") {
        return Err(format!("Mesa did not pose as OpenGL 3.3: the context is '{version}'"));
    }
    match (said("drawn: "), said("refused: ")) {
        (Some(_), _) => Ok(()),
        (None, Some(line)) if MUST_DRAW_ON_OPENGL_3_3.contains(&chapter) => {
            Err(format!("{chapter} must draw on OpenGL 3.3, and was refused: {line}"))
        }
        (None, Some(line)) if line.contains("cannot do what this chapter needs") => Ok(()),
        (None, Some(line)) => Err(format!("refused without naming what it lacks: {line}")),
        (None, None) => Err(format!("the child said neither drawn nor refused: {stdout}{stderr}")),
    }
}

/// The child's side of [`on_opengl_3_3`]: says the context's version, then
/// draws (or is refused); the exit code is 1 when the picture is wrong.
fn opengl_3_3_child(chapter: &str) -> i32 {
    let Some(entry) = snapshots::find(chapter) else {
        eprintln!("no chapter {chapter}");
        return 1;
    };
    match common::Gpu::headless_on(common::wgpu::Backends::GL, common::GpuNeeds::default()) {
        Ok(gpu) => println!("version: {}", gpu.adapter.get_info().driver_info),
        Err(error) => println!("version: none ({error})"),
    }
    match snapshots::draw_on_gl(&entry) {
        Ok(snapshots::OnGl::Drawn(comparison)) => println!("drawn: {comparison}"),
        Ok(snapshots::OnGl::Refused(line)) => println!("refused: {line}"),
        Err(error) => {
            println!("{error:#}");
            return 1;
        }
    }
    0
}
