//! The whole terrain on the GPU: every chunk's vertices in one buffer,
//! the index buffers all chunks share, and the vertex layout that tells the
//! GPU how to read a `TerrainVertex`.

use common::wgpu;
use common::wgpu::util::DeviceExt as _;

use crate::chunks::{Aabb, CHUNK_VERTICES, TerrainVertex, chunk_bounds, chunk_indices, chunk_vertices, coarse_indices};
use crate::culling::Frustum;
use crate::heightfield::HeightField;

// ANCHOR: terrain_mesh
/// The whole terrain on the GPU: every chunk's vertices in one buffer, one
/// shared index buffer, and each chunk's bounding box for culling.
pub struct TerrainMesh {
    pub vertex_buffer: wgpu::Buffer,
    pub index_buffer: wgpu::Buffer,
    pub index_count: u32,
    /// `coarse_indices(8)`, for seeing every chunk from far away.
    pub coarse_index_buffer: wgpu::Buffer,
    pub coarse_index_count: u32,
    pub bounds: Vec<Aabb>,
    pub chunks_per_side: u32,
}

impl TerrainMesh {
    /// The vertices and bounding boxes of the chunks in rows `rows`, row
    /// by row. Rows of chunks are independent: each core builds a band.
    pub fn chunk_rows(field: &HeightField, rows: std::ops::Range<u32>) -> (Vec<TerrainVertex>, Vec<Aabb>) {
        let n = field.settings.chunks_per_side;
        let chunks = |band: std::ops::Range<usize>| {
            band.flat_map(move |row| (0..n).map(move |cx| (cx, rows.start + row as u32)))
        };
        let vertices = common::parallel::map_bands(rows.len(), |band| {
            chunks(band).flat_map(|(cx, cz)| chunk_vertices(field, cx, cz)).collect()
        });
        let bounds = common::parallel::map_bands(rows.len(), |band| {
            chunks(band).map(|(cx, cz)| chunk_bounds(field, cx, cz)).collect()
        });
        (vertices, bounds)
    }

    /// Puts every chunk's vertices in one buffer, beside the index buffers
    /// all chunks share.
    pub fn upload(device: &wgpu::Device, chunks_per_side: u32, vertices: &[TerrainVertex], bounds: Vec<Aabb>) -> Self {
        let buffer = |label, contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        let vertex_buffer = buffer("terrain vertices", bytemuck::cast_slice(vertices), wgpu::BufferUsages::VERTEX);
        let (indices, coarse) = (chunk_indices(), coarse_indices(8));
        Self {
            vertex_buffer,
            index_buffer: buffer("chunk indices", bytemuck::cast_slice(&indices), wgpu::BufferUsages::INDEX),
            index_count: indices.len() as u32,
            coarse_index_buffer: buffer("coarse indices", bytemuck::cast_slice(&coarse), wgpu::BufferUsages::INDEX),
            coarse_index_count: coarse.len() as u32,
            bounds,
            chunks_per_side,
        }
    }

    /// Draws chunk `chunk`: its vertices start at `chunk × 4225` in the
    /// shared buffer (the base vertex), and drawing it as instance `chunk`
    /// tells the shader which chunk it is.
    pub fn draw_chunk(&self, pass: &mut wgpu::RenderPass<'_>, chunk: u32) {
        let base_vertex = (chunk * CHUNK_VERTICES) as i32;
        pass.draw_indexed(0..self.index_count, base_vertex, chunk..chunk + 1);
    }

    /// Binds the buffers and draws the chunks `frustum` can see; returns how many.
    pub fn draw_visible(&self, pass: &mut wgpu::RenderPass<'_>, frustum: &Frustum) -> usize {
        pass.set_vertex_buffer(0, self.vertex_buffer.slice(..));
        pass.set_index_buffer(self.index_buffer.slice(..), wgpu::IndexFormat::Uint16);
        let mut drawn = 0;
        for (chunk, bounds) in self.bounds.iter().enumerate() {
            if frustum.intersects(bounds) {
                self.draw_chunk(pass, chunk as u32);
                drawn += 1;
            }
        }
        drawn
    }

    /// Draws every chunk with the coarse index list.
    pub fn draw_all_coarse(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_vertex_buffer(0, self.vertex_buffer.slice(..));
        pass.set_index_buffer(self.coarse_index_buffer.slice(..), wgpu::IndexFormat::Uint16);
        for chunk in 0..self.bounds.len() as u32 {
            pass.draw_indexed(0..self.coarse_index_count, (chunk * CHUNK_VERTICES) as i32, chunk..chunk + 1);
        }
    }
}
// ANCHOR_END: terrain_mesh

// ANCHOR: vertex_layout
/// `@location(0)` the height, `@location(1)` the normal, unpacked by the
/// GPU from four signed bytes to four floats in −1..1.
pub const TERRAIN_VERTEX_LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
    array_stride: std::mem::size_of::<TerrainVertex>() as wgpu::BufferAddress,
    step_mode: wgpu::VertexStepMode::Vertex,
    attributes: &wgpu::vertex_attr_array![0 => Float32, 1 => Snorm8x4],
};
// ANCHOR_END: vertex_layout
