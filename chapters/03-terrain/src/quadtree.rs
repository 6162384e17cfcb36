//! The quadtree over the chunk grid: four chunks make a node of level 1,
//! four of those a node of level 2, up to one node for the whole map. Each
//! frame it is walked from the root, and each node is either drawn at its
//! own level, as four patches, or split into its children where they are
//! near enough to need finer cells. Nodes outside the frustum are skipped
//! with everything under them.

use common::glam::Vec3;

use crate::chunks::Aabb;
use crate::culling::Frustum;
use crate::heightfield::CHUNK_QUADS;
use crate::lod::LodRanges;

/// Quads along one side of a patch: a quarter of a node, so a node of
/// level L is four patches of 32 × 32 cells, each 2^L samples wide.
pub const PATCH_QUADS: u32 = CHUNK_QUADS / 2;

// ANCHOR: patch
/// One patch to draw, as the vertex shader reads it (per instance): where
/// it starts, in samples, and its level, so its cells are 2^level samples
/// wide. Every patch is the same grid of 33 × 33 vertices.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Patch {
    pub origin: [u32; 2],
    pub level: u32,
}
// ANCHOR_END: patch

impl Patch {
    /// Triangles in one patch.
    pub const TRIANGLES: u32 = PATCH_QUADS * PATCH_QUADS * 2;
}

/// The nodes' boxes, level by level: `levels[0]` holds the chunks' boxes,
/// `levels[L]` those of the nodes of 2^L × 2^L chunks, and the last level
/// one box around the whole map.
pub struct Quadtree {
    levels: Vec<Vec<Aabb>>,
}

impl Quadtree {
    /// The tree over `chunk_bounds`, `chunks_per_side` a side (a power of two).
    pub fn new(chunk_bounds: &[Aabb], chunks_per_side: u32) -> Self {
        assert!(chunks_per_side.is_power_of_two(), "the quadtree needs a power of two of chunks a side");
        assert_eq!(chunk_bounds.len(), (chunks_per_side * chunks_per_side) as usize);
        let mut levels = vec![chunk_bounds.to_vec()];
        let mut side = chunks_per_side;
        while side > 1 {
            let below = levels.last().expect("level 0 is there");
            side /= 2;
            let node = |x: u32, z: u32| {
                let child = |i: u32, j: u32| below[((2 * z + j) * 2 * side + 2 * x + i) as usize];
                child(0, 0).union(&child(1, 0)).union(&child(0, 1)).union(&child(1, 1))
            };
            levels.push((0..side * side).map(|i| node(i % side, i / side)).collect());
        }
        Self { levels }
    }

    /// The level of the root.
    pub fn top_level(&self) -> u32 {
        self.levels.len() as u32 - 1
    }

    /// The box of node (x, z) of `level`.
    pub fn bounds(&self, level: u32, x: u32, z: u32) -> &Aabb {
        let side = 1 << (self.top_level() - level);
        &self.levels[level as usize][(z * side + x) as usize]
    }

    // ANCHOR: node_reach
    /// D: the longest diagonal of any node below the root, a node of level
    /// L counted as 1/2^L of its length. No two points of a node of level L
    /// are further apart than 2^L · D, which is what the morph must allow
    /// for (`LodRanges::morph_start`).
    pub fn node_reach(&self) -> f32 {
        let top = self.top_level();
        (0..top)
            .flat_map(|level| self.levels[level as usize].iter().map(move |b| b.diagonal() / (1u32 << level) as f32))
            .fold(0.0, f32::max)
    }
    // ANCHOR_END: node_reach

    // ANCHOR: select
    /// The patches to draw from `eye`: every part of the map inside
    /// `frustum`, each at the coarsest level whose range reaches it.
    pub fn select(&self, frustum: &Frustum, eye: Vec3, ranges: &LodRanges, patches: &mut Vec<Patch>) {
        patches.clear();
        self.visit(self.top_level(), 0, 0, frustum, eye, ranges, patches);
    }

    #[allow(clippy::too_many_arguments)]
    fn visit(
        &self,
        level: u32,
        x: u32,
        z: u32,
        frustum: &Frustum,
        eye: Vec3,
        ranges: &LodRanges,
        patches: &mut Vec<Patch>,
    ) {
        if !frustum.intersects(self.bounds(level, x, z)) {
            return;
        }
        // The node's four quarters, as patches of its own level.
        let span = CHUNK_QUADS << level; // samples across the node
        let quarter = |i: u32, j: u32| Patch { origin: [x * span + i * span / 2, z * span + j * span / 2], level };
        if level == 0 {
            patches.extend([quarter(0, 0), quarter(1, 0), quarter(0, 1), quarter(1, 1)]);
            return;
        }
        // A child needs finer cells when it reaches into the sphere where
        // the level below is drawn; the others are drawn at this level.
        let finer = ranges.range(level - 1);
        for (i, j) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (cx, cz) = (2 * x + i, 2 * z + j);
            let child = self.bounds(level - 1, cx, cz);
            if child.distance_to(eye) < finer {
                self.visit(level - 1, cx, cz, frustum, eye, ranges, patches);
            } else if frustum.intersects(child) {
                patches.push(quarter(i, j));
            }
        }
    }
    // ANCHOR_END: select

    /// The level a point `distance` metres away is drawn at, ignoring the
    /// sizes of nodes: the first whose range reaches past it. (For tests and
    /// the book: the walk above decides by whole nodes.)
    pub fn level_at(ranges: &LodRanges, distance: f32) -> u32 {
        (0..=ranges.top_level).find(|&level| distance < ranges.range(level)).unwrap_or(ranges.top_level)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::Camera;

    /// A flat map of `n` × `n` chunks of 64 m, heights 0 to 1 m.
    fn flat(n: u32) -> Quadtree {
        let bounds: Vec<Aabb> = (0..n * n)
            .map(|i| {
                let min = Vec3::new((i % n) as f32 * 64.0, 0.0, (i / n) as f32 * 64.0);
                Aabb { min, max: min + Vec3::new(64.0, 1.0, 64.0) }
            })
            .collect();
        Quadtree::new(&bounds, n)
    }

    fn everything() -> Frustum {
        // A camera high above, looking down at the whole map: every box is in view.
        let mut camera = Camera::looking_at(Vec3::new(512.0, 5000.0, 512.0), Vec3::new(512.0, 0.0, 511.0), 1.0);
        camera.far = 10_000.0;
        Frustum::from_view_projection(camera.view_projection())
    }

    #[test]
    fn parents_hold_their_children() {
        let tree = flat(16);
        assert_eq!(tree.top_level(), 4);
        let root = tree.bounds(4, 0, 0);
        assert_eq!((root.min, root.max), (Vec3::ZERO, Vec3::new(1024.0, 1.0, 1024.0)));
        let node = tree.bounds(2, 1, 3);
        assert_eq!((node.min.x, node.min.z, node.max.x, node.max.z), (256.0, 768.0, 512.0, 1024.0));
    }

    #[test]
    fn patches_cover_the_map_once_with_finer_ones_nearer() {
        let tree = flat(16);
        let ranges = LodRanges { first: 100.0, morph_start: 0.9, top_level: tree.top_level() };
        let eye = Vec3::new(100.0, 2.0, 100.0);
        let mut patches = Vec::new();
        tree.select(&everything(), eye, &ranges, &mut patches);
        // Every sample square of the map is covered by exactly one patch.
        let mut cover = vec![0u8; 1024 * 1024];
        for p in &patches {
            let side = PATCH_QUADS << p.level;
            for z in p.origin[1]..p.origin[1] + side {
                for x in p.origin[0]..p.origin[0] + side {
                    cover[(z * 1024 + x) as usize] += 1;
                }
            }
        }
        assert!(cover.iter().all(|&c| c == 1), "holes or overlaps");
        // The patch under the eye is of level 0, the far corner's of level 3
        // (its node, 512 m across, is entirely beyond level 2's 400 m).
        let at = |x: u32, z: u32| {
            patches
                .iter()
                .find(|p| {
                    let side = PATCH_QUADS << p.level;
                    (p.origin[0]..p.origin[0] + side).contains(&x) && (p.origin[1]..p.origin[1] + side).contains(&z)
                })
                .expect("covered")
                .level
        };
        assert_eq!(at(100, 100), 0);
        assert_eq!(at(1000, 1000), 3);
        // Neighbouring patches differ by one level at most.
        for z in 0..1023 {
            for x in 0..1023 {
                assert!(at(x, z).abs_diff(at(x + 1, z)) <= 1 && at(x, z).abs_diff(at(x, z + 1)) <= 1, "({x}, {z})");
            }
        }
    }

    #[test]
    fn full_detail_is_every_chunk_in_four_patches_of_level_0() {
        let tree = flat(4);
        let ranges = LodRanges { first: f32::INFINITY, morph_start: 0.9, top_level: tree.top_level() };
        let mut patches = Vec::new();
        tree.select(&everything(), Vec3::new(10.0, 5.0, 10.0), &ranges, &mut patches);
        assert_eq!(patches.len(), 4 * 16);
        assert!(patches.iter().all(|p| p.level == 0));
    }

    #[test]
    fn what_the_frustum_misses_is_not_drawn() {
        let tree = flat(16);
        let ranges = LodRanges { first: 100.0, morph_start: 0.9, top_level: tree.top_level() };
        // At the west edge, looking east along z = 32 with a narrow view.
        let mut camera = Camera::looking_at(Vec3::new(-10.0, 0.5, 32.0), Vec3::new(900.0, 0.5, 32.0), 1.0);
        camera.fov_y = 0.05;
        camera.far = 2000.0;
        let frustum = Frustum::from_view_projection(camera.view_projection());
        let mut patches = Vec::new();
        tree.select(&frustum, camera.position, &ranges, &mut patches);
        assert!(!patches.is_empty());
        // Every patch drawn lies in the first row of chunks' nodes: z < 64 · 2^level.
        for p in &patches {
            assert!(p.origin[1] < (CHUNK_QUADS << p.level), "{p:?}");
        }
    }

    #[test]
    fn the_node_reach_is_the_largest_diagonal_per_level() {
        let tree = flat(4);
        // Level 0's boxes are 64 × 1 × 64: diagonal 90.52 m; each level up
        // doubles x and z but not y, so level 0 is the largest per 2^L.
        let diagonal = (64.0f32 * 64.0 * 2.0 + 1.0).sqrt();
        assert!((tree.node_reach() - diagonal).abs() < 1e-3, "{}", tree.node_reach());
    }

    #[test]
    fn level_at_a_distance_worked_by_hand() {
        let ranges = LodRanges { first: 200.0, morph_start: 0.75, top_level: 6 };
        assert_eq!(Quadtree::level_at(&ranges, 150.0), 0);
        assert_eq!(Quadtree::level_at(&ranges, 250.0), 1);
        // 1000 m: past 200, 400 and 800, before 1600.
        assert_eq!(Quadtree::level_at(&ranges, 1000.0), 3);
        assert_eq!(Quadtree::level_at(&ranges, 1e7), 6);
    }
}
