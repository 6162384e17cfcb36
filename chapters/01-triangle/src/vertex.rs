//! The triangle's vertices: what one corner holds, how the GPU finds its
//! fields in the vertex buffer, and the three corners themselves.

use common::wgpu;

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
    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
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
