//! Chapter 03's integration tests, one binary: the terrain made in steps,
//! the `--walk` switch, and the worked solutions to the page's exercises.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.

mod prepare;
mod solutions;
mod walk;
