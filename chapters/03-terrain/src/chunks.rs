//! The height field cut into chunks of 64 × 64 quads: a bounding box for
//! each, which culling tests, the quadtree groups, and later chapters
//! group their own things by (chapter 05's rocks).

use common::glam::Vec3;

use crate::heightfield::{CHUNK_QUADS, HeightField};

/// An axis-aligned box, for culling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    /// The smallest box holding both.
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb { min: self.min.min(other.min), max: self.max.max(other.max) }
    }

    /// How far `point` is from the nearest point of the box (0 inside).
    pub fn distance_to(&self, point: Vec3) -> f32 {
        (point.clamp(self.min, self.max) - point).length()
    }

    /// The length of the box's diagonal: no two points in it are further apart.
    pub fn diagonal(&self) -> f32 {
        (self.max - self.min).length()
    }
}

// ANCHOR: chunk_bounds
/// The box around chunk (cx, cz) in world space: its 65 × 65 samples,
/// border rows included.
pub fn chunk_bounds(field: &HeightField, cx: u32, cz: u32) -> Aabb {
    let (mut low, mut high) = (f32::INFINITY, f32::NEG_INFINITY);
    for z in 0..=CHUNK_QUADS {
        for x in 0..=CHUNK_QUADS {
            let h = field.height(i64::from(cx * CHUNK_QUADS + x), i64::from(cz * CHUNK_QUADS + z));
            low = low.min(h);
            high = high.max(h);
        }
    }
    let size = CHUNK_QUADS as f32 * field.settings.spacing;
    let origin = Vec3::new(cx as f32 * size, low, cz as f32 * size);
    Aabb { min: origin, max: Vec3::new(origin.x + size, high, origin.z + size) }
}
// ANCHOR_END: chunk_bounds

#[cfg(test)]
mod tests {
    use super::*;
    use crate::heightfield::TerrainSettings;

    #[test]
    fn bounds_enclose_the_chunk() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 2, ..Default::default() });
        let bounds = chunk_bounds(&field, 1, 0);
        assert_eq!((bounds.min.x, bounds.max.x, bounds.min.z, bounds.max.z), (64.0, 128.0, 0.0, 64.0));
        for z in 0..=64 {
            for x in 64..=128 {
                let h = field.height(x, z);
                assert!(h >= bounds.min.y && h <= bounds.max.y, "({x}, {z}) at {h} m");
            }
        }
        // The box is tight: its top and bottom are samples of the chunk.
        let heights: Vec<f32> =
            (0..=64).flat_map(|z| (64..=128).map(move |x| (x, z))).map(|(x, z)| field.height(x, z)).collect();
        assert!(heights.contains(&bounds.min.y) && heights.contains(&bounds.max.y));
    }

    #[test]
    fn distance_to_a_box_is_zero_inside_and_straight_line_outside() {
        let b = Aabb { min: Vec3::ZERO, max: Vec3::new(10.0, 2.0, 10.0) };
        assert_eq!(b.distance_to(Vec3::new(5.0, 1.0, 5.0)), 0.0);
        // 3 m east of the east face, level with the box: 3 m.
        assert_eq!(b.distance_to(Vec3::new(13.0, 1.0, 5.0)), 3.0);
        // Beyond a corner: a 3-4-5 triangle in x and z, 12 m up from the top: 13 m.
        assert_eq!(b.distance_to(Vec3::new(13.0, 14.0, 14.0)), 13.0);
        assert_eq!(b.diagonal(), (204.0f32).sqrt());
    }
}
