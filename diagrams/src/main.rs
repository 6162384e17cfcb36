//! `diagrams DIR`: writes the book's SVG diagrams into DIR (`cargo xtask book`
//! runs it with `book/src/diagrams`).

use std::process::ExitCode;

fn main() -> ExitCode {
    let Some(dir) = std::env::args_os().nth(1) else {
        eprintln!("usage: diagrams DIR");
        return ExitCode::from(2);
    };
    let dir = std::path::PathBuf::from(dir);
    if let Err(error) = std::fs::create_dir_all(&dir) {
        eprintln!("error: cannot create {}: {error}", dir.display());
        return ExitCode::FAILURE;
    }
    for (name, svg) in diagrams::all() {
        let path = dir.join(name);
        if let Err(error) = std::fs::write(&path, svg) {
            eprintln!("error: cannot write {}: {error}", path.display());
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}
