//! The course: every chapter of the book, in book order, each as one
//! [`Record`] made from its `impl Chapter` (name, title, views, snapshot
//! time, browser tolerance, whether it prepares in steps). The snapshot
//! test, the browser build and its test, the diagrams and xtask read
//! chapters from here, so a fact about a chapter is written once, in the
//! chapter. Adding a chapter adds one line to [`chapters`] and one
//! dependency to this crate's `Cargo.toml`.

use std::process::ExitCode;

use common::headless::{Offscreen, draw_frame, read_texture};
use common::{Camera, Chapter, Gpu, GpuNeeds, PassTimer, Target, Tolerance, View, anyhow, image, show_view};

/// Every chapter, in book order.
pub fn chapters() -> Vec<Record> {
    vec![
        record::<triangle::Triangle>(),
        record::<camera::CameraChapter>(),
        record::<terrain::TerrainChapter>(),
        record::<fog::FogChapter>(),
        record::<instancing::InstancingChapter>(),
        record::<skybox::SkyboxChapter>(),
        record::<water::WaterChapter>(),
        record::<lighting::LightingChapter>(),
        record::<textures::TexturesChapter>(),
        record::<shadows::ShadowsChapter>(),
        record::<voronoi_water::VoronoiWaterChapter>(),
    ]
}

/// The chapter called `name` (its package name), if there is one.
pub fn find(name: &str) -> Option<Record> {
    chapters().into_iter().find(|r| r.name == name)
}

/// What the tools know of one chapter, whatever its type.
#[derive(Clone, Copy)]
pub struct Record {
    /// The package name: `cargo run -p NAME`, its page `live/NAME/`.
    pub name: &'static str,
    /// The book's title for it.
    pub title: &'static str,
    pub views: &'static [View],
    /// The scene time of its snapshots and still pictures.
    pub snapshot_time: f32,
    /// How far its still picture in the browser may be from the native one.
    pub browser_tolerance: Tolerance,
    /// Whether it prepares in steps before its first frame (chapter 03's terrain).
    pub prepares_in_steps: bool,
    pub needs: GpuNeeds,
    /// Runs it as its binary's `main` does (in a browser, from the page's URL).
    pub run: fn() -> ExitCode,
    /// Makes an instance for `target` on `gpu`.
    pub open: fn(&Gpu, Target) -> anyhow::Result<Box<dyn AnyChapter>>,
}

fn record<C: Chapter>() -> Record {
    Record {
        name: C::NAME,
        title: C::TITLE,
        views: C::VIEWS,
        snapshot_time: C::SNAPSHOT_TIME,
        browser_tolerance: C::BROWSER_TOLERANCE,
        prepares_in_steps: C::PREPARES_IN_STEPS,
        needs: C::gpu_needs(),
        run: common::run::<C>,
        open: |gpu, target| Ok(Box::new(Instance { chapter: C::new(gpu, target)?, target })),
    }
}

impl Record {
    /// The index of the first view that is a snapshot (the one the
    /// browser test and the bench use).
    pub fn first_snapshot_view(&self) -> usize {
        self.views.iter().position(|v| v.snapshot).unwrap_or(0)
    }
}

/// A chapter instance, whatever its type, as the tests drive it.
pub trait AnyChapter {
    /// As the overlay does: the view's settings, and a preset's camera.
    fn show(&mut self, view: usize);
    fn reset_camera(&mut self, view: usize);
    fn camera(&mut self) -> Option<Camera>;
    fn set_camera(&mut self, camera: Camera);
    /// Renders `view` at `time` offscreen; returns the picture and the
    /// passes it drew (timed on the GPU, then on the CPU).
    fn render(&mut self, gpu: &Gpu, view: usize, time: f32) -> anyhow::Result<(image::RgbaImage, Vec<&'static str>)>;
}

struct Instance<C: Chapter> {
    chapter: C,
    target: Target,
}

impl<C: Chapter> AnyChapter for Instance<C> {
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
        debug_assert!(view < C::VIEWS.len());
        let offscreen = Offscreen::new(&gpu.device, self.target);
        let timer = PassTimer::off();
        draw_frame(gpu, &mut self.chapter, &offscreen.view, time, view, &timer);
        let mut passes = timer.take_labels();
        passes.extend(timer.take_cpu().into_iter().map(|(label, _)| label));
        Ok((read_texture(gpu, &offscreen.texture)?, passes))
    }
}
