//! Keyboard and mouse state gathered by the window runner, handed to a
//! chapter once per frame.

use std::collections::HashSet;

use glam::Vec2;
use winit::keyboard::KeyCode;

/// What the learner is doing with keyboard and mouse this frame.
#[derive(Debug, Default, Clone)]
pub struct Input {
    held: HashSet<KeyCode>,
    pressed: HashSet<KeyCode>,
    /// Mouse movement since the last frame, in pixels, while looking around
    /// (left button held over the scene, or the pointer locked with Tab).
    pub look: Vec2,
    /// Scroll since the last frame, in lines (positive away from the user).
    pub scroll: f32,
}

impl Input {
    /// The key is down now.
    pub fn held(&self, key: KeyCode) -> bool {
        self.held.contains(&key)
    }

    /// How many keys are down now.
    pub fn held_count(&self) -> usize {
        self.held.len()
    }

    /// The key went down during this frame.
    pub fn pressed(&self, key: KeyCode) -> bool {
        self.pressed.contains(&key)
    }

    pub fn key_down(&mut self, key: KeyCode) {
        if self.held.insert(key) {
            self.pressed.insert(key);
        }
    }

    pub fn key_up(&mut self, key: KeyCode) {
        self.held.remove(&key);
    }

    /// Forget held keys, e.g. when the window loses focus and key-up
    /// events would never arrive.
    pub fn release_all(&mut self) {
        self.held.clear();
    }

    /// Called after each frame: per-frame events are consumed.
    pub fn end_frame(&mut self) {
        self.pressed.clear();
        self.look = Vec2::ZERO;
        self.scroll = 0.0;
    }
}
