//! Chapter 09: textures. Chapter 08's city gets brick, concrete, metal,
//! roads and lit windows; its cars become a model loaded from OBJ and MTL
//! files. On the way: texture coordinates and texel density, sampling and
//! mipmaps, colour spaces, tangent space and normal maps, and reading
//! whatever model a learner brings (`--model PATH.obj`).
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// The tangent frame normal maps need, per vertex or per face.
pub mod tangents;
// The textured vertex, models with a range of indices per material, instances.
pub mod mesh;
// OBJ and MTL files, read and made drawable.
pub mod obj;
// The textures and models carried inside the binary.
pub mod builtin;
// Materials on the GPU: textures in the right colour space, samplers.
pub mod materials;
// Mip chains made on the GPU.
pub mod mipmaps;
// What the chapter draws, as data: the textured city, the stage, the lab.
pub mod scenes;
// Textured, normal-mapped, lit models drawn into a pass.
pub mod textured_renderer;
// The chapter itself: its settings, views, models and frame.
pub mod demo;

pub use demo::{BuiltinModels, CameraPreset, Featured, Scene, Settings, Tangents, TexturesChapter, VIEW_TABLE};
pub use textured_renderer::{Draw, DrawList, SurfaceOptions, TexturedRenderer, upload_model};
