//! The chapter itself: `impl Chapter`, which composes chapter 08's
//! lights, sky and post chain with the textured renderer into a frame,
//! applies the views (`views.rs`) and their cameras (`camera_presets.rs`),
//! draws what `drawables.rs` assembles, and puts a learner's model on the
//! stage (`featured.rs`).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, Preparation, Target, View, anyhow,
    egui, views_of, wgpu, winit::keyboard::KeyCode,
};
use lighting::bloom::BloomSettings;
use lighting::city::{City, Clocks};
use lighting::clusters;
use lighting::lights::{TimeOfDay, daylight};
use lighting::{CitySky, Highlight, LoopOptions, PostChain, PostOutput, PostSettings, SceneLights, Shading};

use crate::builtin;
use crate::camera_presets::CameraPreset;
use crate::drawables::{self, BuiltinModels, FrameDraws, Models};
use crate::featured::Featured;
use crate::materials::{self, Materials, SamplerMode, Uploader};
use crate::mesh::ModelInstance;
use crate::mipmaps::MipMaker;
use crate::obj::ReadFile;
use crate::scenes::{self, Scene};
use crate::textured_renderer::{Draw, DrawList, SurfaceOptions, TexturedRenderer};
use crate::views::{Settings, Tangents, VIEW_TABLE};

pub struct TexturesChapter {
    pub settings: Settings,
    pub scene: Scene,
    pub camera: Camera,
    pub controller: FlyController,
    pub city: City,
    pub clocks: Clocks,
    last_time: f32,
    mips: MipMaker,
    materials: Materials,
    models: Models,
    pub featured: Featured,
    renderer: TexturedRenderer,
    instances: wgpu::Buffer,
    scene_lights: SceneLights,
    sky: CitySky,
    post: PostChain,
    target: Target,
    /// What loading had to warn about, one line each.
    pub warnings: Vec<String>,
    /// What loading the built-in textures cost.
    texture_report: TextureReport,
    last_lights: usize,
}

/// The built-in textures: how many, and what loading them cost.
#[derive(Clone, Copy, Debug)]
struct TextureReport {
    materials: usize,
    texels: u64,
    /// Decoding, uploading and the mip passes, waited for, in ms.
    load_ms: f64,
    /// The mip passes alone, on the GPU, in ms.
    mip_ms: f64,
}

impl Chapter for TexturesChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0202: the textures' mip levels differ most; outliers at most 0.1%. Worst 16×16 patch 0.236 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.04, outliers: 0.002, patch: 0.36 };
    const TITLE: &'static str = "09 · Textures";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
    const POST_ANTIALIASING: bool = true;
    const SNAPSHOT_TIME: f32 = 6.0;
    const BENCH_FRAMES: u32 = 5;
    const BENCH_BASELINE: Option<&'static str> = Some("no-normal-maps");
    const MAIN_SHADER: Option<&'static str> = Some("textures/textured.wgsl");
    const KEYS: &'static [(&'static str, &'static str)] = &[
        ("W A S D / arrows", "move"),
        ("E / Space, Q / Shift+Space", "rise, fall"),
        ("left drag, or Tab to lock", "look around"),
        ("[", "pause or resume the drones"),
        ("]", "pause or resume the cars"),
    ];
    const FLAGS: &'static [ChapterFlag] = &[ChapterFlag {
        name: "model",
        value_name: "PATH.obj",
        help: "Show this OBJ model (with its MTL and textures beside it) on the stage instead of the car",
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
        let device = &gpu.device;
        let builtin: Arc<anyhow::Result<BuiltinModels>> = gpu.cached((), BuiltinModels::load);
        let builtin = match builtin.as_ref() {
            Ok(models) => models,
            Err(error) => anyhow::bail!("the built-in models: {error:#}"),
        };
        let read: ReadFile = &builtin::read;
        let mut mips = MipMaker::new(gpu)?;
        let ((materials, models, warnings, mip_ms), load_ms) = common::timing::measure(|| {
            let mut up = Uploader::new(gpu, &mut mips, read);
            let mut materials = Materials::new(&mut up);
            materials.insert_image(&mut up, Path::new(scenes::CHECKER), &materials::checkerboard());
            let models = Models::upload(device, &mut up, &mut materials, builtin);
            let mip_ms = up.finish();
            let mut warnings = builtin.car.warnings.clone();
            warnings.extend(builtin.tower.warnings.iter().cloned());
            warnings.append(&mut materials.warnings);
            (materials, models, warnings, mip_ms)
        });
        let texture_report =
            TextureReport { materials: materials.list.len(), texels: materials.texels, load_ms, mip_ms };
        let scene_lights = SceneLights::new(gpu)?;
        let post = PostChain::new(gpu, target)?;
        let multisample = post.hdr().multisample();
        let renderer = TexturedRenderer::new(gpu, &scene_lights, &materials, multisample)?;
        let sky = CitySky::new(gpu, &scene_lights, multisample)?;
        let instances = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("instances"),
            size: 64 * std::mem::size_of::<ModelInstance>() as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let featured = Featured::car(device, &builtin.car, models.car.first_material);
        for warning in &warnings {
            eprintln!("warning: {warning}");
        }
        let (scene, camera) = CameraPreset::City.place(target.aspect());
        Ok(Self {
            settings: Settings::DAY,
            scene,
            camera,
            controller: FlyController { speed: 12.0, ..Default::default() },
            city: City::new(),
            clocks: Clocks::default(),
            last_time: 0.0,
            mips,
            materials,
            models,
            featured,
            renderer,
            instances,
            scene_lights,
            sky,
            post,
            target,
            warnings,
            texture_report,
            last_lights: 0,
        })
    }

    // ANCHOR: model_flag
    fn apply_flags(&mut self, gpu: &Gpu, flags: &FlagValues) -> anyhow::Result<()> {
        let Some(path) = flags.get("model") else { return Ok(()) };
        let featured = Featured::load(gpu, &mut self.mips, &mut self.materials, &PathBuf::from(path))?;
        for warning in &featured.warnings {
            eprintln!("warning: {warning}");
        }
        self.warnings.extend(featured.warnings.iter().cloned());
        self.featured = featured;
        Ok(())
    }
    // ANCHOR_END: model_flag

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.post.resize(gpu, target);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
    }

    fn reset_camera(&mut self, view: usize) {
        let preset = VIEW_TABLE[view].camera.unwrap_or(CameraPreset::City);
        (self.scene, self.camera) = preset.place(self.target.aspect());
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        if input.pressed(KeyCode::BracketLeft) {
            self.clocks.drones.set_paused(!self.clocks.drones.is_paused(), self.last_time);
        }
        if input.pressed(KeyCode::BracketRight) {
            self.clocks.cars.set_paused(!self.clocks.cars.is_paused(), self.last_time);
        }
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.last_time = frame.time;
        let s = self.settings;
        let day = daylight(s.time_of_day.phase(frame.time, 120.0));
        let camera = self.camera;

        // This frame's lights, instances and draws, by scene.
        let FrameDraws { lights, instances, draws } = match self.scene {
            Scene::City => {
                drawables::city_draws(gpu, &self.city, &self.clocks, &mut self.models.drones, frame.time, &day)
            }
            Scene::Stage => drawables::stage_draws(self.featured.placement, s.tangents),
            Scene::Lab => drawables::lab_draws(),
        };
        let lists = frame.timer.cpu("light culling", || clusters::cull(&camera, &lights));
        self.last_lights = lights.len();
        let highlight = match self.scene {
            Scene::Stage if self.featured.physical => Highlight::CookTorrance,
            _ => Highlight::BlinnPhong,
        };
        let options = LoopOptions { culling: true, highlight, heat_map: false };
        self.scene_lights.write(gpu, &camera, &day, &lights, &lists, options);
        self.sky.write(gpu, &camera, &day);
        let bytes = (instances.len() * std::mem::size_of::<ModelInstance>()) as u64;
        if bytes > self.instances.size() {
            self.instances = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("instances"),
                size: bytes.next_power_of_two(),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
        }
        gpu.queue.write_buffer(&self.instances, 0, bytemuck::cast_slice(&instances));
        let draws: Vec<Draw> = draws
            .into_iter()
            .map(|(which, instances)| Draw { model: self.models.get(which, &self.featured), instances })
            .collect();

        // The scene, in HDR, then the sky behind it.
        {
            let mut pass = self.post.hdr().pass(frame.encoder, frame.timer, "scene", wgpu::Color::BLACK);
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            let list = DrawList { materials: &self.materials, instances: &self.instances, draws };
            let surfaces = SurfaceOptions {
                shading: s.shading,
                sampler: s.sampler,
                normal_maps: s.normal_maps,
                flip_green: s.flip_green,
                swapped_colour_spaces: s.swapped_colour_spaces,
                show_frame: s.show_frame,
            };
            let mut drawn = self.renderer.draw(gpu, &mut pass, &surfaces, self.target.width, &list);
            if !s.show_frame {
                drawn += self.sky.draw(&mut pass);
            }
            frame.drawn.add("scene", drawn);
        }

        // Bloom, then tone mapping to the target (chapter 08's). The
        // tangent frame is shown as it is, not tone-mapped.
        let output = if s.show_frame { PostOutput::RawHdr } else { PostOutput::Picture };
        let bloom = s.bloom.then(BloomSettings::default);
        self.post.finish(gpu, frame, &PostSettings { output, exposure: s.exposure, bloom });
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let aspect = self.target.aspect();
        ui.horizontal(|ui| {
            ui.label("go to");
            for (label, preset) in
                [("city", CameraPreset::City), ("stage", CameraPreset::Car), ("sampling lab", CameraPreset::Lab)]
            {
                if ui.button(label).clicked() {
                    (self.scene, self.camera) = preset.place(aspect);
                }
            }
        });
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            ui.label("time of day");
            for time in TimeOfDay::ALL {
                ui.radio_value(&mut s.time_of_day, time, format!("{time:?}").to_lowercase());
            }
        });
        ui.horizontal(|ui| {
            ui.label("shading");
            ui.radio_value(&mut s.shading, Shading::Flat, "flat");
            ui.radio_value(&mut s.shading, Shading::Gouraud, "Gouraud");
            ui.radio_value(&mut s.shading, Shading::Phong, "Phong");
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("sampler");
            for (mode, label) in [
                (SamplerMode::Nearest, "nearest"),
                (SamplerMode::Linear, "bilinear"),
                (SamplerMode::Mipmaps, "trilinear (mipmaps)"),
                (SamplerMode::Anisotropic, "anisotropic 16x"),
            ] {
                ui.radio_value(&mut s.sampler, mode, label);
            }
        });
        if !self.renderer.anisotropy {
            ui.label("this adapter cannot filter anisotropically: 'anisotropic' is trilinear here");
        }
        ui.checkbox(&mut s.normal_maps, "normal maps (Phong shading only)");
        ui.checkbox(&mut s.flip_green, "read normal maps' green as down the image (DirectX)");
        ui.horizontal(|ui| {
            ui.label("tangents on the stage's primitives");
            ui.radio_value(&mut s.tangents, Tangents::PerVertex, "per vertex");
            ui.radio_value(&mut s.tangents, Tangents::PerFace, "per face");
        });
        ui.checkbox(&mut s.swapped_colour_spaces, "swap colour spaces (albedo as data, normal maps as sRGB)");
        ui.checkbox(&mut s.show_frame, "show the tangent frame (T | B | N)");
        ui.checkbox(&mut s.bloom, "bloom");
        ui.add(egui::Slider::new(&mut s.exposure, 0.1..=4.0).logarithmic(true).text("exposure"));
        self.featured.panel(ui, &self.materials);
        // The model's own warnings are in its panel.
        for warning in self.warnings.iter().filter(|w| !self.featured.warnings.contains(w)) {
            ui.colored_label(egui::Color32::from_rgb(230, 180, 60), warning);
        }
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        let TextureReport { materials, texels, load_ms, mip_ms } = self.texture_report;
        let f = &self.featured;
        let load = match (f.load_ms, f.peak_memory) {
            (Some(ms), Some(bytes)) => format!(", loaded in {ms:.0} ms, peak memory {} MiB", bytes / (1 << 20)),
            (Some(ms), None) => format!(", loaded in {ms:.0} ms"),
            _ => String::new(),
        };
        format!(
            "{materials} materials, {:.1} M texels: decoded, uploaded and mipmapped in {load_ms:.0} ms, of which the mip passes {mip_ms:.1} ms; model {}: {} triangles{load}; {} lights; anisotropic filtering {}",
            texels as f64 / 1e6,
            f.name,
            f.triangles,
            self.last_lights,
            if self.renderer.anisotropy { "available" } else { "not available" },
        )
    }
}
