//! What a book page quotes from a bench table (`book/src/bench/*.md`,
//! written by `cargo xtask bench`), and from a run of the code. The tests
//! of the pages' worked solutions read a bench figure here, write it as the
//! page does, and check that the page says it, so that a bench run that
//! moves a figure fails them until the page follows; a figure measured by
//! running the code once and copied into a test is a [`Measured`].

/// A figure a worked solution's test got by running the chapter's code (a
/// render, a cull, a simulation) and copied, with the page, which says
/// "measured" beside it: a change detector. It says the code still gives
/// what the page says, not why; a figure a test can derive from first
/// principles is derived there instead. Each solutions file keeps its
/// measured figures together, in one `measured` block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    pub value: f64,
    /// How far a new run may land from it and still be the page's figure.
    pub within: f64,
}

impl Measured {
    pub const fn new(value: f64, within: f64) -> Self {
        Self { value, within }
    }

    /// Whether `actual` is the measured figure still.
    pub fn holds(self, actual: f64) -> bool {
        (actual - self.value).abs() <= self.within
    }

    /// Panics unless `actual` is the measured figure still, saying that
    /// `what` moved and what to do about it.
    #[track_caller]
    pub fn check(self, what: &str, actual: impl Into<f64>) {
        let actual = actual.into();
        assert!(
            self.holds(actual),
            "{what} is now {actual}, where the test and its page have {} (±{}), measured on an earlier run: a \
             change detector moved. If the change is meant, measure again and copy the new figure here and onto \
             the page",
            self.value,
            self.within
        );
    }
}

/// The median, in ms, of the first row of a bench table that starts
/// `| view | what`: `median_ms(table, "default", "frame")`.
pub fn median_ms(table: &str, view: &str, what: &str) -> Option<f64> {
    let row = table.lines().find(|line| line.starts_with(&format!("| {view} | {what}")))?;
    row.split('|').nth(4)?.trim().parse().ok()
}

/// A whole number as the pages write it: `186000.0` → `186,000`, rounded
/// to the nearest whole, with the commas of [`crate::draw_counts::thousands`].
pub fn thousands(value: f64) -> String {
    let whole = crate::draw_counts::thousands(value.abs().round() as u64);
    if value.round() < 0.0 { format!("-{whole}") } else { whole }
}

/// Every page of a chapter's section of the book (`book/src/NN-name/`,
/// `section` being `NN-name`), joined in file order: what a test reads to
/// check that the chapter's pages quote a figure, on whichever of its
/// lessons the figure stands.
#[cfg(not(target_arch = "wasm32"))]
pub fn section_text(section: &str) -> String {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../book/src").join(section);
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(&folder)
        .unwrap_or_else(|e| panic!("cannot read the book's section {}: {e}", folder.display()))
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|path| path.extension().is_some_and(|e| e == "md"))
        .collect();
    files.sort();
    files.iter().map(|f| std::fs::read_to_string(f).unwrap_or_default()).collect::<Vec<_>>().join("\n")
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
    #[should_panic(expected = "a change detector moved")]
    fn a_measured_figure_that_moved_says_so() {
        let measured = Measured::new(0.157, 0.02);
        assert!(measured.holds(0.17) && !measured.holds(0.18));
        measured.check("the share of pixels that change", 0.18);
    }

    #[test]
    fn figures_are_read_and_written_as_the_pages_do() {
        let table = "| view | what | min ms | median ms | p95 ms |\n|---|---|---:|---:|---:|\n\
                     | default | frame (CPU+GPU) | 1.00 | 2.50 | 3.00 |\n| default | GPU: scene pass | 0.5 | 0.75 | 1 |\n";
        assert_eq!(median_ms(table, "default", "frame"), Some(2.5));
        assert_eq!(median_ms(table, "default", "GPU: scene pass"), Some(0.75));
        assert_eq!(median_ms(table, "other", "frame"), None);
        assert_eq!(
            (thousands(186_000.0), thousands(1_248.4), thousands(999.6), thousands(-100.0), thousands(-1_234.0)),
            ("186,000".into(), "1,248".into(), "1,000".into(), "-100".into(), "-1,234".into())
        );
        let page = "1. Why?\n\n<details>\nIt costs 4 ms.\n</details>\n\n2. And?\n<details>\nNo.\n</details>";
        assert_eq!(solution(page, "Why?"), Some("\n\n<details>\nIt costs 4 ms.\n"));
        assert_eq!(solution(page, "How?"), None);
    }
}
