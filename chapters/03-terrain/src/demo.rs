//! The chapter itself: what each view decides, the views and their
//! cameras, the overlay's controls, and `impl Chapter`, which draws the
//! terrain from the flying camera, or from high above for `chunks`.

use std::sync::Arc;

use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, Preparation, Reloadable, SceneTargets,
    ShaderFile, Target, View, ViewRow, anyhow, egui, shader, views_of, wgpu,
};

use crate::cameras::{close_up_camera, overhead_camera, start_camera};
use crate::ground::{self, Movement};
use crate::heightfield::{HeightField, TerrainSettings};
use crate::lod::Detail;
use crate::terrain_data::TerrainData;
use crate::terrain_renderer::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer, Viewpoint, gpu_needs};

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// How the ground is coloured.
    pub shading: Shading,
    /// Levels of detail (true), or every chunk in view at full detail.
    pub lod: bool,
    /// Look from 4 km overhead at what the flying camera draws.
    pub from_above: bool,
}

impl Settings {
    pub const DEFAULT: Self = Self { shading: Shading::Shaded, lod: true, from_above: false };
}

/// The places a view can put the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// At the foot of the cliff, where the wireframe's cells are large.
    CloseUp,
}

impl CameraPreset {
    pub fn camera(self, field: &HeightField, aspect: f32) -> Camera {
        match self {
            Self::CloseUp => close_up_camera(field, aspect),
        }
    }
}

// Every view but `close-up` is a mode: a way of drawing what the flying
// camera sees. `quadtree` too: it shows that camera's patches from above.

/// Every view, with the settings it applies and, for a preset, its camera.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 8] = [
    ViewRow::mode("default", "the terrain, coloured by height and slope, with its cliff", Settings::DEFAULT),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "full-detail",
        "the same picture with every chunk in view at full detail: many times the triangles",
        Settings { lod: false, ..Settings::DEFAULT },
    )
    .same_picture_as("default"),
    ViewRow::mode(
        "lod-levels",
        "a colour per level of detail, blending into the next where the mesh morphs",
        Settings { shading: Shading::Levels, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "wireframe",
        "the triangles drawn, wherever they are at least 4 pixels apart",
        Settings { shading: Shading::Wireframe, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "close-up",
        "the wireframe from the foot of the cliff, where the 1 m cells are large",
        Settings { shading: Shading::Wireframe, ..Settings::DEFAULT },
        CameraPreset::CloseUp,
    ),
    ViewRow::mode(
        "normals",
        "normals from the whole height field: the same at every level of detail",
        Settings { shading: Shading::Normals, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "quadtree",
        "from 4 km above: the patches your camera draws, a colour per level; nothing where it culls",
        Settings { shading: Shading::Levels, from_above: true, ..Settings::DEFAULT },
    ),
];

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
