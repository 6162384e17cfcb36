//! Level of detail: how far each level of the quadtree reaches, chosen so
//! that a cell of the mesh covers about the same number of pixels near and
//! far, and the morph that lets a level fade into the next as the camera
//! moves, so that nothing pops and no crack opens where two levels meet.

/// How finely one picture of the terrain is drawn: how many pixels high
/// the picture is (which decides how many metres a pixel spans at each
/// distance), and the most pixels a mesh cell may span at the far end of
/// its level's range. `cell_pixels: None` draws every chunk in view at full
/// detail, the `full-detail` view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Detail {
    pub picture_height: u32,
    pub cell_pixels: Option<f32>,
}

impl Detail {
    /// Cells at most this many pixels wide where a level ends (and twice
    /// that where it begins, half as far away).
    pub const CELL_PIXELS: f32 = 4.0;

    /// Level of detail for a picture `picture_height` pixels high.
    pub fn lod(picture_height: u32) -> Self {
        Self { picture_height, cell_pixels: Some(Self::CELL_PIXELS) }
    }

    /// Every chunk in view at full detail.
    pub fn full(picture_height: u32) -> Self {
        Self { picture_height, cell_pixels: None }
    }
}

// ANCHOR: ranges
/// How far each level reaches, and where in its range it starts to morph.
/// Level 0 (cells of one sample) is drawn up to `first` metres from the
/// eye, level 1 (cells of two) up to twice that, level L up to 2^L times;
/// the top level, the whole map in one node, reaches everywhere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodRanges {
    /// Metres: the end of level 0's range, r_0.
    pub first: f32,
    /// The part of each range after which its level morphs into the next.
    pub morph_start: f32,
    /// The level of the quadtree's root.
    pub top_level: u32,
}

/// The latest a level may start to morph, as a part of its range: a tenth
/// of the range is left for the morph, however near the ranges are.
pub const LATEST_MORPH_START: f32 = 0.9;

impl LodRanges {
    // ANCHOR: first_range
    /// The ranges for a picture: a cell 2^L samples wide, seen at the end
    /// of its range r_L = 2^L · r_0, spans `cell_pixels` pixels when
    ///
    /// ```text
    /// r_0 = spacing · picture_height / (cell_pixels · 2 tan(fov_y / 2))
    /// ```
    ///
    /// since a pixel at distance d spans d · 2 tan(fov_y / 2) / picture_height
    /// metres. `node_reach` is D, the most a node of level L spans, divided
    /// by 2^L (`Quadtree::node_reach`): the morph starts where it leaves no
    /// crack, and that puts a floor under r_0 (`morph_start`). Full detail
    /// puts the first range at infinity: every node splits down to level 0.
    pub fn new(detail: Detail, fov_y: f32, spacing: f32, node_reach: f32, top_level: u32) -> Self {
        let first = match detail.cell_pixels {
            Some(pixels) => {
                let from_pixels = spacing * detail.picture_height as f32 / (pixels * 2.0 * (fov_y / 2.0).tan());
                from_pixels.max(Self::nearest_first(node_reach))
            }
            None => f32::INFINITY,
        };
        Self { first, morph_start: Self::morph_start(first, node_reach), top_level }
    }
    // ANCHOR_END: first_range

    // ANCHOR: morph_start
    /// Where a level starts to morph, as a part of its range, so that no
    /// crack opens. A patch of level L lies in a node that reaches into the
    /// sphere of radius r_L, so none of its points is further than
    /// r_L + 2^L · D. There it has morphed fully into level L + 1 (its morph
    /// ends at r_L), and its coarser neighbour, of level L + 1, must not yet
    /// have started morphing into level L + 2: that level's morph may start
    /// no nearer than r_L + 2^L · D = 2^L (r_0 + D), which is a part
    /// (r_0 + D) / 2 r_0 of its range r_{L+1} = 2^{L+1} r_0. The same part
    /// for every level.
    pub fn morph_start(first: f32, node_reach: f32) -> f32 {
        if first.is_finite() { (first + node_reach) / (2.0 * first) } else { LATEST_MORPH_START }
    }

    /// The nearest r_0 may be: where the morph would start at
    /// `LATEST_MORPH_START`, (r_0 + D) / 2 r_0 = 0.9, so r_0 = D / 0.8.
    pub fn nearest_first(node_reach: f32) -> f32 {
        node_reach / (2.0 * LATEST_MORPH_START - 1.0)
    }
    // ANCHOR_END: morph_start

    /// Where level `level` ends (metres from the eye).
    pub fn range(&self, level: u32) -> f32 {
        if level >= self.top_level { f32::INFINITY } else { self.first * (1u32 << level) as f32 }
    }

    // ANCHOR: morph
    /// How far a vertex of level `level`, `distance` metres from the eye,
    /// has morphed into the next level: 0 until `morph_start` of the way
    /// through the range, rising linearly to 1 at its end. (`terrain.wgsl`
    /// computes the same on the GPU; this copy is for tests and figures.)
    pub fn morph(&self, level: u32, distance: f32) -> f32 {
        let end = self.range(level);
        if !end.is_finite() {
            return 0.0;
        }
        let start = self.morph_start * end;
        ((distance - start) / (end - start)).clamp(0.0, 1.0)
    }
    // ANCHOR_END: morph
}
// ANCHOR_END: ranges

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_range_follows_the_pixels_worked_by_hand() {
        // 60° of view, 1080 pixels high, 1 m cells at most 4 pixels wide:
        // 2 tan 30° = 1.1547, and 1080 / (4 × 1.1547) = 233.8 m.
        let ranges = LodRanges::new(Detail::lod(1080), 60f32.to_radians(), 1.0, 100.0, 6);
        assert!((ranges.first - 233.8).abs() < 0.1, "{}", ranges.first);
        // Nodes at most 100 m across per 2^L: the morph starts at
        // (233.8 + 100) / 467.6 = 71.4 % of each range.
        assert!((ranges.morph_start - 0.7139).abs() < 1e-3, "{}", ranges.morph_start);
        assert_eq!(ranges.range(3), 8.0 * ranges.first);
        assert_eq!(ranges.range(6), f32::INFINITY, "the root reaches everywhere");
        // At the end of level 2's range its 4 m cells are 4 pixels wide:
        // a pixel spans 935.3 m × 1.1547 / 1080 = 1.0 m there.
        let pixel = ranges.range(2) * 2.0 * 30f32.to_radians().tan() / 1080.0;
        assert!((4.0 / pixel - 4.0).abs() < 1e-3);
        // A small picture would want a nearer range than the morph allows:
        // r_0 = 100 / 0.8 = 125 m, and the morph starts at 90 %.
        let small = LodRanges::new(Detail::lod(450), 60f32.to_radians(), 1.0, 100.0, 6);
        assert!((small.first - 125.0).abs() < 1e-3 && (small.morph_start - 0.9).abs() < 1e-6, "{small:?}");
        assert_eq!(LodRanges::new(Detail::full(450), 1.0, 1.0, 200.0, 6).first, f32::INFINITY);
    }

    #[test]
    fn the_morph_is_zero_until_it_starts_and_one_at_the_end() {
        let ranges = LodRanges { first: 200.0, morph_start: 0.75, top_level: 6 };
        // Level 1 ends at 400 m and starts morphing at 300 m.
        assert_eq!(ranges.morph(1, 0.0), 0.0);
        assert_eq!(ranges.morph(1, 300.0), 0.0);
        assert_eq!(ranges.morph(1, 350.0), 0.5);
        assert_eq!(ranges.morph(1, 400.0), 1.0);
        assert_eq!(ranges.morph(1, 5000.0), 1.0);
        // The root never morphs: there is no coarser level to become.
        assert_eq!(ranges.morph(6, 1e9), 0.0);
        // Full detail never morphs.
        assert_eq!(LodRanges { first: f32::INFINITY, morph_start: 0.9, top_level: 6 }.morph(0, 1e9), 0.0);
    }
}

#[cfg(test)]
mod crack_tests {
    use super::*;

    /// The argument of `morph_start`, checked with numbers: for a patch of
    /// level L whose node just touches the sphere of r_L, the farthest point
    /// of the patch is r_L + 2^L · D; there the patch has morphed fully and
    /// its coarser neighbour not at all.
    #[test]
    fn at_the_farthest_point_of_a_patch_the_levels_agree() {
        for (first, reach) in [(125.0, 100.0), (233.8, 100.0), (400.0, 107.0), (1000.0, 50.0)] {
            let ranges = LodRanges { first, morph_start: LodRanges::morph_start(first, reach), top_level: 6 };
            for level in 0..5 {
                let farthest = ranges.range(level) + (1u32 << level) as f32 * reach;
                assert_eq!(ranges.morph(level, farthest), 1.0);
                assert_eq!(ranges.morph(level + 1, farthest), 0.0, "r_0 {first}, D {reach}, level {level}");
                // And a little further the coarser level is already morphing.
                assert!(ranges.morph(level + 1, farthest * 1.01) > 0.0);
            }
        }
    }
}
