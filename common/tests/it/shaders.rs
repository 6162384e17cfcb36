//! Every WGSL file in `shaders/` composes with the modules it imports and
//! validates, through the same `compose` the chapters use, without a GPU.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

fn wgsl_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files.extend(wgsl_files(&path));
        } else if path.extension().is_some_and(|e| e == "wgsl") {
            files.push(path);
        }
    }
    files
}

/// The paths after a file's `#import`s, without the items:
/// `#import terrain::{a, b}` → `terrain`, `#import common::fullscreen::{a}`
/// → `common::fullscreen`, `#import terrain::globals` → `terrain::globals`
/// (the module is then a prefix of it; see `module_of`).
fn imported_paths(source: &str) -> Vec<String> {
    source
        .lines()
        .filter_map(|l| l.strip_prefix("#import "))
        .map(|rest| rest.split("::{").next().unwrap_or("").trim().trim_end_matches(';').to_string())
        .collect()
}

/// The longest known module name that `path` starts with.
fn module_of<'a>(path: &str, modules: &'a HashMap<String, &(String, String)>) -> Option<&'a str> {
    let mut candidate = path;
    loop {
        if let Some((name, _)) = modules.get_key_value(candidate) {
            return Some(name);
        }
        candidate = &candidate[..candidate.rfind("::")?];
    }
}

#[test]
fn every_shader_validates() {
    let root = Path::new(common::shader::SHADER_DIR);
    let files: Vec<(String, String)> = wgsl_files(root)
        .iter()
        .map(|f| (f.strip_prefix(root).unwrap().display().to_string(), std::fs::read_to_string(f).unwrap()))
        .collect();
    assert!(files.len() >= 4, "found only {files:?}");
    let modules: HashMap<String, &(String, String)> = files
        .iter()
        .filter_map(|file| {
            let name = file.1.lines().find_map(|l| l.strip_prefix("#define_import_path "))?;
            Some((name.trim().to_string(), file))
        })
        .collect();

    // A file's imports, each after the modules it imports in turn
    // (`lighting::lights` imports `lighting::brdf`).
    fn add_imports<'m>(
        source: &str,
        path: &str,
        modules: &'m HashMap<String, &(String, String)>,
        imports: &mut Vec<(&'m str, String)>,
        failures: &mut Vec<String>,
    ) {
        for imported in imported_paths(source) {
            match module_of(&imported, modules).and_then(|name| modules.get(name)) {
                Some((import_path, text)) => {
                    if imports.iter().all(|(p, _)| p != import_path) {
                        add_imports(text, import_path, modules, imports, failures);
                        imports.push((import_path.as_str(), text.clone()));
                    }
                }
                None => failures.push(format!("{path}: imports unknown module `{imported}`")),
            }
        }
    }

    let mut failures = Vec::new();
    for (path, source) in &files {
        let mut imports = Vec::new();
        add_imports(source, path, &modules, &mut imports, &mut failures);
        if let Err(error) = common::shader::compose(source, path, &imports) {
            failures.push(error.0);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
