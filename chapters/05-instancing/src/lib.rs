//! Chapter 05: instancing. One rock mesh, up to a million rocks, one draw
//! call; and the same rocks drawn one call at a time, to see why it matters.
//! The scene is the Mars plain so far: terrain, fog and rocks.

use common::glam::{Vec3, Vec4};
use common::texture::{depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, Mesh, MeshData, ShaderError, ShaderFile, Target, Vertex, View,
    anyhow, egui, shader, wgpu,
};
use fog::{FogBinding, FogSettings, MAX_FAR, fog_shader};
use terrain::culling::Frustum;
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer};

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
/// `count` rocks scattered over a 1.6 km square of the plain in front of
/// the start camera, each on the ground, half buried, never on the cliff.
/// Placement is uniform, so the first n of them are a fair sample at any n:
/// the rock-count slider just draws fewer.
pub fn scatter(field: &HeightField, count: usize, seed: u64) -> Vec<RockInstance> {
    let mut rng = Rng::new(seed);
    let centre = plain_camera(field, 1.0).position;
    let mut rocks = Vec::with_capacity(count);
    while rocks.len() < count {
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
    Camera { far: MAX_FAR, near: 0.1, ..Camera::looking_at(eye, target, aspect) }
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
    View { name: "default", about: "the Mars plain: terrain, fog and 200,000 rocks in one draw call" },
    View { name: "naive", about: "the same plain with 2,000 rocks, one draw call each" },
    View { name: "rocks-10k", about: "bench: 10,000 rocks, instanced, no terrain" },
    View { name: "rocks-100k", about: "bench: 100,000 rocks, instanced, no terrain" },
    View { name: "rocks-1m", about: "bench: 1,000,000 rocks, instanced, no terrain" },
    View { name: "naive-10k", about: "bench: 10,000 rocks, one draw call each, no terrain" },
    View { name: "flat-1m", about: "bench: 1,000,000 rocks, instanced, flat colour: the cost floor" },
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

pub struct InstancingChapter {
    pub terrain: TerrainRenderer,
    pub fog: FogSettings,
    /// The light, and the fog's colour (linear RGB); chapter 06 moves both
    /// with the time of day.
    pub sun: Sun,
    pub fog_colour: [f32; 3],
    pub setup: Setup,
    pub camera: Camera,
    pub controller: FlyController,
    pub fog_binding: FogBinding,
    rock: Mesh,
    instances: wgpu::Buffer,
    /// The first `MAX_ONE_PER_DRAW` rocks again, one per 256-byte slot, for
    /// the one-draw-per-rock path.
    singles: wgpu::Buffer,
    singles_group: wgpu::BindGroup,
    single_stride: u32,
    layouts: [wgpu::PipelineLayout; 2],
    terrain_pipeline: wgpu::RenderPipeline,
    rock_pipelines: RockPipelines,
    depth: wgpu::TextureView,
    target: Target,
    /// Draw calls in the last frame.
    pub draw_calls: u32,
    regenerate_requested: bool,
    /// The frustum of the last `prepare`, for culling chunks in `draw`.
    frustum: Frustum,
}

impl InstancingChapter {
    fn build_rock_pipelines(
        gpu: &Gpu,
        layouts: &[wgpu::PipelineLayout; 2],
        format: wgpu::TextureFormat,
    ) -> Result<RockPipelines, ShaderError> {
        let module = rocks_shader().module(&gpu.device)?;
        gpu.catch_validation(|| RockPipelines {
            instanced: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_main"),
            one_per_draw: rock_pipeline(gpu, &module, &layouts[1], format, "vs_single", "fs_main"),
            flat: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_flat"),
        })
        .map_err(ShaderError)
    }

    /// Scatters the rocks on the current terrain and uploads both copies.
    fn upload_rocks(device: &wgpu::Device, field: &HeightField, stride: u32) -> (wgpu::Buffer, wgpu::Buffer) {
        let rocks = scatter(field, MAX_ROCKS as usize, SEED);
        let instances = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("rock instances"),
            contents: bytemuck::cast_slice(&rocks),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let mut slots = vec![0u8; stride as usize * MAX_ONE_PER_DRAW as usize];
        for (slot, rock) in slots.chunks_exact_mut(stride as usize).zip(&rocks) {
            slot[..std::mem::size_of::<RockInstance>()].copy_from_slice(bytemuck::bytes_of(rock));
        }
        let singles = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("one rock per slot"),
            contents: &slots,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        (instances, singles)
    }

    fn singles_group(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, singles: &wgpu::Buffer) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("one rock"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: singles,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<RockInstance>() as u64),
                }),
            }],
        })
    }

    /// The depth buffer the main pass draws with (a cheap handle: wgpu views
    /// are reference-counted).
    pub fn depth(&self) -> wgpu::TextureView {
        self.depth.clone()
    }

    /// Writes the uniforms for drawing the plain from `camera`, keeping
    /// what `clip` keeps (`KEEP_ALL` for everything). Later chapters draw the
    /// plain several times a frame, from several cameras, through this.
    pub fn prepare(&mut self, gpu: &Gpu, camera: &Camera, clip: Vec4) {
        if std::mem::take(&mut self.regenerate_requested) {
            self.terrain.regenerate(gpu);
            // The rocks must follow the new ground.
            (self.instances, self.singles) = Self::upload_rocks(&gpu.device, &self.terrain.field, self.single_stride);
            let layout = self.rock_pipelines.one_per_draw.get_bind_group_layout(2);
            self.singles_group = Self::singles_group(&gpu.device, &layout, &self.singles);
        }
        self.camera.far = self.fog.opaque_distance().min(MAX_FAR);
        let camera = Camera { far: self.camera.far, ..*camera };
        self.fog_binding.write_with_colour(&gpu.queue, self.fog, self.fog_colour);
        self.terrain.write_globals_clipped(&gpu.queue, &camera, self.sun, Shading::Shaded, clip);
        self.frustum = Frustum::from_view_projection(camera.view_projection());
    }

    /// Draws the terrain and the rocks as prepared into `pass`.
    pub fn draw(&mut self, pass: &mut wgpu::RenderPass<'_>) {
        // Group 0 (camera, sun) and group 1 (fog) serve the terrain and the rocks alike.
        pass.set_bind_group(1, &self.fog_binding.group, &[]);
        self.terrain.bind(pass);
        if self.setup.terrain {
            pass.set_pipeline(&self.terrain_pipeline);
            self.terrain.draw(pass, &self.frustum);
        }
        self.draw_calls = self.draw_rocks(pass) + u32::from(self.setup.terrain);
    }

    // ANCHOR: draw_rocks
    /// Draws the first `setup.rocks` rocks; returns the number of draw calls.
    fn draw_rocks(&self, pass: &mut wgpu::RenderPass<'_>) -> u32 {
        let Setup { rocks, mode, .. } = self.setup;
        pass.set_vertex_buffer(0, self.rock.vertex_buffer.slice(..));
        pass.set_index_buffer(self.rock.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        match mode {
            Mode::Instanced | Mode::Flat => {
                let pipeline =
                    if mode == Mode::Flat { &self.rock_pipelines.flat } else { &self.rock_pipelines.instanced };
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(1, self.instances.slice(..));
                // Every rock, one call: the GPU loops over the instances itself.
                pass.draw_indexed(0..self.rock.index_count, 0, 0..rocks);
                1
            }
            Mode::OnePerDraw => {
                pass.set_pipeline(&self.rock_pipelines.one_per_draw);
                let rocks = rocks.min(MAX_ONE_PER_DRAW);
                for i in 0..rocks {
                    // A bind group change and a draw per rock, validated and
                    // recorded one by one: this is the cost instancing removes.
                    pass.set_bind_group(2, &self.singles_group, &[i * self.single_stride]);
                    pass.draw_indexed(0..self.rock.index_count, 0, 0..1);
                }
                rocks
            }
        }
    }
    // ANCHOR_END: draw_rocks
}

impl Chapter for InstancingChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "05 · Instancing";
    const VIEWS: &'static [View] = VIEWS;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let terrain = TerrainRenderer::new(gpu, TerrainSettings::default());
        let fog_binding = FogBinding::new(device);
        let single_stride = (std::mem::size_of::<RockInstance>() as u32)
            .next_multiple_of(device.limits().min_uniform_buffer_offset_alignment);
        let (instances, singles) = Self::upload_rocks(device, &terrain.field, single_stride);
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
        let singles_group = Self::singles_group(device, &single_layout, &singles);
        let layout = |label, groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        let shared = [Some(&terrain.bind_group_layout), Some(&fog_binding.layout)];
        let layouts =
            [layout("rocks", &shared), layout("one rock per draw", &[shared[0], shared[1], Some(&single_layout)])];
        let terrain_pipeline = terrain.pipeline(gpu, &fog_shader(), &layouts[0], target.format)?;
        let rock_pipelines = Self::build_rock_pipelines(gpu, &layouts, target.format)?;
        Ok(Self {
            camera: plain_camera(&terrain.field, target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            fog: FogSettings::HAZE,
            sun: Sun::AFTERNOON,
            fog_colour: [SKY.r as f32, SKY.g as f32, SKY.b as f32],
            setup: setup_for("default"),
            terrain,
            fog_binding,
            rock: rock_mesh(SEED).upload(device, "rock"),
            instances,
            singles,
            singles_group,
            single_stride,
            layouts,
            terrain_pipeline,
            rock_pipelines,
            depth: depth_view(device, target.width, target.height),
            target,
            draw_calls: 0,
            regenerate_requested: false,
            frustum: Frustum::from_view_projection(Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, 1.0).view_projection()),
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
    }

    fn select_view(&mut self, view: usize) {
        self.setup = setup_for(VIEWS[view].name);
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        let camera = self.camera;
        self.prepare(gpu, &camera, KEEP_ALL);
        let mut pass = frame.scene_pass("terrain and rocks", SKY, &self.depth);
        self.draw(&mut pass);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.setup;
        ui.horizontal(|ui| {
            ui.radio_value(&mut s.mode, Mode::Instanced, "instanced");
            ui.radio_value(&mut s.mode, Mode::OnePerDraw, "one draw per rock");
            ui.radio_value(&mut s.mode, Mode::Flat, "flat");
        });
        let max = if s.mode == Mode::OnePerDraw { MAX_ONE_PER_DRAW } else { MAX_ROCKS };
        s.rocks = s.rocks.min(max);
        ui.add(egui::Slider::new(&mut s.rocks, 0..=max).logarithmic(true).text("rocks"));
        ui.checkbox(&mut s.terrain, "terrain");
        ui.label(format!("draw calls last frame: {}", self.draw_calls));
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        ui.collapsing("terrain settings", |ui| {
            self.regenerate_requested |= self.terrain.settings_ui(ui);
        });
        ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=200.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&self) -> String {
        format!(
            "{} rocks, {:?}, {} draw calls; {} vertices per rock, {} bytes per instance",
            self.setup.rocks,
            self.setup.mode,
            self.draw_calls,
            self.rock.index_count,
            std::mem::size_of::<RockInstance>()
        )
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        let terrain = self.terrain.pipeline(gpu, &fog_shader(), &self.layouts[0], self.target.format)?;
        self.rock_pipelines = Self::build_rock_pipelines(gpu, &self.layouts, self.target.format)?;
        self.terrain_pipeline = terrain;
        Ok(())
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
    fn a_prefix_of_the_rocks_is_the_smaller_scatter() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 64, ..Default::default() });
        assert_eq!(scatter(&field, 500, SEED)[..], scatter(&field, 2_000, SEED)[..500]);
    }
}
