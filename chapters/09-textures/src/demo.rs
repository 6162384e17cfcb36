//! The chapter itself: the settings each view applies, the views and
//! where they put the camera, the built-in and featured models, and `impl
//! Chapter`, which composes chapter 08's lights, sky and post chain with
//! the textured renderer into a frame.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use common::args::UsageError;
use common::glam::{Mat4, Quat, Vec3};
use common::{
    Camera, Chapter, ChapterFlag, FlagValues, FlyController, Frame, Gpu, Input, Preparation, Target, View, ViewRow,
    anyhow, egui, views_of, wgpu, winit::keyboard::KeyCode,
};
use lighting::bloom::BloomSettings;
use lighting::city::{City, Clocks};
use lighting::clusters;
use lighting::lights::{Daylight, Light, TimeOfDay, daylight};
use lighting::{
    CitySky, Highlight, LightCount, LoopOptions, PostChain, PostOutput, PostSettings, SceneLights, Shading,
};

use crate::builtin;
use crate::materials::{self, Materials, SamplerMode, Uploader};
use crate::mesh::{GpuModel, MaterialDesc, ModelData, ModelInstance};
use crate::mipmaps::MipMaker;
use crate::obj::{self, LoadedModel, ReadFile};
use crate::scenes;
use crate::textured_renderer::{Draw, DrawList, SurfaceOptions, TexturedRenderer, upload_model};

// ANCHOR: views
/// Every view, once: what it shows, and for a preset where the camera goes.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 16] = [
    ViewRow::mode("day", "the textured city at noon, from above", Settings::DAY),
    ViewRow::mode(
        "night",
        "the textured city at night: lit windows, lamps, headlights",
        Settings { time_of_day: TimeOfDay::Night, ..Settings::DAY },
    ),
    ViewRow::preset(
        "car",
        "the car model and its five materials on the stage (or the model given with --model)",
        Settings::STAGE,
        CameraPreset::Car,
    ),
    ViewRow::preset(
        "normal-maps",
        "the stage in a low sun: normal maps give brick, panels and concrete their relief",
        Settings::STAGE,
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "no-normal-maps",
        "the same without normal maps: flat, as if painted",
        Settings { normal_maps: false, ..Settings::STAGE },
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "gouraud",
        "the same stage lit per vertex, the textures still read per pixel: no relief, the lamp's pool smeared",
        Settings { shading: Shading::Gouraud, ..Settings::STAGE },
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "flat",
        "lit once per face: facets of one light each, the bricks still sharp within them",
        Settings { shading: Shading::Flat, ..Settings::STAGE },
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "vertex-tangents",
        "close over the sphere's pole in a low evening sun, one tangent per vertex: the joints' bevels shade smoothly",
        Settings { time_of_day: TimeOfDay::Evening, ..Settings::STAGE },
        CameraPreset::SphereTop,
    ),
    ViewRow::preset(
        "face-tangents",
        "the same with one tangent per triangle, as the seed did: the bevels' shading jumps at every edge",
        Settings { time_of_day: TimeOfDay::Evening, tangents: Tangents::PerFace, ..Settings::STAGE },
        CameraPreset::SphereTop,
    ),
    ViewRow::preset(
        "tbn",
        "the tangent frame as colours: tangent (left third), bitangent (middle), normal (right)",
        Settings { show_frame: true, ..Settings::STAGE },
        CameraPreset::WholeStage,
    ),
    ViewRow::preset(
        "wrong-colour-space",
        "albedo read as data and normal maps as sRGB: washed-out colour, bent light",
        Settings { swapped_colour_spaces: true, ..Settings::STAGE },
        CameraPreset::Car,
    ),
    ViewRow::preset(
        "nearest",
        "a checkerboard to the horizon, nearest texel: blocky near, moiré far",
        Settings { sampler: SamplerMode::Nearest, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::preset(
        "linear",
        "the same, bilinear: smooth near, still moiré far",
        Settings { sampler: SamplerMode::Linear, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::preset(
        "mipmaps",
        "trilinear filtering with mipmaps: no moiré, but the distance turns grey",
        Settings { sampler: SamplerMode::Mipmaps, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::preset(
        "anisotropic",
        "anisotropic filtering (16x): the squares stay sharp much further",
        Settings { sampler: SamplerMode::Anisotropic, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::no_aa("day", Settings::DAY),
];
// ANCHOR_END: views

/// Which set the camera is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scene {
    /// Chapter 08's city, textured, with car models and the tower.
    City,
    /// A model on a stage, with a brick wall and a row of primitives.
    Stage,
    /// A checkerboard floor to the horizon, for comparing samplers.
    Lab,
}

/// Where tangents come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tangents {
    /// Averaged per vertex and made orthogonal to its normal.
    PerVertex,
    /// One per triangle (the seed's way), on the stage's primitives.
    PerFace,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub time_of_day: TimeOfDay,
    /// Lit per face, per vertex or per fragment (chapter 08's switch).
    pub shading: Shading,
    pub sampler: SamplerMode,
    pub normal_maps: bool,
    /// Read normal maps' green as pointing down the image (DirectX's way).
    pub flip_green: bool,
    pub tangents: Tangents,
    /// Albedo read as linear data and normal maps as sRGB: the mistake.
    pub swapped_colour_spaces: bool,
    /// Show the tangent frame as colours instead of the picture.
    pub show_frame: bool,
    pub bloom: bool,
    pub exposure: f32,
}

impl Settings {
    /// The textured city at noon: what the chapter starts with.
    pub const DAY: Self = Self {
        time_of_day: TimeOfDay::Noon,
        shading: Shading::Phong,
        // Trilinear: anisotropic filtering is sharper, and about twenty
        // times dearer on a software rasteriser (see the bench).
        sampler: SamplerMode::Mipmaps,
        normal_maps: true,
        flip_green: false,
        tangents: Tangents::PerVertex,
        swapped_colour_spaces: false,
        show_frame: false,
        bloom: true,
        exposure: 1.0,
    };

    /// The stage's views: the morning sun.
    pub const STAGE: Self = Self { time_of_day: TimeOfDay::Morning, ..Self::DAY };

    /// The sampling lab's views: black and white squares, so no bloom, and
    /// an exposure that keeps white below the shoulder of the tone curve.
    pub const LAB: Self = Self { bloom: false, exposure: 0.5, ..Self::DAY };
}

/// Where a preset puts the camera, and in which scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// Above the city (chapter 08's aerial camera): where the chapter
    /// starts, and where "reset camera" takes the modes.
    City,
    /// In front of the stage, on the featured model.
    Car,
    /// The left of the stage: the wall, the sphere, the torus and the
    /// cone, in a low sun from the side.
    Wall,
    /// The whole stage from the front, a little above.
    WholeStage,
    /// Close over the top of the stage's sphere, where its texture's u
    /// lines circle the pole: where one tangent per triangle strays
    /// furthest from one per vertex.
    SphereTop,
    /// Standing on the sampling lab's checkerboard, looking to the horizon.
    Lab,
}

impl CameraPreset {
    /// The scene this preset is in, and the camera there for a target of `aspect`.
    pub fn place(self, aspect: f32) -> (Scene, Camera) {
        let at = |eye: Vec3, target: Vec3| Camera { near: 0.1, far: 900.0, ..Camera::looking_at(eye, target, aspect) };
        match self {
            Self::City => (Scene::City, lighting::aerial_camera(aspect)),
            Self::Car => (Scene::Stage, at(Vec3::new(-3.3, 1.9, 4.3), Vec3::new(0.2, 0.7, 0.0))),
            Self::Wall => (Scene::Stage, at(Vec3::new(-2.2, 1.5, 0.9), Vec3::new(-6.4, 0.9, -3.6))),
            Self::WholeStage => (Scene::Stage, at(Vec3::new(0.0, 4.2, 10.5), Vec3::new(0.0, 1.0, -2.0))),
            Self::SphereTop => (Scene::Stage, at(Vec3::new(-3.95, 2.15, -2.85), Vec3::new(-3.8, 1.5, -3.3))),
            Self::Lab => (
                Scene::Lab,
                Camera {
                    near: 0.1,
                    far: 1500.0,
                    ..Camera::looking_at(Vec3::new(0.0, 1.7, 0.0), Vec3::new(0.0, 0.0, -30.0), aspect)
                },
            ),
        }
    }
}

/// The CPU side of every built-in model, made once per device and shared
/// by every instance of the chapter (`Gpu::cached`): tangents for a whole
/// city take a while in a debug build.
pub struct BuiltinModels {
    pub city: ModelData,
    pub stage: ModelData,
    pub stage_face_tangents: ModelData,
    pub lab: ModelData,
    pub car: LoadedModel,
    pub tower: LoadedModel,
}

impl BuiltinModels {
    fn load() -> anyhow::Result<Self> {
        let read: ReadFile = &builtin::read;
        let stage = scenes::stage_set();
        Ok(Self {
            city: scenes::textured_city(&City::new()),
            stage_face_tangents: stage.with_face_tangents(),
            stage,
            lab: scenes::lab_floor(),
            car: obj::load(Path::new("models/car/car.obj"), read)?,
            tower: obj::load(Path::new("models/tower/tower.obj"), read)?,
        })
    }
}

/// The featured model on the stage: the car, or the learner's.
pub struct Featured {
    pub name: String,
    pub model: GpuModel,
    pub placement: Mat4,
    pub triangles: usize,
    pub vertices: usize,
    pub objects: usize,
    /// Its materials: `model.first_material` onwards, this many.
    pub materials: usize,
    /// Whether its vertices carry colours.
    pub vertex_colours: bool,
    /// Whether its MTL gives roughness or metalness (Pr, Pm): a model made
    /// for physically based shading, which the stage then shades with
    /// chapter 08's Cook-Torrance instead of Blinn-Phong.
    pub physical: bool,
    /// The model's own warnings (the chapter's `warnings` hold them too).
    pub warnings: Vec<String>,
    /// Scale applied to fit the stage, and the load time and memory (for
    /// a learner's model).
    pub scale: f32,
    pub load_ms: Option<f64>,
    pub peak_memory: Option<u64>,
}

impl Featured {
    /// The model's facts, as the overlay's model panel gives them.
    pub fn facts(&self) -> String {
        format!(
            "model: {}: {} triangles, {} vertices, {} objects, scaled ×{:.3} to fit{}",
            self.name,
            self.triangles,
            self.vertices,
            self.objects,
            self.scale,
            if self.vertex_colours { "; it has vertex colours" } else { "" },
        ) + if self.physical { "; shaded by Cook-Torrance (its MTL gives Pr, Pm or their maps)" } else { "" }
    }
}

/// Everything drawable, on the GPU.
struct Models {
    city: GpuModel,
    drones: GpuModel,
    car: GpuModel,
    tower: GpuModel,
    stage: GpuModel,
    stage_face_tangents: GpuModel,
    lab: GpuModel,
}

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

impl TexturesChapter {
    /// The city at this moment: lights, and the instances and draws for the
    /// textured city, the tower, the car models and the drones.
    fn city_frame(
        &mut self,
        gpu: &Gpu,
        time: f32,
        day: &Daylight,
        instances: &mut Vec<ModelInstance>,
    ) -> (Vec<Light>, Vec<(Which, std::ops::Range<u32>)>) {
        let traffic = self.city.traffic(self.clocks.cars.time(time), self.clocks.drones.time(time));
        let lights = lighting::frame_lights(&self.city, &traffic, &[], LightCount::City, day.night);
        let drones = scenes::bake(&traffic.drone_parts);
        self.models.drones.update(&gpu.device, &gpu.queue, &drones);
        let mut draws = Vec::new();
        let mut push = |which, list: Vec<ModelInstance>| {
            let start = instances.len() as u32;
            instances.extend(list);
            draws.push((which, start..instances.len() as u32));
        };
        push(Which::City, vec![ModelInstance::new(Mat4::IDENTITY, 1.0)]);
        push(Which::Drones, vec![ModelInstance::new(Mat4::IDENTITY, 1.0)]);
        // The tower's windows light up as night falls.
        push(Which::Tower, vec![ModelInstance::new(scenes::tower_placement(), day.night)]);
        let cars = traffic
            .cars
            .iter()
            .map(|pose| {
                ModelInstance::new(
                    Mat4::from_rotation_translation(Quat::from_rotation_y(pose.heading), pose.position),
                    1.0,
                )
            })
            .collect();
        push(Which::Car, cars);
        (lights, draws)
    }

    /// What the featured model is made of: counts, materials and where
    /// their textures were found, and what loading it warned about.
    fn model_panel(&self, ui: &mut egui::Ui) {
        let f = &self.featured;
        ui.label(f.facts());
        let first = f.model.first_material;
        let materials = self.materials.list.get(first..first + f.materials).unwrap_or_default();
        egui::CollapsingHeader::new(format!("its {} materials and their textures", materials.len()))
            .id_salt("model materials")
            .show(ui, |ui| {
                for material in materials {
                    let d = &material.desc;
                    ui.label(format!(
                        "{}: colour {:.2} {:.2} {:.2}{}",
                        d.name,
                        d.diffuse.x,
                        d.diffuse.y,
                        d.diffuse.z,
                        if material.maps.is_empty() { ", no textures" } else { "" }
                    ));
                    for (what, source) in &material.maps {
                        ui.small(format!("    {what}: {source}"));
                    }
                }
                for warning in &f.warnings {
                    ui.colored_label(egui::Color32::from_rgb(230, 180, 60), warning);
                }
            });
    }
}

/// Refuses a model whose buffers this GPU cannot hold, before trying to
/// make them (which would end the program).
fn check_fits(gpu: &Gpu, path: &Path, model: &ModelData) -> Result<(), UsageError> {
    let limit = gpu.device.limits().max_buffer_size;
    let vertex_bytes = (model.vertices.len() * std::mem::size_of::<crate::mesh::TexturedVertex>()) as u64;
    let index_bytes = (model.indices.len() * 4) as u64;
    if vertex_bytes.max(index_bytes) > limit {
        return Err(UsageError(format!(
            "--model: {}: {} vertices and {} triangles need {} MiB, more than the {} MiB this GPU allows in one buffer",
            path.display(),
            model.vertices.len(),
            model.triangle_count(),
            vertex_bytes.max(index_bytes) >> 20,
            limit >> 20
        )));
    }
    Ok(())
}

/// Which model a draw uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Which {
    City,
    Drones,
    Tower,
    Car,
    Featured,
    Stage,
    StageFaceTangents,
    Lab,
}

impl Chapter for TexturesChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0202: the textures' mip levels differ most; outliers at most 0.1%. Worst 16×16 patch 0.236 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.04, outliers: 0.002, patch: 0.36 };
    const TITLE: &'static str = "09 · Textures";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);
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
            let mut model = |data: &ModelData, label| upload_model(&mut up, &mut materials, data, label);
            let city = model(&builtin.city, "city");
            let models = Models {
                drones: GpuModel::upload(device, &ModelData::default(), city.first_material, "drones"),
                car: model(&builtin.car.model, "car"),
                tower: model(&builtin.tower.model, "tower"),
                stage: model(&builtin.stage, "stage"),
                stage_face_tangents: model(&builtin.stage_face_tangents, "stage, face tangents"),
                lab: model(&builtin.lab, "lab"),
                city,
            };
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
        let (placement, scale) = scenes::stage_placement(builtin.car.model.bounds());
        let featured = Featured {
            name: "the car (assets/models/car/car.obj)".into(),
            // The car's own buffers again, with the car's materials.
            model: GpuModel::upload(device, &builtin.car.model, models.car.first_material, "featured"),
            placement,
            triangles: builtin.car.model.triangle_count(),
            vertices: builtin.car.model.vertices.len(),
            objects: builtin.car.objects,
            materials: builtin.car.model.materials.len(),
            vertex_colours: builtin.car.vertex_colours,
            physical: builtin.car.model.materials.iter().any(MaterialDesc::is_physical),
            warnings: builtin.car.warnings.clone(),
            scale,
            load_ms: None,
            peak_memory: None,
        };
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
        let path = PathBuf::from(path);
        let read: ReadFile = &|p: &Path| common::files::read(p);
        let (loaded, load_ms) = common::timing::measure(|| obj::load(&path, read));
        let loaded = loaded.map_err(|e| UsageError(format!("--model: {e}")))?;
        check_fits(gpu, &path, &loaded.model)?;
        let mut up = Uploader::new(gpu, &mut self.mips, read);
        let model = upload_model(&mut up, &mut self.materials, &loaded.model, "model");
        up.finish();
        let (placement, scale) = scenes::stage_placement(loaded.model.bounds());
        let mut warnings = loaded.warnings;
        warnings.append(&mut self.materials.warnings);
        for warning in &warnings {
            eprintln!("warning: {warning}");
        }
        self.warnings.extend(warnings.iter().cloned());
        self.featured = Featured {
            name: path.display().to_string(),
            model,
            placement,
            triangles: loaded.model.triangle_count(),
            vertices: loaded.model.vertices.len(),
            objects: loaded.objects,
            materials: loaded.model.materials.len(),
            vertex_colours: loaded.vertex_colours,
            physical: loaded.model.materials.iter().any(MaterialDesc::is_physical),
            warnings,
            scale,
            load_ms: Some(load_ms),
            peak_memory: common::memory::peak_process_bytes(),
        };
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
        let mut instances = Vec::new();
        let (lights, draws) = match self.scene {
            Scene::City => self.city_frame(gpu, frame.time, &day, &mut instances),
            Scene::Stage => {
                instances.push(ModelInstance::new(Mat4::IDENTITY, 1.0));
                instances.push(ModelInstance::new(self.featured.placement, 1.0));
                let set = if s.tangents == Tangents::PerFace { Which::StageFaceTangents } else { Which::Stage };
                (scenes::stage_lights(), vec![(set, 0..1), (Which::Featured, 1..2)])
            }
            Scene::Lab => {
                instances.push(ModelInstance::new(Mat4::IDENTITY, 1.0));
                (Vec::new(), vec![(Which::Lab, 0..1)])
            }
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
        let models = &self.models;
        let draws: Vec<Draw> = draws
            .into_iter()
            .map(|(which, instances)| Draw {
                model: match which {
                    Which::City => &models.city,
                    Which::Drones => &models.drones,
                    Which::Tower => &models.tower,
                    Which::Car => &models.car,
                    Which::Featured => &self.featured.model,
                    Which::Stage => &models.stage,
                    Which::StageFaceTangents => &models.stage_face_tangents,
                    Which::Lab => &models.lab,
                },
                instances,
            })
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
        self.model_panel(ui);
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
