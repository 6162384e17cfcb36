//! The plumbing every chapter shares, and two lessons of chapter 02 that
//! every later chapter builds on: the camera (`camera.rs`, which the
//! [`Chapter`] trait itself names) and the unit primitives
//! (`primitives.rs`). Page 02 teaches those two from here. Four small
//! helpers that later chapters need live here too, so that using them
//! does not make a chapter depend on unrelated chapters: Perlin noise and
//! fBm (`noise.rs`, taught on page 03), a seeded random number generator
//! (`rng.rs`, page 05), the sun's path through the day (`sun.rs`, page
//! 06), and an orbit camera (`orbit.rs`, page 07; chapter 11 sails with
//! it). Nothing else in this crate is a technique the book teaches.
//!
//! A chapter implements [`Chapter`]; its `main` calls [`run`]. From there
//! this crate opens a window with an egui overlay and hot-reloaded shaders,
//! or renders headless for `--screenshot`, `--bench` and the snapshot tests.

pub mod args;
pub mod book_figures;
#[cfg(target_arch = "wasm32")]
mod browser;
pub mod camera;
pub mod chapter;
mod cli;
pub mod draw_counts;
pub mod editor;
pub mod files;
pub mod fingerprint;
pub mod fullscreen;
pub mod gpu;
pub mod headless;
pub mod input;
pub mod leak;
pub mod memory;
pub mod mesh;
pub mod multisampling;
pub mod noise;
pub mod orbit;
mod overlay;
pub mod parallel;
pub mod pipeline;
pub mod preparation;
pub mod primitives;
mod probe;
pub mod reload;
pub mod rng;
pub mod shader;
pub mod sun;
mod surface;
pub mod texture;
pub mod timing;
#[cfg(target_arch = "wasm32")]
pub mod web;
mod window;

pub use camera::{Camera, CameraPlace, FlyController};
pub use chapter::{Chapter, ChapterFlag, FlagValues, Frame, Tolerance, View, ViewKind, ViewRow, views_of};
pub use cli::run;
pub use draw_counts::{DrawCounts, Drawn, PassCount};
pub use gpu::{Gpu, GpuNeeds, NoAdapter};
pub use input::Input;
pub use mesh::{Mesh, MeshData, Vertex};
pub use multisampling::{Antialiasing, SceneTargets, Target};
pub use orbit::Orbit;
pub use preparation::Preparation;
pub use reload::Reloadable;
pub use shader::{ShaderError, ShaderFile};
pub use timing::{PassTimer, Stats};

// Chapters use the same versions as `common` without listing them again.
pub use {anyhow, bytemuck, egui, glam, image, log, wgpu, winit};
