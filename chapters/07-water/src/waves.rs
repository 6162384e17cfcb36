//! Geometric waves: a sum of directional sine waves, with normals worked
//! out analytically, and the lake's eight as a set the overlay edits one by
//! one, with the overlay's controls for it. The vertex shader evaluates the
//! same sums (water.wgsl); this CPU copy is what the tests check.

use std::f32::consts::TAU;

use common::egui;
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

// ANCHOR: wave_set
/// The eight waves a lake moves by: the lake's own ([`lake_waves`]) until
/// one is edited. A view chooses `Lake`, so choosing a view puts back the
/// lake's own waves exactly, whatever was edited before.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WaveSet {
    /// [`lake_waves`], unchanged.
    Lake,
    /// The lake's waves as the overlay left them.
    Edited([Wave; 8]),
}

impl WaveSet {
    /// The waves themselves.
    pub fn waves(&self) -> [Wave; 8] {
        match self {
            Self::Lake => lake_waves(),
            Self::Edited(waves) => *waves,
        }
    }

    /// Replaces wave `index` with `wave`. A wave the shader cannot draw
    /// (no such index, a wavelength that is not positive, a direction
    /// that is not a unit vector, anything not finite) is refused with
    /// the reason, and nothing changes.
    pub fn set(&mut self, index: usize, wave: Wave) -> Result<(), String> {
        let mut waves = self.waves();
        let Some(slot) = waves.get_mut(index) else {
            return Err(format!("there is no wave {index}: the lake has waves 0 to 7"));
        };
        let numbers = [wave.direction.x, wave.direction.y, wave.amplitude, wave.wavelength, wave.speed];
        if numbers.iter().any(|n| !n.is_finite()) {
            return Err(format!("wave {index}: every number must be finite, not {wave:?}"));
        }
        if wave.wavelength <= 0.0 {
            return Err(format!("wave {index}: the wavelength must be positive, not {} m", wave.wavelength));
        }
        if (wave.direction.length() - 1.0).abs() > 1e-3 {
            return Err(format!("wave {index}: the direction must be a unit vector, not {}", wave.direction));
        }
        *slot = wave;
        *self = Self::Edited(waves);
        Ok(())
    }
}

impl Wave {
    /// The direction the crests travel, in degrees from +x (east) towards
    /// −z (north): how the overlay shows it.
    pub fn heading_degrees(&self) -> f32 {
        (-self.direction.y).atan2(self.direction.x).to_degrees()
    }

    /// The same wave travelling towards `degrees` (as [`Wave::heading_degrees`]).
    pub fn heading(self, degrees: f32) -> Self {
        let (sin, cos) = degrees.to_radians().sin_cos();
        Self { direction: Vec2::new(cos, -sin), ..self }
    }
}
// ANCHOR_END: wave_set

// ANCHOR: edit_waves
/// The overlay's controls for each of the eight waves, and a button that
/// puts back the lake's own. An edit goes through [`WaveSet::set`], which
/// refuses a wave the shader cannot draw (the sliders' ranges keep to
/// what it can); the view chosen next puts the lake's waves back.
pub fn edit_waves(ui: &mut egui::Ui, waves: &mut WaveSet) {
    for (index, wave) in waves.waves().into_iter().enumerate() {
        egui::CollapsingHeader::new(format!("wave {}", index + 1)).show(ui, |ui| {
            let mut edited = wave;
            let mut heading = wave.heading_degrees();
            let mut changed =
                ui.add(egui::Slider::new(&mut edited.amplitude, 0.0..=1.0).text("amplitude (m)")).changed();
            changed |= ui
                .add(egui::Slider::new(&mut edited.wavelength, 1.0..=100.0).logarithmic(true).text("wavelength (m)"))
                .changed();
            changed |= ui.add(egui::Slider::new(&mut edited.speed, 0.0..=12.0).text("speed (m/s)")).changed();
            if ui.add(egui::Slider::new(&mut heading, -180.0..=180.0).text("heading (° from east to north)")).changed()
            {
                edited = edited.heading(heading);
                changed = true;
            }
            if changed && let Err(reason) = waves.set(index, edited) {
                ui.colored_label(egui::Color32::RED, reason);
            }
        });
    }
    if ui.add_enabled(*waves != WaveSet::Lake, egui::Button::new("reset the waves")).clicked() {
        *waves = WaveSet::Lake;
    }
}
// ANCHOR_END: edit_waves

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

    /// What the overlay does to a wave, through the same settings: an
    /// edit moves the surface the CPU computes, and choosing a view
    /// (`WaveSet::Lake`) puts back the lake's own waves, bit for bit.
    #[test]
    fn editing_a_wave_moves_the_surface_and_reset_restores_it_exactly() {
        let points: Vec<(f32, f32, f32)> =
            (0..50).map(|i| (i as f32 * 2.3 - 40.0, i as f32 * 1.1 - 20.0, i as f32 * 0.2)).collect();
        let heights =
            |set: &WaveSet| -> Vec<f32> { points.iter().map(|&(x, z, t)| height(&set.waves(), x, z, t)).collect() };
        let mut set = WaveSet::Lake;
        let before = heights(&set);
        for (index, edit) in [
            (0, Wave { amplitude: 0.4, ..lake_waves()[0] }),
            (3, Wave { wavelength: 30.0, ..lake_waves()[3] }),
            (5, Wave { speed: 0.0, ..lake_waves()[5] }),
            (7, lake_waves()[7].heading(-120.0)),
        ] {
            let mut edited = WaveSet::Lake;
            edited.set(index, edit).unwrap();
            assert_eq!(edited.waves()[index], edit);
            assert_eq!(edited.waves().iter().filter(|w| lake_waves().contains(w)).count(), 7, "one wave changed");
            let after = heights(&edited);
            let moved = before.iter().zip(&after).filter(|(a, b)| (*a - *b).abs() > 1e-4).count();
            assert!(moved > 30, "editing wave {index} moved {moved} of 50 points");
            set.set(index, edit).unwrap();
        }
        assert_ne!(heights(&set), before);
        set = WaveSet::Lake;
        assert_eq!(set.waves(), lake_waves());
        let restored = heights(&set);
        assert!(restored.iter().zip(&before).all(|(a, b)| a.to_bits() == b.to_bits()), "reset is exact");
    }

    #[test]
    fn a_wave_the_shader_cannot_draw_is_refused() {
        let mut set = WaveSet::Lake;
        let wave = lake_waves()[2];
        let refused = [
            (8, wave),
            (2, Wave { wavelength: 0.0, ..wave }),
            (2, Wave { amplitude: f32::NAN, ..wave }),
            (2, Wave { direction: Vec2::new(3.0, 0.0), ..wave }),
        ];
        for (index, bad) in refused {
            let error = set.set(index, bad).unwrap_err();
            assert!(error.contains("wave"), "{error}");
        }
        assert_eq!(set, WaveSet::Lake, "nothing changed");
    }

    #[test]
    fn heading_round_trips() {
        for wave in lake_waves() {
            let turned = wave.heading(wave.heading_degrees());
            assert!(turned.direction.distance(wave.direction) < 1e-5);
        }
        let north = Wave::deep_water(Vec2::X, 0.1, 10.0).heading(90.0);
        assert!(north.direction.distance(Vec2::new(0.0, -1.0)) < 1e-6);
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
