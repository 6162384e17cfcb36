//! Motion as a pure function of time: closed paths made of straight
//! segments and circular turns, walked at a constant speed, and clocks that
//! can be paused and resumed without losing their place.

use std::f32::consts::TAU;

use common::glam::{Vec2, Vec3};

// ANCHOR: segment
/// One piece of a path: a straight run, or a turn along a circular arc.
/// Turns join straights tangentially, so the heading never jumps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Segment {
    /// Straight ahead for `length` metres.
    Straight { length: f32 },
    /// A turn of `angle` radians (positive turns left, seen from above)
    /// on a circle of `radius` metres.
    Turn { radius: f32, angle: f32 },
}

impl Segment {
    pub fn length(&self) -> f32 {
        match *self {
            Segment::Straight { length } => length,
            Segment::Turn { radius, angle } => radius * angle.abs(),
        }
    }
}
// ANCHOR_END: segment

/// Where something is on a path and which way it faces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub position: Vec3,
    /// Radians about +y; 0 faces −z, like the camera's yaw.
    pub heading: f32,
}

impl Pose {
    /// The unit vector the pose faces, in the ground plane.
    pub fn forward(&self) -> Vec3 {
        Vec3::new(-self.heading.sin(), 0.0, -self.heading.cos())
    }
}

/// A closed path at a fixed height, walked at a constant speed.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentedPath {
    /// Where the path starts (x, z) and at what height it runs.
    pub start: Vec2,
    pub height: f32,
    /// The heading at the start.
    pub heading: f32,
    pub segments: Vec<Segment>,
    /// Metres per second.
    pub speed: f32,
}

impl SegmentedPath {
    /// The segments of a rectangle `depth` metres ahead by `width` across,
    /// with corners rounded to `radius`, turning left at every corner when
    /// `left` is true (anticlockwise, seen from above), right otherwise.
    pub fn rounded_rectangle(depth: f32, width: f32, radius: f32, left: bool) -> Vec<Segment> {
        let turn = if left { TAU / 4.0 } else { -TAU / 4.0 };
        let mut segments = Vec::new();
        for side in [depth, width, depth, width] {
            segments.push(Segment::Straight { length: side - 2.0 * radius });
            segments.push(Segment::Turn { radius, angle: turn });
        }
        segments
    }

    /// Metres around the whole path.
    pub fn length(&self) -> f32 {
        self.segments.iter().map(Segment::length).sum()
    }

    /// Seconds to go once around.
    pub fn period(&self) -> f32 {
        self.length() / self.speed
    }

    // ANCHOR: at
    /// The pose `time` seconds after leaving the start.
    pub fn at(&self, time: f32) -> Pose {
        // Distances repeat every lap; reducing them first keeps f32
        // precise however long the scene runs.
        let mut left = (time * self.speed).rem_euclid(self.length());
        let mut position = self.start;
        let mut heading = self.heading;
        for segment in &self.segments {
            let length = segment.length();
            let along = left.min(length);
            let forward = Vec2::new(-heading.sin(), -heading.cos());
            match *segment {
                Segment::Straight { .. } => position += forward * along,
                Segment::Turn { radius, angle } => {
                    // The centre of the turn is `radius` to the side we turn to.
                    let side =
                        if angle > 0.0 { Vec2::new(forward.y, -forward.x) } else { Vec2::new(-forward.y, forward.x) };
                    let centre = position + side * radius;
                    let turned = along / radius * angle.signum();
                    let from_centre = position - centre;
                    position = centre + rotate(from_centre, turned);
                    heading += turned;
                }
            }
            left -= along;
            if left <= 0.0 {
                break;
            }
        }
        Pose { position: Vec3::new(position.x, self.height, position.y), heading }
    }
    // ANCHOR_END: at
}

/// Turns a vector in the ground plane by `angle` radians, the same sense
/// as the heading (positive turns from −z towards −x: left, seen from above).
fn rotate(v: Vec2, angle: f32) -> Vec2 {
    let (s, c) = angle.sin_cos();
    // Heading h faces (−sin h, −cos h); turning it by a gives h + a, which
    // is this rotation applied to (x, z).
    Vec2::new(c * v.x + s * v.y, -s * v.x + c * v.y)
}

// ANCHOR: clock
/// A clock for one group of things (the cars, the drones) that the learner
/// can pause while scene time goes on. Its time is a function of scene time
/// and the pauses so far: paused for T and resumed, it reads what it would
/// have read had those T seconds never passed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PausableClock {
    /// Scene time at which the current pause began.
    paused_at: Option<f32>,
    /// Seconds spent in pauses that have ended.
    paused_for: f32,
}

impl PausableClock {
    /// The clock's time at scene time `scene_time`.
    pub fn time(&self, scene_time: f32) -> f32 {
        match self.paused_at {
            Some(start) => start - self.paused_for,
            None => scene_time - self.paused_for,
        }
    }

    pub fn is_paused(&self) -> bool {
        self.paused_at.is_some()
    }

    /// Pauses or resumes at scene time `scene_time`.
    pub fn set_paused(&mut self, paused: bool, scene_time: f32) {
        match (self.paused_at, paused) {
            (None, true) => self.paused_at = Some(scene_time),
            (Some(start), false) => {
                self.paused_for += scene_time - start;
                self.paused_at = None;
            }
            _ => {}
        }
    }
}
// ANCHOR_END: clock

#[cfg(test)]
mod tests {
    use super::*;

    fn loop_path() -> SegmentedPath {
        let segments = SegmentedPath::rounded_rectangle(80.0, 50.0, 8.0, true);
        SegmentedPath { start: Vec2::new(10.0, 20.0), height: 12.0, heading: 0.3, segments, speed: 14.0 }
    }

    /// Distances at which one segment ends and the next begins.
    fn joints(path: &SegmentedPath) -> Vec<f32> {
        path.segments
            .iter()
            .scan(0.0, |sum, s| {
                *sum += s.length();
                Some(*sum)
            })
            .collect()
    }

    #[test]
    fn position_is_continuous_at_every_joint() {
        let path = loop_path();
        for joint in joints(&path) {
            let (before, after) = (path.at((joint - 1e-3) / path.speed), path.at((joint + 1e-3) / path.speed));
            assert!(before.position.distance(after.position) < 5e-3, "jump at {joint} m");
        }
    }

    #[test]
    fn the_heading_turns_without_jumps() {
        let path = loop_path();
        let dt = 0.01;
        // At most what the tightest turn does in dt, plus rounding.
        let limit = path.speed * dt / 8.0 + 1e-4;
        let mut last = path.at(0.0).heading;
        for step in 1..=(path.period() / dt) as usize {
            let heading = path.at(step as f32 * dt).heading;
            let change = (heading - last + TAU / 2.0).rem_euclid(TAU) - TAU / 2.0;
            assert!(change.abs() <= limit, "heading jumped by {change} rad at {} s", step as f32 * dt);
            last = heading;
        }
    }

    #[test]
    fn speed_along_the_path_is_constant_within_one_percent() {
        let path = loop_path();
        let dt = 0.005;
        for step in 0..(path.period() / dt) as usize {
            let t = step as f32 * dt;
            let moved = path.at(t).position.distance(path.at(t + dt).position) / dt;
            assert!((moved - path.speed).abs() < 0.01 * path.speed, "{moved} m/s at {t} s");
        }
    }

    #[test]
    fn a_closed_path_returns_to_its_start() {
        let path = loop_path();
        let (start, lap) = (path.at(0.0), path.at(path.period()));
        assert!(start.position.distance(lap.position) < 1e-3);
        // The segments themselves close the loop, not only the modulo.
        let end = path.at(path.period() * (1.0 - 1e-6));
        assert!(end.position.distance(start.position) < 0.01, "{} vs {}", end.position, start.position);
        let turned = (end.heading - start.heading).rem_euclid(TAU);
        assert!(turned < 1e-3 || TAU - turned < 1e-3, "the heading is off by {turned} rad after a lap");
        assert_eq!(start.position.y, path.height);
    }

    #[test]
    fn the_pose_faces_along_the_motion() {
        let path = loop_path();
        for t in [0.5, 3.0, 7.7, 11.0] {
            let moved = (path.at(t + 1e-3).position - path.at(t).position).normalize();
            assert!(moved.dot(path.at(t).forward()) > 0.999, "at {t} s");
        }
    }

    #[test]
    fn pausing_for_t_and_resuming_is_as_if_t_never_passed() {
        let path = loop_path();
        let mut clock = PausableClock::default();
        let (paused_at, pause) = (4.0, 7.5);
        clock.set_paused(true, paused_at);
        assert_eq!(clock.time(paused_at + 3.0), paused_at, "stopped while paused");
        clock.set_paused(false, paused_at + pause);
        for after in [0.0, 1.0, 5.25] {
            let resumed = path.at(clock.time(paused_at + pause + after));
            let never_paused = path.at(paused_at + after);
            assert!(resumed.position.distance(never_paused.position) < 1e-4);
        }
    }
}
