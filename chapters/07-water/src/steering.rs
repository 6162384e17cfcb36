//! How the mouse moves the camera round the lake: chapter 02's fly camera,
//! or `common::Orbit` turning round a point on the water, as seed 003's
//! trackball did. The orbit takes over where the camera is, so switching
//! never jumps, and neither way changes what a view draws.

use common::glam::{Vec2, Vec3};
use common::{Camera, Input, Orbit};
use terrain::ground;

use crate::lake::orbit_point;

// ANCHOR: steering
/// How the mouse moves the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Steering {
    /// Chapter 02's fly camera: keys move, dragging looks round.
    Fly,
    /// `common::Orbit`: dragging turns round a point on the lake, the wheel zooms.
    Orbit,
}

/// The orbit round the lake: from level with the water (never below it,
/// nor lifting a camera that takes over low over the water) to nearly
/// overhead, 3 m to 1.5 km from the point.
pub const LAKE_ORBIT: Orbit = Orbit::new(0.0, 0.5, 50.0).within((0.0, 1.5), (3.0, 1500.0));

/// The orbit while it steers the camera: the orbit, the point on the lake
/// it turns round, and where it last put the camera (position, yaw, pitch).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbiting {
    orbit: Orbit,
    point: Vec3,
    placed: (Vec3, f32, f32),
}
// ANCHOR_END: steering

/// The fly camera's keys (with walking), then the orbit camera's mouse.
pub const STEERING_KEYS: [(&str, &str); 9] = [
    ground::KEYS[0],
    ground::KEYS[1],
    ground::KEYS[2],
    ground::KEYS[3],
    ground::KEYS[4],
    ground::KEYS[5],
    ground::KEYS[6],
    ("drag (orbit camera)", "turn round the point on the lake"),
    ("scroll (orbit camera)", "nearer or further"),
];

// ANCHOR: orbit
/// The orbit camera's frame: it takes the camera over where it is,
/// turning round the point of the lake (its `level`, `centre` and `size`)
/// it looks at (and again whenever something else moved it: a preset,
/// "reset camera"), then the drag turns it and the wheel zooms. The camera
/// keeps its optics.
pub fn steer_orbit(
    orbiting: &mut Option<Orbiting>,
    camera: &mut Camera,
    (level, centre, size): (f32, Vec2, f32),
    input: &Input,
) {
    let here = (camera.position, camera.yaw, camera.pitch);
    let mut current = match *orbiting {
        Some(current) if current.placed == here => current,
        _ => {
            let point = orbit_point(camera, level, centre, size);
            Orbiting { orbit: LAKE_ORBIT.through(camera.position, point), point, placed: here }
        }
    };
    current.orbit.steer(input.look, input.scroll);
    let placed = current.orbit.camera(current.point, camera.aspect);
    *camera = Camera { position: placed.position, yaw: placed.yaw, pitch: placed.pitch, ..*camera };
    current.placed = (placed.position, placed.yaw, placed.pitch);
    *orbiting = Some(current);
}
// ANCHOR_END: orbit
