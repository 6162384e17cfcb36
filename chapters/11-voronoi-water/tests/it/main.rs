//! Chapter 11's integration tests, one binary: hot reload, the sea, and the Voronoi diagrams.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod hot_reload;
mod sea;
mod voronoi;
