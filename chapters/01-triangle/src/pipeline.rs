//! The render pipeline: everything the GPU must know before it draws the
//! triangle, fixed in one object; and the chapter's two, the smooth one and
//! the flat one, built from `triangle.wgsl`.

use common::{Gpu, ShaderError, shader, wgpu};

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

// ANCHOR: pipelines
/// The chapter's two pipelines, both from `triangle.wgsl`: the smooth one
/// (`vs_main`, `fs_main`) and the flat one (`vs_flat`, `fs_flat`). An error
/// in the shader, or a pipeline that fails validation, comes back as a
/// `ShaderError`, for the overlay and the terminal to show.
pub fn build_pipelines(
    gpu: &Gpu,
    format: wgpu::TextureFormat,
    multisample: wgpu::MultisampleState,
) -> Result<[wgpu::RenderPipeline; 2], ShaderError> {
    let module = shader!("triangle/triangle.wgsl").module(gpu)?;
    gpu.catch_validation(|| {
        [
            build_pipeline(&gpu.device, &module, format, "vs_main", "fs_main", multisample),
            build_pipeline(&gpu.device, &module, format, "vs_flat", "fs_flat", multisample),
        ]
    })
    .map_err(ShaderError)
}
// ANCHOR_END: pipelines
