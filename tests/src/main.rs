//! `snapshots [--bless] [CHAPTER...]`: compare (or, with --bless, rewrite)
//! the reference images. Run it as `cargo xtask snapshot`.

use std::process::ExitCode;

fn main() -> ExitCode {
    common::gpu::quiet_driver_warnings();
    let mut bless = false;
    let mut names = Vec::new();
    for arg in std::env::args().skip(1) {
        match arg.as_str() {
            "--bless" => bless = true,
            name => names.push(name.to_string()),
        }
    }
    let known: Vec<&str> = snapshots::chapters().iter().map(|e| e.name).collect();
    if let Some(bad) = names.iter().find(|n| !known.contains(&n.as_str())) {
        eprintln!("error: unknown chapter '{bad}'; the chapters are: {}", known.join(", "));
        return ExitCode::from(2);
    }
    let mut failed = 0;
    let mut passed = 0;
    for entry in snapshots::chapters() {
        if !names.is_empty() && !names.iter().any(|n| n == entry.name) {
            continue;
        }
        if bless {
            match entry.bless() {
                Ok(paths) => paths.iter().for_each(|p| println!("blessed {}", p.display())),
                Err(e) => {
                    eprintln!("error: {}: {e:#}", entry.name);
                    failed += 1;
                }
            }
            continue;
        }
        match entry.check() {
            Ok(results) => {
                for r in results {
                    match r.outcome {
                        Ok(c) => {
                            passed += 1;
                            println!("ok   {}/{}: {c}", entry.name, r.view);
                        }
                        Err(e) => {
                            failed += 1;
                            println!("FAIL {}/{}: {e}", entry.name, r.view);
                        }
                    }
                }
            }
            Err(e) => {
                failed += 1;
                eprintln!("error: {}: {e:#}", entry.name);
            }
        }
    }
    if !bless {
        println!("snapshots: {passed} passed, {failed} failed");
    }
    if failed == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}
