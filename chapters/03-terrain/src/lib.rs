//! Chapter 03: terrain from noise. Improved Perlin noise summed in octaves
//! makes a height map; the map is cut into chunks that share one index
//! buffer; chunks the camera cannot see are skipped before drawing.

pub mod chunks;
pub mod culling;
pub mod heightfield;
pub mod noise;

use std::sync::Arc;

use common::chapter::uniform_entry;
use common::glam::{Vec3, Vec4};
use common::texture::{depth_test, depth_view};
use common::timing::measure;
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, ShaderError, ShaderFile, Target, View, anyhow, egui, shader,
    wgpu,
};

use chunks::{Aabb, CHUNK_VERTICES, TerrainVertex, chunk_bounds, chunk_indices, chunk_vertices, coarse_indices};
use culling::Frustum;
use heightfield::{CHUNK_QUADS, HeightField, HeightRows, TerrainSettings};

pub const VIEWS: &[View] = &[
    View::mode("default", "the terrain, coloured by height and slope, with its cliff"),
    View::mode("wireframe", "the triangles of the height-map mesh, wherever they are at least 8 pixels apart"),
    View::preset("close-up", "the wireframe from the foot of the cliff, where the 1 m cells are large"),
    View::mode("normals", "normals from the whole height field: no seams at chunk borders"),
    View::mode("chunks", "from 4 km above: a colour per chunk your camera draws, dark for the culled ones"),
];

/// Pale butterscotch: the Martian sky, and the clear colour.
pub const SKY: wgpu::Color = wgpu::Color { r: 0.62, g: 0.42, b: 0.28, a: 1.0 };

/// The light: a direction towards the sun, and how strong it is (1 by day,
/// 0 when it is below the horizon). Chapter 06 moves it with the sky.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sun {
    pub direction: Vec3,
    pub strength: f32,
}

impl Sun {
    /// Low in the south-east, so slopes show as light and shade.
    pub const AFTERNOON: Self = Self { direction: Vec3::new(0.75, 0.35, 0.35), strength: 1.0 };
}

// ANCHOR: terrain_mesh
/// The whole terrain on the GPU: every chunk's vertices in one buffer, one
/// shared index buffer, and each chunk's bounding box for culling.
pub struct TerrainMesh {
    pub vertex_buffer: wgpu::Buffer,
    pub index_buffer: wgpu::Buffer,
    pub index_count: u32,
    /// `coarse_indices(8)`, for seeing every chunk from far away.
    pub coarse_index_buffer: wgpu::Buffer,
    pub coarse_index_count: u32,
    pub bounds: Vec<Aabb>,
    pub chunks_per_side: u32,
}

impl TerrainMesh {
    /// The vertices and bounding boxes of the chunks in rows `rows`, row
    /// by row. Rows of chunks are independent: each core builds a band.
    pub fn chunk_rows(field: &HeightField, rows: std::ops::Range<u32>) -> (Vec<TerrainVertex>, Vec<Aabb>) {
        let n = field.settings.chunks_per_side;
        let chunks = |band: std::ops::Range<usize>| {
            band.flat_map(move |row| (0..n).map(move |cx| (cx, rows.start + row as u32)))
        };
        let vertices = common::parallel::map_bands(rows.len(), |band| {
            chunks(band).flat_map(|(cx, cz)| chunk_vertices(field, cx, cz)).collect()
        });
        let bounds = common::parallel::map_bands(rows.len(), |band| {
            chunks(band).map(|(cx, cz)| chunk_bounds(field, cx, cz)).collect()
        });
        (vertices, bounds)
    }

    /// Puts every chunk's vertices in one buffer, beside the index buffers
    /// all chunks share.
    pub fn upload(device: &wgpu::Device, chunks_per_side: u32, vertices: &[TerrainVertex], bounds: Vec<Aabb>) -> Self {
        let buffer = |label, contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        let vertex_buffer = buffer("terrain vertices", bytemuck::cast_slice(vertices), wgpu::BufferUsages::VERTEX);
        let (indices, coarse) = (chunk_indices(), coarse_indices(8));
        Self {
            vertex_buffer,
            index_buffer: buffer("chunk indices", bytemuck::cast_slice(&indices), wgpu::BufferUsages::INDEX),
            index_count: indices.len() as u32,
            coarse_index_buffer: buffer("coarse indices", bytemuck::cast_slice(&coarse), wgpu::BufferUsages::INDEX),
            coarse_index_count: coarse.len() as u32,
            bounds,
            chunks_per_side,
        }
    }

    /// Draws chunk `chunk`: its vertices start at `chunk × 4225` in the
    /// shared buffer (the base vertex), and drawing it as instance `chunk`
    /// tells the shader which chunk it is.
    pub fn draw_chunk(&self, pass: &mut wgpu::RenderPass<'_>, chunk: u32) {
        let base_vertex = (chunk * CHUNK_VERTICES) as i32;
        pass.draw_indexed(0..self.index_count, base_vertex, chunk..chunk + 1);
    }

    /// Binds the buffers and draws the chunks `frustum` can see; returns how many.
    pub fn draw_visible(&self, pass: &mut wgpu::RenderPass<'_>, frustum: &Frustum) -> usize {
        pass.set_vertex_buffer(0, self.vertex_buffer.slice(..));
        pass.set_index_buffer(self.index_buffer.slice(..), wgpu::IndexFormat::Uint16);
        let mut drawn = 0;
        for (chunk, bounds) in self.bounds.iter().enumerate() {
            if frustum.intersects(bounds) {
                self.draw_chunk(pass, chunk as u32);
                drawn += 1;
            }
        }
        drawn
    }

    /// Draws every chunk with the coarse index list.
    pub fn draw_all_coarse(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_vertex_buffer(0, self.vertex_buffer.slice(..));
        pass.set_index_buffer(self.coarse_index_buffer.slice(..), wgpu::IndexFormat::Uint16);
        for chunk in 0..self.bounds.len() as u32 {
            pass.draw_indexed(0..self.coarse_index_count, (chunk * CHUNK_VERTICES) as i32, chunk..chunk + 1);
        }
    }
}
// ANCHOR_END: terrain_mesh

// ANCHOR: vertex_layout
/// `@location(0)` the height, `@location(1)` the normal, unpacked by the
/// GPU from four signed bytes to four floats in −1..1.
pub const TERRAIN_VERTEX_LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
    array_stride: std::mem::size_of::<TerrainVertex>() as wgpu::BufferAddress,
    step_mode: wgpu::VertexStepMode::Vertex,
    attributes: &wgpu::vertex_attr_array![0 => Float32, 1 => Snorm8x4],
};
// ANCHOR_END: vertex_layout

/// `Globals` in terrain.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Globals {
    view_proj: [[f32; 4]; 4],
    eye: [f32; 4],
    sun: [f32; 4],
    grid: [u32; 4],
    scale: [f32; 4],
    clip: [f32; 4],
}

/// What every chapter that draws the terrain asks of the device: clip
/// distances where the adapter has them (`terrain.wgsl` clips with them,
/// and with a fragment discard otherwise). Asking for the same thing keeps
/// chapters 03 to 07 on one kind of device, so a process that opens several
/// of them can share the terrain made on it (`Gpu::cached`).
pub fn gpu_needs() -> common::GpuNeeds {
    common::GpuNeeds { required: wgpu::Features::empty(), optional: wgpu::Features::CLIP_DISTANCES }
}

/// A clip plane (n, d): fragments with n · p + d < 0 are discarded. `KEEP_ALL`
/// clips nothing; chapter 07 keeps what is above or below the water.
pub const KEEP_ALL: Vec4 = Vec4::new(0.0, 0.0, 0.0, 1.0);

/// How the terrain shader colours the ground (`globals.grid.z`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shading {
    Shaded = 0,
    Wireframe = 1,
    Normals = 2,
    Chunks = 3,
}

/// The camera views start from: on the plain south of the cliff, looking
/// north at it, with hills behind.
pub fn start_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47;
    let z = s.cliff_line(x) + 170.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 30.0, z);
    let target = Vec3::new(x + 120.0, field.height_at(x + 120.0, z - 300.0), z - 300.0);
    Camera { far: 3000.0, near: 0.5, ..Camera::looking_at(eye, target, aspect) }
}

/// Close to the ground at the foot of the cliff, where the wireframe's
/// one-metre cells are large enough to see.
fn close_up_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47;
    let z = s.cliff_line(x) + 45.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 9.0, z);
    let target = Vec3::new(x + 20.0, field.height_at(x + 20.0, z - 30.0) + 4.0, z - 30.0);
    Camera { far: 3000.0, near: 0.5, ..Camera::looking_at(eye, target, aspect) }
}

/// High above the middle of the world, looking down with north (−z) at
/// the top of the picture. Built from angles: straight down, `looking_at`
/// cannot tell which way is up (the pitch rounds to exactly −90° in f32).
fn overhead_camera(field: &HeightField, aspect: f32) -> Camera {
    let centre = field.settings.extent() * 0.5;
    Camera {
        position: Vec3::new(centre, 4200.0, centre),
        yaw: 0.0,
        pitch: -89.99f32.to_radians(),
        fov_y: 60f32.to_radians(),
        aspect,
        near: 10.0,
        far: 6000.0,
    }
}

/// The terrain's CPU and GPU data for one set of settings: the height
/// field, the chunk meshes, and how long each took to make (ms).
pub struct TerrainData {
    pub field: HeightField,
    pub mesh: TerrainMesh,
    pub timings: (f64, f64),
}

impl TerrainData {
    /// The data for `settings`, made once per device: later chapters, and
    /// tests that create chapters again and again, share it.
    pub fn get(gpu: &Gpu, settings: TerrainSettings) -> Arc<Self> {
        gpu.cached(settings, || {
            let mut build = TerrainBuild::new(settings);
            loop {
                match build {
                    TerrainBuild::Done(data) => return data,
                    unfinished => build = unfinished.step(&gpu.device),
                }
            }
        })
    }

    /// [`TerrainData::get`] in steps, for [`Chapter::prepare`]: a browser
    /// page shows its progress between them. `None` when the data is
    /// already made.
    pub fn prepare(gpu: &Gpu, settings: TerrainSettings) -> Option<common::Preparation> {
        if gpu.is_cached::<TerrainSettings, Self>(&settings) {
            return None;
        }
        let mut build = Some(TerrainBuild::new(settings));
        Some(common::Preparation::new("generating the terrain", move |gpu| {
            let Some(unfinished) = build.take() else { return 1.0 };
            match unfinished.step(&gpu.device) {
                TerrainBuild::Done(data) => {
                    gpu.cached(settings, || data);
                    1.0
                }
                next => build.insert(next).progress(),
            }
        }))
    }
}

/// The terrain made a slice at a time: rows of heights, then rows of
/// chunk meshes, then the upload. [`TerrainData::get`] takes the same
/// steps in one go, so every test of the terrain tests the steps too.
enum TerrainBuild {
    /// Milliseconds spent so far in `ms`.
    Heights {
        rows: HeightRows,
        ms: f64,
    },
    /// Milliseconds spent on heights, then on meshes, in `timings`.
    Meshes {
        field: HeightField,
        vertices: Vec<TerrainVertex>,
        bounds: Vec<Aabb>,
        timings: (f64, f64),
    },
    Done(TerrainData),
}

impl TerrainBuild {
    /// 55 to 85 ms of heights and about 60 ms of meshes a step, measured
    /// in Chromium on the machine the book's figures come from.
    const HEIGHT_ROWS_PER_STEP: usize = 64;
    const CHUNK_ROWS_PER_STEP: u32 = 4;
    /// The heights' share of the whole work, as measured natively (1650 ms
    /// of heights to 645 ms of meshes).
    const HEIGHTS_SHARE: f32 = 0.72;

    fn new(settings: TerrainSettings) -> Self {
        Self::Heights { rows: HeightRows::new(settings), ms: 0.0 }
    }

    /// The next slice of work done.
    fn step(self, device: &wgpu::Device) -> Self {
        match self {
            Self::Heights { mut rows, ms } => {
                let ((), took) = measure(|| rows.add(Self::HEIGHT_ROWS_PER_STEP));
                if rows.done() < rows.size {
                    return Self::Heights { rows, ms: ms + took };
                }
                let chunks = rows.settings.chunks_per_side.pow(2) as usize;
                let vertices = Vec::with_capacity(chunks * CHUNK_VERTICES as usize);
                Self::Meshes { field: rows.finish(), vertices, bounds: Vec::new(), timings: (ms + took, 0.0) }
            }
            Self::Meshes { field, mut vertices, mut bounds, mut timings } => {
                let n = field.settings.chunks_per_side;
                let first = bounds.len() as u32 / n;
                if first < n {
                    let rows = first..(first + Self::CHUNK_ROWS_PER_STEP).min(n);
                    let ((more_vertices, more_bounds), ms) = measure(|| TerrainMesh::chunk_rows(&field, rows));
                    vertices.extend(more_vertices);
                    bounds.extend(more_bounds);
                    timings.1 += ms;
                    return Self::Meshes { field, vertices, bounds, timings };
                }
                // Every chunk is built: the upload is the last step.
                let (mesh, ms) = measure(|| TerrainMesh::upload(device, n, &vertices, bounds));
                timings.1 += ms;
                Self::Done(TerrainData { field, mesh, timings })
            }
            done @ Self::Done(_) => done,
        }
    }

    /// The fraction of the whole work done.
    fn progress(&self) -> f32 {
        match self {
            Self::Heights { rows, .. } => Self::HEIGHTS_SHARE * rows.done() as f32 / rows.size as f32,
            Self::Meshes { field, bounds, .. } => {
                let chunks = field.settings.chunks_per_side.pow(2) as f32;
                // The upload is still to come.
                Self::HEIGHTS_SHARE + (1.0 - Self::HEIGHTS_SHARE) * 0.95 * bounds.len() as f32 / chunks
            }
            Self::Done(_) => 1.0,
        }
    }
}

// ANCHOR: viewpoint
/// The uniforms for drawing the terrain from one camera: group 0 of
/// `terrain.wgsl`, which shaders that import the module read too. A frame
/// that draws the terrain from several cameras (chapter 07's reflection,
/// refraction and main picture) has one viewpoint for each, so that all of
/// them can be recorded into one encoder and submitted once.
pub struct Viewpoint {
    globals: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    frustum: Frustum,
}
// ANCHOR_END: viewpoint

/// The terrain, ready to draw: its data and the layout of group 0. Later
/// chapters draw the same ground with shaders of their own that
/// `#import terrain`.
pub struct TerrainRenderer {
    /// What the learner edits in the overlay; applied by `regenerate`.
    pub settings: TerrainSettings,
    data: Arc<TerrainData>,
    /// One flag per chunk for the `chunks` view (shared by every viewpoint).
    chunk_flags: wgpu::Buffer,
    pub bind_group_layout: wgpu::BindGroupLayout,
}

impl TerrainRenderer {
    pub fn new(gpu: &Gpu, settings: TerrainSettings) -> Self {
        let device = &gpu.device;
        let data = TerrainData::get(gpu, settings);
        let chunk_flags = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("chunk drawn flags"),
            size: u64::from(settings.chunks_per_side.pow(2).max(1)) * 4,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("terrain"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT, std::mem::size_of::<Globals>()),
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: true },
                        has_dynamic_offset: false,
                        min_binding_size: wgpu::BufferSize::new(4),
                    },
                    count: None,
                },
            ],
        });
        Self { settings, data, chunk_flags, bind_group_layout }
    }

    /// The height field the terrain was made from: where the ground is.
    pub fn field(&self) -> &HeightField {
        &self.data.field
    }

    pub fn mesh(&self) -> &TerrainMesh {
        &self.data.mesh
    }

    /// Makes the terrain again from `self.settings` (the number of chunks
    /// stays as it was). Viewpoints keep working.
    pub fn regenerate(&mut self, gpu: &Gpu) {
        self.settings.chunks_per_side = self.data.field.settings.chunks_per_side;
        self.data = TerrainData::get(gpu, self.settings);
    }

    /// A new set of uniforms for drawing the terrain from one more camera.
    pub fn viewpoint(&self, device: &wgpu::Device) -> Viewpoint {
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("terrain globals"),
            size: std::mem::size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("terrain"),
            layout: &self.bind_group_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: globals.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: self.chunk_flags.as_entire_binding() },
            ],
        });
        let frustum = Frustum::from_view_projection(Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, 1.0).view_projection());
        Viewpoint { globals, bind_group, frustum }
    }

    /// A pipeline that draws the terrain mesh with `shader`'s `vs_main` and
    /// `fs_main`; `layout` starts with this renderer's bind group layout.
    pub fn pipeline(
        &self,
        gpu: &Gpu,
        shader: &ShaderFile,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader.module(gpu)?;
        gpu.catch_validation(|| {
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(shader.path),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    buffers: &[Some(TERRAIN_VERTEX_LAYOUT)],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
                depth_stencil: depth_test(),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_main"),
                    targets: &[Some(format.into())],
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        })
        .map_err(ShaderError)
    }

    /// Aims `viewpoint` at the scene from `camera`: writes its uniforms,
    /// lit by `sun`, keeping what `clip` keeps ([`KEEP_ALL`] for
    /// everything), and keeps the camera's frustum for culling.
    pub fn aim(
        &self,
        queue: &wgpu::Queue,
        viewpoint: &mut Viewpoint,
        camera: &Camera,
        sun: Sun,
        shading: Shading,
        clip: Vec4,
    ) {
        let globals = Globals {
            view_proj: camera.view_projection().to_cols_array_2d(),
            eye: camera.position.extend(1.0).into(),
            sun: sun.direction.normalize().extend(sun.strength).into(),
            grid: [self.data.mesh.chunks_per_side, CHUNK_QUADS, shading as u32, 0],
            scale: [self.data.field.settings.spacing, self.data.field.settings.height, 0.0, 0.0],
            clip: clip.into(),
        };
        queue.write_buffer(&viewpoint.globals, 0, bytemuck::bytes_of(&globals));
        viewpoint.frustum = Frustum::from_view_projection(camera.view_projection());
    }

    /// Marks which chunks `frustum` keeps, for `Shading::Chunks`.
    pub fn write_chunk_flags(&self, queue: &wgpu::Queue, frustum: &Frustum) {
        let flags: Vec<u32> = self.data.mesh.bounds.iter().map(|b| u32::from(frustum.intersects(b))).collect();
        queue.write_buffer(&self.chunk_flags, 0, bytemuck::cast_slice(&flags));
    }

    /// Binds group 0 for `viewpoint`: what other shaders that import the
    /// terrain module (fog, rocks, water) read too.
    pub fn bind(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &Viewpoint) {
        pass.set_bind_group(0, &viewpoint.bind_group, &[]);
    }

    /// Binds group 0 and draws the chunks the viewpoint's camera can see;
    /// returns how many (one draw call each).
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &Viewpoint) -> usize {
        self.bind(pass, viewpoint);
        self.data.mesh.draw_visible(pass, &viewpoint.frustum)
    }

    /// Sliders for the generator; true when the terrain should be regenerated.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> bool {
        let size = self.data.field.size;
        ui.label(format!(
            "{size} × {size} samples, {} bytes per vertex; heights {:.0} ms, meshes {:.0} ms",
            std::mem::size_of::<TerrainVertex>(),
            self.data.timings.0,
            self.data.timings.1
        ));
        let s = &mut self.settings;
        let mut changed = false;
        let mut slider = |ui: &mut egui::Ui, widget: egui::Slider| {
            let response = ui.add(widget);
            // Regenerating 16 million samples takes a moment: only when the slider is let go.
            changed |= response.drag_stopped() || (response.changed() && !response.dragged());
        };
        slider(ui, egui::Slider::new(&mut s.fbm.octaves, 1..=10).text("octaves"));
        slider(ui, egui::Slider::new(&mut s.fbm.persistence, 0.2..=0.8).text("persistence"));
        slider(ui, egui::Slider::new(&mut s.fbm.lacunarity, 1.5..=3.0).text("lacunarity"));
        slider(ui, egui::Slider::new(&mut s.feature_size, 100.0..=4000.0).logarithmic(true).text("largest hills (m)"));
        slider(ui, egui::Slider::new(&mut s.height, 0.0..=300.0).text("height (m)"));
        slider(ui, egui::Slider::new(&mut s.cliff_height, 0.0..=120.0).text("cliff (m)"));
        slider(ui, egui::Slider::new(&mut s.seed, 0..=100).text("seed"));
        changed
    }

    /// The chapter's figures for `--bench`.
    pub fn stats(&self, drawn: usize) -> String {
        let size = self.data.field.size;
        format!(
            "{size}×{size} heights in {:.0} ms, chunk meshes built and uploaded in {:.0} ms; {} bytes per vertex, {:.0} MB of vertices; {drawn} of {} chunks drawn",
            self.data.timings.0,
            self.data.timings.1,
            std::mem::size_of::<TerrainVertex>(),
            self.data.mesh.vertex_buffer.size() as f64 / 1e6,
            self.data.mesh.bounds.len()
        )
    }
}

pub struct TerrainChapter {
    pub terrain: TerrainRenderer,
    pub camera: Camera,
    pub controller: FlyController,
    viewpoint: Viewpoint,
    layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    depth: wgpu::TextureView,
    target: Target,
    /// Chunks drawn in the last frame.
    pub drawn: usize,
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
    const VIEWS: &'static [View] = VIEWS;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn gpu_needs() -> common::GpuNeeds {
        gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    fn prepare(gpu: &Gpu) -> Option<common::Preparation> {
        TerrainData::prepare(gpu, TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let terrain = TerrainRenderer::new(gpu, TerrainSettings::default());
        let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("terrain"),
            bind_group_layouts: &[Some(&terrain.bind_group_layout)],
            immediate_size: 0,
        });
        let pipeline = terrain.pipeline(gpu, &terrain_shader(), &layout, target.format)?;
        Ok(Self {
            camera: start_camera(terrain.field(), target.aspect()),
            controller: FlyController { speed: 40.0, ..Default::default() },
            viewpoint: terrain.viewpoint(&gpu.device),
            terrain,
            layout,
            pipeline,
            depth: depth_view(&gpu.device, target.width, target.height),
            target,
            drawn: 0,
            regenerate_requested: false,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
    }

    // Every view but `close-up` is a mode: a way of drawing what the flying
    // camera sees. `chunks` too: it shows that camera's culling from above.

    fn reset_camera(&mut self, view: usize) {
        let (field, aspect) = (self.terrain.field(), self.target.aspect());
        self.camera = match VIEWS[view].name {
            "close-up" => close_up_camera(field, aspect),
            _ => start_camera(field, aspect),
        };
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
            self.terrain.regenerate(gpu);
        }
        let shading = match VIEWS[frame.view].name {
            "wireframe" | "close-up" => Shading::Wireframe,
            "normals" => Shading::Normals,
            "chunks" => Shading::Chunks,
            _ => Shading::Shaded,
        };
        let mut pass = frame.scene_pass("terrain", SKY, &self.depth);
        pass.set_pipeline(&self.pipeline);
        if shading == Shading::Chunks {
            // Look from high above at what the flying camera culls: every
            // chunk is drawn (coarsely), coloured if the camera keeps it.
            let frustum = Frustum::from_view_projection(self.camera.view_projection());
            self.terrain.write_chunk_flags(&gpu.queue, &frustum);
            self.drawn = self.terrain.mesh().bounds.iter().filter(|b| frustum.intersects(b)).count();
            let overhead = overhead_camera(self.terrain.field(), self.target.aspect());
            self.terrain.aim(&gpu.queue, &mut self.viewpoint, &overhead, Sun::AFTERNOON, shading, KEEP_ALL);
            self.terrain.bind(&mut pass, &self.viewpoint);
            self.terrain.mesh().draw_all_coarse(&mut pass);
        } else {
            self.terrain.aim(&gpu.queue, &mut self.viewpoint, &self.camera, Sun::AFTERNOON, shading, KEEP_ALL);
            self.drawn = self.terrain.draw(&mut pass, &self.viewpoint);
        }
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label(format!("chunks drawn: {} / {}", self.drawn, self.terrain.mesh().bounds.len()));
        self.regenerate_requested |= self.terrain.settings_ui(ui);
        ui.add(egui::Slider::new(&mut self.controller.speed, 5.0..=400.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        self.terrain.stats(self.drawn)
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.pipeline = self.terrain.pipeline(gpu, &terrain_shader(), &self.layout, self.target.format)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_camera_culls_behind_and_keeps_ahead() {
        let field = HeightField::generate(TerrainSettings::default());
        let camera = start_camera(&field, 16.0 / 9.0);
        let frustum = Frustum::from_view_projection(camera.view_projection());
        let chunk_at = |p: Vec3| {
            let n = field.settings.chunks_per_side as f32;
            let size = field.settings.extent() / n;
            ((p.z / size).floor() * n + (p.x / size).floor()) as usize
        };
        let bounds: Vec<Aabb> = (0..field.settings.chunks_per_side.pow(2))
            .map(|i| chunk_bounds(&field, i % field.settings.chunks_per_side, i / field.settings.chunks_per_side))
            .collect();
        let ahead = camera.position + camera.forward() * 300.0;
        let behind = camera.position - camera.forward() * 300.0;
        assert!(frustum.intersects(&bounds[chunk_at(ahead)]), "ahead");
        assert!(!frustum.intersects(&bounds[chunk_at(behind)]), "behind");
        let n = field.settings.chunks_per_side as usize;
        let camera_row = chunk_at(camera.position) / n;
        let north = (0..bounds.len()).filter(|&i| i / n < camera_row && frustum.intersects(&bounds[i])).count();
        let south = (0..bounds.len()).filter(|&i| i / n > camera_row && frustum.intersects(&bounds[i])).count();
        assert!(north > 500 && south == 0, "{north} chunks drawn north of the camera, {south} south");
    }

    #[test]
    fn overhead_view_has_north_at_the_top() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 2, ..Default::default() });
        let top = overhead_camera(&field, 1.0).view_projection();
        let ndc_y = |z: f32| {
            let c = top * Vec3::new(64.0, 0.0, z).extend(1.0);
            c.y / c.w
        };
        assert!(ndc_y(0.0) > ndc_y(128.0), "north (−z) must be up");
    }
}
