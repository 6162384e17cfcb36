//! Every chapter in one binary, for measuring on a machine with a GPU but no
//! Rust toolchain (`xtask/gpu-bench.sh`): one stripped, compressed file
//! travels instead of eleven. Linked under a chapter's name (`terrain`), it
//! is that chapter's binary, arguments and all (`terrain --bench`);
//! `every_chapter --list-chapters` prints the names, one a line.

use std::process::ExitCode;

fn main() -> ExitCode {
    let argv0 = std::env::args().next().unwrap_or_default();
    let name = std::path::Path::new(&argv0).file_name().unwrap_or_default().to_string_lossy().into_owned();
    if let Some(chapter) = course::find(&name) {
        return (chapter.run)();
    }
    let names: Vec<&str> = course::chapters().iter().map(|c| c.name).collect();
    if std::env::args().nth(1).as_deref() == Some("--list-chapters") {
        println!("{}", names.join("\n"));
        return ExitCode::SUCCESS;
    }
    eprintln!(
        "every_chapter: called as '{name}', which names no chapter; link it under a chapter's name ({}) \
         or run it with --list-chapters",
        names.join(", ")
    );
    ExitCode::from(2)
}
