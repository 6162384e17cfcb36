//! Chapter 06's integration tests, one binary: the sun in the sky is the
//! light on the ground, the day draws chapter 05's rocks as chapter 05
//! does, and the worked solutions to the exercises of chapter 06.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.
//! Chapters 04 and 05 have no test binary of their own: their solutions
//! and checks are in their libraries' unit tests. The tests here share one
//! device, so the terrain and the million rocks are made once for all of
//! them (`Gpu::cached`).

use std::sync::OnceLock;

use common::Gpu;

mod plain_rocks;
mod solutions;
mod sun;

/// The device every test here that draws the Mars plain shares, with the
/// needs of the plain (`instancing::gpu_needs`: chapter 03's, and indirect
/// draws for chapter 05's `multi-draw` view).
pub fn plain_gpu() -> &'static Gpu {
    static GPU: OnceLock<Gpu> = OnceLock::new();
    GPU.get_or_init(|| Gpu::headless(instancing::gpu_needs()).expect("an adapter (lavapipe will do)"))
}
