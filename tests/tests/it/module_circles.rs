//! A chapter's modules are its pieces, read in the book's order: each may
//! build on others, but no two may lean on each other, directly or round a
//! circle (`city` using `countryside` using `city`), or neither could be
//! read, tested or reused alone. Reads every chapter's `src/*.rs` (test
//! modules left out), takes `crate::name` paths as uses, and looks for
//! circles.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The modules of `crate::` that `source` names, before its first
/// `#[cfg(test)]` (tests may reach across).
fn uses(source: &str) -> BTreeSet<String> {
    let code = source.split("#[cfg(test)]").next().unwrap_or(source);
    let mut found = BTreeSet::new();
    for (at, _) in code.match_indices("crate::") {
        let rest = &code[at + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let group = &group[..group.find('}').unwrap_or(group.len())];
            found.extend(group.split(',').filter_map(|item| item.trim().split("::").next()).map(str::to_string));
        } else {
            found.insert(rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect());
        }
    }
    found
}

/// A circle in `graph`, as the modules along it, if there is one.
fn circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn walk(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(start) = path.iter().position(|n| n == node) {
            let mut found = path[start..].to_vec();
            found.push(node.to_string());
            return Some(found);
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(found) = walk(next, graph, path, done) {
                return Some(found);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph.keys().find_map(|node| walk(node, graph, &mut Vec::new(), &mut done))
}

fn module_graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut sources = BTreeMap::new();
    for entry in std::fs::read_dir(src).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        if path.extension().is_some_and(|e| e == "rs") && name != "lib" && name != "main" {
            sources.insert(name, std::fs::read_to_string(&path).unwrap());
        }
    }
    sources
        .iter()
        .map(|(name, source)| {
            let used = uses(source).into_iter().filter(|u| u != name && sources.contains_key(u)).collect();
            (name.clone(), used)
        })
        .collect()
}

#[test]
fn no_chapter_has_modules_that_lean_on_each_other() {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("../chapters");
    let mut circles = Vec::new();
    let mut count = 0;
    for entry in std::fs::read_dir(&chapters).unwrap() {
        let src = entry.unwrap().path().join("src");
        let graph = module_graph(&src);
        count += graph.len();
        if let Some(found) = circle(&graph) {
            circles.push(format!("{}: {}", src.display(), found.join(" → ")));
        }
    }
    assert!(count > 50, "read only {count} modules");
    assert!(circles.is_empty(), "modules that lean on each other:\n{}", circles.join("\n"));
}

#[test]
fn the_circle_finder_finds_a_circle_of_three_and_none_in_a_chain() {
    let graph = |edges: &[(&str, &str)]| {
        let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (from, to) in edges {
            g.entry(from.to_string()).or_default().insert(to.to_string());
            g.entry(to.to_string()).or_default();
        }
        g
    };
    assert_eq!(circle(&graph(&[("a", "b"), ("b", "c"), ("a", "c")])), None);
    let found = circle(&graph(&[("a", "b"), ("b", "c"), ("c", "a")])).unwrap();
    assert_eq!(found.len(), 4, "{found:?}");
    let source = "use crate::city::{HALF, Shape};\nuse crate::{lights, paths::Pose};\n#[cfg(test)]\nuse crate::demo;";
    assert_eq!(uses(source), ["city", "lights", "paths"].map(String::from).into());
}
