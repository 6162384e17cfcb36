//! Building parts that move, as the city project animated some of its
//! buildings' parts: a crown turning on the tallest tower's roof and a
//! neon sign sliding up and down its face. Each is a pure
//! function of scene time: the same time, the same pose.

use std::f32::consts::TAU;

use common::glam::{Mat4, Quat, Vec3};

use crate::city::{City, Material, Piece, Shape};

// ANCHOR: moving_parts
/// Seconds for the crown to turn once, and for the sign to go up and back.
pub const TURN_PERIOD: f32 = 10.0;
pub const SLIDE_PERIOD: f32 = 16.0;

/// Where the moving parts are mounted, from the city's towers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MovingParts {
    /// The top of the roof cap the crown's mast stands on.
    pub crown_base: Vec3,
    /// The crown's arm, tip to tip.
    pub crown_span: f32,
    /// Where the sign's centre line meets the tower's east face (towards
    /// the avenue along x = 0), at y = 0.
    pub sign_face: Vec3,
    pub sign_width: f32,
    /// The sign's centre's lowest and highest heights.
    pub sign_low: f32,
    pub sign_high: f32,
}

impl MovingParts {
    /// Both on the tallest square tower: the crown on its roof cap (the
    /// rooftop camera stands beside the cap, looking away), the sign on its
    /// east face, towards the avenue along x = 0.
    pub fn new(city: &City) -> Self {
        let tallest = city.tallest_tower();
        let size = tallest.model.x_axis.length();
        let top = tallest.model.transform_point3(Vec3::Y * 0.5);
        Self {
            // The roof cap is 2 m tall (city.rs).
            crown_base: top + Vec3::Y * 2.0,
            crown_span: 0.9 * size,
            sign_face: Vec3::new(top.x + size / 2.0, 0.0, top.z),
            sign_width: 0.7 * size,
            sign_low: 0.3 * top.y,
            sign_high: 0.85 * top.y,
        }
    }

    /// The crown's turn at `time`, radians about +y, in 0..2π.
    pub fn crown_angle(time: f32) -> f32 {
        (TAU * time / TURN_PERIOD).rem_euclid(TAU)
    }

    /// The sign's centre's height at `time`: up and down, easing at both
    /// ends as a lift does (half a cosine), from `sign_low` at time 0.
    pub fn sign_height(&self, time: f32) -> f32 {
        let up = 0.5 - 0.5 * (TAU * time / SLIDE_PERIOD).cos();
        self.sign_low + (self.sign_high - self.sign_low) * up
    }

    /// Every moving part at `time`.
    pub fn pieces(&self, time: f32) -> Vec<Piece> {
        let mast = 6.0;
        let turn = Quat::from_rotation_y(Self::crown_angle(time));
        let head = self.crown_base + Vec3::Y * mast;
        let at = |shape, position: Vec3, rotation: Quat, scale: Vec3, material| Piece {
            shape,
            model: Mat4::from_scale_rotation_translation(scale, rotation, position),
            material,
        };
        let mut pieces = vec![
            at(
                Shape::Cylinder,
                self.crown_base + Vec3::Y * mast / 2.0,
                Quat::IDENTITY,
                Vec3::new(0.6, mast, 0.6),
                Material::Metal,
            ),
            at(Shape::Cube, head, turn, Vec3::new(self.crown_span, 0.5, 1.2), Material::Metal),
        ];
        for tip in [-0.5, 0.5] {
            let end = head + turn * Vec3::X * tip * self.crown_span;
            pieces.push(at(Shape::Sphere, end, Quat::IDENTITY, Vec3::splat(1.8), Material::Neon));
        }
        let sign = self.sign_face.with_y(self.sign_height(time)) + Vec3::X * 0.3;
        pieces.push(at(Shape::Cube, sign, Quat::IDENTITY, Vec3::new(0.4, 3.5, self.sign_width), Material::Neon));
        pieces
    }
}
// ANCHOR_END: moving_parts

#[cfg(test)]
mod tests {
    use std::f32::consts::{FRAC_PI_2, PI};

    use super::*;

    /// The crown's arm: its direction at a time, from the placed piece.
    fn arm(parts: &MovingParts, time: f32) -> Vec3 {
        parts.pieces(time)[1].model.transform_vector3(Vec3::X).normalize()
    }

    #[test]
    fn the_crown_is_at_known_turns_at_known_times() {
        let parts = MovingParts::new(&City::new());
        // A quarter period turns +x a quarter turn about +y, to −z.
        for (time, angle, direction) in [
            (0.0, 0.0, Vec3::X),
            (TURN_PERIOD / 4.0, FRAC_PI_2, Vec3::NEG_Z),
            (TURN_PERIOD / 2.0, PI, Vec3::NEG_X),
            (TURN_PERIOD * 3.25, FRAC_PI_2, Vec3::NEG_Z),
        ] {
            assert!((MovingParts::crown_angle(time) - angle).abs() < 1e-4, "at {time} s");
            assert!(arm(&parts, time).distance(direction) < 1e-4, "at {time} s the arm points {}", arm(&parts, time));
        }
        // The tips stay on the arm's circle, over the mast.
        for time in [0.0, 1.3, 7.7, 123.4] {
            let tips = &parts.pieces(time)[2..4];
            for tip in tips {
                let at = tip.model.w_axis.truncate() - (parts.crown_base + Vec3::Y * 6.0);
                assert!((at.length() - parts.crown_span / 2.0).abs() < 1e-3 && at.y.abs() < 1e-4);
            }
        }
    }

    #[test]
    fn the_sign_rides_between_its_ends_on_the_towers_face() {
        let city = City::new();
        let parts = MovingParts::new(&city);
        assert_eq!(parts.sign_height(0.0), parts.sign_low);
        assert!((parts.sign_height(SLIDE_PERIOD / 2.0) - parts.sign_high).abs() < 1e-3);
        let middle = (parts.sign_low + parts.sign_high) / 2.0;
        assert!((parts.sign_height(SLIDE_PERIOD / 4.0) - middle).abs() < 1e-3);
        let tower = city.tallest_tower().model;
        let roof = tower.transform_point3(Vec3::Y * 0.5).y;
        for i in 0..200 {
            let time = i as f32 * 0.37;
            let sign = parts.pieces(time)[4].model;
            let (centre, half) = (sign.w_axis.truncate(), sign.y_axis.length() / 2.0);
            assert!(centre.y - half >= 0.2 && centre.y + half <= roof, "the sign leaves the face at {time} s");
            // Its back against the face: on the tower's east side, touching it.
            let face_x = tower.w_axis.x + tower.x_axis.length() / 2.0;
            assert!((centre.x - sign.x_axis.length() / 2.0 - face_x).abs() < 0.2, "off the face at {time} s");
        }
    }
}
