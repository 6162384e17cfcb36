//! Chapter 09: textures. Chapter 08's city gets brick, concrete, metal,
//! roads and lit windows; its cars become a model loaded from OBJ and MTL
//! files. On the way: texture coordinates and texel density, sampling and
//! mipmaps, colour spaces, tangent space and normal maps, and reading
//! whatever model a learner brings (`--model PATH.obj`).
//!
//! The modules below come in the order the book's lessons teach them; the
//! re-exports after them are the pieces later chapters compose.

// Texture coordinates: what the chapter draws, as data, each texture at its
// size in metres (texel density); and which set a camera is in.
pub mod scenes;
// Sampling: materials on the GPU, their samplers (nearest to anisotropic),
// and textures uploaded in the right colour space.
pub mod materials;
// sRGB: mip chains made on the GPU, averaged in linear light.
pub mod mipmaps;
// Models: the textured vertex, models with a range of indices per material, instances.
pub mod mesh;
// Models: OBJ and MTL files, read and made drawable, messy ones repaired.
pub mod obj;
// The textures and models carried inside the binary.
pub mod builtin;
// Bringing your own model: the featured model on the stage, the car or `--model`'s.
pub mod featured;
// Normal maps: the tangent frame they need, per vertex or per face.
pub mod tangents;
// Flat, Gouraud and Phong: textured, normal-mapped, lit models drawn into a pass.
pub mod textured_renderer;
// Everything drawn, assembled: the built-in models and each frame's draws.
pub mod drawables;
// The views and the settings each applies.
pub mod views;
// Where each view puts the camera.
pub mod camera_presets;
// The chapter itself: its models, frame and overlay.
pub mod demo;

pub use camera_presets::CameraPreset;
pub use demo::TexturesChapter;
pub use drawables::BuiltinModels;
pub use featured::Featured;
pub use scenes::Scene;
pub use textured_renderer::{Draw, DrawList, SurfaceOptions, TexturedRenderer, upload_model};
pub use views::{Settings, Tangents, VIEW_TABLE};
