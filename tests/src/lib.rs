//! The snapshot test: every view of every chapter (from `course`'s
//! records), rendered offscreen at a fixed size and time and compared with
//! `tests/snapshots/<chapter>/<view>.png`.
//!
//! `cargo test` checks them, and checks that views are pure (a live chapter
//! that has been through every other view draws each view exactly as a
//! fresh one does). Only `cargo xtask snapshot --bless` (which runs this
//! crate's binary with `--bless`) writes references, and it records each
//! in the bless log (`blessings`).

pub mod bench_tables;
pub mod blessings;
pub mod book;
pub mod snapshot;

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use common::fingerprint::Fingerprint;
use common::glam::Vec3;
use common::headless::OFFSCREEN_FORMAT;
use common::{Camera, Gpu, GpuNeeds, NoAdapter, PassCount, Target, View, ViewKind, anyhow, image, wgpu};
pub use course::{AnyChapter, Record, chapters, find};

use blessings::{Entry, Log};
use snapshot::{Comparison, Rule, Tolerance};

/// Snapshots are rendered at this size: large enough to judge, small enough
/// for a software rasteriser to render and compare quickly.
/// (A frame's fingerprint is taken at this size too, so that this run can
/// check the bench tables': `common::fingerprint::SIZE` is written once.)
pub const WIDTH: u32 = common::fingerprint::SIZE.0;
pub const HEIGHT: u32 = common::fingerprint::SIZE.1;

/// Snapshots are rendered into this target, multisampled as a learner's
/// window is by default.
pub fn target() -> Target {
    Target { format: OFFSCREEN_FORMAT, width: WIDTH, height: HEIGHT, samples: common::multisampling::SAMPLES }
}

/// [`target`], with the samples a pixel `view` is drawn with (a `no-aa`
/// view's one): a chapter is made for one number of samples, so a view
/// that asks for another is drawn by a chapter made for it, as every
/// runner does.
pub fn target_for(view: &View) -> Target {
    Target { samples: view.samples(common::Antialiasing::default()), ..target() }
}

/// The README and the book's `SUMMARY.md` as the chapter records say they
/// should read, as (path, text): the README's chapter table between its
/// markers, and everything in the summary after its first pages (the
/// parts, each with its opening page and its chapters, and the appendices).
pub fn course_docs() -> anyhow::Result<Vec<(PathBuf, String)>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let chapters = chapters();
    let readme_path = root.join("README.md");
    let readme = std::fs::read_to_string(&readme_path)?;
    let (start, end) =
        ("<!-- chapters: written from course::chapters() by `cargo xtask book` -->\n", "<!-- end of chapters -->");
    let (Some(a), Some(b)) = (readme.find(start), readme.find(end)) else {
        anyhow::bail!("README.md has lost its chapter table's markers: {start:?} and {end:?}");
    };
    let readme = format!("{}{start}{}{}", &readme[..a], course::readme_table(&chapters), &readme[b..]);
    let summary_path = root.join("book/src/SUMMARY.md");
    let summary = std::fs::read_to_string(&summary_path)?;
    // The first pages (title, introduction) run up to the first part heading.
    let head_end = summary.match_indices("\n# ").next().map_or(summary.len(), |(i, _)| i + 1);
    let head = summary[..head_end].trim_end();
    let src = root.join("book/src");
    let summary = format!("{head}\n{}", course::summary_chapters(&chapters, |c| book::sub_pages(&src, c)));
    Ok(vec![(readme_path, readme), (summary_path, summary)])
}

/// `tests/snapshots`, where the references live.
pub fn snapshot_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("snapshots")
}

pub fn reference_path(chapter: &str, view: &str) -> PathBuf {
    snapshot_dir().join(chapter).join(format!("{view}.png"))
}

/// Devices not lent out at the moment, with what was cached on them, by
/// the needs and backends they were made for.
static IDLE_DEVICES: Mutex<Vec<(Key, Arc<Gpu>)>> = Mutex::new(Vec::new());

/// What a device was made for: the chapter's needs, on which backends.
type Key = (GpuNeeds, wgpu::Backends);

/// A device lent to one thread until the lease is dropped, then kept for
/// the next chapter with the same needs, which finds the terrain and rocks
/// already made on it (`Gpu::cached`). A thread never shares its device: a
/// software rasteriser runs one device's submissions one after another, so
/// two threads on one device would wait for each other.
pub struct Lease {
    key: Key,
    gpu: Option<Arc<Gpu>>,
}

impl std::ops::Deref for Lease {
    type Target = Gpu;
    fn deref(&self) -> &Gpu {
        self.gpu.as_ref().expect("a lease holds its device until dropped")
    }
}

impl Drop for Lease {
    fn drop(&mut self) {
        if let Some(gpu) = self.gpu.take() {
            IDLE_DEVICES.lock().unwrap_or_else(|e| e.into_inner()).push((self.key.clone(), gpu));
        }
    }
}

/// Lends a device with `needs`: an idle one if there is one, else a new one.
pub fn lease(needs: GpuNeeds) -> anyhow::Result<Lease> {
    lease_on(needs, wgpu::Backends::empty())
}

/// [`lease`] on `backends` (empty: as `Gpu::headless` chooses).
pub fn lease_on(needs: GpuNeeds, backends: wgpu::Backends) -> anyhow::Result<Lease> {
    let key = (needs.clone(), backends);
    let idle = {
        let mut devices = IDLE_DEVICES.lock().unwrap_or_else(|e| e.into_inner());
        devices.iter().position(|(k, _)| *k == key).map(|i| devices.swap_remove(i).1)
    };
    let gpu = match idle {
        Some(gpu) => gpu,
        None if backends.is_empty() => Arc::new(Gpu::headless(needs)?),
        None => Arc::new(Gpu::headless_on(backends, needs)?),
    };
    Ok(Lease { key, gpu: Some(gpu) })
}

/// The outcome for one view.
pub struct ViewResult {
    pub view: &'static str,
    /// How it was compared, and the figures.
    pub outcome: Result<(Rule, Comparison), String>,
}

/// What blessing did to one view.
#[derive(Clone, Debug, PartialEq)]
pub enum Blessing {
    /// The picture is its reference's (within [`snapshot::SAME_COLOUR`]),
    /// and the log knows the reference: nothing written.
    Unchanged,
    /// The picture is its reference's, which the log did not know (or knew
    /// only as made on an unknown adapter): the entry records it as made on
    /// this adapter, the file is untouched.
    Recorded(Entry),
    /// A new or changed picture written, and its entry; the picture it
    /// replaced is kept beside it as `<view>-old.png` to look at.
    Written { entry: Entry, old_copy: Option<PathBuf> },
}

/// What the snapshot test does with a chapter's record.
pub trait Snapshots {
    /// A device with the chapter's needs.
    fn gpu(&self) -> anyhow::Result<Lease>;
    /// Renders each of `views` (every view when empty) and compares it
    /// with its reference; with every view, also checks the bench table and
    /// that the views can be told apart. Returns each view's outcome and
    /// the other problems.
    fn check(&self, views: &[String]) -> anyhow::Result<(Vec<ViewResult>, Vec<String>)>;
    /// Writes the reference of each of `views` (every snapshot view when
    /// empty) that is missing or that the picture no longer matches
    /// (rounding aside), and makes its entry for the bless log with
    /// `reason`; returns what it did, view by view. The caller appends the
    /// entries to the log.
    fn bless(&self, views: &[String], reason: &str, log: &Log) -> anyhow::Result<Vec<(&'static str, Blessing)>>;
    /// [`Snapshots::check`], and that views are pure; returns every problem.
    fn check_purity(&self) -> anyhow::Result<Vec<String>>;
}

impl Snapshots for Record {
    fn gpu(&self) -> anyhow::Result<Lease> {
        lease((self.needs)())
    }

    // ANCHOR: check
    /// Renders every view with one instance of the chapter, in book order
    /// (views are pure, and `check_purity` proves it), compares each with its
    /// reference, checks the chapter's bench table against the passes
    /// each view drew, and that the references can be told apart.
    fn check(&self, views: &[String]) -> anyhow::Result<(Vec<ViewResult>, Vec<String>)> {
        let gpu = self.gpu()?;
        let rules = Rules::new(&gpu)?;
        let mut chapter = (self.open)(&gpu, target())?;
        let mut samples = target().samples;
        let mut results = Vec::new();
        let mut passes = Vec::new();
        let mut frames = bench_view_frames(self);
        let mut problems = Vec::new();
        let chosen = |name: &str| views.is_empty() || views.iter().any(|v| v == name);
        for (i, view) in self.views.iter().enumerate().filter(|(_, v)| v.snapshot && chosen(v.name)) {
            if target_for(view).samples != samples {
                samples = target_for(view).samples;
                chapter = (self.open)(&gpu, target_for(view))?;
            }
            chapter.show(i);
            chapter.reset_camera(i);
            let outcome = chapter.render_counted(&gpu, i, self.snapshot_time).map_err(|e| format!("{e:#}")).and_then(
                |(image, drawn, counted)| {
                    problems.extend(counted_but_not_drawn(self, view, &drawn, &counted));
                    passes.push((view.name, drawn));
                    frames.push((view.name, fingerprint(self, i, &counted)));
                    compare(self, i, &image, &rules)
                },
            );
            results.push(ViewResult { view: view.name, outcome });
        }
        if !views.is_empty() {
            return Ok((results, problems));
        }
        problems.extend(bench_tables::check(self.name, self.views, &passes, &frames));
        problems.extend(views_told_apart(self));
        Ok((results, problems))
    }
    // ANCHOR_END: check

    /// Renders each view with a fresh instance, as `--screenshot` does, and
    /// writes it as the new reference where it is missing or changed.
    fn bless(&self, views: &[String], reason: &str, log: &Log) -> anyhow::Result<Vec<(&'static str, Blessing)>> {
        let gpu = self.gpu()?;
        let adapter = blessings::adapter(&gpu);
        let mut done = Vec::new();
        let chosen = |name: &str| views.is_empty() || views.iter().any(|v| v == name);
        for (i, view) in self.views.iter().enumerate().filter(|(_, v)| v.snapshot && chosen(v.name)) {
            let path = reference_path(self.name, view.name);
            std::fs::create_dir_all(path.parent().expect("reference paths have a folder"))?;
            let mut chapter = (self.open)(&gpu, target_for(view))?;
            chapter.show(i);
            let picture = chapter.render(&gpu, i, self.snapshot_time)?.0;
            for stale in ["actual", "diff"] {
                let _ = std::fs::remove_file(snapshot::sibling(&path, stale));
            }
            let old_bytes = std::fs::read(&path).ok();
            let old = old_bytes.as_deref().and_then(|b| image::load_from_memory(b).ok()).map(|o| o.to_rgba8());
            let old_hash = old_bytes.as_deref().map(blessings::hash);
            let same_size = old.as_ref().filter(|o| o.dimensions() == picture.dimensions());
            let entry = |new: String, comparison: Option<Comparison>| Entry {
                view: format!("{}/{}", self.name, view.name),
                old: old_hash.clone(),
                new,
                mean: comparison.map(|c| c.mean),
                patch: comparison.map(|c| c.patch),
                adapter: adapter.clone(),
                reason: reason.to_string(),
            };
            // A reference the picture matches but for rounding (another
            // machine's) is kept: blessing rewrites only what changed.
            if let (Some(old), Some(old_hash)) = (same_size, &old_hash)
                && snapshot::beyond_rounding(old, &picture).0 == 0
            {
                let view_name = format!("{}/{}", self.name, view.name);
                let known =
                    log.blessing_of(&view_name, old_hash).is_some_and(|e| e.adapter != blessings::UNKNOWN_ADAPTER);
                let outcome = if known {
                    Blessing::Unchanged
                } else {
                    Blessing::Recorded(entry(old_hash.clone(), Some(Comparison::SAME)))
                };
                done.push((view.name, outcome));
                continue;
            }
            let comparison = same_size.map(|old| snapshot::compare(old, &picture).0);
            let old_copy = match &old_bytes {
                Some(bytes) => {
                    let copy = snapshot::sibling(&path, "old");
                    std::fs::write(&copy, bytes)?;
                    Some(copy)
                }
                None => None,
            };
            let mut encoded = std::io::Cursor::new(Vec::new());
            picture.write_to(&mut encoded, image::ImageFormat::Png)?;
            let bytes = encoded.into_inner();
            std::fs::write(&path, &bytes)?;
            done.push((view.name, Blessing::Written { entry: entry(blessings::hash(&bytes), comparison), old_copy }));
        }
        Ok(done)
    }

    // ANCHOR: purity
    /// What a view shows must not depend on the views chosen before it.
    /// One live instance flies somewhere and passes through every view;
    /// then, for each view, it selects it and resets the camera as the
    /// overlay's button does, and must draw the same bytes as a fresh
    /// instance showing that view. The reference is a fresh instance's
    /// picture (`bless` makes one per view), so where the live picture has
    /// the reference's colours (rounding aside: `snapshot::SAME_COLOUR`, so
    /// another machine's rasteriser passes too) that is shown without
    /// drawing again; only where it differs more is a fresh instance drawn
    /// to tell the two apart. Modes must leave the camera
    /// alone, and presets must set all of it. Each picture is compared with
    /// the reference, and the bench table with the passes drawn. Returns
    /// every problem found.
    fn check_purity(&self) -> anyhow::Result<Vec<String>> {
        let gpu = self.gpu()?;
        let rules = Rules::new(&gpu)?;
        let mut live = (self.open)(&gpu, target())?;
        let mut problems = Vec::new();
        let mut passes = Vec::new();
        let mut frames = bench_view_frames(self);
        if let Some(start) = live.camera() {
            live.set_camera(elsewhere(&start));
        }
        for view in (0..self.views.len()).rev() {
            live.show(view);
        }
        for (i, view) in self.views.iter().enumerate() {
            problems.extend(camera_rules(self, live.as_mut(), i));
            if !view.snapshot {
                continue;
            }
            // A view drawn with other samples a pixel gets a chapter made
            // for it in every runner: nothing before it can leak into it.
            if target_for(view).samples != target().samples {
                let mut own = (self.open)(&gpu, target_for(view))?;
                own.show(i);
                let (picture, drawn, counted) = own.render_counted(&gpu, i, self.snapshot_time)?;
                passes.push((view.name, drawn));
                frames.push((view.name, fingerprint(self, i, &counted)));
                if let Err(e) = compare(self, i, &picture, &rules) {
                    problems.push(format!("{}/{}: {e}", self.name, view.name));
                }
                continue;
            }
            live.show(i);
            live.reset_camera(i);
            let (after_the_others, drawn, counted) = live.render_counted(&gpu, i, self.snapshot_time)?;
            passes.push((view.name, drawn));
            frames.push((view.name, fingerprint(self, i, &counted)));
            let reference = image::open(reference_path(self.name, view.name)).ok().map(|r| r.to_rgba8());
            let matches_reference = reference.as_ref().is_some_and(|r| {
                r.dimensions() == after_the_others.dimensions() && snapshot::compare(r, &after_the_others).0.mean == 0.0
            });
            let picture = if matches_reference {
                after_the_others
            } else {
                let mut fresh = (self.open)(&gpu, target())?;
                fresh.show(i);
                let (fresh_picture, _) = fresh.render(&gpu, i, self.snapshot_time)?;
                if after_the_others != fresh_picture {
                    let path = std::env::temp_dir().join(format!("{}-{}-after-other-views.png", self.name, view.name));
                    after_the_others.save(&path)?;
                    problems.push(format!(
                        "{}/{}: after the other views and a camera reset, the picture differs from a fresh \
                         instance's (a view that depends on history, or a render that is not deterministic); it is {}",
                        self.name,
                        view.name,
                        path.display()
                    ));
                }
                fresh_picture
            };
            if let Err(e) = compare(self, i, &picture, &rules) {
                problems.push(format!("{}/{}: {e}", self.name, view.name));
            }
        }
        problems.extend(bench_tables::check(self.name, self.views, &passes, &frames));
        problems.extend(views_told_apart(self));
        Ok(problems)
    }
    // ANCHOR_END: purity
}

/// The fingerprint of `record`'s view `view`, from the frame the snapshot
/// run drew of it (`counted`, its passes' counts), as the bench takes it
/// (`common::headless::fingerprint`).
fn fingerprint(record: &Record, view: usize, counted: &[PassCount]) -> Fingerprint {
    Fingerprint::new((record.view_settings)(view), target_for(&record.views[view]).samples, counted)
}

/// The fingerprints of `record`'s bench views, which the snapshot run does
/// not draw: their settings and samples.
fn bench_view_frames(record: &Record) -> Vec<(&'static str, Fingerprint)> {
    record
        .views
        .iter()
        .enumerate()
        .filter(|(_, view)| !view.snapshot)
        .map(|(i, view)| (view.name, fingerprint(record, i, &[])))
        .collect()
}

/// The passes a frame counted triangles for must be passes it drew, by
/// the names they are timed by: the overlay's and the bench's lines per
/// pass then sit beside the pass's time. A problem per pass that is not.
fn counted_but_not_drawn(record: &Record, view: &View, drawn: &[&str], counted: &[PassCount]) -> Vec<String> {
    counted
        .iter()
        .filter(|count| !drawn.contains(&count.pass))
        .map(|count| {
            format!(
                "{}/{}: counts triangles for a `{}` pass, but the passes it began are {drawn:?}: count under \
                 the name the pass is timed by",
                record.name, view.name, count.pass
            )
        })
        .collect()
}

/// Every view exists to show something the others do not, so the snapshot
/// test must be able to tell each from every other: were a view to draw
/// another's picture (a switch that does nothing, a mode that fell back to
/// the default), it must fail. A view that draws another's picture by
/// another method (`View::same_picture_as`) must instead look alike.
/// Checked on the references, pair by pair; returns the problems.
fn views_told_apart(record: &Record) -> Vec<String> {
    let pictures: Vec<(&common::View, image::RgbaImage)> = record
        .views
        .iter()
        .filter(|v| v.snapshot)
        // A missing reference fails the view's own check.
        .filter_map(|v| Some((v, image::open(reference_path(record.name, v.name)).ok()?.to_rgba8())))
        .collect();
    let mut problems = Vec::new();
    for view in record.views.iter().filter(|v| v.same_picture_as.is_some()) {
        let twin = view.same_picture_as.unwrap_or_default();
        if !record.views.iter().any(|v| v.name == twin && v.snapshot) {
            problems.push(format!(
                "{}/{}: draws the picture of `{twin}`, which is no snapshot view",
                record.name, view.name
            ));
        }
    }
    // Twins of twins are twins: `multi-draw` draws `cpu-culling`'s picture,
    // which draws `default`'s (chapter 05), so all three must look alike.
    let original = |view: &common::View| {
        let mut name = view.name;
        for _ in 0..record.views.len() {
            match record.views.iter().find(|v| v.name == name).and_then(|v| v.same_picture_as) {
                Some(twin) => name = twin,
                None => break,
            }
        }
        name
    };
    for (i, (a, first)) in pictures.iter().enumerate() {
        for (b, second) in &pictures[i + 1..] {
            let twins = original(a) == original(b);
            // Twins drawn with different samples a pixel differ along every edge.
            let tolerance =
                if twins && a.antialiasing != b.antialiasing { ANTIALIASED_TWIN } else { Tolerance::DEFAULT };
            let apart = first.dimensions() != second.dimensions() || snapshot::tells_apart(first, second, tolerance);
            if twins && apart {
                problems.push(format!(
                    "{}: `{}` should draw `{}`'s picture by another method, but the snapshot test tells them apart",
                    record.name, a.name, b.name
                ));
            } else if !twins && !apart {
                problems.push(format!(
                    "{}: the views `{}` and `{}` look alike to the snapshot test (within its tolerance), so \
                     neither is checked against the other: make each show what it is for",
                    record.name, a.name, b.name
                ));
            }
        }
    }
    problems
}

/// How far a `no-aa` view, one sample a pixel, may be from the multisampled
/// view it draws again (or an `fxaa` view, one sample and the post pass):
/// the same picture, with every edge stepped, or blended by FXAA, instead
/// of multisampled. The mean grows with how much of the picture is edge.
/// Measured on lavapipe (2026-11-28): chapters 01 to 07 came within FLIP
/// mean 0.0102 (chapter 06's sky-lit plain, with a million rocks' edges)
/// and a worst patch of 0.159 (chapter 01's triangle, all edge); the city
/// of chapter 08, a picture of thin towers, windows and trees, 0.0243 for
/// `no-aa` and 0.0240 for `fxaa` (0.39 % outliers, worst patch 0.194);
/// chapter 09's, 0.0179.
pub const ANTIALIASED_TWIN: Tolerance = Tolerance { mean: 0.035, outliers: 0.01, patch: 0.3 };

// ANCHOR: gl
/// How far a chapter's first view drawn by OpenGL may be from its
/// reference, drawn by Vulkan: llvmpipe's GL and lavapipe share Mesa's
/// rasteriser but not the path from WGSL to it (GLSL, not SPIR-V), and
/// round some shading apart. Measured on this machine's llvmpipe GL 4.5,
/// the eleven first views came within FLIP mean 0.0043, 0.007 % of pixels
/// above 0.3 and a worst patch of 0.124 (chapter 07's lake) of their
/// references: the default tolerance holds, with room.
pub const GL_TOLERANCE: Tolerance = Tolerance::DEFAULT;

/// What OpenGL made of a chapter: its first view's picture within
/// [`GL_TOLERANCE`] of the reference, or the one line a chapter that needs
/// more than the adapter has stops with.
pub enum OnGl {
    Drawn(Comparison),
    Refused(String),
}

/// Opens `record`'s chapter on OpenGL (`WGPU_BACKEND=gl`: llvmpipe's GL 4.5
/// with Debian's `libegl1 libegl-mesa0 libgles2 libgl1-mesa-dri`) and
/// draws its first view, or takes its refusal. A panic (a shader the GL
/// backend cannot translate, a feature it lacks) fails the caller's test.
pub fn draw_on_gl(record: &Record) -> anyhow::Result<OnGl> {
    draw_first_view((record.needs)(), wgpu::Backends::GL, record, "OpenGL", GL_TOLERANCE)
}

/// Draws `record`'s first view on a device given none of the optional
/// features the chapter could use (clip distances, a first instance in
/// indirect draws, timestamps, an RG11B10 target, …), so that every
/// fallback draws here, where lavapipe has them all; the picture must be
/// the reference's within [`Tolerance::DEFAULT`].
pub fn draw_without_optional_features(record: &Record) -> anyhow::Result<OnGl> {
    let needs = GpuNeeds { optional: wgpu::Features::empty(), ..(record.needs)() };
    draw_first_view(needs, wgpu::Backends::empty(), record, "a device with no optional features", Tolerance::DEFAULT)
}

/// Opens `record`'s chapter with `needs` on `backends` (empty: as
/// `Gpu::headless` chooses), draws its first view and compares it with
/// the reference, or takes the chapter's one-line refusal.
fn draw_first_view(
    needs: GpuNeeds,
    backends: wgpu::Backends,
    record: &Record,
    on: &str,
    tolerance: Tolerance,
) -> anyhow::Result<OnGl> {
    let gpu = match lease_on(needs, backends) {
        Ok(gpu) => gpu,
        Err(error) => {
            let Some(refusal) = error.downcast_ref::<NoAdapter>() else { return Err(error) };
            // What the chapter's binary prints before it exits with 2.
            let line = format!("error: {refusal}");
            anyhow::ensure!(
                refusal.lacking,
                "no adapter for {on} ({line}): for OpenGL, install Debian's libegl1 libegl-mesa0 libgles2 \
                 libgl1-mesa-dri (`cargo xtask test` does)"
            );
            anyhow::ensure!(line.lines().count() == 1, "a refusal of more than one line: {line}");
            return Ok(OnGl::Refused(line));
        }
    };
    if backends == wgpu::Backends::GL {
        let info = gpu.adapter.get_info();
        anyhow::ensure!(info.backend == wgpu::Backend::Gl, "asked for OpenGL, got {:?}", info.backend);
    }
    let mut chapter = (record.open)(&gpu, target())?;
    let view = record.views.iter().position(|v| v.snapshot).expect("a chapter has a snapshot view");
    chapter.show(view);
    let (picture, _) = chapter.render(&gpu, view, record.snapshot_time)?;
    let reference = reference_path(record.name, record.views[view].name);
    let label = if backends == wgpu::Backends::GL { "gl" } else { "no-features" };
    let shown = std::env::temp_dir().join(format!("{}-{}-{label}", record.name, record.views[view].name));
    let _ = std::fs::create_dir_all(&shown);
    // The reference's copy beside the picture, so a failure's -actual and
    // -diff land in a scratch folder and not beside the reference.
    let copy = shown.join(format!("{}.png", record.views[view].name));
    std::fs::copy(&reference, &copy)?;
    let comparison = snapshot::check(&picture, &copy, Rule::Perceptual(tolerance))
        .map_err(|e| anyhow::anyhow!("{}/{} on {on}: {e}", record.name, record.views[view].name))?;
    Ok(OnGl::Drawn(comparison))
}
// ANCHOR_END: gl

/// Which [`Rule`] holds for a reference: the bless log, and the adapter
/// the pictures are drawn on now.
pub struct Rules {
    log: Log,
    adapter: String,
}

impl Rules {
    pub fn new(gpu: &Gpu) -> anyhow::Result<Self> {
        Ok(Self::from_parts(Log::read()?, blessings::adapter(gpu)))
    }

    /// The rules a `log` gives on `adapter` (as [`blessings::adapter`]
    /// writes it).
    pub fn from_parts(log: Log, adapter: String) -> Self {
        Self { log, adapter }
    }

    /// Exact when the log says `reference` was made on this adapter, by
    /// FLIP with `tolerance` otherwise.
    pub fn for_reference(&self, view: &str, reference: &Path, tolerance: Tolerance) -> Rule {
        match self.log.adapter_of(view, reference) {
            Some(adapter) if adapter == self.adapter => Rule::Exact,
            _ => Rule::Perceptual(tolerance),
        }
    }
}

/// Compares a view's picture with its reference, by the rule that holds
/// for it.
fn compare(
    record: &Record,
    view: usize,
    image: &image::RgbaImage,
    rules: &Rules,
) -> Result<(Rule, Comparison), String> {
    let reference = reference_path(record.name, record.views[view].name);
    let rule =
        rules.for_reference(&format!("{}/{}", record.name, record.views[view].name), &reference, Tolerance::DEFAULT);
    snapshot::check(image, &reference, rule).map(|c| (rule, c)).map_err(|e| e.to_string())
}

/// A mode never moves the camera; a preset puts it in the same place
/// wherever it was.
fn camera_rules(record: &Record, live: &mut dyn AnyChapter, view: usize) -> Option<String> {
    let start = live.camera()?;
    let (name, kind) = (record.views[view].name, record.views[view].kind);
    let moved = elsewhere(&start);
    live.set_camera(moved);
    live.show(view);
    let after = live.camera()?;
    match kind {
        ViewKind::Mode if after != moved => {
            Some(format!("{}/{name} is a mode but moved the camera from {moved:?} to {after:?}", record.name))
        }
        ViewKind::Preset => {
            live.set_camera(elsewhere(&moved));
            live.show(view);
            let again = live.camera()?;
            (again != after).then(|| {
                format!(
                    "{}/{name} is a preset but left part of the camera as it was: {after:?} vs {again:?}",
                    record.name
                )
            })
        }
        ViewKind::Mode => None,
    }
}

/// A camera somewhere else, looking another way, with other optics: what a
/// learner might have flown to.
fn elsewhere(camera: &Camera) -> Camera {
    Camera {
        position: camera.position + Vec3::new(7.0, 3.0, -5.0),
        yaw: camera.yaw + 1.0,
        pitch: (camera.pitch - 0.2).clamp(-1.5, 1.5),
        fov_y: camera.fov_y * 0.8,
        near: camera.near * 2.0,
        far: camera.far * 0.7,
        aspect: camera.aspect,
    }
}
