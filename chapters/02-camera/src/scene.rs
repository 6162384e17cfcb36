//! The field of primitives: the six shapes, where each object stands and
//! how it moves (its model matrix), the three rows of them, and the ground
//! they stand on.

use std::f32::consts::PI;

use common::glam::{Mat4, Quat, Vec3};
use common::{MeshData, primitives};

/// The six primitives from `common::primitives`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    Cube,
    Sphere,
    Cylinder,
    Cone,
    Torus,
    Pyramid,
}

impl Shape {
    pub const ALL: [Shape; 6] =
        [Shape::Cube, Shape::Sphere, Shape::Cylinder, Shape::Cone, Shape::Torus, Shape::Pyramid];

    /// The shape's mesh, made on the CPU.
    pub fn mesh(self) -> MeshData {
        match self {
            Shape::Cube => primitives::cube(),
            Shape::Sphere => primitives::uv_sphere(32, 16),
            Shape::Cylinder => primitives::cylinder(32),
            Shape::Cone => primitives::cone(32),
            Shape::Torus => primitives::torus(48, 16, 0.15),
            Shape::Pyramid => primitives::pyramid(),
        }
    }
}

// ANCHOR: placement
/// Where one object stands and how it moves.
#[derive(Clone, Copy, Debug)]
pub struct Placement {
    pub shape: Shape,
    pub position: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
    /// Turns around the object's own y axis, radians per second.
    pub spin: f32,
    pub color: [f32; 3],
}

impl Placement {
    /// Model matrix at scene time `time`: scale first, then rotate, then
    /// move. Read right to left: T · R · S applied to a vertex v is
    /// T(R(S v)), so scaling happens in the object's own axes.
    pub fn model(&self, time: f32) -> Mat4 {
        let rotation = self.rotation * Quat::from_rotation_y(self.spin * time);
        Mat4::from_translation(self.position) * Mat4::from_quat(rotation) * Mat4::from_scale(self.scale)
    }
}
// ANCHOR_END: placement

/// How much larger the back row's shapes are made than the front row's
/// (which are as built): larger, and still smaller on the picture.
pub const BACK_ROW_SCALE: f32 = 1.4;

// ANCHOR: scene
/// Three rows of the six primitives: as built (front), stretched and
/// tilted (middle), and spinning at different rates (back).
pub fn scene() -> Vec<Placement> {
    let palette = [
        [0.80, 0.25, 0.20],
        [0.90, 0.60, 0.15],
        [0.30, 0.65, 0.30],
        [0.20, 0.45, 0.80],
        [0.55, 0.30, 0.75],
        [0.85, 0.80, 0.70],
    ];
    let mut objects = Vec::new();
    for (i, &shape) in Shape::ALL.iter().enumerate() {
        let x = (i as f32 - 2.5) * 2.2;
        let color = palette[i];
        let upright = Quat::IDENTITY;
        objects.push(Placement {
            shape,
            position: Vec3::new(x, 0.5, 2.0),
            rotation: upright,
            scale: Vec3::ONE,
            spin: 0.0,
            color,
        });
        objects.push(Placement {
            shape,
            position: Vec3::new(x, 0.9, -1.0),
            rotation: Quat::from_rotation_z(0.35) * Quat::from_rotation_x(-0.3),
            scale: Vec3::new(0.7, 1.6, 0.7),
            spin: 0.0,
            color,
        });
        objects.push(Placement {
            shape,
            position: Vec3::new(x, 1.2, -4.0),
            rotation: Quat::from_rotation_x(PI / 2.0 * (i % 2) as f32),
            scale: Vec3::splat(BACK_ROW_SCALE),
            spin: 0.4 + 0.25 * i as f32,
            color,
        });
    }
    objects
}
// ANCHOR_END: scene

// ANCHOR: ground
/// The ground is `primitives::plane(1)`, one metre across, stretched to a
/// square this many metres wide.
pub const GROUND_SIZE: f32 = 60.0;

/// The ground's colour; its alpha is the strength of the checker pattern
/// the fragment shader draws (the objects' is 0).
pub const GROUND_COLOR: [f32; 4] = [0.35, 0.36, 0.38, 1.0];

/// The ground's model matrix: only a scale, since it lies at the origin.
pub fn ground_model() -> Mat4 {
    Mat4::from_scale(Vec3::new(GROUND_SIZE, 1.0, GROUND_SIZE))
}
// ANCHOR_END: ground
