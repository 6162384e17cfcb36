//! The sun's path through the day (chapter 06 teaches it; chapters 07,
//! 08 and 10 light their scenes with it): the turn of the sky at a time of day,
//! the sun it carries (the light the ground is lit by), and how much of the
//! day sky shows.

use std::f32::consts::TAU;

use glam::{Quat, Vec3};

/// The light: a direction towards the sun, and how strong it is (1 by day,
/// 0 when it is below the horizon). Chapter 03 lights its terrain with a
/// fixed one; chapter 06 moves it with the sky.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sun {
    pub direction: Vec3,
    pub strength: f32,
}

impl Sun {
    /// Low in the south-east, so slopes show as light and shade.
    pub const AFTERNOON: Self = Self { direction: Vec3::new(0.75, 0.35, 0.35), strength: 1.0 };
}

// ANCHOR: sun_path
/// Where the sun rises: on the eastern horizon (+x), a little south (+z).
pub const SUNRISE: Vec3 = Vec3::new(0.957_826_3, 0.0, 0.287_347_9); // normalize(1, 0, 0.3)

/// The turn of the sky, sun and stars, at a time of day (`phase`: 0
/// midnight, 0.25 sunrise, 0.5 noon, 0.75 sunset): about the z (north–south)
/// axis, which carries the sun from the eastern horizon up over the southern
/// sky and down in the west (−x).
pub fn celestial_turn(phase: f32) -> Quat {
    Quat::from_rotation_z(TAU * (phase - 0.25))
}

/// The light at a time of day: the sun, turned with the sky, fading out as
/// it sinks below the horizon. The sky shader draws the sun in this very
/// direction, so what lights the ground is what the sky shows.
pub fn sun_at(phase: f32) -> Sun {
    let direction = celestial_turn(phase) * SUNRISE;
    Sun { direction, strength: smoothstep(-0.05, 0.15, direction.y) }
}

/// How much of the day sky shows, from the sun's height.
pub fn day_blend(sun: Sun) -> f32 {
    smoothstep(-0.15, 0.1, sun.direction.y)
}
// ANCHOR_END: sun_path

fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let t = ((x - edge0) / (edge1 - edge0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sun_rises_in_the_east_peaks_at_noon_and_sets_in_the_west() {
        let at = |phase| sun_at(phase).direction;
        assert!(at(0.25).y.abs() < 1e-5 && at(0.25).x > 0.9, "sunrise in the east");
        assert!(at(0.5).y > 0.95, "noon overhead");
        assert!(at(0.75).y.abs() < 1e-5 && at(0.75).x < -0.9, "sunset in the west");
        assert!(at(0.0).y < -0.9, "midnight below");
        assert_eq!(sun_at(0.5).strength, 1.0);
        assert_eq!(sun_at(0.0).strength, 0.0);
        assert_eq!(day_blend(sun_at(0.5)), 1.0);
        assert_eq!(day_blend(sun_at(0.0)), 0.0);
    }
}
