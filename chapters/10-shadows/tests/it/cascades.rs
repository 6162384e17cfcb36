//! Cascades (`shadows::cascades`): the split distances and the cascade a
//! depth falls in against hand-worked values, the slice's sphere against
//! hand-worked values and a real camera's corners, and each map's texels
//! kept in place while the camera moves and turns.

use common::Camera;
use common::glam::Vec3;
use shadows::cascades::{cascade_of, fit_cascades, practical_splits, slice_sphere};
use shadows::light_box::LightBox;

fn close(a: f32, b: f32, within: f32) -> bool {
    (a - b).abs() <= within
}

#[test]
fn the_practical_splits_blend_the_logarithmic_and_uniform_cuts() {
    // Worked by hand for near 1 m, far 1,000 m, four slices:
    // logarithmic cuts 1000^(i/4): 1, 5.6234, 31.623, 177.83, 1000;
    // uniform cuts 1 + 999·i/4: 1, 250.75, 500.5, 750.25, 1000;
    // halfway between (λ = 0.5): 1, 128.19, 266.06, 464.04, 1000.
    let half = practical_splits(1.0, 1000.0, 4, 0.5);
    for (got, want) in half.iter().zip([1.0, 128.19, 266.06, 464.04, 1000.0]) {
        assert!(close(*got, want, 0.01), "{half:?}");
    }
    let logarithmic = practical_splits(1.0, 1000.0, 4, 1.0);
    for (got, want) in logarithmic.iter().zip([1.0, 5.6234, 31.623, 177.83, 1000.0]) {
        assert!(close(*got, want, 0.01), "{logarithmic:?}");
    }
    let uniform = practical_splits(1.0, 1000.0, 4, 0.0);
    for (got, want) in uniform.iter().zip([1.0, 250.75, 500.5, 750.25, 1000.0]) {
        assert!(close(*got, want, 0.001), "{uniform:?}");
    }
}

#[test]
fn a_depth_falls_in_the_slice_whose_cuts_hold_it() {
    let cuts = [1.0, 128.19, 266.06, 464.04, 1000.0];
    assert_eq!(cascade_of(0.5, &cuts), None, "before the near plane");
    assert_eq!(cascade_of(1.0, &cuts), Some(0));
    assert_eq!(cascade_of(128.18, &cuts), Some(0));
    assert_eq!(cascade_of(128.19, &cuts), Some(1), "a cut belongs to the slice it starts");
    assert_eq!(cascade_of(300.0, &cuts), Some(2));
    assert_eq!(cascade_of(999.9, &cuts), Some(3));
    assert_eq!(cascade_of(1000.0, &cuts), None, "the far plane and past it");
}

#[test]
fn the_slice_sphere_is_the_hand_worked_one_and_holds_every_corner() {
    // 90° up and down, square: k² = 1·(1 + 1) = 2. From 1 m to 3 m,
    // (1 + 3)(1 + 2)/2 = 6 is past the far cut, so the centre is at 3
    // and the radius the far corners' distance from the axis, 3√2.
    let (along, radius) = slice_sphere(1.0, 3.0, 90f32.to_radians(), 1.0);
    assert!(close(along, 3.0, 1e-5) && close(radius, 3.0 * 2f32.sqrt(), 1e-4), "{along} {radius}");
    // tan(fov/2) = 0.1, square: k² = 0.02. From 10 m to 20 m the centre
    // is at 30·1.02/2 = 15.3, and the radius √(4.7² + 400·0.02) =
    // √30.09 = 5.4854, the same to the near corners: √(5.3² + 2).
    let fov = 2.0 * 0.1f32.atan();
    let (along, radius) = slice_sphere(10.0, 20.0, fov, 1.0);
    assert!(close(along, 15.3, 1e-4) && close(radius, 5.4854, 1e-3), "{along} {radius}");
    // A second way: the corners of a real camera's slice, found from
    // its inverse view-projection, all lie inside (some on) the sphere.
    let camera = Camera::looking_at(Vec3::new(3.0, 40.0, -7.0), Vec3::new(90.0, 2.0, 300.0), 16.0 / 9.0);
    let view = camera.view_projection().inverse();
    let (along, radius) = slice_sphere(camera.near, camera.far, camera.fov_y, camera.aspect);
    let centre = camera.position + camera.forward() * along;
    for i in 0..8 {
        let ndc = Vec3::new(if i & 1 == 0 { -1.0 } else { 1.0 }, if i & 2 == 0 { -1.0 } else { 1.0 }, (i / 4) as f32);
        let corner = view.project_point3(ndc);
        assert!(corner.distance(centre) <= radius * 1.0001, "corner {i} at {corner} outside");
    }
}

/// Where a world point falls on a cascade's map, in texels.
fn in_texels(light: &LightBox, point: Vec3, size: u32) -> (f32, f32) {
    let clip = light.view_proj.project_point3(point);
    ((clip.x + 1.0) / 2.0 * size as f32, (clip.y + 1.0) / 2.0 * size as f32)
}

#[test]
fn moving_or_turning_the_camera_keeps_each_maps_texels_where_they_were() {
    let size = 1024;
    let sun = Vec3::new(0.4, 0.5, -0.3).normalize();
    let casters = (Vec3::new(-500.0, -20.0, -500.0), Vec3::new(500.0, 80.0, 500.0));
    let mut camera = Camera::looking_at(Vec3::new(0.0, 10.0, 0.0), Vec3::new(30.0, 0.0, 100.0), 16.0 / 9.0);
    camera.far = 400.0;
    let splits = practical_splits(camera.near, camera.far, 4, 0.7);
    let before = fit_cascades(&camera, sun, casters, size, &splits);
    // A third of the first cascade's texel sideways, and 7° of turn.
    let mut moved = camera;
    moved.position += camera.right() * before[0].light.texel / 3.0;
    moved.yaw += 7f32.to_radians();
    let after = fit_cascades(&moved, sun, casters, size, &splits);
    let ground = Vec3::new(12.0, 0.0, 60.0);
    for (k, (a, b)) in before.iter().zip(&after).enumerate() {
        assert_eq!(a.light.texel, b.light.texel, "cascade {k}: its texels changed size");
        // The same point on the ground lies at the same place inside
        // its texel: the grid moved by whole texels, or not at all.
        let ((ax, ay), (bx, by)) = (in_texels(&a.light, ground, size), in_texels(&b.light, ground, size));
        let shift = |u: f32, v: f32| ((u - v) - (u - v).round()).abs();
        assert!(shift(ax, bx) < 2e-3 && shift(ay, by) < 2e-3, "cascade {k}: ({ax}, {ay}) then ({bx}, {by})");
    }
}
