//! Chapter 09's integration tests, one binary: GPU mipmaps, OBJ + MTL models (`--model`), and tangents.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod mipmaps;
mod models;
mod tangents;
