//! The pipeline that draws the scene's meshes: the chapter's shaders, the
//! vertex layout, back faces culled, and a depth test.

use common::texture::DEPTH_FORMAT;
use common::wgpu;

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
