//! Frustum culling: skip the chunks the camera cannot see before the GPU
//! ever hears of them.

use common::glam::{Mat4, Vec3, Vec4};

use crate::chunks::Aabb;

// ANCHOR: frustum
/// The six planes bounding what a camera sees, each as (n, d) with the
/// normal pointing inward: a point p is inside a plane when n · p + d ≥ 0.
pub struct Frustum {
    planes: [Vec4; 6],
}

impl Frustum {
    /// Reads the planes straight out of the view-projection matrix
    /// (Gribb and Hartmann's method). A point is visible when its clip
    /// coordinates satisfy −w ≤ x ≤ w, −w ≤ y ≤ w and 0 ≤ z ≤ w; each
    /// inequality, written with the matrix rows, is a plane in world space.
    pub fn from_view_projection(m: Mat4) -> Self {
        let (r0, r1, r2, r3) = (m.row(0), m.row(1), m.row(2), m.row(3));
        let planes = [r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2].map(|p| p / p.truncate().length());
        Self { planes }
    }

    /// False only when the box is entirely outside one plane. For each
    /// plane it tests the box corner furthest along the plane's normal: if
    /// even that corner is outside, the whole box is.
    pub fn intersects(&self, b: &Aabb) -> bool {
        self.planes.iter().all(|p| {
            let corner = Vec3::select(p.truncate().cmpge(Vec3::ZERO), b.max, b.min);
            p.truncate().dot(corner) + p.w >= 0.0
        })
    }
}
// ANCHOR_END: frustum

#[cfg(test)]
mod tests {
    use super::*;
    use common::Camera;

    fn cube_at(centre: Vec3) -> Aabb {
        Aabb { min: centre - Vec3::splat(5.0), max: centre + Vec3::splat(5.0) }
    }

    #[test]
    fn a_chunk_in_front_is_drawn_and_one_behind_is_not() {
        let camera = Camera::looking_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 16.0 / 9.0);
        let frustum = Frustum::from_view_projection(camera.view_projection());
        assert!(frustum.intersects(&cube_at(Vec3::new(0.0, 0.0, -50.0))), "in front");
        assert!(!frustum.intersects(&cube_at(Vec3::new(0.0, 0.0, 50.0))), "behind");
        assert!(!frustum.intersects(&cube_at(Vec3::new(200.0, 0.0, -50.0))), "far to the right");
        assert!(!frustum.intersects(&cube_at(Vec3::new(0.0, 0.0, -camera.far - 20.0))), "beyond the far plane");
        // A box straddling the edge of the view is kept.
        let edge = 50.0 * (camera.fov_y / 2.0).tan() * camera.aspect;
        assert!(frustum.intersects(&cube_at(Vec3::new(edge + 4.0, 0.0, -50.0))), "straddling the right edge");
    }

    #[test]
    fn a_big_box_around_the_camera_is_drawn() {
        let camera = Camera::looking_at(Vec3::new(3.0, 2.0, 1.0), Vec3::new(3.0, 0.0, -10.0), 1.0);
        let frustum = Frustum::from_view_projection(camera.view_projection());
        assert!(frustum.intersects(&Aabb { min: Vec3::splat(-100.0), max: Vec3::splat(100.0) }));
    }
}
