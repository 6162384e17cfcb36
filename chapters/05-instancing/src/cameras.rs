//! Where the chapter looks from: standing on the plain among the rocks.
//! The rocks are stored nearest this camera first, and chapters 06 and 07
//! start from it too.

use common::Camera;
use common::glam::Vec3;
use terrain::heightfield::HeightField;

/// Standing on the plain, eyes 3.5 m up, looking across the rocks at the cliff.
pub fn plain_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47 + 60.0;
    let z = s.cliff_line(x) + 230.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 3.5, z);
    let ahead = Vec3::new(x + 40.0, 0.0, z - 200.0);
    let target = Vec3::new(ahead.x, field.height_at(ahead.x, ahead.z) + 2.0, ahead.z);
    Camera { far: fog::MAX_FAR, near: 0.1, ..Camera::looking_at(eye, target, aspect) }
}

/// No view of this chapter places the camera (every one is a mode): this
/// enum has no values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {}

impl CameraPreset {
    pub fn camera(self, _field: &HeightField, _aspect: f32) -> Camera {
        match self {}
    }
}
