//! common's integration tests, one binary: cube maps, `Gpu::cached`, an
//! adapter refused for what a chapter needs, readback, and every WGSL file
//! in `shaders/` composed and validated.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod cubemap;
mod gpu_cache;
mod needs;
mod readback;
mod shaders;
