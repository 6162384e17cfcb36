//! The snapshot registry: every chapter, every view, rendered offscreen at a
//! fixed size and time and compared with `tests/snapshots/<chapter>/<view>.png`.
//!
//! `cargo test` checks them, and checks that views are pure (a live chapter
//! that has been through every other view draws each view exactly as a
//! fresh one does). Only `cargo xtask snapshot --bless` (which runs this
//! crate's binary with `--bless`) writes references.

pub mod bench_tables;
pub mod diagrams;
pub mod snapshot;

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, Offscreen, draw_frame, read_texture};
use common::{Camera, Chapter, Gpu, GpuNeeds, PassTimer, Target, View, ViewKind, anyhow, image, show_view};

use snapshot::{Comparison, Tolerance};

/// Snapshots are rendered at this size: large enough to judge, small enough
/// for a software rasteriser to render and compare quickly.
pub const WIDTH: u32 = 800;
pub const HEIGHT: u32 = 450;

/// Every chapter, in book order. A new chapter adds one line here (and one
/// dependency in Cargo.toml); a test fails if a chapter crate is missing.
pub fn chapters() -> Vec<Entry> {
    vec![
        entry::<triangle::Triangle>(),
        entry::<camera::CameraChapter>(),
        entry::<terrain::TerrainChapter>(),
        entry::<fog::FogChapter>(),
        entry::<instancing::InstancingChapter>(),
        entry::<skybox::SkyboxChapter>(),
        entry::<water::WaterChapter>(),
        entry::<lighting::LightingChapter>(),
        entry::<textures::TexturesChapter>(),
        entry::<shadows::ShadowsChapter>(),
        entry::<voronoi_water::VoronoiWaterChapter>(),
    ]
}

/// One chapter as the snapshot tests see it.
pub struct Entry {
    pub name: &'static str,
    pub views: &'static [View],
    pub time: f32,
    needs: GpuNeeds,
    /// How far each view may drift from its reference (see [`Tolerance`]).
    pub tolerance: fn(usize) -> Tolerance,
    open: fn(&Gpu) -> anyhow::Result<Box<dyn Live>>,
}

fn entry<C: Chapter>() -> Entry {
    Entry {
        name: C::NAME,
        views: C::VIEWS,
        time: C::SNAPSHOT_TIME,
        needs: C::gpu_needs(),
        tolerance: |_| Tolerance::DEFAULT,
        open: |gpu| Ok(Box::new(LiveChapter { chapter: C::new(gpu, target())?, views: C::VIEWS })),
    }
}

fn target() -> Target {
    Target { format: OFFSCREEN_FORMAT, width: WIDTH, height: HEIGHT }
}

pub fn find(name: &str) -> Option<Entry> {
    chapters().into_iter().find(|e| e.name == name)
}

/// `tests/snapshots`, where the references live.
pub fn snapshot_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("snapshots")
}

pub fn reference_path(chapter: &str, view: &str) -> PathBuf {
    snapshot_dir().join(chapter).join(format!("{view}.png"))
}

/// Devices not lent out at the moment, with what was cached on them.
static IDLE_DEVICES: Mutex<Vec<(GpuNeeds, Arc<Gpu>)>> = Mutex::new(Vec::new());

/// A device lent to one thread until the lease is dropped, then kept for
/// the next chapter with the same needs, which finds the terrain and rocks
/// already made on it (`Gpu::cached`). A thread never shares its device: a
/// software rasteriser runs one device's submissions one after another, so
/// two threads on one device would wait for each other.
pub struct Lease {
    needs: GpuNeeds,
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
            IDLE_DEVICES.lock().unwrap_or_else(|e| e.into_inner()).push((self.needs, gpu));
        }
    }
}

/// Lends a device with `needs`: an idle one if there is one, else a new one.
pub fn lease(needs: GpuNeeds) -> anyhow::Result<Lease> {
    let idle = {
        let mut devices = IDLE_DEVICES.lock().unwrap_or_else(|e| e.into_inner());
        devices.iter().position(|(n, _)| *n == needs).map(|i| devices.swap_remove(i).1)
    };
    let gpu = match idle {
        Some(gpu) => gpu,
        None => Arc::new(Gpu::headless(needs)?),
    };
    Ok(Lease { needs, gpu: Some(gpu) })
}

/// A chapter instance, whatever its type.
trait Live {
    /// As the overlay does: the view's settings, and a preset's camera.
    fn show(&mut self, view: usize);
    fn reset_camera(&mut self, view: usize);
    fn camera(&mut self) -> Option<Camera>;
    fn set_camera(&mut self, camera: Camera);
    /// Renders `view` at `time`; returns the picture and the passes it drew.
    fn render(&mut self, gpu: &Gpu, view: usize, time: f32) -> anyhow::Result<(image::RgbaImage, Vec<&'static str>)>;
}

struct LiveChapter<C: Chapter> {
    chapter: C,
    views: &'static [View],
}

impl<C: Chapter> Live for LiveChapter<C> {
    fn show(&mut self, view: usize) {
        show_view(&mut self.chapter, view);
    }

    fn reset_camera(&mut self, view: usize) {
        self.chapter.reset_camera(view);
    }

    fn camera(&mut self) -> Option<Camera> {
        self.chapter.camera_mut().copied()
    }

    fn set_camera(&mut self, camera: Camera) {
        if let Some(c) = self.chapter.camera_mut() {
            *c = camera;
        }
    }

    fn render(&mut self, gpu: &Gpu, view: usize, time: f32) -> anyhow::Result<(image::RgbaImage, Vec<&'static str>)> {
        debug_assert!(view < self.views.len());
        let offscreen = Offscreen::new(&gpu.device, target());
        let timer = PassTimer::off();
        draw_frame(gpu, &mut self.chapter, &offscreen.view, time, view, &timer);
        let mut passes = timer.take_labels();
        passes.extend(timer.take_cpu().into_iter().map(|(label, _)| label));
        Ok((read_texture(gpu, &offscreen.texture)?, passes))
    }
}

/// The outcome for one view.
pub struct ViewResult {
    pub view: &'static str,
    pub outcome: Result<Comparison, String>,
}

impl Entry {
    pub fn gpu(&self) -> anyhow::Result<Lease> {
        lease(self.needs)
    }

    // ANCHOR: check
    /// Renders every view with one instance of the chapter, in book order
    /// (views are pure, and `check_purity` proves it), compares each with its
    /// reference, and checks the chapter's bench table against the passes
    /// each view drew.
    pub fn check(&self) -> anyhow::Result<(Vec<ViewResult>, Vec<String>)> {
        let gpu = self.gpu()?;
        let mut chapter = (self.open)(&gpu)?;
        let mut results = Vec::new();
        let mut passes = Vec::new();
        for (i, view) in self.views.iter().enumerate().filter(|(_, v)| v.snapshot) {
            chapter.show(i);
            chapter.reset_camera(i);
            let outcome =
                chapter.render(&gpu, i, self.time).map_err(|e| format!("{e:#}")).and_then(|(image, drawn)| {
                    passes.push((view.name, drawn));
                    self.compare(i, &image)
                });
            results.push(ViewResult { view: view.name, outcome });
        }
        let table_problems = bench_tables::check(self.name, self.views, &passes);
        Ok((results, table_problems))
    }
    // ANCHOR_END: check

    fn compare(&self, view: usize, image: &image::RgbaImage) -> Result<Comparison, String> {
        let reference = reference_path(self.name, self.views[view].name);
        snapshot::check(image, &reference, (self.tolerance)(view)).map_err(|e| e.to_string())
    }

    /// Renders every view with a fresh instance, as `--screenshot` does, and
    /// writes it as the new reference. Returns the paths.
    pub fn bless(&self) -> anyhow::Result<Vec<PathBuf>> {
        let gpu = self.gpu()?;
        let mut written = Vec::new();
        for (i, view) in self.views.iter().enumerate().filter(|(_, v)| v.snapshot) {
            let path = reference_path(self.name, view.name);
            std::fs::create_dir_all(path.parent().expect("reference paths have a folder"))?;
            let mut chapter = (self.open)(&gpu)?;
            chapter.show(i);
            chapter.render(&gpu, i, self.time)?.0.save(&path)?;
            for stale in ["actual", "diff"] {
                let _ = std::fs::remove_file(snapshot::sibling(&path, stale));
            }
            written.push(path);
        }
        Ok(written)
    }

    // ANCHOR: purity
    /// What a view shows must not depend on the views chosen before it.
    /// One live instance flies somewhere and passes through every view;
    /// then, for each view, it selects it and resets the camera as the
    /// overlay's button does, and must draw the same bytes as a fresh
    /// instance showing that view. Modes must leave the camera alone, and
    /// presets must set all of it. Each fresh picture is also compared with
    /// the reference, and the bench table with the passes drawn. Returns
    /// every problem found.
    pub fn check_purity(&self) -> anyhow::Result<Vec<String>> {
        let gpu = self.gpu()?;
        let mut live = (self.open)(&gpu)?;
        let mut problems = Vec::new();
        let mut passes = Vec::new();
        if let Some(start) = live.camera() {
            live.set_camera(elsewhere(&start));
        }
        for view in (0..self.views.len()).rev() {
            live.show(view);
        }
        for (i, view) in self.views.iter().enumerate() {
            problems.extend(self.camera_rules(live.as_mut(), i));
            if !view.snapshot {
                continue;
            }
            live.show(i);
            live.reset_camera(i);
            let (after_the_others, _) = live.render(&gpu, i, self.time)?;
            let mut fresh = (self.open)(&gpu)?;
            fresh.show(i);
            let (fresh_picture, drawn) = fresh.render(&gpu, i, self.time)?;
            passes.push((view.name, drawn));
            if after_the_others != fresh_picture {
                let path = std::env::temp_dir().join(format!("{}-{}-after-other-views.png", self.name, view.name));
                after_the_others.save(&path)?;
                problems.push(format!(
                    "{}/{}: after the other views and a camera reset, the picture differs from a fresh instance's \
                     (a view that depends on history, or a render that is not deterministic); it is {}",
                    self.name,
                    view.name,
                    path.display()
                ));
            }
            if let Err(e) = self.compare(i, &fresh_picture) {
                problems.push(format!("{}/{}: {e}", self.name, view.name));
            }
        }
        problems.extend(bench_tables::check(self.name, self.views, &passes));
        Ok(problems)
    }
    // ANCHOR_END: purity

    /// A mode never moves the camera; a preset puts it in the same place
    /// wherever it was.
    fn camera_rules(&self, live: &mut dyn Live, view: usize) -> Option<String> {
        let start = live.camera()?;
        let (name, kind) = (self.views[view].name, self.views[view].kind);
        let moved = elsewhere(&start);
        live.set_camera(moved);
        live.show(view);
        let after = live.camera()?;
        match kind {
            ViewKind::Mode if after != moved => {
                Some(format!("{}/{name} is a mode but moved the camera from {moved:?} to {after:?}", self.name))
            }
            ViewKind::Preset => {
                live.set_camera(elsewhere(&moved));
                live.show(view);
                let again = live.camera()?;
                (again != after).then(|| {
                    format!(
                        "{}/{name} is a preset but left part of the camera as it was: {after:?} vs {again:?}",
                        self.name
                    )
                })
            }
            ViewKind::Mode => None,
        }
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
