//! Chapter 05: instancing. One rock mesh, up to a million rocks, one draw
//! call; and the same rocks drawn one call at a time, to see why it matters.
//! The scene is the Mars plain so far: terrain, fog and rocks, put together
//! as a `MarsPlain` that chapters 06 and 07 reuse.

use std::sync::Arc;

use common::glam::{Vec3, Vec4};
use common::texture::{depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, Mesh, MeshData, ShaderError, ShaderFile, Target, Vertex, View,
    anyhow, egui, shader, wgpu,
};
use fog::{FogBinding, FogSettings, fog_shader};
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer, Viewpoint};

// ANCHOR: rng
/// SplitMix64: a tiny, fast, seedable random number generator. Same seed,
/// same rocks, on every machine, which is what snapshots need.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1): the top 24 bits, which an f32 holds exactly.
    pub fn unit(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32
    }

    pub fn range(&mut self, low: f32, high: f32) -> f32 {
        low + (high - low) * self.unit()
    }
}
// ANCHOR_END: rng

// ANCHOR: rock_mesh
/// A low-poly rock: an icosahedron whose twelve corners are pushed in or
/// out at random, squashed, and shaded flat, so each of its 20 faces
/// catches the light on its own. 60 vertices.
pub fn rock_mesh(seed: u64) -> MeshData {
    let t = (1.0 + 5f32.sqrt()) / 2.0;
    let corners = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    const FACES: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let mut rng = Rng::new(seed);
    let points: Vec<Vec3> = corners
        .iter()
        .map(|&c| {
            let p = Vec3::from(c).normalize() * rng.range(0.75, 1.15) * 0.5;
            // Flatter than tall, and sitting on its base.
            Vec3::new(p.x, p.y * 0.8 + 0.1, p.z)
        })
        .collect();
    let mut mesh = MeshData::default();
    for face in FACES {
        let [a, b, c] = face.map(|i| points[i]);
        let normal = (b - a).cross(c - a).normalize();
        for p in [a, b, c] {
            mesh.indices.push(mesh.vertices.len() as u32);
            mesh.vertices.push(Vertex { position: p.into(), normal: normal.into(), uv: [0.0; 2] });
        }
    }
    mesh
}
// ANCHOR_END: rock_mesh

// ANCHOR: instance
/// One rock as the GPU reads it (`Rock` in rocks.wgsl): 32 bytes, against
/// 64 for a full model matrix. A million rocks are 32 MB.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RockInstance {
    pub position: [f32; 3],
    pub yaw: f32,
    pub scale: [f32; 3],
    pub shade: f32,
}

impl RockInstance {
    /// `step_mode: Instance`: the GPU moves to the next `RockInstance` once
    /// per instance, while the mesh's vertices (buffer 0) step per vertex.
    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<RockInstance>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &wgpu::vertex_attr_array![3 => Float32x4, 4 => Float32x4],
    };
}
// ANCHOR_END: instance

// ANCHOR: scatter
/// How many places a rock may try before the scatter gives up on it.
pub const ATTEMPTS_PER_ROCK: usize = 20;

/// Up to `count` rocks scattered over a 1.6 km square of the plain in front
/// of the start camera, each on the ground, half buried, never on a steep
/// slope. Placement is uniform, so the first n of them are a fair sample at
/// any n: the rock-count slider just draws fewer. A random place on a slope
/// is rejected and another tried; on terrain that is steep almost
/// everywhere (the sliders can make it so) that could go on for ever, so
/// after `ATTEMPTS_PER_ROCK × count` tries the scatter stops, with fewer rocks.
pub fn scatter(field: &HeightField, count: usize, seed: u64) -> Vec<RockInstance> {
    let mut rng = Rng::new(seed);
    let centre = plain_camera(field, 1.0).position;
    let mut rocks = Vec::with_capacity(count);
    for _ in 0..count.saturating_mul(ATTEMPTS_PER_ROCK) {
        if rocks.len() == count {
            break;
        }
        let x = centre.x + rng.range(-800.0, 800.0);
        let z = centre.z + rng.range(-1400.0, 200.0);
        // Dust does not stay on steep slopes, and neither do rocks.
        let normal = field.normal((x / field.settings.spacing) as i64, (z / field.settings.spacing) as i64);
        if normal.y < 0.9 {
            continue;
        }
        // Many small rocks, a few large ones.
        let size = 0.3 + 1.8 * rng.unit().powi(2);
        let scale = [size * rng.range(0.8, 1.5), size * rng.range(0.7, 1.3), size * rng.range(0.8, 1.5)];
        let y = field.height_at(x, z) - 0.15 * scale[1];
        rocks.push(RockInstance {
            position: [x, y, z],
            yaw: rng.range(0.0, std::f32::consts::TAU),
            scale,
            shade: rng.unit(),
        });
    }
    rocks
}
// ANCHOR_END: scatter

/// Standing on the plain, eyes 3.5 m up, looking across the rocks at the cliff.
pub fn plain_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47 + 60.0;
    let z = s.cliff_line(x) + 230.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 3.5, z);
    let ahead = Vec3::new(x + 40.0, 0.0, z - 200.0);
    let target = Vec3::new(ahead.x, field.height_at(ahead.x, ahead.z) + 2.0, ahead.z);
    Camera { far: fog::MAX_FAR, near: 0.1, ..Camera::looking_at(eye, target, aspect) }
}

/// How the rocks are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// All rocks in one instanced draw call.
    Instanced,
    /// One draw call per rock, each with its own uniform offset.
    OnePerDraw,
    /// Instanced, with a flat colour and no lighting or fog: the floor.
    Flat,
}

/// What a view shows: the rock count, how they are drawn, and whether the
/// terrain is drawn too (the bench views leave it out so that the numbers
/// are the rocks' alone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    pub rocks: u32,
    pub mode: Mode,
    pub terrain: bool,
}

pub const VIEWS: &[View] = &[
    View::mode("default", "the Mars plain: terrain, fog and 200,000 rocks in one draw call"),
    View::mode("naive", "the same plain with 2,000 rocks, one draw call each"),
    View::mode("rocks-10k", "bench: 10,000 rocks, instanced, no terrain"),
    View::mode("rocks-100k", "bench: 100,000 rocks, instanced, no terrain"),
    View::mode("rocks-1m", "bench: 1,000,000 rocks, instanced, no terrain"),
    View::mode("naive-10k", "bench: 10,000 rocks, one draw call each, no terrain"),
    View::mode("flat-1m", "bench: 1,000,000 rocks, instanced, flat colour: the cost floor"),
];

fn setup_for(view: &str) -> Setup {
    let (rocks, mode, terrain) = match view {
        "naive" => (2_000, Mode::OnePerDraw, true),
        "rocks-10k" => (10_000, Mode::Instanced, false),
        "rocks-100k" => (100_000, Mode::Instanced, false),
        "rocks-1m" => (1_000_000, Mode::Instanced, false),
        "naive-10k" => (10_000, Mode::OnePerDraw, false),
        "flat-1m" => (1_000_000, Mode::Flat, false),
        _ => (200_000, Mode::Instanced, true),
    };
    Setup { rocks, mode, terrain }
}

/// The most rocks the instance buffer holds, and the most drawn one by one.
pub const MAX_ROCKS: u32 = 1_000_000;
pub const MAX_ONE_PER_DRAW: u32 = 20_000;
const SEED: u64 = 5;

/// The rocks on the GPU: the one mesh, every rock's instance record, and
/// the first `MAX_ONE_PER_DRAW` of them again, one per 256-byte uniform
/// slot, for the one-draw-per-rock comparison. Made once per terrain and
/// device, and shared (a million rocks take a moment to scatter).
pub struct RockField {
    mesh: Mesh,
    instances: wgpu::Buffer,
    singles: wgpu::Buffer,
    single_stride: u32,
    /// How many rocks the scatter placed (fewer than `MAX_ROCKS` only on
    /// terrain too steep for them).
    pub placed: u32,
}

impl RockField {
    pub fn get(gpu: &Gpu, field: &HeightField) -> Arc<Self> {
        gpu.cached((field.settings, SEED), || {
            let device = &gpu.device;
            let rocks = scatter(field, MAX_ROCKS as usize, SEED);
            let instances = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("rock instances"),
                contents: bytemuck::cast_slice(&rocks),
                usage: wgpu::BufferUsages::VERTEX,
            });
            let single_stride = (std::mem::size_of::<RockInstance>() as u32)
                .next_multiple_of(device.limits().min_uniform_buffer_offset_alignment);
            let mut slots = vec![0u8; single_stride as usize * MAX_ONE_PER_DRAW as usize];
            for (slot, rock) in slots.chunks_exact_mut(single_stride as usize).zip(&rocks) {
                slot[..std::mem::size_of::<RockInstance>()].copy_from_slice(bytemuck::bytes_of(rock));
            }
            let singles = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("one rock per slot"),
                contents: &slots,
                usage: wgpu::BufferUsages::UNIFORM,
            });
            Self {
                mesh: rock_mesh(SEED).upload(device, "rock"),
                instances,
                singles,
                single_stride,
                placed: rocks.len() as u32,
            }
        })
    }
}

fn rocks_shader() -> ShaderFile {
    shader!("instancing/rocks.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl"])
}

struct RockPipelines {
    instanced: wgpu::RenderPipeline,
    one_per_draw: wgpu::RenderPipeline,
    flat: wgpu::RenderPipeline,
}

fn rock_pipeline(
    gpu: &Gpu,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    format: wgpu::TextureFormat,
    vertex_entry: &str,
    fragment_entry: &str,
) -> wgpu::RenderPipeline {
    let instanced = vertex_entry == "vs_instanced";
    let buffers = [Some(Vertex::LAYOUT), instanced.then_some(RockInstance::LAYOUT)];
    gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(vertex_entry),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vertex_entry),
            buffers: if instanced { &buffers } else { &buffers[..1] },
            compilation_options: Default::default(),
        },
        primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
        depth_stencil: depth_test(),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fragment_entry),
            targets: &[Some(format.into())],
            compilation_options: Default::default(),
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Draw calls recorded for one picture of the plain.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawCalls {
    /// One per terrain chunk in view.
    pub terrain: u32,
    /// One for all rocks, or one per rock.
    pub rocks: u32,
}

impl DrawCalls {
    pub fn total(&self) -> u32 {
        self.terrain + self.rocks
    }
}

// ANCHOR: mars_plain
/// The Mars plain: chapter 03's terrain in chapter 04's fog, strewn with this
/// chapter's rocks. Chapters 05, 06 and 07 each own one and draw it through
/// explicit inputs: a viewpoint aimed from a camera, the sun, the air, and
/// what the picture should show.
pub struct MarsPlain {
    pub terrain: TerrainRenderer,
    rocks: Arc<RockField>,
    /// The fog's uniform (group 1), the same for every picture of a frame.
    pub fog: FogBinding,
    singles_group: wgpu::BindGroup,
    layouts: [wgpu::PipelineLayout; 2],
    terrain_pipeline: wgpu::RenderPipeline,
    rock_pipelines: RockPipelines,
    format: wgpu::TextureFormat,
}
// ANCHOR_END: mars_plain

impl MarsPlain {
    /// The plain for targets of `format`.
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let terrain = TerrainRenderer::new(gpu, TerrainSettings::default());
        let rocks = RockField::get(gpu, terrain.field());
        let fog = FogBinding::new(device);
        let single_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("one rock"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: true,
                    min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<RockInstance>() as u64),
                },
                count: None,
            }],
        });
        let layout = |label, groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        let shared = [Some(&terrain.bind_group_layout), Some(&fog.layout)];
        let layouts =
            [layout("rocks", &shared), layout("one rock per draw", &[shared[0], shared[1], Some(&single_layout)])];
        let terrain_pipeline = terrain.pipeline(gpu, &fog_shader(), &layouts[0], format)?;
        let rock_pipelines = Self::build_rock_pipelines(gpu, &layouts, format)?;
        let singles_group = Self::singles_group(device, &single_layout, &rocks);
        Ok(Self { terrain, rocks, fog, singles_group, layouts, terrain_pipeline, rock_pipelines, format })
    }

    fn build_rock_pipelines(
        gpu: &Gpu,
        layouts: &[wgpu::PipelineLayout; 2],
        format: wgpu::TextureFormat,
    ) -> Result<RockPipelines, ShaderError> {
        let module = rocks_shader().module(gpu)?;
        gpu.catch_validation(|| RockPipelines {
            instanced: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_main"),
            one_per_draw: rock_pipeline(gpu, &module, &layouts[1], format, "vs_single", "fs_main"),
            flat: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_flat"),
        })
        .map_err(ShaderError)
    }

    fn singles_group(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, rocks: &RockField) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("one rock"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &rocks.singles,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<RockInstance>() as u64),
                }),
            }],
        })
    }

    /// How many rocks there are to draw.
    pub fn rocks_placed(&self) -> u32 {
        self.rocks.placed
    }

    /// Makes the terrain again from `self.terrain.settings`, and the rocks on it.
    pub fn regenerate(&mut self, gpu: &Gpu) {
        self.terrain.regenerate(gpu);
        self.rocks = RockField::get(gpu, self.terrain.field());
        let layout = self.rock_pipelines.one_per_draw.get_bind_group_layout(2);
        self.singles_group = Self::singles_group(&gpu.device, &layout, &self.rocks);
    }

    /// Sets the air every picture of this frame is seen through: `fog`, in
    /// the colour `fog_colour` (linear RGB).
    pub fn set_air(&self, queue: &wgpu::Queue, fog: FogSettings, fog_colour: [f32; 3]) {
        self.fog.write_with_colour(queue, fog, fog_colour);
    }

    /// Aims `viewpoint` from `camera`, lit by `sun`, keeping what `clip` keeps.
    pub fn aim(&self, queue: &wgpu::Queue, viewpoint: &mut Viewpoint, camera: &Camera, sun: Sun, clip: Vec4) {
        self.terrain.aim(queue, viewpoint, camera, sun, Shading::Shaded, clip);
    }

    // ANCHOR: draw
    /// Records the terrain (unless `setup` leaves it out) and `setup.rocks`
    /// rocks into `pass`, as seen from `viewpoint`.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &Viewpoint, setup: Setup) -> DrawCalls {
        // Group 0 (camera, sun) and group 1 (fog) serve the terrain and the rocks alike.
        pass.set_bind_group(1, &self.fog.group, &[]);
        self.terrain.bind(pass, viewpoint);
        let mut calls = DrawCalls::default();
        if setup.terrain {
            pass.set_pipeline(&self.terrain_pipeline);
            calls.terrain = self.terrain.draw(pass, viewpoint) as u32;
        }
        calls.rocks = self.draw_rocks(pass, setup);
        calls
    }
    // ANCHOR_END: draw

    // ANCHOR: draw_rocks
    /// Draws the first `setup.rocks` rocks; returns the number of draw calls.
    fn draw_rocks(&self, pass: &mut wgpu::RenderPass<'_>, setup: Setup) -> u32 {
        let Setup { mode, .. } = setup;
        let rocks = setup.rocks.min(self.rocks.placed);
        let mesh = &self.rocks.mesh;
        pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
        pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        match mode {
            Mode::Instanced | Mode::Flat => {
                let pipeline =
                    if mode == Mode::Flat { &self.rock_pipelines.flat } else { &self.rock_pipelines.instanced };
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(1, self.rocks.instances.slice(..));
                // Every rock, one call: the GPU loops over the instances itself.
                pass.draw_indexed(0..mesh.index_count, 0, 0..rocks);
                1
            }
            Mode::OnePerDraw => {
                pass.set_pipeline(&self.rock_pipelines.one_per_draw);
                let rocks = rocks.min(MAX_ONE_PER_DRAW);
                for i in 0..rocks {
                    // A bind group change and a draw per rock, validated and
                    // recorded one by one: this is the cost instancing removes.
                    pass.set_bind_group(2, &self.singles_group, &[i * self.rocks.single_stride]);
                    pass.draw_indexed(0..mesh.index_count, 0, 0..1);
                }
                rocks
            }
        }
    }
    // ANCHOR_END: draw_rocks

    /// Rebuilds the terrain and rock pipelines from the WGSL on disk.
    pub fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        let terrain = self.terrain.pipeline(gpu, &fog_shader(), &self.layouts[0], self.format)?;
        self.rock_pipelines = Self::build_rock_pipelines(gpu, &self.layouts, self.format)?;
        self.terrain_pipeline = terrain;
        Ok(())
    }
}

pub struct InstancingChapter {
    pub plain: MarsPlain,
    pub fog: FogSettings,
    pub setup: Setup,
    pub camera: Camera,
    pub controller: FlyController,
    viewpoint: Viewpoint,
    depth: wgpu::TextureView,
    target: Target,
    /// Draw calls in the last frame.
    pub draw_calls: DrawCalls,
    regenerate_requested: bool,
}

impl Chapter for InstancingChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "05 · Instancing";
    const VIEWS: &'static [View] = VIEWS;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn gpu_needs() -> common::GpuNeeds {
        terrain::gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    fn prepare(gpu: &Gpu) -> Option<common::Preparation> {
        terrain::TerrainData::prepare(gpu, TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let plain = MarsPlain::new(gpu, target.format)?;
        Ok(Self {
            camera: plain_camera(plain.terrain.field(), target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            fog: FogSettings::HAZE,
            setup: setup_for("default"),
            viewpoint: plain.terrain.viewpoint(&gpu.device),
            plain,
            depth: depth_view(&gpu.device, target.width, target.height),
            target,
            draw_calls: DrawCalls::default(),
            regenerate_requested: false,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
    }

    fn apply_view(&mut self, view: usize) {
        self.setup = setup_for(VIEWS[view].name);
    }

    fn reset_camera(&mut self, _view: usize) {
        self.camera = plain_camera(self.plain.terrain.field(), self.target.aspect());
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
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
        self.plain.aim(&gpu.queue, &mut self.viewpoint, &self.camera, Sun::AFTERNOON, KEEP_ALL);
        let mut pass = frame.scene_pass("terrain and rocks", SKY, &self.depth);
        self.draw_calls = self.plain.draw(&mut pass, &self.viewpoint, self.setup);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.setup;
        ui.horizontal(|ui| {
            ui.radio_value(&mut s.mode, Mode::Instanced, "instanced");
            ui.radio_value(&mut s.mode, Mode::OnePerDraw, "one draw per rock");
            ui.radio_value(&mut s.mode, Mode::Flat, "flat");
        });
        let max = if s.mode == Mode::OnePerDraw { MAX_ONE_PER_DRAW } else { self.plain.rocks_placed() };
        s.rocks = s.rocks.min(max);
        ui.add(egui::Slider::new(&mut s.rocks, 0..=max).logarithmic(true).text("rocks"));
        ui.checkbox(&mut s.terrain, "terrain");
        let calls = self.draw_calls;
        ui.label(format!(
            "draw calls last frame: {} ({} terrain chunks, {} for the rocks)",
            calls.total(),
            calls.terrain,
            calls.rocks
        ));
        if self.plain.rocks_placed() < MAX_ROCKS {
            ui.label(format!("this terrain is steep: only {} rocks found room", self.plain.rocks_placed()));
        }
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        ui.collapsing("terrain settings", |ui| {
            self.regenerate_requested |= self.plain.terrain.settings_ui(ui);
        });
        ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=200.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        let calls = self.draw_calls;
        format!(
            "{} rocks, {:?}; {} draw calls ({} terrain chunks + {} for the rocks); {} vertices per rock, {} bytes per instance",
            self.setup.rocks.min(self.plain.rocks_placed()),
            self.setup.mode,
            calls.total(),
            calls.terrain,
            calls.rocks,
            rock_mesh(SEED).vertices.len(),
            std::mem::size_of::<RockInstance>()
        )
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.plain.reload_shaders(gpu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_generator_is_seeded() {
        let (mut a, mut b, mut c) = (Rng::new(1), Rng::new(1), Rng::new(2));
        let xs: Vec<u64> = (0..5).map(|_| a.next_u64()).collect();
        assert_eq!(xs, (0..5).map(|_| b.next_u64()).collect::<Vec<_>>());
        assert_ne!(xs, (0..5).map(|_| c.next_u64()).collect::<Vec<_>>());
        // The published first outputs of SplitMix64 from state 0.
        let mut zero = Rng::new(0);
        assert_eq!(zero.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(zero.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert!((0..1000).all(|_| (0.0..1.0).contains(&a.unit())));
    }

    #[test]
    fn the_rock_is_closed_flat_shaded_and_sixty_vertices() {
        let rock = rock_mesh(SEED);
        assert_eq!((rock.vertices.len(), rock.indices.len()), (60, 60));
        let volume: f32 = rock.triangles().map(|[a, b, c]| a.dot(b.cross(c)) / 6.0).sum();
        assert!(volume > 0.05, "faces must wind outward: volume {volume}");
        for face in rock.vertices.chunks_exact(3) {
            assert!(face.iter().all(|v| v.normal == face[0].normal), "flat shading");
        }
        assert_ne!(rock_mesh(SEED).vertices, rock_mesh(SEED + 1).vertices);
    }

    #[test]
    fn rocks_sit_on_the_ground_and_avoid_the_cliff() {
        let field = HeightField::generate(TerrainSettings::default());
        let rocks = scatter(&field, 2_000, SEED);
        assert_eq!(rocks, scatter(&field, 2_000, SEED), "same seed, same rocks");
        for rock in &rocks {
            let [x, y, z] = rock.position;
            let ground = field.height_at(x, z);
            assert!(y <= ground && y > ground - 1.0, "rock at {y} m, ground at {ground} m");
            let n = field.normal(x as i64, z as i64);
            assert!(n.y >= 0.9);
        }
    }

    #[test]
    fn the_scatter_gives_up_where_the_ground_is_too_steep() {
        // A ramp rising 1.2 m per metre everywhere: no slope under 25°.
        let settings = TerrainSettings::default();
        let size = settings.samples();
        let heights = (0..size * size).map(|i| 1.2 * (i % size) as f32).collect();
        let field = HeightField { settings, size, heights };
        assert!(scatter(&field, 1_000, SEED).is_empty(), "no rock belongs on this slope, and the scatter must stop");
        // Where half the ground is flat, the scatter still fills its count.
        let half: Vec<f32> =
            (0..size * size).map(|i| if i % size < size / 2 { 0.0 } else { 1.2 * (i % size) as f32 }).collect();
        let field = HeightField { settings, size, heights: half };
        assert_eq!(scatter(&field, 1_000, SEED).len(), 1_000);
    }

    #[test]
    fn a_prefix_of_the_rocks_is_the_smaller_scatter() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 64, ..Default::default() });
        assert_eq!(scatter(&field, 500, SEED)[..], scatter(&field, 2_000, SEED)[..500]);
    }
}
