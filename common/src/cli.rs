//! The entry point every chapter's `main` calls: parse the flags, then open
//! a window or render headless.

use std::process::ExitCode;

#[cfg(not(target_arch = "wasm32"))]
use anyhow::Context as _;

use crate::Chapter;
#[cfg(not(target_arch = "wasm32"))]
use crate::args::{Args, UsageError, check_size, check_writable};
use crate::chapter::About;
#[cfg(not(target_arch = "wasm32"))]
use crate::headless::{self, RenderRequest};
#[cfg(not(target_arch = "wasm32"))]
use crate::{Gpu, NoAdapter, Stats};

/// Runs chapter `C` as the command line asks. Every chapter's `main` is
/// this one call. Errors print as one line and a non-zero exit code, never
/// a panic: 2 for bad flags and a missing adapter, 1 for anything else.
pub fn run<C: Chapter>() -> ExitCode {
    run_chapter(About::of::<C>())
}

/// [`run`], whatever the chapter's type: the runners below are compiled
/// once, here, rather than once for each chapter's binary.
pub fn run_chapter(about: About) -> ExitCode {
    // In a browser the page's URL is the command line.
    #[cfg(target_arch = "wasm32")]
    return crate::browser::run(about);
    #[cfg(not(target_arch = "wasm32"))]
    run_native(about)
}

#[cfg(not(target_arch = "wasm32"))]
fn run_native(about: About) -> ExitCode {
    crate::gpu::quiet_driver_warnings();
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let args = match Args::parse_from_of(&about, std::env::args_os()) {
        Ok(args) => args,
        Err(error) => error.exit(),
    };
    if args.list_views {
        use std::io::Write as _;
        // `--list-views | head -1` closes the pipe early: stop quietly then.
        let mut out = std::io::stdout().lock();
        for view in about.views {
            if writeln!(out, "{:<14} {}", view.name, view.about).is_err() {
                break;
            }
        }
        return ExitCode::SUCCESS;
    }
    let result = if args.screenshot.is_some() || args.bench {
        run_headless(&about, &args)
    } else {
        crate::window::run(about, &args)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            let usage = error.is::<UsageError>() || error.is::<NoAdapter>();
            ExitCode::from(if usage { 2 } else { 1 })
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn run_headless(about: &About, args: &Args) -> anyhow::Result<()> {
    if let Some(path) = &args.screenshot {
        check_writable(path)?;
    }
    let mut needs = (about.gpu_needs)();
    if args.bench {
        // GPU pass times, where the adapter can measure them.
        needs.optional |= wgpu::Features::TIMESTAMP_QUERY;
    }
    let gpu = Gpu::headless(needs)?;
    check_size(&gpu, args.size)?;
    let time = args.time.unwrap_or(about.snapshot_time);
    let request = |view| RenderRequest {
        width: args.size.width,
        height: args.size.height,
        time,
        view,
        camera: args.camera,
        antialiasing: args.antialiasing,
    };

    if let Some(path) = &args.screenshot {
        let shot = request(args.view_index_in(about.views));
        let image = headless::render_image_of(about, &gpu, &shot, &args.chapter_flags)?;
        image.save(path).with_context(|| format!("cannot write {}", path.display()))?;
        println!("{}", path.display());
    }
    if args.bench {
        let views: Vec<usize> = match &args.view {
            Some(_) => vec![args.view_index_in(about.views)],
            None => (0..about.views.len()).collect(),
        };
        let frames = args.frames.unwrap_or(about.bench_frames);
        println!(
            "{} on {}, {}x{}, {frames} frames per view",
            about.name,
            gpu.describe(),
            args.size.width,
            args.size.height
        );
        // Every row carries the fingerprint of the frame it timed
        // (`common::fingerprint`), and the frames section says what each was.
        println!("| view | what | min ms | median ms | p95 ms | frame |");
        println!("|---|---|---:|---:|---:|---|");
        let row = |view: &str, what: &str, s: Stats, frame: &str| {
            println!("| {view} | {what} | {:.2} | {:.2} | {:.2} | {frame} |", s.min, s.median, s.p95);
        };
        let mut notes = Vec::new();
        let mut medians = Vec::new();
        let mut triangles = Vec::new();
        let mut frames_timed = Vec::new();
        for view in views {
            let report = headless::bench_of(about, &gpu, &request(view), frames, &args.chapter_flags)?;
            let fingerprint = headless::fingerprint_of(about, &gpu, view, &args.chapter_flags)?;
            let frame = fingerprint.id();
            medians.push((report.view, report.frame.median));
            row(report.view, "frame (CPU+GPU)", report.frame, &frame);
            for (pass, stats) in &report.passes {
                row(report.view, &format!("GPU: {pass} pass"), *stats, &frame);
            }
            for (work, stats) in &report.cpu {
                row(report.view, &format!("CPU: {work}"), *stats, &frame);
            }
            frames_timed.push((report.view, fingerprint));
            let extra = if report.stats.is_empty() { String::new() } else { format!("; {}", report.stats) };
            notes.push(format!("- {}: setup (`Chapter::new`) {:.0} ms{extra}", report.view, report.setup_ms));
            notes.push(format!("- {}: {}", report.view, report.memory.summary()));
            triangles.extend(report.drawn.iter().map(|count| (report.view, *count)));
        }
        if args.view.is_none() {
            let (file, edit) = headless::edit_to_frame_of(about, &gpu, &request(0), 5, &args.chapter_flags)?;
            notes.push(format!(
                "- a shader edit to the frame that shows it (`{file}`, 5 edits built with Ctrl+Enter): \
                 median {:.0} ms (min {:.0}, p95 {:.0})",
                edit.median, edit.min, edit.p95
            ));
        }
        println!("\n{}", notes.join("\n"));
        if !triangles.is_empty() {
            print_triangles(&triangles);
        }
        println!("\n{}", crate::fingerprint::frames_section(&frames_timed));
        let baseline = about.bench_baseline.and_then(|name| medians.iter().find(|(view, _)| *view == name));
        if let Some(&(name, base)) = baseline {
            println!("\nEach view's median frame against `{name}`'s:\n");
            println!("| view | median frame ms | × `{name}` |");
            println!("|---|---:|---:|");
            for (view, median) in &medians {
                println!("| {view} | {median:.2} | {:.2} |", median / base);
            }
        }
    }
    Ok(())
}

/// The bench's table of what each view drew, pass by pass, in the last
/// measured frame: draw calls and triangles, as the chapter counted them
/// while recording (`Frame::drawn`).
#[cfg(not(target_arch = "wasm32"))]
fn print_triangles(counts: &[(&str, crate::PassCount)]) {
    use crate::draw_counts::thousands;
    println!("\nTriangles drawn in a frame, pass by pass, counted from the draws recorded:\n");
    println!("| view | pass | draws | triangles |");
    println!("|---|---|---:|---:|");
    for (view, count) in counts {
        println!("| {view} | {} | {} | {} |", count.pass, count.drawn.draws, thousands(count.drawn.triangles));
    }
}
