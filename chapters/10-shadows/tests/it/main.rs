//! Chapter 10's integration tests, one binary: what a frame draws, the
//! game, hot reload, the physics, the shadow maps, the cascades' fitting,
//! the lantern's cube shadow map, and the worked solutions to the page's
//! exercises.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod cascades;
mod draw_counts;
mod game;
mod hot_reload;
mod physics;
mod point_shadows;
mod shadow_maps;
mod solutions;
