//! Chapter 01: the first triangle. A vertex buffer, a WGSL shader pair and a
//! render pipeline: the three things every later picture is made of.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces other crates use.

// Lesson 1: one corner of the triangle as the GPU reads it, and the triangle's three.
pub mod vertex;
// Lesson 2: the render pipeline (shader stages, vertex layout, primitive,
// target format), and the chapter's smooth and flat pair.
pub mod pipeline;
// Lesson 3: the views, smooth and flat (interpolation switched off).
pub mod views;
// The chapter itself: the vertex buffer, the pipelines and the frame.
pub mod demo;

pub use demo::Triangle;
pub use pipeline::{build_pipeline, build_pipelines};
pub use vertex::{ColoredVertex, TRIANGLE};
pub use views::{CameraPreset, Settings, VIEW_TABLE};
