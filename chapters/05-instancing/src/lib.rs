//! Chapter 05: instancing. One rock mesh, a million rocks over the whole
//! map, grouped by terrain chunk so that only the groups in view are drawn,
//! a few instanced calls in all; and the same rocks drawn one call at a
//! time, to see why it matters. The scene is the Mars plain so far:
//! terrain, fog and rocks, put together as a `MarsPlain` that chapters 06
//! and 07 reuse.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// A tiny seeded random number generator (SplitMix64).
pub use common::rng;
// The one rock mesh: a randomised, flat-shaded icosahedron.
pub mod rock_mesh;
// Per-instance records, the scatter, and the rocks on the GPU.
pub mod rock_field;
// The rocks grouped by terrain chunk, and the groups a camera keeps.
pub mod rock_groups;
// Terrain, fog and rocks together, drawn instanced or one call per rock.
pub mod mars_plain;
// GPU memory against map size, as the Mars project measured its memory.
pub mod map_memory;
// The chapter itself: its views and frame.
pub mod demo;

pub use demo::{CameraPreset, InstancingChapter, VIEW_TABLE};
pub use mars_plain::{DrawCalls, MarsPlain, Mode, Setup, gpu_needs, plain_camera};
pub use rng::Rng;
pub use rock_field::{ATTEMPTS_PER_ROCK, MAX_ONE_PER_DRAW, MAX_ROCKS, RockField, RockInstance, rocks_on_map, scatter};
pub use rock_groups::{RockGroup, RockRuns, chunk_of, group_by_chunk, visible_runs};
pub use rock_mesh::rock_mesh;
