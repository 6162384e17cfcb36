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

#[cfg(test)]
mod tests {
    use super::*;

    const TABLE: &str = "Measured by …\n\n| view | what | min ms | median ms | p95 ms |\n|---|---|---:|---:|---:|\n\
        | day | frame (CPU+GPU) | 1.00 | 2.00 | 3.00 |\n| day | GPU: plain and sky pass | 1.00 | 2.00 | 3.00 |\n\n- day: setup 3 ms\n";

    const VIEWS: &[View] = &[View::mode("day", "")];

    #[test]
    fn a_table_that_matches_passes() {
        assert!(check_table("t.md", TABLE, "sky", VIEWS, &[("day", vec!["plain and sky"])]).is_empty());
    }

    #[test]
    fn a_pass_no_longer_drawn_a_view_not_benched_and_an_unknown_view_fail() {
        let problems = check_table("t.md", TABLE, "sky", VIEWS, &[("day", vec!["terrain", "sky"])]);
        assert!(problems.len() == 1 && problems[0].contains("no longer draws a `plain and sky` pass"), "{problems:?}");
        let two: &[View] = &[View::mode("day", ""), View::mode("dusk", "")];
        let drawn = [("day", vec!["plain and sky"]), ("dusk", vec!["plain and sky"])];
        let problems = check_table("t.md", TABLE, "sky", two, &drawn);
        assert!(problems.len() == 1 && problems[0].contains("no row for the view `dusk`"), "{problems:?}");
        let noon: &[View] = &[View::mode("noon", "")];
        let problems = check_table("t.md", TABLE, "sky", noon, &[("noon", vec![])]);
        assert!(problems.iter().any(|p| p.contains("`day` is not a view of sky")), "{problems:?}");
    }

    /// The table of triangles is read by its own rows, and a pass counted
    /// there that the view no longer draws fails like a timed one.
    #[test]
    fn counted_passes_must_be_drawn_too() {
        let counted = format!(
            "{TABLE}\nTriangles drawn in a frame, pass by pass, counted from the draws recorded:\n\n\
             | view | pass | draws | triangles |\n|---|---|---:|---:|\n| day | plain and sky | 3 | 1,234 |\n"
        );
        assert_eq!(triangle_rows(&counted), [("day".to_string(), "plain and sky".to_string())]);
        assert_eq!(rows(&counted), rows(TABLE), "the timed rows are read as before");
        assert!(check_table("t.md", &counted, "sky", VIEWS, &[("day", vec!["plain and sky"])]).is_empty());
        let renamed = counted.replace("| day | plain and sky | 3 |", "| day | plain | 3 |");
        let problems = check_table("t.md", &renamed, "sky", VIEWS, &[("day", vec!["plain and sky"])]);
        assert!(problems.len() == 1 && problems[0].contains("counts triangles of a `plain` pass"), "{problems:?}");
    }

    #[test]
    fn rows_are_read_with_their_passes() {
        assert_eq!(
            rows(TABLE),
            vec![("day".to_string(), None), ("day".to_string(), Some("plain and sky".to_string()))]
        );
    }
}
