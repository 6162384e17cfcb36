//! Hot reload without forwarding: pipelines built from WGSL files register
//! themselves on the device, with the files they were built from, and are
//! rebuilt when one of those files changes, wherever in a chapter they
//! live. A piece keeps a [`Reloadable`] where it would keep its pipelines;
//! nothing has to pass the news down to it.

use std::sync::{Arc, Mutex, Weak};

use crate::{Gpu, ShaderError};

/// Pipelines (or anything else made from shaders) that `build` makes, and
/// makes again when a WGSL file it read changes: see [`Gpu::reload_shaders`].
/// The files are the ones `build` turned into modules with
/// [`crate::ShaderFile::module`], with the modules they import; they are
/// noted while `build` runs, so they cannot be listed wrong.
pub struct Reloadable<P> {
    slot: Arc<Slot<P>>,
}

// A device is shared between threads on the desktop; a page has one thread,
// where wgpu's handles are not `Send`.
#[cfg(not(target_arch = "wasm32"))]
type Build<P> = Box<dyn Fn(&Gpu) -> Result<P, ShaderError> + Send + Sync>;
#[cfg(target_arch = "wasm32")]
type Build<P> = Box<dyn Fn(&Gpu) -> Result<P, ShaderError>>;

struct Slot<P> {
    files: Vec<&'static str>,
    build: Build<P>,
    current: Mutex<P>,
}

impl<P: Clone + wgpu::WasmNotSendSync + 'static> Reloadable<P> {
    /// Runs `build` and keeps what it made; `build` runs again on every
    /// reload of a file it used.
    pub fn new(
        gpu: &Gpu,
        build: impl Fn(&Gpu) -> Result<P, ShaderError> + wgpu::WasmNotSendSync + 'static,
    ) -> Result<Self, ShaderError> {
        let (made, files) = gpu.shaders.recording(|| build(gpu));
        let slot = Arc::new(Slot { files, build: Box::new(build), current: Mutex::new(made?) });
        let rebuild: Arc<dyn Rebuild> = slot.clone();
        let mut live = gpu.shaders.live.lock().unwrap_or_else(|e| e.into_inner());
        // Pieces that remake theirs (chapter 10's caster, on a new bias)
        // drop the old one: forget it here.
        live.retain(|entry| entry.strong_count() > 0);
        live.push(Arc::downgrade(&rebuild));
        drop(live);
        Ok(Self { slot })
    }

    /// What `build` made last time it succeeded. Pipelines are handles: the
    /// clone is cheap.
    pub fn get(&self) -> P {
        self.slot.current.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// The WGSL files (paths under `shaders/`) this was built from.
    pub fn files(&self) -> &[&'static str] {
        &self.slot.files
    }
}

/// What the device's registry can do with a [`Reloadable`] of any type.
#[cfg(not(target_arch = "wasm32"))]
trait Rebuild: Send + Sync {
    fn uses(&self, file: &str) -> bool;
    fn rebuild(&self, gpu: &Gpu) -> Result<(), ShaderError>;
}
#[cfg(target_arch = "wasm32")]
trait Rebuild {
    fn uses(&self, file: &str) -> bool;
    fn rebuild(&self, gpu: &Gpu) -> Result<(), ShaderError>;
}

impl<P: wgpu::WasmNotSendSync + 'static> Rebuild for Slot<P> {
    fn uses(&self, file: &str) -> bool {
        self.files.contains(&file)
    }

    fn rebuild(&self, gpu: &Gpu) -> Result<(), ShaderError> {
        // On an error the last good value stays.
        let made = (self.build)(gpu)?;
        *self.current.lock().unwrap_or_else(|e| e.into_inner()) = made;
        Ok(())
    }
}

/// A device's shaders: where they are read from, and every [`Reloadable`]
/// built on it that is still alive. Part of [`Gpu`].
#[derive(Default)]
pub(crate) struct ShaderRegistry {
    pub(crate) root: Mutex<Option<std::path::PathBuf>>,
    live: Mutex<Vec<Weak<dyn Rebuild>>>,
    /// The files noted by each `build` running now, with its thread
    /// (tests build on one device from several threads), innermost last.
    noting: Mutex<Vec<(std::thread::ThreadId, Vec<&'static str>)>>,
}

impl ShaderRegistry {
    /// Runs `build`, returning what it made and the files it read.
    fn recording<T>(&self, build: impl FnOnce() -> T) -> (T, Vec<&'static str>) {
        let thread = std::thread::current().id();
        self.noting.lock().unwrap_or_else(|e| e.into_inner()).push((thread, Vec::new()));
        let made = build();
        let mut noting = self.noting.lock().unwrap_or_else(|e| e.into_inner());
        let mine = noting.iter().rposition(|(t, _)| *t == thread).expect("pushed above");
        (made, noting.remove(mine).1)
    }

    /// `ShaderFile::module` calls this for the file it reads and its imports.
    pub(crate) fn note(&self, file: &crate::ShaderFile) {
        let mut noting = self.noting.lock().unwrap_or_else(|e| e.into_inner());
        let thread = std::thread::current().id();
        if let Some((_, files)) = noting.iter_mut().rev().find(|(t, _)| *t == thread) {
            for path in std::iter::once(file.path).chain(file.imports.iter().map(|i| i.path)) {
                if !files.contains(&path) {
                    files.push(path);
                }
            }
        }
    }

    /// The live entries that use any of `changed`, dropping dead ones.
    fn using(&self, changed: &[&str]) -> Vec<Arc<dyn Rebuild>> {
        let mut live = self.live.lock().unwrap_or_else(|e| e.into_inner());
        live.retain(|entry| entry.strong_count() > 0);
        live.iter().filter_map(Weak::upgrade).filter(|entry| changed.iter().any(|file| entry.uses(file))).collect()
    }
}

impl Gpu {
    /// WGSL files changed (paths under `shaders/`, like
    /// `"triangle/triangle.wgsl"`): rebuilds every live [`Reloadable`] made
    /// from one of them, reading where [`Gpu::read_shaders_from`] says.
    /// Returns how many were rebuilt, or every error, one after another:
    /// whatever failed keeps its last good pipelines.
    pub fn reload_shaders(&self, changed: &[&str]) -> Result<usize, ShaderError> {
        // Outside the registry's lock: a rebuild notes files and may register.
        let users = self.shaders.using(changed);
        let mut errors: Vec<String> = Vec::new();
        for error in users.iter().filter_map(|entry| entry.rebuild(self).err()) {
            // A broken module imported by several pipelines says so once.
            if !errors.contains(&error.0) {
                errors.push(error.0);
            }
        }
        if errors.is_empty() { Ok(users.len()) } else { Err(ShaderError(errors.join("\n\n"))) }
    }
}
