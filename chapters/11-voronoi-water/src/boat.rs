//! The boat: where it sails (a course for pictures, the keys for people),
//! and how it rides the waves, from the same wave function the vertex
//! shader uses, sampled at its bow, stern and both sides.

use common::glam::{Mat4, Quat, Vec2, Vec3};
use water::waves::Wave;

use crate::sea;

/// The boat's model is 8 m from bow to stern …
pub const LENGTH: f32 = 8.0;
/// … 2.6 m in the beam …
pub const BEAM: f32 = 2.6;
/// … and floats with its keel this far below the water.
pub const DRAFT: f32 = 0.5;
/// Its mast's top, above the keel: nothing of the boat, its sail and its
/// sailor reaches higher.
pub const MAST_TOP: f32 = 8.2;

/// Where the boat is and which way it points. A heading of 0 points the
/// bow towards −z; positive turns it left (counter-clockwise from above).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Helm {
    /// On the sea's period, [0, L)²: see [`Helm::wrapped`].
    pub position: Vec2,
    pub heading: f32,
    /// Metres per second along the heading.
    pub speed: f32,
}

/// Unit vector the bow points along, in the xz plane (x, z).
pub fn forward(heading: f32) -> Vec2 {
    Vec2::new(-heading.sin(), -heading.cos())
}

// ANCHOR: course
/// The course the boat sails when nobody steers: a circle 120 m across at
/// 5 m/s, around a point among the islands, once every 75 seconds.
pub const COURSE_CENTRE: Vec2 = Vec2::new(2048.0, 2048.0);
pub const COURSE_RADIUS: f32 = 60.0;
pub const COURSE_SPEED: f32 = 5.0;

/// The boat on its course at scene time `time`. A pure function of time:
/// the time is first reduced to one lap, so that after a million seconds
/// the angle is still exact.
pub fn on_course(time: f32) -> Helm {
    let lap = std::f32::consts::TAU * COURSE_RADIUS / COURSE_SPEED;
    let angle = time.rem_euclid(lap) / lap * std::f32::consts::TAU;
    let position = COURSE_CENTRE + COURSE_RADIUS * Vec2::new(angle.cos(), angle.sin());
    // Counter-clockwise seen from above (+y) is clockwise in (x, z): the
    // boat moves along (−sin, cos) in (x, z).
    let along = Vec2::new(-angle.sin(), angle.cos());
    Helm { position, heading: (-along.x).atan2(-along.y), speed: COURSE_SPEED }
}
// ANCHOR_END: course

// ANCHOR: helm
/// The keys' orders this frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Orders {
    pub ahead: bool,
    pub astern: bool,
    pub left: bool,
    pub right: bool,
}

impl Helm {
    /// Top speed ahead, m/s (astern: a third of it).
    pub const TOP_SPEED: f32 = 9.0;

    /// Steers for `dt` seconds: the throttle eases the speed towards its
    /// target, the rudder turns the boat the more the faster it goes.
    pub fn steer(&mut self, orders: Orders, dt: f32) {
        let dt = if dt.is_finite() { dt.clamp(0.0, 0.25) } else { 0.0 };
        let target = match (orders.ahead, orders.astern) {
            (true, false) => Self::TOP_SPEED,
            (false, true) => -Self::TOP_SPEED / 3.0,
            _ => 0.0,
        };
        self.speed += (target - self.speed) * (1.0 - (-dt / 1.5).exp());
        let rudder = f32::from(u8::from(orders.left)) - f32::from(u8::from(orders.right));
        self.heading = (self.heading + rudder * 0.6 * dt * (self.speed / Self::TOP_SPEED).clamp(-1.0, 1.0))
            .rem_euclid(std::f32::consts::TAU);
        self.position += forward(self.heading) * self.speed * dt;
        *self = self.wrapped();
    }

    /// The same place, moved back onto the sea's first period. The sea
    /// repeats every [`sea::PERIOD_METRES`], so this changes nothing one
    /// can see, and keeps every world position small enough for f32 to
    /// place a vertex to a tenth of a millimetre, however far one sails.
    pub fn wrapped(self) -> Self {
        Self { position: self.position.rem_euclid(Vec2::splat(sea::PERIOD_METRES)), ..self }
    }
}
// ANCHOR_END: helm

// ANCHOR: pose
/// The boat as it rides the waves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub helm: Helm,
    /// The water's mean height under the boat, metres.
    pub heave: f32,
    /// Radians, bow up positive: from the heights at bow and stern.
    pub pitch: f32,
    /// Radians, starboard (right) side up positive: from the heights at
    /// the two sides.
    pub roll: f32,
}

/// The heights of the water under the bow, the stern, the left side and
/// the right side of a boat at `helm`.
pub fn hull_heights(waves: &[Wave], helm: &Helm, time: f32) -> [f32; 4] {
    let ahead = forward(helm.heading);
    let right = Vec2::new(-ahead.y, ahead.x);
    let at = |offset: Vec2| sea::height(waves, helm.position + offset, time);
    [at(ahead * LENGTH / 2.0), at(-ahead * LENGTH / 2.0), at(-right * BEAM / 2.0), at(right * BEAM / 2.0)]
}

/// How a boat at `helm` sits on the waves at `time`: as high as the mean of
/// the four heights, its keel along the line from stern to bow, its deck
/// along the line from side to side.
pub fn float_on(waves: &[Wave], helm: Helm, time: f32) -> Pose {
    let [bow, stern, left, right] = hull_heights(waves, &helm, time);
    Pose {
        helm,
        heave: (bow + stern + left + right) / 4.0,
        pitch: (bow - stern).atan2(LENGTH),
        roll: (right - left).atan2(BEAM),
    }
}

impl Pose {
    /// The boat model's transform: sunk to its draft, rolled, pitched,
    /// turned to its heading, and lifted to the water.
    pub fn model(&self) -> Mat4 {
        let p = self.helm.position;
        Mat4::from_translation(Vec3::new(p.x, self.heave, p.y))
            * Mat4::from_quat(
                Quat::from_rotation_y(self.helm.heading)
                    * Quat::from_rotation_x(self.pitch)
                    * Quat::from_rotation_z(self.roll),
            )
            * Mat4::from_translation(Vec3::new(0.0, -DRAFT, 0.0))
    }
}
// ANCHOR_END: pose

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_course_is_a_circle_sailed_bow_first() {
        for t in [0.0, 10.0, 40.0, 1e6] {
            let helm = on_course(t);
            assert!((helm.position.distance(COURSE_CENTRE) - COURSE_RADIUS).abs() < 1e-2);
            // A second later the boat is 5 m ahead of where it was (a
            // second: at 10⁶ s, f32 cannot tell times closer than 1/16 s).
            let later = on_course(t + 1.0).position - helm.position;
            assert!(later.normalize().dot(forward(helm.heading)) > 0.99, "at {t} s the boat sails sideways");
            assert!((later.length() - COURSE_SPEED).abs() < 0.02, "at {t} s: {} m in a second", later.length());
        }
    }

    #[test]
    fn the_model_puts_the_bow_where_the_heights_were_taken() {
        let helm = Helm { position: Vec2::new(100.0, 200.0), heading: 0.7, speed: 0.0 };
        let pose = Pose { helm, heave: 0.0, pitch: 0.0, roll: 0.0 };
        // The model's bow, at z = −4 on the deck line, lands ahead of the boat.
        let bow = pose.model().transform_point3(Vec3::new(0.0, DRAFT, -LENGTH / 2.0));
        let expected = helm.position + forward(helm.heading) * LENGTH / 2.0;
        assert!(Vec2::new(bow.x, bow.z).distance(expected) < 1e-4);
    }

    #[test]
    fn the_bow_rises_with_the_water_under_it() {
        // A single long wave: the pitch is the slope between bow and stern.
        let waves = [Wave { direction: Vec2::new(0.0, -1.0), amplitude: 1.0, wavelength: 40.0, speed: 0.0 }];
        for x in 0..20 {
            let helm = Helm { position: Vec2::new(0.0, x as f32 * 2.0), heading: 0.0, speed: 0.0 };
            let pose = float_on(&waves, helm, 0.0);
            let [bow, stern, ..] = hull_heights(&waves, &helm, 0.0);
            assert!((pose.pitch.tan() - (bow - stern) / LENGTH).abs() < 1e-5);
            let model = pose.model();
            let bow_point = model.transform_point3(Vec3::new(0.0, DRAFT, -LENGTH / 2.0));
            let stern_point = model.transform_point3(Vec3::new(0.0, DRAFT, LENGTH / 2.0));
            assert!(((bow_point.y - stern_point.y) - (bow - stern)).abs() < 0.05 * (bow - stern).abs() + 1e-4);
            assert!(pose.roll.abs() < 1e-5, "a wave along the keel does not roll the boat");
        }
    }

    #[test]
    fn steering_wraps_onto_the_first_period_and_survives_bad_steps() {
        let mut helm = Helm { position: Vec2::new(4095.0, 1.0), heading: std::f32::consts::FRAC_PI_2, speed: 9.0 };
        // Heading π/2: the bow points towards −x. Sail backwards past 0 …
        helm.heading += std::f32::consts::PI;
        for _ in 0..100 {
            helm.steer(Orders { ahead: true, ..Default::default() }, 0.1);
        }
        assert!(helm.position.x >= 0.0 && helm.position.x < sea::PERIOD_METRES);
        for dt in [f32::NAN, -1.0, f32::INFINITY, 1e9] {
            helm.steer(Orders { ahead: true, left: true, ..Default::default() }, dt);
            assert!(helm.position.is_finite() && helm.heading.is_finite());
        }
    }
}
