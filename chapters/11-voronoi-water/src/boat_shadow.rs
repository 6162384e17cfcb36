//! The boat's shadow: chapter 10's `fit_light` fits the sun's box to
//! whatever points it is given, so the chapter gives it only the boat (its
//! sail and sailor inside the same box) and where its shadow can fall on
//! the water. The whole shadow map then goes to one small boat.

use common::glam::Vec3;
use water::waves::Wave;

use crate::boat::{self, Pose};

/// How far along the sun's rays a shadow is followed, metres: a low sun's
/// shadows run long, and beyond this they are lost in the glare.
pub const SHADOW_REACH: f32 = 40.0;

// ANCHOR: shadow_focus
/// What the sun's box must hold for a boat at `pose` on `waves`, with the
/// light coming from `towards_light`: the boat's corners (the first eight
/// points), and where their shadows can fall on the lowest water, at most
/// [`SHADOW_REACH`] away; and the corners' bounds.
pub fn shadow_focus(pose: &Pose, waves: &[Wave], towards_light: Vec3) -> (Vec<Vec3>, (Vec3, Vec3)) {
    let model = pose.model();
    let corners: Vec<Vec3> = (0..8)
        .map(|i| {
            let x = if i & 1 == 0 { -boat::BEAM / 2.0 } else { boat::BEAM / 2.0 };
            let y = if i & 2 == 0 { 0.0 } else { boat::MAST_TOP };
            let z = if i & 4 == 0 { -boat::LENGTH / 2.0 } else { boat::LENGTH / 2.0 };
            model.transform_point3(Vec3::new(x, y, z))
        })
        .collect();
    let bounds = corners.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    // The lowest the water goes: every wave in a trough at once.
    let lowest = -waves.iter().map(|w| w.amplitude).sum::<f32>();
    let mut focus = corners.clone();
    for c in &corners {
        let run = ((c.y - lowest) / towards_light.y.max(1e-3)).min(SHADOW_REACH);
        focus.push(*c - towards_light * run);
    }
    (focus, bounds)
}
// ANCHOR_END: shadow_focus
