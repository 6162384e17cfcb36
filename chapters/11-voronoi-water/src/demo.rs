//! The chapter itself: `impl Chapter`, which composes this chapter's
//! diagram, water, sea, sky, islands and boat with chapter 08's lights and
//! post chain and chapter 10's shadow map into a frame, applies the views
//! (`views`, `camera_presets`), steers the boat and the day from the keys
//! (`steering`, `day_clock`), and puts the settings in the overlay.

use common::glam::Vec3;
use common::{
    Chapter, Frame, Gpu, Input, Orbit, Preparation, Target, View, anyhow, egui, views_of, wgpu,
    winit::keyboard::KeyCode,
};
use lighting::bloom::BloomSettings;
use lighting::{Highlight, LoopOptions, PostChain, PostOutput, PostSettings, SceneLights};
use shadows::ShadowedRenderer;
use shadows::shadow_map::{Filter, MapView, ShadowMap, ShadowSettings, fit_light};

use crate::atmosphere::{self, Atmosphere, Sky};
use crate::boat::{self, Helm, Pose};
use crate::boat_models::BoatModels;
use crate::boat_shadow::shadow_focus;
use crate::camera_presets::{SUNSET_ORBIT, orbit_camera, orbit_of};
use crate::day_clock::DayClock;
use crate::islands::IslandRenderer;
use crate::sea::{self, SeaRenderer, SeaSettings};
use crate::sites;
use crate::steering::{Play, orders_from};
use crate::views::{SNAPSHOT_TIME, Settings, Show, VIEW_TABLE};
use crate::voronoi::{Method, Voronoi};
use crate::water_texture::{self, Picture, WaterTexture};

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
    /// The boat, its sail and its sailor, placed by one instance.
    pub models: BoatModels,
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
}

impl Chapter for VoronoiWaterChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0091: foam lines are one pixel wide; outliers at most 0.1%. Worst 16×16 patch 0.171 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.042, outliers: 0.002, patch: 0.25 };
    const TITLE: &'static str = "11 · Voronoi water";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
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
        lighting::scene_lights::gpu_needs()
    }

    /// Nothing takes long enough to prepare in steps.
    type Prepared = ();

    fn prepare(_gpu: &Gpu) -> Preparation<()> {
        Preparation::ready(())
    }

    fn new(gpu: &Gpu, target: Target, (): ()) -> anyhow::Result<Self> {
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
        let models = BoatModels::load(gpu)?;
        let boat_renderer = ShadowedRenderer::new(gpu, &scene_lights, &models.materials, &shadow_map, multisample)?;
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
            models,
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
        self.orbit = orbit_of(VIEW_TABLE[view].camera);
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
            self.show.picture(gpu, frame, &self.water, picture, self.target.aspect(), water_texture::TILES_SHOWN_DOWN);
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
        let (focus, bounds) = shadow_focus(&pose, self.sea.waves(), day.direction);
        let light = fit_light(day.direction, &focus, bounds, self.shadow_map.size);
        self.shadow_map.write(gpu, &light, &shadow);
        // The boat, its sail (bent by the wind) and its sailor, on the waves.
        self.models.place(gpu, &pose);
        let list = self.models.draw_list();
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
