//! Finding a GPU (or a software rasteriser) and opening a device on it.
//!
//! Everything else in the book starts from a [`Gpu`]: the adapter says what
//! the machine can do, the device creates resources, the queue runs work.

use std::any::Any;
use std::collections::HashMap;
use std::fmt;
use std::path::PathBuf;
use std::sync::{Arc, Mutex, Weak};

use crate::shader::{ShaderError, ShaderFile};

/// The adapter, device and queue a chapter draws with.
pub struct Gpu {
    pub instance: wgpu::Instance,
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// See [`Gpu::cached`].
    cache: Mutex<Vec<Box<dyn Any + Send>>>,
    /// Where shaders are read from, and what to rebuild when they change.
    pub(crate) shaders: ShaderRegistry,
}

/// What a chapter needs beyond the WebGPU baseline. Optional features are
/// enabled when the adapter has them; required ones make setup fail clearly.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GpuNeeds {
    pub required: wgpu::Features,
    pub optional: wgpu::Features,
    /// What the chapter needs of an adapter that is less than a full
    /// WebGPU one (OpenGL, WebGL2): compute shaders, storage buffers in
    /// vertex shaders, indirect draws. Setup on an adapter without them
    /// fails with one line naming what is missing.
    pub downlevel: wgpu::DownlevelFlags,
    /// The least the chapter can draw with: an adapter below any of these
    /// is refused in one line naming each. Every device is opened with
    /// WebGPU's default limits (or the adapter's, where it has less), raised
    /// only to these, so that a pipeline that asks for more than a learner's
    /// adapter must give fails here too. The default is WebGL2's, the least
    /// any adapter the course runs on has.
    pub limits: wgpu::Limits,
}

/// Nothing beyond WebGPU's baseline, and nothing WebGL2 lacks.
impl Default for GpuNeeds {
    fn default() -> Self {
        Self {
            required: wgpu::Features::empty(),
            optional: wgpu::Features::empty(),
            downlevel: wgpu::DownlevelFlags::empty(),
            limits: wgpu::Limits::downlevel_webgl2_defaults(),
        }
    }
}

impl GpuNeeds {
    /// What an adapter with `features`, `downlevel` and `limits` lacks of
    /// these needs, one phrase each (empty: it has everything).
    pub fn missing_on(
        &self,
        features: wgpu::Features,
        downlevel: wgpu::DownlevelFlags,
        limits: &wgpu::Limits,
    ) -> Vec<String> {
        let mut missing = Vec::new();
        let features = self.required - features;
        if !features.is_empty() {
            missing
                .push(format!("the features {}", features.iter_names().map(|(n, _)| n).collect::<Vec<_>>().join(", ")));
        }
        if !(self.downlevel - downlevel).is_empty() {
            missing.push(names(self.downlevel - downlevel));
        }
        self.limits.check_limits_with_fail_fn(limits, false, |name, needed, has| {
            missing.push(format!("{name} of {needed} (it has {has})"));
        });
        missing
    }

    /// The limits a device is opened with on an adapter that has
    /// `adapter`: WebGPU's defaults raised to what the chapter needs, and
    /// lowered to what the adapter has.
    pub fn device_limits(&self, adapter: &wgpu::Limits) -> wgpu::Limits {
        wgpu::Limits::default().or_better_values_from(&self.limits).or_worse_values_from(adapter)
    }
}

/// Instance flags for `backends`: without wgpu's validation of indirect
/// draws where OpenGL may be chosen. That validation runs a compute shader
/// that an OpenGL 3.3 driver cannot build, and
/// the device is lost before the first frame (wgpu issue #8799); the
/// course's indirect arguments are written by its own compute pass, whose
/// counts chapter 05's tests check.
pub fn instance_flags(flags: wgpu::InstanceFlags, backends: wgpu::Backends) -> wgpu::InstanceFlags {
    if backends.contains(wgpu::Backends::GL) { flags - wgpu::InstanceFlags::VALIDATION_INDIRECT_CALL } else { flags }
}

/// Setup failed in a way a learner can fix: the message says how.
#[derive(Debug)]
pub struct NoAdapter {
    pub reason: String,
    /// An adapter was found but lacks what the chapter needs (`reason`
    /// names each); otherwise there was none, or no device could be opened.
    pub lacking: bool,
}

impl NoAdapter {
    /// No adapter, or none that opened a device, for `reason`.
    pub fn none(reason: impl Into<String>) -> Self {
        Self { reason: reason.into(), lacking: false }
    }
}

/// Where to get a working driver on the system this runs on.
fn driver_advice() -> &'static str {
    if cfg!(target_os = "macos") {
        "Metal comes with macOS 10.13 and later: update macOS, or run on a Mac with a Metal GPU"
    } else if cfg!(target_os = "windows") {
        "install your GPU maker's current driver (DirectX 12 or Vulkan)"
    } else {
        "install a driver; with no GPU, the software Vulkan driver works: \
         `sudo apt-get install mesa-vulkan-drivers` on Debian/Ubuntu"
    }
}

impl fmt::Display for NoAdapter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (cfg!(target_arch = "wasm32"), self.lacking) {
            (true, false) => write!(
                f,
                "this browser gives the page neither WebGPU nor WebGL2 ({}). Open it in a browser with \
                 WebGPU turned on, or turn on hardware acceleration (WebGL2), or run the chapter on the \
                 desktop: `cargo run -p <chapter>`",
                self.reason
            ),
            (true, true) => write!(
                f,
                "this browser's adapter cannot draw this chapter: {}. Open it in a browser with WebGPU \
                 turned on, or run the chapter on the desktop: `cargo run -p <chapter>`",
                self.reason
            ),
            (false, false) => write!(f, "no usable graphics adapter ({}). {}", self.reason, driver_advice()),
            (false, true) => write!(f, "{}", self.reason),
        }
    }
}

impl std::error::Error for NoAdapter {}

/// Mesa's Vulkan driver prints "XDG_RUNTIME_DIR is invalid" twice per
/// device when that variable is unset, as it is on servers and in
/// containers; nothing here needs it. Call first thing in `main`, before
/// any other thread exists.
pub fn quiet_driver_warnings() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        // SAFETY: called at the start of `main`, while no other thread can
        // read the environment.
        unsafe { std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir()) };
    }
}

/// The instance a window asks for its device, with the backends `desc`
/// allows (in a browser the caller puts the page's choice there: both,
/// or only one with `?backend=`). In a browser WebGPU comes first, and
/// WebGL2 where the browser has no working WebGPU adapter; `Instance::new`
/// alone would pick WebGPU whenever `navigator.gpu` exists, even with no
/// adapter behind it.
pub async fn window_instance(mut desc: wgpu::InstanceDescriptor) -> wgpu::Instance {
    desc.flags = instance_flags(desc.flags, desc.backends);
    #[cfg(target_arch = "wasm32")]
    {
        wgpu::util::new_instance_with_webgpu_detection(desc).await
    }
    #[cfg(not(target_arch = "wasm32"))]
    wgpu::Instance::new(desc)
}

/// The adapter's downlevel capabilities as a chapter can use them: what
/// wgpu reports, less compute shaders on an OpenGL context older than 4.3
/// (or OpenGL ES 3.1). wgpu counts compute there when the driver offers
/// `GL_ARB_compute_shader` (Mesa does, under any version), but it writes
/// GLSL for the context's own version, and GLSL 3.30 has no compute stage:
/// the pipeline would fail to build ("selected version doesn't support
/// COMPUTE_SHADER") where the chapter could have fallen back or refused.
pub fn usable_downlevel(adapter: &wgpu::Adapter) -> wgpu::DownlevelCapabilities {
    let mut capabilities = adapter.get_downlevel_capabilities();
    let info = adapter.get_info();
    if info.backend == wgpu::Backend::Gl && !gl_version_compiles_compute(&info.driver_info) {
        capabilities.flags -= wgpu::DownlevelFlags::COMPUTE_SHADERS;
    }
    capabilities
}

/// Whether an OpenGL context whose `GL_VERSION` string is `version` (wgpu
/// gives it as the adapter's `driver_info`) takes compute shaders in its
/// own GLSL version: OpenGL 4.3 or OpenGL ES 3.1 and later. A string this
/// cannot read is trusted to be what wgpu said.
pub fn gl_version_compiles_compute(version: &str) -> bool {
    // "4.6.0 NVIDIA 550.54", "3.3 (Core Profile) Mesa 24.2", "OpenGL ES 3.2
    // Mesa 24.2", "WebGL 2.0 (OpenGL ES 3.0 Chromium)".
    let (numbers, least) = match version.rfind(" ES ") {
        Some(at) => (&version[at + 4..], (3, 1)),
        None if version.starts_with("WebGL ") => return false,
        None => (version, (4, 3)),
    };
    let mut parts = numbers.split(|c: char| !c.is_ascii_digit()).filter(|p| !p.is_empty());
    match (parts.next().and_then(|p| p.parse::<u32>().ok()), parts.next().and_then(|p| p.parse::<u32>().ok())) {
        (Some(major), Some(minor)) => (major, minor) >= least,
        _ => true,
    }
}

/// `COMPUTE_SHADERS, VERTEX_STORAGE`: flags by name, for a one-line message.
fn names(flags: wgpu::DownlevelFlags) -> String {
    flags.iter_names().map(|(name, _)| name).collect::<Vec<_>>().join(", ")
}

impl Gpu {
    /// What the adapter can do of what WebGPU takes for granted, as the
    /// chapters may rely on it (see [`usable_downlevel`]).
    pub fn downlevel(&self) -> wgpu::DownlevelCapabilities {
        usable_downlevel(&self.adapter)
    }

    /// A device with no window: for screenshots, benches and tests.
    ///
    /// `WGPU_BACKEND` (vulkan, gl, metal, dx12) picks the API. Without it
    /// the primary APIs are tried first and OpenGL only if they find
    /// nothing, which avoids GL driver noise on machines with Vulkan.
    pub fn headless(needs: GpuNeeds) -> Result<Self, NoAdapter> {
        if let Some(backends) = wgpu::Backends::from_env() {
            return Self::headless_on(backends, needs);
        }
        Self::headless_on(wgpu::Backends::PRIMARY, needs.clone())
            .or_else(|_| Self::headless_on(wgpu::Backends::GL, needs))
    }

    /// [`Gpu::headless`] on `backends` only: the snapshot test draws every
    /// chapter on OpenGL too.
    pub fn headless_on(backends: wgpu::Backends, needs: GpuNeeds) -> Result<Self, NoAdapter> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        desc.backends = backends;
        desc.flags = instance_flags(desc.flags, backends);
        pollster::block_on(Self::open(wgpu::Instance::new(desc), None, needs))
    }

    /// A device that can present to `surface` (created from `instance`).
    pub async fn open(
        instance: wgpu::Instance,
        surface: Option<&wgpu::Surface<'_>>,
        needs: GpuNeeds,
    ) -> Result<Self, NoAdapter> {
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: surface,
                ..Default::default()
            })
            .await
            .map_err(|e| NoAdapter::none(e.to_string()))?;

        let has = adapter.limits();
        let missing = needs.missing_on(adapter.features(), usable_downlevel(&adapter).flags, &has);
        if !missing.is_empty() {
            let info = adapter.get_info();
            return Err(NoAdapter {
                reason: format!(
                    "{} on {:?} cannot do what this chapter needs: {}",
                    info.name,
                    info.backend,
                    missing.join("; ")
                ),
                lacking: true,
            });
        }
        let features = needs.required | (needs.optional & adapter.features());
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("chapter device"),
                required_features: features,
                required_limits: needs.device_limits(&has),
                ..Default::default()
            })
            .await
            .map_err(|e| NoAdapter::none(format!("request_device failed: {e}")))?;

        Ok(Self { instance, adapter, device, queue, cache: Mutex::default(), shaders: Default::default() })
    }

    /// Returns the value made for `key` on this device, making it first if
    /// the last value of this type was made for another key (one is kept
    /// per type). For immutable data that is slow to make and the same for
    /// every instance that asks, like chapter 03's terrain: a window that
    /// regenerates it keeps one copy, and tests that create a chapter many
    /// times make it once. `make` must not call `cached` itself.
    pub fn cached<K, V>(&self, key: K, make: impl FnOnce() -> V) -> Arc<V>
    where
        K: PartialEq + Send + 'static,
        V: Send + Sync + 'static,
    {
        let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
        let slot = cache.iter_mut().find_map(|entry| entry.downcast_mut::<(K, Arc<V>)>());
        match slot {
            Some((k, v)) if *k == key => v.clone(),
            Some(entry) => {
                *entry = (key, Arc::new(make()));
                entry.1.clone()
            }
            None => {
                let value = Arc::new(make());
                cache.push(Box::new((key, value.clone())));
                value
            }
        }
    }

    /// Whether [`Gpu::cached`] holds a value of type `V` made for `key`.
    pub fn is_cached<K, V>(&self, key: &K) -> bool
    where
        K: PartialEq + Send + 'static,
        V: Send + Sync + 'static,
    {
        let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
        cache.iter_mut().find_map(|entry| entry.downcast_mut::<(K, Arc<V>)>()).is_some_and(|(k, _)| k == key)
    }

    /// Makes the shaders this device builds come from `root` (a folder laid
    /// out like `shaders/`) instead of the copies embedded in the binary,
    /// or from the embedded copies again with `None`. The window points
    /// this at the source tree it watches for edits (hot reload); a test
    /// points it at a scratch copy it breaks, on a device of its own.
    pub fn read_shaders_from(&self, root: Option<PathBuf>) {
        *self.shaders.root.lock().unwrap_or_else(|e| e.into_inner()) = root;
    }

    /// Where this device's shaders come from: see [`Gpu::read_shaders_from`].
    pub fn shader_root(&self) -> Option<PathBuf> {
        self.shaders.root.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// One line naming the adapter, for logs and bench tables.
    pub fn describe(&self) -> String {
        let info = self.adapter.get_info();
        format!("{} ({:?}, {:?})", info.name, info.backend, info.device_type)
    }

    /// Runs `create` inside a validation error scope and returns the error
    /// instead of letting wgpu's default handler panic. Hot reload uses
    /// this so that a shader that parses but does not fit its pipeline
    /// layout is reported, not fatal.
    ///
    /// In the browser an error scope can only be awaited, and there is no
    /// hot reload to protect, so `create` simply runs: a mistake there is a
    /// bug, reported by wgpu on the console.
    pub fn catch_validation<T>(&self, create: impl FnOnce() -> T) -> Result<T, String> {
        if cfg!(target_arch = "wasm32") {
            return Ok(create());
        }
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let value = create();
        match pollster::block_on(scope.pop()) {
            None => Ok(value),
            Some(error) => Err(error.to_string()),
        }
    }
}

/// What the device's registry can do with a [`Reloadable`] of any type.
#[cfg(not(target_arch = "wasm32"))]
pub(crate) trait Rebuild: Send + Sync {
    fn uses(&self, file: &str) -> bool;
    fn rebuild(self: Arc<Self>, gpu: &Gpu) -> Result<(), ShaderError>;
}
#[cfg(target_arch = "wasm32")]
pub(crate) trait Rebuild {
    fn uses(&self, file: &str) -> bool;
    fn rebuild(self: Arc<Self>, gpu: &Gpu) -> Result<(), ShaderError>;
}

/// A device's shaders: where they are read from, and every [`Reloadable`]
/// built on it that is still alive. Part of [`Gpu`]: it lives here, beside it, so that the device and
/// `reload`, which rebuilds pipelines on the device, do not lean on each
/// other.
#[derive(Default)]
pub(crate) struct ShaderRegistry {
    pub(crate) root: Mutex<Option<std::path::PathBuf>>,
    /// Text the shader panel put in place of a file's, by path: read before
    /// the source tree or the embedded copy (see [`Gpu::edit_shader`]).
    pub(crate) edits: Mutex<HashMap<String, String>>,
    /// Every file a module was made from on this device, with its imports.
    pub(crate) met: Mutex<Vec<ShaderFile>>,
    pub(crate) live: Mutex<Vec<Weak<dyn Rebuild>>>,
    /// The files noted by each `build` running now, with its thread
    /// (tests build on one device from several threads), innermost last.
    pub(crate) noting: Mutex<Vec<(std::thread::ThreadId, Vec<&'static str>)>>,
}

impl ShaderRegistry {
    /// Runs `build`, returning what it made and the files it read.
    pub(crate) fn recording<T>(&self, build: impl FnOnce() -> T) -> (T, Vec<&'static str>) {
        let thread = std::thread::current().id();
        self.noting.lock().unwrap_or_else(|e| e.into_inner()).push((thread, Vec::new()));
        let made = build();
        let mut noting = self.noting.lock().unwrap_or_else(|e| e.into_inner());
        let mine = noting.iter().rposition(|(t, _)| *t == thread).expect("pushed above");
        (made, noting.remove(mine).1)
    }

    /// The text a module is made from: the panel's edit, else the file
    /// under `root` (the source tree), else the embedded copy.
    pub(crate) fn text(&self, file: &ShaderFile, root: Option<&std::path::Path>) -> Result<String, ShaderError> {
        match self.edits.lock().unwrap_or_else(|e| e.into_inner()).get(file.path) {
            Some(edited) => Ok(edited.clone()),
            None => file.source(root),
        }
    }

    /// `ShaderFile::module` calls this for the file it reads and its imports.
    pub(crate) fn note(&self, file: &ShaderFile) {
        let mut met = self.met.lock().unwrap_or_else(|e| e.into_inner());
        for met_now in std::iter::once(file).chain(file.imports) {
            if !met.iter().any(|known| known.path == met_now.path) {
                met.push(*met_now);
            }
        }
        drop(met);
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
    pub(crate) fn using(&self, changed: &[&str]) -> Vec<Arc<dyn Rebuild>> {
        let mut live = self.live.lock().unwrap_or_else(|e| e.into_inner());
        live.retain(|entry| entry.strong_count() > 0);
        live.iter().filter_map(Weak::upgrade).filter(|entry| changed.iter().any(|file| entry.uses(file))).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::gl_version_compiles_compute;

    /// Compute shaders are core in OpenGL 4.3 and OpenGL ES 3.1 (the
    /// Khronos specifications' version histories); WebGL2 has none. The
    /// strings are as drivers write GL_VERSION.
    #[test]
    fn compute_is_counted_from_opengl_4_3_and_es_3_1() {
        for (version, compute) in [
            ("4.6.0 NVIDIA 550.54.14", true),
            ("4.5 (Core Profile) Mesa 22.3.6", true),
            ("4.3 (Core Profile) Mesa 22.3.6", true),
            ("4.2 (Core Profile) Mesa 22.3.6", false),
            ("3.3 (Core Profile) Mesa 22.3.6", false),
            ("4.1 Metal - 88.1", false),
            ("OpenGL ES 3.2 Mesa 22.3.6", true),
            ("OpenGL ES 3.1 v1.r38p1", true),
            ("OpenGL ES 3.0 Mesa 22.3.6", false),
            ("WebGL 2.0 (OpenGL ES 3.0 Chromium)", false),
            ("WebGL 2.0", false),
            // Unreadable: wgpu's word stands.
            ("unknown", true),
        ] {
            assert_eq!(gl_version_compiles_compute(version), compute, "{version}");
        }
    }
}
