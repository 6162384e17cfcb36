//! The bench tables' check: a table that matches passes; a pass no longer
//! drawn (timed or counted), a view not benched and an unknown view fail.

use common::View;
use snapshots::bench_tables::{check_table, rows, triangle_rows};

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
    assert_eq!(rows(TABLE), vec![("day".to_string(), None), ("day".to_string(), Some("plain and sky".to_string()))]);
}
