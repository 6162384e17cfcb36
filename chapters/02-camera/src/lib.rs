//! Chapter 02: model, view and projection. A field of primitives, each
//! placed by its own model matrix, seen through a perspective camera you fly
//! with the keyboard and mouse, with a depth buffer sorting out what is in
//! front.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces other crates use.

// The field of primitives: shapes, placements and their model matrices.
pub mod scene;
// The camera's and the objects' uniforms, one buffer at dynamic offsets.
pub mod uniforms;
// The pipeline with a depth test.
pub mod pipeline;
// The depth buffer shown as a picture.
pub mod depth_display;
// The chapter itself: its settings, views, camera and frame.
pub mod demo;

pub use demo::{CameraChapter, CameraPreset, Display, Settings, VIEW_TABLE};
pub use scene::{Placement, Shape, scene};
