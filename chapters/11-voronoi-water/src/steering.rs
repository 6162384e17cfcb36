//! Who sails: the course, which every picture shows, or the keys (W and S
//! ahead and astern, A and D to turn), which take over at the first press.

use common::Input;
use common::winit::keyboard::KeyCode;

use crate::boat::{Helm, Orders};

/// Who sails: the course (pictures, and a window until a key is pressed)
/// or the keys.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Play {
    Course,
    Keys(Helm),
}

/// The orders the keys give this frame.
pub fn orders_from(input: &Input) -> Orders {
    Orders {
        ahead: input.held(KeyCode::KeyW),
        astern: input.held(KeyCode::KeyS),
        left: input.held(KeyCode::KeyA),
        right: input.held(KeyCode::KeyD),
    }
}
