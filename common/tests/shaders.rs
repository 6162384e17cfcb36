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

/// The module names a file imports: `#import terrain::{a, b}` → `terrain`.
fn imported_modules(source: &str) -> Vec<String> {
    source
        .lines()
        .filter_map(|l| l.strip_prefix("#import "))
        .map(|rest| rest.split(|c: char| c == ':' || c == ';' || c.is_whitespace()).next().unwrap_or("").to_string())
        .collect()
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

    let mut failures = Vec::new();
    for (path, source) in &files {
        let mut imports = Vec::new();
        for name in imported_modules(source) {
            match modules.get(&name) {
                Some((import_path, text)) => imports.push((import_path.as_str(), text.clone())),
                None => failures.push(format!("{path}: imports unknown module `{name}`")),
            }
        }
        if let Err(error) = common::shader::compose(source, path, &imports) {
            failures.push(error.0);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
