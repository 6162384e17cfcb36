//! Every WGSL file in `shaders/` parses and validates, without a GPU.

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

#[test]
fn every_shader_validates() {
    let root = Path::new(common::shader::SHADER_DIR);
    let files = wgsl_files(root);
    assert!(files.len() >= 3, "found only {files:?}");
    let mut failures = Vec::new();
    for file in &files {
        let source = std::fs::read_to_string(file).unwrap();
        let name = file.strip_prefix(root).unwrap().display().to_string();
        if let Err(error) = common::shader::validate(&source, &name) {
            failures.push(error.0);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
