//! The terrain, ready to draw for any chapter: the sun and the shading
//! mode as inputs, a `Viewpoint` (group 0 of `terrain.wgsl`) per camera,
//! pipelines for shaders that `#import terrain`, and the culled draw.

use std::sync::Arc;

use common::chapter::uniform_entry;
use common::glam::{Vec3, Vec4};
use common::texture::depth_test;
use common::{Camera, Gpu, ShaderError, ShaderFile, egui, wgpu};

use crate::chunks::TerrainVertex;
use crate::culling::Frustum;
use crate::heightfield::{CHUNK_QUADS, HeightField, TerrainSettings};
use crate::lod::Detail;
use crate::terrain_data::TerrainData;
use crate::terrain_mesh::{TERRAIN_VERTEX_LAYOUT, TerrainMesh};

/// Pale butterscotch: the Martian sky, and the clear colour.
pub const SKY: wgpu::Color = wgpu::Color { r: 0.62, g: 0.42, b: 0.28, a: 1.0 };

pub use common::sun::Sun;

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

impl Viewpoint {
    /// The frustum of the camera this viewpoint was last aimed from: later
    /// chapters cull what they group by chunk (chapter 05's rocks) with it.
    pub fn frustum(&self) -> &Frustum {
        &self.frustum
    }
}

/// The terrain, ready to draw: its data and the layout of group 0. Later
/// chapters draw the same ground with shaders of their own that
/// `#import terrain`.
pub struct TerrainRenderer {
    /// What the learner edits in the overlay; applied by `regenerate`.
    pub settings: TerrainSettings,
    /// How the ground is coloured in the pictures aimed from now on.
    pub shading: Shading,
    data: Arc<TerrainData>,
    /// One flag per chunk for the `chunks` view (shared by every viewpoint).
    chunk_flags: wgpu::Buffer,
    pub bind_group_layout: wgpu::BindGroupLayout,
}

impl TerrainRenderer {
    /// The renderer of terrain `data` (what [`TerrainData::prepare`] made).
    pub fn new(gpu: &Gpu, data: Arc<TerrainData>) -> Self {
        let device = &gpu.device;
        let settings = data.field.settings;
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
        Self { settings, shading: Shading::Shaded, data, chunk_flags, bind_group_layout }
    }

    /// The height field the terrain was made from: where the ground is.
    pub fn field(&self) -> &HeightField {
        &self.data.field
    }

    pub fn mesh(&self) -> &TerrainMesh {
        &self.data.mesh
    }

    pub fn chunk_bounds(&self) -> &[crate::chunks::Aabb] {
        &self.data.mesh.bounds
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
    /// `fs_main`; `layout` starts with a renderer's bind group layout. It
    /// takes no renderer, so that a `Reloadable` can call it again on hot reload.
    pub fn pipeline(
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

    /// Aims `viewpoint` at the scene from `camera`, for a picture drawn
    /// as finely as `detail` asks: writes its uniforms, lit by `sun`,
    /// keeping what `clip` keeps ([`KEEP_ALL`] for everything), and keeps
    /// the camera's frustum for culling.
    pub fn aim(
        &self,
        queue: &wgpu::Queue,
        viewpoint: &mut Viewpoint,
        camera: &Camera,
        detail: Detail,
        sun: Sun,
        clip: Vec4,
    ) {
        let _ = detail;
        let shading = self.shading;
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
