//! A little 2D physics for a side-scroller: boxes that fall, slide and
//! stop against other boxes, and never pass through them. The level is
//! solid axis-aligned boxes; the player is one more box that moves.
//!
//! Motion is *swept*: a step finds the first solid the moving box would
//! touch along its whole path and stops it there, so no speed can carry it
//! through a wall between two frames. The side it touched comes from when
//! each axis started to overlap, which is the direction the body came from.

use glam::Vec2;

// ANCHOR: types
/// An axis-aligned box: `min` is the lower left corner, `max` the upper right.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec2,
    pub max: Vec2,
}

/// A moving box and its velocity in m/s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    pub aabb: Aabb,
    pub velocity: Vec2,
}

/// Which sides of a body touched a solid during a step.
#[derive(Default, Debug, Clone, Copy, PartialEq)]
pub struct Contacts {
    pub floor: bool,
    pub ceiling: bool,
    pub left: bool,
    pub right: bool,
}
// ANCHOR_END: types

impl Aabb {
    pub fn new(min: Vec2, max: Vec2) -> Self {
        Self { min, max }
    }

    /// The box of `size` whose bottom centre is `foot`.
    pub fn standing_at(foot: Vec2, size: Vec2) -> Self {
        Self { min: foot - Vec2::new(size.x / 2.0, 0.0), max: foot + Vec2::new(size.x / 2.0, size.y) }
    }

    pub fn size(&self) -> Vec2 {
        self.max - self.min
    }

    pub fn centre(&self) -> Vec2 {
        (self.min + self.max) / 2.0
    }

    /// Whether the two boxes share some area. Boxes that only touch along
    /// an edge or at a corner do not.
    pub fn overlaps(&self, other: &Aabb) -> bool {
        overlap(self.min.x, self.max.x, other.min.x, other.max.x)
            && overlap(self.min.y, self.max.y, other.min.y, other.max.y)
    }
}

/// Boxes closer than this count as touching. Positions are snapped to
/// contact exactly, so gaps this small only come from rounding.
pub const SKIN: f32 = 1e-4;

/// Whether [a0, a1] and [b0, b1] overlap by more than [`SKIN`].
fn overlap(a0: f32, a1: f32, b0: f32, b1: f32) -> bool {
    (a1 - b0).min(b1 - a0) > SKIN
}

// ANCHOR: sweep
/// When, as a fraction of the motion `d`, a box moving along one axis
/// from [b0, b1] overlaps the solid's [s0, s1]: `(entry, exit)`, with
/// entry −∞ if they overlap already. `None` if they never do.
fn axis_times(b0: f32, b1: f32, s0: f32, s1: f32, d: f32) -> Option<(f32, f32)> {
    if overlap(b0, b1, s0, s1) {
        let exit = if d > 0.0 {
            (s1 - b0) / d
        } else if d < 0.0 {
            (s0 - b1) / d
        } else {
            f32::INFINITY
        };
        return Some((f32::NEG_INFINITY, exit));
    }
    // Apart (or touching): the gap ahead must close.
    let (gap, far) = if d > 0.0 {
        (s0 - b1, s1 - b0)
    } else if d < 0.0 {
        (b0 - s1, b1 - s0)
    } else {
        return None;
    };
    if gap < -SKIN {
        return None; // the solid is behind
    }
    let speed = d.abs();
    Some((gap.max(0.0) / speed, far / speed))
}

/// A hit: the fraction of the motion before it, and the axis it stopped
/// (0 for x, 1 for y).
struct Hit {
    time: f32,
    axis: usize,
    solid: Aabb,
}

/// The first solid that `aabb`, moved by `d`, would run into.
fn first_hit(aabb: &Aabb, d: Vec2, solids: &[Aabb]) -> Option<Hit> {
    let mut first: Option<Hit> = None;
    for solid in solids {
        let Some((entry_x, exit_x)) = axis_times(aabb.min.x, aabb.max.x, solid.min.x, solid.max.x, d.x) else {
            continue;
        };
        let Some((entry_y, exit_y)) = axis_times(aabb.min.y, aabb.max.y, solid.min.y, solid.max.y, d.y) else {
            continue;
        };
        // The boxes overlap while both axes do; the axis that starts to
        // overlap last is the side that was hit. A tie (to within the
        // skin) is a corner met exactly: land on it, or bump it from
        // below, rather than stop dead beside it.
        let entry = entry_x.max(entry_y);
        let exit = exit_x.min(exit_y);
        if entry >= exit || !(0.0..=1.0).contains(&entry) {
            continue; // never both at once, already inside, or not this step
        }
        let tie = (entry_x - entry_y).abs() * d.length() <= SKIN;
        let axis = if entry_x > entry_y && !tie { 0 } else { 1 };
        if first.as_ref().is_none_or(|f| entry < f.time) {
            first = Some(Hit { time: entry, axis, solid: *solid });
        }
    }
    first
}
// ANCHOR_END: sweep

// ANCHOR: step
/// Moves `body` for `dt` seconds against the solid boxes. `gravity` is the size of the
/// downward acceleration in m/s² (9.81 pulls towards −y); `friction` is a deceleration
/// in m/s² opposing horizontal motion while on a floor, which never reverses it.
/// Returns the sides that touched something during the step.
pub fn step(body: &mut Body, solids: &[Aabb], gravity: f32, friction: f32, dt: f32) -> Contacts {
    let mut contacts = Contacts::default();
    if !(dt > 0.0 && dt.is_finite()) {
        return contacts;
    }
    if !body.velocity.is_finite() {
        body.velocity = Vec2::ZERO;
    }
    // Forces first, then motion with the new velocity (semi-implicit Euler).
    if standing(&body.aabb, solids) {
        let slower = (body.velocity.x.abs() - friction.max(0.0) * dt).max(0.0);
        body.velocity.x = slower.copysign(body.velocity.x);
    }
    body.velocity.y -= gravity * dt;

    let mut motion = body.velocity * dt;
    // Each hit removes one axis of the motion: two hits at most, and a
    // third pass to move what is left.
    for _ in 0..3 {
        let Some(hit) = first_hit(&body.aabb, motion, solids) else {
            translate(&mut body.aabb, motion);
            break;
        };
        let a = hit.axis;
        // Move up to the contact, then put the touching faces exactly
        // together: rounding never leaves a gap or an overlap to grow.
        translate(&mut body.aabb, motion * hit.time);
        let size = body.aabb.max[a] - body.aabb.min[a];
        if motion[a] > 0.0 {
            body.aabb.max[a] = hit.solid.min[a];
            body.aabb.min[a] = hit.solid.min[a] - size;
        } else {
            body.aabb.min[a] = hit.solid.max[a];
            body.aabb.max[a] = hit.solid.max[a] + size;
        }
        match (a, motion[a] > 0.0) {
            (0, true) => contacts.right = true,
            (0, false) => contacts.left = true,
            (_, true) => contacts.ceiling = true,
            (_, false) => contacts.floor = true,
        }
        // What is left of the motion slides along the surface.
        motion *= 1.0 - hit.time;
        motion[a] = 0.0;
        body.velocity[a] = 0.0;
    }
    contacts
}
// ANCHOR_END: step

fn translate(aabb: &mut Aabb, by: Vec2) {
    aabb.min += by;
    aabb.max += by;
}

/// Whether `aabb` rests on the top of a solid.
pub fn standing(aabb: &Aabb, solids: &[Aabb]) -> bool {
    solids.iter().any(|s| (aabb.min.y - s.max.y).abs() <= SKIN && overlap(aabb.min.x, aabb.max.x, s.min.x, s.max.x))
}
