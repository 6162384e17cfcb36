//! Chapter 11: Voronoi water. A boat sails an endless toon sea at sunset.
//! The water's pattern is a Voronoi diagram made on the GPU every frame,
//! by drawing cones with a depth test or by jump flooding, then coloured,
//! blurred and edged with foam; the sea is one fixed grid that follows the
//! boat, its waves worked out in the vertex shader from where each vertex
//! is in the world; the boat's sail fills with the wind across it. The
//! finale: it composes chapter 07's waves, chapter 08's light and bloom,
//! chapter 09's model loader and chapter 10's shadow map.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them keep the demo's names at the crate's root.

// The diagram's sites: points in the tile that wander.
pub mod sites;
// The diagram on the GPU, by cones or by jump flooding.
pub mod voronoi;
// From the diagram to the water's texture: colours, blur, foam.
pub mod water_texture;
// The endless sea on one fixed grid that follows the boat.
pub mod sea;
// Where the boat sails, and how it rides the waves.
pub mod boat;
// Its sail, which fills with the wind, and its sailor.
pub mod sail;
// Colour from gradients: the sky, the sun's light, the islands.
pub mod atmosphere;
// Islands on the horizon.
pub mod islands;
// The chapter itself: its settings, views, camera, clock and frame.
pub mod demo;

pub use demo::{
    CameraPreset, DayClock, HIGH_ORBIT, Play, SAIL_ORBIT, SNAPSHOT_TIME, SUNSET_ORBIT, Settings, Show, VIEW_TABLE,
    VoronoiWaterChapter, orbit_camera, orders_from,
};
