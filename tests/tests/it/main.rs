//! Workspace-level tests that need more than one chapter's pieces, one binary: clip distances, the shader panel, hot reload, light culling, chapter flags headless, the rocks' levels of detail. (The snapshot comparison is its own harness, `tests/snapshots.rs`.)
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod chapter_flags;
mod clipping;
mod editor;
mod hot_reload;
mod light_culling;
mod rock_lod;
mod try_it_links;
