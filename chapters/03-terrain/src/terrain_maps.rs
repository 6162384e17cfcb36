//! The terrain on the GPU: the heights in one texture, which the vertex
//! shader reads wherever a patch puts a vertex, the normals in another,
//! which the fragment shader samples, and the one grid of 32 × 32 quads
//! that every patch draws.

use common::wgpu;
use common::wgpu::util::DeviceExt as _;

use crate::heightfield::HeightField;
use crate::quadtree::{PATCH_QUADS, Patch};

/// Vertices along one side of a patch.
pub const PATCH_SIDE: u32 = PATCH_QUADS + 1;

// ANCHOR: terrain_maps
/// The height field as the GPU reads it: a 32-bit float per sample (the
/// vertex shader reads exact heights, never filtered ones), and each
/// sample's normal in two signed bytes, x and z (y is the rest of the unit
/// length: terrain never faces down), filtered between samples.
pub struct TerrainMaps {
    pub heights: wgpu::Texture,
    pub normals: wgpu::Texture,
    /// The patch grid's triangles, shared by every patch.
    pub patch_indices: wgpu::Buffer,
    pub patch_index_count: u32,
}
// ANCHOR_END: terrain_maps

// ANCHOR: pack_normal
/// A normal's x and z in two signed bytes (−1..1 as −127..127).
pub fn pack_normal(n: common::glam::Vec3) -> [i8; 2] {
    let q = |v: f32| (v.clamp(-1.0, 1.0) * 127.0).round() as i8;
    [q(n.x), q(n.z)]
}
// ANCHOR_END: pack_normal

/// The packed normals of the field's rows `rows`, row by row. Rows are
/// independent: each core packs a band.
pub fn normal_rows(field: &HeightField, rows: std::ops::Range<u32>) -> Vec<[i8; 2]> {
    let size = field.size;
    common::parallel::map_bands(rows.len(), |band| {
        band.map(|row| rows.start + row as u32)
            .flat_map(|z| (0..size).map(move |x| pack_normal(field.normal(i64::from(x), i64::from(z)))))
            .collect()
    })
}

// ANCHOR: indices
/// Two triangles per quad, counter-clockwise seen from above, the quad's
/// diagonal from its (x + 1, z) corner to its (x, z + 1) corner. One list
/// serves every patch at every level: only the spacing of the vertices
/// differs, and the vertex shader applies it.
pub fn patch_indices() -> Vec<u16> {
    let mut indices = Vec::with_capacity((PATCH_QUADS * PATCH_QUADS * 6) as usize);
    for z in 0..PATCH_QUADS {
        for x in 0..PATCH_QUADS {
            let a = (z * PATCH_SIDE + x) as u16; // (x, z)
            let b = a + 1; // (x + 1, z)
            let c = a + PATCH_SIDE as u16; // (x, z + 1)
            let d = c + 1; // (x + 1, z + 1)
            indices.extend([a, c, b, b, c, d]);
        }
    }
    indices
}
// ANCHOR_END: indices

impl TerrainMaps {
    /// The field's heights and its packed normals (`normal_rows` of every
    /// row) on the GPU, beside the patch grid.
    pub fn upload(device: &wgpu::Device, queue: &wgpu::Queue, field: &HeightField, normals: &[[i8; 2]]) -> Self {
        let size = wgpu::Extent3d { width: field.size, height: field.size, depth_or_array_layers: 1 };
        let texture = |label, format, contents: &[u8]| {
            device.create_texture_with_data(
                queue,
                &wgpu::TextureDescriptor {
                    label: Some(label),
                    size,
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING,
                    view_formats: &[],
                },
                wgpu::util::TextureDataOrder::LayerMajor,
                contents,
            )
        };
        let heights = texture("terrain heights", wgpu::TextureFormat::R32Float, bytemuck::cast_slice(&field.heights));
        let normals = texture("terrain normals", wgpu::TextureFormat::Rg8Snorm, bytemuck::cast_slice(normals));
        let indices = patch_indices();
        let patch_indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("patch indices"),
            contents: bytemuck::cast_slice(&indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self { heights, normals, patch_indices, patch_index_count: indices.len() as u32 }
    }

    /// Bytes the maps hold on the GPU.
    pub fn gpu_bytes(&self) -> u64 {
        let texels = u64::from(self.heights.width()) * u64::from(self.heights.height());
        texels * (4 + 2) + self.patch_indices.size()
    }
}

// ANCHOR: patch_layout
/// `@location(0)`: a patch's origin and level, stepping once per instance:
/// one instanced draw puts the same grid at every patch.
pub const PATCH_LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
    array_stride: std::mem::size_of::<Patch>() as wgpu::BufferAddress,
    step_mode: wgpu::VertexStepMode::Instance,
    attributes: &wgpu::vertex_attr_array![0 => Uint32x3],
};
// ANCHOR_END: patch_layout

#[cfg(test)]
mod tests {
    use super::*;
    use common::glam::Vec3;

    #[test]
    fn indices_cover_every_quad_facing_up() {
        let indices = patch_indices();
        assert_eq!(indices.len(), (PATCH_QUADS * PATCH_QUADS * 6) as usize);
        assert!(indices.iter().all(|&i| u32::from(i) < PATCH_SIDE * PATCH_SIDE));
        let position = |i: u16| Vec3::new(f32::from(i % PATCH_SIDE as u16), 0.0, f32::from(i / PATCH_SIDE as u16));
        for t in indices.chunks_exact(3) {
            let [a, b, c] = [position(t[0]), position(t[1]), position(t[2])];
            assert!((b - a).cross(c - a).y > 0.0, "triangle {t:?} faces down");
        }
    }

    #[test]
    fn normals_keep_their_direction_in_two_bytes() {
        for n in [Vec3::Y, Vec3::new(-1.0, 1.0, 0.0).normalize(), Vec3::new(0.3, 0.8, -0.5).normalize()] {
            let [x, z] = pack_normal(n).map(|b| f32::from(b) / 127.0);
            let back = Vec3::new(x, (1.0 - x * x - z * z).max(0.0).sqrt(), z);
            assert!(back.angle_between(n) < 0.7f32.to_radians(), "{n} came back as {back}");
        }
    }
}
