//! Chapter 05: instancing. One rock mesh, a million rocks over the whole
//! map, drawn a few instanced calls in all; first culled by chunk on the
//! CPU, then rock by rock on the GPU, where a compute pass (the course's
//! first) keeps the rocks in view, grades them by their size on screen and
//! writes the indirect draws of three levels of detail. And the same rocks
//! drawn one call at a time, to see why it matters. The scene is the Mars
//! plain so far: terrain, fog and rocks, put together as a `MarsPlain` that
//! chapters 06 and 07 reuse.
//!
//! The modules below come in the order the book explains them, each using
//! only those above it; the re-exports after them are the pieces later
//! chapters compose.

// A tiny seeded random number generator (SplitMix64).
pub use common::rng;
// The rock's mesh, at three levels of detail.
pub mod rock_mesh;
// Per-instance records, and the scatter.
pub mod rock_scatter;
// The rocks grouped by terrain chunk, and the groups a camera keeps.
pub mod rock_groups;
// The camera standing on the plain.
pub mod cameras;
// The rocks on the GPU, made once and shared.
pub mod rock_field;
// The rocks culled and graded per rock on the GPU: a compute pass.
pub mod rock_culling;
// Terrain, fog and rocks together, each picture with its own viewpoint.
pub mod mars_plain;
// GPU memory against map size, as the Mars project measured its memory.
pub mod map_memory;
// The chapter itself: its views and frame.
pub mod demo;

pub use cameras::plain_camera;
pub use demo::{CameraPreset, InstancingChapter, VIEW_TABLE};
pub use mars_plain::{Culling, DrawCalls, MarsPlain, Mode, PlainViewpoint, RocksDrawn, Setup, gpu_needs};
pub use rng::Rng;
pub use rock_culling::{Grading, Picture, RockCulling, RockLists, RockSource, WORKGROUP_SIZE, missing_capability};
pub use rock_field::{MAX_ONE_PER_DRAW, RockField};
pub use rock_groups::{RockGroup, RockRuns, chunk_of, group_by_chunk, visible_runs};
pub use rock_mesh::{LEVELS, rock_levels, rock_mesh};
pub use rock_scatter::{ATTEMPTS_PER_ROCK, MAX_ROCKS, RockInstance, SEED, rocks_on_map, scatter};
