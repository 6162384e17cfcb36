//! Chapter 03: terrain from noise. Improved Perlin noise summed in octaves
//! makes a height map; the map is cut into chunks, and a quadtree over them
//! draws each part of the map with cells that look the same size on screen
//! near and far, morphing between levels, and skips what the camera cannot see.
//!
//! The modules below come in the order the book's lessons explain them;
//! the re-exports after them are the pieces later chapters compose.

// Lesson 1, noise and octaves: improved Perlin noise and fBm.
pub use common::noise;
// Lesson 2, the height field: heights from noise, with a cliff, and
// normals from the whole field.
pub mod heightfield;
// Lesson 2: the heights and normals on the GPU, and the grid's index list
// (its per-patch layout is lesson 4's).
pub mod terrain_maps;
// Lesson 3, chunks and frustum culling: the chunks' boxes...
pub mod chunks;
// ...and the camera's six planes, which skip the boxes out of view.
pub mod culling;
// Lessons 4 and 5: how far each level of detail reaches, and the morph.
pub mod lod;
// Lesson 4, the quadtree over the chunks, which chooses the patches to
// draw (and lesson 5, the largest node, where the morph must start).
pub mod quadtree;
// Lesson 4: the terrain made once per device, in steps, and shared.
pub mod terrain_data;
// Lesson 4: the terrain ready to draw, a viewpoint per camera.
pub mod terrain_renderer;
// Lesson 6: walking on the ground, and never flying below it.
pub mod ground;
// The start camera, the close-up preset and the view from overhead.
pub mod cameras;
// The views, as one table of what each decides.
pub mod views;
// The chapter itself: only its wiring, `impl Chapter` and the overlay.
pub mod demo;

pub use cameras::{CameraPreset, start_camera};
pub use demo::TerrainChapter;
pub use lod::{Detail, LodRanges};
pub use quadtree::{Patch, Quadtree};
pub use terrain_data::TerrainData;
pub use terrain_maps::{PATCH_LAYOUT, TerrainMaps};
pub use terrain_renderer::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer, Viewpoint, gpu_needs};
pub use views::{Settings, VIEW_TABLE};
