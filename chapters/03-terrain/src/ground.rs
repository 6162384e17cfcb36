//! Keeping the eye on the ground: walking over the height field at head
//! height, following its slopes and stopped by the map's edge, and, when
//! flying, never sinking below it. The fly controller moves the camera
//! freely; this puts it back where a walker (or a careful drone) could be.

use common::chapter::ChapterFlag;
use common::winit::keyboard::KeyCode;
use common::{Camera, FlyController, Input};

use crate::heightfield::HeightField;

/// How the learner moves over the terrain.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Movement {
    /// Freely, like a drone: anywhere above the ground (the default).
    #[default]
    Fly,
    /// On foot: the eye at [`EYE_HEIGHT`] over the ground, inside the map.
    Walk,
}

/// A standing person's eye above the ground, metres.
pub const EYE_HEIGHT: f32 = 1.7;
/// The least a flying eye keeps above the ground, metres: twice the
/// largest near plane of the terrain chapters' cameras (0.5 m), so the
/// ground never cuts the picture's bottom edge away.
pub const FLY_CLEARANCE: f32 = 1.0;
/// How far inside the map's edge a walker stops, metres: beyond the edge
/// there is no terrain to stand on.
pub const EDGE_MARGIN: f32 = 2.0;

/// The key that switches between walking and flying.
pub const WALK_KEY: KeyCode = KeyCode::KeyG;

/// `--walk`: start on foot.
pub const WALK_FLAG: ChapterFlag =
    ChapterFlag { name: "walk", value_name: "", help: "Start walking on the ground instead of flying (G switches)" };

/// The fly controller's keys for the F1 help, and the walk switch.
pub const KEYS: &[(&str, &str)] = &[
    ("W A S D / arrows", "move"),
    ("E / Space", "rise (flying)"),
    ("Q / Shift+Space", "fall (flying)"),
    ("Ctrl", "move 4x faster"),
    ("left drag, or Tab to lock", "look around"),
    ("scroll", "move forward and back"),
    ("G", "walk on the ground, or fly"),
];

// ANCHOR: keep_on_ground
/// Puts `camera` back on `field` after a step of free flight. Walking,
/// the eye stands [`EYE_HEIGHT`] over the ground under it (so it climbs
/// and descends with the slopes) and inside the map; flying, it stays at
/// least [`FLY_CLEARANCE`] above the ground. Either way the result depends
/// only on where the camera is now, never on how fast it got there, so no
/// speed carries it through a hill or past the edge.
pub fn keep_on_ground(camera: &mut Camera, field: &HeightField, movement: Movement) {
    let p = &mut camera.position;
    if !p.is_finite() {
        return;
    }
    if movement == Movement::Walk {
        let extent = (field.size - 1) as f32 * field.settings.spacing;
        p.x = p.x.clamp(EDGE_MARGIN, extent - EDGE_MARGIN);
        p.z = p.z.clamp(EDGE_MARGIN, extent - EDGE_MARGIN);
    }
    let ground = field.height_at(p.x, p.z);
    p.y = match movement {
        Movement::Walk => ground + EYE_HEIGHT,
        Movement::Fly => p.y.max(ground + FLY_CLEARANCE),
    };
}
// ANCHOR_END: keep_on_ground

/// Where a terrain chapter's first frame starts, in every runner
/// (`Chapter::before_first_frame`): walking (`--walk`), the eye stands on
/// the ground under the place the view or `--camera` gave it, as the first
/// walking frame would put it; flying, the camera stays exactly where it
/// was placed, so that a picture may look from anywhere (under the ground
/// too, which the window's first flying frame would lift).
pub fn first_frame(camera: &mut Camera, field: &HeightField, movement: Movement) {
    if movement == Movement::Walk {
        keep_on_ground(camera, field, movement);
    }
}

/// One frame of a terrain chapter's camera: [`WALK_KEY`] switches how the
/// learner moves, the fly controller moves the camera, and the ground
/// puts it back where it may be.
pub fn step(
    controller: &FlyController,
    camera: &mut Camera,
    movement: &mut Movement,
    field: &HeightField,
    input: &Input,
    dt: f32,
) {
    if input.pressed(WALK_KEY) {
        *movement = match movement {
            Movement::Fly => Movement::Walk,
            Movement::Walk => Movement::Fly,
        };
    }
    controller.update(camera, input, dt);
    keep_on_ground(camera, field, *movement);
}

/// The overlay's switch between walking and flying.
pub fn movement_switch(ui: &mut common::egui::Ui, movement: &mut Movement) {
    ui.horizontal(|ui| {
        ui.label("move:");
        ui.radio_value(movement, Movement::Fly, "fly");
        ui.radio_value(movement, Movement::Walk, "walk (G)");
    });
}

/// The movement `--walk` asks for.
pub fn movement_from_flags(flags: &common::chapter::FlagValues) -> Movement {
    if flags.get(WALK_FLAG.name).is_some() { Movement::Walk } else { Movement::Fly }
}

#[cfg(test)]
mod tests {
    use common::glam::Vec3;

    use super::*;
    use crate::heightfield::TerrainSettings;

    fn field() -> HeightField {
        // 129 × 129 samples a metre apart: hills of the real settings, small.
        HeightField::generate(TerrainSettings { chunks_per_side: 2, ..Default::default() })
    }

    fn camera_at(position: Vec3) -> Camera {
        Camera { position, near: 0.5, ..Camera::looking_at(position, position + Vec3::X, 16.0 / 9.0) }
    }

    /// A flight that dives from high above into the hills and skims along
    /// them, in steps of every size: the flying eye never ends a step
    /// below the ground, and the walking eye is always at head height.
    #[test]
    fn a_diving_flight_never_ends_below_the_ground() {
        let field = field();
        let extent = 128.0;
        let mut lowest_seen = f32::INFINITY;
        for movement in [Movement::Fly, Movement::Walk] {
            for step in [0.01f32, 0.5, 3.0, 40.0] {
                let mut camera = camera_at(Vec3::new(10.0, 60.0, 10.0));
                let mut t = 0.0;
                while t < extent {
                    // Down at 45° into the ground, then across it.
                    camera.position += Vec3::new(step, -step, step * 0.7);
                    keep_on_ground(&mut camera, &field, movement);
                    let p = camera.position;
                    let ground = field.height_at(p.x, p.z);
                    match movement {
                        Movement::Fly => assert!(p.y >= ground + FLY_CLEARANCE - 1e-4, "{p} over {ground}"),
                        Movement::Walk => assert!((p.y - ground - EYE_HEIGHT).abs() < 1e-4, "{p} over {ground}"),
                    }
                    lowest_seen = lowest_seen.min(p.y - ground);
                    t += step;
                }
            }
        }
        // The flight did reach the ground: the clamp was at work.
        assert!(lowest_seen < FLY_CLEARANCE + 1e-3, "{lowest_seen}");
    }

    /// Walking follows the slopes: over a stretch where the ground rises
    /// and falls by metres, the eye rises and falls with it exactly.
    #[test]
    fn walking_follows_the_slopes() {
        let field = field();
        let heights: Vec<f32> = (0..100)
            .map(|i| {
                let mut camera = camera_at(Vec3::new(5.0 + i as f32, 500.0, 64.0));
                keep_on_ground(&mut camera, &field, Movement::Walk);
                camera.position.y - EYE_HEIGHT
            })
            .collect();
        let (low, high) = heights.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(l, h), &y| (l.min(y), h.max(y)));
        assert!(high - low > 1.0, "a stretch with slopes to follow: {low}..{high}");
        for (i, y) in heights.iter().enumerate() {
            let ground = field.height_at(5.0 + i as f32, 64.0);
            assert!((y - ground).abs() < 1e-4, "{y} over ground at {ground}");
        }
    }

    /// The map's edge stops a walker at any speed, on every side and in
    /// the corners; flying may leave the map.
    #[test]
    fn the_edge_holds_at_every_speed() {
        let field = field();
        let extent = 128.0;
        for speed in [1.0f32, 100.0, 1e4, 1e9] {
            for direction in [Vec3::X, -Vec3::X, Vec3::Z, -Vec3::Z, Vec3::new(1.0, 0.0, -1.0)] {
                let mut camera = camera_at(Vec3::new(64.0, 10.0, 64.0));
                camera.position += direction * speed;
                keep_on_ground(&mut camera, &field, Movement::Walk);
                let p = camera.position;
                for c in [p.x, p.z] {
                    assert!(
                        (EDGE_MARGIN..=extent - EDGE_MARGIN).contains(&c),
                        "{p} after {speed} m towards {direction}"
                    );
                }
                assert!(p.is_finite());
            }
        }
        let mut flying = camera_at(Vec3::new(64.0, 10.0, 64.0));
        flying.position.x += 1000.0;
        keep_on_ground(&mut flying, &field, Movement::Fly);
        assert_eq!(flying.position.x, 1064.0, "flying is free to leave the map");
    }

    #[test]
    fn g_switches_walking_and_flying_and_the_flag_starts_on_foot() {
        let field = field();
        let mut camera = camera_at(Vec3::new(64.0, 40.0, 64.0));
        let mut movement = Movement::Fly;
        let mut input = Input::default();
        input.key_down(WALK_KEY);
        step(&FlyController::default(), &mut camera, &mut movement, &field, &input, 0.016);
        assert_eq!(movement, Movement::Walk);
        assert!((camera.position.y - field.height_at(64.0, 64.0) - EYE_HEIGHT).abs() < 1e-4);
        input.end_frame();
        step(&FlyController::default(), &mut camera, &mut movement, &field, &input, 0.016);
        assert_eq!(movement, Movement::Walk, "a key held down switches once");
        let walk = common::chapter::FlagValues(vec![("walk", "true".into())]);
        assert_eq!(movement_from_flags(&walk), Movement::Walk);
        assert_eq!(movement_from_flags(&Default::default()), Movement::Fly);
    }
}
