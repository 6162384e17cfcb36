//! Chapter 02's integration tests, one binary: the worked solutions to the
//! page's exercises. (The scene's own tests are unit tests in `src/`.)
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.

mod solutions;
