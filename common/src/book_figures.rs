//! What a book page quotes from a bench table (`book/src/bench/*.md`,
//! written by `cargo xtask bench`). The tests of the pages' worked
//! solutions read a figure here, write it as the page does, and check that
//! the page says it, so that a bench run that moves a figure fails them
//! until the page follows.

/// The median, in ms, of the first row of a bench table that starts
/// `| view | what`: `median_ms(table, "default", "frame")`.
pub fn median_ms(table: &str, view: &str, what: &str) -> Option<f64> {
    let row = table.lines().find(|line| line.starts_with(&format!("| {view} | {what}")))?;
    row.split('|').nth(4)?.trim().parse().ok()
}

/// A whole number as the pages write it: `186000.0` → `186,000`.
pub fn thousands(value: f64) -> String {
    let digits = format!("{value:.0}");
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && c != '-' && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// The worked solution on `page` that follows `opening`, up to its
/// `</details>`.
pub fn solution<'page>(page: &'page str, opening: &str) -> Option<&'page str> {
    page.split_once(opening)?.1.split("</details>").next()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figures_are_read_and_written_as_the_pages_do() {
        let table = "| view | what | min ms | median ms | p95 ms |\n|---|---|---:|---:|---:|\n\
                     | default | frame (CPU+GPU) | 1.00 | 2.50 | 3.00 |\n| default | GPU: scene pass | 0.5 | 0.75 | 1 |\n";
        assert_eq!(median_ms(table, "default", "frame"), Some(2.5));
        assert_eq!(median_ms(table, "default", "GPU: scene pass"), Some(0.75));
        assert_eq!(median_ms(table, "other", "frame"), None);
        assert_eq!(
            (thousands(186_000.0), thousands(1_248.4), thousands(999.6)),
            ("186,000".into(), "1,248".into(), "1,000".into())
        );
        let page = "1. Why?\n\n<details>\nIt costs 4 ms.\n</details>\n\n2. And?\n<details>\nNo.\n</details>";
        assert_eq!(solution(page, "Why?"), Some("\n\n<details>\nIt costs 4 ms.\n"));
        assert_eq!(solution(page, "How?"), None);
    }
}
