//! `snapshots [CHAPTER...]`: compare the reference images;
//! `snapshots --bless CHAPTER[/VIEW]... --reason "..."`: rewrite the ones
//! that changed and record each in the bless log. Run it as `cargo xtask
//! snapshot`.
//!
//! Chapters are checked on two threads: a software rasteriser processes a
//! draw's vertices on the thread that submitted it, so two chapters at once
//! use both cores where one would leave the second idle.

use std::process::ExitCode;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use snapshots::blessings::{self, Log};
use snapshots::{Blessing, Record as Entry, Snapshots as _};

/// How to bless, for the error that refuses a bless without a reason.
const BLESS_USAGE: &str = "cargo xtask snapshot --bless CHAPTER[/VIEW]... --reason \"what changed and why\"";

fn main() -> ExitCode {
    common::gpu::quiet_driver_warnings();
    let mut bless = false;
    let mut reason: Option<String> = None;
    let mut names = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--bless" => bless = true,
            "--docs" => return write_docs(),
            "--reason" => reason = args.next(),
            _ if arg.starts_with("--reason=") => reason = Some(arg["--reason=".len()..].to_string()),
            _ if arg.starts_with('-') => {
                eprintln!("error: unknown flag '{arg}'; the flags are --bless and --reason");
                return ExitCode::from(2);
            }
            name => names.push(name.to_string()),
        }
    }
    let all = snapshots::chapters();
    // `chapter` or `chapter/view`.
    let mut targets: Vec<(String, Option<String>)> = Vec::new();
    for name in &names {
        let (chapter, view) = match name.split_once('/') {
            Some((chapter, view)) => (chapter, Some(view)),
            None => (name.as_str(), None),
        };
        let Some(entry) = all.iter().find(|e| e.name == chapter) else {
            let known: Vec<&str> = all.iter().map(|e| e.name).collect();
            eprintln!("error: unknown chapter '{chapter}'; the chapters are: {}", known.join(", "));
            return ExitCode::from(2);
        };
        if let Some(view) = view
            && !entry.views.iter().any(|v| v.snapshot && v.name == view)
        {
            let known: Vec<&str> = entry.views.iter().filter(|v| v.snapshot).map(|v| v.name).collect();
            eprintln!("error: {chapter} has no snapshot view '{view}'; its views are: {}", known.join(", "));
            return ExitCode::from(2);
        }
        targets.push((chapter.to_string(), view.map(str::to_string)));
    }
    let chosen: Vec<Entry> =
        all.into_iter().filter(|e| targets.is_empty() || targets.iter().any(|(c, _)| c == e.name)).collect();
    let started = Instant::now();
    match (bless, reason) {
        (true, Some(reason)) if !reason.trim().is_empty() => return bless_all(&chosen, &targets, reason.trim()),
        (true, _) => {
            eprintln!("error: a bless needs a reason, which the bless log keeps: {BLESS_USAGE}");
            return ExitCode::from(2);
        }
        (false, Some(_)) => {
            eprintln!("error: --reason goes with --bless: {BLESS_USAGE}");
            return ExitCode::from(2);
        }
        (false, None) => {}
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
                    let views = views_named(&targets, entry.name);
                    let outcome = entry.check(&views);
                    let _lock = print.lock();
                    match outcome {
                        Ok((results, problems)) => {
                            for r in results {
                                match r.outcome {
                                    Ok((rule, c)) => {
                                        passed.fetch_add(1, Ordering::SeqCst);
                                        println!("ok   {}/{}: {rule}, {c}", entry.name, r.view);
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
    let (passed, mut failed) = (passed.into_inner(), failed.into_inner());
    match Log::read().and_then(|log| blessings::unlogged_references(&log)) {
        Ok(problems) => {
            for problem in &problems {
                println!("FAIL {problem}");
            }
            failed += problems.len();
        }
        Err(e) => {
            println!("FAIL the bless log: {e:#}");
            failed += 1;
        }
    }
    println!(
        "snapshots: {passed} passed, {failed} failed, {} chapters in {:.1} s",
        chosen.len(),
        started.elapsed().as_secs_f64()
    );
    if failed == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}

/// Blesses the views `targets` name (every view of a chapter named alone;
/// every view of every chapter when there are none) with `reason`, and
/// records each in the bless log.
fn bless_all(chosen: &[Entry], targets: &[(String, Option<String>)], reason: &str) -> ExitCode {
    let log = match Log::read() {
        Ok(log) => log,
        Err(e) => {
            eprintln!("error: {e:#}");
            return ExitCode::FAILURE;
        }
    };
    let mut failed = false;
    let mut entries = Vec::new();
    for entry in chosen {
        match entry.bless(&views_named(targets, entry.name), reason, &log) {
            Ok(done) => {
                for (view, blessing) in done {
                    let name = format!("{}/{view}", entry.name);
                    match blessing {
                        Blessing::Unchanged => println!("unchanged {name}: within one colour level of its reference"),
                        Blessing::Recorded(logged) => {
                            println!("recorded  {name}: unchanged, now in the log as drawn on {}", logged.adapter);
                            entries.push(logged);
                        }
                        Blessing::Written { entry: logged, old_copy } => {
                            let against = match (logged.mean, logged.patch, &old_copy) {
                                (Some(mean), Some(patch), Some(old)) => format!(
                                    "FLIP mean {mean:.5}, worst patch {patch:.3} against the old picture, kept as {}",
                                    old.display()
                                ),
                                (_, _, Some(old)) => {
                                    format!("a new size; the old picture is kept as {}", old.display())
                                }
                                _ => "a new view".to_string(),
                            };
                            println!("blessed   {name}: {against}");
                            entries.push(logged);
                        }
                    }
                }
            }
            Err(e) => {
                eprintln!("error: {}: {e:#}", entry.name);
                failed = true;
            }
        }
    }
    if let Err(e) = Log::append(&entries) {
        eprintln!("error: {e:#}");
        return ExitCode::FAILURE;
    }
    let written = entries.iter().filter(|e| e.old.as_ref() != Some(&e.new)).count();
    if !entries.is_empty() {
        println!("\n{} entries added to {}.", entries.len(), blessings::path().display());
    }
    if written > 0 {
        println!(
            "{written} pictures written: look at each beside its `-old.png`, then commit them with the log in one commit."
        );
    }
    if failed { ExitCode::FAILURE } else { ExitCode::SUCCESS }
}

/// The views of `chapter` that `targets` name; empty for all of them (a
/// chapter named alone means all its views, whatever else names it).
fn views_named(targets: &[(String, Option<String>)], chapter: &str) -> Vec<String> {
    if targets.iter().any(|(c, v)| c == chapter && v.is_none()) {
        return Vec::new();
    }
    targets.iter().filter(|(c, _)| c == chapter).filter_map(|(_, v)| v.clone()).collect()
}

/// `--docs`: writes the README's chapter table and the book's summary from
/// the chapter records, then checks the pages' shape (`cargo xtask book`
/// runs it before building).
fn write_docs() -> ExitCode {
    let written = snapshots::course_docs().and_then(|docs| {
        for (path, text) in docs {
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
                std::fs::write(&path, text)?;
                println!("wrote {}", path.display());
            }
        }
        // The pages' shape, as the test `the_book_is_made_of_lessons_in_book_order` checks it.
        let src = snapshots::book::book_src();
        let summary = std::fs::read_to_string(src.join("SUMMARY.md"))?;
        let problems = snapshots::book::check(&src, &snapshots::chapters(), &summary)?;
        common::anyhow::ensure!(problems.is_empty(), "the book's pages:\n  {}", problems.join("\n  "));
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
