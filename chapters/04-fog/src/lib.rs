//! Chapter 04: exponential distance fog. Chapter 03's terrain, seen
//! through air that thickens with distance and fades into the sky, which
//! also lets the far plane come in and the distant chunks go.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// Density and gradient: visibility, the opaque distance, the far plane.
pub mod fog_settings;
// The fog's uniform and bind group (group 1 of `fog.wgsl`), and its shader.
pub mod fog_binding;
// The chapter itself: its views and frame.
pub mod demo;
// The worked solutions to the lessons' exercises, each a test.
#[cfg(test)]
mod solutions;

pub use demo::{CameraPreset, FogChapter, Settings, VIEW_TABLE};
pub use fog_binding::{FogBinding, fog_shader};
pub use fog_settings::{FogSettings, MAX_FAR};
