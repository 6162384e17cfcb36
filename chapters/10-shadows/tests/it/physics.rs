//! The side-scroller's physics, on its own: resting, walls at any speed,
//! ceilings, friction, ledges and corners.

use glam::Vec2;
use shadows::physics::{Aabb, Body, Contacts, step};

const DT: f32 = 1.0 / 60.0;
const G: f32 = 9.81;

fn boxed(x0: f32, y0: f32, x1: f32, y1: f32) -> Aabb {
    Aabb::new(Vec2::new(x0, y0), Vec2::new(x1, y1))
}

/// A 0.8 × 1.8 m body standing with its feet at `foot`, moving at `velocity`.
fn player(foot: Vec2, velocity: Vec2) -> Body {
    Body { aabb: Aabb::standing_at(foot, Vec2::new(0.8, 1.8)), velocity }
}

/// The ground: the half-plane below y = 0, 200 m wide.
fn ground() -> Aabb {
    boxed(-100.0, -10.0, 100.0, 0.0)
}

#[test]
fn a_dropped_body_comes_to_rest_on_a_platform_and_stays_exactly_there() {
    let platform = boxed(-2.0, 1.0, 2.0, 1.5);
    let solids = [ground(), platform];
    let mut body = player(Vec2::new(0.3, 4.0), Vec2::ZERO);
    for _ in 0..120 {
        step(&mut body, &solids, G, 20.0, DT);
    }
    for n in 0..600 {
        let contacts = step(&mut body, &solids, G, 20.0, DT);
        assert!(contacts.floor, "step {n}: not on the floor");
        assert!((body.aabb.min.y - 1.5).abs() <= 1e-4, "step {n}: feet at {}", body.aabb.min.y);
        assert_eq!(body.velocity, Vec2::ZERO, "step {n}");
    }
}

#[test]
fn no_speed_tunnels_through_a_thin_wall() {
    let wall = boxed(5.0, 0.0, 5.1, 3.0);
    let solids = [ground(), wall];
    let mut body = player(Vec2::new(0.0, 0.0), Vec2::new(200.0, 0.0));
    let mut right = false;
    for _ in 0..10 {
        right |= step(&mut body, &solids, G, 0.0, DT).right;
        assert!(body.aabb.max.x <= 5.0 + 1e-4, "went through: right side at {}", body.aabb.max.x);
    }
    assert!(right, "the wall was not reported");
    assert_eq!(body.velocity.x, 0.0);
    assert_eq!(body.aabb.max.x, 5.0, "stopped short of the wall");
    // Every speed from 1 to 2,000 m/s and every starting phase, both ways.
    for speed in (1..=2000).step_by(7).map(|s| s as f32) {
        for start in [-3.0, -2.71, -1.05, -0.5] {
            let mut body = player(Vec2::new(start, 0.0), Vec2::new(speed, 0.0));
            let mut mirrored = player(Vec2::new(10.1 - start, 0.0), Vec2::new(-speed, 0.0));
            for _ in 0..30 {
                step(&mut body, &solids, G, 0.0, DT);
                step(&mut mirrored, &solids, G, 0.0, DT);
            }
            assert!(body.aabb.max.x <= 5.0 + 1e-4, "{speed} m/s from {start}: right side at {}", body.aabb.max.x);
            assert!(mirrored.aabb.min.x >= 5.1 - 1e-4, "{speed} m/s leftwards: left side at {}", mirrored.aabb.min.x);
        }
    }
}

#[test]
fn a_jump_into_a_low_ceiling_reports_it_and_falls_back() {
    let ceiling = boxed(-3.0, 2.3, 3.0, 2.6);
    let solids = [ground(), ceiling];
    let mut body = player(Vec2::ZERO, Vec2::new(0.0, 8.0));
    let (mut bumped, mut landed_after) = (false, false);
    for _ in 0..180 {
        let contacts = step(&mut body, &solids, G, 20.0, DT);
        assert!(body.aabb.max.y <= 2.3 + 1e-4, "head in the ceiling at {}", body.aabb.max.y);
        if contacts.ceiling {
            bumped = true;
            assert!(body.velocity.y <= 0.0, "still rising after the bump");
        }
        landed_after |= bumped && contacts.floor;
    }
    assert!(bumped, "the ceiling was not reported");
    assert!(landed_after, "did not fall back to the floor");
    assert_eq!(body.aabb.min.y, 0.0);
}

#[test]
fn friction_stops_a_slide_in_v_over_f() {
    let solids = [ground()];
    for (v, f) in [(6.0f32, 30.0f32), (-6.0, 30.0), (10.0, 7.0), (0.5, 40.0)] {
        let mut body = player(Vec2::ZERO, Vec2::new(v, 0.0));
        let mut steps = 0;
        while body.velocity.x != 0.0 {
            step(&mut body, &solids, G, f, DT);
            assert!(body.velocity.x * v >= 0.0, "friction reversed the slide");
            steps += 1;
            assert!(steps < 10_000);
        }
        let stopped = steps as f32 * DT;
        assert!((stopped - v.abs() / f).abs() <= DT + 1e-6, "{v} m/s at {f} m/s²: stopped after {stopped} s");
    }
}

#[test]
fn a_body_walking_off_a_ledge_falls() {
    let ledge = boxed(-5.0, 2.0, 0.0, 3.0);
    let solids = [ground(), ledge];
    let mut body = player(Vec2::new(-1.0, 3.0), Vec2::new(3.0, 0.0));
    let mut left_the_ledge = false;
    for _ in 0..120 {
        let contacts = step(&mut body, &solids, G, 0.0, DT);
        left_the_ledge |= !contacts.floor && body.aabb.min.x > 0.0;
    }
    assert!(left_the_ledge, "never left the ledge");
    assert_eq!(body.aabb.min.y, 0.0, "did not land on the ground below");
}

#[test]
fn corners_behave_as_a_player_expects() {
    // Falling straight down with a side exactly along a platform's side:
    // touching is not standing, so the body falls past, touching nothing.
    let platform = boxed(0.0, 1.0, 4.0, 1.5);
    let solids = [ground(), platform];
    let mut body = player(Vec2::new(-0.4, 3.0), Vec2::ZERO);
    for _ in 0..120 {
        let c = step(&mut body, &solids, G, 0.0, DT);
        assert!(!c.left && !c.right && !c.ceiling, "{c:?}");
    }
    assert_eq!(body.aabb.min.y, 0.0);

    // A centimetre of overlap is enough to land on.
    let mut body = player(Vec2::new(-0.39, 3.0), Vec2::ZERO);
    for _ in 0..120 {
        step(&mut body, &solids, G, 0.0, DT);
    }
    assert_eq!(body.aabb.min.y, 1.5, "slipped off a 1 cm ledge");

    // Meeting the corner exactly, diagonally: land on it, not stop beside it.
    let mut body = Body { aabb: boxed(-1.3, 1.75, -0.5, 3.55), velocity: Vec2::new(60.0, -30.0) };
    let c = step(&mut body, &solids, 0.0, 0.0, DT);
    assert!(c.floor && !c.right, "{c:?}");
    assert_eq!(body.aabb.min.y, 1.5);
    assert!(body.velocity.x > 0.0, "a landing does not stop the run");

    // Running across two boxes side by side at the same height: no snag.
    let solids = [boxed(-10.0, -1.0, 0.0, 0.0), boxed(0.0, -1.0, 10.0, 0.0)];
    let mut body = player(Vec2::new(-3.0, 0.0), Vec2::new(5.0, 0.0));
    for _ in 0..60 {
        let c = step(&mut body, &solids, G, 0.0, DT);
        assert!(c.floor && !c.left && !c.right, "{c:?} at x = {}", body.aabb.min.x);
    }
    assert_eq!(body.velocity.x, 5.0);

    // Falling against a wall: the wall stops the run, not the fall.
    let solids = [ground(), boxed(1.0, 0.0, 2.0, 10.0)];
    let mut body = player(Vec2::new(0.58, 5.0), Vec2::new(4.0, 0.0));
    let c = step(&mut body, &solids, G, 0.0, DT);
    assert!(c.right && !c.floor, "{c:?}");
    assert!(body.velocity.y < 0.0);
    for _ in 0..120 {
        body.velocity.x = 4.0; // keep pressing against it
        step(&mut body, &solids, G, 0.0, DT);
    }
    assert_eq!((body.aabb.max.x, body.aabb.min.y), (1.0, 0.0), "stuck on the wall");
}

#[test]
fn bad_steps_change_nothing_and_a_huge_step_does_not_fall_through_the_floor() {
    let solids = [ground()];
    let start = player(Vec2::new(0.0, 2.0), Vec2::new(1.0, 0.0));
    for dt in [0.0, -1.0, f32::NAN, f32::INFINITY] {
        let mut body = start;
        assert_eq!(step(&mut body, &solids, G, 10.0, dt), Contacts::default());
        assert_eq!(body, start, "dt = {dt}");
    }
    let mut body = Body { velocity: Vec2::new(f32::NAN, 1.0), ..start };
    step(&mut body, &solids, G, 10.0, DT);
    assert!(body.aabb.min.is_finite() && body.velocity.is_finite());
    let mut body = start;
    let c = step(&mut body, &solids, G, 10.0, 10.0);
    assert!(c.floor);
    assert_eq!(body.aabb.min.y, 0.0);
}
