//! The book read as a learner meets it, and held to the shape a lesson
//! must have. Each chapter is a section: an opening page
//! (`NN-name/index.md`) that lists its lessons and its reference pages,
//! then those pages. The checks, each naming the page and what is wrong:
//!
//! - no page holds more than [`WORD_LIMIT`] words of prose (code, tables,
//!   markup and directives left out);
//! - a lesson opens with the run line of the view it teaches
//!   (`{{#run CHAPTER VIEW}}`, which the book's build writes as the
//!   command and the live frame on that view) and what to look for, and
//!   ends with its exercises, its questions (each answer folded) and a
//!   recap;
//! - every `{{#run …}}` and `{{#view …}}` names a chapter and one of its
//!   views, and every view of every chapter is named on one of its
//!   chapter's lessons;
//! - every link between pages resolves, to the page and to the heading;
//! - every "exercise N" names an exercise that exists: on its own page,
//!   or on the page its link goes to;
//! - every page is in the summary, and the summary's chapters come in the
//!   order of `course::chapters()`;
//! - what prose names in code font is there: a file, type, function or
//!   constant of the workspace ([`CodeIndex`]), and a view of the page's
//!   chapter is named by `{{#view …}}`;
//! - no measured quantity is typed into prose ([`typed_measurements`]):
//!   a figure comes from its table or code by `{{#figure …}}`, or is
//!   marked as quoted from its source by `{{#cited …}}`.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use common::anyhow;
use course::{Record, SubPage};

/// The most prose a page may hold: at 200 words a minute, a sitting.
pub const WORD_LIMIT: usize = 3_000;

/// The heading over an opening page's list of lessons, and over its list
/// of reference pages.
pub const LESSONS_HEADING: &str = "## The lessons";
pub const REFERENCE_HEADING: &str = "## Reference pages";

/// The line that follows a lesson's run line: what the learner should see.
pub const LOOK_FOR: &str = "**Look for:**";

/// `book/src`.
pub fn book_src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../book/src")
}

/// A page of the book: its file, relative to `book/src` (with `/`), and
/// its text.
#[derive(Clone, Debug)]
pub struct Page {
    pub file: String,
    pub text: String,
}

/// Every page under `src`: the Markdown files, but not the bench tables,
/// the copied figures and diagrams, or the summary.
pub fn read_pages(src: &Path) -> anyhow::Result<Vec<Page>> {
    fn walk(src: &Path, dir: &Path, pages: &mut Vec<Page>) -> anyhow::Result<()> {
        for entry in std::fs::read_dir(dir)? {
            let path = entry?.path();
            let relative = path.strip_prefix(src)?.to_string_lossy().replace('\\', "/");
            if path.is_dir() {
                if !["bench", "figures", "diagrams", "pictures"].contains(&relative.as_str()) {
                    walk(src, &path, pages)?;
                }
            } else if path.extension().is_some_and(|e| e == "md") && relative != "SUMMARY.md" {
                pages.push(Page { file: relative, text: std::fs::read_to_string(&path)? });
            }
        }
        Ok(())
    }
    let mut pages = Vec::new();
    walk(src, src, &mut pages)?;
    pages.sort_by(|a, b| a.file.cmp(&b.file));
    Ok(pages)
}

/// The lines of `text` outside fenced code blocks, with their numbers
/// (from 1).
fn outside_code(text: &str) -> Vec<(usize, &str)> {
    let mut fence: Option<&str> = None;
    let mut lines = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        match fence {
            Some(f) if trimmed.starts_with(f) => fence = None,
            Some(_) => {}
            None if trimmed.starts_with("```") => fence = Some("```"),
            None if trimmed.starts_with("~~~") => fence = Some("~~~"),
            None => lines.push((i + 1, line)),
        }
    }
    lines
}

/// `line` without its `{{#…}}` directives (each left as one word: a
/// figure is a number in the text), HTML tags, link targets and image
/// lines: what a reader reads as words.
pub fn prose_of(line: &str) -> String {
    let trimmed = line.trim();
    if trimmed.starts_with('|') || trimmed.starts_with("![") {
        return String::new();
    }
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("{{#") {
            let end = after.find("}}").map_or(after.len(), |e| e + 2);
            let directive = &after[..end.min(after.len())];
            // A run line is a command and a frame, not prose; a figure or a
            // view's name reads as one word; a check prints nothing.
            if directive.starts_with("figure") || directive.starts_with("view") {
                out.push_str(" x ");
            }
            rest = &after[end.min(after.len())..];
        } else if let Some(after) = rest.strip_prefix("](") {
            let end = after.find(')').map_or(after.len(), |e| e + 1);
            out.push(' ');
            rest = &after[end..];
        } else if let Some(after) = rest.strip_prefix('<') {
            // A tag starts with a letter or `/`; `a < b` is prose.
            match after.find('>').filter(|_| after.starts_with(|c: char| c.is_ascii_alphabetic() || c == '/')) {
                Some(end) => {
                    out.push(' ');
                    rest = &after[end + 1..];
                }
                None => {
                    out.push('<');
                    rest = after;
                }
            }
        } else {
            let c = rest.chars().next().expect("not empty");
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// The words of prose in `text`: fenced code, tables, images, markup and
/// directives left out.
pub fn prose_words(text: &str) -> usize {
    outside_code(text)
        .into_iter()
        .map(|(_, line)| prose_of(line).split_whitespace().filter(|w| w.chars().any(char::is_alphanumeric)).count())
        .sum()
}

/// The units after which a number in prose is a measurement: a time, a
/// size in memory, a rate, a share or a ratio.
pub const MEASURED_UNITS: [&str; 14] =
    ["ms", "µs", "ns", "s", "MB", "KB", "GB", "MiB", "KiB", "GiB", "FPS", "%", "×", "times"];

/// `line` as prose, with inline code spans gone too.
fn prose_without_code(line: &str) -> String {
    let prose = prose_of(line);
    let mut out = String::with_capacity(prose.len());
    for (i, part) in prose.split('`').enumerate() {
        // Even parts are outside code spans.
        if i % 2 == 0 {
            out.push_str(part);
        } else {
            out.push(' ');
        }
    }
    out
}

/// Every measured quantity typed into the prose of `text`, as (line,
/// the number and its unit): a number followed by one of
/// [`MEASURED_UNITS`], outside code, tables, directives and HTML. A
/// figure belongs in a `{{#figure …}}` that reads it from its table or its
/// code, and a figure quoted from elsewhere (a paper, a seed's report) in
/// a `{{#cited TEXT | SOURCE}}`. A size (`1280 × 720`, `3×3`) is not a
/// ratio, and `s` and `times` count only after a space.
pub fn typed_measurements(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (number, line) in outside_code(text) {
        let prose: Vec<char> = prose_without_code(line).chars().collect();
        let mut i = 0;
        while i < prose.len() {
            let starts_number = prose[i].is_ascii_digit()
                && (i == 0 || !(prose[i - 1].is_alphanumeric() || matches!(prose[i - 1], '_' | '.' | ',' | '-' | '/')));
            if !starts_number {
                i += 1;
                continue;
            }
            let mut end = i;
            while end < prose.len()
                && (prose[end].is_ascii_digit()
                    || (matches!(prose[end], ',' | '.') && prose.get(end + 1).is_some_and(char::is_ascii_digit)))
            {
                end += 1;
            }
            let mut unit_at = end;
            while unit_at < prose.len() && matches!(prose[unit_at], ' ' | '\u{a0}' | '\u{202f}' | '\u{2009}') {
                unit_at += 1;
            }
            let spaced = unit_at > end;
            let rest: String = prose[unit_at..].iter().collect();
            let unit = MEASURED_UNITS.iter().find(|unit| {
                let Some(after) = rest.strip_prefix(**unit) else { return false };
                let bounded = !after.starts_with(|c: char| c.is_alphanumeric());
                match **unit {
                    "s" | "times" => spaced && bounded,
                    // `1280 × 720`, `3×3`: a size, not a ratio.
                    "×" => !after.trim_start().starts_with(|c: char| c.is_ascii_digit()),
                    "%" => true,
                    _ => bounded,
                }
            });
            if let Some(unit) = unit {
                let figure: String = prose[i..end].iter().collect();
                found.push((number, format!("{figure}{}{unit}", if spaced { " " } else { "" })));
            }
            i = end.max(i + 1);
        }
    }
    found
}

/// What prose may name in code font and have resolved: every identifier
/// in the workspace's Rust and WGSL, and every file in the repository.
pub struct CodeIndex {
    identifiers: BTreeSet<String>,
    files: Vec<String>,
}

impl CodeIndex {
    /// Reads the repository at `root` (its sources, shaders, assets and
    /// book; never `target/`).
    pub fn build(root: &Path) -> anyhow::Result<Self> {
        fn walk(root: &Path, dir: &Path, index: &mut CodeIndex) -> anyhow::Result<()> {
            for entry in std::fs::read_dir(dir)? {
                let path = entry?.path();
                let name = path.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default();
                if path.is_dir() {
                    let skipped = [".git", "target", ".gl", ".gpubench"].contains(&name.as_str());
                    if !(skipped || (name == "book" && dir.ends_with("book"))) {
                        walk(root, &path, index)?;
                    }
                    continue;
                }
                let relative = path.strip_prefix(root)?.to_string_lossy().replace('\\', "/");
                if name.ends_with(".rs") || name.ends_with(".wgsl") || name == "Cargo.toml" {
                    let text = std::fs::read_to_string(&path)?;
                    for word in text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')) {
                        if word.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
                            index.identifiers.insert(word.to_string());
                        }
                    }
                }
                index.files.push(relative);
            }
            Ok(())
        }
        let mut index = Self { identifiers: BTreeSet::new(), files: Vec::new() };
        walk(root, root, &mut index)?;
        Ok(index)
    }

    /// Whether `name`, written in code font in prose, is something in the
    /// workspace: a file (a path the repository's files end with), or an
    /// identifier (the last of a `::` path, `()` after a function
    /// allowed). `None` when it does not look like a name of code at all
    /// (a word, an expression, a flag, a number).
    pub fn resolves(&self, name: &str) -> Option<bool> {
        let name = name.trim();
        let looks_like_file = name.rsplit_once('.').is_some_and(|(stem, ext)| {
            !stem.is_empty()
                && ["rs", "wgsl", "toml", "png", "obj", "mtl", "svg", "glb", "gltf", "sh", "md"].contains(&ext)
                && !name.contains(' ')
        });
        if looks_like_file {
            let path = name.trim_start_matches("./");
            return Some(self.files.iter().any(|f| f == path || f.ends_with(&format!("/{path}"))));
        }
        let path = name.strip_suffix("()").unwrap_or(name);
        let segments: Vec<&str> = path.split("::").collect();
        let identifier = |s: &str| {
            s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
                && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        };
        if !segments.iter().all(|s| identifier(s)) {
            return None;
        }
        let last = segments.last().copied().unwrap_or_default();
        let camel =
            last.chars().skip(1).any(|c| c.is_ascii_uppercase()) && last.chars().any(|c| c.is_ascii_lowercase());
        let looks_like_code = segments.len() > 1 || last.contains('_') || camel;
        looks_like_code.then(|| self.identifiers.contains(last))
    }
}

/// The code spans in the prose of `text` (outside fenced code, tables and
/// directives), as (line, content).
pub fn code_spans(text: &str) -> Vec<(usize, String)> {
    let mut spans = Vec::new();
    for (number, line) in outside_code(text) {
        let prose = prose_of(line);
        for (i, part) in prose.split('`').enumerate() {
            if i % 2 == 1 && !part.is_empty() {
                spans.push((number, part.to_string()));
            }
        }
    }
    spans
}

/// A `{{#run CHAPTER VIEW}}` or `{{#view CHAPTER VIEW}}` on a page.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ViewNamed {
    pub run: bool,
    pub chapter: String,
    pub view: String,
    pub line: usize,
}

/// Every run line and view named on `text`, outside code.
pub fn views_named(text: &str) -> Vec<ViewNamed> {
    let mut found = Vec::new();
    for (number, line) in outside_code(text) {
        for (kind, run) in [("{{#run ", true), ("{{#view ", false)] {
            for (at, _) in line.match_indices(kind) {
                let rest = &line[at + kind.len()..];
                let body = &rest[..rest.find("}}").unwrap_or(rest.len())];
                let mut words = body.split_whitespace();
                found.push(ViewNamed {
                    run,
                    chapter: words.next().unwrap_or_default().to_string(),
                    view: words.next().unwrap_or_default().to_string(),
                    line: number,
                });
            }
        }
    }
    found
}

/// The pages an opening page lists under `heading` (its lessons, or its
/// reference pages): `1. [Title](file.md)…` or `- [Title](file.md)…`,
/// with the file relative to `folder`.
pub fn listed_pages(opening: &str, folder: &str, heading: &str) -> Vec<SubPage> {
    let mut pages = Vec::new();
    let mut inside = false;
    for (_, line) in outside_code(opening) {
        if line.starts_with("## ") {
            inside = line.trim_end() == heading;
            continue;
        }
        if !inside {
            continue;
        }
        let item = line.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start_matches(['.', '-', ' ']);
        let is_item = line != item && item.starts_with('[') && !line.starts_with(' ');
        if is_item && let Some((title, rest)) = item[1..].split_once("](") {
            let file = &rest[..rest.find(')').unwrap_or(rest.len())];
            pages.push(SubPage { title: title.to_string(), file: format!("{folder}/{file}") });
        }
    }
    pages
}

/// The lessons and then the reference pages of `record`'s section, as its
/// opening page lists them (none if it cannot be read).
pub fn sub_pages(src: &Path, record: &Record) -> Vec<SubPage> {
    let folder = course::section(record);
    let Ok(opening) = std::fs::read_to_string(src.join(course::page(record))) else { return Vec::new() };
    let mut pages = listed_pages(&opening, &folder, LESSONS_HEADING);
    pages.extend(listed_pages(&opening, &folder, REFERENCE_HEADING));
    pages
}

/// The id mdBook gives a heading: lower case, spaces to `-`, anything but
/// letters, digits, `-` and `_` dropped; or its own `{#id}`.
pub fn heading_id(heading: &str) -> String {
    let heading = heading.trim();
    if let Some(open) = heading.rfind("{#")
        && heading.ends_with('}')
    {
        return heading[open + 2..heading.len() - 1].to_string();
    }
    // Inline markup: the text of a link, not its target.
    let text = prose_links_to_text(heading);
    text.chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '_' || c == '-' {
                Some(c.to_lowercase().next().unwrap_or(c))
            } else if c.is_whitespace() {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

fn prose_links_to_text(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find("](") {
        out.push_str(&rest[..at]);
        let after = &rest[at + 2..];
        rest = &after[after.find(')').map_or(after.len(), |e| e + 1)..];
    }
    out.push_str(rest);
    out
}

/// The ids a link may name on `text`: every heading's, numbered as mdBook
/// numbers repeats (`numbers`, `numbers-1`), and every HTML `id="…"`.
pub fn heading_ids(text: &str) -> BTreeSet<String> {
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    let mut ids = BTreeSet::new();
    for (_, line) in outside_code(text) {
        for (at, _) in line.match_indices(" id=\"") {
            let id = &line[at + 5..];
            ids.insert(id[..id.find('"').unwrap_or(id.len())].to_string());
        }
        let Some(heading) = line.strip_prefix('#').map(|h| h.trim_start_matches('#')) else { continue };
        if !heading.starts_with(' ') {
            continue;
        }
        let id = heading_id(heading);
        let count = seen.entry(id.clone()).or_insert(0);
        ids.insert(if *count == 0 { id.clone() } else { format!("{id}-{count}") });
        *count += 1;
    }
    ids
}

/// The `## ` sections of `text`, in order, as their heading lines.
fn sections(text: &str) -> Vec<(usize, String)> {
    outside_code(text)
        .into_iter()
        .filter(|(_, line)| line.starts_with("## "))
        .map(|(n, line)| (n, line.trim_end().to_string()))
        .collect()
}

/// The text of the `## ` section `heading` on `text`, up to the next one.
fn section_text(text: &str, heading: &str) -> Option<String> {
    let mut out = String::new();
    let mut inside = false;
    let mut found = false;
    for (_, line) in outside_code(text) {
        if line.starts_with("## ") {
            inside = line.trim_end() == heading;
            found |= inside;
            continue;
        }
        if inside {
            out.push_str(line);
            out.push('\n');
        }
    }
    found.then_some(out)
}

/// The numbered items at the top level of `section` (`1. …`, unindented).
fn numbered_items(section: &str) -> usize {
    section
        .lines()
        .filter(|line| {
            let digits = line.len() - line.trim_start_matches(|c: char| c.is_ascii_digit()).len();
            digits > 0 && line[digits..].starts_with(". ")
        })
        .count()
}

/// How many exercises `text` sets: the numbered items under `## Exercises`.
pub fn exercise_count(text: &str) -> usize {
    section_text(text, "## Exercises").map_or(0, |s| numbered_items(&s))
}

/// A link on a page: its target as written, and the text it is on.
struct Link<'t> {
    line: usize,
    text: &'t str,
    target: &'t str,
}

/// The Markdown links (`[text](target)`) and HTML `href`s on `text`,
/// outside code.
fn links(text: &str) -> Vec<Link<'_>> {
    let mut found = Vec::new();
    for (number, line) in outside_code(text) {
        for (at, _) in line.match_indices("](") {
            let target = &line[at + 2..];
            let target = &target[..target.find(')').unwrap_or(target.len())];
            let opening = line[..at].rfind('[').unwrap_or(at);
            found.push(Link { line: number, text: &line[opening..at], target });
        }
        for (at, _) in line.match_indices("href=\"") {
            let target = &line[at + 6..];
            let target = &target[..target.find('"').unwrap_or(target.len())];
            found.push(Link { line: number, text: "", target });
        }
    }
    found
}

/// `target`, a link on the page `from`, as a page of the book and a
/// heading id: `None` for what is not a page (a figure, a live frame, an
/// outside address).
pub fn page_target(from: &str, target: &str) -> Option<(String, Option<String>)> {
    if target.contains("://") || target.starts_with("mailto:") || target.starts_with("//") {
        return None;
    }
    let (path, anchor) = match target.split_once('#') {
        Some((path, anchor)) => (path, Some(anchor.to_string())),
        None => (target, None),
    };
    let path = path.split('?').next().unwrap_or_default();
    let file = if path.is_empty() {
        from.to_string()
    } else if let Some(stem) = path.strip_suffix(".md").or_else(|| path.strip_suffix(".html")) {
        let folder = from.rsplit_once('/').map_or("", |(f, _)| f);
        normalise(&format!("{folder}/{stem}.md"))?
    } else {
        return None;
    };
    // mdBook's page for a folder's `index.md` is its `index.html`.
    Some((file, anchor))
}

/// `a/b/../c.md` as `a/c.md`; `None` for a path above `book/src`.
fn normalise(path: &str) -> Option<String> {
    let mut parts: Vec<&str> = Vec::new();
    for part in path.split('/') {
        match part {
            "" | "." => {}
            ".." => {
                parts.pop()?;
            }
            _ => parts.push(part),
        }
    }
    Some(parts.join("/"))
}

/// The numbers of the exercises a piece of prose names: "exercise 3",
/// "exercises 1 and 2", "exercises 2–4" (every number in the run).
pub fn exercises_named(line: &str) -> Vec<u32> {
    let lower = line.to_lowercase();
    let mut numbers = Vec::new();
    for (at, _) in lower.match_indices("exercise") {
        let mut rest = lower[at + "exercise".len()..].trim_start_matches('s');
        if !rest.starts_with(' ') {
            continue;
        }
        loop {
            rest = rest.trim_start();
            let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
            if digits.is_empty() {
                break;
            }
            numbers.push(digits.parse().unwrap_or(u32::MAX));
            rest = &rest[digits.len()..];
            let next = rest.trim_start();
            if let Some(after) = ["and ", ", ", "to ", "–", "-"]
                .iter()
                .find_map(|sep| next.strip_prefix(sep))
                .filter(|a| a.trim_start().starts_with(|c: char| c.is_ascii_digit()))
            {
                rest = after;
            } else {
                break;
            }
        }
    }
    numbers
}

/// Every problem with the book's shape, each naming its page.
pub fn check(src: &Path, chapters: &[Record], summary: &str) -> anyhow::Result<Vec<String>> {
    let pages = read_pages(src)?;
    let index = CodeIndex::build(&src.join("../.."))?;
    let by_file: BTreeMap<&str, &Page> = pages.iter().map(|p| (p.file.as_str(), p)).collect();
    let mut problems = Vec::new();

    // The lessons and reference pages of every chapter, and whose they are.
    let mut lessons: BTreeMap<String, &Record> = BTreeMap::new();
    let mut reference: BTreeSet<String> = BTreeSet::new();
    for record in chapters {
        let opening = course::page(record);
        let Some(page) = by_file.get(opening.as_str()) else {
            problems.push(format!("{} has no opening page, {opening}", record.name));
            continue;
        };
        let folder = course::section(record);
        let listed = listed_pages(&page.text, &folder, LESSONS_HEADING);
        if listed.is_empty() {
            problems.push(format!("{opening}: lists no lessons under `{LESSONS_HEADING}`"));
        }
        let references = listed_pages(&page.text, &folder, REFERENCE_HEADING);
        // The sidebar (the summary, made from these lists) and the page
        // agree on the page's title.
        for sub in listed.iter().chain(&references) {
            let title = by_file.get(sub.file.as_str()).and_then(|p| p.text.lines().next()?.strip_prefix("# "));
            if let Some(title) = title.filter(|t| t.trim() != sub.title) {
                problems.push(format!(
                    "{opening}: lists {} as `{}`, but its title is `{}`",
                    sub.file,
                    sub.title,
                    title.trim()
                ));
            }
        }
        for lesson in listed {
            lessons.insert(lesson.file, record);
        }
        for page in references {
            reference.insert(page.file);
        }
        lessons.insert(opening, record);
    }

    for page in &pages {
        let words = prose_words(&page.text);
        if words > WORD_LIMIT {
            problems.push(format!(
                "{}: {words} words of prose, more than the {WORD_LIMIT} a sitting allows: split it into lessons",
                page.file
            ));
        }
        for named in views_named(&page.text) {
            let Some(record) = chapters.iter().find(|r| r.name == named.chapter) else {
                problems.push(format!("{}:{}: `{}` is no chapter", page.file, named.line, named.chapter));
                continue;
            };
            if !record.views.iter().any(|v| v.name == named.view) {
                let views: Vec<&str> = record.views.iter().map(|v| v.name).collect();
                problems.push(format!(
                    "{}:{}: {} has no view `{}` (its views: {})",
                    page.file,
                    named.line,
                    named.chapter,
                    named.view,
                    views.join(", ")
                ));
            }
        }
        problems.extend(link_problems(page, &by_file));
        // Code named in prose must exist: a rename fails the build.
        let own_views = chapters
            .iter()
            .find(|r| page.file.starts_with(&format!("{}/", course::section(r))))
            .map_or(&[][..], |r| r.views);
        for (line, name) in code_spans(&page.text) {
            if own_views.iter().any(|v| v.name == name) {
                problems.push(format!(
                    "{}:{line}: `{name}` names a view: write it as {{{{#view CHAPTER {name}}}}}, which the build checks",
                    page.file
                ));
            } else if index.resolves(&name) == Some(false) {
                problems.push(format!(
                    "{}:{line}: `{name}` names no file, type, function or constant in the workspace (a name \
                     from outside it, an API's, is written {{{{#external {name} | WHERE IT IS FROM}}}})",
                    page.file
                ));
            }
        }
        for (line, typed) in typed_measurements(&page.text) {
            problems.push(format!(
                "{}:{line}: `{typed}` is a measurement typed into the prose: write it with {{{{#figure …}}}} from \
                 its table or code, or quote it with {{{{#cited {typed} | SOURCE}}}}",
                page.file
            ));
        }
    }

    // Every lesson: its run line first, what to look for, and its ending.
    for (file, record) in &lessons {
        let Some(page) = by_file.get(file.as_str()) else {
            problems.push(format!("{file}: listed on {}'s opening page, but there is no such page", record.name));
            continue;
        };
        problems.extend(lesson_problems(page, record, file == &course::page(record)));
    }
    for file in &reference {
        if !by_file.contains_key(file.as_str()) {
            problems.push(format!("{file}: listed as a reference page, but there is no such page"));
        }
    }

    // Every view taught on a lesson of its own chapter.
    for record in chapters {
        let taught: BTreeSet<&str> = lessons
            .iter()
            .filter(|(_, r)| r.name == record.name)
            .filter_map(|(file, _)| by_file.get(file.as_str()))
            .flat_map(|page| views_named(&page.text))
            .filter(|named| named.chapter == record.name)
            .map(|named| record.views.iter().find(|v| v.name == named.view).map_or("", |v| v.name))
            .collect();
        for view in record.views {
            if !taught.contains(view.name) {
                problems.push(format!(
                    "{}: the view `{}` is taught on none of the chapter's lessons (name it with \
                     {{{{#run {} {}}}}} or {{{{#view {} {}}}}})",
                    course::section(record),
                    view.name,
                    record.name,
                    view.name,
                    record.name,
                    view.name
                ));
            }
        }
    }

    problems.extend(summary_problems(summary, &pages, chapters));
    Ok(problems)
}

/// A lesson (or a chapter's opening page) opens with its run line and
/// what to look for; a lesson ends with exercises, questions and a recap.
fn lesson_problems(page: &Page, record: &Record, opening: bool) -> Vec<String> {
    let mut problems = Vec::new();
    let file = &page.file;
    let mut lines = page.text.lines().map(str::trim).filter(|l| !l.is_empty());
    if !lines.next().is_some_and(|l| l.starts_with("# ")) {
        problems.push(format!("{file}: does not start with its title (`# …`)"));
    }
    match lines.next() {
        Some(line) if line.starts_with("{{#run ") => {
            let named = views_named(line);
            if named.first().is_none_or(|n| n.chapter != record.name) {
                problems.push(format!("{file}: its run line runs another chapter than {}", record.name));
            }
            if !opening && !lines.next().is_some_and(|l| l.starts_with(LOOK_FOR)) {
                problems.push(format!("{file}: the run line is not followed by what to look for (`{LOOK_FOR} …`)"));
            }
        }
        _ => problems.push(format!(
            "{file}: does not open with the run line of the view it teaches (`{{{{#run {} VIEW}}}}` after the title)",
            record.name
        )),
    }
    if opening {
        return problems;
    }
    let headings: Vec<String> = sections(&page.text).into_iter().map(|(_, h)| h).collect();
    let position = |name: &str| headings.iter().position(|h| h == name);
    let (exercises, questions, recap) = (position("## Exercises"), position("## Questions"), position("## Recap"));
    match (exercises, questions, recap) {
        (Some(e), Some(q), Some(r)) if e < q && q < r => {
            if headings[r + 1..].iter().any(|h| h != "## References") {
                problems.push(format!("{file}: only `## References` may follow the recap"));
            }
        }
        _ => problems.push(format!(
            "{file}: a lesson ends with `## Exercises`, `## Questions` and `## Recap`, in that order (it has: {})",
            headings.join(", ")
        )),
    }
    if exercises.is_some() && exercise_count(&page.text) == 0 {
        problems.push(format!("{file}: its exercises section sets no exercise (`1. …`)"));
    }
    if let Some(questions) = section_text(&page.text, "## Questions") {
        let (asked, answered) = (numbered_items(&questions), questions.matches("<details>").count());
        if asked < 2 || answered < asked {
            problems.push(format!(
                "{file}: {asked} questions with {answered} folded answers (`<details>`): ask at least two, answer each"
            ));
        }
    }
    problems
}

/// Links to pages that are not there, to headings a page does not have,
/// and "exercise N" where there is no exercise N.
fn link_problems(page: &Page, by_file: &BTreeMap<&str, &Page>) -> Vec<String> {
    let mut problems = Vec::new();
    let own_exercises = exercise_count(&page.text);
    let mut linked_exercise_lines = BTreeSet::new();
    for link in links(&page.text) {
        let Some((file, anchor)) = page_target(&page.file, link.target) else { continue };
        let Some(target) = by_file.get(file.as_str()) else {
            // An `.html` link that is no page is the built book's own (a
            // live frame): the HTML link check after the build sees those.
            if !link.target.split(['#', '?']).next().unwrap_or_default().ends_with(".html") {
                problems.push(format!(
                    "{}:{}: links to `{}`, which is no page of the book",
                    page.file, link.line, link.target
                ));
            }
            continue;
        };
        if let Some(anchor) = anchor.filter(|a| !a.is_empty())
            && !heading_ids(&target.text).contains(&anchor)
        {
            problems.push(format!(
                "{}:{}: links to `{}`, but {} has no heading `#{anchor}`",
                page.file, link.line, link.target, file
            ));
        }
        let named = exercises_named(link.text);
        if !named.is_empty() {
            linked_exercise_lines.insert(link.line);
            let count = exercise_count(&target.text);
            for n in named.into_iter().filter(|&n| n == 0 || n as usize > count) {
                problems.push(format!(
                    "{}:{}: `{}` names exercise {n}, but {file} sets {count}",
                    page.file, link.line, link.text
                ));
            }
        }
    }
    for (number, line) in outside_code(&page.text) {
        if linked_exercise_lines.contains(&number) {
            continue;
        }
        for n in exercises_named(&prose_of(line)) {
            if n == 0 || n as usize > own_exercises {
                problems.push(format!(
                    "{}:{number}: names exercise {n}, but the page sets {own_exercises} (link to another page's \
                     exercise: `[exercise {n}](page.md#exercises)`)",
                    page.file
                ));
            }
        }
    }
    problems
}

/// Every page is in the summary, and the chapters come in book order.
fn summary_problems(summary: &str, pages: &[Page], chapters: &[Record]) -> Vec<String> {
    let mut problems = Vec::new();
    let listed: Vec<&str> = summary
        .lines()
        .filter_map(|line| line.split_once("](").map(|(_, rest)| &rest[..rest.find(')').unwrap_or(rest.len())]))
        .collect();
    for page in pages {
        if !listed.contains(&page.file.as_str()) {
            problems.push(format!("{}: not in SUMMARY.md, so no reader reaches it", page.file));
        }
    }
    let openings: Vec<String> = chapters.iter().map(course::page).collect();
    let order: Vec<&str> = listed.iter().copied().filter(|f| openings.iter().any(|o| o == f)).collect();
    if order != openings.iter().map(String::as_str).collect::<Vec<_>>() {
        problems.push(format!(
            "SUMMARY.md lists the chapters as {order:?}, but course::chapters() orders them {openings:?}"
        ));
    }
    problems
}
