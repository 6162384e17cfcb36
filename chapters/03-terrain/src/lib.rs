//! Chapter 03: terrain from noise. Improved Perlin noise summed in octaves
//! makes a height map; the map is cut into chunks, and a quadtree over them
//! draws each part of the map with cells that look the same size on screen
//! near and far, morphing between levels, and skips what the camera cannot see.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// Improved Perlin noise and its octaves (fBm).
pub use common::noise;
// The height field: heights from noise, with a cliff, and normals.
pub mod heightfield;
// The height field cut into chunks, each with a bounding box.
pub mod chunks;
// Which chunks the camera can see.
pub mod culling;
// How far each level of detail reaches, and the morph between levels.
pub mod lod;
// The quadtree over the chunks, which chooses the patches to draw.
pub mod quadtree;
// The heights and normals on the GPU, and the one patch grid.
pub mod terrain_maps;
// The terrain made once per device, in steps, and shared.
pub mod terrain_data;
// The terrain ready to draw: a viewpoint per camera, the sun, the shading.
pub mod terrain_renderer;
// Walking on the ground, and never flying below it.
pub mod ground;
// The start camera, the close-up and the view from overhead.
pub mod cameras;
// The chapter itself: its settings, views and frame.
pub mod demo;

pub use cameras::start_camera;
pub use demo::{CameraPreset, Settings, TerrainChapter, VIEW_TABLE};
pub use lod::{Detail, LodRanges};
pub use quadtree::{Patch, Quadtree};
pub use terrain_data::TerrainData;
pub use terrain_maps::{PATCH_LAYOUT, TerrainMaps};
pub use terrain_renderer::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer, Viewpoint, gpu_needs};
