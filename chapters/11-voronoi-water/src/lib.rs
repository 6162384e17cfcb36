//! Chapter 11: Voronoi water. A boat sails an endless toon sea at sunset.
//! The water's pattern is a Voronoi diagram made on the GPU every frame,
//! by drawing cones with a depth test or by jump flooding, then coloured,
//! blurred and edged with foam; the sea is one fixed grid that follows the
//! boat, its waves worked out in the vertex shader from where each vertex
//! is in the world; the boat's sail fills with the wind across it. The
//! finale: it composes chapter 07's waves, chapter 08's light and bloom,
//! chapter 09's model loader and chapter 10's shadow map.
//!
//! The modules below come in the order the book's lessons teach them; the
//! re-exports after them keep the demo's names at the crate's root.

// Lesson 1: the diagram's sites, points in the tile that wander.
pub mod sites;
// Lessons 1 and 2: the diagram on the GPU, by cones or by jump flooding.
pub mod voronoi;
// Lesson 3: from the diagram to the water's texture: colours, blur, foam.
pub mod water_texture;
// Lesson 4: the endless sea on one fixed grid that follows the boat.
pub mod sea;
// Lesson 5: where the boat sails, and how it rides the waves.
pub mod boat;
// Lesson 5: who sails, the course or the keys.
pub mod steering;
// Lesson 5: its sail, which fills with the wind, and its sailor.
pub mod sail;
// Lesson 5: the boat, sail and sailor as models, placed by one instance.
pub mod boat_models;
// Lesson 6: colour from gradients: the sky, the sun's light, the islands.
pub mod atmosphere;
// Lesson 6: the day's clock, which moves the sun.
pub mod day_clock;
// Lesson 6: islands on the horizon.
pub mod islands;
// Lesson 6: the boat's shadow, the sun's box fitted around it.
pub mod boat_shadow;
// The views, each once: the settings they apply.
pub mod views;
// Where the camera goes: round the boat, and the views' presets.
pub mod camera_presets;
// The chapter itself: its frame, its keys and its overlay.
pub mod demo;

pub use camera_presets::{CameraPreset, HIGH_ORBIT, SAIL_ORBIT, SUNSET_ORBIT, orbit_camera};
pub use day_clock::DayClock;
pub use demo::VoronoiWaterChapter;
pub use steering::{Play, orders_from};
pub use views::{SNAPSHOT_TIME, Settings, Show, VIEW_TABLE};
