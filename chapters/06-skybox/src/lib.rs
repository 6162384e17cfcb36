//! Chapter 06: a sky box. Two cube maps, day and night, blended by the time
//! of day and turning with it; the sun painted in the day sky is the light
//! the ground is lit by, and the fog takes the colour of the sky's horizon.
//! The scene is chapter 05's Mars plain, under a `Sky` that chapter 07 reuses.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// The sun's path: the sky's turn at a time of day, the sun, the day blend.
pub use common::sun as sun_path;
// The sky: cube maps, their horizon colour, a viewpoint per camera, the draw.
pub mod sky;
// The chapter itself: its settings, views, cameras and frame.
pub mod demo;

pub use demo::{CameraPreset, Settings, SkyboxChapter, VIEW_TABLE};
pub use sky::{DAY, NIGHT, Sky, SkyViewpoint, horizon_colour};
pub use sun_path::{SUNRISE, celestial_turn, day_blend, sun_at};
