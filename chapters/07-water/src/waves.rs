//! Geometric waves: a sum of directional sine waves, with normals worked
//! out analytically. The vertex shader evaluates the same sums (water.wgsl);
//! this CPU copy is what the tests check.

use std::f32::consts::TAU;

use common::glam::{Vec2, Vec3};

/// Surface gravity on Mars, m/s². Waves there are slower than on Earth.
pub const MARS_GRAVITY: f32 = 3.71;

// ANCHOR: wave
/// One train of waves crossing the lake.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    /// Unit vector along which the crests travel (in the xz plane).
    pub direction: Vec2,
    /// Crest height above the mean level, metres.
    pub amplitude: f32,
    /// Crest to crest, metres.
    pub wavelength: f32,
    /// How fast the crests move, m/s.
    pub speed: f32,
}

impl Wave {
    /// A deep-water wave: its speed follows from its wavelength,
    /// c = √(g λ / 2π), so longer waves outrun short ones.
    pub fn deep_water(direction: Vec2, amplitude: f32, wavelength: f32) -> Self {
        Self {
            direction: direction.normalize(),
            amplitude,
            wavelength,
            speed: (MARS_GRAVITY * wavelength / TAU).sqrt(),
        }
    }

    /// The wave's phase at point p and time t: k (d · p − c t), with k = 2π/λ.
    fn phase(&self, p: Vec2, time: f32) -> f32 {
        TAU / self.wavelength * (self.direction.dot(p) - self.speed * time)
    }
}

/// Height of the water above its mean level at (x, z) and time t:
/// h = Σ Aᵢ sin(phaseᵢ).
pub fn height(waves: &[Wave], x: f32, z: f32, time: f32) -> f32 {
    waves.iter().map(|w| w.amplitude * w.phase(Vec2::new(x, z), time).sin()).sum()
}

/// The surface normal, from the derivatives of the sum: for each wave,
/// ∂h/∂x = A k dₓ cos(phase) and ∂h/∂z = A k d_z cos(phase); the normal is
/// (−∂h/∂x, 1, −∂h/∂z), normalised.
pub fn normal(waves: &[Wave], x: f32, z: f32, time: f32) -> Vec3 {
    let mut slope = Vec2::ZERO;
    for w in waves {
        let k = TAU / w.wavelength;
        slope += w.amplitude * k * w.phase(Vec2::new(x, z), time).cos() * w.direction;
    }
    Vec3::new(-slope.x, 1.0, -slope.y).normalize()
}
// ANCHOR_END: wave

// ANCHOR: lake_waves
/// The lake's eight wave trains: wind from the south-west, directions
/// spread by ±40°, wavelengths from 24 m down to 6 m, each with the same
/// gentle steepness (amplitude over wavelength) of 1/160, which keeps every
/// slope of their sum under 25°. (A sum of sines can be steep but never
/// folds over; folding belongs to Gerstner waves, which move points
/// sideways, and there steepness is what limits it.)
pub fn lake_waves() -> [Wave; 8] {
    let wavelengths = [24.0, 17.0, 13.0, 11.0, 9.0, 8.0, 7.0, 6.3];
    let spread = [0.0, -0.5, 0.45, -0.25, 0.7, 0.2, -0.7, 0.35];
    std::array::from_fn(|i| {
        let angle: f32 = 0.6 + spread[i];
        Wave::deep_water(Vec2::new(angle.cos(), -angle.sin()), wavelengths[i] / 160.0, wavelengths[i])
    })
}
// ANCHOR_END: lake_waves

#[cfg(test)]
mod tests {
    use super::*;

    /// The analytic normal agrees with the normal of the surface measured
    /// by finite differences of `height`, everywhere and at any time.
    #[test]
    fn analytic_normals_match_finite_differences() {
        let waves = lake_waves();
        let e = 0.01;
        for i in 0..200 {
            let (x, z, t) = (i as f32 * 1.37 - 90.0, i as f32 * 0.91 - 40.0, i as f32 * 0.13);
            let dx = (height(&waves, x + e, z, t) - height(&waves, x - e, z, t)) / (2.0 * e);
            let dz = (height(&waves, x, z + e, t) - height(&waves, x, z - e, t)) / (2.0 * e);
            let measured = Vec3::new(-dx, 1.0, -dz).normalize();
            let analytic = normal(&waves, x, z, t);
            assert!(
                analytic.angle_between(measured).to_degrees() < 0.1,
                "at ({x}, {z}, {t}): {analytic} vs {measured}"
            );
        }
    }

    #[test]
    fn waves_travel_along_their_direction_at_their_speed() {
        let wave = Wave::deep_water(Vec2::X, 0.5, 10.0);
        // Deep water on Mars: c = √(3.71 · 10 / 2π) ≈ 2.43 m/s.
        assert!((wave.speed - 2.43).abs() < 0.01);
        // The crest at x moves to x + c t after t seconds.
        let (x, t) = (3.0, 4.0);
        let waves = [wave];
        assert!((height(&waves, x, 0.0, 0.0) - height(&waves, x + wave.speed * t, 0.0, t)).abs() < 1e-4);
        // And nothing changes across it.
        assert!((height(&waves, x, 0.0, 0.0) - height(&waves, x, 7.0, 0.0)).abs() < 1e-6);
    }

    #[test]
    fn the_lake_is_gentle() {
        let waves = lake_waves();
        let highest: f32 = waves.iter().map(|w| w.amplitude).sum();
        assert!(highest < 0.6, "crests at most {highest} m");
        for i in 0..100 {
            assert!(normal(&waves, i as f32 * 3.1, i as f32 * 1.7, 2.0).y > 0.9, "no slope steeper than about 25°");
        }
    }
}
