//! Who plays the game: the script (every picture, and a window until a key
//! is pressed) or the keys. The script's game is a pure function of scene
//! time, replayed in fixed steps from the start, so that the picture at
//! time T is the same on every machine; the keys' game advances by the
//! real time between frames, in the same fixed steps.

use common::Input;
use common::winit::keyboard::KeyCode;

use crate::game::{self, Controls, Game, Level};
use crate::physics::Aabb;

// ANCHOR: play
/// Who plays: the script (pictures, and a window until a key is pressed)
/// or the keys.
pub enum Play {
    /// The scripted run at the scene time, kept so that the next frame
    /// continues from it rather than replaying from the start. (To see it
    /// again in a window, set the overlay's scene time back to 0.)
    Demo(Game),
    Keys(Game),
}

/// The keys' controls this frame. Pressing left and right together
/// cancels out; jump is held, so holding Space jumps again on landing.
pub fn controls_from(input: &Input) -> Controls {
    let any = |keys: &[KeyCode]| keys.iter().any(|k| input.held(*k));
    Controls {
        left: any(&[KeyCode::KeyA, KeyCode::ArrowLeft]),
        right: any(&[KeyCode::KeyD, KeyCode::ArrowRight]),
        jump: any(&[KeyCode::Space, KeyCode::KeyW, KeyCode::ArrowUp]),
    }
}
// ANCHOR_END: play

impl Play {
    /// The game as it stands at scene time `time`: the keys' game as it
    /// is, or the script's run on from where it was (from the start, if
    /// `time` went back).
    pub fn game_at(&mut self, level: &Level, solids: &[Aabb], time: f32) -> Game {
        match self {
            Play::Keys(game) => *game,
            Play::Demo(game) => {
                // The script ends at 21 s and the player stands still from
                // then on: a time past a minute is a minute, so that
                // `--time 1e9` does not simulate thirty years.
                let steps = (time.min(60.0) / game::STEP).round() as u64;
                if steps < game.steps {
                    *game = Game::new(level);
                }
                while game.steps < steps {
                    let controls = game::script(game.time());
                    game.step(solids, controls);
                }
                *game
            }
        }
    }
}
