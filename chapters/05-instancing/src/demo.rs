//! The chapter itself: the overlay's controls and `impl Chapter`, which
//! draws the Mars plain from the camera standing on it, as each view of
//! `views.rs` sets it up.

use common::book_figures::thousands;
use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, SceneTargets, Target, View, anyhow,
    egui, views_of,
};
use fog::FogSettings;
use terrain::ground::{self, Movement};
use terrain::heightfield::TerrainSettings;
use terrain::{KEEP_ALL, SKY, Sun};

use crate::cameras::plain_camera;
use crate::mars_plain::{Culling, DrawCalls, MarsPlain, Mode, PlainViewpoint, RocksDrawn, Setup};
use crate::rock_field::MAX_ONE_PER_DRAW;
use crate::rock_scatter::{RockInstance, rocks_on_map};
use crate::views::VIEW_TABLE;

impl InstancingChapter {
    // ANCHOR: rocks_drawn
    /// "276,571 of 1,000,000 rocks drawn (1,135 of 4,096 groups), 5,531,420
    /// triangles", or where the GPU graded them, "… (820 full, 3,000
    /// octahedra, 26,000 tetrahedra), …": `drawn` against the rocks in this
    /// view's world.
    pub fn rocks_drawn(&self, drawn: Option<RocksDrawn>) -> String {
        let world = self.setup.rocks.min(self.plain.rocks_placed());
        let Some(drawn) = drawn else {
            return format!("rocks drawn of {}: counting on the GPU…", thousands(world.into()));
        };
        let how = match drawn.levels {
            Some([full, octahedra, tetrahedra]) => format!(
                "{} full, {} octahedra, {} tetrahedra",
                thousands(full.into()),
                thousands(octahedra.into()),
                thousands(tetrahedra.into())
            ),
            None => format!(
                "{} of {} groups",
                thousands(self.draw_calls.rock_groups.into()),
                thousands(self.plain.rock_groups(world).into())
            ),
        };
        format!(
            "{} of {} rocks drawn ({how}), {} rock triangles",
            thousands(drawn.rocks.into()),
            thousands(world.into()),
            thousands(drawn.triangles as f64)
        )
    }
    // ANCHOR_END: rocks_drawn
}

pub struct InstancingChapter {
    pub plain: MarsPlain,
    pub fog: FogSettings,
    pub setup: Setup,
    pub camera: Camera,
    pub controller: FlyController,
    /// Flying (the default) or walking on the ground (G, `--walk`).
    pub movement: Movement,
    viewpoint: PlainViewpoint,
    /// The scene's samples and depth, resolved into the frame.
    scene: SceneTargets,
    target: Target,
    /// Draw calls in the last frame.
    pub draw_calls: DrawCalls,
    regenerate_requested: bool,
}

impl Chapter for InstancingChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "05 · Instancing";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
    const KEYS: &'static [(&'static str, &'static str)] = ground::KEYS;
    const FLAGS: &'static [ChapterFlag] = &[ground::WALK_FLAG];
    const BENCH_FRAMES: u32 = 10;
    // The rocks' own shader, rather than the culling's (the first the plain builds).
    const MAIN_SHADER: Option<&'static str> = Some("instancing/rocks.wgsl");

    fn gpu_needs() -> common::GpuNeeds {
        crate::mars_plain::gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    /// The terrain, made in steps: see chapter 03.
    type Prepared = std::sync::Arc<terrain::TerrainData>;

    fn prepare(gpu: &Gpu) -> common::Preparation<Self::Prepared> {
        terrain::TerrainData::prepare(gpu, TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target, terrain: Self::Prepared) -> anyhow::Result<Self> {
        let scene = SceneTargets::new(gpu, target);
        let plain = MarsPlain::new(gpu, target.format, &[scene.samples()], terrain)?;
        Ok(Self {
            camera: plain_camera(plain.terrain.field(), target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            movement: Movement::Fly,
            fog: FogSettings::HAZE,
            setup: Setup::DEFAULT,
            viewpoint: plain.viewpoint(&gpu.device, scene.samples()),
            plain,
            scene,
            target,
            draw_calls: DrawCalls::default(),
            regenerate_requested: false,
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
        self.setup = VIEW_TABLE[view].settings;
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
        if std::mem::take(&mut self.regenerate_requested) {
            self.plain.regenerate(gpu);
        }
        // Chapter 04: nothing beyond the fog's opaque distance needs drawing.
        self.camera.far = self.fog.far_plane();
        let sky = [SKY.r as f32, SKY.g as f32, SKY.b as f32];
        self.plain.set_air(&gpu.queue, self.fog, sky);
        self.plain.aim(
            gpu,
            &mut self.viewpoint,
            &self.camera,
            self.setup.detail(self.target.height),
            Sun::AFTERNOON,
            KEEP_ALL,
        );
        // The rocks' compute pass (or the CPU's list of draws), before the
        // render pass that draws them.
        self.plain.cull(gpu, frame.encoder, frame.timer, &mut self.viewpoint, self.setup);
        let drawn = frame.drawn;
        let mut pass = frame.multisampled_pass("terrain and rocks", SKY, &self.scene);
        self.draw_calls = self.plain.draw(&mut pass, &self.viewpoint, self.setup);
        drawn.add("terrain and rocks", self.draw_calls.drawn());
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.setup;
        ui.horizontal_wrapped(|ui| {
            ui.label("culling:");
            ui.radio_value(&mut s.culling, Culling::PerRock, "per rock on the GPU, graded by size");
            ui.radio_value(&mut s.culling, Culling::PerRockFullDetail, "per rock on the GPU, full detail");
            ui.radio_value(&mut s.culling, Culling::Chunks, "by chunk on the CPU");
            ui.radio_value(&mut s.culling, Culling::Off, "none");
        });
        ui.horizontal_wrapped(|ui| {
            ui.radio_value(&mut s.mode, Mode::Instanced, "instanced");
            ui.radio_value(&mut s.mode, Mode::Indirect, "one indirect call");
            ui.radio_value(&mut s.mode, Mode::OnePerDraw, "one draw per rock");
            ui.radio_value(&mut s.mode, Mode::Flat, "flat");
            ui.radio_value(&mut s.mode, Mode::Groups, "groups");
            ui.radio_value(&mut s.mode, Mode::Levels, "levels");
        });
        let max = if s.mode == Mode::OnePerDraw { MAX_ONE_PER_DRAW } else { self.plain.rocks_placed() };
        s.rocks = s.rocks.min(max);
        ui.add(egui::Slider::new(&mut s.rocks, 0..=max).logarithmic(true).text("rocks"));
        ui.checkbox(&mut s.terrain, "terrain");
        if let Some(fallback) = self.fallback_line() {
            ui.label(fallback);
        }
        let calls = self.draw_calls;
        ui.label(format!(
            "draw calls last frame: {} ({} terrain chunks, {} for the rocks); {}",
            calls.total(),
            calls.terrain,
            calls.rocks,
            self.rocks_drawn(calls.rocks_drawn)
        ));
        if (self.plain.rocks_placed() as usize) < rocks_on_map(&self.plain.terrain.field().settings) {
            ui.label(format!("this terrain is steep: only {} rocks found room", self.plain.rocks_placed()));
        }
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        ui.collapsing("terrain settings", |ui| {
            self.regenerate_requested |= self.plain.terrain.settings_ui(ui);
        });
        ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=200.0).logarithmic(true).text("speed (m/s)"));
        ground::movement_switch(ui, &mut self.movement);
    }

    fn stats(&mut self, gpu: &Gpu) -> String {
        let calls = self.draw_calls;
        let drawn = self.plain.rocks_drawn_now(gpu, &self.viewpoint, self.setup);
        let fallback = self.fallback_line().map_or(String::new(), |line| format!("; {line}"));
        format!(
            "{}, {:?}, culling {:?}; {} draw calls ({} for the terrain + {} for the rocks); {:?} triangles per rock by level, {} bytes per instance{fallback}",
            self.rocks_drawn(Some(drawn)),
            self.setup.mode,
            self.setup.culling,
            calls.total(),
            calls.terrain,
            calls.rocks,
            self.plain.rock_triangles(),
            std::mem::size_of::<RockInstance>()
        )
    }
}

impl InstancingChapter {
    /// The viewpoint the chapter's picture is drawn from: its rock lists,
    /// for the tests.
    pub fn viewpoint(&self) -> &PlainViewpoint {
        &self.viewpoint
    }

    /// The overlay's and the bench's line where this view asks the GPU to
    /// cull and the device cannot: which capability it lacks.
    fn fallback_line(&self) -> Option<String> {
        let per_rock = matches!(self.setup.culling, Culling::PerRock | Culling::PerRockFullDetail);
        self.plain.culling_fallback().filter(|_| per_rock)
    }
}
