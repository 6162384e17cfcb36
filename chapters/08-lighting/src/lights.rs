//! Lights: the sun by time of day, point lights with inverse-square falloff
//! in a smooth range window, and spot lights with an inner and outer cone.
//! The shader (`lights.wgsl`) evaluates the same formulas; these copies are
//! what the tests check, and what the CPU culling relies on.

use common::glam::Vec3;

// ANCHOR: falloff
/// How much of a light's intensity reaches `distance` metres away.
///
/// Inverse-square, as light spreads over a sphere's area, with 1 added
/// below the line so that a point right at the light is not infinitely
/// bright, times a window that takes it smoothly to exactly zero at `range`
/// (Karis 2013). The exact zero is what makes culling safe: a light can
/// only be skipped where it would add nothing.
pub fn attenuation(distance: f32, range: f32) -> f32 {
    let ratio = distance / range;
    let window = (1.0 - ratio.powi(4)).clamp(0.0, 1.0).powi(2);
    window / (distance * distance + 1.0)
}

/// How much of a spot light reaches a direction at `cos_angle` from its
/// axis: all of it inside the inner cone, none outside the outer cone, and
/// a smooth step between.
pub fn spot_factor(cos_angle: f32, cos_inner: f32, cos_outer: f32) -> f32 {
    smoothstep(cos_outer, cos_inner, cos_angle)
}
// ANCHOR_END: falloff

pub fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let t = ((x - edge0) / (edge1 - edge0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

// ANCHOR: light
/// A light in the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub position: Vec3,
    /// Linear RGB, times the intensity: what arrives at 1 m is about half this.
    pub colour: Vec3,
    /// Beyond this many metres the light adds nothing at all.
    pub range: f32,
    pub kind: LightKind,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    Point,
    /// Shines along `direction`, full within `inner` radians of it and
    /// fading out by `outer`.
    Spot {
        direction: Vec3,
        inner: f32,
        outer: f32,
    },
}

/// `Light` in lights.wgsl: 64 bytes, the same for point and spot lights
/// (a point light has cos_inner = −2 and cos_outer = −3, below any cosine,
/// so that its cone lets everything through).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuLight {
    pub position: [f32; 3],
    pub range: f32,
    pub colour: [f32; 3],
    pub cos_inner: f32,
    pub direction: [f32; 3],
    pub cos_outer: f32,
    pub _padding: [f32; 4],
}
// ANCHOR_END: light

impl Light {
    pub fn to_gpu(&self) -> GpuLight {
        let (direction, cos_inner, cos_outer) = match self.kind {
            LightKind::Point => (Vec3::NEG_Y, -2.0, -3.0),
            LightKind::Spot { direction, inner, outer } => (direction.normalize(), inner.cos(), outer.cos()),
        };
        GpuLight {
            position: self.position.into(),
            range: self.range,
            colour: self.colour.into(),
            cos_inner,
            direction: direction.into(),
            cos_outer,
            _padding: [0.0; 4],
        }
    }

    /// What this light adds at `point`, before the surface's own response:
    /// colour × falloff × cone.
    pub fn reaching(&self, point: Vec3) -> Vec3 {
        let to_point = point - self.position;
        let distance = to_point.length();
        let cone = match self.kind {
            LightKind::Point => 1.0,
            LightKind::Spot { direction, inner, outer } => {
                spot_factor(direction.normalize().dot(to_point / distance.max(1e-6)), inner.cos(), outer.cos())
            }
        };
        self.colour * attenuation(distance, self.range) * cone
    }
}

// ANCHOR: sun
/// The time of day the overlay's presets name, and auto, which runs it
/// with scene time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeOfDay {
    Morning,
    Noon,
    Evening,
    Night,
    Auto,
}

impl TimeOfDay {
    pub const ALL: [TimeOfDay; 5] =
        [TimeOfDay::Morning, TimeOfDay::Noon, TimeOfDay::Evening, TimeOfDay::Night, TimeOfDay::Auto];

    /// The phase of the day (0 midnight, 0.25 sunrise, 0.5 noon, 0.75
    /// sunset) at scene time `time`, for a day `day_seconds` long.
    pub fn phase(self, time: f32, day_seconds: f32) -> f32 {
        match self {
            TimeOfDay::Morning => 0.31,
            TimeOfDay::Noon => 0.5,
            TimeOfDay::Evening => 0.715,
            TimeOfDay::Night => 0.0,
            TimeOfDay::Auto => (0.3 + time / day_seconds).rem_euclid(1.0),
        }
    }
}

/// The sun and the sky's light at one moment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Daylight {
    /// Unit vector towards the sun.
    pub direction: Vec3,
    /// The sun's light, linear RGB: white high up, orange near the horizon,
    /// nothing below it.
    pub sun: Vec3,
    /// Light from the whole sky, which reaches every surface a little.
    pub ambient: Vec3,
    /// The sky's colour at the horizon and overhead, for the background.
    pub horizon: Vec3,
    pub zenith: Vec3,
    /// 0 by day, 1 at night: street lamps and glowing windows follow it.
    pub night: f32,
}

/// The sun's path is chapter 06's: rising in the east, over the south.
pub fn daylight(phase: f32) -> Daylight {
    let direction = common::sun::sun_at(phase).direction;
    let height = direction.y;
    let up = smoothstep(-0.04, 0.12, height);
    let white = smoothstep(0.05, 0.45, height);
    let sun = Vec3::new(1.0, 0.42, 0.16).lerp(Vec3::new(1.0, 0.95, 0.88), white) * 2.4 * up;
    let day = smoothstep(-0.12, 0.1, height);
    let dusk = (1.0 - white) * up;
    let ambient =
        Vec3::new(0.010, 0.012, 0.028).lerp(Vec3::new(0.20, 0.24, 0.32), day) + Vec3::new(0.08, 0.03, 0.0) * dusk;
    let horizon =
        Vec3::new(0.012, 0.016, 0.04).lerp(Vec3::new(0.45, 0.58, 0.78), day).lerp(Vec3::new(0.95, 0.45, 0.2), dusk);
    let zenith = Vec3::new(0.002, 0.003, 0.012).lerp(Vec3::new(0.12, 0.28, 0.62), day);
    Daylight { direction, sun, ambient, horizon, zenith, night: 1.0 - smoothstep(-0.05, 0.15, height) }
}
// ANCHOR_END: sun

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attenuation_falls_monotonically_to_exactly_zero_at_the_range() {
        let range = 30.0;
        let mut last = attenuation(0.0, range);
        assert_eq!(last, 1.0);
        for i in 1..=400 {
            let d = i as f32 * 0.1;
            let a = attenuation(d, range);
            assert!(a <= last, "rises at {d} m");
            if d >= range {
                assert!(a < 1.0 / 255.0 && a == 0.0, "{a} at {d} m, beyond the range");
            }
            last = a;
        }
        // Inside, it stays close to the inverse square until the window bites.
        let near = attenuation(3.0, range) * (3.0f32 * 3.0 + 1.0);
        assert!(near > 0.99, "the window takes {near} of the light at a tenth of the range");
    }

    #[test]
    fn spot_lights_are_full_inside_the_inner_cone_and_dark_outside_the_outer() {
        let (inner, outer) = (15f32.to_radians(), 30f32.to_radians());
        let light = Light {
            position: Vec3::ZERO,
            colour: Vec3::ONE,
            range: 100.0,
            kind: LightKind::Spot { direction: Vec3::NEG_Z, inner, outer },
        };
        let at = |degrees: f32| {
            let (s, c) = degrees.to_radians().sin_cos();
            light.reaching(Vec3::new(s, 0.0, -c) * 10.0).x / attenuation(10.0, 100.0)
        };
        for degrees in [0.0, 5.0, 14.9] {
            assert!((at(degrees) - 1.0).abs() < 1e-5, "{} at {degrees}°", at(degrees));
        }
        for degrees in [30.1, 45.0, 90.0, 180.0] {
            assert_eq!(at(degrees), 0.0, "light at {degrees}°");
        }
        assert!(at(20.0) > at(25.0) && at(25.0) > 0.0 && at(20.0) < 1.0, "a smooth fall between the cones");
    }

    #[test]
    fn the_sun_is_white_at_noon_orange_low_and_gone_at_night() {
        let noon = daylight(0.5);
        assert!(noon.sun.x > 2.0 && (noon.sun.z / noon.sun.x) > 0.85 && noon.night == 0.0);
        let evening = daylight(TimeOfDay::Evening.phase(0.0, 1.0));
        assert!(evening.sun.x > 0.0 && evening.sun.z < 0.5 * evening.sun.x, "{:?}", evening.sun);
        let night = daylight(0.0);
        assert_eq!(night.sun, Vec3::ZERO);
        assert_eq!(night.night, 1.0);
        assert!(night.ambient.length() < 0.05);
    }
}
