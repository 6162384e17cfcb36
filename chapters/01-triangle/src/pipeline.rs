//! The render pipeline: everything the GPU must know before it draws the
//! triangle, fixed in one object.

use common::wgpu;

use crate::vertex::ColoredVertex;

// ANCHOR: pipeline
/// Builds a pipeline from one vertex and one fragment entry point of
/// `triangle.wgsl`. Everything the GPU needs to know ahead of drawing is
/// fixed here: the shader stages, the vertex layout, the kind of primitive
/// and the format of the picture it draws into, and how many samples a
/// pixel it has (one, or four with multisampling: chapter 02).
pub fn build_pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    format: wgpu::TextureFormat,
    vertex_entry: &str,
    fragment_entry: &str,
    multisample: wgpu::MultisampleState,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(vertex_entry),
        layout: None, // no uniforms or textures yet: derive an empty layout
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vertex_entry),
            buffers: &[Some(ColoredVertex::LAYOUT)],
            compilation_options: Default::default(),
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            front_face: wgpu::FrontFace::Ccw,
            cull_mode: Some(wgpu::Face::Back),
            ..Default::default()
        },
        depth_stencil: None,
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
