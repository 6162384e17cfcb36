//! Level of detail: how finely each part of the terrain is drawn, so that
//! a cell of the mesh covers about the same number of pixels near and far.

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
    /// Cells at most this many pixels wide where a level ends.
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
