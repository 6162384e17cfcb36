//! Where the camera starts: the place every view opens on, and the
//! (empty) list of views that set the camera themselves. Every view of
//! this chapter is a mode, a way of drawing, so flying somewhere and then
//! switching views keeps the place.

use common::Camera;
use common::glam::Vec3;

// ANCHOR: start_camera
/// The camera every view starts from: above and behind the front row,
/// looking down at the field, with its far plane at 200 m.
pub fn start_camera(aspect: f32) -> Camera {
    let mut camera = Camera::looking_at(Vec3::new(-3.0, 4.0, 9.0), Vec3::new(0.0, 0.5, -1.0), aspect);
    camera.far = 200.0;
    camera
}
// ANCHOR_END: start_camera

// ANCHOR: presets
/// No view of this chapter places the camera (every one is a mode): this
/// enum has no values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {}

impl CameraPreset {
    pub fn camera(self, _aspect: f32) -> Camera {
        match self {}
    }
}
// ANCHOR_END: presets
