//! The WGSL files under `shaders/` and what each imports, read from the
//! files themselves (no GPU, no chapter code): for the tests that must
//! reach every shader, whether or not a chapter's code names it.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Every `.wgsl` file under `dir`, as its path under `shaders/` with `/`.
pub fn wgsl_files(shaders: &Path, dir: &Path, found: &mut Vec<String>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            wgsl_files(shaders, &path, found);
        } else if path.extension().is_some_and(|e| e == "wgsl") {
            let relative = path.strip_prefix(shaders).unwrap();
            found.push(relative.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/"));
        }
    }
}

/// The WGSL files under `shaders/`, each with the files it `#import`s
/// (found by their `#define_import_path`), by path.
pub fn import_graph(shaders: &Path) -> BTreeMap<String, Vec<String>> {
    let mut files = Vec::new();
    wgsl_files(shaders, shaders, &mut files);
    let texts: BTreeMap<String, String> =
        files.into_iter().map(|f| (f.clone(), std::fs::read_to_string(shaders.join(&f)).unwrap())).collect();
    let modules: BTreeMap<String, String> = texts
        .iter()
        .flat_map(|(file, text)| {
            text.lines()
                .filter_map(|l| l.trim().strip_prefix("#define_import_path"))
                .map(move |name| (name.trim().to_string(), file.clone()))
        })
        .collect();
    texts
        .iter()
        .map(|(file, text)| {
            let imports = text
                .lines()
                .filter_map(|l| l.trim().strip_prefix("#import "))
                .map(|spec| {
                    // `a::b::{x, y}`, `a::b::x` or `a::b`: the module is the
                    // longest prefix that some file defines.
                    let path = spec.split(['{', ' ']).next().unwrap_or_default().trim_end_matches("::");
                    let segments: Vec<&str> = path.split("::").collect();
                    (1..=segments.len())
                        .rev()
                        .find_map(|n| modules.get(&segments[..n].join("::")).cloned())
                        .unwrap_or_else(|| panic!("{file}: no file defines the module of `#import {spec}`"))
                })
                .collect();
            (file.clone(), imports)
        })
        .collect()
}
