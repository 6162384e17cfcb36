//! `snapshots [--bless] [CHAPTER...]`: compare (or, with --bless, rewrite)
//! the reference images. Run it as `cargo xtask snapshot`.
//!
//! Chapters are checked on two threads: a software rasteriser processes a
//! draw's vertices on the thread that submitted it, so two chapters at once
//! use both cores where one would leave the second idle.

use std::process::ExitCode;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use snapshots::{Record as Entry, Snapshots as _};

fn main() -> ExitCode {
    common::gpu::quiet_driver_warnings();
    let mut bless = false;
    let mut names = Vec::new();
    for arg in std::env::args().skip(1) {
        match arg.as_str() {
            "--bless" => bless = true,
            "--docs" => return write_docs(),
            name => names.push(name.to_string()),
        }
    }
    let all = snapshots::chapters();
    if let Some(bad) = names.iter().find(|n| !all.iter().any(|e| e.name == n.as_str())) {
        let known: Vec<&str> = all.iter().map(|e| e.name).collect();
        eprintln!("error: unknown chapter '{bad}'; the chapters are: {}", known.join(", "));
        return ExitCode::from(2);
    }
    let chosen: Vec<Entry> =
        all.into_iter().filter(|e| names.is_empty() || names.iter().any(|n| n == e.name)).collect();
    let started = Instant::now();
    if bless {
        return bless_all(&chosen);
    }
    // The heaviest chapters come last in the book: start them first.
    let order: Vec<&Entry> = chosen.iter().rev().collect();
    let next = AtomicUsize::new(0);
    let (passed, failed) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let print = Mutex::new(());
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| {
                while let Some(entry) = order.get(next.fetch_add(1, Ordering::SeqCst)) {
                    let outcome = entry.check();
                    let _lock = print.lock();
                    match outcome {
                        Ok((results, problems)) => {
                            for r in results {
                                match r.outcome {
                                    Ok(c) => {
                                        passed.fetch_add(1, Ordering::SeqCst);
                                        println!("ok   {}/{}: {c}", entry.name, r.view);
                                    }
                                    Err(e) => {
                                        failed.fetch_add(1, Ordering::SeqCst);
                                        println!("FAIL {}/{}: {e}", entry.name, r.view);
                                    }
                                }
                            }
                            for problem in problems {
                                failed.fetch_add(1, Ordering::SeqCst);
                                println!("FAIL {}: {problem}", entry.name);
                            }
                        }
                        Err(e) => {
                            failed.fetch_add(1, Ordering::SeqCst);
                            eprintln!("error: {}: {e:#}", entry.name);
                        }
                    }
                }
            });
        }
    });
    let (passed, failed) = (passed.into_inner(), failed.into_inner());
    println!(
        "snapshots: {passed} passed, {failed} failed, {} chapters in {:.1} s",
        chosen.len(),
        started.elapsed().as_secs_f64()
    );
    if failed == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}

fn bless_all(chosen: &[Entry]) -> ExitCode {
    let mut failed = false;
    for entry in chosen {
        match entry.bless() {
            Ok(paths) => paths.iter().for_each(|p| println!("blessed {}", p.display())),
            Err(e) => {
                eprintln!("error: {}: {e:#}", entry.name);
                failed = true;
            }
        }
    }
    if failed { ExitCode::FAILURE } else { ExitCode::SUCCESS }
}

/// `--docs`: writes the README's chapter table and the book's summary from
/// the chapter records (`cargo xtask book` runs it).
fn write_docs() -> ExitCode {
    let written = snapshots::course_docs().and_then(|docs| {
        for (path, text) in docs {
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
                std::fs::write(&path, text)?;
                println!("wrote {}", path.display());
            }
        }
        Ok(())
    });
    match written {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::FAILURE
        }
    }
}
