//! Chapter 01: the first triangle. A vertex buffer, a WGSL shader pair and a
//! render pipeline: the three things every later picture is made of.

use common::wgpu::util::DeviceExt as _;
use common::{Chapter, Frame, Gpu, ShaderError, Target, View, anyhow, egui, shader, wgpu};

// ANCHOR: vertex
/// One corner of the triangle as the GPU reads it: two floats of position
/// in clip space, then three of linear RGB colour. `repr(C)` fixes the
/// field order and `Pod` lets us hand a slice of these to the GPU as bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ColoredVertex {
    pub position: [f32; 2],
    pub color: [f32; 3],
}

impl ColoredVertex {
    /// Tells the pipeline how to find `@location(0)` and `@location(1)` in
    /// each 20-byte vertex.
    const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<ColoredVertex>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &wgpu::vertex_attr_array![0 => Float32x2, 1 => Float32x3],
    };
}
// ANCHOR_END: vertex

// ANCHOR: vertices
/// Counter-clockwise, the winding wgpu treats as front-facing by default.
pub const TRIANGLE: [ColoredVertex; 3] = [
    ColoredVertex { position: [0.0, 0.7], color: [1.0, 0.0, 0.0] },
    ColoredVertex { position: [-0.7, -0.6], color: [0.0, 1.0, 0.0] },
    ColoredVertex { position: [0.7, -0.6], color: [0.0, 0.0, 1.0] },
];
// ANCHOR_END: vertices

/// The background, a dark blue-grey (linear RGB).
const CLEAR: wgpu::Color = wgpu::Color { r: 0.02, g: 0.025, b: 0.04, a: 1.0 };

pub const VIEWS: &[View] = &[
    View::mode("default", "colours interpolated across the triangle"),
    View::mode("flat", "interpolation off: one colour per triangle, from its first vertex"),
];

pub struct Triangle {
    vertices: wgpu::Buffer,
    corners: [ColoredVertex; 3],
    smooth: wgpu::RenderPipeline,
    flat: wgpu::RenderPipeline,
    format: wgpu::TextureFormat,
}

// ANCHOR: pipeline
/// Builds a pipeline from one vertex and one fragment entry point of
/// `triangle.wgsl`. Everything the GPU needs to know ahead of drawing is
/// fixed here: the shader stages, the vertex layout, the kind of primitive
/// and the format of the picture it draws into.
fn build_pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    format: wgpu::TextureFormat,
    vertex_entry: &str,
    fragment_entry: &str,
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
        multisample: Default::default(),
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

impl Triangle {
    fn pipelines(gpu: &Gpu, format: wgpu::TextureFormat) -> Result<[wgpu::RenderPipeline; 2], ShaderError> {
        let module = shader!("triangle/triangle.wgsl").module(gpu)?;
        gpu.catch_validation(|| {
            [
                build_pipeline(&gpu.device, &module, format, "vs_main", "fs_main"),
                build_pipeline(&gpu.device, &module, format, "vs_flat", "fs_flat"),
            ]
        })
        .map_err(ShaderError)
    }
}

impl Chapter for Triangle {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "01 · The first triangle";
    const VIEWS: &'static [View] = VIEWS;

    // ANCHOR: new
    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let vertices = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("triangle vertices"),
            contents: bytemuck::cast_slice(&TRIANGLE),
            // COPY_DST so the colour pickers in the overlay can rewrite it.
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        });
        let [smooth, flat] = Self::pipelines(gpu, target.format)?;
        Ok(Self { vertices, corners: TRIANGLE, smooth, flat, format: target.format })
    }
    // ANCHOR_END: new

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        gpu.queue.write_buffer(&self.vertices, 0, bytemuck::cast_slice(&self.corners));
        let mut pass = frame.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("triangle"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: frame.target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(CLEAR), store: wgpu::StoreOp::Store },
            })],
            timestamp_writes: frame.timer.pass("triangle"),
            ..Default::default()
        });
        pass.set_pipeline(if VIEWS[frame.view].name == "flat" { &self.flat } else { &self.smooth });
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.draw(0..3, 0..1);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label("Corner colours (linear RGB):");
        ui.horizontal(|ui| {
            for corner in &mut self.corners {
                ui.color_edit_button_rgb(&mut corner.color);
            }
        });
        if ui.button("reset").clicked() {
            self.corners = TRIANGLE;
        }
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        [self.smooth, self.flat] = Self::pipelines(gpu, self.format)?;
        Ok(())
    }
}
