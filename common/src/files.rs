//! Reading files a learner names (a model, its materials, its textures).
//! Chapters read through here, never `std::fs` directly, so that the web
//! build has one place to fetch from instead.

use std::path::{Path, PathBuf};

/// A file that could not be read: which one, and why.
#[derive(Debug)]
pub struct ReadError {
    pub path: PathBuf,
    pub reason: String,
}

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot read {}: {}", self.path.display(), self.reason)
    }
}

impl std::error::Error for ReadError {}

/// The whole file at `path`.
pub fn read(path: &Path) -> Result<Vec<u8>, ReadError> {
    std::fs::read(path).map_err(|e| ReadError { path: path.to_path_buf(), reason: reason(&e) })
}

/// An I/O error as a short reason, without the "(os error 2)" tail.
fn reason(error: &std::io::Error) -> String {
    match error.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        std::io::ErrorKind::IsADirectory => "it is a folder, not a file".into(),
        _ => error.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_file_is_named_with_a_plain_reason() {
        let error = read(Path::new("no/such/model.obj")).unwrap_err();
        assert_eq!(error.to_string(), "cannot read no/such/model.obj: no such file");
    }

    #[test]
    fn a_folder_is_not_a_file() {
        let error = read(&std::env::temp_dir()).unwrap_err();
        assert!(error.to_string().contains("cannot read"), "{error}");
    }
}
