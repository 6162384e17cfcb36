//! What the chapter can show: the scene lit, its normals, or its depth
//! buffer as distance or as stored; the settings a view decides, and the
//! table of views.

use common::ViewRow;

use crate::camera_presets::CameraPreset;

/// What the picture shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    /// The scene, lit by a fixed sun.
    Shaded,
    /// World-space normals as colours.
    Normals,
    /// The depth buffer as distance.
    Depth,
    /// The depth buffer as stored.
    DepthRaw,
}

impl Display {
    /// Whether the picture is the depth buffer, read as data (drawn at one
    /// sample a pixel: a multisampled depth buffer would need a shader of
    /// its own).
    pub fn reads_depth(self) -> bool {
        matches!(self, Display::Depth | Display::DepthRaw)
    }
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    pub display: Display,
}

impl Settings {
    pub const DEFAULT: Self = Self { display: Display::Shaded };
}

/// Every view, with the settings it applies.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 5] = [
    ViewRow::mode("default", "the field of primitives, lit by a fixed sun", Settings::DEFAULT),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "depth",
        "the depth buffer as distance: black near, white at 25 m",
        Settings { display: Display::Depth },
    ),
    ViewRow::mode(
        "depth-raw",
        "the depth buffer as stored: almost everything is nearly 1",
        Settings { display: Display::DepthRaw },
    ),
    ViewRow::mode("normals", "world-space normals as colours", Settings { display: Display::Normals }),
];
