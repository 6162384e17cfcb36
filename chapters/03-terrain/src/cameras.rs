//! Where the chapter looks from, on any height field: the start camera
//! that later chapters share, a close-up at the foot of the cliff (the one
//! view that is a preset), and the view from high overhead.

use common::Camera;
use common::glam::Vec3;

use crate::heightfield::HeightField;

/// The camera views start from: on the plain south of the cliff, looking
/// north at it, with hills behind.
pub fn start_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47;
    let z = s.cliff_line(x) + 170.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 30.0, z);
    let target = Vec3::new(x + 120.0, field.height_at(x + 120.0, z - 300.0), z - 300.0);
    Camera { far: 3000.0, near: 0.5, ..Camera::looking_at(eye, target, aspect) }
}

/// Close to the ground at the foot of the cliff, where the wireframe's
/// one-metre cells are large enough to see.
pub fn close_up_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47;
    let z = s.cliff_line(x) + 45.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 9.0, z);
    let target = Vec3::new(x + 20.0, field.height_at(x + 20.0, z - 30.0) + 4.0, z - 30.0);
    Camera { far: 3000.0, near: 0.5, ..Camera::looking_at(eye, target, aspect) }
}

/// High above the middle of the world, looking down with north (−z) at
/// the top of the picture. Built from angles: straight down, `looking_at`
/// cannot tell which way is up (the pitch rounds to exactly −90° in f32).
pub fn overhead_camera(field: &HeightField, aspect: f32) -> Camera {
    let centre = field.settings.extent() * 0.5;
    Camera {
        position: Vec3::new(centre, 4200.0, centre),
        yaw: 0.0,
        pitch: -89.99f32.to_radians(),
        fov_y: 60f32.to_radians(),
        aspect,
        near: 10.0,
        far: 6000.0,
    }
}

/// The places a view can put the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// At the foot of the cliff, where the wireframe's cells are large.
    CloseUp,
}

impl CameraPreset {
    pub fn camera(self, field: &HeightField, aspect: f32) -> Camera {
        match self {
            Self::CloseUp => close_up_camera(field, aspect),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chunks::{Aabb, chunk_bounds};
    use crate::culling::Frustum;
    use crate::heightfield::TerrainSettings;

    #[test]
    fn start_camera_culls_behind_and_keeps_ahead() {
        let field = HeightField::generate(TerrainSettings::default());
        let camera = start_camera(&field, 16.0 / 9.0);
        let frustum = Frustum::from_view_projection(camera.view_projection());
        let chunk_at = |p: Vec3| {
            let n = field.settings.chunks_per_side as f32;
            let size = field.settings.extent() / n;
            ((p.z / size).floor() * n + (p.x / size).floor()) as usize
        };
        let bounds: Vec<Aabb> = (0..field.settings.chunks_per_side.pow(2))
            .map(|i| chunk_bounds(&field, i % field.settings.chunks_per_side, i / field.settings.chunks_per_side))
            .collect();
        let ahead = camera.position + camera.forward() * 300.0;
        let behind = camera.position - camera.forward() * 300.0;
        assert!(frustum.intersects(&bounds[chunk_at(ahead)]), "ahead");
        assert!(!frustum.intersects(&bounds[chunk_at(behind)]), "behind");
        let n = field.settings.chunks_per_side as usize;
        let camera_row = chunk_at(camera.position) / n;
        let north = (0..bounds.len()).filter(|&i| i / n < camera_row && frustum.intersects(&bounds[i])).count();
        let south = (0..bounds.len()).filter(|&i| i / n > camera_row && frustum.intersects(&bounds[i])).count();
        assert!(north > 500 && south == 0, "{north} chunks drawn north of the camera, {south} south");
    }

    #[test]
    fn overhead_view_has_north_at_the_top() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 2, ..Default::default() });
        let top = overhead_camera(&field, 1.0).view_projection();
        let ndc_y = |z: f32| {
            let c = top * Vec3::new(64.0, 0.0, z).extend(1.0);
            c.y / c.w
        };
        assert!(ndc_y(0.0) > ndc_y(128.0), "north (−z) must be up");
    }
}
