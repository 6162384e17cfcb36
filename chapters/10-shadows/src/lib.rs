//! Chapter 10: shadows. A side-scrolling game whose level is lit by a sun
//! that casts shadows: the scene is drawn twice, once from the sun into a
//! shadow map (depth only), then from the camera, each fragment asking the
//! map whether the sun can see it. A lantern in the tunnel does the same
//! for a light that shines every way, with six maps on a cube. Around it,
//! the small engine of the seed: boxes that collide, a player who runs and
//! jumps, and background layers that scroll at their own rates.
//!
//! The modules below come in the order the book explains them; the
//! re-exports after them are the pieces later chapters compose.

// The sun's box, the shadow map, its pass and its filters.
pub mod shadow_map;
// The lantern's cube shadow map: six faces, compared by distance.
pub mod point_shadow;
// Boxes that fall, slide and stop against other boxes.
pub mod physics;
// The level, the player, and the script that plays it.
pub mod game;
// Background layers that scroll at their own rates.
pub mod parallax;
// Textured, lit models with the sun scaled by the shadow map.
pub mod shadowed_renderer;
// The level as things to draw, and the sun's path.
pub mod scene;
// Lines over the picture: collision boxes, the sun's box.
pub mod lines;
// The chapter itself: its settings, views, camera, play and frame.
pub mod demo;

pub use demo::{
    CAMERA_DISTANCE, CameraPreset, DAY_SECONDS, Fit, Settings, ShadowsChapter, Show, VIEW_TABLE, controls_from,
    lantern_camera, side_camera, visible_part,
};
pub use point_shadow::PointShadow;
pub use shadowed_renderer::ShadowedRenderer;
