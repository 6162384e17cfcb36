//! The sun's box: the orthographic volume the shadow map covers. Fitted to
//! the part of the level the camera sees (`visible_part`), as deep as every
//! caster between that part and the sun, and kept from shimmering: its
//! width never changes while the camera slides, and it moves in whole
//! texels of the map.

use common::Camera;
use common::glam::{Mat4, Vec3};

// ANCHOR: visible
/// The part of the level the camera sees: where the corners of its view
/// cross the level's front and back faces (z = ±`half_depth`). The sun's
/// box is fitted around these eight points.
pub fn visible_part(camera: &Camera, half_depth: f32) -> [Vec3; 8] {
    let inverse = camera.view_projection().inverse();
    std::array::from_fn(|i| {
        let ndc = Vec3::new(if i & 1 == 0 { -1.0 } else { 1.0 }, if i & 2 == 0 { -1.0 } else { 1.0 }, 1.0);
        let far = inverse.project_point3(ndc);
        let z = if i & 4 == 0 { half_depth } else { -half_depth };
        let t = (z - camera.position.z) / (far.z - camera.position.z);
        camera.position + (far - camera.position) * t
    })
}
// ANCHOR_END: visible

// ANCHOR: fit
/// The sun's orthographic box: where it looks from, what it covers, and
/// what one texel of the map covers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightBox {
    /// World to the light's clip space.
    pub view_proj: Mat4,
    /// Metres one texel covers, across the box.
    pub texel: f32,
    /// Metres from the box's near face to its far face.
    pub depth: f32,
}

/// Fits the sun's box for a map of `size` texels: its sides around the
/// `focus` points (the part of the level the camera sees), its depth over
/// every caster in `caster_bounds` (something off screen can still throw
/// a shadow into view). `towards_sun` is a unit vector.
///
/// Two things keep shadows from shimmering as the camera moves. The box's
/// width is that of a sphere around the focus points, rounded up to half
/// a metre: when the camera only slides, the width never changes, so a
/// texel always covers the same ground. And the box moves only in whole
/// texels, so every texel edge stays where it was on the ground.
pub fn fit_light(towards_sun: Vec3, focus: &[Vec3], caster_bounds: (Vec3, Vec3), size: u32) -> LightBox {
    let (low, high) = focus.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let centre = (low + high) / 2.0;
    let reach = focus.iter().map(|p| p.distance(centre)).fold(0.0, f32::max);
    let radius = (reach * 2.0).ceil() / 2.0;
    fit_sphere(towards_sun, (centre, radius), focus, caster_bounds, size)
}

/// The sun's box around a sphere (`centre`, `radius`) for a map of `size`
/// texels: as wide as the sphere, moved only in whole texels, and as deep
/// as every caster in `caster_bounds` and every point in `receivers`
/// (what the box must shade). [`fit_light`] puts a sphere around what the
/// camera sees; each cascade of [`crate::cascades`] puts one around its
/// slice of the view.
pub fn fit_sphere(
    towards_sun: Vec3,
    (centre, radius): (Vec3, f32),
    receivers: &[Vec3],
    caster_bounds: (Vec3, Vec3),
    size: u32,
) -> LightBox {
    let up = if towards_sun.y.abs() > 0.99 { Vec3::Z } else { Vec3::Y };
    // A rotation only: light space is world space turned to face the sun.
    let rotation = Mat4::look_to_rh(Vec3::ZERO, -towards_sun, up);
    let texel = 2.0 * radius / size as f32;
    let middle = rotation.transform_point3(centre);
    let snap = |v: f32| (v / texel).round() * texel;
    let (x, y) = (snap(middle.x), snap(middle.y));
    // Depth: from the caster nearest the sun to the point farthest from it.
    let (cl, ch) = caster_bounds;
    let corners = (0..8).map(|i| {
        Vec3::new(
            if i & 1 == 0 { cl.x } else { ch.x },
            if i & 2 == 0 { cl.y } else { ch.y },
            if i & 4 == 0 { cl.z } else { ch.z },
        )
    });
    let distances = corners.chain(receivers.iter().copied()).map(|p| -rotation.transform_point3(p).z);
    let (near, far) = distances.fold((f32::MAX, f32::MIN), |(n, f), d| (n.min(d), f.max(d)));
    let (near, far) = (near - 1.0, far + 1.0);
    let projection = Mat4::orthographic_rh(x - radius, x + radius, y - radius, y + radius, near, far);
    LightBox { view_proj: projection * rotation, texel, depth: far - near }
}
// ANCHOR_END: fit

impl LightBox {
    /// The box's eight corners in the world, for drawing it.
    pub fn corners(&self) -> [Vec3; 8] {
        let inverse = self.view_proj.inverse();
        std::array::from_fn(|i| {
            let x = if i & 1 == 0 { -1.0 } else { 1.0 };
            let y = if i & 2 == 0 { -1.0 } else { 1.0 };
            let z = if i & 4 == 0 { 0.0 } else { 1.0 };
            inverse.project_point3(Vec3::new(x, y, z))
        })
    }
}

/// Where the line `p + t·d` runs inside the box `(low, high)`, as (t in,
/// t out), if it does: the slab method, one axis at a time. The book's
/// figure of the shadow test and the test of its numbers follow a ray from
/// the ground towards the sun through the level's bounds with it.
pub fn through_box(p: Vec3, d: Vec3, (low, high): (Vec3, Vec3)) -> Option<(f32, f32)> {
    let (mut enter, mut exit) = (f32::MIN, f32::MAX);
    for axis in 0..3 {
        if d[axis].abs() < 1e-9 {
            if p[axis] < low[axis] || p[axis] > high[axis] {
                return None;
            }
            continue;
        }
        let (a, b) = ((low[axis] - p[axis]) / d[axis], (high[axis] - p[axis]) / d[axis]);
        enter = enter.max(a.min(b));
        exit = exit.min(a.max(b));
    }
    (enter <= exit).then_some((enter, exit))
}

/// The section the figure of the shadow test draws and its test checks,
/// metres: B on the ground at x = 25.6 m (under the third platform, 23 to
/// 26 m), A on the ground 5 m from B towards the sun.
pub const SECTION_AT: f32 = 25.6;
pub const SECTION_LIT_AT: f32 = 5.0;
