//! The book's one WebAssembly program: every chapter's page loads it, and
//! the page's `<body data-chapter="NAME">` says which chapter to run. One
//! program instead of one per chapter: a reader downloads it once for the
//! whole book, and the browser build links once.

fn main() -> std::process::ExitCode {
    #[cfg(target_arch = "wasm32")]
    {
        let name = common::web::page_chapter();
        match course::find(&name) {
            Some(record) => (record.run)(),
            None => {
                let known: Vec<&str> = course::chapters().iter().map(|r| r.name).collect();
                common::web::show_error(&format!(
                    "this page asks for chapter '{name}'; the chapters are: {}",
                    known.join(", ")
                ));
                std::process::ExitCode::FAILURE
            }
        }
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        eprintln!("live is the book's browser program: run a chapter with `cargo run -p NAME`");
        std::process::ExitCode::from(2)
    }
}
