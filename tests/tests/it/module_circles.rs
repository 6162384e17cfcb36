//! A chapter's modules are its pieces, read in the book's order: each may
//! build on others, but no two may lean on each other, directly or round a
//! circle (`city` using `countryside` using `city`), or neither could be
//! read, tested or reused alone. Reads every chapter's modules (each file
//! under `src/`, a folder's files belonging to its module), takes every
//! path from `crate::` or `super::` in code as a use (comments, which
//! link for the reader, are left out), nested `use` groups and test
//! modules included, resolves a name the crate's root re-exports
//! (`crate::GpuMaterial`) to the module it comes from, and looks for
//! circles.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Every path `source` names from `crate::` or `super::`, as its segments
/// after that prefix: `use crate::{a::{X, Y}, b};` names `a::X`, `a::Y`
/// and `b`; `crate::c::f()` in code names `c::f`. `super::` is read as
/// `crate::` (a chapter's modules sit at its root).
fn named_paths(source: &str) -> Vec<Vec<String>> {
    // Comments link to other modules for the reader; they use nothing.
    let source: String = source
        .lines()
        .map(|line| if line.trim_start().starts_with("//") { "" } else { line })
        .collect::<Vec<_>>()
        .join("\n");
    let source = source.as_str();
    let mut paths = Vec::new();
    for prefix in ["crate::", "super::"] {
        for (at, _) in source.match_indices(prefix) {
            let before = source[..at].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let mut rest = &source[at + prefix.len()..];
            tree(&mut rest, Vec::new(), &mut paths);
        }
    }
    paths
}

/// Reads one use tree from the start of `rest` (`a::b`, `a::{b, c::{d}}`,
/// `*`), appending each leaf's full path (`prefix` then its segments).
fn tree(rest: &mut &str, prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
    *rest = rest.trim_start();
    if let Some(group) = rest.strip_prefix('{') {
        *rest = group;
        loop {
            tree(rest, prefix.clone(), out);
            *rest = rest.trim_start();
            match rest.chars().next() {
                Some(',') => *rest = &rest[1..],
                Some('}') => {
                    *rest = &rest[1..];
                    return;
                }
                _ => return,
            }
            if rest.trim_start().starts_with('}') {
                *rest = &rest.trim_start()[1..];
                return;
            }
        }
    }
    let length = rest.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '*')).unwrap_or(rest.len());
    if length == 0 {
        if !prefix.is_empty() {
            out.push(prefix);
        }
        return;
    }
    let mut path = prefix;
    path.push(rest[..length].to_string());
    *rest = &rest[length..];
    if let Some(deeper) = rest.strip_prefix("::") {
        *rest = deeper;
        tree(rest, path, out);
    } else {
        out.push(path);
        // `a as b`: the alias names nothing new.
        if let Some(alias) = rest.trim_start().strip_prefix("as ") {
            let alias = alias.trim_start();
            let length = alias.find(|c: char| !(c.is_alphanumeric() || c == '_')).unwrap_or(alias.len());
            *rest = &alias[length..];
        }
    }
}

/// A chapter's modules: each module's name (its file under `src/`, or its
/// folder) with the text of its files.
fn modules(src: &Path) -> BTreeMap<String, String> {
    let mut modules: BTreeMap<String, String> = BTreeMap::new();
    for entry in std::fs::read_dir(src).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        if path.is_dir() {
            let mut text = String::new();
            for file in std::fs::read_dir(&path).unwrap() {
                text.push_str(&std::fs::read_to_string(file.unwrap().path()).unwrap_or_default());
            }
            modules.entry(name).or_default().push_str(&text);
        } else if path.extension().is_some_and(|e| e == "rs") {
            modules.entry(name).or_default().push_str(&std::fs::read_to_string(&path).unwrap());
        }
    }
    modules
}

/// The names the crate's root re-exports, each with the module it comes
/// from: `pub use materials::{GpuMaterial, Material as M};` maps
/// `GpuMaterial` and `M` to `materials`.
fn re_exports(lib: &str) -> BTreeMap<String, String> {
    let mut names = BTreeMap::new();
    for (at, _) in lib.match_indices("pub use ") {
        let mut rest = &lib[at + "pub use ".len()..];
        let statement = &rest[..rest.find(';').unwrap_or(rest.len())];
        let mut leaves = Vec::new();
        rest = statement;
        tree(&mut rest, Vec::new(), &mut leaves);
        for leaf in leaves {
            let (Some(module), Some(last)) = (leaf.first(), leaf.last()) else { continue };
            // The alias, where there is one: `X as Y` exports Y.
            let exported = statement
                .split(&format!("{last} as "))
                .nth(1)
                .and_then(|after| after.split(|c: char| !(c.is_alphanumeric() || c == '_')).next())
                .unwrap_or(last);
            names.insert(exported.to_string(), module.clone());
        }
    }
    names
}

/// Which module each module uses, through any path: `crate::x::…` and
/// `super::x::…` name `x`, a re-exported name its defining module.
fn module_graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut sources = modules(src);
    let lib = sources.remove("lib").unwrap_or_default();
    sources.remove("main");
    let exported = re_exports(&lib);
    sources
        .iter()
        .map(|(name, source)| {
            let used = named_paths(source)
                .into_iter()
                .filter_map(|path| {
                    let first = path.first()?;
                    if sources.contains_key(first) { Some(first.clone()) } else { exported.get(first).cloned() }
                })
                .filter(|used| used != name && sources.contains_key(used))
                .collect();
            (name.clone(), used)
        })
        .collect()
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

#[test]
fn no_chapter_has_modules_that_lean_on_each_other() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut circles = Vec::new();
    let mut count = 0;
    let mut crates = vec![root.join("common/src")];
    for entry in std::fs::read_dir(root.join("chapters")).unwrap() {
        crates.push(entry.unwrap().path().join("src"));
    }
    for src in crates {
        let graph = module_graph(&src);
        count += graph.len();
        if let Some(found) = circle(&graph) {
            circles.push(format!("{}: {}", src.display(), found.join(" → ")));
        }
    }
    assert!(count > 80, "read only {count} modules");
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
}

/// The ways a module names another, each read as the compiler reads it
/// (the cases the first reader missed: a nested group, a root re-export,
/// `super::`, a path in code, a test module, a module in a folder).
#[test]
fn every_way_of_naming_a_module_is_read() {
    let paths = |source: &str| -> BTreeSet<String> { named_paths(source).iter().map(|p| p.join("::")).collect() };
    assert_eq!(
        paths("use crate::{a::{X, Y as Z}, b};\nfn f() { crate::c::make(); super::d::E::new(); }"),
        ["a::X", "a::Y", "b", "c::make", "d::E::new"].map(String::from).into()
    );
    assert_eq!(paths("use crate::a::*;\nlet x = my_crate::b;"), ["a::*"].map(String::from).into());
    let exported = re_exports("pub use materials::{GpuMaterial, Material as Mat};\npub use city::City;");
    assert_eq!(exported.get("GpuMaterial").map(String::as_str), Some("materials"));
    assert_eq!(exported.get("Mat").map(String::as_str), Some("materials"));
    assert_eq!(exported.get("City").map(String::as_str), Some("city"));

    // A chapter on disk: `city` uses `materials` through the root's
    // re-export, and `materials`'s tests use `city` through `super::`; a
    // folder module `paths` uses `city` from its second file.
    let src = std::env::temp_dir().join(format!("module-circles-{}", std::process::id()));
    std::fs::create_dir_all(src.join("paths")).unwrap();
    std::fs::write(
        src.join("lib.rs"),
        "pub mod city;\npub mod materials;\npub mod paths;\npub use materials::GpuMaterial;",
    )
    .unwrap();
    std::fs::write(src.join("city.rs"), "use crate::GpuMaterial;\n").unwrap();
    std::fs::write(
        src.join("materials.rs"),
        "pub struct GpuMaterial;\n#[cfg(test)]\nmod tests { fn t() { super::city::x(); } }",
    )
    .unwrap();
    std::fs::write(src.join("paths/mod.rs"), "mod curve;\n").unwrap();
    std::fs::write(src.join("paths/curve.rs"), "use crate::city::City;\n").unwrap();
    let graph = module_graph(&src);
    std::fs::remove_dir_all(&src).unwrap();
    assert_eq!(graph["city"], ["materials"].map(String::from).into());
    assert_eq!(graph["paths"], ["city"].map(String::from).into());
    let found = circle(&graph).expect("city → materials → city");
    assert_eq!(found.len(), 3, "{found:?}");
}
