//! Cascaded shadow maps: the view cut by distance into slices, each slice
//! shadowed by a map of its own, so that the texels near the eye are a few
//! centimetres and the ones a kilometre away a few metres, and no map is
//! spent on ground the camera does not see. The slices are cut by the
//! practical split scheme of parallel-split shadow maps (Zhang et al.
//! 2006); each slice's box is fitted to a sphere around it and moved in
//! whole texels, which keeps its shadows still while the camera moves and
//! turns (Valient 2008).

use common::Camera;
use common::glam::Vec3;

use crate::light_box::{LightBox, fit_sphere};

/// The most cascades a view may have: one texture array layer each.
pub const MAX_CASCADES: usize = 4;

// ANCHOR: splits
/// Where the view between `near` and `far` is cut into `count` slices:
/// `count + 1` distances along the view axis, from `near` to `far`. Each
/// is a blend, by `lambda`, of two cuts: the logarithmic one, whose slices
/// all span the same ratio of distances (what a perspective view needs for
/// texels that cover the same number of pixels everywhere), and the
/// uniform one, whose slices span the same metres (the logarithmic cut
/// alone gives the nearest slice almost nothing). Zhang et al. 2006's
/// practical split scheme: `lambda` 1 is the logarithmic cut, 0 the
/// uniform one.
pub fn practical_splits(near: f32, far: f32, count: usize, lambda: f32) -> Vec<f32> {
    (0..=count)
        .map(|i| {
            let fraction = i as f32 / count as f32;
            let logarithmic = near * (far / near).powf(fraction);
            let uniform = near + (far - near) * fraction;
            lambda * logarithmic + (1.0 - lambda) * uniform
        })
        .collect()
}

/// The cascade that shadows a point `depth` metres in front of the camera
/// (along its axis): the slice whose near cut is at or before it and whose
/// far cut is after it. `None` before the first cut and from the last on.
pub fn cascade_of(depth: f32, splits: &[f32]) -> Option<usize> {
    splits.windows(2).position(|cut| (cut[0]..cut[1]).contains(&depth))
}
// ANCHOR_END: splits

// ANCHOR: sphere
/// The smallest sphere around the slice of a view from `near` to `far`
/// metres along its axis, as (how far along the axis its centre is, its
/// radius). It depends on the slice, the field of view and the aspect
/// only, never on where the camera looks: turning the camera moves the
/// sphere but never changes its size, so a texel of the slice's map always
/// covers the same ground.
///
/// A corner of the slice at distance `d` is `d·k` from the axis, with
/// `k² = tan²(fov_y/2)·(1 + aspect²)`. A centre at `c` as far from the near
/// corners as from the far ones solves `(c − near)² + near²k² = (far − c)² +
/// far²k²`: `c = (near + far)(1 + k²)/2`. Past `far` (a wide, shallow
/// slice), the far corners' own circle is the smallest sphere: `c = far`.
pub fn slice_sphere(near: f32, far: f32, fov_y: f32, aspect: f32) -> (f32, f32) {
    let tan = (fov_y / 2.0).tan();
    let k2 = tan * tan * (1.0 + aspect * aspect);
    let along = ((near + far) * (1.0 + k2) / 2.0).min(far);
    let radius = ((far - along).powi(2) + far * far * k2).sqrt();
    (along, radius)
}
// ANCHOR_END: sphere

// ANCHOR: fit
/// One cascade: its slice of the view and the sun's box that shadows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cascade {
    /// Metres along the view axis where the slice starts and ends.
    pub near: f32,
    pub far: f32,
    pub light: LightBox,
}

/// The cascades of `camera`'s view cut at `splits`, for maps of `size`
/// texels: each slice's sphere, a box around it moved in whole texels
/// ([`fit_sphere`]), as deep as every caster in `caster_bounds`.
pub fn fit_cascades(
    camera: &Camera,
    towards_sun: Vec3,
    caster_bounds: (Vec3, Vec3),
    size: u32,
    splits: &[f32],
) -> Vec<Cascade> {
    splits
        .windows(2)
        .map(|cut| {
            let (near, far) = (cut[0], cut[1]);
            let (along, radius) = slice_sphere(near, far, camera.fov_y, camera.aspect);
            let centre = camera.position + camera.forward() * along;
            let corners = slice_corners(camera, near, far);
            Cascade { near, far, light: fit_sphere(towards_sun, (centre, radius), &corners, caster_bounds, size) }
        })
        .collect()
}
// ANCHOR_END: fit

/// The eight corners of the slice of `camera`'s view from `near` to `far`
/// metres along its axis: near ones first.
pub fn slice_corners(camera: &Camera, near: f32, far: f32) -> [Vec3; 8] {
    let (forward, right) = (camera.forward(), camera.right());
    let up = right.cross(forward);
    let tan_y = (camera.fov_y / 2.0).tan();
    let tan_x = tan_y * camera.aspect;
    std::array::from_fn(|i| {
        let d = if i & 4 == 0 { near } else { far };
        let x = if i & 1 == 0 { -tan_x } else { tan_x };
        let y = if i & 2 == 0 { -tan_y } else { tan_y };
        camera.position + (forward + right * x + up * y) * d
    })
}
