//! The three terms of light a surface reflects, one at a time: the sky's
//! even light (ambient), Lambert's light from the sun and the lamps
//! (diffuse), and the highlights (specular). The loop in `lights.wgsl`
//! adds them up; the `ambient`, `diffuse` and `specular` views show each
//! alone by zeroing the inputs of the other two, with no branch in any
//! shader.

use common::glam::Vec3;

use crate::city_meshes::GpuMaterial;
use crate::lights::{Daylight, Light};

// ANCHOR: terms
/// The three terms `light_surface` in lights.wgsl adds up for a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightTerm {
    /// albedo × the sky's light: the same whichever way the surface faces.
    Ambient,
    /// albedo × radiance × n · l, from the sun and every light: Lambert's.
    Diffuse,
    /// specular × the highlight's lobe × radiance × n · l: the highlights.
    Specular,
}

impl LightTerm {
    /// Switches off the glow and the inputs of the other two terms. The
    /// shader adds up three products: zeroing the sun and the lamps leaves
    /// the ambient term; zeroing the sky's light and the specular strength
    /// leaves the diffuse; zeroing the sky's light and the albedo leaves the
    /// highlights. Exactly one term is drawn, with no branch in any shader.
    pub fn isolate(self, day: &mut Daylight, lights: &mut Vec<Light>, materials: &mut [GpuMaterial]) {
        for material in materials.iter_mut() {
            material.emissive = [0.0; 3];
            match self {
                Self::Ambient => {}
                Self::Diffuse => material.specular = 0.0,
                Self::Specular => (material.albedo, material.albedo_high) = ([0.0; 3], [0.0; 3]),
            }
        }
        match self {
            // No light arrives from a direction: no diffuse light, no highlight.
            Self::Ambient => {
                day.sun = Vec3::ZERO;
                lights.clear();
            }
            // The sky's light: the ambient colour, and for Cook-Torrance the
            // sky itself (these views do not draw it).
            Self::Diffuse | Self::Specular => {
                (day.ambient, day.horizon, day.zenith) = (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)
            }
        }
    }
}
// ANCHOR_END: terms
