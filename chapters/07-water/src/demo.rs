//! The chapter itself: what each view decides, the views and their
//! cameras, the overlay's controls (the water's style, each wave, fly or
//! orbit camera), and `impl Chapter`, which composes chapter 05's plain,
//! chapter 06's sky and the water: three pictures of the scene a frame,
//! then the water reading two of them.

use std::sync::Arc;

use common::book_figures::thousands;
use common::chapter::scene_pass;
use common::glam::{Vec2, Vec3, Vec4};
use common::{
    Camera, Chapter, ChapterFlag, Drawn, FlagValues, FlyController, Frame, Gpu, Input, Orbit, PassTimer, SceneTargets,
    Target, View, ViewRow, anyhow, egui, views_of, wgpu,
};
use fog::FogSettings;
use instancing::{MarsPlain, PlainViewpoint, RocksDrawn, Setup, plain_camera};
use skybox::{Sky, SkyViewpoint, sun_at};
use terrain::ground::{self, Movement};
use terrain::heightfield::HeightField;
use terrain::{KEEP_ALL, SKY};

use crate::lake::{find_lake, lake_camera, mirrored, orbit_point};
use crate::water_renderer::{Style, WaterRenderer, WaterSettings};
use crate::waves::WaveSet;

/// What reaches the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    /// The lake, with everything around it.
    Lake,
    /// The reflection picture, full screen.
    Reflection,
    /// The refraction picture, full screen.
    Refraction,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub water: WaterSettings,
    pub display: Display,
    /// The plain in every picture as drawn before levels of detail
    /// (`Setup::at_full_detail`).
    pub full_detail: bool,
}

impl Settings {
    pub const DEFAULT: Self = Self { water: WaterSettings::DEFAULT, display: Display::Lake, full_detail: false };
}

/// How high above the water the start camera stands, metres.
const EYE_HEIGHT: f32 = 18.0;

/// The places a view can put the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// At the same shore, 6 m above the water, where the waves look large.
    CloseToWater,
}

impl CameraPreset {
    pub fn camera(self, field: &HeightField, centre: Vec2, size: f32, level: f32, aspect: f32) -> Camera {
        match self {
            Self::CloseToWater => lake_camera(field, centre, size, level, 6.0, aspect),
        }
    }
}

/// Every view, with the settings it applies and, for a preset, its camera.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 8] = [
    ViewRow::mode(
        "default",
        "the lake: reflection and refraction mixed by Fresnel, ripples and waves",
        Settings::DEFAULT,
    ),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "reflection",
        "the reflection picture, full screen: the scene above the water, from below it",
        Settings { display: Display::Reflection, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "refraction",
        "the refraction picture, full screen: the scene below the water",
        Settings { display: Display::Refraction, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "waves",
        "the geometric waves three times as strong, seen from 6 m above the water",
        Settings { water: WaterSettings { wave_strength: 3.0, ..WaterSettings::DEFAULT }, ..Settings::DEFAULT },
        CameraPreset::CloseToWater,
    ),
    ViewRow::mode(
        "no-fresnel",
        "reflection and refraction half and half at every angle",
        Settings { water: WaterSettings { fresnel: false, ..WaterSettings::DEFAULT }, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "textured-waves",
        "seed 003's style: a tiled water texture pushed aside by its own colours, on the waves three times as strong",
        Settings {
            water: WaterSettings { style: Style::Texture, wave_strength: 3.0, ..WaterSettings::DEFAULT },
            ..Settings::DEFAULT
        },
        CameraPreset::CloseToWater,
    ),
    ViewRow::bench(
        "full-detail",
        "bench: the lake as drawn before levels of detail, terrain and rocks at full detail in all three pictures",
        Settings { full_detail: true, ..Settings::DEFAULT },
    ),
];

// ANCHOR: steering
/// How the mouse moves the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Steering {
    /// Chapter 02's fly camera: keys move, dragging looks round.
    Fly,
    /// `common::Orbit`: dragging turns round a point on the lake, the wheel zooms.
    Orbit,
}

/// The orbit round the lake: from level with the water (never below it,
/// nor lifting a camera that takes over low over the water) to nearly
/// overhead, 3 m to 1.5 km from the point.
const LAKE_ORBIT: Orbit = Orbit::new(0.0, 0.5, 50.0).within((0.0, 1.5), (3.0, 1500.0));

/// The orbit while it steers the camera: the orbit, the point on the lake
/// it turns round, and where it last put the camera (position, yaw, pitch).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Orbiting {
    orbit: Orbit,
    point: Vec3,
    placed: (Vec3, f32, f32),
}
// ANCHOR_END: steering

/// The uniforms for drawing the plain and the sky from one camera. The
/// frame draws three pictures, each from its own camera, so it keeps three
/// of these, and all three pictures are recorded before one submit.
struct Eye {
    plain: PlainViewpoint,
    sky: SkyViewpoint,
    /// What the plain drew in this eye's last picture, where it was taken
    /// in the last frame: counted on the CPU, or read back late from the GPU.
    drawn: Option<Option<RocksDrawn>>,
}

/// Which of the frame's pictures an `Eye` draws.
const REFLECTION: usize = 0;
const REFRACTION: usize = 1;
const MAIN: usize = 2;

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

/// Where `take_picture` draws: one of the water's pictures (its colour
/// and its depth, one sample a pixel: the water reads that depth), or the
/// frame, through the scene's samples.
enum DrawnInto<'a> {
    Picture(&'a wgpu::TextureView, &'a wgpu::TextureView),
    Frame(&'a SceneTargets, &'a wgpu::TextureView),
}

impl WaterChapter {
    // ANCHOR: picture
    /// Records the plain and the sky, seen from `camera` through eye `eye`,
    /// into `into`, keeping only what `clip` keeps. Each
    /// picture has its own eye, so its uniforms are not overwritten by the
    /// next picture's before the one submit at the end of the frame.
    #[allow(clippy::too_many_arguments)]
    fn take_picture(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        (label, eye): (&'static str, usize),
        into: DrawnInto<'_>,
        camera: &Camera,
        clip: Vec4,
        phase: f32,
    ) -> Drawn {
        let Eye { plain, sky, drawn } = &mut self.eyes[eye];
        // The picture's own height: the half-size reflection and refraction
        // see each rock half as many pixels across, and grade it so.
        let rocks = if self.settings.full_detail { self.rocks.at_full_detail() } else { self.rocks };
        let height = match into {
            DrawnInto::Picture(colour, _) | DrawnInto::Frame(_, colour) => colour.texture().height(),
        };
        let detail = rocks.detail(height);
        self.plain.aim(gpu, plain, camera, detail, sun_at(phase), clip);
        self.sky.aim(&gpu.queue, sky, camera, phase);
        // The rocks' compute pass, with this picture's clip plane: rocks
        // wholly on the cut side of the water are never drawn.
        self.plain.cull(gpu, encoder, timer, plain, rocks);
        let mut pass = match into {
            DrawnInto::Picture(colour, depth) => scene_pass(encoder, timer, label, colour, SKY, depth),
            DrawnInto::Frame(scene, frame) => scene.pass(encoder, timer, label, frame, Some(SKY)),
        };
        let calls = self.plain.draw(&mut pass, plain, rocks);
        *drawn = Some(calls.rocks_drawn);
        calls.drawn() + self.sky.draw(&mut pass, sky)
    }
    // ANCHOR_END: picture

    // ANCHOR: orbit
    /// The orbit camera's frame: it takes the camera over where it is,
    /// turning round the point of the lake it looks at (and again whenever
    /// something else moved it: a preset, "reset camera"), then the drag
    /// turns it and the wheel zooms. The camera keeps its optics.
    fn steer_orbit(&mut self, input: &Input) {
        let camera = self.camera;
        let here = (camera.position, camera.yaw, camera.pitch);
        let mut orbiting = match self.orbiting {
            Some(orbiting) if orbiting.placed == here => orbiting,
            _ => {
                let point = orbit_point(&camera, self.level, self.centre, self.size);
                Orbiting { orbit: LAKE_ORBIT.through(camera.position, point), point, placed: here }
            }
        };
        orbiting.orbit.steer(input.look, input.scroll);
        let placed = orbiting.orbit.camera(orbiting.point, camera.aspect);
        self.camera = Camera { position: placed.position, yaw: placed.yaw, pitch: placed.pitch, ..camera };
        orbiting.placed = (placed.position, placed.yaw, placed.pitch);
        self.orbiting = Some(orbiting);
    }
    // ANCHOR_END: orbit
}

/// The fly camera's keys (with walking), then the orbit camera's mouse.
const STEERING_KEYS: [(&str, &str); 9] = [
    ground::KEYS[0],
    ground::KEYS[1],
    ground::KEYS[2],
    ground::KEYS[3],
    ground::KEYS[4],
    ground::KEYS[5],
    ground::KEYS[6],
    ("drag (orbit camera)", "turn round the point on the lake"),
    ("scroll (orbit camera)", "nearer or further"),
];

impl Chapter for WaterChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0049; outliers at most 0.1%. Worst 16×16 patch 0.063 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.018, outliers: 0.002, patch: 0.2 };
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "07 · Water";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);
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
            Eye { plain: plain.viewpoint(device, samples), sky: sky.viewpoint(device, samples), drawn: None }
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
            Steering::Orbit => self.steer_orbit(input),
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
        // 1. The reflection: from below the water, keeping what is above it.
        if pictures && display != Display::Refraction {
            let above = Vec4::new(0.0, 1.0, 0.0, -self.level + bias);
            let targets = DrawnInto::Picture(&reflection.colour, &reflection.depth);
            let mirror = mirrored(&camera, self.level);
            let picture = self.take_picture(
                gpu,
                frame.encoder,
                frame.timer,
                ("reflection", REFLECTION),
                targets,
                &mirror,
                above,
                phase,
            );
            frame.drawn.add("reflection", picture);
        }
        // 2. The refraction: from the camera, keeping what is below the water.
        if pictures && display != Display::Reflection {
            let below = Vec4::new(0.0, -1.0, 0.0, self.level + bias);
            let targets = DrawnInto::Picture(&refraction.colour, &refraction.depth);
            let picture = self.take_picture(
                gpu,
                frame.encoder,
                frame.timer,
                ("refraction", REFRACTION),
                targets,
                &camera,
                below,
                phase,
            );
            frame.drawn.add("refraction", picture);
        }
        match display {
            Display::Reflection => return frame.drawn.add("show picture", self.water.show(frame, 0)),
            Display::Refraction => return frame.drawn.add("show picture", self.water.show(frame, 1)),
            Display::Lake => {}
        }

        // 3. The scene itself, whole.
        let scene = self.scene.clone();
        let targets = DrawnInto::Frame(&scene, frame.target);
        let picture = self.take_picture(
            gpu,
            frame.encoder,
            frame.timer,
            ("plain and sky", MAIN),
            targets,
            &camera,
            KEEP_ALL,
            phase,
        );
        frame.drawn.add("plain and sky", picture);

        // 4. The water on top, reading both pictures (or, in seed 003's style, its texture).
        self.water.aim(&gpu.queue, self.level, frame.time, &camera, self.settings.water);
        // Drawn on the scene's samples and depth as the main pass left
        // them, and resolved into the frame again.
        let mut pass = scene.pass(frame.encoder, frame.timer, "water surface", frame.target, None);
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

/// "rocks drawn: reflection 1,200 (5,000 triangles), …", for each of the
/// frame's pictures that was drawn and counted.
fn rocks_per_picture(drawn: [Option<RocksDrawn>; 3]) -> String {
    let names = [(REFLECTION, "reflection"), (REFRACTION, "refraction"), (MAIN, "plain and sky")];
    let pictures: Vec<String> = (names.iter())
        .filter_map(|&(eye, name)| {
            let drawn = drawn[eye]?;
            Some(format!("{name} {} ({} triangles)", thousands(drawn.rocks.into()), thousands(drawn.triangles as f64)))
        })
        .collect();
    format!("rocks drawn: {}", if pictures.is_empty() { "counting…".to_string() } else { pictures.join(", ") })
}

// ANCHOR: edit_waves
/// The overlay's controls for each of the eight waves, and a button that
/// puts back the lake's own. An edit goes through [`WaveSet::set`], which
/// refuses a wave the shader cannot draw (the sliders' ranges keep to
/// what it can); the view chosen next puts the lake's waves back.
fn edit_waves(ui: &mut egui::Ui, waves: &mut WaveSet) {
    for (index, wave) in waves.waves().into_iter().enumerate() {
        egui::CollapsingHeader::new(format!("wave {}", index + 1)).show(ui, |ui| {
            let mut edited = wave;
            let mut heading = wave.heading_degrees();
            let mut changed =
                ui.add(egui::Slider::new(&mut edited.amplitude, 0.0..=1.0).text("amplitude (m)")).changed();
            changed |= ui
                .add(egui::Slider::new(&mut edited.wavelength, 1.0..=100.0).logarithmic(true).text("wavelength (m)"))
                .changed();
            changed |= ui.add(egui::Slider::new(&mut edited.speed, 0.0..=12.0).text("speed (m/s)")).changed();
            if ui.add(egui::Slider::new(&mut heading, -180.0..=180.0).text("heading (° from east to north)")).changed()
            {
                edited = edited.heading(heading);
                changed = true;
            }
            if changed && let Err(reason) = waves.set(index, edited) {
                ui.colored_label(egui::Color32::RED, reason);
            }
        });
    }
    if ui.add_enabled(*waves != WaveSet::Lake, egui::Button::new("reset the waves")).clicked() {
        *waves = WaveSet::Lake;
    }
}
// ANCHOR_END: edit_waves

#[cfg(test)]
mod tests {
    use common::chapter::view_index;
    use common::headless::{OFFSCREEN_FORMAT, capture};

    use super::*;
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
