//! The field of primitives: each object's model matrix (scale, then
//! rotation, then translation), its spin with scene time, and the rows.

use std::f32::consts::PI;

use camera::{Placement, Shape, scene};
use common::glam::{Quat, Vec3};

#[test]
fn model_matrix_scales_then_rotates_then_translates() {
    let placement = Placement {
        shape: Shape::Cube,
        position: Vec3::new(10.0, 0.0, 0.0),
        rotation: Quat::from_rotation_z(PI / 2.0),
        scale: Vec3::new(2.0, 1.0, 1.0),
        spin: 0.0,
        color: [1.0; 3],
    };
    // +x is doubled to (2,0,0), turned a quarter about z to (0,2,0), moved by +10 x.
    let p = placement.model(0.0).transform_point3(Vec3::X);
    assert!(p.distance(Vec3::new(10.0, 2.0, 0.0)) < 1e-5, "{p}");
}

#[test]
fn spin_follows_scene_time() {
    let mut placement = scene()[2];
    placement.rotation = Quat::IDENTITY;
    placement.spin = PI / 2.0;
    let p = placement.model(1.0).transform_vector3(Vec3::X / placement.scale);
    assert!(p.distance(Vec3::NEG_Z) < 1e-5, "{p}");
}

#[test]
fn the_scene_has_every_primitive_in_every_row() {
    let objects = scene();
    assert_eq!(objects.len(), 18);
    for shape in Shape::ALL {
        assert_eq!(objects.iter().filter(|o| o.shape == shape).count(), 3);
    }
}
