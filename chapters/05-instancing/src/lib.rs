//! Chapter 05: instancing. One rock mesh, a million rocks over the whole
//! map, drawn a few instanced calls in all; first culled by chunk on the
//! CPU, then rock by rock on the GPU, where a compute pass (the course's
//! first) keeps the rocks in view, grades them by their size on screen and
//! writes the indirect draws of three levels of detail. And the same rocks
//! drawn one call at a time, to see why it matters. The scene is the Mars
//! plain so far: terrain, fog and rocks, put together as a `MarsPlain` that
//! chapters 06 and 07 reuse.
//!
//! The modules below come in the order the book's lessons explain them,
//! each using only those above it; the re-exports after them are the
//! pieces later chapters compose.

// A tiny seeded random number generator (SplitMix64).
pub use common::rng;
// The rock's mesh, at three levels of detail (lessons 1 and 5).
pub mod rock_mesh;
// Per-instance records, their vertex layout, and the scatter (lesson 1).
pub mod rock_scatter;
// The camera standing on the plain, which the groups are sorted from.
pub mod cameras;
// The rocks grouped by terrain chunk, and the groups a camera keeps (lesson 2).
pub mod rock_groups;
// The rocks on the GPU, made once and shared: the instance buffer (lesson 1).
pub mod rock_field;
// How big a rock looks, and the sizes that pick its level (lesson 5).
pub mod size_on_screen;
// Reading the GPU's counts back, at once or a frame late (lesson 6).
pub mod read_back;
// The rocks culled and graded per rock on the GPU: a compute pass (lessons 3 and 4).
pub mod rock_culling;
// What the GPU's culling needs of a device, and what is missing (lesson 6).
pub mod capabilities;
// Terrain, fog and rocks together, each picture with its own viewpoint;
// the rocks drawn instanced, one per call or from a list (lessons 1 and 2).
pub mod mars_plain;
// GPU memory against map size, as the Mars project measured its memory.
pub mod map_memory;
// The chapter's views, each a setup of the plain.
pub mod views;
// The chapter itself: its overlay and frame.
pub mod demo;
// The worked solutions to the lessons' exercises, each a test.
#[cfg(test)]
mod solutions;
// The GPU's culling checked against counts and levels worked out here.
#[cfg(test)]
mod culling_checks;

pub use cameras::{CameraPreset, plain_camera};
pub use capabilities::missing_capability;
pub use demo::InstancingChapter;
pub use mars_plain::{Culling, DrawCalls, MarsPlain, Mode, PlainViewpoint, RocksDrawn, Setup, gpu_needs};
pub use rng::Rng;
pub use rock_culling::{RockCulling, RockLists, RockSource, WORKGROUP_SIZE};
pub use rock_field::{MAX_ONE_PER_DRAW, RockField};
pub use rock_groups::{RockGroup, RockRuns, chunk_of, group_by_chunk, visible_runs};
pub use rock_mesh::{LEVELS, rock_levels, rock_mesh};
pub use rock_scatter::{ATTEMPTS_PER_ROCK, MAX_ROCKS, RockInstance, SEED, rocks_on_map, scatter};
pub use size_on_screen::{Grading, Picture};
pub use views::VIEW_TABLE;
