//! Chapter 10: shadows.

pub mod physics;
