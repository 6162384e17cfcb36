//! Chapter 10's integration tests, one binary: the game, hot reload, the physics, and the shadow maps.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod game;
mod hot_reload;
mod physics;
mod shadow_maps;
