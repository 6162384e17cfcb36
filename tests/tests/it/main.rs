//! Workspace-level tests, one binary: the snapshot comparison and the
//! bless log, the bench tables' check, real references painted out, and
//! what needs more than one chapter's pieces (clip distances, the shader
//! panel, hot reload, light culling, the limits each chapter declares, chapter flags headless, the rocks'
//! levels of detail, chapter 04's fog, every shader translated for Metal,
//! Direct3D and WebGL2), and that no chapter's modules lean on
//! each other in a circle. (The snapshot test of every view
//! is its own harness, `tests/snapshots.rs`.)
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file here would be another link of all of them.

mod bench_tables;
mod blessings;
mod book_pages;
mod chapter_flags;
mod clipping;
mod comparison;
mod editor;
mod fog;
mod hot_reload;
mod light_culling;
mod limits;
mod lod_same_picture;
mod module_circles;
mod references;
mod rock_lod;
mod shader_files;
mod translation;
mod try_it_links;
