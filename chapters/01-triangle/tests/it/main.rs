//! Chapter 01's integration tests, one binary: the triangle renders where
//! it should, and the worked solutions to the page's exercises.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.

mod antialiasing;
mod render;
mod solutions;
