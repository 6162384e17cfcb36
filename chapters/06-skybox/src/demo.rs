//! The chapter itself: the time of day each view starts at, the views and
//! their cameras, the overlay's controls, and `impl Chapter`, which draws
//! chapter 05's plain lit by the sun and then the sky in the same pass.

use common::book_figures::thousands;
use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, SceneTargets, Target, View, ViewRow,
    anyhow, egui, views_of,
};
use fog::FogSettings;
use instancing::{DrawCalls, MarsPlain, PlainViewpoint, Setup, plain_camera};
use terrain::KEEP_ALL;
use terrain::ground::{self, Movement};
use terrain::heightfield::HeightField;

use crate::sky::{Sky, SkyViewpoint};
use crate::sun_path::sun_at;

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// The time of day at scene time 0: 0 midnight, 0.25 sunrise, 0.5
    /// noon, 0.75 sunset.
    pub start_phase: f32,
    /// The plain as drawn before levels of detail (`Setup::at_full_detail`).
    pub full_detail: bool,
}

impl Settings {
    /// Mid-morning.
    pub const DEFAULT: Self = Self { start_phase: 0.40, full_detail: false };
}

/// The places a view can put the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// The plain's camera, turned to face the sunset.
    Dusk,
}

impl CameraPreset {
    pub fn camera(self, field: &HeightField, aspect: f32) -> Camera {
        match self {
            Self::Dusk => dusk_camera(field, aspect),
        }
    }
}

/// Every view, with the time of day it starts at and, for a preset, its camera.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 5] = [
    ViewRow::mode("day", "mid-morning: the sun high in the east, the plain in full light", Settings::DEFAULT),
    ViewRow::no_aa("day", Settings::DEFAULT),
    ViewRow::preset(
        "dusk",
        "facing west as the sun sets in its blue Martian halo",
        Settings { start_phase: 0.745, ..Settings::DEFAULT },
        CameraPreset::Dusk,
    ),
    ViewRow::mode(
        "night",
        "stars over the plain, lit by the sky alone",
        Settings { start_phase: 0.02, ..Settings::DEFAULT },
    ),
    ViewRow::bench(
        "full-detail",
        "bench: the day view as drawn before levels of detail, terrain and rocks at full detail",
        Settings { full_detail: true, ..Settings::DEFAULT },
    ),
];

/// The plain's camera, turned to face the sunset: west (−x), a little
/// south, a little up.
fn dusk_camera(field: &HeightField, aspect: f32) -> Camera {
    Camera { yaw: 0.95f32.atan2(-0.3), pitch: 4f32.to_radians(), ..plain_camera(field, aspect) }
}

pub struct SkyboxChapter {
    pub plain: MarsPlain,
    pub sky: Sky,
    pub camera: Camera,
    pub controller: FlyController,
    /// Flying (the default) or walking on the ground (G, `--walk`).
    pub movement: Movement,
    pub fog: FogSettings,
    pub rocks: Setup,
    /// What the view decides: the time of day at scene time 0.
    pub settings: Settings,
    /// How long a day lasts (s).
    pub day_seconds: f32,
    /// The time of day of the last frame (0 midnight, 0.5 noon).
    phase: f32,
    viewpoint: (PlainViewpoint, SkyViewpoint),
    /// The scene's samples and depth, resolved into the frame.
    scene: SceneTargets,
    target: Target,
    draw_calls: DrawCalls,
}

impl SkyboxChapter {
    // ANCHOR: time_of_day
    /// The time of day at scene time `time`: 0 midnight, 0.5 noon.
    pub fn phase_at(&self, time: f32) -> f32 {
        (self.settings.start_phase + time / self.day_seconds).rem_euclid(1.0)
    }
    // ANCHOR_END: time_of_day

    /// The rocks as this view draws them: the full-detail view culls them by
    /// chunk on the CPU, every kept one whole (`Setup::at_full_detail`). The
    /// frame and the stats line both read it, so the line counts what was drawn.
    fn rocks_setup(&self) -> Setup {
        if self.settings.full_detail { self.rocks.at_full_detail() } else { self.rocks }
    }
}

impl Chapter for SkyboxChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0055; outliers at most 0.1%. Worst 16×16 patch 0.056 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.016, outliers: 0.002, patch: 0.2 };
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "06 · Sky box";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
    const SNAPSHOT_TIME: f32 = 0.0;
    const KEYS: &'static [(&'static str, &'static str)] = ground::KEYS;
    const FLAGS: &'static [ChapterFlag] = &[ground::WALK_FLAG];
    const BENCH_FRAMES: u32 = 10;

    fn gpu_needs() -> common::GpuNeeds {
        terrain::gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    /// The terrain, made in steps: see chapter 03.
    type Prepared = std::sync::Arc<terrain::TerrainData>;

    fn prepare(gpu: &Gpu) -> common::Preparation<Self::Prepared> {
        terrain::TerrainData::prepare(gpu, terrain::heightfield::TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target, terrain: Self::Prepared) -> anyhow::Result<Self> {
        let scene = SceneTargets::new(gpu, target);
        let samples = scene.samples();
        let plain = MarsPlain::new(gpu, target.format, &[samples], terrain)?;
        let sky = Sky::new(gpu, target.format, &[samples])?;
        Ok(Self {
            camera: plain_camera(plain.terrain.field(), target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            movement: Movement::Fly,
            fog: FogSettings::HAZE,
            rocks: instancing::Setup::DEFAULT,
            settings: Settings::DEFAULT,
            day_seconds: 240.0,
            phase: Settings::DEFAULT.start_phase,
            viewpoint: (plain.viewpoint(&gpu.device, samples), sky.viewpoint(&gpu.device, samples)),
            scene,
            plain,
            sky,
            target,
            draw_calls: DrawCalls::default(),
        })
    }

    fn apply_flags(&mut self, _gpu: &Gpu, flags: &FlagValues) -> anyhow::Result<()> {
        self.movement = ground::movement_from_flags(flags);
        Ok(())
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.scene = SceneTargets::new(gpu, Target { samples: self.scene.samples(), ..target });
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
    }

    fn reset_camera(&mut self, view: usize) {
        let (field, aspect) = (self.plain.terrain.field(), self.target.aspect());
        self.camera = match VIEW_TABLE[view].camera {
            Some(preset) => preset.camera(field, aspect),
            None => plain_camera(field, aspect),
        };
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn before_first_frame(&mut self, _camera_placed: bool) {
        ground::first_frame(&mut self.camera, self.plain.terrain.field(), self.movement);
    }

    fn update(&mut self, input: &Input, dt: f32) {
        let field = self.plain.terrain.field();
        ground::step(&self.controller, &mut self.camera, &mut self.movement, field, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        // The time of day sets the light on the ground and the fog's colour.
        self.phase = self.phase_at(frame.time);
        self.camera.far = self.fog.far_plane();
        self.plain.set_air(&gpu.queue, self.fog, self.sky.fog_colour(self.phase));
        let rocks = self.rocks_setup();
        let (ground, sky) = &mut self.viewpoint;
        self.plain.aim(gpu, ground, &self.camera, rocks.detail(self.target.height), sun_at(self.phase), KEEP_ALL);
        self.sky.aim(&gpu.queue, sky, &self.camera, self.phase);
        self.plain.cull(gpu, frame.encoder, frame.timer, ground, rocks);
        // The clear colour is never seen: the sky covers whatever the plain leaves.
        let drawn = frame.drawn;
        let mut pass = frame.multisampled_pass("plain and sky", terrain::SKY, &self.scene);
        self.draw_calls = self.plain.draw(&mut pass, ground, rocks);
        drawn.add("plain and sky", self.draw_calls.drawn() + self.sky.draw(&mut pass, sky));
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let hours = self.phase * 24.0;
        ui.label(format!("time of day {:02}:{:02}", hours as u32, ((hours.fract()) * 60.0) as u32));
        ui.add(egui::Slider::new(&mut self.settings.start_phase, 0.0..=1.0).text("time of day at t = 0"));
        ui.add(egui::Slider::new(&mut self.day_seconds, 10.0..=1200.0).logarithmic(true).text("day length (s)"));
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        let max = self.plain.rocks_placed();
        ui.add(egui::Slider::new(&mut self.rocks.rocks, 0..=max).logarithmic(true).text("rocks"));
        // Chapter 05's counts, read back from the GPU a frame or two late.
        if let Some(drawn) = self.draw_calls.rocks_drawn {
            let (rocks, triangles) = (thousands(drawn.rocks.into()), thousands(drawn.triangles as f64));
            ui.label(format!("{rocks} rocks drawn, {triangles} rock triangles"));
        }
        if let Some(fallback) = self.plain.culling_fallback() {
            ui.label(fallback);
        }
        ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=200.0).logarithmic(true).text("speed (m/s)"));
        ground::movement_switch(ui, &mut self.movement);
    }

    fn stats(&mut self, gpu: &Gpu) -> String {
        let calls = self.draw_calls;
        // The setup the frame drew with: the full-detail view culls by chunk,
        // and asking the GPU's lists for its rocks would read lists it never filled.
        let drawn = self.plain.rocks_drawn_now(gpu, &self.viewpoint.0, self.rocks_setup());
        let fallback = self.plain.culling_fallback().map_or(String::new(), |line| format!("; {line}"));
        format!(
            "time of day {:.3}; {} of {} rocks drawn, {} rock triangles; {} draw calls ({} terrain chunks, {} for the rocks, 1 for the sky){fallback}",
            self.phase,
            thousands(drawn.rocks.into()),
            thousands(self.rocks.rocks.min(self.plain.rocks_placed()).into()),
            thousands(drawn.triangles as f64),
            calls.total() + 1,
            calls.terrain,
            calls.rocks
        )
    }
}
