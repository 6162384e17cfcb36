//! Cutting the height field into chunks: one vertex buffer holding every
//! chunk, one index buffer they all share, and a bounding box per chunk.

use common::glam::Vec3;

use crate::heightfield::{CHUNK_QUADS, HeightField};

/// Vertices along one side of a chunk.
pub const CHUNK_SIDE: u32 = CHUNK_QUADS + 1;
/// Vertices in one chunk.
pub const CHUNK_VERTICES: u32 = CHUNK_SIDE * CHUNK_SIDE;

// ANCHOR: vertex
/// Eight bytes per vertex. x and z are not stored: the vertex shader works
/// them out from the vertex's index in its chunk and the chunk's index.
/// The normal is packed into four signed bytes (−1..1 as −127..127).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TerrainVertex {
    pub height: f32,
    pub normal: [i8; 4],
}
// ANCHOR_END: vertex

/// An axis-aligned box around one chunk, for culling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

fn pack(n: Vec3) -> [i8; 4] {
    let q = |v: f32| (v.clamp(-1.0, 1.0) * 127.0).round() as i8;
    [q(n.x), q(n.y), q(n.z), 0]
}

// ANCHOR: chunk_vertices
/// The vertices of chunk (cx, cz), row by row. Neighbouring chunks both
/// hold their shared border row, with the same height and normal.
pub fn chunk_vertices(field: &HeightField, cx: u32, cz: u32) -> Vec<TerrainVertex> {
    let mut vertices = Vec::with_capacity(CHUNK_VERTICES as usize);
    for z in 0..CHUNK_SIDE {
        for x in 0..CHUNK_SIDE {
            let (gx, gz) = (i64::from(cx * CHUNK_QUADS + x), i64::from(cz * CHUNK_QUADS + z));
            vertices.push(TerrainVertex { height: field.height(gx, gz), normal: pack(field.normal(gx, gz)) });
        }
    }
    vertices
}
// ANCHOR_END: chunk_vertices

// ANCHOR: indices
/// Two triangles per quad, counter-clockwise seen from above. Every chunk
/// has the same layout, so this one list serves them all, and 65 × 65
/// vertices fit 16-bit indices.
pub fn chunk_indices() -> Vec<u16> {
    let mut indices = Vec::with_capacity((CHUNK_QUADS * CHUNK_QUADS * 6) as usize);
    for z in 0..CHUNK_QUADS {
        for x in 0..CHUNK_QUADS {
            let a = (z * CHUNK_SIDE + x) as u16; // (x, z)
            let b = a + 1; // (x + 1, z)
            let c = a + CHUNK_SIDE as u16; // (x, z + 1)
            let d = c + 1; // (x + 1, z + 1)
            indices.extend([a, c, b, b, c, d]);
        }
    }
    indices
}
// ANCHOR_END: indices

/// A coarse index list for seeing chunks from far away: quads of `step` ×
/// `step` samples, over the same vertices. The overhead `chunks` view, where
/// a whole chunk is a few pixels wide, draws this instead of 8,192 triangles.
pub fn coarse_indices(step: u32) -> Vec<u16> {
    let quads = CHUNK_QUADS / step;
    let mut indices = Vec::with_capacity((quads * quads * 6) as usize);
    for z in 0..quads {
        for x in 0..quads {
            let a = (z * step * CHUNK_SIDE + x * step) as u16;
            let b = a + step as u16;
            let c = a + (step * CHUNK_SIDE) as u16;
            let d = c + step as u16;
            indices.extend([a, c, b, b, c, d]);
        }
    }
    indices
}

/// The box around chunk (cx, cz) in world space.
pub fn chunk_bounds(field: &HeightField, cx: u32, cz: u32) -> Aabb {
    let (mut low, mut high) = (f32::INFINITY, f32::NEG_INFINITY);
    for z in 0..CHUNK_SIDE {
        for x in 0..CHUNK_SIDE {
            let h = field.height(i64::from(cx * CHUNK_QUADS + x), i64::from(cz * CHUNK_QUADS + z));
            low = low.min(h);
            high = high.max(h);
        }
    }
    let size = CHUNK_QUADS as f32 * field.settings.spacing;
    let origin = Vec3::new(cx as f32 * size, low, cz as f32 * size);
    Aabb { min: origin, max: Vec3::new(origin.x + size, high, origin.z + size) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::heightfield::TerrainSettings;

    #[test]
    fn vertex_is_eight_bytes() {
        assert_eq!(std::mem::size_of::<TerrainVertex>(), 8);
    }

    #[test]
    fn indices_cover_every_quad_facing_up() {
        let indices = chunk_indices();
        assert_eq!(indices.len(), (CHUNK_QUADS * CHUNK_QUADS * 6) as usize);
        assert!(indices.iter().all(|&i| u32::from(i) < CHUNK_VERTICES));
        let position = |i: u16| Vec3::new(f32::from(i % CHUNK_SIDE as u16), 0.0, f32::from(i / CHUNK_SIDE as u16));
        for t in indices.chunks_exact(3) {
            let [a, b, c] = [position(t[0]), position(t[1]), position(t[2])];
            assert!((b - a).cross(c - a).y > 0.0, "triangle {t:?} faces down");
        }
    }

    #[test]
    fn coarse_indices_cover_the_chunk_with_fewer_triangles() {
        let coarse = coarse_indices(8);
        assert_eq!(coarse.len(), 8 * 8 * 6);
        assert!(coarse.iter().all(|&i| u32::from(i) < CHUNK_VERTICES));
        // The four corners of the chunk are used, so nothing is cut off.
        for corner in [0, CHUNK_QUADS, CHUNK_QUADS * CHUNK_SIDE, CHUNK_VERTICES - 1] {
            assert!(coarse.contains(&(corner as u16)), "corner {corner}");
        }
    }

    #[test]
    fn normals_match_across_chunk_borders() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 2, ..Default::default() });
        let (left, right) = (chunk_vertices(&field, 0, 0), chunk_vertices(&field, 1, 0));
        let (top, bottom) = (chunk_vertices(&field, 0, 0), chunk_vertices(&field, 0, 1));
        let side = CHUNK_SIDE as usize;
        for i in 0..side {
            // The last column of the left chunk is the first column of the right one.
            assert_eq!(left[i * side + side - 1], right[i * side], "row {i}");
            // The last row of the top chunk is the first row of the bottom one.
            assert_eq!(top[(side - 1) * side + i], bottom[i], "column {i}");
        }
        // And they are real slopes, not all pointing straight up.
        assert!(left.iter().any(|v| v.normal[1] < 126));
    }

    #[test]
    fn bounds_enclose_the_chunk() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 2, ..Default::default() });
        let bounds = chunk_bounds(&field, 1, 0);
        assert_eq!((bounds.min.x, bounds.max.x, bounds.min.z, bounds.max.z), (64.0, 128.0, 0.0, 64.0));
        for v in chunk_vertices(&field, 1, 0) {
            assert!(v.height >= bounds.min.y && v.height <= bounds.max.y);
        }
    }
}
