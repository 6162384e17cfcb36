//! Chapter 11's integration tests, one binary: hot reload, the sea, the
//! Voronoi diagrams, and the worked solutions to the page's exercises.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod hot_reload;
mod sea;
mod solutions;
mod voronoi;
