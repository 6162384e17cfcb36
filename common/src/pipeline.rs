//! Shorthands for the boilerplate of drawing: the pass that starts a 3D
//! frame, an opaque mesh pipeline, and bind-group layout entries. Chapter
//! 02 writes each of these out in full; later chapters call these.

use crate::PassTimer;

/// Begins the pass that starts most 3D frames, into any `target`: clear it
/// to `clear` and `depth` to the far plane (1.0), time it as `label`.
/// `Frame::scene_pass` begins it into the frame; this is for pictures a
/// chapter renders besides the frame itself (chapter 07's reflection and
/// refraction).
pub fn scene_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    timer: &PassTimer,
    label: &'static str,
    target: &wgpu::TextureView,
    clear: wgpu::Color,
    depth: &wgpu::TextureView,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: target,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load: wgpu::LoadOp::Clear(clear), store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
            stencil_ops: None,
        }),
        timestamp_writes: timer.pass(label),
        ..Default::default()
    })
}

/// An opaque mesh pipeline: back faces culled, depth tested against
/// [`crate::texture::depth_test`], one colour `target` of `multisample`'s
/// samples a pixel ([`crate::SceneTargets::multisample`]); `entries` names
/// the vertex and fragment functions, and the fragment's names the pipeline.
/// Chapter 02 writes one out in full; later chapters call this.
pub fn mesh_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    (vertex_entry, fragment_entry): (&str, &str),
    buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
    target: wgpu::ColorTargetState,
    multisample: wgpu::MultisampleState,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(fragment_entry),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vertex_entry),
            buffers,
            compilation_options: Default::default(),
        },
        primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
        depth_stencil: crate::texture::depth_test(),
        multisample,
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fragment_entry),
            targets: &[Some(target)],
            compilation_options: Default::default(),
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// A bind-group layout entry for a 2D texture read by fragment shaders;
/// `filterable` float textures are the common case (chapter 02 spells
/// entries out; later chapters call these).
pub fn texture_entry(binding: u32, sample_type: wgpu::TextureSampleType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

/// The sample type of colour textures that may be filtered.
pub const FILTERABLE: wgpu::TextureSampleType = wgpu::TextureSampleType::Float { filterable: true };

/// A bind-group layout entry for a filtering sampler used by fragment shaders.
pub fn sampler_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        count: None,
    }
}

/// A bind-group layout entry for a read-only storage buffer of any size.
/// Chapters 08–11 keep the values their shaders branch or loop on here
/// rather than in a uniform buffer: Mesa's lavapipe 22.3 can compile a copy
/// of a large shader with such uniform values written in, for each set of
/// values it is bound with, and keep every copy (the book's chapter 08
/// pitfalls).
pub fn storage_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: true },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// A bind-group layout entry for a uniform buffer of `size` bytes (chapter 02
/// spells these out; later chapters call this).
pub fn uniform_entry(binding: u32, visibility: wgpu::ShaderStages, size: usize) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: wgpu::BufferSize::new(size as u64),
        },
        count: None,
    }
}
