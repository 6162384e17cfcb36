//! Chapter 02: model, view and projection. A field of primitives, each
//! placed by its own model matrix, seen through a perspective camera you fly
//! with the keyboard and mouse, with a depth buffer sorting out what is in
//! front.
//!
//! The modules below come in the order the book's lessons explain them
//! (the camera's matrices and its fly controller are `common`'s, since
//! every 3D chapter uses them); the re-exports after them are the pieces
//! other crates use.

// Lesson 2, a fly camera: where the camera starts.
pub mod camera_presets;
// Lesson 3, primitives: the shapes, their placements and model matrices, the ground.
pub mod scene;
// Lesson 4, uniforms: the camera's and the objects', one buffer at dynamic offsets.
pub mod uniforms;
// Lesson 5, the depth buffer: the pipeline with a depth test, and the chapter's pipelines.
pub mod pipeline;
// Lesson 5, the depth buffer shown as a picture.
pub mod depth_display;
// The views: the scene, its normals, its depth buffer two ways.
pub mod views;
// The chapter itself: the camera, the frame, and the overlay's controls.
pub mod demo;

pub use camera_presets::{CameraPreset, start_camera};
pub use demo::CameraChapter;
pub use scene::{Placement, Shape, scene};
pub use views::{Display, Settings, VIEW_TABLE};
