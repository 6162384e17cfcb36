//! The chapter itself: the settings each view applies, the views, the
//! orbit camera and the day's clock, who sails (the course or the keys),
//! and `impl Chapter`, which composes this chapter's diagram, water, sea,
//! sky, islands and sail with chapter 08's lights and post chain, chapter
//! 09's boat and chapter 10's shadow map into a frame.

use common::glam::Vec3;
use common::{
    Camera, Chapter, Frame, Gpu, Input, Orbit, Preparation, Target, View, ViewRow, anyhow, egui, views_of, wgpu,
    winit::keyboard::KeyCode,
};
use lighting::bloom::BloomSettings;
use lighting::{Highlight, LoopOptions, PostChain, PostOutput, PostSettings, SceneLights};
use shadows::ShadowedRenderer;
use shadows::shadow_map::{Filter, MapView, ShadowMap, ShadowSettings, fit_light};
use textures::materials::{Materials, Uploader};
use textures::mesh::{GpuModel, ModelInstance};
use textures::mipmaps::MipMaker;
use textures::{Draw, DrawList, obj, upload_model};

use crate::atmosphere::{self, Atmosphere, DAY_SECONDS, Sky};
use crate::boat::{self, Helm, Orders, Pose};
use crate::islands::IslandRenderer;
use crate::sail::{self, Rig};
use crate::sea::{self, SeaRenderer, SeaSettings};
use crate::sites;
use crate::voronoi::{Method, Voronoi, VoronoiSettings};
use crate::water_texture::{self, Picture, Processing, WaterTexture};

// ANCHOR: views
/// Every view, once: what it shows, and for a preset where the camera goes.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 26] = [
    ViewRow::preset(
        "default",
        "sunset: the boat sails into the sun over the Voronoi sea",
        Settings::SUNSET,
        CameraPreset::Sunset,
    ),
    ViewRow::mode(
        "noon",
        "the same sea at noon, the sun 60° high",
        Settings { day_start: 0.5 - SNAPSHOT_TIME / DAY_SECONDS, ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "night",
        "night: the moon's light, the sky from the gradient's dark end",
        Settings { day_start: 0.95 - SNAPSHOT_TIME / DAY_SECONDS, ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "voronoi",
        "the raw diagram by cones of 8 segments, a hue per cell, tiled 1.5 times down",
        Settings::diagram(Method::Cones, sites::DEFAULT_COUNT, 512),
    ),
    ViewRow::mode(
        "blurred",
        "the cells in the sea's shades, box-blurred twice",
        Settings { show: Show::Picture(Picture::Blurred), ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "edges",
        "Sobel's edges of the blurred cells: the lines of foam",
        Settings { show: Show::Picture(Picture::Edges), ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "cells",
        "an id buffer: each pixel's nearest site as red = i % 256, green = i / 256",
        Settings {
            voronoi: VoronoiSettings { method: Method::ExactCones, ..VoronoiSettings::DEFAULT },
            show: Show::Cells,
            ..Settings::SUNSET
        },
    ),
    ViewRow::mode(
        "jfa",
        "the raw diagram by jump flooding, a hue per cell",
        Settings::diagram(Method::JumpFlooding, sites::DEFAULT_COUNT, 512),
    ),
    ViewRow::mode(
        "shadow-map",
        "the sun's depth, fitted tightly around the boat",
        Settings { show: Show::ShadowMap, ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "bloom-only",
        "what bloom adds: the sun and the glints on the water",
        Settings { show: Show::BloomOnly, ..Settings::SUNSET },
    ),
    ViewRow::preset(
        "grid",
        "the sea's grid as wires, seen from high up: it follows the boat",
        Settings { wires: true, ..Settings::SUNSET },
        CameraPreset::High,
    ),
    ViewRow::mode(
        "small-grid",
        "the seed's magic carpet: a grid of 24 m, three boat lengths",
        Settings { small_grid: true, ..Settings::SUNSET },
    ),
    ViewRow::preset(
        "sail",
        "close by the boat's side: the sail filled by the wind, the sailor at the helm",
        Settings::SUNSET,
        CameraPreset::Sail,
    ),
    ViewRow::no_aa_from("default", Settings::SUNSET, CameraPreset::Sunset),
    ViewRow::bench("cones-64-512", "64 sites by cones at 512²", Settings::diagram(Method::Cones, 64, 512)),
    ViewRow::bench("jfa-64-512", "64 sites by jump flooding at 512²", Settings::diagram(Method::JumpFlooding, 64, 512)),
    ViewRow::bench("cones-1024-512", "1,024 sites by cones at 512²", Settings::diagram(Method::Cones, 1024, 512)),
    ViewRow::bench(
        "jfa-1024-512",
        "1,024 sites by jump flooding at 512²",
        Settings::diagram(Method::JumpFlooding, 1024, 512),
    ),
    ViewRow::bench("cones-16384-512", "16,384 sites by cones at 512²", Settings::diagram(Method::Cones, 16384, 512)),
    ViewRow::bench(
        "jfa-16384-512",
        "16,384 sites by jump flooding at 512²",
        Settings::diagram(Method::JumpFlooding, 16384, 512),
    ),
    ViewRow::bench("cones-64-1024", "64 sites by cones at 1024²", Settings::diagram(Method::Cones, 64, 1024)),
    ViewRow::bench(
        "jfa-64-1024",
        "64 sites by jump flooding at 1024²",
        Settings::diagram(Method::JumpFlooding, 64, 1024),
    ),
    ViewRow::bench("cones-1024-1024", "1,024 sites by cones at 1024²", Settings::diagram(Method::Cones, 1024, 1024)),
    ViewRow::bench(
        "jfa-1024-1024",
        "1,024 sites by jump flooding at 1024²",
        Settings::diagram(Method::JumpFlooding, 1024, 1024),
    ),
    ViewRow::bench("cones-16384-1024", "16,384 sites by cones at 1024²", Settings::diagram(Method::Cones, 16384, 1024)),
    ViewRow::bench(
        "jfa-16384-1024",
        "16,384 sites by jump flooding at 1024²",
        Settings::diagram(Method::JumpFlooding, 16384, 1024),
    ),
];

/// Where a preset puts the orbit camera; a mode leaves it, and "reset
/// camera" takes it back to [`SUNSET_ORBIT`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// [`SUNSET_ORBIT`]: behind the boat, into the sunset.
    Sunset,
    /// [`HIGH_ORBIT`]: high over the boat, to see the grid.
    High,
    /// [`SAIL_ORBIT`]: beside the boat, on the side its sail fills towards.
    Sail,
}
// ANCHOR_END: views

/// What the frame shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Show {
    /// The sea, the boat, the sky.
    Scene,
    /// A picture of the water texture's chain, full screen.
    Picture(Picture),
    /// The diagram's ids at the target's size, exactly.
    Cells,
    /// The shadow map, full screen.
    ShadowMap,
    /// What bloom adds, alone.
    BloomOnly,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub voronoi: VoronoiSettings,
    /// Sites in the diagram.
    pub sites: u32,
    /// The water texture's side, texels.
    pub texture_size: u32,
    pub processing: Processing,
    pub show: Show,
    /// The time of day at scene time 0 (0.25 sunrise, 0.5 noon, 0.75 sunset).
    pub day_start: f32,
    /// The day moves on with scene time, a day every [`DAY_SECONDS`].
    pub day_runs: bool,
    /// The grid moves in whole cells (off: by fractions, and the waves swim).
    pub snap_grid: bool,
    pub small_grid: bool,
    pub wires: bool,
    pub textured_sea: bool,
    pub shadows: bool,
    pub bloom: bool,
}

/// Scene time of the snapshots, seconds.
pub const SNAPSHOT_TIME: f32 = 20.0;

impl Settings {
    /// Sunset over the Voronoi sea: what the chapter starts with.
    pub const SUNSET: Self = Self {
        voronoi: VoronoiSettings::DEFAULT,
        sites: sites::DEFAULT_COUNT,
        texture_size: 512,
        processing: Processing::DEFAULT,
        show: Show::Scene,
        // At the snapshot time the sun stands 4.6° above the horizon.
        day_start: 0.735 - SNAPSHOT_TIME / DAY_SECONDS,
        day_runs: true,
        snap_grid: true,
        small_grid: false,
        wires: false,
        textured_sea: true,
        shadows: true,
        bloom: true,
    };

    /// The raw diagram of `sites` sites by `method` in a texture
    /// `texture_size` texels wide, a hue per cell, full screen.
    pub const fn diagram(method: Method, sites: u32, texture_size: u32) -> Self {
        Self {
            voronoi: VoronoiSettings { method, ..VoronoiSettings::DEFAULT },
            sites,
            texture_size,
            processing: Processing { water_colours: false, ..Processing::DEFAULT },
            show: Show::Picture(Picture::Colours),
            ..Self::SUNSET
        }
    }
}

// ANCHOR: orbit
/// The camera circles the boat (`common::Orbit`): from just above the
/// water to nearly overhead, 10 to 400 m away.
const ROUND_THE_BOAT: Orbit = Orbit::new(1.95, 0.22, 26.0).within((0.02, 1.5), (10.0, 400.0));
/// From behind the boat's left, looking west into the sunset.
pub const SUNSET_ORBIT: Orbit = ROUND_THE_BOAT;
/// High over the boat, to see the grid.
pub const HIGH_ORBIT: Orbit = Orbit { pitch: 1.2, distance: 110.0, ..ROUND_THE_BOAT };
/// Close by the boat's port quarter at the snapshot time, when the wind
/// fills the sail towards that side (a test checks both).
pub const SAIL_ORBIT: Orbit = Orbit { yaw: 0.45, pitch: 0.1, distance: 12.5, ..ROUND_THE_BOAT };

/// The camera looking at a point 2 m above `boat` from `orbit`.
pub fn orbit_camera(orbit: &Orbit, boat: Vec3, aspect: f32) -> Camera {
    Camera { near: 0.5, far: 2000.0, ..orbit.camera(boat + Vec3::Y * 2.0, aspect) }
}
// ANCHOR_END: orbit

// ANCHOR: clock
/// The day's clock: the phase follows scene time unless frozen (Space);
/// holding Q or E runs it backwards or forwards.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DayClock {
    /// Phase added by Q and E.
    pub shift: f32,
    /// The phase it was frozen at.
    pub frozen: Option<f32>,
}

impl DayClock {
    /// The phase of the day, 0..1, at scene time `time`.
    pub fn phase(&self, settings: &Settings, time: f32) -> f32 {
        let running = if settings.day_runs { time.rem_euclid(DAY_SECONDS) / DAY_SECONDS } else { 0.0 };
        self.frozen.unwrap_or(settings.day_start + self.shift + running).rem_euclid(1.0)
    }
}
// ANCHOR_END: clock

/// Who sails: the course (pictures, and a window until a key is pressed)
/// or the keys.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Play {
    Course,
    Keys(Helm),
}

/// The orders the keys give this frame.
pub fn orders_from(input: &Input) -> Orders {
    Orders {
        ahead: input.held(KeyCode::KeyW),
        astern: input.held(KeyCode::KeyS),
        left: input.held(KeyCode::KeyA),
        right: input.held(KeyCode::KeyD),
    }
}

pub struct VoronoiWaterChapter {
    pub settings: Settings,
    pub orbit: Orbit,
    pub clock: DayClock,
    pub play: Play,
    /// The last frame's scene time, for freezing the clock where it is.
    last_time: f32,
    pub voronoi: Voronoi,
    pub water: WaterTexture,
    show: water_texture::Show,
    pub sea: SeaRenderer,
    islands: IslandRenderer,
    sky: Sky,
    pub atmosphere: Atmosphere,
    pub scene_lights: SceneLights,
    pub shadow_map: ShadowMap,
    map_view: MapView,
    boat_renderer: ShadowedRenderer,
    materials: Materials,
    boat: GpuModel,
    /// The sail as made (flat) and the sailor, on the CPU: the sail is
    /// bent from it every frame.
    pub rig: Rig,
    sail: GpuModel,
    sailor: GpuModel,
    boat_instance: wgpu::Buffer,
    post: PostChain,
    target: Target,
}

impl VoronoiWaterChapter {
    /// Where the boat is at scene time `time`.
    pub fn helm_at(&self, time: f32) -> Helm {
        match self.play {
            Play::Course => boat::on_course(time),
            Play::Keys(helm) => helm,
        }
    }

    /// The boat's pose on the waves at `time`.
    pub fn pose_at(&self, time: f32) -> Pose {
        boat::float_on(self.sea.waves(), self.helm_at(time), time)
    }

    // ANCHOR: shadow_focus
    /// What the sun's box must hold: the boat's corners, and where their
    /// shadows can fall on the water, at most 40 m away (a low sun's
    /// shadows run long; beyond that, they are lost in the glare).
    fn shadow_focus(&self, pose: &Pose, towards_light: Vec3) -> (Vec<Vec3>, (Vec3, Vec3)) {
        let model = pose.model();
        let corners: Vec<Vec3> = (0..8)
            .map(|i| {
                let x = if i & 1 == 0 { -boat::BEAM / 2.0 } else { boat::BEAM / 2.0 };
                let y = if i & 2 == 0 { 0.0 } else { boat::MAST_TOP };
                let z = if i & 4 == 0 { -boat::LENGTH / 2.0 } else { boat::LENGTH / 2.0 };
                model.transform_point3(Vec3::new(x, y, z))
            })
            .collect();
        let bounds = corners.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        // The lowest the water goes: every wave in a trough at once.
        let lowest = -self.sea.waves().iter().map(|w| w.amplitude).sum::<f32>();
        let mut focus = corners.clone();
        for c in &corners {
            let run = ((c.y - lowest) / towards_light.y.max(1e-3)).min(40.0);
            focus.push(*c - towards_light * run);
        }
        (focus, bounds)
    }
    // ANCHOR_END: shadow_focus
}

/// The boat and its textures: the only files of chapter 09's this chapter
/// embeds, so that the browser downloads no more than it draws.
const BOAT_FILES: &[(&str, &[u8])] = textures::builtin![
    "models/boat/boat.obj",
    "models/boat/boat.mtl",
    "textures/metal/albedo.png",
    "textures/metal/normal.png",
];

/// A file the chapter carries (the boat's, or the sail's and the
/// sailor's), by its path under `assets/`.
fn read_builtin(path: &std::path::Path) -> Result<Vec<u8>, common::files::ReadError> {
    textures::builtin::find(BOAT_FILES, path).or_else(|_| sail::read_builtin(path))
}

impl Chapter for VoronoiWaterChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0091: foam lines are one pixel wide; outliers at most 0.1%. Worst 16×16 patch 0.171 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.042, outliers: 0.002, patch: 0.25 };
    const TITLE: &'static str = "11 · Voronoi water";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);
    const POST_ANTIALIASING: bool = true;
    const SNAPSHOT_TIME: f32 = SNAPSHOT_TIME;
    const BENCH_FRAMES: u32 = 10;
    const BENCH_BASELINE: Option<&'static str> = Some("cones-64-512");
    const MAIN_SHADER: Option<&'static str> = Some("voronoi-water/sea.wgsl");
    const KEYS: &'static [(&'static str, &'static str)] = &[
        ("W S", "ahead, astern (the first key takes over from the course)"),
        ("A D", "turn"),
        ("drag, wheel", "circle the boat, zoom"),
        ("Space", "freeze the day"),
        ("Q / E (held)", "run the day backwards / forwards"),
    ];

    fn gpu_needs() -> common::GpuNeeds {
        common::GpuNeeds {
            required: wgpu::Features::empty(),
            optional: PostChain::OPTIONAL_FEATURES,
            downlevel: lighting::scene_lights::DOWNLEVEL,
        }
    }

    /// Nothing takes long enough to prepare in steps.
    type Prepared = ();

    fn prepare(_gpu: &Gpu) -> Preparation<()> {
        Preparation::ready(())
    }

    fn new(gpu: &Gpu, target: Target, (): ()) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let settings = Settings::SUNSET;
        let post = PostChain::new(gpu, target)?;
        let multisample = post.hdr().multisample();
        let voronoi = Voronoi::new(gpu, settings.texture_size, settings.texture_size)?;
        let water = WaterTexture::new(gpu, settings.texture_size)?;
        let show = water_texture::Show::new(gpu, &water, target.format)?;
        let atmosphere = Atmosphere::new(gpu)?;
        let scene_lights = SceneLights::new(gpu)?;
        let shadow_map = ShadowMap::new(gpu, 1024)?;
        let sea = SeaRenderer::new(gpu, &scene_lights, &atmosphere, &shadow_map, sea::sea_waves(), multisample)?;
        let islands = IslandRenderer::new(gpu, &scene_lights, &atmosphere, multisample)?;
        let sky = Sky::new(gpu, &scene_lights.layout, &atmosphere, multisample)?;
        // The boat: chapter 09's model, materials and loader.
        let loaded = obj::load(std::path::Path::new("models/boat/boat.obj"), &read_builtin)?;
        // Its sail and sailor: two more models, through the same loader.
        let rig = sail::load(&sail::read_builtin)?;
        for warning in loaded.warnings.iter().chain(&rig.warnings) {
            eprintln!("warning: {warning}");
        }
        let mut mips = MipMaker::new(gpu)?;
        let mut up = Uploader::new(gpu, &mut mips, &read_builtin);
        let mut materials = Materials::new(&mut up);
        let boat = upload_model(&mut up, &mut materials, &loaded.model, "boat");
        let sail = upload_model(&mut up, &mut materials, &rig.sail, "sail");
        let sailor = upload_model(&mut up, &mut materials, &rig.sailor, "sailor");
        up.finish();
        let boat_renderer = ShadowedRenderer::new(gpu, &scene_lights, &materials, &shadow_map, multisample)?;
        let boat_instance = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("boat"),
            size: std::mem::size_of::<ModelInstance>() as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Ok(Self {
            settings,
            orbit: SUNSET_ORBIT,
            clock: DayClock::default(),
            play: Play::Course,
            last_time: 0.0,
            voronoi,
            water,
            show,
            sea,
            islands,
            sky,
            atmosphere,
            scene_lights,
            shadow_map,
            map_view: MapView::new(gpu, target.format)?,
            boat_renderer,
            materials,
            boat,
            rig,
            sail,
            sailor,
            boat_instance,
            post,
            target,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.post.resize(gpu, target);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
        self.clock = DayClock::default();
    }

    fn reset_camera(&mut self, view: usize) {
        self.orbit = match VIEW_TABLE[view].camera {
            Some(CameraPreset::High) => HIGH_ORBIT,
            Some(CameraPreset::Sail) => SAIL_ORBIT,
            Some(CameraPreset::Sunset) | None => SUNSET_ORBIT,
        };
    }

    // ANCHOR: update
    fn update(&mut self, input: &Input, dt: f32) {
        let orders = orders_from(input);
        if self.play == Play::Course && (orders.ahead || orders.astern || orders.left || orders.right) {
            self.play = Play::Keys(boat::on_course(self.last_time));
        }
        if let Play::Keys(helm) = &mut self.play {
            helm.steer(orders, dt);
        }
        self.orbit.steer(input.look, input.scroll);
        if input.pressed(KeyCode::Space) {
            let phase = self.clock.phase(&self.settings, self.last_time);
            match self.clock.frozen.take() {
                // Go on from where it stands: shift the running clock there.
                Some(_) => self.clock.shift += phase - self.clock.phase(&self.settings, self.last_time),
                None => self.clock.frozen = Some(phase),
            }
        }
        // Q and E: a whole day in twelve seconds of holding.
        let dt = if dt.is_finite() { dt.clamp(0.0, 0.25) } else { 0.0 };
        let run = (f32::from(u8::from(input.held(KeyCode::KeyE))) - f32::from(u8::from(input.held(KeyCode::KeyQ))))
            * dt
            / 12.0;
        match &mut self.clock.frozen {
            Some(frozen) => *frozen = (*frozen + run).rem_euclid(1.0),
            None => self.clock.shift = (self.clock.shift + run).rem_euclid(1.0),
        }
    }
    // ANCHOR_END: update

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        let s = self.settings;
        let time = frame.time;
        self.last_time = time;

        // The diagram of this moment's sites: at the target's size for the
        // exact `cells` view, else at the texture's.
        let sites = sites::wandering(s.sites, sites::DEFAULT_SEED, time);
        if s.show == Show::Cells {
            let size = (self.target.width, self.target.height);
            frame.drawn.extend([self.voronoi.render(gpu, frame.encoder, frame.timer, &sites, size, &s.voronoi)]);
            self.show.cells(gpu, frame, &self.water, self.voronoi.ids());
            return;
        }
        let size = s.texture_size;
        frame.drawn.extend([self.voronoi.render(gpu, frame.encoder, frame.timer, &sites, (size, size), &s.voronoi)]);
        frame.drawn.extend(self.water.render(gpu, frame.encoder, frame.timer, self.voronoi.ids(), size, &s.processing));
        if let Show::Picture(picture) = s.show {
            self.show.picture(gpu, frame, &self.water, picture, self.target.aspect(), 1.5);
            return;
        }

        // The boat on the waves, the camera around it, the sun over it.
        let pose = self.pose_at(time);
        let boat_at = Vec3::new(pose.helm.position.x, pose.heave, pose.helm.position.y);
        let camera = orbit_camera(&self.orbit, boat_at, self.target.aspect());
        let towards_sun = atmosphere::sun_direction(self.clock.phase(&s, time));
        let day = self.atmosphere.gradients.daylight(towards_sun);
        self.atmosphere.write(gpu, &camera, towards_sun);
        let options = LoopOptions { culling: false, highlight: Highlight::BlinnPhong, heat_map: false };
        self.scene_lights.write(gpu, &camera, &day, &[], &Default::default(), options);

        // The boat's shadow: the sun's box fitted tightly around it.
        let shadow = ShadowSettings {
            size: 1024,
            filter: if s.shadows { Filter::Pcf3x3 } else { Filter::Off },
            ..Default::default()
        };
        let (focus, bounds) = self.shadow_focus(&pose, day.direction);
        let light = fit_light(day.direction, &focus, bounds, self.shadow_map.size);
        self.shadow_map.write(gpu, &light, &shadow);
        // ANCHOR: rig_draw
        // The sail filled by the wind across it; the boat, the sail and the
        // sailor all placed by the boat's one instance, its model matrix.
        let across = sail::wind_across(pose.helm.heading, sail::wind());
        gpu.queue.write_buffer(&self.sail.vertices, 0, bytemuck::cast_slice(&self.rig.bent_sail(across)));
        gpu.queue.write_buffer(&self.boat_instance, 0, bytemuck::bytes_of(&ModelInstance::new(pose.model(), 0.0)));
        let list = DrawList {
            materials: &self.materials,
            instances: &self.boat_instance,
            draws: [&self.boat, &self.sail, &self.sailor]
                .into_iter()
                .map(|model| Draw { model, instances: 0..1 })
                .collect(),
        };
        // ANCHOR_END: rig_draw
        frame.drawn.extend([self.shadow_map.render(gpu, frame.encoder, frame.timer, &shadow, &list)]);
        if s.show == Show::ShadowMap {
            // Depths stretched over the boat's (its first eight points).
            let depths = focus.iter().take(8).map(|p| light.view_proj.project_point3(*p).z);
            let range = depths.fold((f32::MAX, f32::MIN), |(lo, hi), z| (lo.min(z), hi.max(z)));
            self.map_view.draw(gpu, frame, &self.shadow_map, range, self.target.aspect());
            return;
        }

        // The scene: sky, islands, sea, boat, into HDR.
        let origin = sea::grid_origin(pose.helm.position, s.snap_grid);
        self.sea.write(gpu, self.water.water(), &SeaSettings { origin, time, textured: s.textured_sea });
        self.islands.write(gpu, pose.helm.position);
        {
            let mut pass = self.post.hdr().pass(frame.encoder, frame.timer, "scene", wgpu::Color::BLACK);
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            let mut drawn = self.sky.draw(&mut pass, &self.atmosphere);
            drawn += self.islands.draw(&mut pass, &self.atmosphere);
            pass.set_bind_group(3, &self.shadow_map.group, &[]);
            drawn += self.sea.draw(&mut pass, s.small_grid, s.wires);
            drawn += self.boat_renderer.draw(&mut pass, &self.shadow_map, &list, false);
            frame.drawn.add("scene", drawn);
        }
        let output = if s.show == Show::BloomOnly { PostOutput::BloomOnly } else { PostOutput::Picture };
        let bloom = (s.bloom || output == PostOutput::BloomOnly).then(BloomSettings::default);
        self.post.finish(gpu, frame, &PostSettings { output, exposure: 1.0, bloom });
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        if let Play::Keys(_) = self.play
            && ui.button("back to the course").clicked()
        {
            self.play = Play::Course;
        }
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            ui.label("show");
            ui.radio_value(&mut s.show, Show::Scene, "the sea");
            ui.radio_value(&mut s.show, Show::Picture(Picture::Colours), "cells");
            ui.radio_value(&mut s.show, Show::Picture(Picture::Blurred), "blurred");
            ui.radio_value(&mut s.show, Show::Picture(Picture::Edges), "edges");
            ui.radio_value(&mut s.show, Show::Picture(Picture::Water), "water texture");
            ui.radio_value(&mut s.show, Show::Cells, "ids");
            ui.radio_value(&mut s.show, Show::ShadowMap, "shadow map");
            ui.radio_value(&mut s.show, Show::BloomOnly, "bloom");
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("diagram by");
            for method in [Method::Cones, Method::ExactCones, Method::JumpFlooding] {
                ui.radio_value(&mut s.voronoi.method, method, method.label());
            }
        });
        ui.add(egui::Slider::new(&mut s.sites, 1..=sites::MAX_COUNT).logarithmic(true).text("sites"));
        ui.add(egui::Slider::new(&mut s.voronoi.segments, 3..=64).text("cone segments"));
        ui.add(egui::Slider::new(&mut s.voronoi.radius_scale, 0.2..=1.5).text("cone radius (× covering radius)"));
        ui.checkbox(&mut s.voronoi.tile_copies, "draw each site at the 8 neighbouring tiles too");
        ui.checkbox(&mut s.voronoi.extra_pass, "JFA+1 (one more pass of step 1)");
        ui.horizontal(|ui| {
            ui.checkbox(&mut s.processing.water_colours, "water colours");
            ui.add(egui::Slider::new(&mut s.processing.blur_radius, 0..=12).text("blur radius"));
            ui.checkbox(&mut s.processing.edges, "foam");
        });
        ui.horizontal(|ui| {
            ui.label("texture");
            for size in [256, 512, 1024] {
                ui.radio_value(&mut s.texture_size, size, format!("{size}²"));
            }
        });
        ui.checkbox(&mut s.snap_grid, "grid moves in whole cells (off: the waves swim)");
        ui.checkbox(&mut s.small_grid, "small grid (the seed's magic carpet)");
        ui.checkbox(&mut s.wires, "grid wires");
        ui.checkbox(&mut s.textured_sea, "Voronoi texture on the sea");
        ui.checkbox(&mut s.shadows, "the boat's shadow");
        ui.checkbox(&mut s.bloom, "bloom");
        ui.checkbox(&mut s.day_runs, "the day runs with time");
        ui.label(format!(
            "cone radius {:.4} tiles; time of day {:.3}{}",
            self.voronoi.cone_radius,
            self.clock.phase(s, self.last_time),
            if self.clock.frozen.is_some() { " (frozen: Space)" } else { "" }
        ));
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        let (w, h) = self.voronoi.size();
        format!(
            "{} sites by {} at {w}×{h}, cone radius {:.4} tiles",
            self.settings.sites,
            self.settings.voronoi.method.label(),
            self.voronoi.cone_radius
        )
    }
}

#[cfg(test)]
mod tests {
    use common::glam::Vec2;

    use super::*;

    #[test]
    fn the_sail_view_looks_at_the_side_the_sail_fills_towards() {
        let heading = boat::on_course(SNAPSHOT_TIME).heading;
        let across = sail::wind_across(heading, sail::wind());
        assert!(across.abs() > 0.5, "at the snapshot the wind is only {across} across the sail");
        let ahead = boat::forward(heading);
        let filled_side = Vec2::new(-ahead.y, ahead.x) * across.signum();
        let back = SAIL_ORBIT.back();
        let eye = Vec2::new(back.x, back.z).normalize();
        // Within 45° of that side: the belly faces the eye.
        let off = eye.angle_to(filled_side).abs().to_degrees();
        assert!(off < 45.0, "the eye is {off}° off the side the sail fills to");
    }
}
