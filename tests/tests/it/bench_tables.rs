//! The bench tables' check: a table that matches passes; a pass no longer
//! drawn, a view not benched and an unknown view fail.

use common::View;
use snapshots::bench_tables::{check_table, rows};

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

#[test]
fn rows_are_read_with_their_passes() {
    assert_eq!(rows(TABLE), vec![("day".to_string(), None), ("day".to_string(), Some("plain and sky".to_string()))]);
}
