//! The chapter itself: the overlay's controls (the water's style, each
//! wave, fly or orbit camera), and `impl Chapter`, which composes chapter
//! 05's plain, chapter 06's sky and the water: three pictures of the scene
//! a frame, then the water reading two of them.

use std::sync::Arc;

use common::book_figures::thousands;
use common::glam::{Vec2, Vec4};
use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, SceneTargets, Target, View, anyhow,
    egui, views_of,
};
use fog::FogSettings;
use instancing::{MarsPlain, Setup, plain_camera};
use skybox::Sky;
use terrain::KEEP_ALL;
use terrain::ground::{self, Movement};

use crate::camera_presets::EYE_HEIGHT;
use crate::lake::{find_lake, lake_camera, mirrored};
use crate::scene_pictures::{DrawnInto, Eye, MAIN, REFLECTION, REFRACTION, rocks_per_picture};
use crate::steering::{Orbiting, STEERING_KEYS, Steering, steer_orbit};
use crate::views::{Display, Settings, VIEW_TABLE};
use crate::water_renderer::{Style, WaterRenderer};
use crate::waves::edit_waves;

/// The time of day the lake is seen at (mid-morning, chapter 06's `day`).
const START_PHASE: f32 = 0.40;

pub struct WaterChapter {
    pub plain: MarsPlain,
    pub sky: Sky,
    pub water: WaterRenderer,
    pub camera: Camera,
    pub controller: FlyController,
    /// Fly (the start) or orbit. Not a setting of the views: it moves the
    /// camera in the window, and never changes what a view draws.
    pub steering: Steering,
    /// Flying, or walking on the ground (G, `--walk`), while steering is `Fly`.
    pub movement: Movement,
    orbiting: Option<Orbiting>,
    pub fog: FogSettings,
    pub rocks: Setup,
    pub settings: Settings,
    /// Seconds in a day (chapter 06's slider).
    pub day_seconds: f32,
    pub level: f32,
    /// The lake's centre (x, z) and side, metres.
    pub centre: Vec2,
    pub size: f32,
    eyes: [Eye; 3],
    /// The main picture's samples and depth, resolved into the frame (an
    /// `Arc`, so that a frame can hold it while it takes the picture).
    scene: Arc<SceneTargets>,
    target: Target,
}

impl Chapter for WaterChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0049; outliers at most 0.1%. Worst 16×16 patch 0.063 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.018, outliers: 0.002, patch: 0.2 };
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "07 · Water";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
    const SNAPSHOT_TIME: f32 = 0.0;
    const KEYS: &'static [(&'static str, &'static str)] = &STEERING_KEYS;
    const FLAGS: &'static [ChapterFlag] = &[ground::WALK_FLAG];
    const BENCH_FRAMES: u32 = 5;

    /// Clip distances where the adapter has them; a fragment discard otherwise.
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
        let device = &gpu.device;
        let scene = Arc::new(SceneTargets::new(gpu, target));
        // The reflection and refraction at one sample a pixel, the main
        // picture at the scene's.
        let counts = [1, scene.samples()];
        let plain = MarsPlain::new(gpu, target.format, &counts, terrain)?;
        let sky = Sky::new(gpu, target.format, &counts)?;
        let field = plain.terrain.field();
        let (centre, size, level) = find_lake(field, &plain_camera(field, target.aspect()));
        let settings = Settings::DEFAULT;
        let main = Target { samples: scene.samples(), ..target };
        let water = WaterRenderer::new(gpu, &plain, centre, size, main, settings.water.resolution)?;
        let eyes = std::array::from_fn(|eye| {
            let samples = if eye == MAIN { scene.samples() } else { 1 };
            Eye::new(&plain, &sky, device, samples)
        });
        let camera = lake_camera(field, centre, size, level, EYE_HEIGHT, target.aspect());
        Ok(Self {
            plain,
            sky,
            water,
            camera,
            controller: FlyController { speed: 10.0, ..Default::default() },
            steering: Steering::Fly,
            movement: Movement::Fly,
            orbiting: None,
            fog: FogSettings::HAZE,
            rocks: Setup::DEFAULT,
            settings,
            day_seconds: 240.0,
            level,
            centre,
            size,
            eyes,
            scene,
            target,
        })
    }

    fn apply_flags(&mut self, _gpu: &Gpu, flags: &FlagValues) -> anyhow::Result<()> {
        self.movement = ground::movement_from_flags(flags);
        Ok(())
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.scene = Arc::new(SceneTargets::new(gpu, Target { samples: self.scene.samples(), ..target }));
        self.water.resize_pictures(&gpu.device, target, self.settings.water.resolution);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
    }

    fn reset_camera(&mut self, view: usize) {
        let (field, aspect) = (self.plain.terrain.field(), self.target.aspect());
        let (centre, size, level) = (self.centre, self.size, self.level);
        self.camera = match VIEW_TABLE[view].camera {
            Some(preset) => preset.camera(field, centre, size, level, aspect),
            None => lake_camera(field, centre, size, level, EYE_HEIGHT, aspect),
        };
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn before_first_frame(&mut self, _camera_placed: bool) {
        if self.steering == Steering::Fly {
            ground::first_frame(&mut self.camera, self.plain.terrain.field(), self.movement);
        }
    }

    fn update(&mut self, input: &Input, dt: f32) {
        match self.steering {
            Steering::Fly => {
                let field = self.plain.terrain.field();
                ground::step(&self.controller, &mut self.camera, &mut self.movement, field, input, dt);
            }
            Steering::Orbit => {
                let lake = (self.level, self.centre, self.size);
                steer_orbit(&mut self.orbiting, &mut self.camera, lake, input);
            }
        }
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        for eye in &mut self.eyes {
            eye.drawn = None;
        }
        self.water.resize_pictures(&gpu.device, self.target, self.settings.water.resolution);
        let phase = (START_PHASE + frame.time / self.day_seconds).rem_euclid(1.0);
        self.camera.far = self.fog.far_plane();
        self.plain.set_air(&gpu.queue, self.fog, self.sky.fog_colour(phase));
        let camera = self.camera;
        let bias = 0.5; // a little overlap, so that waves do not open gaps at the shore
        let (display, style) = (self.settings.display, self.settings.water.style);
        // Seed 003's style reads no pictures: then only a view of one draws it.
        let pictures = style == Style::Pictures || display != Display::Lake;
        let (reflection, refraction) = (self.water.reflection.clone(), self.water.refraction.clone());
        // Each picture through its own eye, with the rocks as the view draws them.
        let rocks = if self.settings.full_detail { self.rocks.at_full_detail() } else { self.rocks };
        let (scene, eyes) = ((&self.plain, &self.sky), &mut self.eyes);
        // 1. The reflection: from below the water, keeping what is above it.
        if pictures && display != Display::Refraction {
            let above = Vec4::new(0.0, 1.0, 0.0, -self.level + bias);
            let into = ("reflection", DrawnInto::Picture(&reflection.colour, &reflection.depth));
            let mirror = mirrored(&camera, self.level);
            let eye = &mut eyes[REFLECTION];
            let picture =
                eye.take_picture(gpu, frame.encoder, frame.timer, scene, into, (&mirror, above), phase, rocks);
            frame.drawn.add("reflection", picture);
        }
        // 2. The refraction: from the camera, keeping what is below the water.
        if pictures && display != Display::Reflection {
            let below = Vec4::new(0.0, -1.0, 0.0, self.level + bias);
            let into = ("refraction", DrawnInto::Picture(&refraction.colour, &refraction.depth));
            let eye = &mut eyes[REFRACTION];
            let picture =
                eye.take_picture(gpu, frame.encoder, frame.timer, scene, into, (&camera, below), phase, rocks);
            frame.drawn.add("refraction", picture);
        }
        match display {
            Display::Reflection => return frame.drawn.add("show picture", self.water.show(frame, 0)),
            Display::Refraction => return frame.drawn.add("show picture", self.water.show(frame, 1)),
            Display::Lake => {}
        }

        // 3. The scene itself, whole.
        let targets = self.scene.clone();
        let into = ("plain and sky", DrawnInto::Frame(&targets, frame.target));
        let eye = &mut eyes[MAIN];
        let picture = eye.take_picture(gpu, frame.encoder, frame.timer, scene, into, (&camera, KEEP_ALL), phase, rocks);
        frame.drawn.add("plain and sky", picture);

        // 4. The water on top, reading both pictures (or, in seed 003's style, its texture).
        self.water.aim(&gpu.queue, self.level, frame.time, &camera, self.settings.water);
        // Drawn on the scene's samples and depth as the main pass left
        // them, and resolved into the frame again.
        let mut pass = targets.pass(frame.encoder, frame.timer, "water surface", frame.target, None);
        frame.drawn.add("water surface", self.water.draw(&mut pass, &self.plain, &self.eyes[MAIN].plain, style));
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.settings.water;
        ui.horizontal(|ui| {
            ui.label("surface:");
            ui.radio_value(&mut s.style, Style::Pictures, "reflection and refraction");
            ui.radio_value(&mut s.style, Style::Texture, "seed 003's texture");
        });
        if s.style == Style::Texture {
            ui.add(egui::Slider::new(&mut s.texture_push, 0.0..=0.6).text("texture pushed by its colours (tiles)"));
        }
        ui.add(egui::Slider::new(&mut s.resolution, 0.25..=1.0).text("reflection/refraction resolution"));
        let mut waves_on = s.wave_strength > 0.0;
        if ui.checkbox(&mut waves_on, "waves (off: the flat surface, textures only)").changed() {
            s.wave_strength = if waves_on { 1.0 } else { 0.0 };
        }
        ui.add(egui::Slider::new(&mut s.wave_strength, 0.0..=4.0).text("wave strength"));
        egui::CollapsingHeader::new("each wave").show(ui, |ui| edit_waves(ui, &mut s.waves));
        ui.add(egui::Slider::new(&mut s.ripples, 0.0..=0.05).text("ripple distortion"));
        ui.checkbox(&mut s.fresnel, "Fresnel");
        let (width, height) = self.water.pictures_size();
        ui.label(format!("water level {:.1} m; pictures {width}×{height}", self.level));
        // Read back from the GPU a frame or two late.
        ui.label(rocks_per_picture(self.eyes.each_ref().map(|eye| eye.drawn.flatten())));
        if let Some(fallback) = self.plain.culling_fallback() {
            ui.label(fallback);
        }
        ui.separator();
        ui.add(egui::Slider::new(&mut self.day_seconds, 10.0..=1200.0).logarithmic(true).text("day length (s)"));
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        let max = self.plain.rocks_placed();
        ui.add(egui::Slider::new(&mut self.rocks.rocks, 0..=max).logarithmic(true).text("rocks"));
        ui.horizontal(|ui| {
            ui.label("camera:");
            ui.radio_value(&mut self.steering, Steering::Fly, "fly");
            ui.radio_value(&mut self.steering, Steering::Orbit, "orbit a point on the lake");
        });
        if self.steering == Steering::Fly {
            ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=100.0).logarithmic(true).text("speed (m/s)"));
            ground::movement_switch(ui, &mut self.movement);
        }
    }

    fn stats(&mut self, gpu: &Gpu) -> String {
        let (width, height) = self.water.pictures_size();
        // Waiting for the GPU's counts of the last frame's pictures.
        let drawn =
            self.eyes.each_ref().map(|eye| eye.drawn.map(|_| self.plain.rocks_drawn_now(gpu, &eye.plain, self.rocks)));
        let fallback = self.plain.culling_fallback().map_or(String::new(), |line| format!("; {line}"));
        format!(
            "pictures {width}×{height}; {} rocks in the world; {}{fallback}",
            thousands(self.rocks.rocks.min(self.plain.rocks_placed()).into()),
            rocks_per_picture(drawn)
        )
    }
}

#[cfg(test)]
mod tests {
    use common::chapter::view_index;
    use common::headless::{OFFSCREEN_FORMAT, capture};

    use super::*;
    use crate::lake::orbit_point;
    use crate::waves::{Wave, lake_waves};

    /// The overlay's controls on one live chapter (making one takes
    /// seconds: the terrain), small and without rocks.
    #[test]
    fn the_overlays_controls() {
        let gpu = Gpu::headless(WaterChapter::gpu_needs()).unwrap();
        let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
        let mut chapter = common::chapter::create::<WaterChapter>(&gpu, target, &Default::default()).unwrap();
        chapter.rocks.rocks = 0; // they cost time and add nothing here
        edits_reach_the_picture_and_choosing_the_view_takes_them_back(&gpu, &mut chapter, target);
        the_orbit_takes_over_where_the_camera_is_and_turns_round_the_lake(&mut chapter);
    }

    /// The overlay's edits reach the picture through the settings, and
    /// choosing a view takes them back, byte for byte: a higher first wave
    /// and a texture that no longer pushes itself both change the water.
    fn edits_reach_the_picture_and_choosing_the_view_takes_them_back(
        gpu: &Gpu,
        chapter: &mut WaterChapter,
        target: Target,
    ) {
        let view = view_index::<WaterChapter>("textured-waves").unwrap();
        let picture =
            |chapter: &mut WaterChapter| capture(gpu, chapter, target, (0.0, view), Default::default()).unwrap();
        let changed = |a: &common::image::RgbaImage, b: &common::image::RgbaImage| {
            a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
        };
        chapter.select_view(view);
        let lake = picture(chapter);
        chapter.settings.water.waves.set(0, Wave { amplitude: 0.6, ..lake_waves()[0] }).unwrap();
        let higher = picture(chapter);
        chapter.select_view(view);
        let again = picture(chapter);
        chapter.settings.water.texture_push = 0.0;
        let still = picture(chapter);
        let (by_wave, by_push) = (changed(&lake, &higher), changed(&lake, &still));
        println!("of {} pixels, the higher wave changes {by_wave}, no push {by_push}", 160 * 90);
        assert!(by_wave > 1000 && by_push > 1000, "{by_wave}, {by_push}");
        assert!(again == lake, "after choosing the view again, {} pixels differ", changed(&lake, &again));
    }

    /// The orbit camera takes over where the camera is, looking at the
    /// point of the lake in the middle of its view; a drag turns it round
    /// that point (down to the water's level, no further) and the wheel
    /// brings it nearer; after a preset has moved the camera, it takes
    /// over from there.
    fn the_orbit_takes_over_where_the_camera_is_and_turns_round_the_lake(chapter: &mut WaterChapter) {
        chapter.select_view(0);
        chapter.reset_camera(0);
        chapter.steering = Steering::Orbit;
        let start = chapter.camera;
        let point = orbit_point(&start, chapter.level, chapter.centre, chapter.size);
        chapter.update(&Input::default(), 0.02);
        assert!(chapter.camera.position.distance(start.position) < 1e-3, "{:?} from {start:?}", chapter.camera);
        assert!(chapter.camera.forward().distance((point - start.position).normalize()) < 1e-4);
        let mut drag = Input::default();
        (drag.look, drag.scroll) = (Vec2::new(120.0, -40.0), 2.0);
        chapter.update(&drag, 0.02);
        let distance = chapter.camera.position.distance(point);
        assert!((distance - 0.81 * start.position.distance(point)).abs() < 0.01, "{distance} m from the point");
        assert!(chapter.camera.forward().distance((point - chapter.camera.position).normalize()) < 1e-4);
        // The drag would have taken the eye under the water: it stops at its level.
        assert!((chapter.camera.position.y - chapter.level).abs() < 1e-3, "{}", chapter.camera.position.y);
        chapter.select_view(view_index::<WaterChapter>("waves").unwrap());
        let preset = chapter.camera;
        chapter.update(&Input::default(), 0.02);
        assert!(chapter.camera.position.distance(preset.position) < 1e-3, "taken over at the preset's place");
    }
}
