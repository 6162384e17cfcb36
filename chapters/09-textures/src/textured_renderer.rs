//! Textured models lit by chapter 08's lights: [`TexturedRenderer`], one
//! pipeline with group 0 the [`SceneLights`], group 1 a material and group
//! 2 the sampler; the [`DrawList`] of models, instances and materials it
//! draws (chapters 10 and 11 draw theirs with it too); and
//! [`upload_model`], which puts a model and its materials on the GPU.

use common::chapter::{mesh_pipeline, sampler_entry, storage_entry};
use common::{Drawn, Gpu, Reloadable, ShaderError, shader, wgpu};
use lighting::{HDR_FORMAT, SceneLights, Shading};

use crate::materials::{Materials, SamplerMode, Uploader};
use crate::mesh::{GpuModel, ModelData, ModelInstance, TexturedVertex};

// ANCHOR: view_options
/// `ViewOptions` in textured.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ViewOptions {
    flip_green: u32,
    target_width: f32,
    _padding: [f32; 2],
}
// ANCHOR_END: view_options

// ANCHOR: renderer
/// Draws textured models lit by chapter 08's lights: one pipeline, group 0
/// the [`SceneLights`], group 1 a material, group 2 the sampler and view
/// options. A piece with explicit inputs: the models, their instances and
/// the materials. Only this chapter draws with it: 10 and 11 use chapter 10's `ShadowedRenderer`.
pub struct TexturedRenderer {
    /// Made again when textured.wgsl or a module it imports is saved (hot reload).
    pipelines: Reloadable<Pipelines>,
    options: wgpu::Buffer,
    /// One group per sampler mode, in `SamplerMode::ALL`'s order.
    sampler_groups: Vec<wgpu::BindGroup>,
    /// Whether the adapter filters anisotropically.
    pub anisotropy: bool,
}

/// Phong shading's fragment shaders: with normal maps, without (no normal
/// map read at all, so the bench sees what they cost); Gouraud and flat
/// shading, which have no use for normal maps; and the tangent frame view.
#[derive(Clone)]
struct Pipelines {
    normal_mapped: wgpu::RenderPipeline,
    plain: wgpu::RenderPipeline,
    gouraud: wgpu::RenderPipeline,
    flat: wgpu::RenderPipeline,
    frame: wgpu::RenderPipeline,
}

/// One model drawn with a range of this frame's instances.
pub struct Draw<'a> {
    pub model: &'a GpuModel,
    pub instances: std::ops::Range<u32>,
}

/// What a frame draws: models with their instances, and the materials
/// the models' parts refer to.
pub struct DrawList<'a> {
    pub materials: &'a Materials,
    pub instances: &'a wgpu::Buffer,
    pub draws: Vec<Draw<'a>>,
}

// ANCHOR_END: renderer

// ANCHOR: draw_list
impl DrawList<'_> {
    /// Draws every model, one draw per part with its material in group 1
    /// (`swapped`: the material's views in the other colour space), into a
    /// pass whose pipeline and other groups are set. Chapter 10 draws its
    /// level with this too. Returns what the draws drew.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, swapped: bool) -> Drawn {
        pass.set_vertex_buffer(1, self.instances.slice(..));
        let mut drawn = Drawn::NOTHING;
        for draw in &self.draws {
            if draw.instances.is_empty() {
                continue;
            }
            pass.set_vertex_buffer(0, draw.model.vertices.slice(..));
            pass.set_index_buffer(draw.model.indices.slice(..), wgpu::IndexFormat::Uint32);
            for part in &draw.model.parts {
                let material = &self.materials.list[draw.model.first_material + part.material];
                pass.set_bind_group(1, if swapped { &material.swapped_group } else { &material.group }, &[]);
                pass.draw_indexed(part.indices.clone(), 0, draw.instances.clone());
                drawn += Drawn::triangle_list(part.indices.clone(), draw.instances.clone());
            }
        }
        drawn
    }
}
// ANCHOR_END: draw_list

impl TexturedRenderer {
    /// The renderer for an HDR pass of `multisample`'s samples a pixel
    /// ([`lighting::HdrTarget::multisample`]).
    pub fn new(
        gpu: &Gpu,
        lights: &SceneLights,
        materials: &Materials,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("view"),
            entries: &[sampler_entry(0), storage_entry(1, wgpu::ShaderStages::FRAGMENT)],
        });
        let options = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("view options"),
            size: std::mem::size_of::<ViewOptions>() as u64,
            // Storage, not uniform: the shader branches on it (see `storage_entry`).
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let anisotropy = gpu.downlevel().flags.contains(wgpu::DownlevelFlags::ANISOTROPIC_FILTERING);
        let sampler_groups = SamplerMode::ALL
            .iter()
            .map(|mode| {
                let sampler = device.create_sampler(&mode.descriptor(anisotropy));
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("view"),
                    layout: &layout,
                    entries: &[
                        wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::Sampler(&sampler) },
                        wgpu::BindGroupEntry { binding: 1, resource: options.as_entire_binding() },
                    ],
                })
            })
            .collect();
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("textured"),
            bind_group_layouts: &[Some(&lights.layout), Some(&materials.layout), Some(&layout)],
            immediate_size: 0,
        });
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &pipeline_layout, multisample))?;
        Ok(Self { pipelines, options, sampler_groups, anisotropy })
    }

    fn pipelines(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        multisample: wgpu::MultisampleState,
    ) -> Result<Pipelines, ShaderError> {
        let module = shader!("textures/textured.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl", "textures/surface.wgsl"])
            .module(gpu)?;
        let buffers = [Some(TexturedVertex::LAYOUT), Some(ModelInstance::LAYOUT)];
        let pipeline =
            |entries| mesh_pipeline(&gpu.device, layout, &module, entries, &buffers, HDR_FORMAT.into(), multisample);
        gpu.catch_validation(|| Pipelines {
            normal_mapped: pipeline(("vs_main", "fs_normal_mapped")),
            plain: pipeline(("vs_main", "fs_plain")),
            gouraud: pipeline(("vs_gouraud", "fs_gouraud")),
            flat: pipeline(("vs_flat", "fs_flat")),
            frame: pipeline(("vs_main", "fs_frame")),
        })
        .map_err(ShaderError)
    }

    // ANCHOR: draw
    /// Draws `draws` into `pass`, whose group 0 must already be the scene's
    /// lights; `instances` holds every draw's instances. Returns what it drew.
    pub fn draw(
        &self,
        gpu: &Gpu,
        pass: &mut wgpu::RenderPass<'_>,
        settings: &SurfaceOptions,
        target_width: u32,
        list: &DrawList,
    ) -> Drawn {
        let options = ViewOptions {
            flip_green: u32::from(settings.flip_green),
            target_width: target_width as f32,
            _padding: [0.0; 2],
        };
        gpu.queue.write_buffer(&self.options, 0, bytemuck::bytes_of(&options));
        let mode = SamplerMode::ALL.iter().position(|m| *m == settings.sampler).unwrap_or(0);
        let pipelines = self.pipelines.get();
        pass.set_pipeline(match (settings.show_frame, settings.shading, settings.normal_maps) {
            (true, _, _) => &pipelines.frame,
            (false, Shading::Flat, _) => &pipelines.flat,
            (false, Shading::Gouraud, _) => &pipelines.gouraud,
            (false, Shading::Phong, true) => &pipelines.normal_mapped,
            (false, Shading::Phong, false) => &pipelines.plain,
        });
        pass.set_bind_group(2, &self.sampler_groups[mode], &[]);
        list.draw(pass, settings.swapped_colour_spaces)
    }
    // ANCHOR_END: draw
}

/// How [`TexturedRenderer::draw`] shades surfaces: what chapter 09's views
/// switch between.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SurfaceOptions {
    /// Where the light is worked out: per face, per vertex or per
    /// fragment (chapter 08's switch). Textures are read per fragment in all three.
    pub shading: Shading,
    pub sampler: SamplerMode,
    /// Normal maps, where the material has them (Phong shading only: lit
    /// per face or per vertex, there is no normal at a texel to bend).
    pub normal_maps: bool,
    /// Read normal maps' green as pointing down the image (DirectX's way).
    pub flip_green: bool,
    /// Albedo read as linear data and normal maps as sRGB: the mistake.
    pub swapped_colour_spaces: bool,
    /// Show the tangent frame as colours instead of the picture.
    pub show_frame: bool,
}

/// Uploads `model`'s materials and then the model.
pub fn upload_model(up: &mut Uploader, materials: &mut Materials, model: &ModelData, label: &str) -> GpuModel {
    let first = materials.list.len();
    for desc in &model.materials {
        materials.add(up, desc);
    }
    GpuModel::upload(&up.gpu.device, model, first, label)
}
