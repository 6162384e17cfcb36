//! Figures on the book's pages, put there from where they come from: a page
//! writes `{{#figure [bench/gpu/sizes.md | terrain | 1280x720]}}` where it
//! means "the terrain's frame on the GPU at 1280 × 720", and the book's build
//! writes the number the table holds today, so a figure cannot go stale when
//! its table is measured again. A claim the prose makes about figures ("less
//! than a fifth", "19 to 30 times") is a `{{#check …}}` beside it, which
//! prints nothing and fails while it is false. `cargo xtask test` expands
//! every page (a unit test below, without building the book), so a row that
//! is gone or a claim that no longer holds fails it, naming the page, the
//! figure and its source.
//!
//! The language, in full (CONTRIBUTING.md has examples):
//!
//! - `{{#figure EXPRESSION}}` or `{{#figure EXPRESSION :FORMAT}}`: the value.
//!   A lone source without a format is written as its source writes it
//!   (`12.83`, `1,219`); anything computed needs a format: `.1` (one
//!   decimal), `,.0` (whole, with thousands separators).
//! - `{{#check EXPRESSION OP EXPRESSION}}`, OP one of `<`, `<=`, `>`, `>=`:
//!   nothing, or a failure.
//! - `{{#measured FILE}}`: a bench table measured on another machine
//!   (`bench/gpu/…`), and under it what changed in the chapter's frames
//!   since, if anything (its frames against the chapter's own table's).
//! - `{{#external NAME | WHERE}}`: NAME in code font, a name from outside
//!   the workspace (WebGPU's, Vulkan's); the book's check resolves any
//!   other name in code font against the workspace's sources.
//! - `{{#cited TEXT | SOURCE}}`: TEXT, a figure quoted from SOURCE (a
//!   paper, a seed's report), which the book's lint of typed measurements
//!   (`snapshots::book`) lets pass.
//! - `{{#run CHAPTER VIEW}}`: the command that runs the chapter on the
//!   view, and the chapter live in the page on it; `{{#view CHAPTER VIEW}}`:
//!   the view's name (`snapshots::book` checks that both name a view).
//! - An expression is numbers, sources, `+ - * /`, parentheses, and
//!   `min(…, …)` and `max(…, …)` (for "least in", "most in").
//! - A source is `[FILE | …]`, FILE relative to the page (as for
//!   `{{#include}}`), then one of
//!   - `ROW… | COLUMN`: a cell of a markdown table: the row whose first cells
//!     start with the ROW keys (`default | frame` is the row
//!     `| default | frame (CPU+GPU) |`), the column whose heading starts with
//!     COLUMN (`median` is `median ms`; `1280x720` is `1280 × 720`); its first
//!     number, or, with a last part holding `#`, the number at the `#`
//!     (`# FPS` in `12.83 ms, 77.9 FPS`);
//!   - `PATTERN`: the number at `#` in the first line that matches, `*`
//!     matching anything (`- default: * far plane # m`), `^` and `$` holding
//!     it to the line's start and end; or, at `@` instead of `#`, the words
//!     there (`on @ (`), which a page may write but not compute with;
//!   - `NAME`, in a `.rs` or `.wgsl` file: the constant `const NAME: … = N;`.
//!
//!   `FILE > TEXT` looks only below the first line holding TEXT (a file's
//!   second table). A ROW key `*` names every row of the first table that
//!   has any, and `* | PATTERN` every line that matches: such a source is
//!   many numbers, for `min(…)` and `max(…)`.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

use anyhow::{Context as _, bail, ensure};

/// The directives a page may hold.
const FIGURE: &str = "{{#figure ";
const CHECK: &str = "{{#check ";
const RUN: &str = "{{#run ";
const VIEW: &str = "{{#view ";
const CITED: &str = "{{#cited ";
const MEASURED: &str = "{{#measured ";
const EXTERNAL: &str = "{{#external ";

/// Expands pages, reading their sources from files (each once).
pub struct Figures {
    files: RefCell<HashMap<PathBuf, String>>,
}

impl Default for Figures {
    fn default() -> Self {
        Self::new()
    }
}

impl Figures {
    pub fn new() -> Self {
        Self { files: RefCell::new(HashMap::new()) }
    }

    /// `text`, the page `page` (whose sources are read relative to `folder`),
    /// with every figure written and every check gone; or every problem, each
    /// naming the page, the directive and, where it got that far, the source.
    pub fn expand(&self, page: &str, folder: &Path, text: &str) -> Result<String, Vec<String>> {
        let mut out = String::with_capacity(text.len());
        let mut problems = Vec::new();
        let mut rest = text;
        while let Some(start) = next_directive(rest) {
            out.push_str(&rest[..start]);
            let after = &rest[start..];
            let Some(end) = after.find("}}") else {
                problems.push(format!("{page}: `{}` is never closed with `}}}}`", first_line(after)));
                rest = "";
                break;
            };
            let directive = &after[..end + 2];
            match self.directive(page, folder, directive) {
                Ok(written) => out.push_str(&written),
                Err(error) => problems.push(format!("{page}: {directive}: {error:#}")),
            }
            rest = &after[end + 2..];
        }
        out.push_str(rest);
        if problems.is_empty() { Ok(out) } else { Err(problems) }
    }

    /// What one `{{#figure …}}` or `{{#check …}}` writes into the page.
    fn directive(&self, page: &str, folder: &Path, directive: &str) -> anyhow::Result<String> {
        let body = &directive[..directive.len() - 2];
        if let Some(file) = body.strip_prefix(MEASURED) {
            return self.measured_elsewhere(folder, file.trim());
        }
        // A name from outside the workspace (an API's), in code font: the
        // book's check resolves every other name in code font against the
        // workspace.
        if let Some(spec) = body.strip_prefix(EXTERNAL) {
            let (name, from) =
                spec.split_once('|').context("an outside name says where it is from: `{{#external NAME | WHERE}}`")?;
            ensure!(
                !name.trim().is_empty() && !from.trim().is_empty(),
                "an outside name needs its name and where it is from"
            );
            return Ok(format!("`{}`", name.trim()));
        }
        // A figure quoted from elsewhere: its text, as quoted. (The source
        // is for whoever checks the quotation; the prose names it too.)
        if let Some(spec) = body.strip_prefix(CITED) {
            let (text, source) =
                spec.split_once('|').context("a quotation needs its source: `{{#cited TEXT | SOURCE}}`")?;
            ensure!(!text.trim().is_empty() && !source.trim().is_empty(), "a quotation needs its text and its source");
            return Ok(text.trim().to_string());
        }
        for (prefix, run) in [(RUN, true), (VIEW, false)] {
            if let Some(spec) = body.strip_prefix(prefix) {
                let words: Vec<&str> = spec.split_whitespace().collect();
                let [chapter, view] = words[..] else { bail!("names a chapter and a view, and nothing else") };
                return Ok(if run { run_line(page, chapter, view) } else { format!("`{view}`") });
            }
        }
        if let Some(spec) = body.strip_prefix(FIGURE) {
            let (expression, format) = split_format(spec)?;
            let (expression, frames) = self.parse_with_frames(folder, expression)?;
            same_frames(&frames)?;
            let lone = matches!(expression, Expression::Source { .. });
            ensure!(lone || !expression.has_words(), "words (from an `@`) cannot be computed with");
            ensure!(format.is_none() || !expression.has_words(), "words (from an `@`) have no format");
            ensure!(
                expression.has_words() || expression.value().is_finite(),
                "is not a finite number: {}",
                expression.describe()
            );
            match (format, &expression) {
                (None, Expression::Source { text, .. }) => Ok(text.clone()),
                (None, _) => bail!("a computed figure needs a format (`:.1`, `:,.0`)"),
                (Some(format), _) => Ok(format.write(expression.value())),
            }
        } else {
            let spec = &body[CHECK.len()..];
            let (left, op, right) = split_comparison(spec)?;
            let ((left, mut frames), (right, more)) =
                (self.parse_with_frames(folder, left)?, self.parse_with_frames(folder, right)?);
            frames.extend(more);
            same_frames(&frames)?;
            ensure!(!left.has_words() && !right.has_words(), "words (from an `@`) cannot be compared");
            let (a, b) = (left.value(), right.value());
            ensure!(
                a.is_finite() && b.is_finite(),
                "compares what is not a number: {} and {}",
                left.describe(),
                right.describe()
            );
            let holds = match op {
                "<" => a < b,
                "<=" => a <= b,
                ">" => a > b,
                _ => a >= b,
            };
            ensure!(holds, "no longer true: {} {op} {}", left.describe(), right.describe());
            Ok(String::new())
        }
    }

    /// An expression, and the frames of the bench rows it reads.
    fn parse_with_frames(&self, folder: &Path, text: &str) -> anyhow::Result<(Expression, Vec<FrameTag>)> {
        let mut parser = Parser { text, at: 0, figures: self, folder, frames: Vec::new() };
        let expression = parser.sum()?;
        parser.skip_spaces();
        ensure!(parser.at == text.len(), "unexpected `{}` in `{text}`", &text[parser.at..]);
        ensure!(!expression.many_outside_extremes(), "a `*` row names many rows: use it inside `min(…)` or `max(…)`");
        Ok((expression, parser.frames))
    }

    /// `{{#measured FILE}}`: a bench table measured where the tests cannot
    /// measure again (`bench/gpu/…`, a lent GPU), and under it, when its
    /// frames are not the ones the chapter draws now (which the chapter's
    /// own table, `bench/…`, holds: the snapshot test keeps it current),
    /// a note of what changed since, view by view.
    fn measured_elsewhere(&self, folder: &Path, file: &str) -> anyhow::Result<String> {
        let current_file = file.replace("/gpu/", "/");
        ensure!(current_file != file, "`{{{{#measured}}}}` is for a table measured elsewhere (`…/bench/gpu/…`)");
        let read = |name: &str| -> anyhow::Result<String> {
            let path = folder.join(name);
            let mut files = self.files.borrow_mut();
            if !files.contains_key(&path) {
                let text = std::fs::read_to_string(&path).with_context(|| format!("cannot read {name}"))?;
                files.insert(path.clone(), text);
            }
            Ok(files[&path].clone())
        };
        let (table, current) = (read(file)?, read(&current_file)?);
        Ok(format!("{table}\n{}", older_frames_note(&table, &current)))
    }

    /// The frame a table row was timed on, where the source `[FILE | ROW…
    /// | COLUMN]` reads a bench table's row: the table (`bench/gpu/x.md`
    /// is `bench/x.md` measured elsewhere), the row's first key, and its
    /// `frame` cell (`None` for a table from before frames were
    /// fingerprinted).
    fn frame_tag(&self, folder: &Path, spec: &str) -> Option<FrameTag> {
        let parts = split_parts(spec);
        let (file, below) = match parts[0].split_once(" > ") {
            Some((file, below)) => (file.trim(), Some(below.trim())),
            None => (parts[0].as_str(), None),
        };
        let keys: Vec<&str> = parts[1..].iter().map(String::as_str).collect();
        if !file.contains("bench/") || keys.len() < 2 || keys.contains(&"*") || keys.iter().any(|k| k.contains('#')) {
            return None;
        }
        let files = self.files.borrow();
        let mut text = files.get(&folder.join(file))?.as_str();
        if let Some(below) = below {
            text = first_table(&text[text.find(below)?..]);
        }
        let mut frame_keys: Vec<&str> = keys[..keys.len() - 1].to_vec();
        frame_keys.extend(["frame", "@$"]);
        let id = table_cells(text, &frame_keys)
            .ok()
            .and_then(|cells| cells.first().map(|c| c.to_string()))
            .filter(|id| id.chars().all(|c| c.is_ascii_hexdigit()));
        Some(FrameTag { table: file.replace("/gpu/", "/"), file: file.to_string(), row: keys[0].to_string(), id })
    }

    /// The numbers a source `[FILE | …]` names (`None` for words at `@`),
    /// and their text there: one, or for a `*` row, every row's.
    fn source(&self, folder: &Path, spec: &str) -> anyhow::Result<Vec<(Option<f64>, String)>> {
        let parts = split_parts(spec);
        let (file, below) = match parts[0].split_once(" > ") {
            Some((file, below)) => (file.trim(), Some(below.trim())),
            None => (parts[0].as_str(), None),
        };
        let keys: Vec<&str> = parts[1..].iter().map(String::as_str).collect();
        ensure!(!keys.is_empty(), "`[{spec}]` names a file but nothing in it");
        let path = folder.join(file);
        let mut files = self.files.borrow_mut();
        if !files.contains_key(&path) {
            let text = std::fs::read_to_string(&path).with_context(|| format!("cannot read {file}"))?;
            files.insert(path.clone(), text);
        }
        let mut text = files[&path].as_str();
        if let Some(below) = below {
            let at = text.find(below).with_context(|| format!("{file} has no line holding `{below}`"))?;
            // The table below that line, and no later one.
            text = first_table(&text[at..]);
        }
        let code = file.ends_with(".rs") || file.ends_with(".wgsl");
        let found = match keys[..] {
            [name] if code && is_identifier(name) => vec![
                find_in_lines(text, &format!("const {name}: * = #;"))?
                    .with_context(|| format!("{file} has no `const {name}: … = NUMBER;`"))?,
            ],
            [pattern] if pattern.contains(['#', '@']) => vec![
                find_in_lines(text, pattern)?.with_context(|| format!("{file} has no line matching `{pattern}`"))?,
            ],
            ["*", pattern] if pattern.contains('#') => {
                let every: Vec<&str> = text
                    .lines()
                    .map(|line| find_in_lines(line, pattern))
                    .collect::<anyhow::Result<Vec<_>>>()?
                    .into_iter()
                    .flatten()
                    .collect();
                ensure!(!every.is_empty(), "{file} has no line matching `{pattern}`");
                every
            }
            _ => table_cells(text, &keys).with_context(|| format!("in {file}"))?,
        };
        let words = keys.last().is_some_and(|k| k.contains('@'));
        found.into_iter().map(|f| Ok((if words { None } else { Some(number_value(f)?) }, f.to_string()))).collect()
    }
}

/// The heading of a bench table's frames section, as `common::fingerprint`
/// writes it (xtask does not link `common`; its test below reads one).
pub const FRAMES_HEADING: &str = "Frames timed, each as its fingerprint describes it";

/// The frames a bench table timed, as (row, frame, samples, passes): from
/// its frames section (a chapter's table), or else from a `frame` column
/// (the sizes table, a row per chapter; samples and passes unknown there).
/// `None` for a table from before frames were fingerprinted.
fn frames_of(table: &str) -> Option<Vec<[String; 4]>> {
    let cells = |line: &str| -> Vec<String> { line.split('|').map(|c| c.trim().to_string()).collect() };
    if let Some(at) = table.find(FRAMES_HEADING) {
        return Some(
            table[at..]
                .lines()
                .map(cells)
                .filter(|c| c.len() == 6 && c[1] != "view" && !c[1].starts_with("---"))
                .map(|c| [c[1].clone(), c[2].clone(), c[3].clone(), c[4].clone()])
                .collect(),
        );
    }
    let lines: Vec<&str> = table.lines().collect();
    // A table's heading: the line above its `|---` line.
    let heading = (0..lines.len().saturating_sub(1))
        .find(|&i| lines[i + 1].starts_with("|-") && cells(lines[i]).iter().any(|c| c == "frame"))?;
    let column = cells(lines[heading]).iter().position(|c| c == "frame")?;
    let rows: Vec<[String; 4]> = lines[heading + 2..]
        .iter()
        .take_while(|l| l.starts_with('|'))
        .map(|l| cells(l))
        .filter(|c| c.len() > column && c[column].chars().all(|ch| ch.is_ascii_hexdigit()) && !c[column].is_empty())
        .map(|c| [c[1].clone(), c[column].clone(), String::new(), String::new()])
        .collect();
    (!rows.is_empty()).then_some(rows)
}

/// What a reader of `table` (measured elsewhere) must know of its frames
/// against `current`'s (the chapter's frames today): nothing when they
/// are the same; else a note, view by view.
fn older_frames_note(table: &str, current: &str) -> String {
    let Some(then) = frames_of(table) else {
        return "\n> **Timed on older frames.** These rows were measured before the bench recorded which frame \
                each one timed: the chapter may have changed since in what they cannot show (its samples a pixel, \
                its passes, its draws). The chapter's own table, measured on lavapipe, is current; the two are not \
                compared figure by figure.\n"
            .to_string();
    };
    let now = frames_of(current).unwrap_or_default();
    let mut changed = Vec::new();
    for [view, id, samples, passes] in &then {
        match now.iter().find(|row| &row[0] == view) {
            None => changed.push(format!("`{view}`: no longer a view of the chapter")),
            Some([_, now_id, now_samples, now_passes]) if now_id != id => {
                let mut what = Vec::new();
                if now_samples != samples {
                    what.push(format!("{samples} samples a pixel then, {now_samples} now"));
                }
                if now_passes != passes {
                    what.push(format!("it drew {passes} then; {now_passes} now"));
                }
                if what.is_empty() && samples.is_empty() {
                    what.push(format!("frame {id} then, {now_id} now"));
                } else if what.is_empty() {
                    what.push("its settings changed".to_string());
                }
                changed.push(format!("`{view}`: {}", what.join("; ")))
            }
            Some(_) => {}
        }
    }
    for [view, ..] in &now {
        if !then.iter().any(|row| &row[0] == view) {
            changed.push(format!("`{view}`: not measured here (a view added since)"));
        }
    }
    if changed.is_empty() {
        return String::new();
    }
    format!(
        "\n> **Timed on older frames.** Some rows here timed a frame the chapter no longer draws:\n>\n{}\n",
        changed.iter().map(|c| format!("> - {c}")).collect::<Vec<_>>().join("\n")
    )
}

/// `text` up to the end of its first table (all of it if it has none).
fn first_table(text: &str) -> &str {
    let mut offset = 0;
    let mut in_table = false;
    for line in text.split_inclusive('\n') {
        let row = line.trim_start().starts_with('|');
        if in_table && !row {
            return &text[..offset];
        }
        in_table |= row;
        offset += line.len();
    }
    text
}

/// The frame a bench row was timed on ([`Figures::frame_tag`]).
#[derive(Clone, Debug)]
struct FrameTag {
    /// The table, wherever it was measured (`bench/x.md` for `bench/gpu/x.md`).
    table: String,
    file: String,
    row: String,
    id: Option<String>,
}

/// A figure or check may combine the same view's rows from two tables
/// (a GPU's and lavapipe's) only if both timed the same frame: a ratio of
/// a one-sample frame to a four-sample one says nothing.
fn same_frames(frames: &[FrameTag]) -> anyhow::Result<()> {
    for (i, a) in frames.iter().enumerate() {
        for b in &frames[i + 1..] {
            if a.table == b.table && a.file != b.file && a.row == b.row && (a.id.is_none() || a.id != b.id) {
                let frame = |t: &FrameTag| t.id.clone().map_or("no recorded frame".into(), |id| format!("frame {id}"));
                bail!(
                    "combines `{} | {}` timed on {} with `{} | {}` timed on {}: measure again, or compare rows of one frame",
                    a.file,
                    a.row,
                    frame(a),
                    b.file,
                    b.row,
                    frame(b)
                );
            }
        }
    }
    Ok(())
}

/// The byte offset of the next directive this preprocessor writes.
fn next_directive(text: &str) -> Option<usize> {
    [FIGURE, CHECK, RUN, VIEW, CITED, MEASURED, EXTERNAL].iter().filter_map(|d| text.find(d)).min()
}

/// The way from `page` (`book/src/05-instancing/gpu.md`, or a name
/// relative to `book/src`) up to the book's root: `../` per folder.
fn to_root(page: &str) -> String {
    let inside = page.strip_prefix("book/src/").unwrap_or(page);
    "../".repeat(inside.matches('/').count())
}

/// `{{#run CHAPTER VIEW}}`: the command that runs the chapter on the view,
/// and the chapter itself on that view, live in the page. (Whether the
/// chapter has the view is the snapshot crate's check, `snapshots::book`,
/// which knows the chapters.)
fn run_line(page: &str, chapter: &str, view: &str) -> String {
    let root = to_root(page);
    let live = format!("{root}live/{chapter}/index.html?view={view}");
    format!(
        "```sh\ncargo run --release -p {chapter} -- --view {view}\n```\n\n\
         <iframe class=\"live-chapter\" loading=\"lazy\" src=\"{live}\" title=\"{chapter}, on its {view} view, \
         running live in this page\" width=\"100%\" height=\"420\" style=\"border: 0\"></iframe>\n\n\
         <small>The chapter itself, on its <code>{view}</code> view, running in your browser: click to start it, \
         then drag to look around and press F1 for its keys. <a href=\"{live}\">Open it on its own</a>; \
         <a href=\"{root}running-in-the-browser.html\">what differs from the desktop</a>.</small>\n"
    )
}

fn first_line(text: &str) -> &str {
    text.lines().next().unwrap_or_default()
}

/// How a computed figure is written: decimals, and thousands separators.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Format {
    decimals: usize,
    thousands: bool,
}

impl Format {
    fn write(self, value: f64) -> String {
        let text = format!("{value:.*}", self.decimals);
        if !self.thousands {
            return text;
        }
        let (sign, digits) = text.strip_prefix('-').map_or(("", text.as_str()), |d| ("-", d));
        let (whole, fraction) = digits.split_once('.').map_or((digits, None), |(w, f)| (w, Some(f)));
        let mut grouped = String::new();
        for (i, c) in whole.chars().enumerate() {
            if i > 0 && (whole.len() - i) % 3 == 0 {
                grouped.push(',');
            }
            grouped.push(c);
        }
        match fraction {
            Some(fraction) => format!("{sign}{grouped}.{fraction}"),
            None => format!("{sign}{grouped}"),
        }
    }
}

/// `EXPRESSION :FORMAT` into the expression and the format, if any. A
/// format is the last `:` outside brackets and quotes.
fn split_format(spec: &str) -> anyhow::Result<(&str, Option<Format>)> {
    let Some(colon) = outside_sources(spec).filter(|&(_, c)| c == ':').map(|(i, _)| i).last() else {
        return Ok((spec.trim(), None));
    };
    let written = spec[colon + 1..].trim();
    let (thousands, decimals) = match written.strip_prefix(',') {
        Some(rest) => (true, rest),
        None => (false, written),
    };
    let decimals = decimals
        .strip_prefix('.')
        .and_then(|d| d.parse().ok())
        .with_context(|| format!("the format `:{written}` is not `.N` or `,.N`"))?;
    Ok((spec[..colon].trim(), Some(Format { decimals, thousands })))
}

/// `A OP B` into its parts; OP outside brackets and quotes.
fn split_comparison(spec: &str) -> anyhow::Result<(&str, &'static str, &str)> {
    let chars: Vec<(usize, char)> = outside_sources(spec).collect();
    for (n, &(i, c)) in chars.iter().enumerate() {
        if c == '<' || c == '>' {
            let equal = chars.get(n + 1).is_some_and(|&(_, next)| next == '=');
            let op = match (c, equal) {
                ('<', false) => "<",
                ('<', true) => "<=",
                ('>', false) => ">",
                _ => ">=",
            };
            return Ok((spec[..i].trim(), op, spec[i + op.len()..].trim()));
        }
    }
    bail!("a check needs a comparison: `<`, `<=`, `>` or `>=`")
}

/// The characters of `text` that are outside `[…]` and `"…"`, with their
/// byte offsets.
fn outside_sources(text: &str) -> impl Iterator<Item = (usize, char)> + '_ {
    let (mut depth, mut quoted) = (0, false);
    text.char_indices().filter(move |&(_, c)| {
        let outside = depth == 0 && !quoted && c != '[' && c != '"';
        match c {
            '"' => quoted = !quoted,
            '[' if !quoted => depth += 1,
            ']' if !quoted => depth -= 1,
            _ => {}
        }
        outside
    })
}

/// The `|`-separated parts of a source, trimmed, quotes taken off.
fn split_parts(spec: &str) -> Vec<String> {
    let (mut parts, mut part, mut quoted) = (Vec::new(), String::new(), false);
    for c in spec.chars() {
        match c {
            '"' => quoted = !quoted,
            '|' if !quoted => parts.push(std::mem::take(&mut part)),
            _ => part.push(c),
        }
    }
    parts.push(part);
    parts.iter().map(|p| p.trim().to_string()).collect()
}

fn is_identifier(text: &str) -> bool {
    text.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && text.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// An expression, with what it was read from (for the messages).
enum Expression {
    Number(f64),
    /// A number, or words (`value` `None`) from an `@`.
    Source {
        spec: String,
        value: Option<f64>,
        text: String,
    },
    /// A source that named many rows (a `*` key): only for `min` and `max`.
    Many {
        spec: String,
        values: Vec<(f64, String)>,
    },
    Operation(Box<Expression>, char, Box<Expression>),
    /// `min(…)` (`least`) or `max(…)`.
    Extreme {
        least: bool,
        of: Vec<Expression>,
    },
}

impl Expression {
    fn value(&self) -> f64 {
        match self {
            Self::Number(value) => *value,
            Self::Source { value, .. } => value.unwrap_or(f64::NAN),
            Self::Many { .. } => f64::NAN,
            Self::Operation(a, op, b) => match op {
                '+' => a.value() + b.value(),
                '-' => a.value() - b.value(),
                '*' => a.value() * b.value(),
                _ => a.value() / b.value(),
            },
            Self::Extreme { least, of } => {
                let values = of.iter().flat_map(|e| match e {
                    Self::Many { values, .. } => values.iter().map(|(v, _)| *v).collect(),
                    _ => vec![e.value()],
                });
                // `f64::min` drops a NaN: a figure that failed to read must not vanish.
                let values: Vec<f64> = values.collect();
                if values.iter().any(|v| v.is_nan()) {
                    f64::NAN
                } else if *least {
                    values.into_iter().fold(f64::INFINITY, f64::min)
                } else {
                    values.into_iter().fold(f64::NEG_INFINITY, f64::max)
                }
            }
        }
    }

    /// Whether a source of many rows stands anywhere but as an argument of
    /// `min` or `max`.
    fn many_outside_extremes(&self) -> bool {
        match self {
            Self::Many { .. } => true,
            Self::Number(_) | Self::Source { .. } => false,
            Self::Operation(a, _, b) => a.many_outside_extremes() || b.many_outside_extremes(),
            Self::Extreme { of, .. } => of.iter().any(|e| !matches!(e, Self::Many { .. }) && e.many_outside_extremes()),
        }
    }

    /// Whether words from an `@` are part of it.
    fn has_words(&self) -> bool {
        let mut sources = Vec::new();
        self.sources(&mut sources);
        sources.iter().any(|s| s.starts_with("words "))
    }

    /// The value, and where each source's number came from.
    fn describe(&self) -> String {
        let mut sources = Vec::new();
        self.sources(&mut sources);
        let value = Format { decimals: 4, thousands: false }.write(self.value());
        if sources.is_empty() { value } else { format!("{value} ({})", sources.join(", ")) }
    }

    fn sources(&self, out: &mut Vec<String>) {
        match self {
            Self::Number(_) => {}
            Self::Source { spec, text, value } => {
                out.push(format!("{}[{spec}] = {text}", if value.is_none() { "words " } else { "" }))
            }
            Self::Operation(a, _, b) => {
                a.sources(out);
                b.sources(out);
            }
            Self::Extreme { of, .. } => of.iter().for_each(|e| e.sources(out)),
            Self::Many { spec, values } => {
                let texts: Vec<&str> = values.iter().map(|(_, t)| t.as_str()).collect();
                out.push(format!("[{spec}] = {}", texts.join(", ")))
            }
        }
    }
}

/// A recursive-descent reader of expressions.
struct Parser<'a> {
    text: &'a str,
    at: usize,
    figures: &'a Figures,
    folder: &'a Path,
    /// The frames of the bench rows read so far.
    frames: Vec<FrameTag>,
}

impl Parser<'_> {
    fn skip_spaces(&mut self) {
        self.at += self.text[self.at..].len() - self.text[self.at..].trim_start().len();
    }

    fn peek(&mut self) -> Option<char> {
        self.skip_spaces();
        self.text[self.at..].chars().next()
    }

    fn sum(&mut self) -> anyhow::Result<Expression> {
        let mut left = self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.at += 1;
            left = Expression::Operation(Box::new(left), op, Box::new(self.product()?));
        }
        Ok(left)
    }

    fn product(&mut self) -> anyhow::Result<Expression> {
        let mut left = self.factor()?;
        while let Some(op @ ('*' | '/')) = self.peek() {
            self.at += 1;
            left = Expression::Operation(Box::new(left), op, Box::new(self.factor()?));
        }
        Ok(left)
    }

    fn factor(&mut self) -> anyhow::Result<Expression> {
        match self.peek() {
            Some('(') => {
                self.at += 1;
                let inner = self.sum()?;
                ensure!(self.peek() == Some(')'), "a `(` without its `)` in `{}`", self.text);
                self.at += 1;
                Ok(inner)
            }
            Some('[') => {
                let rest = &self.text[self.at..];
                let end = outside_sources(rest)
                    .next()
                    .map_or(rest.len(), |(i, _)| i)
                    .checked_sub(1)
                    .filter(|&i| rest[i..].starts_with(']'))
                    .with_context(|| format!("a `[` without its `]` in `{}`", self.text))?;
                let spec = rest[1..end].trim().to_string();
                self.at += end + 1;
                let mut found = self.figures.source(self.folder, &spec)?;
                self.frames.extend(self.figures.frame_tag(self.folder, &spec));
                if found.len() == 1 {
                    let (value, text) = found.remove(0);
                    return Ok(Expression::Source { spec, value, text });
                }
                let values = found.into_iter().map(|(v, t)| (v.unwrap_or(f64::NAN), t)).collect();
                Ok(Expression::Many { spec, values })
            }
            Some('m') if ["min(", "max("].iter().any(|f| self.text[self.at..].starts_with(f)) => {
                let least = self.text[self.at..].starts_with("min(");
                self.at += 4;
                let mut of = vec![self.sum()?];
                while self.peek() == Some(',') {
                    self.at += 1;
                    of.push(self.sum()?);
                }
                ensure!(self.peek() == Some(')'), "a `min(` or `max(` without its `)` in `{}`", self.text);
                self.at += 1;
                Ok(Expression::Extreme { least, of })
            }
            _ => {
                let rest = &self.text[self.at..];
                let number = number_at(rest).with_context(|| {
                    format!("expected a number, a `[source]` or `(` at `{}`", rest.chars().take(20).collect::<String>())
                })?;
                self.at += number.len();
                Ok(Expression::Number(number_value(number)?))
            }
        }
    }
}

/// The number `text` starts with, as written: `-12.5`, `1,219`, `1_000_000`.
fn number_at(text: &str) -> Option<&str> {
    let bytes = text.as_bytes();
    let mut end = usize::from(bytes.first() == Some(&b'-'));
    let digits_from = end;
    let digit = |i: usize| bytes.get(i).is_some_and(u8::is_ascii_digit);
    while digit(end) {
        end += 1;
        // A separator belongs to the number when three digits follow it.
        if matches!(bytes.get(end), Some(b',' | b'_')) && (1..=3).all(|k| digit(end + k)) && !digit(end + 4) {
            end += 1;
        }
    }
    if end == digits_from {
        return None;
    }
    if bytes.get(end) == Some(&b'.') && digit(end + 1) {
        end += 1;
        while digit(end) {
            end += 1;
        }
    }
    Some(&text[..end])
}

fn number_value(text: &str) -> anyhow::Result<f64> {
    text.replace([',', '_'], "").parse().with_context(|| format!("`{text}` is not a number"))
}

/// One piece of a line pattern.
#[derive(Debug)]
enum Piece<'a> {
    Text(&'a str),
    Anything,
    Number,
    Words,
    End,
}

/// The number at `#` (or the words at `@`) in the first line of `text`
/// that `pattern` matches (anywhere in the line; a number is matched
/// whole, never its tail; words as few as let the rest match).
fn find_in_lines<'t>(text: &'t str, pattern: &str) -> anyhow::Result<Option<&'t str>> {
    ensure!(
        pattern.matches(['#', '@']).count() == 1,
        "a pattern holds one `#` (the number) or one `@` (the words): `{pattern}`"
    );
    // `^` holds the pattern to the start of the line, `$` to its end.
    let (from_start, pattern) = pattern.strip_prefix('^').map_or((false, pattern), |p| (true, p));
    let (to_end, pattern) = pattern.strip_suffix('$').map_or((false, pattern), |p| (true, p));
    let mut pieces = Vec::new();
    let mut rest = pattern;
    while let Some(at) = rest.find(['*', '#', '@']) {
        if at > 0 {
            pieces.push(Piece::Text(&rest[..at]));
        }
        pieces.push(match &rest[at..at + 1] {
            "*" => Piece::Anything,
            "#" => Piece::Number,
            _ => Piece::Words,
        });
        rest = &rest[at + 1..];
    }
    if !rest.is_empty() {
        pieces.push(Piece::Text(rest));
    }
    if to_end {
        pieces.push(Piece::End);
    }
    let starts = |line: &str| {
        let last = if from_start { 0 } else { line.len() };
        (0..=last).filter(|&i| line.is_char_boundary(i)).collect::<Vec<_>>()
    };
    Ok(text.lines().find_map(|line| starts(line).into_iter().find_map(|i| matches(line, i, &pieces))))
}

/// Whether `line` from byte `at` on starts with `pieces`; the number at
/// their `#` if so.
fn matches<'t>(line: &'t str, at: usize, pieces: &[Piece]) -> Option<&'t str> {
    let Some((first, rest)) = pieces.split_first() else { return Some("") };
    match first {
        Piece::Text(text) => line[at..].starts_with(text).then(|| matches(line, at + text.len(), rest)).flatten(),
        Piece::Number => {
            let inside_a_number = line[..at].ends_with(|c: char| c.is_ascii_digit() || c == '.' || c == ',');
            let number = number_at(&line[at..]).filter(|_| !inside_a_number)?;
            matches(line, at + number.len(), rest).map(|_| number)
        }
        Piece::Words => (at + 1..=line.len())
            .filter(|&i| line.is_char_boundary(i))
            .find_map(|i| matches(line, i, rest).map(|_| line[at..i].trim()))
            .filter(|words| !words.is_empty()),
        Piece::End => (at == line.len()).then_some(""),
        Piece::Anything => (at..=line.len()).filter(|&i| line.is_char_boundary(i)).find_map(|i| matches(line, i, rest)),
    }
}

/// `cell` as a key sees it: `1280 × 720` is `1280x720`.
fn normalised(cell: &str) -> String {
    cell.replace(" × ", "x").replace('×', "x")
}

/// Whether a cell (or a heading) is named by `key`: it is the key, or starts
/// with it and goes on with something other than a letter, digit or `-`
/// (`frame` names `frame (CPU+GPU)`, `default` does not name `default-2`).
fn names(cell: &str, key: &str) -> bool {
    let (cell, key) = (normalised(cell), normalised(key));
    cell.strip_prefix(&key).is_some_and(|rest| rest.chars().next().is_none_or(|c| !(c.is_alphanumeric() || c == '-')))
}

/// The number in the first table of `text` with a row named by `keys`
/// (all but the column), in the column named by the last key, or at the `#`
/// of a last key that holds one; with a `*` key, the number in every row
/// it names.
fn table_cells<'t>(text: &'t str, keys: &[&str]) -> anyhow::Result<Vec<&'t str>> {
    let (keys, pick) = match keys.split_last() {
        Some((last, rest)) if last.contains(['#', '@']) => (rest, Some(*last)),
        _ => (keys, None),
    };
    let Some((column, row_keys)) = keys.split_last().filter(|(_, rows)| !rows.is_empty()) else {
        bail!("a table's cell needs a row and a column: `[FILE | ROW… | COLUMN]`");
    };
    let cells = |line: &'t str| -> Vec<&'t str> {
        let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
        inner.split('|').map(str::trim).collect()
    };
    let lines: Vec<&str> = text.lines().collect();
    let mut tables_seen = 0;
    let mut column_missing = None;
    let mut at = 0;
    while at + 1 < lines.len() {
        // A table: a heading line, then a line of `---`.
        if !(lines[at].trim_start().starts_with('|') && lines[at + 1].trim_start().starts_with("|-")) {
            at += 1;
            continue;
        }
        tables_seen += 1;
        let heading = cells(lines[at]);
        let rows: Vec<Vec<&str>> =
            lines[at + 2..].iter().take_while(|l| l.trim_start().starts_with('|')).map(|l| cells(l)).collect();
        at += 2 + rows.len();
        let named: Vec<&Vec<&str>> = rows
            .iter()
            .filter(|row| {
                row.len() >= row_keys.len() && row_keys.iter().zip(row.iter()).all(|(k, c)| *k == "*" || names(c, k))
            })
            .collect();
        let many = row_keys.contains(&"*");
        match named[..] {
            [] => continue,
            [_] | [_, _, ..] if many || named.len() == 1 => {
                let Some(index) = heading.iter().position(|h| names(h, column)) else {
                    column_missing = Some(heading.join(" | "));
                    continue;
                };
                let number = |row: &Vec<&'t str>| -> anyhow::Result<&'t str> {
                    let cell = row.get(index).with_context(|| format!("the row `{}` is short", row.join(" | ")))?;
                    match pick {
                        Some(pattern) => find_in_lines(cell, pattern)?
                            .with_context(|| format!("the cell `{cell}` does not match `{pattern}`")),
                        None => number_at(cell.trim_start_matches(|c: char| !(c.is_ascii_digit() || c == '-')))
                            .with_context(|| format!("the cell `{cell}` holds no number")),
                    }
                };
                return named.into_iter().map(number).collect();
            }
            _ => bail!(
                "`{}` names {} rows: {}; write more of the cells",
                row_keys.join(" | "),
                named.len(),
                named.iter().map(|r| format!("`{}`", r.join(" | "))).collect::<Vec<_>>().join(", ")
            ),
        }
    }
    match column_missing {
        Some(heading) => bail!("no column `{column}` (the headings: {heading})"),
        None if tables_seen == 0 => bail!("no table"),
        None => bail!("no row `{}`", row_keys.join(" | ")),
    }
}

/// The book's pages in `src`: every `.md` file in it and in its chapters'
/// folders (the bench tables in `bench/` are sources, not pages).
fn pages(src: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut pages = Vec::new();
    for entry in std::fs::read_dir(src).with_context(|| format!("cannot read {}", src.display()))? {
        let path = entry?.path();
        let name = path.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default();
        if path.is_dir() && !["bench", "figures", "diagrams", "pictures"].contains(&name.as_str()) {
            pages.extend(pages_in(&path)?);
        } else if path.extension().is_some_and(|e| e == "md") {
            pages.push(path);
        }
    }
    pages.sort();
    Ok(pages)
}

fn pages_in(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut pages = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.extension().is_some_and(|e| e == "md") {
            pages.push(path);
        }
    }
    Ok(pages)
}

/// Every problem on every page of `src`, each on a line of its own.
fn check_pages(src: &Path) -> anyhow::Result<Vec<String>> {
    let figures = Figures::new();
    let mut problems = Vec::new();
    for page in pages(src)? {
        let text = std::fs::read_to_string(&page)?;
        let name = page.strip_prefix(crate::root()).unwrap_or(&page).display().to_string();
        if let Err(found) = figures.expand(&name, page.parent().unwrap_or(src), &text) {
            problems.extend(found);
        }
    }
    Ok(problems)
}

/// `cargo xtask figures [PAGE…]`: every page's figures and listings
/// checked, as the book's build and `cargo xtask test` check them; each PAGE named (`frame-rates.md`)
/// printed with its figures written, to read what a reader will.
pub fn run(pages_to_print: &[String]) -> anyhow::Result<()> {
    let src = crate::root().join("book/src");
    let problems = check_pages(&src)?;
    ensure!(problems.is_empty(), "figures that do not match their sources:\n  {}", problems.join("\n  "));
    let broken = crate::book::check_includes(&src)?;
    ensure!(broken.is_empty(), "broken listings in the book:\n  {}", broken.join("\n  "));
    for name in pages_to_print {
        let path = src.join(name);
        let text = std::fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
        let folder = path.parent().unwrap_or(&src);
        let expanded = Figures::new().expand(name, folder, &text).map_err(|p| anyhow::anyhow!(p.join("\n")))?;
        print!("{expanded}");
    }
    println!("every figure on the book's pages matches its source");
    Ok(())
}

/// The mdBook preprocessor `cargo xtask book` adds: every page's figures
/// written, its checks gone, or the build fails with every problem.
pub struct Preprocessor;

impl mdbook_preprocessor::Preprocessor for Preprocessor {
    fn name(&self) -> &str {
        "figures"
    }

    fn run(
        &self,
        context: &mdbook_preprocessor::PreprocessorContext,
        mut book: mdbook_preprocessor::book::Book,
    ) -> anyhow::Result<mdbook_preprocessor::book::Book> {
        let src = context.root.join(&context.config.book.src);
        let figures = Figures::new();
        let mut problems = Vec::new();
        book.for_each_chapter_mut(|chapter| {
            let Some(path) = &chapter.source_path else { return };
            let page = format!("book/src/{}", path.display());
            let folder = src.join(path.parent().unwrap_or(Path::new("")));
            match figures.expand(&page, &folder, &chapter.content) {
                Ok(expanded) => chapter.content = expanded,
                Err(found) => problems.extend(found),
            }
        });
        ensure!(problems.is_empty(), "figures that do not match their sources:\n  {}", problems.join("\n  "));
        Ok(book)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder with a bench table, a saved run's note and a constant, as
    /// the book's sources are; one folder per test (they run side by side).
    fn sources(test: &str) -> PathBuf {
        let folder = std::env::temp_dir().join(format!("xtask-figures-{test}-{}", std::process::id()));
        std::fs::create_dir_all(folder.join("bench")).unwrap();
        std::fs::write(
            folder.join("bench/fog.md"),
            "Measured by …: fog on Some GPU, 1280x720.\n\n| view | what | min ms | median ms | p95 ms |\n\
             |---|---|---:|---:|---:|\n| default | frame (CPU+GPU) | 278.67 | 289.49 | 307.27 |\n\
             | default | GPU: terrain pass | 278.17 | 288.98 | 306.70 |\n| default-2 | frame (CPU+GPU) | 1 | 2 | 3 |\n\
             | dense | frame (CPU+GPU) | 45.60 | 46.78 | 50.40 |\n\n\
             - default: setup (`Chapter::new`) 1417 ms; far plane 2088 m; 1,051 of 4096 chunks drawn\n\n\
             The second:\n\n| chapter | 1280 × 720 |\n|---|---:|\n| fog (`day`) | 8.50 ms, 117.6 FPS |\n",
        )
        .unwrap();
        std::fs::write(folder.join("code.rs"), "/// Rocks.\npub const MAX_ROCKS: u32 = 1_000_000;\n").unwrap();
        folder
    }

    fn expand(test: &str, text: &str) -> Result<String, Vec<String>> {
        Figures::new().expand("page.md", &sources(test), text)
    }

    #[test]
    fn figures_come_from_table_cells_lines_and_constants() {
        let page = "a {{#figure [bench/fog.md | default | frame | median]}} ms frame, \
                    pass {{#figure [bench/fog.md | default | GPU: terrain | p95]}}; \
                    {{#figure [bench/fog.md | - default: * far plane # m]}} m, \
                    {{#figure [bench/fog.md | # of 4096 chunks]}} chunks, \
                    {{#figure [bench/fog.md | fog on @, 1280x720]}}, \
                    {{#figure [bench/fog.md | ^- default: * # ms]}} and {{#figure [bench/fog.md | # of 4096 chunks drawn$]}}, \
                    {{#figure [bench/fog.md > The second | fog | 1280x720 | # FPS]}} FPS, \
                    {{#figure [code.rs | MAX_ROCKS]}} rocks, \
                    {{#figure [code.rs | MAX_ROCKS] / 4 :,.0}} a quarter, \
                    {{#figure max(2, min(7, [bench/fog.md | dense | frame | median]), 3) :.0}} at most, \
                    {{#figure min([bench/fog.md | * | frame | median]) :.2}} to {{#figure max([bench/fog.md | * | frame | median]) :.2}}, \
                    {{#figure max([bench/fog.md | * | # ms]) :.0}}, \
                    {{#figure ([bench/fog.md | default | frame | median] - 1) / [bench/fog.md | dense | frame | median] :.2}}×.";
        assert_eq!(
            expand("cells", page).unwrap(),
            "a 289.49 ms frame, pass 306.70; 2088 m, 1,051 chunks, Some GPU, 1417 and 1,051, 117.6 FPS, 1_000_000 rocks, 250,000 a quarter, 7 at most, 2.00 to 289.49, 1417, 6.17×."
        );
    }

    #[test]
    fn a_check_writes_nothing_while_it_holds_and_fails_naming_its_sources_when_not() {
        let holds =
            "fog{{#check [bench/fog.md | dense | frame | median] * 6 < [bench/fog.md | default | frame | median]}}.";
        assert_eq!(expand("checks", holds).unwrap(), "fog.");
        let fails =
            "{{#check [bench/fog.md | dense | frame | median] * 7 <= [bench/fog.md | default | frame | median]}}";
        let problems = expand("checks", fails).unwrap_err();
        assert_eq!(problems.len(), 1);
        assert!(
            problems[0].starts_with("page.md: {{#check [bench/fog.md | dense")
                && problems[0]
                    .contains("no longer true: 327.4600 ([bench/fog.md | dense | frame | median] = 46.78) <= 289.4900"),
            "{problems:?}"
        );
    }

    #[test]
    fn a_missing_row_column_file_or_line_names_the_page_the_figure_and_the_source() {
        let cases = [
            ("{{#figure [bench/fog.md | night | frame | median]}}", "in bench/fog.md: no row `night | frame`"),
            ("{{#figure [bench/fog.md | default | frame | mean]}}", "no column `mean`"),
            ("{{#figure [bench/fog.md | default | median]}}", "names 2 rows"),
            ("{{#figure [bench/sky.md | day | frame | median]}}", "cannot read bench/sky.md"),
            ("{{#figure [bench/fog.md | near plane # m]}}", "bench/fog.md has no line matching `near plane # m`"),
            ("{{#figure [code.rs | MAX_TREES]}}", "code.rs has no `const MAX_TREES"),
            ("{{#figure [bench/fog.md | far plane #$]}}", "no line matching `far plane #$`"),
            ("{{#figure [bench/fog.md | ^far plane #]}}", "no line matching `^far plane #`"),
            ("{{#figure [bench/fog.md | # of # chunks]}}", "one `#` (the number)"),
            ("{{#figure [bench/fog.md | fog on @, #x720]}}", "one `#` (the number)"),
            ("{{#figure [bench/fog.md | fog on @, 1280x720] :.1}}", "words (from an `@`) have no format"),
            ("{{#check [bench/fog.md | fog on @, 1280x720] < 1}}", "cannot be compared"),
            ("{{#figure [bench/fog.md | dense | frame | median] * 2}}", "needs a format"),
            ("{{#figure [bench/fog.md | dense | frame | median] :2}}", "is not `.N`"),
            ("{{#check 1 = 1}}", "needs a comparison"),
            ("{{#figure [bench/fog.md | * | frame | median] :.1}}", "use it inside `min(…)` or `max(…)`"),
            ("{{#figure min([bench/fog.md | * | frame | median] * 2) :.1}}", "use it inside `min(…)` or `max(…)`"),
            ("{{#figure [bench/fog.md | dense | frame | median}}", "without its `]`"),
        ];
        for (page, expected) in cases {
            let problems = expand("problems", &format!("text {page} text")).unwrap_err();
            assert!(
                problems.len() == 1
                    && problems[0].starts_with(&format!("page.md: {page}: "))
                    && problems[0].contains(expected),
                "{page}: {problems:?}"
            );
        }
        // Every problem on a page is reported, not only the first.
        let two = "{{#figure [bench/a.md | x | y]}} and {{#figure [bench/b.md | x | y]}}";
        assert_eq!(expand("problems", two).unwrap_err().len(), 2);
    }

    /// A chapter's table on lavapipe and the same measured on a GPU, each
    /// with its frames; `gpu_frame` is the GPU run's frame of `default`.
    fn two_tables(test: &str, gpu_frame: &str) -> PathBuf {
        let folder = std::env::temp_dir().join(format!("xtask-frames-{test}-{}", std::process::id()));
        std::fs::create_dir_all(folder.join("bench/gpu")).unwrap();
        let table = |frame: &str, median: &str| {
            format!(
                "| view | what | min ms | median ms | p95 ms | frame |\n|---|---|---:|---:|---:|---|\n\
                 | default | frame (CPU+GPU) | 1 | {median} | 3 | {frame} |\n\
                 | dense | frame (CPU+GPU) | 1 | 2 | 3 | 0000dddd |\n\n\
                 {FRAMES_HEADING} (drawn at 800 × 450):\n\n| view | frame | samples | passes |\n|---|---|---:|---|\n\
                 | default | {frame} | {} | terrain: 1 draw, 10 triangles |\n| dense | 0000dddd | 4 | terrain: 1 draw, 5 triangles |\n",
                if frame == "aaaa0000" { 4 } else { 1 }
            )
        };
        std::fs::write(folder.join("bench/fog.md"), table("aaaa0000", "100")).unwrap();
        std::fs::write(folder.join("bench/gpu/fog.md"), table(gpu_frame, "1")).unwrap();
        std::fs::write(
            folder.join("bench/gpu/old.md"),
            "| view | what | median ms |\n|---|---|---:|\n| default | frame | 1 |\n",
        )
        .unwrap();
        std::fs::write(folder.join("bench/old.md"), table("aaaa0000", "100")).unwrap();
        folder
    }

    #[test]
    fn rows_of_one_view_timed_on_different_frames_are_not_combined() {
        let ratio =
            "{{#figure [bench/fog.md | default | frame | median] / [bench/gpu/fog.md | default | frame | median] :.0}}";
        // Same frame: a like-for-like ratio.
        assert_eq!(Figures::new().expand("page.md", &two_tables("same", "aaaa0000"), ratio).unwrap(), "100");
        // The GPU timed an older frame (one sample a pixel): refused, naming both.
        let problems = Figures::new().expand("page.md", &two_tables("other", "bbbb1111"), ratio).unwrap_err();
        assert!(
            problems[0].contains("timed on frame aaaa0000") && problems[0].contains("frame bbbb1111"),
            "{problems:?}"
        );
        // A table from before fingerprints, in a check too.
        let check =
            "{{#check [bench/old.md | default | frame | median] > [bench/gpu/old.md | default | frame | median]}}";
        let problems = Figures::new().expand("page.md", &two_tables("old", "aaaa0000"), check).unwrap_err();
        assert!(problems[0].contains("no recorded frame"), "{problems:?}");
        // Two views of one table are two frames by design: allowed.
        let views =
            "{{#figure [bench/fog.md | default | frame | median] / [bench/fog.md | dense | frame | median] :.0}}";
        assert_eq!(Figures::new().expand("page.md", &two_tables("views", "aaaa0000"), views).unwrap(), "50");
    }

    #[test]
    fn a_table_measured_elsewhere_is_marked_with_what_changed_since() {
        let page = "{{#measured bench/gpu/fog.md}}";
        let same = Figures::new().expand("page.md", &two_tables("mark-same", "aaaa0000"), page).unwrap();
        assert!(!same.contains("older frames"), "{same}");
        let older = Figures::new().expand("page.md", &two_tables("mark-older", "bbbb1111"), page).unwrap();
        assert!(older.contains("`default`: 1 samples a pixel then, 4 now"), "{older}");
        assert!(!older.contains("`dense`"), "{older}");
        let unknown =
            Figures::new().expand("page.md", &two_tables("mark-old", "aaaa0000"), "{{#measured bench/gpu/old.md}}");
        assert!(unknown.unwrap().contains("before the bench recorded which frame"));
    }

    #[test]
    fn a_missing_figure_in_min_or_max_fails_and_a_table_after_a_line_is_only_that_table() {
        let folder = sources("nan");
        // `f64::min` drops a NaN (a median of 0 divided by another): it
        // printed 3 here.
        assert_eq!(Figures::new().expand("page.md", &folder, "{{#figure min(2, 3) :.0}}").unwrap(), "2");
        let problems = Figures::new().expand("page.md", &folder, "{{#figure min(0 / 0, 3) :.0}}").unwrap_err();
        assert!(problems[0].contains("is not a finite number"), "{problems:?}");
        let problems = Figures::new().expand("page.md", &folder, "{{#check max(0 / 0, 3) > 1}}").unwrap_err();
        assert!(problems[0].contains("not a number"), "{problems:?}");
        let second = "{{#figure [bench/fog.md > The second | default | frame | median]}}";
        let problems = Figures::new().expand("page.md", &folder, second).unwrap_err();
        assert!(problems[0].contains("no row `default | frame`"), "{problems:?}");
    }

    #[test]
    fn numbers_and_formats_are_read_and_written_as_pages_write_them() {
        assert_eq!(number_at("1,219 of"), Some("1,219"));
        assert_eq!(number_at("0.08, 0.15"), Some("0.08"));
        assert_eq!(number_at("1_000_000;"), Some("1_000_000"));
        assert_eq!(number_at("-3.5 m"), Some("-3.5"));
        assert_eq!(number_at("12,34"), Some("12"));
        assert_eq!(number_at("x"), None);
        let format = |decimals, thousands| Format { decimals, thousands };
        assert_eq!(format(0, true).write(1_234_567.4), "1,234,567");
        assert_eq!(format(1, true).write(-1234.56), "-1,234.6");
        assert_eq!(format(2, false).write(19.0), "19.00");
    }

    /// The preprocessor in mdBook's own build, as `cargo xtask book` runs
    /// it (the HTML only: no snapshots, diagrams or WebAssembly): the pages
    /// come out with their figures written and no directive left.
    #[test]
    fn the_built_book_has_its_figures_written() {
        let out = std::env::temp_dir().join(format!("xtask-figures-book-{}", std::process::id()));
        let mut book = mdbook_driver::MDBook::load(crate::root().join("book")).unwrap();
        book.config.build.build_dir = out.clone();
        book.with_preprocessor(Preprocessor).build().unwrap();
        let page = std::fs::read_to_string(out.join("frame-rates.html")).unwrap();
        let gpu_sizes = std::fs::read_to_string(crate::root().join("book/src/bench/gpu/sizes.md")).unwrap();
        let threads = gpu_sizes.split(" threads.").next().and_then(|before| before.rsplit(' ').next()).unwrap();
        std::fs::remove_dir_all(&out).unwrap();
        assert!(!page.contains("{{#figure") && !page.contains("{{#check"), "a directive was left in the page");
        // The thread count, written from `gpu.txt`, as the sizes table names it.
        let written = format!("with a {threads}-thread Intel Xeon");
        assert!(page.contains(&written), "frame-rates.html should say `{written}`");
    }

    /// Every page of the book, expanded as `cargo xtask book` does: a
    /// figure whose row, column, line or constant is gone, or a check that
    /// no longer holds, fails here, without building the book.
    #[test]
    fn every_figure_on_every_page_comes_from_its_source_and_every_check_holds() {
        let src = crate::root().join("book/src");
        let problems = check_pages(&src).unwrap();
        assert!(problems.is_empty(), "figures that do not match their sources:\n  {}", problems.join("\n  "));
    }
}
