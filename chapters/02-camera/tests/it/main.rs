//! Chapter 02's tests, one binary: the scene's model matrices, what a
//! frame draws and where `--camera` puts the eye, and the worked solutions
//! to the page's exercises. (The library has no unit tests: a second test
//! binary would be one more link of wgpu.)
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.

mod counts_and_places;
mod scene;
mod solutions;
