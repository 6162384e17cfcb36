//! Chapter 09's integration tests, one binary: GPU mipmaps, OBJ + MTL
//! models (`--model`), flat, Gouraud and Phong shading of textured
//! surfaces, tangents, and the worked solutions to the page's exercises.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod mipmaps;
mod models;
mod shading;
mod solutions;
mod tangents;
