//! Building the book: figures from the snapshot references, diagrams drawn
//! by code, listings from the code by anchor, numbers from their tables
//! (`figures`), and a failure for any anchor, link or figure that is broken.

use std::path::{Path, PathBuf};

use anyhow::{Context as _, bail};

use crate::{cargo, root};

/// Builds `book/book/`, its browser program compiled by `profile`. With
/// `check_snapshots`, first renders every view and compares it with its
/// reference, so no figure can be out of date.
pub fn build(check_snapshots: bool, profile: crate::web::Profile) -> anyhow::Result<()> {
    if check_snapshots {
        crate::prerequisites::ensure_adapter()?;
        cargo(&["run", "--quiet", "-p", "snapshots"])?;
    }
    let book = root().join("book");
    println!("\n$ building {}", book.display());
    copy_figures(&root().join("tests/snapshots"), &book.join("src/figures"))?;
    // Diagrams are drawn by code from the chapters' own functions, fresh each build.
    let diagrams = book.join("src/diagrams");
    cargo(&["run", "--quiet", "-p", "diagrams", "--", &diagrams.display().to_string()])?;
    // The README's chapter table and the summary, from the chapter records.
    cargo(&["run", "--quiet", "-p", "snapshots", "--", "--docs"])?;
    let problems = check_includes(&book.join("src"))?;
    if !problems.is_empty() {
        bail!("broken listings in the book:\n  {}", problems.join("\n  "));
    }
    mdbook_driver::MDBook::load(&book)
        .and_then(|mut b| b.with_preprocessor(crate::figures::Preprocessor).build())
        .map_err(|e| anyhow::anyhow!("{e:#}"))
        .context("mdbook failed")?;
    let html = book.join("book");
    // Every page's live frame points into live/: built now, so the link
    // check below fails if a chapter's page is missing.
    crate::web::build(&html, profile)?;
    let broken = check_links(&html)?;
    if !broken.is_empty() {
        bail!("broken links in the book:\n  {}", broken.join("\n  "));
    }
    println!("book: {}", html.join("index.html").display());
    Ok(())
}

/// Copies `tests/snapshots/<chapter>/<view>.png` to `book/src/figures/`,
/// leaving out the `-actual` and `-diff` pictures of failed runs, the
/// `-old` ones a bless keeps, and the bless log.
fn copy_figures(from: &Path, to: &Path) -> anyhow::Result<()> {
    if to.exists() {
        std::fs::remove_dir_all(to)?;
    }
    for chapter in std::fs::read_dir(from).with_context(|| format!("cannot read {}", from.display()))? {
        let chapter = chapter?.path();
        if !chapter.is_dir() {
            continue;
        }
        let target = to.join(chapter.file_name().context("chapter folder")?);
        std::fs::create_dir_all(&target)?;
        for file in std::fs::read_dir(&chapter)? {
            let file = file?.path();
            let name = file.file_name().context("file name")?.to_string_lossy().to_string();
            let left_over = ["-actual.png", "-diff.png", "-old.png"].iter().any(|s| name.ends_with(s));
            if name.ends_with(".png") && !left_over {
                std::fs::copy(&file, target.join(&name))?;
            }
        }
    }
    Ok(())
}

fn markdown_files(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            files.extend(markdown_files(&path)?);
        } else if path.extension().is_some_and(|e| e == "md") {
            files.push(path);
        }
    }
    Ok(files)
}

/// Every `{{#include file:anchor}}` must name a file that exists and an
/// anchor that it opens and closes. mdbook itself only warns and leaves the
/// listing empty, which is how a book drifts from its code.
pub fn check_includes(src: &Path) -> anyhow::Result<Vec<String>> {
    let mut problems = Vec::new();
    for page in markdown_files(src)? {
        let text = std::fs::read_to_string(&page)?;
        for (start, _) in text.match_indices("{{#") {
            let rest = &text[start + 3..];
            let Some(end) = rest.find("}}") else { continue };
            let directive = rest[..end].trim();
            let Some(spec) = ["include ", "rustdoc_include "].iter().find_map(|d| directive.strip_prefix(d)) else {
                continue;
            };
            let spec = spec.trim();
            let (file, anchor) = match spec.split_once(':') {
                Some((file, anchor)) => (file, Some(anchor)),
                None => (spec, None),
            };
            let where_ = format!("{}: {{{{#{directive}}}}}", page.strip_prefix(src).unwrap_or(&page).display());
            let path = page.parent().context("page folder")?.join(file);
            let Ok(target) = std::fs::read_to_string(&path) else {
                problems.push(format!("{where_}: no file {}", path.display()));
                continue;
            };
            // Line ranges (`:10:20`) are not anchors.
            if let Some(anchor) = anchor.filter(|a| !a.starts_with(|c: char| c.is_ascii_digit())) {
                let opens = target.lines().any(|l| l.trim_end().ends_with(&format!("ANCHOR: {anchor}")));
                let closes = target.lines().any(|l| l.trim_end().ends_with(&format!("ANCHOR_END: {anchor}")));
                if !(opens && closes) {
                    problems
                        .push(format!("{where_}: {} has no ANCHOR/ANCHOR_END pair named '{anchor}'", path.display()));
                }
            }
        }
    }
    Ok(problems)
}

/// Every relative `href` and `src` in the generated HTML must point at a
/// file that exists (external links are not fetched).
fn check_links(html_root: &Path) -> anyhow::Result<Vec<String>> {
    let mut broken = Vec::new();
    let mut stack = vec![html_root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir)? {
            let path = entry?.path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "html") {
                continue;
            }
            let text = std::fs::read_to_string(&path)?;
            for attribute in ["href=\"", "src=\""] {
                for (start, _) in text.match_indices(attribute) {
                    let value = &text[start + attribute.len()..];
                    let link = &value[..value.find('"').unwrap_or(0)];
                    let external = link.contains("://")
                        || link.starts_with("//")
                        || link.starts_with("mailto:")
                        || link.starts_with("data:");
                    let target = link.split(['#', '?']).next().unwrap_or("");
                    if external || target.is_empty() {
                        continue;
                    }
                    let resolved = path.parent().context("page folder")?.join(target);
                    if !resolved.exists() {
                        broken.push(format!(
                            "{} links to {link}",
                            path.strip_prefix(html_root).unwrap_or(&path).display()
                        ));
                    }
                }
            }
        }
    }
    broken.sort();
    broken.dedup();
    Ok(broken)
}
