//! An orbit camera, the other way to move a [`Camera`] besides
//! [`crate::FlyController`]: the eye circles a point it always looks at.
//! Dragging turns it round the point and over it, the wheel brings it
//! nearer or further. The point is an input each time, so the orbit can
//! follow something that moves (chapter 11's boat) or stay put (a spot on
//! chapter 07's lake).

use glam::{Vec2, Vec3};

use crate::Camera;

// ANCHOR: orbit
/// Where the eye sits round the point it looks at: `yaw` radians round +y
/// (0 puts the eye on the point's +z side, so that it looks towards −z, as
/// a [`Camera`] with yaw 0 does), `pitch` radians above the point's
/// horizon (positive: the eye is higher and looks down), `distance` metres
/// away. How far drag and wheel may take it is part of it: `pitch_range`
/// and `distance_range`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    pub yaw: f32,
    pub pitch: f32,
    pub distance: f32,
    /// Lowest and highest pitch the drag reaches, radians.
    pub pitch_range: (f32, f32),
    /// Nearest and furthest the wheel reaches, metres.
    pub distance_range: (f32, f32),
}

impl Orbit {
    /// Radians turned per pixel dragged.
    pub const TURN_PER_PIXEL: f32 = 0.005;
    /// What one line of the wheel multiplies the distance by: a tenth nearer.
    pub const ZOOM_PER_LINE: f32 = 0.9;
    /// The steepest the eye ever looks, whatever `pitch_range` says: straight
    /// down (or up) the view has no "up" to orient it by, and the view
    /// matrix degenerates (the fly camera stops at the same angle).
    pub const STEEPEST: f32 = 89.0 * std::f32::consts::PI / 180.0;
    /// The nearest the eye ever comes, metres: at the point itself it would
    /// have no direction to look along.
    pub const NEAREST: f32 = 1e-3;

    /// An orbit that drag and wheel may take anywhere short of the poles,
    /// from 1 m to 10 km away; narrow it with [`Orbit::within`].
    pub const fn new(yaw: f32, pitch: f32, distance: f32) -> Self {
        Self { yaw, pitch, distance, pitch_range: (-1.5, 1.5), distance_range: (1.0, 10_000.0) }
    }

    /// The same orbit, with drag and wheel kept within `pitch` (radians)
    /// and `distance` (metres).
    pub const fn within(self, pitch: (f32, f32), distance: (f32, f32)) -> Self {
        Self { pitch_range: pitch, distance_range: distance, ..self }
    }

    /// The orbit round `target` whose eye is at `eye`, with this orbit's
    /// ranges (the angles and the distance are kept inside them): how to
    /// take over from a camera that something else placed.
    pub fn through(self, eye: Vec3, target: Vec3) -> Self {
        let offset = eye - target;
        let distance = offset.length();
        if !distance.is_finite() || distance < Self::NEAREST {
            // No direction from the point to the eye: keep the angles.
            return Self { distance: self.clamp_distance(distance.max(0.0)), ..self };
        }
        let pitch = self.clamp_pitch((offset.y / distance).clamp(-1.0, 1.0).asin());
        let yaw = offset.x.atan2(offset.z);
        Self { yaw, pitch, distance: self.clamp_distance(distance), ..self }
    }

    /// Turns the orbit by a drag of `drag` pixels (right turns the eye to
    /// the left round the point; down raises it) and zooms by `wheel`
    /// lines (positive: nearer). Non-finite input is ignored.
    pub fn steer(&mut self, drag: Vec2, wheel: f32) {
        if drag.is_finite() {
            self.yaw -= drag.x * Self::TURN_PER_PIXEL;
            self.pitch = self.clamp_pitch(self.pitch + drag.y * Self::TURN_PER_PIXEL);
        }
        if wheel.is_finite() {
            self.distance = self.clamp_distance(self.distance * Self::ZOOM_PER_LINE.powf(wheel));
        }
    }

    /// Unit vector from the point to the eye.
    pub fn back(&self) -> Vec3 {
        let pitch = self.pitch.clamp(-Self::STEEPEST, Self::STEEPEST);
        Vec3::new(self.yaw.sin() * pitch.cos(), pitch.sin(), self.yaw.cos() * pitch.cos())
    }

    /// Where the eye is, orbiting `target`.
    pub fn eye(&self, target: Vec3) -> Vec3 {
        target + self.back() * self.distance.max(Self::NEAREST)
    }

    /// The camera at the eye, looking at `target`, with a [`Camera`]'s
    /// default optics for `aspect` (replace those with struct update).
    pub fn camera(&self, target: Vec3, aspect: f32) -> Camera {
        let camera = Camera::looking_at(self.eye(target), target, aspect);
        if camera.yaw.is_finite() && camera.pitch.is_finite() {
            return camera;
        }
        // The eye rounded onto the point (a point so far out that a
        // millimetre vanishes in its rounding): looking back along the
        // orbit's own direction is looking at the point.
        Camera { yaw: self.yaw, pitch: -self.back().y.asin(), ..camera }
    }

    fn clamp_pitch(&self, pitch: f32) -> f32 {
        pitch.clamp(self.pitch_range.0, self.pitch_range.1).clamp(-Self::STEEPEST, Self::STEEPEST)
    }

    fn clamp_distance(&self, distance: f32) -> f32 {
        distance.clamp(self.distance_range.0, self.distance_range.1).max(Self::NEAREST)
    }
}
// ANCHOR_END: orbit

#[cfg(test)]
mod tests {
    use super::*;

    const TARGET: Vec3 = Vec3::new(12.0, 3.0, -40.0);

    fn finite(camera: &Camera) -> bool {
        camera.position.is_finite()
            && camera.yaw.is_finite()
            && camera.pitch.is_finite()
            && camera.view_projection().is_finite()
    }

    #[test]
    fn the_camera_looks_at_the_target_from_the_orbits_distance() {
        let mut orbit = Orbit::new(0.7, 0.3, 25.0);
        for step in 0..50 {
            orbit.steer(Vec2::new(37.0, (step % 7) as f32 * 9.0 - 30.0), 0.0);
            let camera = orbit.camera(TARGET, 1.5);
            assert!((camera.position.distance(TARGET) - 25.0).abs() < 1e-3, "distance kept at step {step}");
            let towards = (TARGET - camera.position).normalize();
            assert!(camera.forward().distance(towards) < 1e-4, "looks at the target at step {step}");
        }
    }

    #[test]
    fn yaw_zero_looks_down_minus_z_like_a_camera() {
        let camera = Orbit::new(0.0, 0.0, 10.0).camera(Vec3::ZERO, 1.0);
        assert!(camera.position.distance(Vec3::new(0.0, 0.0, 10.0)) < 1e-5);
        assert!(camera.forward().distance(-Vec3::Z) < 1e-5);
    }

    #[test]
    fn pitch_stays_in_its_range_however_far_the_drag() {
        let mut orbit = Orbit::new(0.0, 0.2, 30.0).within((0.02, 1.5), (10.0, 400.0));
        orbit.steer(Vec2::new(0.0, 1e6), 0.0);
        assert_eq!(orbit.pitch, 1.5);
        orbit.steer(Vec2::new(0.0, -1e6), 0.0);
        assert_eq!(orbit.pitch, 0.02);
        // A range wider than the poles is still kept off them.
        let mut wide = Orbit::new(0.0, 0.0, 30.0).within((-4.0, 4.0), (1.0, 100.0));
        wide.steer(Vec2::new(0.0, 1e6), 0.0);
        assert_eq!(wide.pitch, Orbit::STEEPEST);
    }

    #[test]
    fn the_wheel_zooms_a_tenth_a_line_and_stops_at_the_range() {
        let mut orbit = Orbit::new(0.0, 0.2, 100.0).within((0.0, 1.0), (10.0, 400.0));
        orbit.steer(Vec2::ZERO, 1.0);
        assert!((orbit.distance - 90.0).abs() < 1e-4);
        orbit.steer(Vec2::ZERO, 1e4);
        assert_eq!(orbit.distance, 10.0);
        orbit.steer(Vec2::ZERO, -1e4);
        assert_eq!(orbit.distance, 400.0);
        orbit.steer(Vec2::new(f32::NAN, f32::INFINITY), f32::NAN);
        assert_eq!((orbit.yaw, orbit.pitch, orbit.distance), (0.0, 0.2, 400.0), "non-finite input ignored");
    }

    #[test]
    fn no_nan_at_the_poles_or_at_zero_distance() {
        for pitch in [-std::f32::consts::FRAC_PI_2, std::f32::consts::FRAC_PI_2, 10.0, -10.0] {
            let orbit = Orbit { pitch, ..Orbit::new(0.3, 0.0, 20.0) };
            let camera = orbit.camera(TARGET, 1.5);
            assert!(finite(&camera), "pitch {pitch}: {camera:?}");
            assert!(camera.pitch.abs() <= Orbit::STEEPEST + 1e-5);
        }
        for distance in [0.0, -5.0, 1e-9] {
            let orbit = Orbit { distance, ..Orbit::new(0.3, 0.4, 20.0) };
            let camera = orbit.camera(TARGET, 1.5);
            assert!(finite(&camera), "distance {distance}: {camera:?}");
        }
        // A point so far out that a millimetre is lost in its rounding.
        let far = Vec3::new(3e7, 0.0, 3e7);
        let camera = Orbit { distance: 0.0, ..Orbit::new(0.3, 0.4, 20.0) }.camera(far, 1.5);
        assert!(finite(&camera), "{camera:?}");
        // Taking over at the point itself keeps the angles.
        let taken = Orbit::new(0.3, 0.4, 20.0).through(TARGET, TARGET);
        assert_eq!((taken.yaw, taken.pitch), (0.3, 0.4));
        assert!(finite(&taken.camera(TARGET, 1.5)));
    }

    #[test]
    fn taking_over_a_camera_keeps_its_eye() {
        let eye = Vec3::new(-30.0, 25.0, 12.0);
        let orbit = Orbit::new(0.0, 0.0, 1.0).within((-1.5, 1.5), (1.0, 500.0)).through(eye, TARGET);
        assert!(orbit.eye(TARGET).distance(eye) < 1e-3, "{:?}", orbit.eye(TARGET));
        assert!((orbit.distance - eye.distance(TARGET)).abs() < 1e-4);
        // Outside the ranges, it is brought inside them.
        let close = Orbit::new(0.0, 0.0, 1.0).within((0.1, 1.0), (10.0, 500.0)).through(TARGET + Vec3::X, TARGET);
        assert_eq!((close.pitch, close.distance), (0.1, 10.0));
    }
}
