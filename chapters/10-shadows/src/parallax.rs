//! Parallax: three pictures on planes standing further and further behind
//! the level. A camera sliding sideways by d moves a plane at distance D
//! across the screen by an amount proportional to d / D, so the far
//! mountains creep and the near forest hurries, with nothing but
//! perspective doing it.

use std::path::Path;

use common::chapter::{FILTERABLE, sampler_entry, texture_entry, uniform_entry};
use common::glam::Vec3;
use common::texture::ColorSpace;
use common::{Drawn, Gpu, Reloadable, ShaderError, anyhow, shader, wgpu};
use lighting::{HDR_FORMAT, SceneLights};
use textures::materials::{Uploader, upload};

use crate::game::Level;

// ANCHOR: layers
/// One background layer: its picture, the plane it stands on (z, behind
/// the level at z = 0), how tall the picture is there, where its bottom
/// edge is, and how much the distance hazes it towards the sky.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    pub picture: &'static str,
    pub z: f32,
    pub height: f32,
    pub bottom: f32,
    pub haze: f32,
}

/// Near to far. Each picture is four times as wide as it is tall, and
/// repeats along x.
pub const LAYERS: [Layer; 3] = [
    Layer { picture: "layers/near.png", z: -14.0, height: 14.0, bottom: -7.0, haze: 0.15 },
    Layer { picture: "layers/middle.png", z: -35.0, height: 28.0, bottom: -12.0, haze: 0.35 },
    Layer { picture: "layers/far.png", z: -90.0, height: 60.0, bottom: -25.0, haze: 0.55 },
];
// ANCHOR_END: layers

/// A corner of a layer's plane.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct LayerVertex {
    position: [f32; 3],
    uv: [f32; 2],
    layer: u32,
}

/// `Layers` in layers.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct LayersUniform {
    horizon: [f32; 4],
    haze: [f32; 4],
    tint_by_depth: [u32; 4],
    _padding: [f32; 4],
}

/// Draws the layers into the scene pass. Inputs: the level (how wide the
/// planes must be), the scene's lights (for the camera and the light
/// they are tinted by), the sky's horizon colour.
pub struct Parallax {
    /// Made again when layers.wgsl or the lights' module is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    groups: Vec<wgpu::BindGroup>,
    uniform: wgpu::Buffer,
    vertices: wgpu::Buffer,
}

impl Parallax {
    /// The layers for an HDR pass of `multisample`'s samples a pixel
    /// ([`lighting::HdrTarget::multisample`]).
    pub fn new(
        gpu: &Gpu,
        up: &mut Uploader,
        lights: &SceneLights,
        level: &Level,
        multisample: wgpu::MultisampleState,
    ) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("layer"),
            entries: &[
                texture_entry(0, FILTERABLE),
                sampler_entry(1),
                uniform_entry(2, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<LayersUniform>()),
            ],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("layers"),
            size: std::mem::size_of::<LayersUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        // Repeats along x, stops at the picture's top and bottom edges.
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("layers"),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        let mut groups = Vec::new();
        for layer in LAYERS {
            let path = Path::new(layer.picture);
            let bytes = (up.read)(path)?;
            let image = common::texture::decode_named(layer.picture, &bytes)?;
            let texture = upload(up, &image, ColorSpace::Srgb, layer.picture);
            groups.push(device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(layer.picture),
                layout: &layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&texture.view) },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&sampler) },
                    wgpu::BindGroupEntry { binding: 2, resource: uniform.as_entire_binding() },
                ],
            }));
        }
        let vertices = common::wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("layers"),
                contents: bytemuck::cast_slice(&Self::planes(level)),
                usage: wgpu::BufferUsages::VERTEX,
            },
        );
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("layers"),
            bind_group_layouts: &[Some(&lights.layout), Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &pipeline_layout, multisample))?;
        Ok(Self { pipeline, groups, uniform, vertices })
    }

    // ANCHOR: planes
    /// Two triangles per layer, wide enough to fill the view from either
    /// end of the level; u counts repeats of the picture, keeping its shape.
    fn planes(level: &Level) -> Vec<LayerVertex> {
        let mut vertices = Vec::new();
        for (index, layer) in LAYERS.iter().enumerate() {
            // The view is about as wide as its distance at 60° and 16:9;
            // three times that covers any window shape.
            let margin = 3.0 * (13.0 - layer.z);
            let (left, right) = (-margin, level.width + margin);
            let (bottom, top) = (layer.bottom, layer.bottom + layer.height);
            let repeat = 4.0 * layer.height;
            let corner = |x: f32, y: f32, v: f32| LayerVertex {
                position: [x, y, layer.z],
                uv: [x / repeat, v],
                layer: index as u32,
            };
            let [a, b, c, d] = [
                corner(left, bottom, 1.0),
                corner(right, bottom, 1.0),
                corner(right, top, 0.0),
                corner(left, top, 0.0),
            ];
            vertices.extend([a, b, c, a, c, d]);
        }
        vertices
    }
    // ANCHOR_END: planes

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        multisample: wgpu::MultisampleState,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module =
            shader!("shadows/layers.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl"]).module(gpu)?;
        let buffer = wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<LayerVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x2, 2 => Uint32],
        };
        // A cut-out at one sample a pixel; with more, alpha to coverage
        // (layers.wgsl says why).
        let (fragment, multisample) = if multisample.count > 1 {
            ("fs_layer_coverage", wgpu::MultisampleState { alpha_to_coverage_enabled: true, ..multisample })
        } else {
            ("fs_layer", multisample)
        };
        gpu.catch_validation(|| {
            common::chapter::mesh_pipeline(
                &gpu.device,
                layout,
                &module,
                ("vs_layer", fragment),
                &[Some(buffer)],
                HDR_FORMAT.into(),
                multisample,
            )
        })
        .map_err(ShaderError)
    }

    /// Draws the layers; group 0 of `pass` must be the scene's lights.
    /// Returns what it drew: two triangles a layer.
    pub fn draw(&self, gpu: &Gpu, pass: &mut wgpu::RenderPass<'_>, horizon: Vec3, tint_by_depth: bool) -> Drawn {
        let uniform = LayersUniform {
            horizon: horizon.extend(1.0).into(),
            haze: [LAYERS[0].haze, LAYERS[1].haze, LAYERS[2].haze, 0.0],
            tint_by_depth: [u32::from(tint_by_depth), 0, 0, 0],
            _padding: [0.0; 4],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        pass.set_pipeline(&self.pipeline.get());
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        let mut drawn = Drawn::NOTHING;
        for (index, group) in self.groups.iter().enumerate() {
            pass.set_bind_group(1, group, &[]);
            let first = 6 * index as u32;
            pass.draw(first..first + 6, 0..1);
            drawn += Drawn::triangle_list(first..first + 6, 0..1);
        }
        drawn
    }
}
