//! Where the camera goes: it circles the boat (`common::Orbit`, as chapter
//! 07's camera circles the lake), and three presets put it behind the boat
//! into the sunset, high over the grid, or close by the sail.

use common::glam::Vec3;
use common::{Camera, Orbit};

/// Where a preset puts the orbit camera; a mode leaves it, and "reset
/// camera" takes it back to [`SUNSET_ORBIT`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// [`SUNSET_ORBIT`]: behind the boat, into the sunset.
    Sunset,
    /// [`HIGH_ORBIT`]: high over the boat, to see the grid.
    High,
    /// [`SAIL_ORBIT`]: beside the boat, on the side its sail fills towards.
    Sail,
}

// ANCHOR: orbit
/// The camera circles the boat (`common::Orbit`): from just above the
/// water to nearly overhead, 10 to 400 m away.
const ROUND_THE_BOAT: Orbit = Orbit::new(1.95, 0.22, 26.0).within((0.02, 1.5), (10.0, 400.0));
/// From behind the boat's left, looking west into the sunset.
pub const SUNSET_ORBIT: Orbit = ROUND_THE_BOAT;
/// High over the boat, to see the grid.
pub const HIGH_ORBIT: Orbit = Orbit { pitch: 1.2, distance: 110.0, ..ROUND_THE_BOAT };
/// Close by the boat's port quarter at the snapshot time, when the wind
/// fills the sail towards that side (a test checks both).
pub const SAIL_ORBIT: Orbit = Orbit { yaw: 0.45, pitch: 0.1, distance: 12.5, ..ROUND_THE_BOAT };

/// The camera looking at a point 2 m above `boat` from `orbit`.
pub fn orbit_camera(orbit: &Orbit, boat: Vec3, aspect: f32) -> Camera {
    Camera { near: 0.5, far: 2000.0, ..orbit.camera(boat + Vec3::Y * 2.0, aspect) }
}
// ANCHOR_END: orbit

/// Where `preset` puts the camera; a mode (no preset) and "reset camera"
/// go back to [`SUNSET_ORBIT`].
pub fn orbit_of(preset: Option<CameraPreset>) -> Orbit {
    match preset {
        Some(CameraPreset::High) => HIGH_ORBIT,
        Some(CameraPreset::Sail) => SAIL_ORBIT,
        Some(CameraPreset::Sunset) | None => SUNSET_ORBIT,
    }
}
