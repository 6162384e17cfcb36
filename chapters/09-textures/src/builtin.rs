//! The files this chapter carries inside its binary: the textures and
//! models `cargo xtask assets` made (see `assets/README.md`), found by
//! their path under `assets/`, so that the chapter runs from anywhere, the
//! browser included, and reads them through the same loader as a
//! learner's files.

use std::path::Path;

use common::files::ReadError;

use crate::obj::normalise;

/// `(path, bytes)` for files under `assets/`, embedded in the binary of
/// the crate that calls it (chapter 10 lists its own files with it).
#[macro_export]
macro_rules! builtin {
    ($($path:literal),* $(,)?) => {
        &[$(($path, include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/", $path)))),*]
    };
}

const FILES: &[(&str, &[u8])] = builtin![
    "textures/brick/albedo.png",
    "textures/brick/normal.png",
    "textures/concrete/albedo.png",
    "textures/concrete/normal.png",
    "textures/metal/albedo.png",
    "textures/metal/normal.png",
    "textures/road/albedo.png",
    "textures/road/normal.png",
    "textures/facade/albedo.png",
    "textures/facade/normal.png",
    "models/car/car.obj",
    "models/car/car.mtl",
    "models/tower/tower.obj",
    "models/tower/tower.mtl",
    "models/boat/boat.obj",
    "models/boat/boat.mtl",
];

/// A built-in file by its path under `assets/` (`..` allowed, as MTL
/// files write them).
pub fn read(path: &Path) -> Result<Vec<u8>, ReadError> {
    find(FILES, path)
}

/// A file of `files` (made by [`builtin!`]) by its path under `assets/`.
/// Chapters 10 and 11 embed only the files they use, in lists of their own.
pub fn find(files: &[(&str, &[u8])], path: &Path) -> Result<Vec<u8>, ReadError> {
    let wanted = normalise(path);
    files
        .iter()
        .find(|(name, _)| Path::new(name) == wanted)
        .map(|(_, bytes)| bytes.to_vec())
        .ok_or_else(|| ReadError { path: path.to_path_buf(), reason: "not among the built-in assets".into() })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_files_are_found_by_relative_paths() {
        assert!(read(Path::new("models/car/../../textures/metal/albedo.png")).is_ok());
        let error = read(Path::new("textures/wood/albedo.png")).unwrap_err();
        assert_eq!(error.to_string(), "cannot read textures/wood/albedo.png: not among the built-in assets");
    }
}
