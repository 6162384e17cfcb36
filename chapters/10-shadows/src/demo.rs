//! The chapter's wiring: `impl Chapter`, which makes the pieces, applies
//! the views (`views`), lets the keys take over from the script (`play`),
//! and renders a frame: the sun's shadow map and the lantern's cube, then
//! the level through the shadowed renderer, then chapter 08's post chain;
//! and the overlay's controls.

use common::args::UsageError;
use common::glam::{Vec3, Vec4};
use common::{
    Chapter, ChapterFlag, FlagValues, Frame, Gpu, Input, Preparation, Target, View, anyhow, egui, views_of, wgpu,
};
use lighting::bloom::BloomSettings;
use lighting::lights::{Daylight, Light};
use lighting::{CitySky, Highlight, LoopOptions, PostChain, PostOutput, PostSettings, SceneLights};
use textures::materials::Uploader;
use textures::mipmaps::MipMaker;

use crate::camera_presets::{CAMERA_DISTANCE, CameraPreset, lantern_camera, side_camera};
use crate::game::{self, Game, Level};
use crate::level_models::{self, LevelModels};
use crate::light_box::{LightBox, fit_light, visible_part};
use crate::lines::{LineList, Lines};
use crate::parallax::Parallax;
use crate::physics;
use crate::play::{Play, controls_from};
use crate::point_shadow::{self, CubeCost, CubeView, PointFilter, PointShadow};
use crate::scene;
use crate::shadow_map::{self, Cull, Filter, ShadowMap};
use crate::shadowed_renderer::ShadowedRenderer;
use crate::views::{DAY_SECONDS, Fit, Settings, Show, VIEW_TABLE};

pub struct ShadowsChapter {
    pub settings: Settings,
    level: Level,
    solids: Vec<physics::Aabb>,
    play: Play,
    /// The level's models, materials and instances.
    models: LevelModels,
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
}

impl Chapter for ShadowsChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0074; outliers at most 0.1%. Worst 16×16 patch 0.096 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.028, outliers: 0.002, patch: 0.2 };
    const TITLE: &'static str = "10 · Shadows";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
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
        lighting::scene_lights::gpu_needs()
    }

    /// Nothing takes long enough to prepare in steps.
    type Prepared = ();

    fn prepare(_gpu: &Gpu) -> Preparation<()> {
        Preparation::ready(())
    }

    fn new(gpu: &Gpu, target: Target, (): ()) -> anyhow::Result<Self> {
        let post = PostChain::new(gpu, target)?;
        let multisample = post.hdr().multisample();
        let level = game::level();
        let mut warnings = Vec::new();
        let (props, player) = level_models::read_models(&mut warnings)?;
        let scene_lights = SceneLights::new(gpu)?;
        let mut mips = MipMaker::new(gpu)?;
        let mut up = Uploader::new(gpu, &mut mips, &scene::read);
        let mut models = LevelModels::upload(gpu, &mut up, &level, &props, &player);
        let parallax = Parallax::new(gpu, &mut up, &scene_lights, &level, multisample)?;
        up.finish();
        warnings.append(&mut models.materials.warnings);
        for warning in &warnings {
            eprintln!("warning: {warning}");
        }
        let shadow_map = ShadowMap::new(gpu, shadow_map::DEFAULT_SIZE)?;
        let point_shadow = PointShadow::new(gpu, point_shadow::DEFAULT_FACE_SIZE)?;
        let renderer = ShadowedRenderer::with_point_light(
            gpu,
            &scene_lights,
            &models.materials,
            &shadow_map,
            &point_shadow,
            multisample,
        )?;
        let map_view = shadow_map::MapView::new(gpu, target.format)?;
        let cube_view = CubeView::new(gpu, target.format, &point_shadow)?;
        let sky = CitySky::new(gpu, &scene_lights, multisample)?;
        let solids = level.solids();
        let bounds = scene::level_bounds(&level);
        let lantern = scene::lantern_light(&level);
        Ok(Self {
            settings: Settings::DEFAULT,
            play: Play::Demo(Game::new(&level)),
            solids,
            level,
            models,
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
        let game = self.play.game_at(&self.level, &self.solids, frame.time);
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
        let focus = s.fit.focus(&visible, bounds);
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
        self.models.place_player(gpu, &game);
        let list = self.models.everything();

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
            let casters = self.models.lantern_casters();
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
            lines = LineList::collision_boxes(&self.solids, &game);
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
