//! What the chapter can show: the settings a view decides (whether the
//! corners' colours are blended across the triangle) and the table of
//! views, each naming the settings it applies.

use common::ViewRow;

// ANCHOR: views
/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// Blend the corners' colours across the triangle (off: every pixel
    /// takes the first corner's colour).
    pub interpolate: bool,
}

impl Settings {
    pub const DEFAULT: Self = Self { interpolate: true };
}

/// The triangle has no camera, so no view is a preset: this enum has no values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {}

/// Every view, with the settings it applies.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 3] = [
    ViewRow::mode("default", "colours interpolated across the triangle", Settings::DEFAULT),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "flat",
        "interpolation off: one colour per triangle, from its first vertex",
        Settings { interpolate: false },
    ),
];
// ANCHOR_END: views
