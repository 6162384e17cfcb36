//! Chapter 03: terrain from noise. Improved Perlin noise summed in octaves
//! makes a height map; the map is cut into chunks, and a quadtree over them
//! draws each part of the map with cells that look the same size on screen
//! near and far, morphing between levels, and skips what the camera cannot see.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// Improved Perlin noise and its octaves (fBm). (Lesson: noise and octaves.)
pub use common::noise;
// The height field: heights from noise, with a cliff, and normals from the
// whole field. (Lesson: the height field, its mesh and its normals.)
pub mod heightfield;
// The height field cut into chunks, each with a bounding box. (Lesson:
// chunks and frustum culling, with the next module.)
pub mod chunks;
// Which chunks the camera can see.
pub mod culling;
// How far each level of detail reaches, and the morph between levels.
// (Lessons: levels of detail, and the morph.)
pub mod lod;
// The quadtree over the chunks, which chooses the patches to draw.
pub mod quadtree;
// The heights and normals on the GPU, and the one patch grid.
pub mod terrain_maps;
// The terrain made once per device, in steps, and shared.
pub mod terrain_data;
// The terrain ready to draw: a viewpoint per camera, the sun, the shading.
pub mod terrain_renderer;
// Walking on the ground, and never flying below it. (Lesson: colour and
// walking.)
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
