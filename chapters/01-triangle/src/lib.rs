//! Chapter 01: the first triangle. A vertex buffer, a WGSL shader pair and a
//! render pipeline: the three things every later picture is made of.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces other crates use.

// One corner of the triangle as the GPU reads it, and the triangle's three.
pub mod vertex;
// The render pipeline: shader stages, vertex layout, primitive, target format.
pub mod pipeline;
// The chapter itself: its settings, views and frame.
pub mod demo;

pub use demo::{CameraPreset, Settings, Triangle, VIEW_TABLE};
pub use pipeline::build_pipeline;
pub use vertex::{ColoredVertex, TRIANGLE};
