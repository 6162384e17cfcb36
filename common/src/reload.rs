//! Hot reload without forwarding: pipelines built from WGSL files register
//! themselves on the device, with the files they were built from, and are
//! rebuilt when one of those files changes, wherever in a chapter they
//! live. A piece keeps a [`Reloadable`] where it would keep its pipelines;
//! nothing has to pass the news down to it.

use std::sync::{Arc, Mutex};

use crate::gpu::Rebuild;
use crate::{Gpu, ShaderError, ShaderFile};

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
    /// What `current` was before the last rebuild, until the page's device
    /// has validated it (browser only).
    #[cfg(target_arch = "wasm32")]
    last_good: Mutex<Option<P>>,
}

impl<P: Clone + wgpu::WasmNotSendSync + 'static> Reloadable<P> {
    /// Runs `build` and keeps what it made; `build` runs again on every
    /// reload of a file it used.
    pub fn new(
        gpu: &Gpu,
        build: impl Fn(&Gpu) -> Result<P, ShaderError> + wgpu::WasmNotSendSync + 'static,
    ) -> Result<Self, ShaderError> {
        let (made, files) = gpu.shaders.recording(|| build(gpu));
        let slot = Arc::new(Slot {
            files,
            build: Box::new(build),
            current: Mutex::new(made?),
            #[cfg(target_arch = "wasm32")]
            last_good: Mutex::new(None),
        });
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

impl<P: wgpu::WasmNotSendSync + 'static> Rebuild for Slot<P> {
    fn uses(&self, file: &str) -> bool {
        self.files.contains(&file)
    }

    fn rebuild(self: Arc<Self>, gpu: &Gpu) -> Result<(), ShaderError> {
        // On an error the last good value stays.
        #[cfg(not(target_arch = "wasm32"))]
        let made = (self.build)(gpu)?;
        // A page's device may answer a pipeline's validation only later
        // (WebGPU): then the value made is taken back when it does.
        #[cfg(target_arch = "wasm32")]
        let made = {
            let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
            let made = (self.build)(gpu)?;
            let slot = self.clone();
            let answer = web_late::answer(scope.pop(), move |error| {
                if let Some(last_good) = slot.last_good.lock().unwrap_or_else(|e| e.into_inner()).take() {
                    *slot.current.lock().unwrap_or_else(|e| e.into_inner()) = last_good;
                }
                web_late::report(error);
            });
            if let Some(error) = answer {
                return Err(ShaderError(error));
            }
            made
        };
        let last_good = std::mem::replace(&mut *self.current.lock().unwrap_or_else(|e| e.into_inner()), made);
        #[cfg(target_arch = "wasm32")]
        {
            *self.last_good.lock().unwrap_or_else(|e| e.into_inner()) = Some(last_good);
        }
        #[cfg(not(target_arch = "wasm32"))]
        drop(last_good);
        Ok(())
    }
}

/// A page's late answers: WebGPU validates a pipeline in the browser's GPU
/// process and says so in a promise.
#[cfg(target_arch = "wasm32")]
mod web_late {
    use std::cell::RefCell;
    use std::future::Future;
    use std::task::{Context, Poll, Waker};

    thread_local! {
        static LATE: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
    }

    /// The error at once if the scope's answer is ready (WebGL2: wgpu
    /// validates in the page); otherwise `late` gets it once it comes.
    pub(super) fn answer(
        popped: impl Future<Output = Option<wgpu::Error>> + 'static,
        late: impl FnOnce(String) + 'static,
    ) -> Option<String> {
        let mut popped = Box::pin(popped);
        match popped.as_mut().poll(&mut Context::from_waker(Waker::noop())) {
            Poll::Ready(error) => error.map(|e| e.to_string()),
            Poll::Pending => {
                wasm_bindgen_futures::spawn_local(async move {
                    if let Some(error) = popped.await {
                        late(error.to_string());
                    }
                });
                None
            }
        }
    }

    pub(super) fn report(error: String) {
        LATE.with(|late| late.borrow_mut().push(error));
    }

    pub(super) fn take() -> Vec<String> {
        LATE.with(|late| std::mem::take(&mut *late.borrow_mut()))
    }
}

// Making a module is where a file is noted for hot reload, so it lives
// here, beside the registry's other users; `shader` itself knows no device.
impl ShaderFile {
    /// Composes the current text (where `gpu` reads shaders from: see
    /// [`crate::Gpu::read_shaders_from`]) with its imports, validates it,
    /// and creates a shader module from it on `gpu`'s device. On a device
    /// with WebGPU's `clip_distances` feature, `CLIP_DISTANCES` is defined
    /// for `#ifdef`s in the WGSL (chapter 07 clips with it).
    /// Inside [`crate::Reloadable::new`], the file and its imports are noted
    /// as what to rebuild from when they change.
    pub fn module(&self, gpu: &crate::Gpu) -> Result<wgpu::ShaderModule, ShaderError> {
        gpu.shaders.note(self);
        let root = gpu.shader_root();
        let mut imports = Vec::new();
        for import in self.imports {
            imports.push((import.path, gpu.shaders.text(import, root.as_deref())?));
        }
        let device = &gpu.device;
        let clip_distances = device.features().contains(wgpu::Features::CLIP_DISTANCES);
        let defs: &[&str] = if clip_distances { &["CLIP_DISTANCES"] } else { &[] };
        let module = crate::shader::compose_with(&gpu.shaders.text(self, root.as_deref())?, self.path, &imports, defs)?;
        Ok(device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(self.path),
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(module)),
        }))
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
        let rebuilt = users.len();
        let mut errors: Vec<String> = Vec::new();
        for error in users.into_iter().filter_map(|entry| entry.rebuild(self).err()) {
            // A broken module imported by several pipelines says so once.
            if !errors.contains(&error.0) {
                errors.push(error.0);
            }
        }
        if errors.is_empty() { Ok(rebuilt) } else { Err(ShaderError(errors.join("\n\n"))) }
    }

    /// Errors a page's device reported after a rebuild had returned
    /// (WebGPU validates pipelines in the browser's GPU process): the
    /// pipelines concerned are back to their last good version. Always
    /// empty on the desktop, where validation answers at once.
    pub fn late_shader_errors(&self) -> Vec<String> {
        #[cfg(target_arch = "wasm32")]
        return web_late::take();
        #[cfg(not(target_arch = "wasm32"))]
        Vec::new()
    }

    /// The WGSL files this device's live pipelines were made from, the
    /// modules they import included, by path: what the shader panel lists.
    pub fn shader_files(&self) -> Vec<ShaderFile> {
        let met = self.shaders.met.lock().unwrap_or_else(|e| e.into_inner()).clone();
        let mut used: Vec<ShaderFile> =
            met.into_iter().filter(|file| !self.shaders.using(&[file.path]).is_empty()).collect();
        used.sort_by_key(|file| file.path);
        used
    }

    /// How many live pipeline sets ([`Reloadable`]s) are made from the file
    /// at `path`, directly or through a file that imports it.
    pub fn shader_users(&self, path: &str) -> usize {
        self.shaders.using(&[path]).len()
    }

    /// The text the file at `path` is built from now (an edit, the source
    /// tree's, or the embedded copy), or `None` for a file no live
    /// pipeline uses.
    pub fn shader_text(&self, path: &str) -> Option<String> {
        let file = self.shader_files().into_iter().find(|file| file.path == path)?;
        self.shaders.text(&file, self.shader_root().as_deref()).ok()
    }

    // ANCHOR: edit_shader
    /// The shader panel's entry point: builds the file at `path` from
    /// `text` from now on (`None`: from its own file again), and rebuilds
    /// every live pipeline made from it or from a file that imports it.
    /// On an error the edit stays in place, as a text editor keeps what was
    /// typed, while the pipelines keep their last good version.
    pub fn edit_shader(&self, path: &str, text: Option<&str>) -> Result<usize, ShaderError> {
        self.set_shader_edit(path, text)?;
        self.reload_shaders(&[path])
    }
    // ANCHOR_END: edit_shader

    /// [`Gpu::edit_shader`] without the rebuild: for an edit that was saved
    /// to the file it replaces, so that the two agree and nothing reloads.
    pub fn set_shader_edit(&self, path: &str, text: Option<&str>) -> Result<(), ShaderError> {
        let files = self.shader_files();
        let Some(file) = files.iter().find(|file| file.path == path) else {
            let names: Vec<&str> = files.iter().map(|file| file.path).collect();
            return Err(ShaderError(format!("no shader {path} here; this chapter's are: {}", names.join(", "))));
        };
        let mut edits = self.shaders.edits.lock().unwrap_or_else(|e| e.into_inner());
        match text {
            Some(text) => edits.insert(file.path.to_string(), text.to_string()),
            None => edits.remove(file.path),
        };
        Ok(())
    }

    /// Edits to build with before any pipeline exists (a page restoring the
    /// reader's edits, or a shared link's, before the chapter is made).
    /// Paths no pipeline turns out to use are simply never read.
    pub fn start_with_shader_edits(&self, edits: Vec<(String, String)>) {
        self.shaders.edits.lock().unwrap_or_else(|e| e.into_inner()).extend(edits);
    }

    /// Forgets every edit (a chapter that failed to build with them is made
    /// again without).
    pub fn drop_shader_edits(&self) {
        self.shaders.edits.lock().unwrap_or_else(|e| e.into_inner()).clear();
    }

    /// The files built from an edit now, with its text, by path.
    pub fn shader_edits(&self) -> Vec<(String, String)> {
        let edits = self.shaders.edits.lock().unwrap_or_else(|e| e.into_inner());
        let mut all: Vec<(String, String)> = edits.iter().map(|(path, text)| (path.clone(), text.clone())).collect();
        all.sort();
        all
    }
}
