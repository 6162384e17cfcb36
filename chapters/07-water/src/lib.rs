//! Chapter 07: water. A lake on the Mars plain, drawn from two extra
//! pictures of the scene each frame (one reflected in the water, one seen
//! through it), mixed by the Fresnel effect, rippled by a DuDv map, lit
//! by a normal map, and moved by eight sine waves, each editable live. Or
//! drawn in seed 003's style: a tiled water texture, scrolled and pushed
//! aside by its own colours. The Mars scene, complete, flown over or
//! orbited.
//!
//! The modules below come in the order the book's lessons teach them; the
//! re-exports after them are the pieces other crates use.

// Where the lake is, the camera at its shore, and the mirrored camera.
pub mod lake;
// The scene (chapter 05's plain, chapter 06's sky) as pictures from any camera, clipped at the water.
pub mod scene_pictures;
// The water: reflection and refraction pictures, and the surface reading them.
pub mod water_renderer;
// Geometric waves: a sum of sine waves, with analytic normals, and the set the overlay edits.
pub mod waves;
// Fly over the lake, or orbit a point on it.
pub mod steering;
// Where the views put the camera.
pub mod camera_presets;
// What each view decides: the water's settings, what reaches the screen.
pub mod views;
// The chapter itself: its overlay and its frame.
pub mod demo;
// Worked solutions to the lessons' exercises, built and checked by `cargo test`.
#[cfg(test)]
mod solutions;

pub use camera_presets::CameraPreset;
pub use demo::WaterChapter;
pub use lake::{find_lake, lake_camera, mirrored, orbit_point};
pub use steering::Steering;
pub use views::{Display, Settings, VIEW_TABLE};
pub use water_renderer::{Picture, Style, WaterRenderer, WaterSettings};
pub use waves::WaveSet;
