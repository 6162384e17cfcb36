//! Chapter 10: shadows.

pub mod game;
pub mod physics;
