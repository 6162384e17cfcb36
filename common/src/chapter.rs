//! The contract every chapter fulfils, so that one runner can open it in a
//! window, render it headless to a PNG, benchmark it and snapshot-test it.

use crate::multisampling::{Antialiasing, SceneTargets};
// Where chapters have long found it: it is multisampling's, whose samples it carries.
pub use crate::multisampling::Target;
use crate::{Camera, CameraPlace, DrawCounts, Gpu, GpuNeeds, Input, PassTimer, Preparation};

// For existing imports (`use common::chapter::{uniform_entry, …}`): the
// helpers live in `crate::pipeline` now.
pub use crate::pipeline::{
    FILTERABLE, mesh_pipeline, sampler_entry, scene_pass, storage_entry, texture_entry, uniform_entry,
};

/// A mistake in the flags found after parsing, a chapter's own included:
/// exit code 2, like clap's.
#[derive(Debug)]
pub struct UsageError(pub String);

impl std::fmt::Display for UsageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for UsageError {}

/// A named picture a chapter can show: the default scene, a preset, or a
/// debug view such as the depth buffer. Every view is a snapshot and a
/// figure, except bench views.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct View {
    pub name: &'static str,
    pub about: &'static str,
    pub kind: ViewKind,
    /// Compared with a reference image by the tests. False for views that
    /// exist to be measured (`View::bench`).
    pub snapshot: bool,
    /// The view whose picture this one draws again by another method, to
    /// compare their cost (instanced rocks and one draw call each). The
    /// tests then check the two look alike, where every other two views
    /// must look different. `None` for most views.
    pub same_picture_as: Option<&'static str>,
    /// How this view smooths edges whatever the runner asks (`no-aa`
    /// views: `Antialiasing::Off`); `None`, as most views, follows
    /// `--antialiasing` and the overlay's switch.
    pub antialiasing: Option<Antialiasing>,
}

/// What choosing a view does to the camera. Either way, what a view shows
/// never depends on the views chosen before it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewKind {
    /// A way of drawing (`flat`, `no-fog`, `wireframe`): it never touches
    /// the camera, so a learner keeps their place while comparing.
    Mode,
    /// A place to look from (`dusk`, a follow camera): choosing it sets
    /// the whole camera.
    Preset,
}

impl View {
    pub const fn mode(name: &'static str, about: &'static str) -> Self {
        Self { name, about, kind: ViewKind::Mode, snapshot: true, same_picture_as: None, antialiasing: None }
    }

    pub const fn preset(name: &'static str, about: &'static str) -> Self {
        Self { name, about, kind: ViewKind::Preset, snapshot: true, same_picture_as: None, antialiasing: None }
    }

    /// A mode that exists to be measured by `--bench` (a workload, such as
    /// a thousand lights looped over naively), not to be looked at: it is
    /// selectable like any view, but not a snapshot. What it computes must
    /// be checked some other way (chapter 08 compares its naive loop with
    /// the culled one in a test).
    pub const fn bench(name: &'static str, about: &'static str) -> Self {
        Self { name, about, kind: ViewKind::Mode, snapshot: false, same_picture_as: None, antialiasing: None }
    }

    /// Samples a pixel this view is drawn with where the runner asks for
    /// `asked`. A runner makes the chapter again when a newly chosen view
    /// needs another count: pipelines are built for one.
    pub const fn samples(&self, asked: Antialiasing) -> u32 {
        self.smoothing(asked).samples()
    }

    /// How this view smooths edges where the runner asks for `asked`: its
    /// own setting if it has one, else `asked`.
    pub const fn smoothing(&self, asked: Antialiasing) -> Antialiasing {
        match self.antialiasing {
            Some(own) => own,
            None => asked,
        }
    }
}

/// What every `no-aa` view shows.
const NO_AA_ABOUT: &str = "the first view drawn with one sample a pixel: its edges as they are without multisampling";

// ANCHOR: view_table
/// One row of a chapter's view table, the one place a view is named: the
/// [`View`], the chapter's settings that choosing it applies (`S`, all of
/// them, whatever the view before), and for a preset the camera it places
/// (`P`, the chapter's own enum of cameras). A mode has no camera, so it
/// never moves the learner's.
#[derive(Clone, Copy, Debug)]
pub struct ViewRow<S, P> {
    pub view: View,
    pub settings: S,
    pub camera: Option<P>,
}

impl<S, P> ViewRow<S, P> {
    /// The settings row `view` of `table` applies, as `Debug` writes them:
    /// what a chapter's [`Chapter::view_settings`] returns.
    pub fn settings_of<const N: usize>(table: &[Self; N], view: usize) -> String
    where
        S: std::fmt::Debug,
    {
        table.get(view).map_or_else(String::new, |row| format!("{:?}", row.settings))
    }

    /// A way of drawing: applies `settings`, leaves the camera alone.
    pub const fn mode(name: &'static str, about: &'static str, settings: S) -> Self {
        Self { view: View::mode(name, about), settings, camera: None }
    }

    /// A place to look from: applies `settings` and puts the camera at `camera`.
    pub const fn preset(name: &'static str, about: &'static str, settings: S, camera: P) -> Self {
        Self { view: View::preset(name, about), settings, camera: Some(camera) }
    }

    /// A workload for `--bench`, not a snapshot (see [`View::bench`]).
    pub const fn bench(name: &'static str, about: &'static str, settings: S) -> Self {
        Self { view: View::bench(name, about), settings, camera: None }
    }

    /// This view draws `view`'s picture by another method (see
    /// [`View::same_picture_as`]).
    pub const fn same_picture_as(mut self, view: &'static str) -> Self {
        self.view.same_picture_as = Some(view);
        self
    }

    /// The `no-aa` view: `twin`'s picture, whose settings are `settings`,
    /// drawn with one sample a pixel, to compare with multisampling.
    pub const fn no_aa(twin: &'static str, settings: S) -> Self {
        Self::mode("no-aa", NO_AA_ABOUT, settings).same_picture_as(twin).antialiasing(Antialiasing::Off)
    }

    /// [`ViewRow::no_aa`] for a `twin` that is a preset: from its `camera`.
    pub const fn no_aa_from(twin: &'static str, settings: S, camera: P) -> Self {
        Self::preset("no-aa", NO_AA_ABOUT, settings, camera).same_picture_as(twin).antialiasing(Antialiasing::Off)
    }

    /// This view smooths edges as `antialiasing` says, whatever the
    /// runner asks (see [`View::antialiasing`]).
    pub const fn antialiasing(mut self, antialiasing: Antialiasing) -> Self {
        self.view.antialiasing = Some(antialiasing);
        self
    }
}

/// The views of a table, in its order: a chapter's [`Chapter::VIEWS`] is
/// `&views_of(&TABLE)`.
pub const fn views_of<S, P, const N: usize>(table: &[ViewRow<S, P>; N]) -> [View; N] {
    let mut views = [View::mode("", ""); N];
    let mut i = 0;
    while i < N {
        views[i] = table[i].view;
        i += 1;
    }
    views
}
// ANCHOR_END: view_table

/// How far a picture may be from its reference and still pass, by NVIDIA's
/// FLIP metric (the snapshot tests compute it): a mean over the image, a
/// share of visibly wrong pixels, and a mean over the worst small patch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Largest allowed mean FLIP error over the image (0 = identical, 1 = opposite).
    pub mean: f32,
    /// Largest allowed fraction of pixels whose FLIP error exceeds
    /// [`Tolerance::OUTLIER_ERROR`]: catches a scattered error (a texture
    /// filtered wrongly, edges moved), which barely moves the mean.
    pub outliers: f32,
    /// Largest allowed mean FLIP error over any [`Tolerance::PATCH`] ×
    /// [`Tolerance::PATCH`] square of pixels: catches a small object gone
    /// missing or changed (the sun's disc, a shadow), whose pixels are too
    /// few for the share of outliers and all in one place.
    pub patch: f32,
}

impl Tolerance {
    /// FLIP error above which a pixel counts as visibly wrong.
    pub const OUTLIER_ERROR: f32 = 0.3;
    /// The side, in pixels, of the squares [`Tolerance::patch`] averages over.
    pub const PATCH: u32 = 16;
    /// Allows rasteriser and driver differences, not missing geometry.
    pub const DEFAULT: Self = Self { mean: 0.01, outliers: 0.001, patch: 0.2 };
}

/// Everything a chapter needs to record one frame.
pub struct Frame<'a> {
    /// Record passes here; the runner submits it.
    pub encoder: &'a mut wgpu::CommandEncoder,
    /// The picture to draw into (window or offscreen), sized like [`Target`].
    pub target: &'a wgpu::TextureView,
    /// Scene time in seconds. Chapters animate from this and never read a
    /// clock, so a snapshot at a given time is the same picture every run.
    pub time: f32,
    /// Index into [`Chapter::VIEWS`].
    pub view: usize,
    /// Hands out GPU timestamp slots for render passes (a no-op when the
    /// adapter has no timestamp queries or nobody is measuring).
    pub timer: &'a PassTimer,
    /// What each pass draws, counted as the chapter records its draws:
    /// `frame.drawn.add("scene", drawn)`, under the name the pass is timed
    /// by. The overlay shows it and `--bench` prints it. A chapter that
    /// counts nothing shows no counts.
    pub drawn: &'a DrawCounts,
    /// How this frame's edges are smoothed: the view's own setting, or the
    /// run's. Its samples were fixed when the chapter was made
    /// ([`Target::samples`]); the post-process pass is decided frame by
    /// frame, by chapters with [`Chapter::POST_ANTIALIASING`].
    pub antialiasing: Antialiasing,
}

impl Frame<'_> {
    /// Begins the pass that starts most 3D frames: clear the target to
    /// `clear` and `depth` to the far plane (1.0), time it as `label`.
    /// Chapter 02 writes this pass out in full; later chapters call this.
    pub fn scene_pass(
        &mut self,
        label: &'static str,
        clear: wgpu::Color,
        depth: &wgpu::TextureView,
    ) -> wgpu::RenderPass<'_> {
        scene_pass(self.encoder, self.timer, label, self.target, clear, depth)
    }

    /// [`Frame::scene_pass`] into `scene`'s samples, resolved into the
    /// frame's target when the pass ends (multisampling, chapter 02).
    pub fn multisampled_pass(
        &mut self,
        label: &'static str,
        clear: wgpu::Color,
        scene: &SceneTargets,
    ) -> wgpu::RenderPass<'_> {
        scene.pass(self.encoder, self.timer, label, self.target, Some(clear))
    }
}

/// A flag of one chapter's own, beside the ones every chapter has
/// (`--model PATH` in chapter 09): `--help` lists it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChapterFlag {
    /// Without the dashes: `"model"` for `--model`.
    pub name: &'static str,
    /// What the value is called in `--help`; empty for a switch that takes
    /// no value (`--walk`), whose value is then `"true"` when given.
    pub value_name: &'static str,
    pub help: &'static str,
}

impl ChapterFlag {
    /// A flag without a value (see [`ChapterFlag::value_name`]).
    pub const fn is_switch(&self) -> bool {
        self.value_name.is_empty()
    }
}

/// The values given for a chapter's own flags, by flag name.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FlagValues(pub Vec<(&'static str, String)>);

impl FlagValues {
    pub fn get(&self, name: &str) -> Option<&str> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, v)| v.as_str())
    }
}

/// One technique of the book, runnable in a window or headless.
pub trait Chapter: Sized + 'static {
    /// The package name, used for the window title, files and `--help`.
    const NAME: &'static str;
    /// The book's title for this chapter.
    const TITLE: &'static str;
    /// Every view the chapter can show; the first is the default.
    const VIEWS: &'static [View];
    /// Scene time at which snapshots and `--screenshot` are taken by default.
    const SNAPSHOT_TIME: f32 = 1.0;
    // ANCHOR: browser_tolerance
    /// How far the chapter's still picture in a browser (SwiftShader's
    /// WebGPU) may be from the same picture rendered natively (lavapipe):
    /// same shaders, two rasterisers, so edges and texture filtering differ
    /// by a level here and there. Measured per chapter by the browser test.
    const BROWSER_TOLERANCE: Tolerance = Tolerance::DEFAULT;
    // ANCHOR_END: browser_tolerance
    /// Whether [`Chapter::prepare`] cuts work into steps: the browser test
    /// then expects to see the page's progress between them.
    const PREPARES_IN_STEPS: bool = false;
    /// Frames `--bench` measures per view unless `--frames` says otherwise:
    /// fewer for chapters whose frames take a second on a software rasteriser.
    const BENCH_FRAMES: u32 = 100;
    /// A view the others are compared with: `--bench` then also prints each
    /// view's median frame as a multiple of this one's.
    const BENCH_BASELINE: Option<&'static str> = None;
    /// The WGSL file (under `shaders/`) the shader panel opens on, where
    /// `shaders/NAME/NAME.wgsl` or `shaders/NAME/scene.wgsl` is not it.
    const MAIN_SHADER: Option<&'static str> = None;
    /// True where the chapter finishes its frames with a post-process
    /// anti-aliasing pass when [`Frame::antialiasing`] asks for one
    /// (chapters 08 to 11, through chapter 08's post chain): `--antialiasing`
    /// and the overlay then offer `post` and `both`.
    const POST_ANTIALIASING: bool = false;
    /// Chapter-specific keys for the F1 help, as (key, what it does).
    const KEYS: &'static [(&'static str, &'static str)] = &[];
    /// Flags of this chapter's own; their values reach [`Chapter::apply_flags`].
    const FLAGS: &'static [ChapterFlag] = &[];

    /// Device features the chapter requires or can use.
    fn gpu_needs() -> GpuNeeds {
        GpuNeeds::default()
    }

    /// What [`Chapter::prepare`] makes for [`Chapter::new`]: chapter 03's
    /// terrain, for one. `()` for chapters with nothing to prepare.
    type Prepared: 'static;

    /// Long CPU work that [`Chapter::new`] needs done first, cut into
    /// steps. A browser page runs one step at a time and shows its progress
    /// between them, where one long call would freeze the page; the desktop
    /// runs them in one go. Chapters with nothing to prepare return
    /// `Preparation::ready(())`.
    fn prepare(gpu: &Gpu) -> Preparation<Self::Prepared>;

    /// Builds buffers, textures and pipelines for `target`, from what
    /// `prepare` made.
    fn new(gpu: &Gpu, target: Target, prepared: Self::Prepared) -> anyhow::Result<Self>;

    /// Takes the values of the chapter's own [`Chapter::FLAGS`], right after
    /// `new`. A value it cannot use is an [`UsageError`] that
    /// names the flag: the program exits with code 2.
    fn apply_flags(&mut self, _gpu: &Gpu, _flags: &FlagValues) -> anyhow::Result<()> {
        Ok(())
    }

    /// The target changed size (window resize); recreate size-dependent
    /// resources such as the depth buffer.
    fn resize(&mut self, _gpu: &Gpu, _target: Target) {}

    /// Applies what `view` decides, whatever the view before it was, except
    /// the camera: its row's settings in the chapter's view table. Only
    /// [`Chapter::select_view`] calls it.
    fn apply_view(&mut self, _view: usize) {}

    /// The settings view `view` applies, as the chapter's view table
    /// writes them (`ViewRow::settings_of(&VIEW_TABLE, view)`): part of
    /// the fingerprint of the view's frame ([`crate::fingerprint`]), so a
    /// bench row timed before the view's settings changed is known to be
    /// older than its frame.
    fn view_settings(view: usize) -> String;

    /// The learner (or `--view`, or a test) picked `view`: its settings,
    /// and for a preset, its camera. The one way to switch views; chapters
    /// implement [`Chapter::apply_view`] and [`Chapter::reset_camera`]
    /// instead of this.
    fn select_view(&mut self, view: usize) {
        self.apply_view(view);
        if Self::VIEWS[view].kind == ViewKind::Preset {
            self.reset_camera(view);
        }
    }

    /// Puts the camera where `view` starts: the preset's camera, or for a
    /// mode, the chapter's starting camera. The overlay's "reset camera"
    /// button calls this.
    fn reset_camera(&mut self, _view: usize) {}

    /// The camera the learner flies, for chapters that have one: the
    /// overlay shows where it is, `--camera` puts it somewhere, and tests
    /// move it.
    fn camera_mut(&mut self) -> Option<&mut Camera> {
        None
    }

    /// Called once by every runner (window, `--screenshot`, `--bench`, a
    /// page), after the view is chosen and `--camera` has placed the camera,
    /// before the first frame: whatever the chapter's flags change about
    /// where that frame starts happens here, since a headless picture never
    /// calls [`Chapter::update`]. `--walk` puts the eye on the ground under
    /// it, as the first walking frame would. `camera_placed` says whether
    /// `--camera` put the camera where it is: a camera that follows
    /// something (chapter 08's car) then stops following, as it does when
    /// the learner takes the controls.
    fn before_first_frame(&mut self, _camera_placed: bool) {}

    /// Interactive input, once per frame before `render`; `dt` is the real
    /// frame time in seconds. Never called when rendering headless.
    fn update(&mut self, _input: &Input, _dt: f32) {}

    /// Records the frame into `frame.encoder`.
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame);

    /// Adds the chapter's controls to the overlay panel. The state the
    /// controls start in is the state snapshots are taken in.
    fn ui(&mut self, _ui: &mut egui::Ui) {}

    /// One line of chapter-specific figures for `--bench` (chunks drawn,
    /// draw calls…), read after the measured frames; it may read results
    /// back from the GPU.
    fn stats(&mut self, _gpu: &Gpu) -> String {
        String::new()
    }
}

// ANCHOR: about
/// What a chapter has made by [`Chapter::prepare`], whatever its type.
pub type Prepared = Box<dyn std::any::Any>;

/// A chapter's constants and the two functions that make one, as values:
/// the runners (the window, the page, the headless picture, the bench)
/// take an `About` and a [`Runnable`], so that they are compiled once in
/// `common` for every chapter, not once more in every chapter's binary.
/// [`About::of`] reads them from a [`Chapter`].
#[derive(Clone, Copy)]
pub struct About {
    pub name: &'static str,
    pub title: &'static str,
    pub views: &'static [View],
    pub snapshot_time: f32,
    pub bench_frames: u32,
    pub bench_baseline: Option<&'static str>,
    pub main_shader: Option<&'static str>,
    pub post_antialiasing: bool,
    pub keys: &'static [(&'static str, &'static str)],
    pub flags: &'static [ChapterFlag],
    pub gpu_needs: fn() -> GpuNeeds,
    pub view_settings: fn(usize) -> String,
    /// [`Chapter::prepare`], its result boxed.
    pub prepare: fn(&Gpu) -> Preparation<Prepared>,
    /// [`Chapter::new`] from what `prepare` made.
    pub make: fn(&Gpu, Target, Prepared) -> anyhow::Result<Box<dyn Runnable>>,
}

impl About {
    pub fn of<C: Chapter>() -> Self {
        Self {
            name: C::NAME,
            title: C::TITLE,
            views: C::VIEWS,
            snapshot_time: C::SNAPSHOT_TIME,
            bench_frames: C::BENCH_FRAMES,
            bench_baseline: C::BENCH_BASELINE,
            main_shader: C::MAIN_SHADER,
            post_antialiasing: C::POST_ANTIALIASING,
            keys: C::KEYS,
            flags: C::FLAGS,
            gpu_needs: C::gpu_needs,
            view_settings: C::view_settings,
            prepare: |gpu| C::prepare(gpu).map(|prepared| Box::new(prepared) as Prepared),
            make: |gpu, target, prepared| {
                let prepared = prepared
                    .downcast::<C::Prepared>()
                    .map_err(|_| anyhow::anyhow!("{}: what was prepared is not what the chapter prepares", C::NAME))?;
                Ok(Box::new(C::new(gpu, target, *prepared)?))
            },
        }
    }

    /// Looks a view up by name.
    pub fn view_index(&self, name: &str) -> Option<usize> {
        self.views.iter().position(|v| v.name == name)
    }

    /// [`create`], whatever the chapter's type.
    pub fn create(&self, gpu: &Gpu, target: Target, flags: &FlagValues) -> anyhow::Result<Box<dyn Runnable>> {
        self.create_prepared(gpu, target, (self.prepare)(gpu).finish(gpu), flags)
    }

    /// [`create_prepared`], whatever the chapter's type.
    pub fn create_prepared(
        &self,
        gpu: &Gpu,
        target: Target,
        prepared: Prepared,
        flags: &FlagValues,
    ) -> anyhow::Result<Box<dyn Runnable>> {
        let mut chapter = (self.make)(gpu, target, prepared)?;
        chapter.apply_flags(gpu, flags)?;
        Ok(chapter)
    }
}

/// What the runners ask of a chapter instance, whatever its type: the
/// methods of [`Chapter`] that take `self`, and its [`About`]. Every
/// chapter is one.
pub trait Runnable {
    fn about(&self) -> About;
    fn apply_flags(&mut self, gpu: &Gpu, flags: &FlagValues) -> anyhow::Result<()>;
    fn resize(&mut self, gpu: &Gpu, target: Target);
    fn select_view(&mut self, view: usize);
    fn reset_camera(&mut self, view: usize);
    fn camera_mut(&mut self) -> Option<&mut Camera>;
    fn before_first_frame(&mut self, camera_placed: bool);
    fn update(&mut self, input: &Input, dt: f32);
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame);
    fn ui(&mut self, ui: &mut egui::Ui);
    fn stats(&mut self, gpu: &Gpu) -> String;
}

impl<C: Chapter> Runnable for C {
    fn about(&self) -> About {
        About::of::<C>()
    }
    fn apply_flags(&mut self, gpu: &Gpu, flags: &FlagValues) -> anyhow::Result<()> {
        Chapter::apply_flags(self, gpu, flags)
    }
    fn resize(&mut self, gpu: &Gpu, target: Target) {
        Chapter::resize(self, gpu, target);
    }
    fn select_view(&mut self, view: usize) {
        Chapter::select_view(self, view);
    }
    fn reset_camera(&mut self, view: usize) {
        Chapter::reset_camera(self, view);
    }
    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Chapter::camera_mut(self)
    }
    fn before_first_frame(&mut self, camera_placed: bool) {
        Chapter::before_first_frame(self, camera_placed);
    }
    fn update(&mut self, input: &Input, dt: f32) {
        Chapter::update(self, input, dt);
    }
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        Chapter::render(self, gpu, frame);
    }
    fn ui(&mut self, ui: &mut egui::Ui) {
        Chapter::ui(self, ui);
    }
    fn stats(&mut self, gpu: &Gpu) -> String {
        Chapter::stats(self, gpu)
    }
}
// ANCHOR_END: about

/// Creates chapter `C` for `target` and gives it its flags: how every
/// runner (window, screenshot, bench) makes one. Runs `C::prepare` in one
/// go first.
pub fn create<C: Chapter>(gpu: &Gpu, target: Target, flags: &FlagValues) -> anyhow::Result<C> {
    create_prepared(gpu, target, C::prepare(gpu).finish(gpu), flags)
}

/// [`create`], from what a preparation run step by step made (a browser page).
pub fn create_prepared<C: Chapter>(
    gpu: &Gpu,
    target: Target,
    prepared: C::Prepared,
    flags: &FlagValues,
) -> anyhow::Result<C> {
    let mut chapter = C::new(gpu, target, prepared)?;
    Chapter::apply_flags(&mut chapter, gpu, flags)?;
    Ok(chapter)
}

/// Puts a chapter where its first frame starts, the same way in every
/// runner: `view` (its settings, and a preset's camera), then `camera`
/// (`--camera`) over it, then [`Chapter::before_first_frame`]. A chapter
/// with no camera refuses `--camera`.
pub fn start(chapter: &mut dyn Runnable, view: usize, camera: Option<CameraPlace>) -> Result<(), UsageError> {
    chapter.select_view(view);
    if let Some(place) = camera {
        let name = chapter.about().name;
        let camera = chapter.camera_mut().ok_or_else(|| {
            UsageError(format!(
                "--camera {place}: the {name} chapter has no camera to place (it draws from a fixed or following viewpoint)"
            ))
        })?;
        place.put(camera);
    }
    chapter.before_first_frame(camera.is_some());
    Ok(())
}

/// Looks a view up by name.
pub fn view_index<C: Chapter>(name: &str) -> Option<usize> {
    C::VIEWS.iter().position(|v| v.name == name)
}
