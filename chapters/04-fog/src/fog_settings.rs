//! The two numbers of exponential fog, and what follows from them: how
//! much of a surface shows through at a distance, where the fog becomes
//! opaque, and so where the far plane can come in.

// ANCHOR: settings
/// The two numbers of exponential fog: visibility = exp(−(distance · density)^gradient).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogSettings {
    /// Per metre.
    pub density: f32,
    pub gradient: f32,
}

impl FogSettings {
    pub const HAZE: Self = Self { density: 0.0015, gradient: 1.5 };
    pub const NONE: Self = Self { density: 0.0, gradient: 1.5 };
    pub const DUST_STORM: Self = Self { density: 0.004, gradient: 2.0 };

    /// How much of a surface at `distance` metres shows through.
    pub fn visibility(&self, distance: f32) -> f32 {
        (-(distance * self.density).powf(self.gradient)).exp()
    }

    /// The distance beyond which less than 1/255 of a surface shows, so
    /// that an 8-bit picture cannot tell it from the sky: solve
    /// (d · density)^gradient = ln 255 for d.
    pub fn opaque_distance(&self) -> f32 {
        if self.density <= 0.0 { f32::INFINITY } else { 255f32.ln().powf(1.0 / self.gradient) / self.density }
    }

    /// Where to put the camera's far plane in this fog: nothing beyond the
    /// opaque distance can be seen, so nothing there needs drawing.
    pub fn far_plane(&self) -> f32 {
        self.opaque_distance().min(MAX_FAR)
    }
}
// ANCHOR_END: settings

/// The farthest the camera ever draws, fog or not.
pub const MAX_FAR: f32 = 3000.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visibility_falls_from_one_to_nothing() {
        let fog = FogSettings::HAZE;
        assert_eq!(fog.visibility(0.0), 1.0);
        assert!(fog.visibility(100.0) > fog.visibility(1000.0));
        // At 1/density metres the exponent is 1 whatever the gradient: e⁻¹.
        let one_over_e = fog.visibility(1.0 / fog.density);
        assert!((one_over_e - (-1f32).exp()).abs() < 1e-6);
        assert_eq!(FogSettings::NONE.visibility(1e6), 1.0);
    }

    #[test]
    fn the_opaque_distance_is_where_one_255th_is_left() {
        for fog in [FogSettings::HAZE, FogSettings::DUST_STORM] {
            let d = fog.opaque_distance();
            assert!((fog.visibility(d) - 1.0 / 255.0).abs() < 1e-5, "{fog:?}");
        }
        assert!(FogSettings::NONE.opaque_distance().is_infinite());
        assert!((FogSettings::DUST_STORM.opaque_distance() - 588.0).abs() < 1.0);
    }
}
