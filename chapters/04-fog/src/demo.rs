//! The chapter itself: the fog each view applies, the views, the
//! overlay's sliders, and `impl Chapter`, which draws chapter 03's terrain
//! through the fog with the far plane pulled in to where it turns opaque.

use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, Reloadable, SceneTargets, Target, View,
    ViewRow, anyhow, egui, views_of, wgpu,
};
use terrain::ground::{self, Movement};
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::{Detail, KEEP_ALL, SKY, Sun, TerrainRenderer, Viewpoint, start_camera};

use crate::fog_binding::{FogBinding, fog_shader};
use crate::fog_settings::FogSettings;

/// No view of this chapter places the camera (every one is a mode): this
/// enum has no values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {}

impl CameraPreset {
    pub fn camera(self, _field: &HeightField, _aspect: f32) -> Camera {
        match self {}
    }
}

/// What a view decides: the fog, and whether the terrain is drawn with
/// chapter 03's levels of detail or every chunk at full detail.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub fog: FogSettings,
    pub full_detail: bool,
}

/// Every view, with the settings it applies.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 5] = [
    ViewRow::mode(
        "default",
        "the terrain in a light haze, fading into the sky",
        Settings { fog: FogSettings::HAZE, full_detail: false },
    ),
    ViewRow::no_aa("default", Settings { fog: FogSettings::HAZE, full_detail: false }),
    ViewRow::mode(
        "no-fog",
        "the same view without fog: a hard edge where the world ends",
        Settings { fog: FogSettings::NONE, full_detail: false },
    ),
    ViewRow::mode(
        "dense",
        "a dust storm: thick fog, and a far plane pulled in to 588 m",
        Settings { fog: FogSettings::DUST_STORM, full_detail: false },
    ),
    ViewRow::mode(
        "full-detail",
        "the default view with every chunk in view at full detail: the same picture",
        Settings { fog: FogSettings::HAZE, full_detail: true },
    )
    .same_picture_as("default"),
];

pub struct FogChapter {
    pub terrain: TerrainRenderer,
    pub fog: FogSettings,
    /// Every chunk in view at full detail, rather than chapter 03's levels.
    pub full_detail: bool,
    pub camera: Camera,
    pub controller: FlyController,
    /// Flying (the default) or walking on the ground (G, `--walk`).
    pub movement: Movement,
    fog_binding: FogBinding,
    viewpoint: Viewpoint,
    /// Rebuilt when fog.wgsl or terrain.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    /// The scene's samples and depth, resolved into the frame.
    scene: SceneTargets,
    target: Target,
    regenerate_requested: bool,
}

impl Chapter for FogChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "04 · Fog";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
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
        terrain::TerrainData::prepare(gpu, TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target, terrain: Self::Prepared) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let terrain = TerrainRenderer::new(gpu, terrain);
        let fog_binding = FogBinding::new(device);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("fog"),
            bind_group_layouts: &[Some(&terrain.bind_group_layout), Some(&fog_binding.layout)],
            immediate_size: 0,
        });
        let scene = SceneTargets::new(gpu, target);
        let format = (target.format, scene.samples());
        let pipeline = Reloadable::new(gpu, move |gpu| TerrainRenderer::pipeline(gpu, &fog_shader(), &layout, format))?;
        Ok(Self {
            camera: start_camera(terrain.field(), target.aspect()),
            controller: FlyController { speed: 40.0, ..Default::default() },
            movement: Movement::Fly,
            fog: FogSettings::HAZE,
            full_detail: false,
            viewpoint: terrain.viewpoint(device),
            terrain,
            fog_binding,
            pipeline,
            scene,
            target,
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
        Settings { fog: self.fog, full_detail: self.full_detail } = VIEW_TABLE[view].settings;
    }

    fn reset_camera(&mut self, view: usize) {
        let (field, aspect) = (self.terrain.field(), self.target.aspect());
        self.camera = match VIEW_TABLE[view].camera {
            Some(preset) => preset.camera(field, aspect),
            None => start_camera(field, aspect),
        };
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn before_first_frame(&mut self, _camera_placed: bool) {
        ground::first_frame(&mut self.camera, self.terrain.field(), self.movement);
    }

    fn update(&mut self, input: &Input, dt: f32) {
        let field = self.terrain.field();
        ground::step(&self.controller, &mut self.camera, &mut self.movement, field, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        if std::mem::take(&mut self.regenerate_requested) {
            self.terrain.regenerate(gpu);
        }
        // Nothing past the opaque distance can be seen: stop drawing there.
        self.camera.far = self.fog.far_plane();
        self.fog_binding.write(&gpu.queue, self.fog);
        let height = self.target.height;
        let detail = if self.full_detail { Detail::full(height) } else { Detail::lod(height) };
        self.terrain.aim(gpu, &mut self.viewpoint, &self.camera, detail, Sun::AFTERNOON, KEEP_ALL);

        // Clear to the fog colour: where there is no ground, the fog's
        // "infinitely far" is what shows.
        let drawn = frame.drawn;
        let mut pass = frame.multisampled_pass("terrain", SKY, &self.scene);
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(1, &self.fog_binding.group, &[]);
        drawn.add("terrain", self.terrain.draw(&mut pass, &self.viewpoint));
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("density (per m)"));
        ui.add(egui::Slider::new(&mut self.fog.gradient, 0.5..=4.0).text("gradient"));
        ui.label(format!("opaque beyond {:.0} m; far plane {:.0} m", self.fog.opaque_distance(), self.camera.far,));
        ui.label(self.terrain.drawn(&self.viewpoint));
        ui.collapsing("terrain", |ui| {
            self.regenerate_requested |= self.terrain.settings_ui(ui);
        });
        ui.add(egui::Slider::new(&mut self.controller.speed, 5.0..=400.0).logarithmic(true).text("speed (m/s)"));
        ground::movement_switch(ui, &mut self.movement);
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        format!("far plane {:.0} m; {}", self.camera.far, self.terrain.stats(&self.viewpoint))
    }
}
