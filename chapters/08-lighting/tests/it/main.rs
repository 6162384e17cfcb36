//! Chapter 08's integration tests, one binary: the bloom chain, `--camera`
//! on a riding view, light extremes, the three shading models and the three terms of the light,
//! the worked solutions to the lessons' exercises, the tone map pass
//! against its Rust mirror, FXAA on edges whose coverage is known, and the
//! physics of Cook-Torrance.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod bloom;
mod camera_flag;
mod extremes;
mod fxaa;
mod pbr;
mod prefiltered_sky;
mod shading;
mod solutions;
mod tone_map;
