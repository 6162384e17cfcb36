//! Chapter 03: terrain from noise. Improved Perlin noise summed in octaves
//! makes a height map; the map is cut into chunks that share one index
//! buffer; chunks the camera cannot see are skipped before drawing.

pub mod chunks;
pub mod culling;
pub mod heightfield;
pub mod noise;

use std::time::Instant;

use common::chapter::uniform_entry;
use common::glam::{Vec3, Vec4};
use common::texture::{depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, ShaderError, ShaderFile, Target, View, anyhow, egui, shader,
    wgpu,
};

use chunks::{Aabb, CHUNK_VERTICES, TerrainVertex, chunk_bounds, chunk_indices, chunk_vertices};
use culling::Frustum;
use heightfield::{CHUNK_QUADS, HeightField, TerrainSettings};

pub const VIEWS: &[View] = &[
    View { name: "default", about: "the terrain, coloured by height and slope, with its cliff" },
    View { name: "wireframe", about: "the triangles of the height-map mesh" },
    View { name: "normals", about: "normals from the whole height field: no seams at chunk borders" },
    View { name: "chunks", about: "from above: a colour per chunk the camera draws, dark for the culled ones" },
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
    pub bounds: Vec<Aabb>,
    pub chunks_per_side: u32,
}

impl TerrainMesh {
    pub fn new(device: &wgpu::Device, field: &HeightField) -> Self {
        let n = field.settings.chunks_per_side;
        // Rows of chunks are independent: each CPU thread fills its own
        // band of the one vertex array, in place.
        let threads = std::thread::available_parallelism().map_or(1, |t| t.get());
        let rows_per_band = (n as usize).div_ceil(threads);
        let row_vertices = (n * CHUNK_VERTICES) as usize;
        let mut vertices = vec![TerrainVertex { height: 0.0, normal: [0; 4] }; n as usize * row_vertices];
        let mut bounds = vec![Aabb { min: Vec3::ZERO, max: Vec3::ZERO }; (n * n) as usize];
        std::thread::scope(|scope| {
            let vertex_bands = vertices.chunks_mut(rows_per_band * row_vertices);
            let bound_bands = bounds.chunks_mut(rows_per_band * n as usize);
            for (band, (vertices, bounds)) in vertex_bands.zip(bound_bands).enumerate() {
                scope.spawn(move || {
                    for (i, bound) in bounds.iter_mut().enumerate() {
                        let (cx, cz) = (i as u32 % n, (band * rows_per_band) as u32 + i as u32 / n);
                        let start = i * CHUNK_VERTICES as usize;
                        vertices[start..start + CHUNK_VERTICES as usize]
                            .copy_from_slice(&chunk_vertices(field, cx, cz));
                        *bound = chunk_bounds(field, cx, cz);
                    }
                });
            }
        });
        let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("terrain vertices"),
            contents: bytemuck::cast_slice(&vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = chunk_indices();
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("chunk indices"),
            contents: bytemuck::cast_slice(&indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self { vertex_buffer, index_buffer, index_count: indices.len() as u32, bounds, chunks_per_side: n }
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

/// Generates the height field and its meshes, timing each (ms).
fn generate(device: &wgpu::Device, settings: TerrainSettings) -> (HeightField, TerrainMesh, (f64, f64)) {
    let start = Instant::now();
    let field = HeightField::generate(settings);
    let heights = start.elapsed().as_secs_f64() * 1e3;
    let start = Instant::now();
    let mesh = TerrainMesh::new(device, &field);
    (field, mesh, (heights, start.elapsed().as_secs_f64() * 1e3))
}

/// The terrain, ready to draw: height field, meshes, and the bind group
/// (group 0) of `terrain.wgsl`. Later chapters draw the same ground with
/// shaders of their own that `#import terrain`.
pub struct TerrainRenderer {
    /// What the learner edits in the overlay; applied by `regenerate`.
    pub settings: TerrainSettings,
    pub field: HeightField,
    pub mesh: TerrainMesh,
    /// How long the last generation took: (height field, meshes and upload), ms.
    pub timings: (f64, f64),
    globals: wgpu::Buffer,
    chunk_flags: wgpu::Buffer,
    pub bind_group_layout: wgpu::BindGroupLayout,
    bind_group: wgpu::BindGroup,
}

impl TerrainRenderer {
    pub fn new(gpu: &Gpu, settings: TerrainSettings) -> Self {
        let device = &gpu.device;
        let (field, mesh, timings) = generate(device, settings);
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("terrain globals"),
            size: std::mem::size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let chunk_flags = Self::flags_buffer(device, mesh.bounds.len() as u32);
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
        let bind_group = Self::bind_group(device, &bind_group_layout, &globals, &chunk_flags);
        Self { settings, field, mesh, timings, globals, chunk_flags, bind_group_layout, bind_group }
    }

    fn flags_buffer(device: &wgpu::Device, chunks: u32) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("chunk drawn flags"),
            size: u64::from(chunks.max(1)) * 4,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn bind_group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        globals: &wgpu::Buffer,
        flags: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("terrain"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: globals.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: flags.as_entire_binding() },
            ],
        })
    }

    /// Regenerates the height field and the mesh from `self.settings`.
    pub fn regenerate(&mut self, gpu: &Gpu) {
        (self.field, self.mesh, self.timings) = generate(&gpu.device, self.settings);
        self.chunk_flags = Self::flags_buffer(&gpu.device, self.mesh.bounds.len() as u32);
        self.bind_group = Self::bind_group(&gpu.device, &self.bind_group_layout, &self.globals, &self.chunk_flags);
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
        let module = shader.module(&gpu.device)?;
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

    /// Writes the frame's uniforms: `eye` is the camera drawn from.
    pub fn write_globals(&self, queue: &wgpu::Queue, eye: &Camera, sun: Sun, shading: Shading) {
        self.write_globals_clipped(queue, eye, sun, shading, KEEP_ALL);
    }

    /// `write_globals` with a clip plane (see [`KEEP_ALL`]).
    pub fn write_globals_clipped(&self, queue: &wgpu::Queue, eye: &Camera, sun: Sun, shading: Shading, clip: Vec4) {
        let globals = Globals {
            view_proj: eye.view_projection().to_cols_array_2d(),
            eye: eye.position.extend(1.0).into(),
            sun: sun.direction.normalize().extend(sun.strength).into(),
            grid: [self.mesh.chunks_per_side, CHUNK_QUADS, shading as u32, 0],
            scale: [self.field.settings.spacing, self.field.settings.height, 0.0, 0.0],
            clip: clip.into(),
        };
        queue.write_buffer(&self.globals, 0, bytemuck::bytes_of(&globals));
    }

    /// Marks which chunks `frustum` keeps, for `Shading::Chunks`.
    pub fn write_chunk_flags(&self, queue: &wgpu::Queue, frustum: &Frustum) {
        let flags: Vec<u32> = self.mesh.bounds.iter().map(|b| u32::from(frustum.intersects(b))).collect();
        queue.write_buffer(&self.chunk_flags, 0, bytemuck::cast_slice(&flags));
    }

    /// Binds group 0 (camera, sun, grid), which other shaders that import
    /// the terrain module read too.
    pub fn bind(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &self.bind_group, &[]);
    }

    /// Binds group 0 and draws the chunks `frustum` keeps; returns how many.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, frustum: &Frustum) -> usize {
        self.bind(pass);
        self.mesh.draw_visible(pass, frustum)
    }

    /// Sliders for the generator; true when the terrain should be regenerated.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> bool {
        let size = self.field.size;
        ui.label(format!(
            "{size} × {size} samples, {} bytes per vertex; heights {:.0} ms, meshes {:.0} ms",
            std::mem::size_of::<TerrainVertex>(),
            self.timings.0,
            self.timings.1
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
        let size = self.field.size;
        format!(
            "{size}×{size} heights in {:.0} ms, chunk meshes built and uploaded in {:.0} ms; {} bytes per vertex, {:.0} MB of vertices; {drawn} of {} chunks drawn",
            self.timings.0,
            self.timings.1,
            std::mem::size_of::<TerrainVertex>(),
            self.mesh.vertex_buffer.size() as f64 / 1e6,
            self.mesh.bounds.len()
        )
    }
}

pub struct TerrainChapter {
    pub terrain: TerrainRenderer,
    pub camera: Camera,
    pub controller: FlyController,
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
    const TITLE: &'static str = "03 · Terrain from noise";
    const VIEWS: &'static [View] = VIEWS;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let terrain = TerrainRenderer::new(gpu, TerrainSettings::default());
        let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("terrain"),
            bind_group_layouts: &[Some(&terrain.bind_group_layout)],
            immediate_size: 0,
        });
        let pipeline = terrain.pipeline(gpu, &terrain_shader(), &layout, target.format)?;
        Ok(Self {
            camera: start_camera(&terrain.field, target.aspect()),
            controller: FlyController { speed: 40.0, ..Default::default() },
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

    /// Each view starts from its own camera: the wireframe from close up.
    fn select_view(&mut self, view: usize) {
        let aspect = self.target.aspect();
        self.camera = match VIEWS[view].name {
            "wireframe" => close_up_camera(&self.terrain.field, aspect),
            _ => start_camera(&self.terrain.field, aspect),
        };
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        if std::mem::take(&mut self.regenerate_requested) {
            self.terrain.regenerate(gpu);
        }
        // Culling always uses the flying camera; the `chunks` view looks at
        // its result from high above.
        let frustum = Frustum::from_view_projection(self.camera.view_projection());
        let (eye, shading) = match VIEWS[frame.view].name {
            "wireframe" => (self.camera, Shading::Wireframe),
            "normals" => (self.camera, Shading::Normals),
            "chunks" => (overhead_camera(&self.terrain.field, self.target.aspect()), Shading::Chunks),
            _ => (self.camera, Shading::Shaded),
        };
        self.terrain.write_globals(&gpu.queue, &eye, Sun::AFTERNOON, shading);
        if shading == Shading::Chunks {
            self.terrain.write_chunk_flags(&gpu.queue, &frustum);
        }

        let mut pass = frame.scene_pass("terrain", SKY, &self.depth);
        pass.set_pipeline(&self.pipeline);
        if shading == Shading::Chunks {
            // Draw every chunk, so the culled ones can be seen as such.
            self.terrain.draw(&mut pass, &Frustum::from_view_projection(eye.view_projection()));
            self.drawn = self.terrain.mesh.bounds.iter().filter(|b| frustum.intersects(b)).count();
        } else {
            self.drawn = self.terrain.draw(&mut pass, &frustum);
        }
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label(format!("chunks drawn: {} / {}", self.drawn, self.terrain.mesh.bounds.len()));
        self.regenerate_requested |= self.terrain.settings_ui(ui);
        ui.add(egui::Slider::new(&mut self.controller.speed, 5.0..=400.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&self) -> String {
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
