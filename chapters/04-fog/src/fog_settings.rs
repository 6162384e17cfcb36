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
