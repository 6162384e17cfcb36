//! The game around the shadows: a level of solid boxes and props, a player
//! who runs and jumps through it, and a script that plays it by itself.
//!
//! The game advances in fixed steps of [`STEP`] seconds, whatever the frame
//! rate: the same inputs give the same run on every machine. A window feeds
//! the keys; pictures, snapshots and `--time T` replay [`script`] from time
//! 0 to T, so the picture at T is always the same.

use glam::{Vec2, Vec3};

use crate::physics::{self, Aabb, Body};

// ANCHOR: tuning
/// The fixed time step: 120 steps a second.
pub const STEP: f32 = 1.0 / 120.0;
/// The most real time one frame may simulate. After the window was hidden
/// for a minute, the game resumes where it was instead of running a minute
/// of steps (or one huge step) at once.
pub const MAX_FRAME_TIME: f32 = 0.25;
/// Downward acceleration, m/s²: stronger than Earth's, as platform games
/// are, so that jumps are quick.
pub const GRAVITY: f32 = 24.0;
/// How fast a slide stops on a floor when no key is held, m/s².
pub const FRICTION: f32 = 30.0;
/// Running speed, m/s, and how fast it is reached on the ground and in the air.
pub const RUN_SPEED: f32 = 6.0;
pub const GROUND_ACCELERATION: f32 = 40.0;
pub const AIR_ACCELERATION: f32 = 16.0;
/// Take-off speed: a jump rises v² / 2g = 2.08 m.
pub const JUMP_SPEED: f32 = 10.0;
/// The player's box, metres.
pub const PLAYER_SIZE: Vec2 = Vec2::new(0.8, 1.7);
// ANCHOR_END: tuning

/// What the player asks for in one step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Controls {
    pub left: bool,
    pub right: bool,
    pub jump: bool,
}

/// The surface a block is made of: one of chapter 09's textures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    Concrete,
    Brick,
    Metal,
}

/// A solid box of the level: its side-on rectangle and how deep it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Block {
    pub aabb: Aabb,
    /// From −depth to +depth along z.
    pub depth: f32,
    pub surface: Surface,
}

/// The models that dress the level (OBJ files from `cargo xtask assets`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PropKind {
    Tree,
    Rock,
    Crate,
    /// The seed's hovering islands: a grassy top (the prop's base) over
    /// a rocky cone, hanging in the air behind the level.
    Island,
    /// The seed's low-poly sphere.
    Sphere,
}

impl PropKind {
    /// Every kind, in the order the chapter loads and draws them.
    pub const ALL: [PropKind; 5] = [Self::Tree, Self::Rock, Self::Crate, Self::Island, Self::Sphere];
}

/// A prop: where it stands (its base), its size, its turn about y, and
/// whether the player collides with it (crates do; trees, rocks and the
/// sphere stand in front of or behind the path, the islands far behind it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prop {
    pub kind: PropKind,
    pub base: Vec3,
    pub scale: f32,
    pub turn: f32,
    pub solid: bool,
}

/// The level: blocks, props, where the player starts, its extent in x,
/// and where its lantern hangs.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    pub blocks: Vec<Block>,
    pub props: Vec<Prop>,
    pub spawn: Vec2,
    pub width: f32,
    /// The lantern's light: the middle of its glass.
    pub lantern: Vec3,
}

// ANCHOR: level
/// The level, about seven screens wide: platforms at several heights, a
/// tunnel with a low ceiling and a lantern in it, walls to jump, crates to
/// climb.
pub fn level() -> Level {
    let block = |x0: f32, y0: f32, x1: f32, y1: f32, surface| Block {
        aabb: Aabb::new(Vec2::new(x0, y0), Vec2::new(x1, y1)),
        depth: 2.0,
        surface,
    };
    let blocks = vec![
        // The ground, deeper than the rest so that shadows have somewhere
        // to fall, and walls at both ends that nobody jumps over.
        Block { depth: 4.0, ..block(-5.0, -6.0, 125.0, 0.0, Surface::Concrete) },
        block(-5.0, 0.0, -4.0, 12.0, Surface::Brick),
        block(124.0, 0.0, 125.0, 12.0, Surface::Brick),
        // Platforms climbing up and down.
        block(10.0, 1.4, 14.0, 1.8, Surface::Concrete),
        block(16.0, 2.9, 20.0, 3.3, Surface::Concrete),
        block(23.0, 1.6, 26.0, 2.0, Surface::Concrete),
        // A wall to jump.
        block(32.0, 0.0, 32.8, 1.6, Surface::Brick),
        // A tunnel: a low ceiling on two pillars.
        block(40.0, 2.3, 52.0, 3.1, Surface::Metal),
        block(40.0, 3.1, 41.0, 4.5, Surface::Brick),
        block(51.0, 3.1, 52.0, 4.5, Surface::Brick),
        // Steps up to a high ledge, and a drop.
        block(64.0, 0.0, 68.0, 1.2, Surface::Concrete),
        block(68.0, 0.0, 72.0, 2.4, Surface::Concrete),
        block(72.0, 0.0, 78.0, 3.6, Surface::Concrete),
        block(84.0, 2.6, 88.0, 3.0, Surface::Metal),
        // A last wall.
        block(96.0, 0.0, 96.8, 1.8, Surface::Brick),
    ];
    let prop = |kind, x: f32, y: f32, z: f32, scale: f32, turn: f32, solid| Prop {
        kind,
        base: Vec3::new(x, y, z),
        scale,
        turn,
        solid,
    };
    let props = vec![
        prop(PropKind::Tree, 3.0, 0.0, -1.2, 1.0, 0.0, false),
        prop(PropKind::Tree, 8.0, 0.0, -1.5, 1.3, 1.0, false),
        prop(PropKind::Rock, 6.0, 0.0, 1.3, 0.8, 0.5, false),
        prop(PropKind::Tree, 21.5, 0.0, -1.4, 1.1, 2.0, false),
        prop(PropKind::Rock, 28.0, 0.0, -1.2, 1.2, 2.5, false),
        prop(PropKind::Tree, 36.0, 0.0, -1.3, 0.9, 3.0, false),
        prop(PropKind::Rock, 46.0, 0.0, 1.4, 0.6, 1.5, false),
        prop(PropKind::Crate, 57.0, 0.0, 0.0, 1.0, 0.0, true),
        prop(PropKind::Crate, 58.0, 0.0, 0.0, 1.0, 0.0, true),
        prop(PropKind::Crate, 58.0, 1.0, 0.0, 1.0, 0.0, true),
        prop(PropKind::Tree, 61.0, 0.0, -1.5, 1.2, 4.0, false),
        prop(PropKind::Tree, 75.0, 3.6, -1.2, 0.8, 5.0, false),
        prop(PropKind::Rock, 82.0, 0.0, -1.0, 1.0, 0.2, false),
        prop(PropKind::Tree, 92.0, 0.0, -1.4, 1.4, 0.7, false),
        prop(PropKind::Crate, 104.0, 0.0, -1.2, 1.0, 0.4, false),
        prop(PropKind::Tree, 110.0, 0.0, -1.3, 1.0, 1.7, false),
        prop(PropKind::Rock, 115.0, 0.0, 1.2, 0.9, 2.2, false),
        // The seed's low-poly sphere, beside the path before the first wall.
        prop(PropKind::Sphere, 30.0, 0.0, -1.4, 1.2, 0.3, false),
        // Its hovering islands, 5 to 11 m behind the level's back (z = −2)
        // and well above the player's head: scenery, never in the way.
        prop(PropKind::Island, 22.5, 5.0, -7.0, 0.6, 0.0, false),
        prop(PropKind::Island, 36.0, 7.5, -10.0, 0.9, 2.0, false),
        prop(PropKind::Island, 46.0, 5.5, -13.0, 1.1, 4.0, false),
    ];
    // The lantern hangs under the tunnel's ceiling (2.3 m up), left of the
    // rock at 46 m and a little behind the path, its glass above the
    // player's head (1.7 m): the ceiling hides it from the sun.
    let lantern = Vec3::new(44.5, 1.95, -0.4);
    Level { blocks, props, spawn: Vec2::new(2.0, 0.0), width: 120.0, lantern }
}
// ANCHOR_END: level

impl Level {
    /// Everything the player collides with: the blocks and the solid props
    /// (a prop's box is its model's, 1 m per unit of scale).
    pub fn solids(&self) -> Vec<Aabb> {
        let props = self.props.iter().filter(|p| p.solid).map(|p| {
            let half = p.scale / 2.0;
            Aabb::new(Vec2::new(p.base.x - half, p.base.y), Vec2::new(p.base.x + half, p.base.y + p.scale))
        });
        self.blocks.iter().map(|b| b.aabb).chain(props).collect()
    }
}

// ANCHOR: game
/// The state of a game: the player's body, which way it faces, whether it
/// stands on something, and time not yet simulated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Game {
    pub player: Body,
    /// +1 facing right, −1 left.
    pub facing: f32,
    pub on_floor: bool,
    /// Steps taken since the start.
    pub steps: u64,
    /// Real time received but not yet simulated, less than one step.
    pub pending: f32,
}

impl Game {
    pub fn new(level: &Level) -> Self {
        Self {
            player: Body { aabb: Aabb::standing_at(level.spawn, PLAYER_SIZE), velocity: Vec2::ZERO },
            facing: 1.0,
            on_floor: true,
            steps: 0,
            pending: 0.0,
        }
    }

    /// Seconds simulated since the start.
    pub fn time(&self) -> f32 {
        self.steps as f32 * STEP
    }

    /// One fixed step with `controls`.
    pub fn step(&mut self, solids: &[Aabb], controls: Controls) {
        let direction = f32::from(controls.right as u8) - f32::from(controls.left as u8);
        let v = &mut self.player.velocity;
        if direction != 0.0 {
            let acceleration = if self.on_floor { GROUND_ACCELERATION } else { AIR_ACCELERATION };
            let target = direction * RUN_SPEED;
            let change = (target - v.x).clamp(-acceleration * STEP, acceleration * STEP);
            v.x += change;
            self.facing = direction;
        }
        if controls.jump && self.on_floor {
            v.y = JUMP_SPEED;
        }
        // Friction only when no key asks to run: it is what stops a player
        // who lets go, not what slows one who runs.
        let friction = if direction == 0.0 { FRICTION } else { 0.0 };
        let contacts = physics::step(&mut self.player, solids, GRAVITY, friction, STEP);
        self.on_floor = contacts.floor || physics::standing(&self.player.aabb, solids);
        self.steps += 1;
    }

    /// Simulates `dt` seconds of real time in fixed steps with the same
    /// controls, carrying the remainder to the next frame. At most
    /// [`MAX_FRAME_TIME`] is simulated; the rest is dropped. Returns the
    /// steps taken.
    pub fn advance(&mut self, solids: &[Aabb], controls: Controls, dt: f32) -> u32 {
        let dt = if dt.is_finite() { dt.clamp(0.0, MAX_FRAME_TIME) } else { 0.0 };
        self.pending += dt;
        let mut steps = 0;
        // A microsecond of slack: four frames of 1/4 s are 120 steps, not
        // 119 and a remainder that rounding left just short of a step.
        while self.pending >= STEP - 1e-6 {
            self.step(solids, controls);
            self.pending = (self.pending - STEP).max(0.0);
            steps += 1;
        }
        steps
    }
}
// ANCHOR_END: game

// ANCHOR: script
/// The demo's input at `time`: run right until the end, jumping where the
/// level asks for it.
pub fn script(time: f32) -> Controls {
    // When jump is pressed, each time for 0.15 s: found by running the
    // level with a simple autopilot (jump when something is ahead at
    // head height) and writing its take-off times down.
    const JUMPS: [f32; 8] = [1.175, 3.808, 5.633, 9.967, 11.375, 12.058, 12.892, 16.892];
    const END: f32 = 21.0;
    Controls { left: false, right: time < END, jump: JUMPS.iter().any(|&at| (at - 0.002..at + 0.148).contains(&time)) }
}

/// The game at `time`, played by [`script`] from the start in fixed steps:
/// a pure function of time, for pictures and tests.
pub fn demo_at(level: &Level, solids: &[Aabb], time: f32) -> Game {
    let mut game = Game::new(level);
    let steps = (time.max(0.0) / STEP).round() as u64;
    for _ in 0..steps {
        let controls = script(game.time());
        game.step(solids, controls);
    }
    game
}
// ANCHOR_END: script
