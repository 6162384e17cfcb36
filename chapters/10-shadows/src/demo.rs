//! The chapter itself: the settings each view applies, the views, the side
//! camera and the part of the level it sees, who plays (the script or the
//! keys), and `impl Chapter`, which renders the sun's shadow map and the
//! lantern's cube, then the level through the shadowed renderer, then
//! chapter 08's post chain.

use std::path::Path;

use common::args::UsageError;
use common::glam::{Mat4, Vec2, Vec3, Vec4};
use common::{
    Camera, Chapter, ChapterFlag, FlagValues, Frame, Gpu, Input, Preparation, Target, View, ViewRow, anyhow, egui,
    views_of, wgpu, winit::keyboard::KeyCode,
};
use lighting::bloom::BloomSettings;
use lighting::lights::{Daylight, Light};
use lighting::{CitySky, Highlight, LoopOptions, PostChain, PostOutput, PostSettings, SceneLights};
use textures::materials::{Materials, Uploader};
use textures::mesh::{GpuModel, ModelInstance};
use textures::mipmaps::MipMaker;
use textures::{Draw, DrawList, obj, upload_model};

use crate::game::{self, Controls, Game, Level, PropKind};
use crate::lines::{LineList, Lines};
use crate::parallax::Parallax;
use crate::physics;
use crate::point_shadow::{self, CubeCost, CubeView, PointFilter, PointShadow, PointShadowSettings};
use crate::scene;
use crate::shadow_map::{self, Bias, Cull, Filter, LightBox, ShadowMap, ShadowSettings, fit_light};
use crate::shadowed_renderer::ShadowedRenderer;

// ANCHOR: views
/// Every view, once, with what it shows. All but `lantern` are modes: the
/// side camera follows the player whatever the view.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 16] = [
    ViewRow::mode(
        "default",
        "the game mid-jump, with soft shadows that harden where they touch (PCSS)",
        Settings::DEFAULT,
    ),
    // The filters side by side, on a 512² map (texels of 8.8 cm), seen
    // from close up: big enough to see what each filter does to them.
    ViewRow::mode(
        "hard",
        "one comparison per pixel: the shadow map's texels are the shadow's edge",
        Settings::close_up(Filter::Hard),
    ),
    ViewRow::mode(
        "pcf-3x3",
        "nine comparisons a texel apart, averaged: a soft edge one texel wide",
        Settings::close_up(Filter::Pcf3x3),
    ),
    ViewRow::mode(
        "poisson",
        "sixteen comparisons on a Poisson disk, turned per pixel: the seed's filter",
        Settings::close_up(Filter::Poisson),
    ),
    ViewRow::mode("acne", "no bias: lit surfaces shadow themselves in stripes", Settings::hard_with(Bias::NONE)),
    ViewRow::mode(
        "peter-panning",
        "far too much bias: shadows come loose from what casts them",
        Settings::hard_with(Bias::TOO_MUCH),
    ),
    ViewRow::mode(
        "shadow-map",
        "the sun's depth, full screen: near the sun dark, far light",
        Settings { show: Show::ShadowMap, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "lantern",
        "the lantern in the tunnel at nightfall: its light stops at the ceiling, and the rock casts a shadow",
        Settings::LANTERN,
        CameraPreset::Lantern,
    ),
    ViewRow::mode(
        "cube-shadow-map",
        "the lantern's six shadow-map faces unfolded in a cross: near the light dark, far light",
        Settings { show: Show::CubeMap, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "light-frustum",
        "the sun's box (yellow) around the part of the level the camera sees (cyan)",
        Settings { light_box: true, camera_distance: 60.0, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "collision-boxes",
        "the boxes the physics works with, drawn over the scene",
        Settings { collision_boxes: true, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "parallax",
        "the background layers tinted by depth: red near, green middle, blue far",
        Settings { tint_layers: true, ..Settings::DEFAULT },
    ),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::bench("map-1024", "Poisson filtering with a 1024² shadow map", Settings::filtered(Filter::Poisson, 1024)),
    ViewRow::bench("map-4096", "Poisson filtering with a 4096² shadow map", Settings::filtered(Filter::Poisson, 4096)),
    ViewRow::bench(
        "no-shadows",
        "no lookup at all, nor the lantern's cube: what the filters are measured against",
        Settings { lantern: PointShadowSettings::OFF, ..Settings::filtered(Filter::Off, shadow_map::DEFAULT_SIZE) },
    ),
];

/// Where a preset puts the camera instead of behind the player.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// In front of the tunnel, looking at the lantern ([`lantern_camera`]).
    Lantern,
}
// ANCHOR_END: views

/// What the camera shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Show {
    /// The lit scene.
    Scene,
    /// The shadow map, full screen.
    ShadowMap,
    /// How much sun reaches each pixel (red), whether its surface faces
    /// the sun (green) and how much of the lantern's light arrives (blue),
    /// unlit: what the shadow tests count.
    Sunlit,
    /// The lantern's cube shadow map, unfolded, full screen.
    CubeMap,
}

/// What the sun's box is fitted to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fit {
    /// The part of the level the camera sees.
    Visible,
    /// The whole level: simpler, and every texel three times as coarse.
    WholeLevel,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub shadow: ShadowSettings,
    /// The lantern's cube shadow map.
    pub lantern: PointShadowSettings,
    pub fit: Fit,
    /// The time of day as a phase (0.25 sunrise, 0.5 noon, 0.75 sunset).
    pub phase: f32,
    /// Whether the sun moves on by itself, a day every [`DAY_SECONDS`].
    pub sun_moves: bool,
    pub show: Show,
    pub collision_boxes: bool,
    pub light_box: bool,
    pub tint_layers: bool,
    /// How far behind the level the camera stands, metres.
    pub camera_distance: f32,
    pub bloom: bool,
}

impl Settings {
    /// The game mid-jump in soft shadows: what the chapter starts with.
    pub const DEFAULT: Self = Self {
        shadow: ShadowSettings { filter: Filter::Pcss, ..ShadowSettings::DEFAULT },
        lantern: PointShadowSettings::DEFAULT,
        fit: Fit::Visible,
        // Nine in the morning: the sun 35° high, on the left, in front.
        phase: 0.375,
        sun_moves: false,
        show: Show::Scene,
        collision_boxes: false,
        light_box: false,
        tint_layers: false,
        camera_distance: CAMERA_DISTANCE,
        bloom: true,
    };

    /// The `lantern` view: the default scene at nightfall, when the
    /// lantern is the only light.
    pub const LANTERN: Self = Self { phase: 0.8, ..Self::DEFAULT };

    /// The default scene with the shadow map looked up by `filter` in a
    /// `size`² map.
    pub const fn filtered(filter: Filter, size: u32) -> Self {
        Self { shadow: ShadowSettings { filter, size, ..Self::DEFAULT.shadow }, ..Self::DEFAULT }
    }

    /// The scene with a 512² map looked up by `filter`, seen from
    /// [`CLOSE_UP_DISTANCE`]: the sun's box is still fitted to the game's
    /// camera, so its texels are as large as in the game, and large on screen.
    pub const fn close_up(filter: Filter) -> Self {
        Self { camera_distance: CLOSE_UP_DISTANCE, ..Self::filtered(filter, 512) }
    }

    /// The default scene with hard shadows and `bias`.
    pub const fn hard_with(bias: Bias) -> Self {
        Self { shadow: ShadowSettings { filter: Filter::Hard, bias, ..Self::DEFAULT.shadow }, ..Self::DEFAULT }
    }
}

// ANCHOR: camera
/// How far in front of the level the camera stands, metres.
pub const CAMERA_DISTANCE: f32 = 11.0;
/// Where the filter views' camera stands instead, metres.
pub const CLOSE_UP_DISTANCE: f32 = 4.0;

/// The side camera: `distance` in front of the level's middle (z = 0),
/// looking down at the player at about 17°, so that the ground where
/// shadows fall shows.
pub fn side_camera(player: Vec2, distance: f32, aspect: f32) -> Camera {
    let eye = Vec3::new(player.x, player.y + 0.3 * distance, distance);
    Camera { near: 0.5, far: 400.0, ..Camera::looking_at(eye, Vec3::new(player.x, player.y, 0.0), aspect) }
}

/// The part of the level the camera sees: where the corners of its view
/// cross the level's front and back faces (z = ±`half_depth`). The sun's
/// box is fitted around these eight points.
pub fn visible_part(camera: &Camera, half_depth: f32) -> [Vec3; 8] {
    let inverse = camera.view_projection().inverse();
    std::array::from_fn(|i| {
        let ndc = Vec3::new(if i & 1 == 0 { -1.0 } else { 1.0 }, if i & 2 == 0 { -1.0 } else { 1.0 }, 1.0);
        let far = inverse.project_point3(ndc);
        let z = if i & 4 == 0 { half_depth } else { -half_depth };
        let t = (z - camera.position.z) / (far.z - camera.position.z);
        camera.position + (far - camera.position) * t
    })
}

/// The `lantern` view's camera: in front of the tunnel, right of the
/// lantern and a little above it, looking down past it at the ground its
/// light falls on.
pub fn lantern_camera(lantern: Vec3, aspect: f32) -> Camera {
    let eye = lantern + Vec3::new(2.6, -0.35, 6.2);
    Camera { near: 0.1, far: 400.0, ..Camera::looking_at(eye, lantern + Vec3::new(0.2, -0.5, 0.0), aspect) }
}
// ANCHOR_END: camera

/// The models the level is drawn with, in the order the draws number
/// them: the level, one per prop kind ([`PropKind::ALL`]), the lantern,
/// the player.
struct Models {
    level: GpuModel,
    props: Vec<GpuModel>,
    lantern: GpuModel,
    player: GpuModel,
}

/// The lantern's place in the models' order: the one model its own cube
/// leaves out, since its light is inside it.
pub const LANTERN_MODEL: usize = 1 + PropKind::ALL.len();

// ANCHOR: play
/// Who plays: the script (pictures, and a window until a key is pressed)
/// or the keys.
enum Play {
    /// The scripted run at the scene time, kept so that the next frame
    /// continues from it rather than replaying from the start. (To see it
    /// again in a window, set the overlay's scene time back to 0.)
    Demo(Game),
    Keys(Game),
}

/// How long a day lasts when the sun moves, seconds.
pub const DAY_SECONDS: f32 = 120.0;

/// The keys' controls this frame. Pressing left and right together
/// cancels out; jump is held, so holding Space jumps again on landing.
pub fn controls_from(input: &Input) -> Controls {
    let any = |keys: &[KeyCode]| keys.iter().any(|k| input.held(*k));
    Controls {
        left: any(&[KeyCode::KeyA, KeyCode::ArrowLeft]),
        right: any(&[KeyCode::KeyD, KeyCode::ArrowRight]),
        jump: any(&[KeyCode::Space, KeyCode::KeyW, KeyCode::ArrowUp]),
    }
}
// ANCHOR_END: play

pub struct ShadowsChapter {
    pub settings: Settings,
    level: Level,
    solids: Vec<physics::Aabb>,
    play: Play,
    materials: Materials,
    models: Models,
    /// Every instance: the level's and the props', which never move, then
    /// the player's, written each frame.
    instances: wgpu::Buffer,
    /// Which model (an index into `Models`' order) draws which instances.
    draws: Vec<(usize, std::ops::Range<u32>)>,
    /// The box around everything that casts a shadow.
    bounds: (Vec3, Vec3),
    renderer: ShadowedRenderer,
    pub shadow_map: ShadowMap,
    map_view: shadow_map::MapView,
    /// The lantern's light, its cube shadow map and the cross that shows it.
    lantern: Light,
    pub point_shadow: PointShadow,
    cube_view: CubeView,
    /// What the cube's passes cost in the last frame, counted as recorded.
    pub cube_cost: CubeCost,
    /// Where the camera is, if a preset put it somewhere; else behind the player.
    preset: Option<CameraPreset>,
    parallax: Parallax,
    lines: Lines,
    scene_lights: SceneLights,
    sky: CitySky,
    post: PostChain,
    target: Target,
    /// This frame's light box, for the overlay.
    last_box: Option<LightBox>,
    /// The size --shadow-map-size asked for.
    size_flag: Option<u32>,
    pub warnings: Vec<String>,
}

impl ShadowsChapter {
    /// The game the keys are playing, once a key has taken over.
    pub fn played_by_keys(&self) -> Option<&Game> {
        match &self.play {
            Play::Keys(game) => Some(game),
            Play::Demo(_) => None,
        }
    }

    /// The game as it stands at scene time `time`.
    fn game_at(&mut self, time: f32) -> Game {
        match &mut self.play {
            Play::Keys(game) => *game,
            Play::Demo(game) => {
                // The script ends at 21 s and the player stands still from
                // then on: a time past a minute is a minute, so that
                // `--time 1e9` does not simulate thirty years.
                let steps = (time.min(60.0) / game::STEP).round() as u64;
                if steps < game.steps {
                    *game = Game::new(&self.level);
                }
                while game.steps < steps {
                    let controls = game::script(game.time());
                    game.step(&self.solids, controls);
                }
                *game
            }
        }
    }

    /// The instances of the level (one), the props kind by kind (trees,
    /// rocks, crates, islands, the sphere), the lantern, and a last one for
    /// the player, with the draws that use them: (model, instances), the
    /// model numbered as in [`LANTERN_MODEL`]'s order. Every draw casts the
    /// sun's shadow; all but the lantern's cast the lantern's.
    pub fn level_instances(level: &Level, game: &Game) -> (Vec<ModelInstance>, Vec<(usize, std::ops::Range<u32>)>) {
        let mut instances = vec![ModelInstance::new(Mat4::IDENTITY, 1.0)];
        let mut draws = vec![(0, 0..1)];
        for (i, kind) in PropKind::ALL.into_iter().enumerate() {
            let start = instances.len() as u32;
            instances.extend(scene::prop_instances(level, kind));
            draws.push((1 + i, start..instances.len() as u32));
        }
        let start = instances.len() as u32;
        instances.push(scene::lantern_instance(level));
        draws.push((LANTERN_MODEL, start..start + 1));
        let start = instances.len() as u32;
        instances.push(scene::player_instance(game));
        draws.push((LANTERN_MODEL + 1, start..start + 1));
        (instances, draws)
    }

    /// Moves the player's instance, the last one, to where `game` has it.
    fn place_player(&self, gpu: &Gpu, game: &Game) {
        let size = std::mem::size_of::<ModelInstance>() as u64;
        let offset = self.instances.size() - size;
        gpu.queue.write_buffer(&self.instances, offset, bytemuck::bytes_of(&scene::player_instance(game)));
    }

    /// The collision boxes, as the physics sees them, in the plane z = 0.
    fn collision_lines(&self, game: &Game) -> LineList {
        let mut list = LineList::default();
        let solid = Vec4::new(0.2, 1.0, 0.3, 1.0);
        for aabb in &self.solids {
            list.rectangle(aabb.min.extend(0.0), aabb.max.extend(0.0), solid);
        }
        let player = if game.on_floor { Vec4::new(1.0, 0.85, 0.1, 1.0) } else { Vec4::new(1.0, 0.25, 0.2, 1.0) };
        list.rectangle(game.player.aabb.min.extend(0.0), game.player.aabb.max.extend(0.0), player);
        list
    }
}

impl Chapter for ShadowsChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0074; outliers at most 0.1%. Worst 16×16 patch 0.096 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.028, outliers: 0.002, patch: 0.2 };
    const TITLE: &'static str = "10 · Shadows";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);
    const POST_ANTIALIASING: bool = true;
    /// Mid-jump: the player is in the air over the first wall.
    const SNAPSHOT_TIME: f32 = 5.7;
    const BENCH_FRAMES: u32 = 10;
    const BENCH_BASELINE: Option<&'static str> = Some("hard");
    const KEYS: &'static [(&'static str, &'static str)] =
        &[("A D / ← →", "run (the first key takes over from the demo)"), ("Space / W / ↑", "jump")];
    const FLAGS: &'static [ChapterFlag] = &[ChapterFlag {
        name: "shadow-map-size",
        value_name: "TEXELS",
        help: "The shadow map's size along each side, 512 to 4096 (clamped to what the adapter allows)",
    }];

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
        let post = PostChain::new(gpu, target)?;
        let multisample = post.hdr().multisample();
        let level = game::level();
        let read: obj::ReadFile = &scene::read;
        let mut warnings = Vec::new();
        let mut load = |path: &str| -> anyhow::Result<obj::LoadedModel> {
            let loaded = obj::load(Path::new(path), read)?;
            warnings.extend(loaded.warnings.iter().cloned());
            Ok(loaded)
        };
        let props =
            PropKind::ALL.iter().map(|&kind| load(scene::prop_model(kind))).collect::<anyhow::Result<Vec<_>>>()?;
        let player = load(scene::PLAYER_MODEL)?;
        let scene_lights = SceneLights::new(gpu)?;
        let mut mips = MipMaker::new(gpu)?;
        let mut up = Uploader::new(gpu, &mut mips, read);
        let mut materials = Materials::new(&mut up);
        let models = Models {
            level: upload_model(&mut up, &mut materials, &scene::level_model(&level), "level"),
            props: props
                .iter()
                .zip(PropKind::ALL)
                .map(|(prop, kind)| upload_model(&mut up, &mut materials, &prop.model, &format!("{kind:?}")))
                .collect(),
            lantern: upload_model(&mut up, &mut materials, &scene::lantern_model(&level), "lantern"),
            player: upload_model(&mut up, &mut materials, &player.model, "player"),
        };
        let parallax = Parallax::new(gpu, &mut up, &scene_lights, &level, multisample)?;
        up.finish();
        warnings.append(&mut materials.warnings);
        for warning in &warnings {
            eprintln!("warning: {warning}");
        }
        let shadow_map = ShadowMap::new(gpu, shadow_map::DEFAULT_SIZE)?;
        let point_shadow = PointShadow::new(gpu, point_shadow::DEFAULT_FACE_SIZE)?;
        let renderer = ShadowedRenderer::with_point_light(
            gpu,
            &scene_lights,
            &materials,
            &shadow_map,
            &point_shadow,
            multisample,
        )?;
        let map_view = shadow_map::MapView::new(gpu, target.format)?;
        let cube_view = CubeView::new(gpu, target.format, &point_shadow)?;
        let sky = CitySky::new(gpu, &scene_lights, multisample)?;
        let solids = level.solids();
        let bounds = scene::level_bounds(&level);
        let (instances, draws) = Self::level_instances(&level, &Game::new(&level));
        let instances = wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("instances"),
                contents: bytemuck::cast_slice(&instances),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            },
        );
        let lantern = scene::lantern_light(&level);
        Ok(Self {
            settings: Settings::DEFAULT,
            play: Play::Demo(Game::new(&level)),
            solids,
            level,
            materials,
            models,
            instances,
            draws,
            bounds,
            renderer,
            shadow_map,
            map_view,
            lantern,
            point_shadow,
            cube_view,
            cube_cost: CubeCost::default(),
            preset: None,
            parallax,
            lines: Lines::new(gpu, target.format)?,
            scene_lights,
            sky,
            post,
            target,
            last_box: None,
            size_flag: None,
            warnings,
        })
    }

    fn apply_flags(&mut self, gpu: &Gpu, flags: &FlagValues) -> anyhow::Result<()> {
        let Some(value) = flags.get("shadow-map-size") else { return Ok(()) };
        let size: u32 = value.parse().map_err(|_| {
            UsageError(format!("--shadow-map-size: '{value}' is not a whole number of texels (512 to 4096)"))
        })?;
        self.size_flag = Some(size);
        self.settings.shadow.size = size;
        self.shadow_map.resize(&gpu.device, size);
        if let Some(note) = &self.shadow_map.note {
            eprintln!("note: {note}");
        }
        Ok(())
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.post.resize(gpu, target);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
        // --shadow-map-size wins over what a view asks for.
        if let Some(size) = self.size_flag {
            self.settings.shadow.size = size;
        }
    }

    fn reset_camera(&mut self, view: usize) {
        self.preset = VIEW_TABLE[view].camera;
    }

    // ANCHOR: update
    fn update(&mut self, input: &Input, dt: f32) {
        let controls = controls_from(input);
        if let Play::Demo(game) = self.play
            && (controls.left || controls.right || controls.jump)
        {
            self.play = Play::Keys(game);
            // Whoever plays sees the player.
            self.preset = None;
        }
        if let Play::Keys(game) = &mut self.play {
            // Fixed steps; a long pause (a hidden window) is capped, not
            // integrated in one go.
            game.advance(&self.solids, controls, dt);
        }
    }
    // ANCHOR_END: update

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        let s = self.settings;
        let game = self.game_at(frame.time);
        let player = game.player.aabb.centre();
        let camera = match self.preset {
            Some(CameraPreset::Lantern) => lantern_camera(self.level.lantern, self.target.aspect()),
            None => side_camera(player, s.camera_distance, self.target.aspect()),
        };
        // The sun's box is fitted to what the game's camera sees, whichever
        // camera draws the picture.
        let game_camera = side_camera(player, CAMERA_DISTANCE, self.target.aspect());
        let bounds = self.bounds;
        let visible = visible_part(&game_camera, bounds.1.z);
        let focus: Vec<Vec3> = match s.fit {
            Fit::Visible => visible.to_vec(),
            Fit::WholeLevel => (0..8)
                .map(|i| {
                    let pick = |bit, lo: f32, hi: f32| if i & bit == 0 { lo } else { hi };
                    Vec3::new(
                        pick(1, bounds.0.x, bounds.1.x),
                        pick(2, bounds.0.y, bounds.1.y),
                        pick(4, bounds.0.z, bounds.1.z),
                    )
                })
                .collect(),
        };
        let phase = if s.sun_moves { s.phase + frame.time / DAY_SECONDS } else { s.phase };
        let day: Daylight = scene::sun_at(phase.rem_euclid(1.0));
        // The map's size first: the box's texels are fitted to it.
        self.shadow_map.resize(&gpu.device, s.shadow.size);
        let light = fit_light(day.direction, &focus, bounds, self.shadow_map.size);
        self.last_box = Some(light);
        self.shadow_map.write(gpu, &light, &s.shadow);
        let options = LoopOptions { culling: false, highlight: Highlight::BlinnPhong, heat_map: false };
        self.scene_lights.write(gpu, &camera, &day, &[], &Default::default(), options);
        self.sky.write(gpu, &camera, &day);
        self.place_player(gpu, &game);
        let m = &self.models;
        let models: Vec<&GpuModel> = std::iter::once(&m.level).chain(&m.props).chain([&m.lantern, &m.player]).collect();
        let list = DrawList {
            materials: &self.materials,
            instances: &self.instances,
            draws: self
                .draws
                .iter()
                .map(|(i, instances)| Draw { model: models[*i], instances: instances.clone() })
                .collect(),
        };

        // Pass one: the sun's view, depth only.
        frame.drawn.extend([self.shadow_map.render(gpu, frame.encoder, frame.timer, &s.shadow, &list)]);
        if s.show == Show::ShadowMap {
            let range = visible.map(|p| light.view_proj.project_point3(p).z);
            let (lo, hi) = range.iter().fold((f32::MAX, f32::MIN), |(lo, hi), z| (lo.min(*z), hi.max(*z)));
            self.map_view.draw(gpu, frame, &self.shadow_map, (lo, hi), self.target.aspect());
            return;
        }

        // Then six passes, one per face of the lantern's cube, of
        // everything but the lantern itself (its light is inside it).
        self.point_shadow.write(gpu, &self.lantern, &s.lantern);
        self.cube_cost = CubeCost::default();
        if s.lantern.filter != PointFilter::Off || s.show == Show::CubeMap {
            let casters = DrawList {
                materials: &self.materials,
                instances: &self.instances,
                draws: self
                    .draws
                    .iter()
                    .filter(|(i, _)| *i != LANTERN_MODEL)
                    .map(|(i, instances)| Draw { model: models[*i], instances: instances.clone() })
                    .collect(),
            };
            self.cube_cost = self.point_shadow.render(frame.encoder, frame.timer, &casters);
            frame.drawn.extend([self.cube_cost.pass_count()]);
        }
        if s.show == Show::CubeMap {
            self.cube_view.draw(gpu, frame, self.target);
            return;
        }

        // The last pass: the camera's view, each fragment asking the maps.
        {
            let mut pass = self.post.hdr().pass(frame.encoder, frame.timer, "scene", wgpu::Color::BLACK);
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            let mut drawn = self.renderer.draw(&mut pass, &self.shadow_map, &list, s.show == Show::Sunlit);
            if s.show == Show::Scene {
                drawn += self.parallax.draw(gpu, &mut pass, day.horizon, s.tint_layers);
                drawn += self.sky.draw(&mut pass);
            }
            frame.drawn.add("scene", drawn);
        }
        // What the tests count is shown as it is, not tone-mapped.
        let output = if s.show == Show::Sunlit { PostOutput::RawHdr } else { PostOutput::Picture };
        let bloom = s.bloom.then(BloomSettings::default);
        self.post.finish(gpu, frame, &PostSettings { output, exposure: 1.0, bloom });

        // Lines over the picture.
        let mut lines = LineList::default();
        if s.collision_boxes {
            lines = self.collision_lines(&game);
        }
        if s.light_box {
            lines.box_edges(&light.corners(), Vec4::new(1.0, 0.85, 0.1, 1.0));
            lines.box_edges(&visible, Vec4::new(0.2, 0.9, 1.0, 1.0));
        }
        let drawn = self.lines.draw(gpu, frame.encoder, frame.timer, frame.target, camera.view_projection(), &lines);
        frame.drawn.extend(drawn);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        if let Play::Keys(_) = self.play
            && ui.button("replay the demo").clicked()
        {
            self.play = Play::Demo(Game::new(&self.level));
        }
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            ui.label("filter");
            for filter in Filter::ALL {
                ui.radio_value(&mut s.shadow.filter, filter, filter.label());
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("shadow map");
            for size in shadow_map::SIZES {
                ui.radio_value(&mut s.shadow.size, size, format!("{size}²"));
            }
        });
        if let Some(note) = &self.shadow_map.note {
            ui.colored_label(egui::Color32::from_rgb(230, 180, 60), note);
        }
        ui.add(egui::Slider::new(&mut s.shadow.bias.slope_scale, 0.0..=20.0).text("slope-scaled bias"));
        ui.add(egui::Slider::new(&mut s.shadow.bias.constant, 0..=100_000).text("constant bias (depth steps)"));
        ui.add(egui::Slider::new(&mut s.shadow.bias.normal_offset, 0.0..=8.0).text("normal offset (texels)"));
        ui.add(egui::Slider::new(&mut s.shadow.radius, 0.5..=8.0).text("Poisson radius (texels)"));
        ui.add(egui::Slider::new(&mut s.shadow.light_width, 0.005..=0.2).logarithmic(true).text("PCSS light width"));
        ui.horizontal_wrapped(|ui| {
            ui.label("lantern's shadow");
            for filter in PointFilter::ALL {
                ui.radio_value(&mut s.lantern.filter, filter, filter.label());
            }
        });
        ui.add(egui::Slider::new(&mut s.lantern.bias.normal_offset, 0.0..=8.0).text("lantern: normal offset (texels)"));
        ui.add(egui::Slider::new(&mut s.lantern.bias.depth, 0.0..=8.0).text("lantern: depth bias (texels)"));
        ui.horizontal(|ui| {
            ui.label("shadow pass culls");
            ui.radio_value(&mut s.shadow.cull, Cull::Back, "back faces");
            ui.radio_value(&mut s.shadow.cull, Cull::Front, "front faces");
            ui.radio_value(&mut s.shadow.cull, Cull::None, "nothing");
        });
        ui.horizontal(|ui| {
            ui.label("fit the sun's box to");
            ui.radio_value(&mut s.fit, Fit::Visible, "what the camera sees");
            ui.radio_value(&mut s.fit, Fit::WholeLevel, "the whole level");
        });
        ui.horizontal(|ui| {
            ui.add(egui::Slider::new(&mut s.phase, 0.2..=0.8).text("time of day (0.25 sunrise, 0.75 sunset)"));
            ui.checkbox(&mut s.sun_moves, "moving");
        });
        ui.checkbox(&mut s.collision_boxes, "collision boxes");
        ui.checkbox(&mut s.light_box, "the sun's box");
        ui.checkbox(&mut s.tint_layers, "tint the layers by depth");
        let cost = self.cube_cost;
        ui.label(format!(
            "lantern's cube: {} passes of {}², {} draw calls, {} triangles",
            cost.passes, self.point_shadow.size, cost.draw_calls, cost.triangles
        ));
        if let Some(light) = self.last_box {
            ui.label(format!(
                "one shadow-map texel covers {:.1} cm; the box is {:.0} m deep",
                light.texel * 100.0,
                light.depth
            ));
        }
        for warning in &self.warnings {
            ui.colored_label(egui::Color32::from_rgb(230, 180, 60), warning);
        }
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        let texel = self.last_box.map_or(0.0, |b| b.texel * 100.0);
        let cost = self.cube_cost;
        format!(
            "shadow map {0}² ({1}), one texel {texel:.2} cm; lantern's cube {2} passes, {3} draw calls, {4} triangles",
            self.shadow_map.size,
            self.settings.shadow.filter.label(),
            cost.passes,
            cost.draw_calls,
            cost.triangles
        )
    }
}
