//! The game around the shadows: the scripted demo plays the whole level,
//! the same time gives the same game, and bad frames break nothing.

use shadows::game::{self, Controls, Game, MAX_FRAME_TIME, STEP};

#[test]
fn the_scripted_run_crosses_the_level_without_getting_stuck() {
    let level = game::level();
    let solids = level.solids();
    let mut game = Game::new(&level);
    let mut furthest = game.player.aabb.min.x;
    let mut log = String::new();
    for n in 0..(25.0 / STEP) as u32 {
        game.step(&solids, game::script(game.time()));
        furthest = furthest.max(game.player.aabb.min.x);
        if n % 60 == 0 {
            let p = game.player.aabb.min;
            log += &format!("{:5.2} s: x {:6.2} y {:5.2}\n", game.time(), p.x, p.y);
        }
        for solid in &solids {
            assert!(!solid.overlaps(&game.player.aabb), "inside {solid:?} at {} s\n{log}", game.time());
        }
    }
    eprintln!("{log}");
    assert!(furthest > 100.0, "the demo stopped at x = {furthest}\n{log}");
}

#[test]
fn the_same_time_gives_the_same_game() {
    let level = game::level();
    let solids = level.solids();
    // `demo_at` replays from the start for each time; one game played on
    // step by step, as a window plays it, must be at the same state when
    // it reaches each of those times, whatever was asked for before (the
    // times go back and forth, so a replay that kept state from the last
    // call would drift).
    let mut played = Game::new(&level);
    assert_eq!(game::demo_at(&level, &solids, 0.0), played, "at 0 s, the game as it starts");
    let times = [1.3, 7.77, 20.0];
    for (n, &time) in times.iter().enumerate() {
        let steps = (time / STEP).round() as u64;
        while played.steps < steps {
            let controls = game::script(played.time());
            played.step(&solids, controls);
        }
        for earlier in &times[..n] {
            game::demo_at(&level, &solids, *earlier);
        }
        let replayed = game::demo_at(&level, &solids, time);
        assert_eq!(replayed.steps, steps, "at {time} s");
        assert!((replayed.time() - time).abs() <= STEP / 2.0, "at {time} s the game says {} s", replayed.time());
        assert_eq!(replayed, played, "at {time} s");
    }
    // And the game does move: 20 s in, the player is far along.
    assert!(played.player.aabb.min.x > game::demo_at(&level, &solids, 1.3).player.aabb.min.x + 20.0);
}

#[test]
fn frames_of_any_length_are_split_into_fixed_steps() {
    let level = game::level();
    let solids = level.solids();
    let right = Controls { right: true, ..Controls::default() };
    // A minute hidden, then shown: at most MAX_FRAME_TIME is simulated.
    let mut game = Game::new(&level);
    let steps = game.advance(&solids, right, 60.0);
    assert_eq!(steps, (MAX_FRAME_TIME / STEP).round() as u32);
    for dt in [f32::NAN, f32::INFINITY, -1.0, 0.0] {
        let before = game;
        assert_eq!(game.advance(&solids, right, dt), 0, "dt = {dt}");
        assert_eq!(game, before);
    }
    // Many short frames and few long ones take the same steps.
    let (mut a, mut b) = (Game::new(&level), Game::new(&level));
    for _ in 0..120 {
        a.advance(&solids, right, 1.0 / 60.0);
    }
    for _ in 0..8 {
        b.advance(&solids, right, 0.25);
    }
    assert_eq!(a.steps, b.steps);
    assert!((a.player.aabb.min.x - b.player.aabb.min.x).abs() < 1e-4);
}

#[test]
fn every_key_at_once_and_jump_every_frame_break_nothing() {
    let level = game::level();
    let solids = level.solids();
    let mut game = Game::new(&level);
    let all = Controls { left: true, right: true, jump: true };
    let mut jumps = 0;
    for _ in 0..1200 {
        let was_on_floor = game.on_floor;
        game.step(&solids, all);
        jumps += u32::from(was_on_floor && game.player.velocity.y > 0.0);
        assert!(game.player.aabb.min.is_finite() && game.player.velocity.is_finite());
        assert!(solids.iter().all(|s| !s.overlaps(&game.player.aabb)));
    }
    // Left and right cancel: it hops on the spot, once per landing.
    assert!((game.player.aabb.min.x - (level.spawn.x - 0.4)).abs() < 1e-4);
    assert!(jumps > 5, "only {jumps} jumps in 10 s of holding jump");
}

/// The seed's props, the hovering islands and the low-poly sphere, are in
/// the chapter's draw list, one draw per kind with one instance per prop,
/// and out of the player's way: none is solid, each model's box lies
/// behind the play plane (clear of the player's 0.76 m wide model) and
/// inside no block of the level (the sphere only touches the ground).
#[test]
fn the_islands_and_the_sphere_are_drawn_and_out_of_the_players_way() {
    use shadows::game::PropKind;
    use shadows::level_models::level_instances;
    use shadows::scene;
    use std::path::Path;

    let level = game::level();
    let (instances, draws) = level_instances(&level, &Game::new(&level));
    for (kind, count) in [(PropKind::Island, 3), (PropKind::Sphere, 1)] {
        let which = 1 + PropKind::ALL.iter().position(|k| *k == kind).unwrap();
        let (_, range) = draws.iter().find(|(model, _)| *model == which).expect("a draw for the kind");
        let drawn = &instances[range.start as usize..range.end as usize];
        assert_eq!(drawn, scene::prop_instances(&level, kind).as_slice(), "{kind:?}");
        assert_eq!(drawn.len(), count, "{kind:?}");

        let model = textures::obj::load(Path::new(scene::prop_model(kind)), &scene::read).unwrap().model;
        for prop in level.props.iter().filter(|p| p.kind == kind) {
            assert!(!prop.solid, "{kind:?} at {:?} is solid", prop.base);
            let at = glam::Mat4::from_scale_rotation_translation(
                glam::Vec3::splat(prop.scale),
                glam::Quat::from_rotation_y(prop.turn),
                prop.base,
            );
            let (low, high) = model.vertices.iter().fold((glam::Vec3::MAX, glam::Vec3::MIN), |(lo, hi), v| {
                let p = at.transform_point3(glam::Vec3::from(v.position));
                (lo.min(p), hi.max(p))
            });
            assert!(high.z < -0.5, "{kind:?} at {:?} reaches z = {} in front of the play plane", prop.base, high.z);
            for block in &level.blocks {
                let inside = low.x < block.aabb.max.x
                    && high.x > block.aabb.min.x
                    && low.y < block.aabb.max.y - 1e-3
                    && high.y > block.aabb.min.y
                    && low.z < block.depth
                    && high.z > -block.depth;
                assert!(!inside, "{kind:?} at {:?} ({low} to {high}) is inside {:?}", prop.base, block.aabb);
            }
        }
    }
    // The solids are the blocks and the crates that are solid, nothing more.
    let solid_props = level.props.iter().filter(|p| p.solid).count();
    assert_eq!(level.solids().len(), level.blocks.len() + solid_props);
}
