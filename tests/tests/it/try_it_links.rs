//! The book's "try it" links cannot rot: every link to a chapter's page
//! that opens the shader panel (`live/CHAPTER/index.html?edit=FILE&at=TEXT`)
//! names a chapter of the course, a WGSL file that chapter builds from, and
//! text that is in that file, read here from `book/src/` and `shaders/`
//! without a GPU.

use std::collections::{BTreeMap, BTreeSet};

use crate::shader_files::import_graph;
use std::path::{Path, PathBuf};

/// How many "try it" links the chapters' exercises had when this test was
/// written: fewer means links were lost, not just moved.
const AT_LEAST: usize = 16;

/// The URL parameters a panel link may carry (the page understands more,
/// but a link to the panel has no business with the others).
const LINK_PARAMETERS: &[&str] = &["edit", "at", "view"];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// One link to a chapter's page with a query, where it was found.
struct Link {
    place: String,
    chapter: String,
    query: String,
}

/// Every `live/CHAPTER/index.html?QUERY` in `text`, the query up to the
/// end of the link (markdown's `)`, an HTML attribute's quote, the end of
/// a code span, a fragment).
fn page_links(text: &str, page: &str) -> Vec<Link> {
    let mut links = Vec::new();
    for (line_number, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(start) = rest.find("live/") {
            rest = &rest[start + "live/".len()..];
            let Some((chapter, after)) = rest.split_once('/') else { break };
            let Some(query) = after.strip_prefix("index.html?") else { continue };
            if chapter.is_empty() || chapter.contains(|c: char| c.is_whitespace() || "()[]\"'<>".contains(c)) {
                continue;
            }
            let end = query.find(|c: char| c.is_whitespace() || ")\"'<>#]`".contains(c)).unwrap_or(query.len());
            links.push(Link {
                place: format!("{page}:{}", line_number + 1),
                chapter: chapter.to_string(),
                query: query[..end].replace("&amp;", "&"),
            });
        }
    }
    links
}

/// A query value decoded as the page's `URLSearchParams` decodes it:
/// `+` is a space, `%XX` a byte, the bytes UTF-8.
fn url_decode(value: &str) -> Result<String, String> {
    let mut bytes = Vec::new();
    let mut input = value.bytes();
    while let Some(byte) = input.next() {
        match byte {
            b'+' => bytes.push(b' '),
            b'%' => {
                let hex: Vec<u8> = input.by_ref().take(2).collect();
                let digits = std::str::from_utf8(&hex).ok().filter(|h| h.len() == 2);
                let decoded = digits.and_then(|h| u8::from_str_radix(h, 16).ok());
                bytes.push(decoded.ok_or_else(|| format!("a bad %-escape in {value:?}"))?);
            }
            _ => bytes.push(byte),
        }
    }
    String::from_utf8(bytes).map_err(|_| format!("{value:?} does not decode to UTF-8"))
}

/// The files a chapter builds from, as far as the files say without a GPU:
/// those in its own folder and every module they import, transitively.
fn chapter_files(chapter: &str, graph: &BTreeMap<String, Vec<String>>) -> BTreeSet<String> {
    let mut reached: BTreeSet<String> = BTreeSet::new();
    let mut to_visit: Vec<String> = graph.keys().filter(|f| f.starts_with(&format!("{chapter}/"))).cloned().collect();
    while let Some(file) = to_visit.pop() {
        if reached.insert(file.clone()) {
            to_visit.extend(graph[&file].iter().cloned());
        }
    }
    reached
}

/// What is wrong with one link, if anything.
fn check(link: &Link, chapters: &[&str], shaders: &Path, graph: &BTreeMap<String, Vec<String>>) -> Result<(), String> {
    if !chapters.contains(&link.chapter.as_str()) {
        return Err(format!("no chapter {:?}; the course's are {}", link.chapter, chapters.join(", ")));
    }
    let mut parameters = BTreeMap::new();
    for pair in link.query.split('&') {
        let (name, value) = pair.split_once('=').unwrap_or((pair, ""));
        let name = url_decode(name)?;
        if !LINK_PARAMETERS.contains(&name.as_str()) {
            return Err(format!("unknown parameter {name:?}; a panel link takes {}", LINK_PARAMETERS.join(", ")));
        }
        parameters.insert(name, url_decode(value)?);
    }
    let file = parameters.get("edit").ok_or("no edit=FILE")?;
    let path = shaders.join(file);
    if file.split('/').any(|part| part == ".." || part.is_empty()) || !path.is_file() {
        return Err(format!("edit={file:?}: no such file under shaders/"));
    }
    let builds_from = chapter_files(&link.chapter, graph);
    if !builds_from.contains(file) {
        return Err(format!(
            "edit={file:?}: not one of the files chapter {} builds from ({})",
            link.chapter,
            builds_from.into_iter().collect::<Vec<_>>().join(", ")
        ));
    }
    let Some(at) = parameters.get("at") else { return Ok(()) };
    if at.is_empty() || at.contains('\n') {
        return Err(format!("at={at:?}: the cursor's place must be text on one line"));
    }
    let text = std::fs::read_to_string(&path).map_err(|e| format!("cannot read {file}: {e}"))?;
    if !text.contains(at.as_str()) {
        return Err(format!("at={at:?} is not in {file}"));
    }
    Ok(())
}

#[test]
fn try_it_links_name_a_chapter_a_file_it_builds_from_and_text_in_that_file() {
    let records = snapshots::chapters();
    let chapters: Vec<&str> = records.iter().map(|r| r.name).collect();
    let shaders = root().join("shaders");
    for chapter in &chapters {
        assert!(shaders.join(chapter).is_dir(), "chapter {chapter} has no folder shaders/{chapter}/");
    }
    let graph = import_graph(&shaders);

    let mut links = Vec::new();
    for page in snapshots::book::read_pages(&snapshots::book::book_src()).unwrap() {
        links.extend(page_links(&page.text, &page.file));
    }
    let errors: Vec<String> = links
        .iter()
        .filter_map(|link| check(link, &chapters, &shaders, &graph).err().map(|e| format!("{}: {e}", link.place)))
        .collect();
    assert!(errors.is_empty(), "broken \"try it\" links in book/src:\n{}", errors.join("\n"));
    let to_the_panel = links.iter().filter(|l| l.query.split('&').any(|p| p.starts_with("edit="))).count();
    assert!(
        to_the_panel >= AT_LEAST,
        "book/src has {to_the_panel} links that open the shader panel; its exercises had {AT_LEAST}"
    );
}

#[test]
fn the_link_reader_decodes_as_a_page_does_and_follows_imports() {
    // Written by hand, not by the code under test.
    assert_eq!(url_decode("sum%20%2B%3D%20x+y%28%29").unwrap(), "sum += x y()");
    assert!(url_decode("bad%2").is_err() && url_decode("bad%zz").is_err());
    let links = page_links(
        r#"1. Exercise. [▶ try it](live/water/index.html?edit=water%2Fwater.wgsl&at=a%29b) and
<iframe src="live/fog/index.html"></iframe> <a href="live/fog/index.html?edit=fog%2Ffog.wgsl&amp;at=x#edits=Q">
In prose, `live/sky/index.html?edit=sky/sky.wgsl&at=y`: a code span."#,
        "page.md",
    );
    let read: Vec<(&str, &str, &str)> =
        links.iter().map(|l| (l.place.as_str(), l.chapter.as_str(), l.query.as_str())).collect();
    assert_eq!(
        read,
        [
            ("page.md:1", "water", "edit=water%2Fwater.wgsl&at=a%29b"),
            ("page.md:2", "fog", "edit=fog%2Ffog.wgsl&at=x"),
            ("page.md:3", "sky", "edit=sky/sky.wgsl&at=y")
        ]
    );
    // Chapter 11's sea imports modules from three other chapters' folders,
    // and chapter 07's water imports chapter 03's terrain.
    let graph = import_graph(&root().join("shaders"));
    let ocean = chapter_files("voronoi-water", &graph);
    for file in ["water/waves.wgsl", "shadows/shadow.wgsl", "lighting/lights.wgsl", "common/fullscreen.wgsl"] {
        assert!(ocean.contains(file), "{file}: {ocean:?}");
    }
    assert!(!ocean.contains("water/water.wgsl"));
    assert!(chapter_files("water", &graph).contains("terrain/terrain.wgsl"));
}
