//! Chapter 02's integration tests, one binary: what a frame draws and
//! where `--camera` puts the eye, and the worked solutions to the page's
//! exercises. (The scene's own tests are unit tests in `src/`.)
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.

mod counts_and_places;
mod solutions;
