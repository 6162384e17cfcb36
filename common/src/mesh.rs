//! The vertex format most chapters share, CPU-side mesh data, and uploading
//! it into vertex and index buffers.

use wgpu::util::DeviceExt;

/// A point on a surface: where it is, which way the surface faces, and
/// where it sits in texture space.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
}

impl Vertex {
    const ATTRIBUTES: [wgpu::VertexAttribute; 3] =
        wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x2];

    /// How the vertex shader sees a buffer of `Vertex`: `@location(0)`
    /// position, `@location(1)` normal, `@location(2)` uv.
    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<Vertex>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &Self::ATTRIBUTES,
    };
}

/// Triangles on the CPU: three indices per triangle, counter-clockwise when
/// seen from the side the normals point to (wgpu's default front face).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

/// A mesh in GPU buffers, ready to draw.
pub struct Mesh {
    pub vertex_buffer: wgpu::Buffer,
    pub index_buffer: wgpu::Buffer,
    pub index_count: u32,
}

impl MeshData {
    pub fn upload(&self, device: &wgpu::Device, label: &str) -> Mesh {
        let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&self.vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&self.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Mesh { vertex_buffer, index_buffer, index_count: self.indices.len() as u32 }
    }

    /// Iterates over triangles as three positions.
    pub fn triangles(&self) -> impl Iterator<Item = [glam::Vec3; 3]> + '_ {
        self.indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]].map(|i| glam::Vec3::from(self.vertices[i as usize].position)))
    }
}

impl Mesh {
    /// Binds the buffers and draws every triangle, `instances` times;
    /// returns what that drew, for the frame's counts.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, instances: std::ops::Range<u32>) -> crate::Drawn {
        pass.set_vertex_buffer(0, self.vertex_buffer.slice(..));
        pass.set_index_buffer(self.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, instances.clone());
        crate::Drawn::triangle_list(0..self.index_count, instances)
    }
}
