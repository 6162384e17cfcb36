//! What each view of the lake decides, written once as a table: the
//! water's settings (its style, its waves, Fresnel or not), which picture
//! reaches the screen (the lake, or the reflection or refraction picture
//! alone, to see what the water reads), whether the plain is drawn at its
//! levels of detail, and, for a preset, where the camera stands.

use common::ViewRow;

use crate::camera_presets::CameraPreset;
use crate::water_renderer::{Style, WaterSettings};

/// What reaches the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    /// The lake, with everything around it.
    Lake,
    /// The reflection picture, full screen.
    Reflection,
    /// The refraction picture, full screen.
    Refraction,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub water: WaterSettings,
    pub display: Display,
    /// The plain in every picture as drawn before levels of detail
    /// (`Setup::at_full_detail`).
    pub full_detail: bool,
}

impl Settings {
    pub const DEFAULT: Self = Self { water: WaterSettings::DEFAULT, display: Display::Lake, full_detail: false };
}

/// Every view, with the settings it applies and, for a preset, its camera.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 8] = [
    ViewRow::mode(
        "default",
        "the lake: reflection and refraction mixed by Fresnel, ripples and waves",
        Settings::DEFAULT,
    ),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "reflection",
        "the reflection picture, full screen: the scene above the water, from below it",
        Settings { display: Display::Reflection, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "refraction",
        "the refraction picture, full screen: the scene below the water",
        Settings { display: Display::Refraction, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "waves",
        "the geometric waves three times as strong, seen from 6 m above the water",
        Settings { water: WaterSettings { wave_strength: 3.0, ..WaterSettings::DEFAULT }, ..Settings::DEFAULT },
        CameraPreset::CloseToWater,
    ),
    ViewRow::mode(
        "no-fresnel",
        "reflection and refraction half and half at every angle",
        Settings { water: WaterSettings { fresnel: false, ..WaterSettings::DEFAULT }, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "textured-waves",
        "seed 003's style: a tiled water texture pushed aside by its own colours, on the waves three times as strong",
        Settings {
            water: WaterSettings { style: Style::Texture, wave_strength: 3.0, ..WaterSettings::DEFAULT },
            ..Settings::DEFAULT
        },
        CameraPreset::CloseToWater,
    ),
    ViewRow::bench(
        "full-detail",
        "bench: the lake as drawn before levels of detail, terrain and rocks at full detail in all three pictures",
        Settings { full_detail: true, ..Settings::DEFAULT },
    ),
];
