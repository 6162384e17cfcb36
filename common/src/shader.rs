//! WGSL files: embedded at compile time, composed from modules with
//! naga_oil's `#import`, validated by naga with readable diagnostics, and
//! re-read from disk while a window is open (hot reload).

use std::path::{Path, PathBuf};
#[cfg(not(target_arch = "wasm32"))]
use std::sync::mpsc;

/// The `shaders/` folder of the source tree this binary was built from.
pub const SHADER_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shaders");

/// A WGSL file under `shaders/`, with its text as it was at compile time.
#[derive(Clone, Copy, Debug)]
pub struct ShaderFile {
    /// Path relative to `shaders/`, e.g. `"triangle/triangle.wgsl"`.
    pub path: &'static str,
    pub embedded: &'static str,
    /// Modules this file `#import`s (files that start with
    /// `#define_import_path`), in an order where each comes after its own imports.
    pub imports: &'static [ShaderFile],
}

/// Names a WGSL file under `shaders/` and embeds it, so the binary runs from
/// anywhere, with the modules it imports:
/// `shader!("fog/fog.wgsl", imports: ["terrain/terrain.wgsl"])`.
/// For use in chapter crates (`chapters/NN-name/`).
#[macro_export]
macro_rules! shader {
    ($path:literal $(, imports: [$($import:literal),* $(,)?])? $(,)?) => {
        $crate::ShaderFile {
            path: $path,
            embedded: include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shaders/", $path)),
            imports: &[$($($crate::shader!($import)),*)?],
        }
    };
}

/// A shader that failed to load: naga's diagnostic, with file and line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderError(pub String);

impl std::fmt::Display for ShaderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ShaderError {}

/// Copies `shaders/` into a fresh folder under the system's temp dir
/// (named `name` and the process id) and returns it: hot-reload tests
/// break shaders in the copy, never in the source tree.
pub fn scratch_copy(name: &str) -> std::io::Result<PathBuf> {
    fn copy(from: &std::path::Path, to: &std::path::Path) -> std::io::Result<()> {
        std::fs::create_dir_all(to)?;
        for entry in std::fs::read_dir(from)? {
            let path = entry?.path();
            let target = to.join(path.file_name().unwrap_or_default());
            if path.is_dir() { copy(&path, &target)? } else { std::fs::copy(&path, &target).map(|_| ())? }
        }
        Ok(())
    }
    let root = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
    copy(std::path::Path::new(SHADER_DIR), &root)?;
    Ok(root)
}

impl ShaderFile {
    /// The text under `root` (a folder laid out like `shaders/`, where hot
    /// reload reads), or the embedded copy with `None`.
    pub fn source(&self, root: Option<&Path>) -> Result<String, ShaderError> {
        match root {
            Some(root) => {
                let path = root.join(self.path);
                std::fs::read_to_string(&path).map_err(|e| ShaderError(format!("cannot read {}: {e}", path.display())))
            }
            None => Ok(self.embedded.to_string()),
        }
    }
}

impl ShaderFile {
    /// Composes and validates the embedded text with `edits` made to the
    /// file at `path` (this file or one it imports), each `(before, after)`
    /// replacing text that occurs exactly once: how the book's solutions
    /// check a shader change against the real files.
    pub fn compose_edited(&self, path: &str, edits: &[(&str, &str)]) -> Result<naga::Module, ShaderError> {
        if self.path != path && !self.imports.iter().any(|i| i.path == path) {
            return Err(ShaderError(format!("{path} is not {} nor one of its imports", self.path)));
        }
        let text = |f: &ShaderFile| -> Result<String, ShaderError> {
            let mut text = f.embedded.to_string();
            if f.path == path {
                for (before, after) in edits {
                    if text.matches(before).count() != 1 {
                        return Err(ShaderError(format!("{path} should hold `{before}` once")));
                    }
                    text = text.replacen(before, after, 1);
                }
            }
            Ok(text)
        };
        let imports = self.imports.iter().map(|i| Ok((i.path, text(i)?))).collect::<Result<Vec<_>, ShaderError>>()?;
        compose_with(&text(self)?, self.path, &imports, &[])
    }
}

// ANCHOR: compose
/// Composes WGSL `source` (at `path`) with the modules it `#import`s, each
/// given as (path, text), and validates the result with naga, the same
/// front end wgpu uses. Errors are codespan diagnostics naming the file and
/// line where the problem is, in whichever module that is.
pub fn compose(source: &str, path: &str, imports: &[(&str, String)]) -> Result<naga::Module, ShaderError> {
    compose_with(source, path, imports, &[])
}

/// `compose`, with `defs` defined for the shaders' `#ifdef`s.
pub fn compose_with(
    source: &str,
    path: &str,
    imports: &[(&str, String)],
    defs: &[&str],
) -> Result<naga::Module, ShaderError> {
    use naga_oil::compose::{ComposableModuleDescriptor, Composer, NagaModuleDescriptor, ShaderDefValue};
    let shader_defs: std::collections::HashMap<String, ShaderDefValue> =
        defs.iter().map(|d| (d.to_string(), ShaderDefValue::Bool(true))).collect();
    // Validate what the GPU may run: clip distances are an optional feature.
    let mut composer = Composer::default().with_capabilities(naga::valid::Capabilities::CLIP_DISTANCES);
    for (import_path, text) in imports {
        let added = composer
            .add_composable_module(ComposableModuleDescriptor {
                source: text,
                file_path: import_path,
                shader_defs: shader_defs.clone(),
                ..Default::default()
            })
            .map(drop);
        added.map_err(|e| ShaderError(e.emit_to_string(&composer)))?;
    }
    // A module can also be the top-level shader (the terrain chapter draws
    // with terrain.wgsl itself). naga_oil rejects an import path there, so
    // it is commented out, which keeps the line numbers.
    let source: String = source
        .lines()
        .map(|line| if line.starts_with("#define_import_path") { "//" } else { line })
        .collect::<Vec<_>>()
        .join("\n");
    composer
        .make_naga_module(NagaModuleDescriptor { source: &source, file_path: path, shader_defs, ..Default::default() })
        .map_err(|e| ShaderError(e.emit_to_string(&composer)))
}
// ANCHOR_END: compose

/// Validates a self-contained WGSL file (no imports).
pub fn validate(source: &str, path: &str) -> Result<naga::Module, ShaderError> {
    compose(source, path, &[])
}

/// Watches `shaders/` and reports when a `.wgsl` file changes.
#[cfg(not(target_arch = "wasm32"))]
pub struct ShaderWatcher {
    /// The folder being watched.
    pub dir: PathBuf,
    _watcher: notify::RecommendedWatcher,
    changes: mpsc::Receiver<PathBuf>,
}

#[cfg(not(target_arch = "wasm32"))]
impl ShaderWatcher {
    /// Starts watching, or returns `None` when the source tree is absent
    /// (a binary copied elsewhere): then the embedded shaders are all there is.
    pub fn start() -> Option<Self> {
        use notify::Watcher as _;
        // Canonical, so changed paths read `/…/shaders/x.wgsl`, not `common/../shaders`.
        let dir = std::fs::canonicalize(SHADER_DIR).ok()?;
        let (sender, changes) = mpsc::channel();
        let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
            if let Ok(event) = event
                && (event.kind.is_modify() || event.kind.is_create())
            {
                for path in event.paths {
                    if path.extension().is_some_and(|e| e == "wgsl") {
                        let _ = sender.send(path);
                    }
                }
            }
        })
        .ok()?;
        watcher.watch(&dir, notify::RecursiveMode::Recursive).ok()?;
        Some(Self { dir, _watcher: watcher, changes })
    }

    /// The files changed since the last call (editors often write several
    /// events per save; they are merged into one list).
    pub fn changed(&self) -> Vec<PathBuf> {
        let mut paths: Vec<PathBuf> = self.changes.try_iter().collect();
        paths.sort();
        paths.dedup();
        paths
    }
}

/// A browser page has no source tree to watch: the shaders are the
/// embedded ones, and hot reload is off.
#[cfg(target_arch = "wasm32")]
pub struct ShaderWatcher {
    pub dir: PathBuf,
}

#[cfg(target_arch = "wasm32")]
impl ShaderWatcher {
    pub fn start() -> Option<Self> {
        None
    }

    pub fn changed(&self) -> Vec<PathBuf> {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diagnostic_names_file_and_line() {
        let broken = "@vertex\nfn vs() -> @builtin(position) vec4<f32> {\n    return vec4<f32>(1.0, 2.0);\n}\n";
        let ShaderError(message) = validate(broken, "camera/broken.wgsl").unwrap_err();
        assert!(message.contains("camera/broken.wgsl:3"), "{message}");
    }

    #[test]
    fn imports_compose_and_their_errors_name_the_imported_file() {
        let module = "#define_import_path shapes\n\nfn half(x: f32) -> f32 {\n    return x * 0.5;\n}\n".to_string();
        let user =
            "#import shapes::half\n\n@fragment\nfn fs() -> @location(0) vec4<f32> { return vec4<f32>(half(1.0)); }\n";
        assert!(compose(user, "user.wgsl", &[("lib/shapes.wgsl", module.clone())]).is_ok());
        let broken = module.replace("x * 0.5", "x * true");
        let ShaderError(message) = compose(user, "user.wgsl", &[("lib/shapes.wgsl", broken)]).unwrap_err();
        assert!(message.contains("lib/shapes.wgsl:") && message.contains("x * true"), "{message}");
    }

    #[test]
    fn a_valid_shader_passes() {
        let ok = "@vertex\nfn vs() -> @builtin(position) vec4<f32> { return vec4<f32>(0.0); }\n";
        assert!(validate(ok, "ok.wgsl").is_ok());
    }
}
