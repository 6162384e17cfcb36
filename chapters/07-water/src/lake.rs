//! Where the lake is on the plain, the camera at its shore, the camera
//! mirrored in its water, which takes the reflection picture, and the
//! point on the lake an orbit camera turns round.

use common::Camera;
use common::glam::{Vec2, Vec3};
use terrain::heightfield::HeightField;

// ANCHOR: lake
/// The lake's side, metres …
pub const LAKE_SIZE_METRES: f32 = 520.0;
/// … how far its centre is ahead of the plain's camera …
pub const LAKE_AHEAD_METRES: f32 = 260.0;
/// … and the percentile of the ground's heights in it that its level is
/// at: this share of the square, the lowest, is under water.
pub const LAKE_LEVEL_PERCENTILE: usize = 30;

/// Where the lake is: a square [`LAKE_SIZE_METRES`] across,
/// [`LAKE_AHEAD_METRES`] ahead of `camera`, its level at the
/// [`LAKE_LEVEL_PERCENTILE`]th percentile of the ground's heights in that
/// square.
pub fn find_lake(field: &HeightField, camera: &Camera) -> (Vec2, f32, f32) {
    let forward = Vec2::new(camera.forward().x, camera.forward().z).normalize();
    let centre = Vec2::new(camera.position.x, camera.position.z) + forward * LAKE_AHEAD_METRES;
    let size = LAKE_SIZE_METRES;
    let mut heights: Vec<f32> = (0..64 * 64)
        .map(|i| {
            let p = centre + (Vec2::new((i % 64) as f32, (i / 64) as f32) / 63.0 - 0.5) * size;
            field.height_at(p.x, p.y)
        })
        .collect();
    heights.sort_by(f32::total_cmp);
    (centre, size, heights[heights.len() * LAKE_LEVEL_PERCENTILE / 100])
}

/// Standing at the lake's southern shore, `height` metres above the water,
/// looking north across it towards the cliff.
pub fn lake_camera(field: &HeightField, centre: Vec2, size: f32, level: f32, height: f32, aspect: f32) -> Camera {
    let eye = Vec2::new(centre.x, centre.y + 0.42 * size);
    let eye = common::glam::Vec3::new(eye.x, (level + height).max(field.height_at(eye.x, eye.y) + 2.0), eye.y);
    let target = common::glam::Vec3::new(centre.x, level, centre.y - 0.2 * size);
    Camera { far: 3000.0, near: 0.1, ..Camera::looking_at(eye, target, aspect) }
}

/// The camera mirrored in the water: as far below the surface as the real
/// one is above it, looking as far up as the real one looks down.
pub fn mirrored(camera: &Camera, level: f32) -> Camera {
    let mut mirror = *camera;
    mirror.position.y = 2.0 * level - camera.position.y;
    mirror.pitch = -camera.pitch;
    mirror
}
// ANCHOR_END: lake

/// The point an orbit camera taking over from `camera` turns round: where
/// the middle of its view meets the water, or the lake's centre when that
/// is off the lake, behind the camera, or nowhere (looking level or up).
pub fn orbit_point(camera: &Camera, level: f32, centre: Vec2, size: f32) -> Vec3 {
    let middle = Vec3::new(centre.x, level, centre.y);
    let forward = camera.forward();
    // How far along the view the water is; negative or infinite when it is not ahead.
    let along = (level - camera.position.y) / forward.y;
    let hit = camera.position + forward * along;
    let on_lake = (hit.x - centre.x).abs() <= size / 2.0 && (hit.z - centre.y).abs() <= size / 2.0;
    if along > 0.0 && hit.is_finite() && on_lake { hit } else { middle }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_orbit_turns_round_the_water_in_view_or_the_lake_centre() {
        let (level, centre, size) = (10.0, Vec2::new(100.0, -50.0), 200.0);
        let looking_down = Camera::looking_at(Vec3::new(100.0, 30.0, 20.0), Vec3::new(100.0, 10.0, -20.0), 1.5);
        let point = orbit_point(&looking_down, level, centre, size);
        assert!(point.distance(Vec3::new(100.0, 10.0, -20.0)) < 1e-3, "{point}");
        let middle = Vec3::new(100.0, 10.0, -50.0);
        let looking_up = Camera::looking_at(Vec3::new(100.0, 30.0, 20.0), Vec3::new(100.0, 40.0, -20.0), 1.5);
        let level_view = Camera::looking_at(Vec3::new(100.0, 10.0, 20.0), Vec3::new(100.0, 10.0, -20.0), 1.5);
        let off_the_lake = Camera::looking_at(Vec3::new(500.0, 30.0, 20.0), Vec3::new(520.0, 10.0, 20.0), 1.5);
        let under_water = Camera::looking_at(Vec3::new(100.0, 5.0, 20.0), Vec3::new(100.0, 0.0, -20.0), 1.5);
        for camera in [looking_up, level_view, off_the_lake, under_water] {
            assert_eq!(orbit_point(&camera, level, centre, size), middle, "{camera:?}");
        }
    }
}
