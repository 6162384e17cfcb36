//! The pipeline that draws the scene's meshes: the chapter's shaders, the
//! vertex layout, back faces culled, and a depth test; and the chapter's
//! pipelines, all built from it but the depth view's.

use common::texture::DEPTH_FORMAT;
use common::{Gpu, ShaderError, fullscreen, shader, wgpu};

/// A pipeline that draws meshes with `vs_main` and `fragment_entry` of
/// `module`, keeping the nearest fragment at each pixel, into targets of
/// `multisample`'s samples a pixel.
// ANCHOR: pipeline
pub fn scene_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    format: wgpu::TextureFormat,
    fragment_entry: &str,
    multisample: wgpu::MultisampleState,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(fragment_entry),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            buffers: &[Some(common::Vertex::LAYOUT)],
            compilation_options: Default::default(),
        },
        primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
        // Keep a fragment only if it is nearer than what is already there,
        // and remember its depth for the fragments that come after it.
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        // One sample a pixel, or four (multisampling): as the pass's targets.
        multisample,
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
// ANCHOR_END: pipeline

/// The chapter's pipelines, kept in a `Reloadable`: rebuilt when their WGSL
/// is saved (hot reload).
#[derive(Clone)]
pub struct Pipelines {
    pub shaded: wgpu::RenderPipeline,
    pub normals: wgpu::RenderPipeline,
    /// `shaded` at one sample a pixel, for the depth views' scene pass.
    pub one_sample: wgpu::RenderPipeline,
    /// The full-screen pass that shows the depth buffer.
    pub depth_view: wgpu::RenderPipeline,
}

impl Pipelines {
    /// Builds them all: the scene's with `scene_layout` into targets of
    /// `multisample`'s samples (and one at one sample), the depth view's
    /// with `depth_layout`, all drawing in `format`.
    pub fn build(
        gpu: &Gpu,
        scene_layout: &wgpu::PipelineLayout,
        depth_layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        let scene = shader!("camera/scene.wgsl").module(gpu)?;
        let depth = shader!("camera/depth.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        let device = &gpu.device;
        gpu.catch_validation(|| Self {
            shaded: scene_pipeline(device, scene_layout, &scene, format, "fs_main", multisample),
            normals: scene_pipeline(device, scene_layout, &scene, format, "fs_normals", multisample),
            one_sample: scene_pipeline(device, scene_layout, &scene, format, "fs_main", Default::default()),
            depth_view: fullscreen::pipeline(
                device,
                "depth view",
                depth_layout,
                &depth,
                "fs_depth",
                format.into(),
                None,
            ),
        })
        .map_err(ShaderError)
    }
}
