//! Where the views put the camera: at the lake's southern shore, looking
//! north across the water towards the cliff, 18 m above the water to
//! start with, or 6 m above it, where the waves look large.

use common::Camera;
use common::glam::Vec2;
use terrain::heightfield::HeightField;

use crate::lake::lake_camera;

/// How high above the water the start camera stands, metres.
pub const EYE_HEIGHT: f32 = 18.0;

/// The places a view can put the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// At the same shore, 6 m above the water, where the waves look large.
    CloseToWater,
}

impl CameraPreset {
    pub fn camera(self, field: &HeightField, centre: Vec2, size: f32, level: f32, aspect: f32) -> Camera {
        match self {
            Self::CloseToWater => lake_camera(field, centre, size, level, 6.0, aspect),
        }
    }
}
