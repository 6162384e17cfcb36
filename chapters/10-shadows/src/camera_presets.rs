//! Where the camera stands: the side camera that follows the player (every
//! view but one, and the camera the sun's box is fitted to), the close-up
//! distance of the filter views, and the `lantern` view's preset in front
//! of the tunnel. A side-scroller's camera only slides, which is what lets
//! the sun's box keep its size (the `light_box` module).

use common::Camera;
use common::glam::{Vec2, Vec3};

// ANCHOR: camera
/// How far in front of the level the camera stands, metres.
pub const CAMERA_DISTANCE: f32 = 11.0;
/// Where the filter views' camera stands instead, metres.
pub const CLOSE_UP_DISTANCE: f32 = 4.0;

/// Where a preset puts the camera instead of behind the player.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// In front of the tunnel, looking at the lantern ([`lantern_camera`]).
    Lantern,
}

/// The side camera: `distance` in front of the level's middle (z = 0),
/// looking down at the player at about 17°, so that the ground where
/// shadows fall shows.
pub fn side_camera(player: Vec2, distance: f32, aspect: f32) -> Camera {
    let eye = Vec3::new(player.x, player.y + 0.3 * distance, distance);
    Camera { near: 0.5, far: 400.0, ..Camera::looking_at(eye, Vec3::new(player.x, player.y, 0.0), aspect) }
}

/// The `lantern` view's camera: in front of the tunnel, right of the
/// lantern and a little above it, looking down past it at the ground its
/// light falls on.
pub fn lantern_camera(lantern: Vec3, aspect: f32) -> Camera {
    let eye = lantern + Vec3::new(2.6, -0.35, 6.2);
    Camera { near: 0.1, far: 400.0, ..Camera::looking_at(eye, lantern + Vec3::new(0.2, -0.5, 0.0), aspect) }
}
// ANCHOR_END: camera
