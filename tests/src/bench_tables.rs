//! The book's bench tables (`book/src/bench/<chapter>.md`, written by
//! `cargo xtask bench`) must describe the chapter as it is: every view in
//! them, and no pass a view no longer draws, timed or counted.

use std::path::{Path, PathBuf};

use common::View;

/// Where `cargo xtask bench` writes a chapter's table.
pub fn table_path(chapter: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../book/src/bench").join(format!("{chapter}.md"))
}

/// The rows of a bench table as (view, pass), where pass is `None` for the
/// whole frame's row and `Some(name)` for a `GPU: name pass` or a
/// `CPU: name` row (work a frame times on the CPU).
pub fn rows(table: &str) -> Vec<(String, Option<String>)> {
    table
        .lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            // | view | what | min | median | p95 |  → ["", view, what, …, ""]
            let (view, what) = (*cells.get(1)?, *cells.get(2)?);
            if cells.len() != 7 || view == "view" || view.starts_with("---") {
                return None;
            }
            let gpu = what.strip_prefix("GPU: ").and_then(|p| p.strip_suffix(" pass"));
            let pass = gpu.or_else(|| what.strip_prefix("CPU: ")).map(str::to_string);
            Some((view.to_string(), pass))
        })
        .collect()
}

/// The rows of a bench table's triangles table (`| view | pass | draws |
/// triangles |`, which `--bench` prints after its notes) as (view, pass).
pub fn triangle_rows(table: &str) -> Vec<(String, String)> {
    table
        .lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            // | view | pass | draws | triangles |  → ["", view, pass, draws, triangles, ""]
            if cells.len() != 6 || cells[1] == "view" || cells[1].starts_with("---") {
                return None;
            }
            cells[3].parse::<u32>().ok()?;
            Some((cells[1].to_string(), cells[2].to_string()))
        })
        .collect()
}

/// Compares `chapter`'s bench table with `drawn`: the passes each view
/// drew when it was rendered. Returns the problems, each saying how to fix it.
pub fn check(chapter: &str, views: &[View], drawn: &[(&str, Vec<&str>)]) -> Vec<String> {
    let path = table_path(chapter);
    match std::fs::read_to_string(&path) {
        Ok(table) => check_table(&path.display().to_string(), &table, chapter, views, drawn),
        Err(_) => vec![format!("{} is missing: run `cargo xtask bench {chapter}`", path.display())],
    }
}

/// [`check`] for a table's text, named `path` in the messages.
pub fn check_table(path: &str, table: &str, chapter: &str, views: &[View], drawn: &[(&str, Vec<&str>)]) -> Vec<String> {
    let rows = rows(table);
    let mut problems = Vec::new();
    let regenerate = format!("run `cargo xtask bench {chapter}`");
    for view in views {
        if !rows.iter().any(|(v, _)| v == view.name) {
            problems.push(format!("{path}: no row for the view `{}`; {regenerate}", view.name));
        }
    }
    for (view, pass) in &rows {
        if !views.iter().any(|v| v.name == view) {
            problems.push(format!("{path}: `{view}` is not a view of {chapter}; {regenerate}"));
            continue;
        }
        // Bench views are not rendered by the snapshot run: their passes are not known here.
        let Some((_, passes)) = drawn.iter().find(|(v, _)| v == view) else { continue };
        if let Some(pass) = pass
            && !passes.contains(&pass.as_str())
        {
            problems
                .push(format!("{path}: `{view}` no longer draws a `{pass}` pass (it draws {passes:?}); {regenerate}"));
        }
    }
    for (view, pass) in triangle_rows(table) {
        let Some((_, passes)) = drawn.iter().find(|(v, _)| *v == view) else { continue };
        if !passes.contains(&pass.as_str()) {
            problems.push(format!(
                "{path}: `{view}` counts triangles of a `{pass}` pass it no longer draws (it draws {passes:?}); \
                 {regenerate}"
            ));
        }
    }
    problems
}
