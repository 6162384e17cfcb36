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

// ANCHOR: morph_start
/// Where in its range a level starts to morph into the next: over the last
/// quarter of it. The larger this is, the shorter the morph, and the
/// further out the first range must reach to stay free of cracks
/// (`Quadtree::crack_free_range`).
pub const MORPH_START: f32 = 0.75;
// ANCHOR_END: morph_start

// ANCHOR: ranges
/// How far each level reaches. Level 0 (cells of one sample) is drawn up
/// to `first` metres from the eye, level 1 (cells of two) up to twice
/// that, level L up to 2^L times; the top level, the whole map in one
/// node, reaches everywhere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodRanges {
    /// Metres: the end of level 0's range.
    pub first: f32,
    /// The level of the quadtree's root.
    pub top_level: u32,
}

impl LodRanges {
    /// The ranges for a picture: a cell 2^L samples wide, seen at the end
    /// of its range r_L = 2^L · r_0, spans `cell_pixels` pixels when
    ///
    /// ```text
    /// r_0 = spacing · picture_height / (cell_pixels · 2 tan(fov_y / 2))
    /// ```
    ///
    /// since a pixel at distance d spans d · 2 tan(fov_y / 2) / picture_height
    /// metres. But never nearer than `crack_free`, the least first range
    /// for which neighbouring levels always meet without a gap. Full detail
    /// puts the first range at infinity: every node splits down to level 0.
    pub fn new(detail: Detail, fov_y: f32, spacing: f32, crack_free: f32, top_level: u32) -> Self {
        let first = match detail.cell_pixels {
            Some(pixels) => {
                let from_pixels = spacing * detail.picture_height as f32 / (pixels * 2.0 * (fov_y / 2.0).tan());
                from_pixels.max(crack_free)
            }
            None => f32::INFINITY,
        };
        Self { first, top_level }
    }

    /// Where level `level` ends (metres from the eye).
    pub fn range(&self, level: u32) -> f32 {
        if level >= self.top_level { f32::INFINITY } else { self.first * (1u32 << level) as f32 }
    }

    // ANCHOR: morph
    /// How far a vertex of level `level`, `distance` metres from the eye,
    /// has morphed into the next level: 0 until `MORPH_START` of the way
    /// through the range, rising linearly to 1 at its end. (`terrain.wgsl`
    /// computes the same on the GPU; this copy is for tests and figures.)
    pub fn morph(&self, level: u32, distance: f32) -> f32 {
        let end = self.range(level);
        if !end.is_finite() {
            return 0.0;
        }
        let start = MORPH_START * end;
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
        assert_eq!(ranges.range(3), 8.0 * ranges.first);
        assert_eq!(ranges.range(6), f32::INFINITY, "the root reaches everywhere");
        // At the end of level 2's range its 4 m cells are 4 pixels wide:
        // a pixel spans 935.3 m × 1.1547 / 1080 = 1.0 m there.
        let pixel = ranges.range(2) * 2.0 * 30f32.to_radians().tan() / 1080.0;
        assert!((4.0 / pixel - 4.0).abs() < 1e-3);
        // A small picture would want a nearer range than cracks allow.
        let small = LodRanges::new(Detail::lod(450), 60f32.to_radians(), 1.0, 200.0, 6);
        assert_eq!(small.first, 200.0);
        assert_eq!(LodRanges::new(Detail::full(450), 1.0, 1.0, 200.0, 6).first, f32::INFINITY);
    }

    #[test]
    fn the_morph_is_zero_until_three_quarters_and_one_at_the_end() {
        let ranges = LodRanges { first: 200.0, top_level: 6 };
        // Level 1 ends at 400 m and starts morphing at 300 m.
        assert_eq!(ranges.morph(1, 0.0), 0.0);
        assert_eq!(ranges.morph(1, 300.0), 0.0);
        assert_eq!(ranges.morph(1, 350.0), 0.5);
        assert_eq!(ranges.morph(1, 400.0), 1.0);
        assert_eq!(ranges.morph(1, 5000.0), 1.0);
        // The root never morphs: there is no coarser level to become.
        assert_eq!(ranges.morph(6, 1e9), 0.0);
        // Full detail never morphs.
        assert_eq!(LodRanges { first: f32::INFINITY, top_level: 6 }.morph(0, 1e9), 0.0);
    }
}
