//! The chapter itself, only its wiring: `impl Chapter`, which makes the
//! terrain renderer and its pipeline, applies the views of `views.rs`,
//! moves the camera over the ground, and draws the terrain from the flying
//! camera (or, for `quadtree`, from high above); and the overlay's controls.

use std::sync::Arc;

use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, Preparation, Reloadable, SceneTargets,
    ShaderFile, Target, View, anyhow, egui, shader, views_of, wgpu,
};

use crate::cameras::{overhead_camera, start_camera};
use crate::ground::{self, Movement};
use crate::heightfield::TerrainSettings;
use crate::lod::Detail;
use crate::terrain_data::TerrainData;
use crate::terrain_renderer::{KEEP_ALL, SKY, Sun, TerrainRenderer, Viewpoint, gpu_needs};
use crate::views::{Settings, VIEW_TABLE};

pub struct TerrainChapter {
    pub settings: Settings,
    pub terrain: TerrainRenderer,
    pub camera: Camera,
    pub controller: FlyController,
    /// Flying (the default) or walking on the ground (G, `--walk`).
    pub movement: Movement,
    viewpoint: Viewpoint,
    /// Rebuilt when terrain.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    /// The scene's samples and depth, resolved into the frame.
    scene: SceneTargets,
    target: Target,
    /// The overlay changed the settings; regenerate before the next frame.
    regenerate_requested: bool,
}

fn terrain_shader() -> ShaderFile {
    shader!("terrain/terrain.wgsl")
}

impl Chapter for TerrainChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "03 · Terrain from noise";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
    const KEYS: &'static [(&'static str, &'static str)] = ground::KEYS;
    const FLAGS: &'static [ChapterFlag] = &[ground::WALK_FLAG];
    const BENCH_FRAMES: u32 = 10;

    fn gpu_needs() -> common::GpuNeeds {
        gpu_needs()
    }

    /// The terrain, the long part of starting: made in steps, so that a
    /// page shows its progress.
    type Prepared = Arc<TerrainData>;

    fn prepare(gpu: &Gpu) -> Preparation<Arc<TerrainData>> {
        TerrainData::prepare(gpu, TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target, terrain: Arc<TerrainData>) -> anyhow::Result<Self> {
        let terrain = TerrainRenderer::new(gpu, terrain);
        let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("terrain"),
            bind_group_layouts: &[Some(&terrain.bind_group_layout)],
            immediate_size: 0,
        });
        let scene = SceneTargets::new(gpu, target);
        let format = (target.format, scene.samples());
        let pipeline =
            Reloadable::new(gpu, move |gpu| TerrainRenderer::pipeline(gpu, &terrain_shader(), &layout, format))?;
        Ok(Self {
            settings: Settings::DEFAULT,
            camera: start_camera(terrain.field(), target.aspect()),
            controller: FlyController { speed: 40.0, ..Default::default() },
            movement: Movement::Fly,
            viewpoint: terrain.viewpoint(&gpu.device),
            terrain,
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
        self.settings = VIEW_TABLE[view].settings;
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
        let settings = self.settings;
        self.terrain.shading = settings.shading;
        let height = self.target.height;
        let detail = if settings.lod { Detail::lod(height) } else { Detail::full(height) };
        // The quadtree view looks from high above at what the flying
        // camera draws: the patches it chose, culled by its frustum.
        let seen_from =
            if settings.from_above { overhead_camera(self.terrain.field(), self.target.aspect()) } else { self.camera };
        let (camera, sun) = (&self.camera, Sun::AFTERNOON);
        self.terrain.aim_seen_from(gpu, &mut self.viewpoint, camera, detail, sun, KEEP_ALL, &seen_from);
        let drawn = frame.drawn;
        let mut pass = frame.multisampled_pass("terrain", SKY, &self.scene);
        pass.set_pipeline(&self.pipeline.get());
        drawn.add("terrain", self.terrain.draw(&mut pass, &self.viewpoint));
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label(self.terrain.drawn(&self.viewpoint));
        self.regenerate_requested |= self.terrain.settings_ui(ui);
        ui.add(egui::Slider::new(&mut self.controller.speed, 5.0..=400.0).logarithmic(true).text("speed (m/s)"));
        ground::movement_switch(ui, &mut self.movement);
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        self.terrain.stats(&self.viewpoint)
    }
}
