//! How big a rock looks, and what that decides: a picture's pixels per
//! radian, which turn a rock's angular size into pixels across, and the
//! sizes at which the GPU's culling draws a rock with fewer triangles, or
//! not at all (`pixels_across` and `kept_size` in rock.wgsl).

use common::Camera;
use common::glam::Vec4;

/// Where one picture is taken from, as the culling needs it: the camera,
/// how many pixels high the picture is, and the plane it is clipped at
/// (`terrain::KEEP_ALL` keeps everything).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Picture {
    pub camera: Camera,
    pub height: u32,
    pub clip: Vec4,
}

// ANCHOR: pixels_per_radian
impl Picture {
    /// Pixels per radian at the picture's centre: `height` pixels span the
    /// field of view, and at the centre a pixel spans 2 tan(fov/2) / height
    /// of the distance.
    pub fn pixels_per_radian(&self) -> f32 {
        self.height as f32 / (2.0 * (self.camera.fov_y / 2.0).tan())
    }
}
// ANCHOR_END: pixels_per_radian

// ANCHOR: grading
/// How a picture grades its rocks by their size on screen, in pixels
/// across (`pixels_across` in rock.wgsl).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grading {
    /// From this size up, the full rock (20 triangles).
    pub full: f32,
    /// From this size to `full`, the octahedron (8 triangles).
    pub coarse: f32,
    /// From this size to `coarse`, the tetrahedron (4); below it, nothing.
    pub drawn: f32,
    /// Between `drawn` and this size a rock shrinks to nothing as it gets
    /// smaller, rather than vanishing at once.
    pub whole: f32,
}

impl Grading {
    /// The plain's: triangles of a few pixels at every level.
    pub const LOD: Self = Self { full: 12.0, coarse: 4.0, drawn: 1.0, whole: 2.0 };
    /// Every rock in view at full size and full detail, however small: the
    /// frustum and the clip plane alone, to compare the graded picture with.
    pub const FULL_DETAIL: Self = Self { full: 0.0, coarse: 0.0, drawn: 0.0, whole: 0.0 };
}
// ANCHOR_END: grading
