//! Chapter 10: shadows. A side-scrolling game whose level is lit by a sun
//! that casts shadows: the scene is drawn twice, once from the sun into a
//! shadow map (depth only), then from the camera, each fragment asking the
//! map whether the sun can see it. A lantern in the tunnel does the same
//! for a light that shines every way, with six maps on a cube. Around it,
//! the small engine of the seed: boxes that collide, a player who runs and
//! jumps, and background layers that scroll at their own rates.
//!
//! The modules below come in the order the book's lessons teach them; the
//! re-exports after them are the pieces later chapters, the tests and the
//! diagrams compose.

// A shadow map in two passes: the map, its pass, its lookups and filters.
pub mod shadow_map;
// The second pass: lit models, the sun scaled by what the map says.
pub mod shadowed_renderer;
// The sun's box: fitted to what the camera sees, snapped to texels.
pub mod light_box;
// Cascades: the view cut by distance, a map for each slice (for scenes
// kilometres deep).
pub mod cascades;
// The lantern's cube shadow map: six faces, compared by distance.
pub mod point_shadow;
// The game: boxes that fall, slide and stop against other boxes,
pub mod physics;
// the level, the player and the script that plays it in fixed steps,
pub mod game;
// and who plays, the script or the keys.
pub mod play;
// Parallax: background layers that scroll at their own rates.
pub mod parallax;
// The level as things to draw, the lantern, and the sun's path.
pub mod scene;
// The level on the GPU: models, instances and the passes' draw lists.
pub mod level_models;
// The side camera and the lantern view's preset.
pub mod camera_presets;
// Lines over the picture: collision boxes, the sun's box.
pub mod lines;
// The views and the settings each applies.
pub mod views;
// The chapter's wiring: new, views applied, play, the frame, the overlay.
pub mod demo;

pub use camera_presets::{CAMERA_DISTANCE, CameraPreset, lantern_camera, side_camera};
pub use demo::ShadowsChapter;
pub use light_box::visible_part;
pub use play::controls_from;
pub use point_shadow::PointShadow;
pub use shadowed_renderer::ShadowedRenderer;
pub use views::{DAY_SECONDS, Fit, Settings, Show, VIEW_TABLE};
