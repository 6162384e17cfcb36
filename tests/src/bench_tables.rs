//! The book's bench tables (`book/src/bench/<chapter>.md`, written by
//! `cargo xtask bench`) must describe the chapter as it is: every view in
//! them, no pass a view no longer draws, timed or counted, and every row
//! timed on the frame the view draws today: the fingerprint the table
//! recorded for each view ([`common::fingerprint`]) must be the one the
//! snapshot run works out again.

use std::path::{Path, PathBuf};

use common::View;
use common::fingerprint::{FRAMES_HEADING, Fingerprint, recorded};

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
            // | view | what | min | median | p95 | frame |  → ["", view, what, …, ""]
            // (a table measured before frames were fingerprinted has no `frame`)
            let (view, what) = (*cells.get(1)?, *cells.get(2)?);
            if !(cells.len() == 7 || cells.len() == 8) || view == "view" || view.starts_with("---") {
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
    // The frames section's rows have as many cells: it comes after.
    let table = &table[..table.find(FRAMES_HEADING).unwrap_or(table.len())];
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

/// Compares `chapter`'s bench table with `drawn`, the passes each view
/// drew when it was rendered, and with `frames`, every view's fingerprint
/// as it is now. Returns the problems, each saying how to fix it.
pub fn check(
    chapter: &str,
    views: &[View],
    drawn: &[(&str, Vec<&str>)],
    frames: &[(&str, Fingerprint)],
) -> Vec<String> {
    let path = table_path(chapter);
    match std::fs::read_to_string(&path) {
        Ok(table) => {
            let path = path.display().to_string();
            let mut problems = check_table(&path, &table, chapter, views, drawn);
            problems.extend(check_frames(&path, &table, chapter, frames));
            problems
        }
        Err(_) => vec![format!("{} is missing: run `cargo xtask bench {chapter}`", path.display())],
    }
}

/// Every view's rows must have timed the frame the view draws now: the
/// fingerprint in the table's frames section is today's. A problem per
/// view that is not, naming what changed and the command that measures
/// it again.
pub fn check_frames(path: &str, table: &str, chapter: &str, frames: &[(&str, Fingerprint)]) -> Vec<String> {
    let again = format!("measure it again: `cargo xtask bench {chapter}`");
    if !table.contains(FRAMES_HEADING) {
        return vec![format!("{path}: measured before its frames were fingerprinted; {again}")];
    }
    let mut problems = Vec::new();
    for (view, now) in frames {
        let Some((id, samples, passes)) = recorded(table, view) else {
            problems.push(format!("{path}: no fingerprint for the view `{view}`; {again}"));
            continue;
        };
        if id != now.id() {
            let mut changes = now.changes_since(&samples, &passes);
            if changes.is_empty() {
                changes.push("the view's settings".into());
            }
            problems.push(format!(
                "{path}: the rows of `{view}` timed frame {id}, but the view now draws frame {} ({}); {again}",
                now.id(),
                changes.join("; ")
            ));
        }
        // Each timing row names the frame it timed: the view's, no other.
        let timed = &table[..table.find(FRAMES_HEADING).unwrap_or(table.len())];
        for line in timed.lines() {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            let is_frame = |c: &str| c.len() == 8 && c.chars().all(|ch| ch.is_ascii_hexdigit());
            // | view | pass | min | median | max | frame |: eight pieces.
            if cells.len() == 8 && cells[1] == *view && is_frame(cells[6]) {
                let row_frame = cells[6];
                if row_frame != id {
                    problems.push(format!(
                        "{path}: a row of `{view}` says it timed frame {row_frame}, its frames section {id}; {again}"
                    ));
                }
            }
        }
    }
    problems
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
