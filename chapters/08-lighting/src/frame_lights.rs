//! Which lights shine in a frame: the moving ones (headlights, tail
//! lights, drones), then the still ones (street lamps and lit buildings),
//! which come on as night falls; and, for the bench's larger counts,
//! beacons scattered over the city.

use common::glam::Vec3;

use crate::city::{City, Traffic};
use crate::lights::{self, Light};
use crate::scene_lights::MAX_LIGHTS;

/// How many lights shine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightCount {
    /// The city's own: lamps, buildings, cars and drones.
    City,
    /// The first n of the city's lights and then of extra beacons: the bench's counts.
    First(u32),
}

// ANCHOR: frame_lights
/// The lights of this frame: the moving ones (cars, drones), then the
/// still ones (street lamps and lit buildings, which come on as night falls,
/// `night` from 0 by day to 1), then beacons, up to the view's count. A
/// light that is off is not in the list at all: it would cost the loop
/// without adding anything.
pub fn frame_lights(city: &City, traffic: &Traffic, beacons: &[Light], count: LightCount, night: f32) -> Vec<Light> {
    let dimmed = |light: &Light| Light { colour: light.colour * night, ..*light };
    let fixed = city.fixed_lights.iter().filter(|_| night > 0.0).map(dimmed);
    let all = traffic.lights.iter().copied().chain(fixed);
    match count {
        LightCount::City => all.collect(),
        LightCount::First(n) => all.chain(beacons.iter().copied()).take(n.min(MAX_LIGHTS) as usize).collect(),
    }
}
// ANCHOR_END: frame_lights

/// Small coloured lights scattered over the city: not part of its design,
/// there to fill the bench's larger light counts.
pub fn beacons(count: usize) -> Vec<Light> {
    let mut rng = common::rng::Rng::new(21);
    (0..count)
        .map(|_| {
            let hue = rng.unit();
            Light {
                position: Vec3::new(rng.range(-170.0, 170.0), rng.range(1.0, 50.0), rng.range(-170.0, 170.0)),
                colour: Vec3::new(0.3 + 0.7 * hue, 0.5, 1.0 - 0.6 * hue) * rng.range(20.0, 60.0),
                range: rng.range(6.0, 22.0),
                kind: lights::LightKind::Point,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenery::billboard;

    /// The page's count: the city's 339 lights and the billboard's 3 spots.
    #[test]
    fn the_night_has_342_lights_with_the_billboards_spots() {
        let city = City::new();
        let traffic = city.traffic(6.0, 6.0);
        let lights = frame_lights(&city, &traffic, &[], LightCount::City, 1.0);
        assert_eq!(lights.len() + billboard().lights(1.0).len(), 342);
    }
}
