//! The terrain, ready to draw for any chapter: the sun and the shading
//! mode as inputs, a `Viewpoint` (group 0 of `terrain.wgsl`) per camera
//! that holds the patches the quadtree chose for it, pipelines for shaders
//! that `#import terrain`, and the draw: one instanced call for every patch.

use std::sync::Arc;

use common::chapter::uniform_entry;
use common::glam::{Vec3, Vec4};
use common::texture::depth_test;
use common::{Camera, Drawn, Gpu, ShaderError, ShaderFile, egui, wgpu};

use crate::chunks::Aabb;
use crate::culling::Frustum;
use crate::heightfield::{CHUNK_QUADS, HeightField, TerrainSettings};
use crate::lod::{Detail, LodRanges};
use crate::quadtree::Patch;
use crate::terrain_data::TerrainData;
use crate::terrain_maps::PATCH_LAYOUT;

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
    lod: [f32; 4],
}

/// What every chapter that draws the terrain asks of the device: clip
/// distances where the adapter has them (`terrain.wgsl` clips with them,
/// and with a fragment discard otherwise). Asking for the same thing keeps
/// chapters 03 to 07 on one kind of device, so a process that opens several
/// of them can share the terrain made on it (`Gpu::cached`).
pub fn gpu_needs() -> common::GpuNeeds {
    let base = common::GpuNeeds::default();
    common::GpuNeeds {
        optional: wgpu::Features::CLIP_DISTANCES,
        // The height and normal maps are one texture each, a sample a texel:
        // 4097 a side by default, more than WebGL2's guaranteed 2048.
        limits: wgpu::Limits { max_texture_dimension_2d: TerrainSettings::default().samples(), ..base.limits },
        ..base
    }
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
    /// A colour per level of detail, blending into the next as it morphs.
    Levels = 3,
}

// ANCHOR: viewpoint
/// Drawing the terrain from one camera: the uniforms of group 0 of
/// `terrain.wgsl` (which shaders that import the module read too), and
/// the patches the quadtree chose for that camera. A frame that draws the
/// terrain from several cameras (chapter 07's reflection, refraction and
/// main picture) has one viewpoint for each, so that all of them can be
/// recorded into one encoder and submitted once.
pub struct Viewpoint {
    globals: wgpu::Buffer,
    /// Group 0: the uniforms, and the maps of the terrain it was made for.
    bind_group: wgpu::BindGroup,
    terrain: Arc<TerrainData>,
    frustum: Frustum,
    patches: Vec<Patch>,
    patch_buffer: wgpu::Buffer,
}
// ANCHOR_END: viewpoint

impl Viewpoint {
    /// The frustum of the camera this viewpoint was last aimed from: later
    /// chapters cull what they group by chunk (chapter 05's rocks) with it.
    pub fn frustum(&self) -> &Frustum {
        &self.frustum
    }

    /// The patches chosen when the viewpoint was last aimed.
    pub fn patches(&self) -> &[Patch] {
        &self.patches
    }

    /// Triangles the terrain's draw from this viewpoint has: every patch's.
    pub fn triangles(&self) -> u64 {
        self.patches.len() as u64 * u64::from(Patch::TRIANGLES)
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
    sampler: wgpu::Sampler,
    pub bind_group_layout: wgpu::BindGroupLayout,
}

impl TerrainRenderer {
    /// The renderer of terrain `data` (what [`TerrainData::prepare`] made).
    pub fn new(gpu: &Gpu, data: Arc<TerrainData>) -> Self {
        let device = &gpu.device;
        let settings = data.field.settings;
        let texture = |binding, visibility, sample_type| wgpu::BindGroupLayoutEntry {
            binding,
            visibility,
            ty: wgpu::BindingType::Texture {
                sample_type,
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        };
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("terrain"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT, std::mem::size_of::<Globals>()),
                // Heights are read exactly, never filtered: 32-bit floats.
                texture(1, wgpu::ShaderStages::VERTEX, wgpu::TextureSampleType::Float { filterable: false }),
                texture(2, wgpu::ShaderStages::FRAGMENT, common::chapter::FILTERABLE),
                common::chapter::sampler_entry(3),
            ],
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("terrain normals"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Self { settings, shading: Shading::Shaded, data, sampler, bind_group_layout }
    }

    /// The height field the terrain was made from: where the ground is.
    pub fn field(&self) -> &HeightField {
        &self.data.field
    }

    /// Chunk (x, z)'s box at `z * chunks_per_side + x`.
    pub fn chunk_bounds(&self) -> &[Aabb] {
        &self.data.chunk_bounds
    }

    /// The terrain's data: field, boxes, quadtree and maps.
    pub fn data(&self) -> &TerrainData {
        &self.data
    }

    /// Makes the terrain again from `self.settings` (the number of chunks
    /// stays as it was). Viewpoints keep working: each takes the new maps
    /// the next time it is aimed.
    pub fn regenerate(&mut self, gpu: &Gpu) {
        self.settings.chunks_per_side = self.data.field.settings.chunks_per_side;
        self.data = TerrainData::get(gpu, self.settings);
    }

    fn bind_group(&self, device: &wgpu::Device, globals: &wgpu::Buffer) -> wgpu::BindGroup {
        let view = |texture: &wgpu::Texture| texture.create_view(&Default::default());
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("terrain"),
            layout: &self.bind_group_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: globals.as_entire_binding() },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&view(&self.data.maps.heights)),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(&view(&self.data.maps.normals)),
                },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.sampler) },
            ],
        })
    }

    /// A new viewpoint: uniforms and room for the patches of one more camera.
    pub fn viewpoint(&self, device: &wgpu::Device) -> Viewpoint {
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("terrain globals"),
            size: std::mem::size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        // At most every chunk at full detail: four patches each.
        let most = 4 * self.data.chunk_bounds.len().max(1);
        let patch_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("terrain patches"),
            size: (most * std::mem::size_of::<Patch>()) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let frustum = Frustum::from_view_projection(Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, 1.0).view_projection());
        Viewpoint {
            bind_group: self.bind_group(device, &globals),
            globals,
            terrain: self.data.clone(),
            frustum,
            patches: Vec::with_capacity(most),
            patch_buffer,
        }
    }

    /// A pipeline that draws the terrain's patches with `shader`'s
    /// `vs_main` and `fs_main` into targets of `format` and `samples`
    /// samples a pixel; `layout` starts with a renderer's bind group
    /// layout. It takes no renderer, so that a `Reloadable` can call it
    /// again on hot reload.
    pub fn pipeline(
        gpu: &Gpu,
        shader: &ShaderFile,
        layout: &wgpu::PipelineLayout,
        (format, samples): (wgpu::TextureFormat, u32),
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader.module(gpu)?;
        gpu.catch_validation(|| {
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(shader.path),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    buffers: &[Some(PATCH_LAYOUT)],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
                depth_stencil: depth_test(),
                multisample: common::multisampling::multisample(samples),
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

    /// How far each level reaches in a picture from `camera` drawn as
    /// finely as `detail` asks.
    pub fn ranges(&self, camera: &Camera, detail: Detail) -> LodRanges {
        let spacing = self.data.field.settings.spacing;
        LodRanges::new(detail, camera.fov_y, spacing, self.data.quadtree.node_reach(), self.data.quadtree.top_level())
    }

    // ANCHOR: aim
    /// Aims `viewpoint` at the scene from `camera`, for a picture drawn
    /// as finely as `detail` asks: chooses the patches to draw, and writes
    /// the uniforms, lit by `sun`, keeping what `clip` keeps ([`KEEP_ALL`]
    /// for everything).
    pub fn aim(&self, gpu: &Gpu, viewpoint: &mut Viewpoint, camera: &Camera, detail: Detail, sun: Sun, clip: Vec4) {
        self.aim_seen_from(gpu, viewpoint, camera, detail, sun, clip, camera);
    }
    // ANCHOR_END: aim

    /// [`TerrainRenderer::aim`], but the picture is taken from `seen_from`
    /// while the patches are chosen, and morph, for `camera`: chapter 03's
    /// `quadtree` view looks from high above at what its camera draws.
    #[allow(clippy::too_many_arguments)]
    pub fn aim_seen_from(
        &self,
        gpu: &Gpu,
        viewpoint: &mut Viewpoint,
        camera: &Camera,
        detail: Detail,
        sun: Sun,
        clip: Vec4,
        seen_from: &Camera,
    ) {
        if !Arc::ptr_eq(&viewpoint.terrain, &self.data) {
            // The terrain was made again: bind its maps instead.
            viewpoint.bind_group = self.bind_group(&gpu.device, &viewpoint.globals);
            viewpoint.terrain = self.data.clone();
        }
        let ranges = self.ranges(camera, detail);
        viewpoint.frustum = Frustum::from_view_projection(camera.view_projection());
        self.data.quadtree.select(&viewpoint.frustum, camera.position, &ranges, &mut viewpoint.patches);
        gpu.queue.write_buffer(&viewpoint.patch_buffer, 0, bytemuck::cast_slice(&viewpoint.patches));
        let settings = &self.data.field.settings;
        let globals = Globals {
            view_proj: seen_from.view_projection().to_cols_array_2d(),
            eye: camera.position.extend(1.0).into(),
            sun: sun.direction.normalize().extend(sun.strength).into(),
            grid: [settings.chunks_per_side, CHUNK_QUADS, self.shading as u32, self.data.field.size],
            scale: [settings.spacing, settings.height, 0.0, 0.0],
            clip: clip.into(),
            // The shader multiplies: keep infinity out of it.
            lod: [ranges.first.min(f32::MAX), ranges.morph_start, ranges.top_level as f32, 0.0],
        };
        gpu.queue.write_buffer(&viewpoint.globals, 0, bytemuck::bytes_of(&globals));
    }

    /// Binds group 0 for `viewpoint`: what other shaders that import the
    /// terrain module (fog, rocks, water) read too.
    pub fn bind(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &Viewpoint) {
        pass.set_bind_group(0, &viewpoint.bind_group, &[]);
    }

    // ANCHOR: draw
    /// Binds group 0 and draws every patch the viewpoint's camera chose,
    /// in one instanced call; returns what it drew.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &Viewpoint) -> Drawn {
        let count = viewpoint.patches.len();
        if count == 0 {
            return Drawn::NOTHING;
        }
        self.bind(pass, viewpoint);
        let maps = &viewpoint.terrain.maps;
        pass.set_vertex_buffer(0, viewpoint.patch_buffer.slice(..(count * std::mem::size_of::<Patch>()) as u64));
        pass.set_index_buffer(maps.patch_indices.slice(..), wgpu::IndexFormat::Uint16);
        pass.draw_indexed(0..maps.patch_index_count, 0, 0..count as u32);
        Drawn::counted(1, viewpoint.triangles())
    }
    // ANCHOR_END: draw

    /// Sliders for the generator; true when the terrain should be regenerated.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> bool {
        let size = self.data.field.size;
        ui.label(format!(
            "{size} × {size} samples; heights {:.0} ms, normals, boxes and upload {:.0} ms",
            self.data.timings.0, self.data.timings.1
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

    /// What a viewpoint draws, for the overlay and `--bench`: patches by
    /// level and triangles.
    pub fn drawn(&self, viewpoint: &Viewpoint) -> String {
        let mut by_level = [0u32; 16];
        for p in viewpoint.patches() {
            by_level[p.level as usize] += 1;
        }
        let levels: Vec<String> = (0..=self.data.quadtree.top_level() as usize)
            .filter(|&l| by_level[l] > 0)
            .map(|l| format!("{} of level {l}", by_level[l]))
            .collect();
        format!(
            "{} patches ({}), {} triangles",
            viewpoint.patches().len(),
            levels.join(", "),
            common::book_figures::thousands(viewpoint.triangles() as f64)
        )
    }

    /// The chapter's figures for `--bench`.
    pub fn stats(&self, viewpoint: &Viewpoint) -> String {
        let size = self.data.field.size;
        format!(
            "{size}×{size} heights in {:.0} ms, normals, boxes and upload in {:.0} ms; {:.1} MB of maps; nodes at most {:.0} m across per level; {}",
            self.data.timings.0,
            self.data.timings.1,
            self.data.maps.gpu_bytes() as f64 / 1e6,
            self.data.quadtree.node_reach(),
            self.drawn(viewpoint)
        )
    }
}
