//! Chapter 03: terrain from noise. Improved Perlin noise summed in octaves
//! makes a height map; the map is cut into chunks that share one index
//! buffer; chunks the camera cannot see are skipped before drawing.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// Improved Perlin noise and its octaves (fBm).
pub use common::noise;
// The height field: heights from noise, with a cliff, and normals.
pub mod heightfield;
// The height field cut into chunks: vertices, shared indices, bounding boxes.
pub mod chunks;
// Every chunk on the GPU in one buffer, and the vertex layout.
pub mod terrain_mesh;
// The terrain made once per device, in steps, and shared.
pub mod terrain_data;
// The terrain ready to draw: a viewpoint per camera, the sun, the shading.
pub mod terrain_renderer;
// Which chunks the camera can see.
pub mod culling;
// How finely each part of the terrain is drawn.
pub mod lod;
// Walking on the ground, and never flying below it.
pub mod ground;
// The start camera, the close-up and the view from overhead.
pub mod cameras;
// The chapter itself: its settings, views and frame.
pub mod demo;

pub use cameras::start_camera;
pub use demo::{CameraPreset, Settings, TerrainChapter, VIEW_TABLE};
pub use lod::Detail;
pub use terrain_data::TerrainData;
pub use terrain_mesh::{TERRAIN_VERTEX_LAYOUT, TerrainMesh};
pub use terrain_renderer::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer, Viewpoint, gpu_needs};
