//! The chapter's views, one row each, and the settings a view applies:
//! the time of day, the shading, the sampler, normal maps on or off, the
//! colour spaces right or swapped, tangents per vertex or per face. Each
//! lesson runs the views that show its idea; the overlay changes the same
//! settings live.

use common::ViewRow;
use lighting::Shading;
use lighting::lights::TimeOfDay;

use crate::camera_presets::CameraPreset;
use crate::materials::SamplerMode;

// ANCHOR: views
/// Every view, once: what it shows, and for a preset where the camera goes.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 16] = [
    ViewRow::mode("day", "the textured city at noon, from above", Settings::DAY),
    ViewRow::mode(
        "night",
        "the textured city at night: lit windows, lamps, headlights",
        Settings { time_of_day: TimeOfDay::Night, ..Settings::DAY },
    ),
    ViewRow::preset(
        "car",
        "the car model and its five materials on the stage (or the model given with --model)",
        Settings::STAGE,
        CameraPreset::Car,
    ),
    ViewRow::preset(
        "normal-maps",
        "the stage in a low sun: normal maps give brick, panels and concrete their relief",
        Settings::STAGE,
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "no-normal-maps",
        "the same without normal maps: flat, as if painted",
        Settings { normal_maps: false, ..Settings::STAGE },
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "gouraud",
        "the same stage lit per vertex, the textures still read per pixel: no relief, the lamp's pool smeared",
        Settings { shading: Shading::Gouraud, ..Settings::STAGE },
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "flat",
        "lit once per face: facets of one light each, the bricks still sharp within them",
        Settings { shading: Shading::Flat, ..Settings::STAGE },
        CameraPreset::Wall,
    ),
    ViewRow::preset(
        "vertex-tangents",
        "close over the sphere's pole in a low evening sun, one tangent per vertex: the joints' bevels shade smoothly",
        Settings { time_of_day: TimeOfDay::Evening, ..Settings::STAGE },
        CameraPreset::SphereTop,
    ),
    ViewRow::preset(
        "face-tangents",
        "the same with one tangent per triangle, as the seed did: the bevels' shading jumps at every edge",
        Settings { time_of_day: TimeOfDay::Evening, tangents: Tangents::PerFace, ..Settings::STAGE },
        CameraPreset::SphereTop,
    ),
    ViewRow::preset(
        "tbn",
        "the tangent frame as colours: tangent (left third), bitangent (middle), normal (right)",
        Settings { show_frame: true, ..Settings::STAGE },
        CameraPreset::WholeStage,
    ),
    ViewRow::preset(
        "wrong-colour-space",
        "albedo read as data and normal maps as sRGB: washed-out colour, bent light",
        Settings { swapped_colour_spaces: true, ..Settings::STAGE },
        CameraPreset::Car,
    ),
    ViewRow::preset(
        "nearest",
        "a checkerboard to the horizon, nearest texel: blocky near, moiré far",
        Settings { sampler: SamplerMode::Nearest, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::preset(
        "linear",
        "the same, bilinear: smooth near, still moiré far",
        Settings { sampler: SamplerMode::Linear, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::preset(
        "mipmaps",
        "trilinear filtering with mipmaps: no moiré, but the distance turns grey",
        Settings { sampler: SamplerMode::Mipmaps, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::preset(
        "anisotropic",
        "anisotropic filtering (16x): the squares stay sharp much further",
        Settings { sampler: SamplerMode::Anisotropic, ..Settings::LAB },
        CameraPreset::Lab,
    ),
    ViewRow::no_aa("day", Settings::DAY),
];
// ANCHOR_END: views

/// Where tangents come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tangents {
    /// Averaged per vertex and made orthogonal to its normal.
    PerVertex,
    /// One per triangle (the seed's way), on the stage's primitives.
    PerFace,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub time_of_day: TimeOfDay,
    /// Lit per face, per vertex or per fragment (chapter 08's switch).
    pub shading: Shading,
    pub sampler: SamplerMode,
    pub normal_maps: bool,
    /// Read normal maps' green as pointing down the image (DirectX's way).
    pub flip_green: bool,
    pub tangents: Tangents,
    /// Albedo read as linear data and normal maps as sRGB: the mistake.
    pub swapped_colour_spaces: bool,
    /// Show the tangent frame as colours instead of the picture.
    pub show_frame: bool,
    pub bloom: bool,
    pub exposure: f32,
}

impl Settings {
    /// The textured city at noon: what the chapter starts with.
    pub const DAY: Self = Self {
        time_of_day: TimeOfDay::Noon,
        shading: Shading::Phong,
        // Trilinear: anisotropic filtering is sharper, and about twenty
        // times dearer on a software rasteriser (see the bench).
        sampler: SamplerMode::Mipmaps,
        normal_maps: true,
        flip_green: false,
        tangents: Tangents::PerVertex,
        swapped_colour_spaces: false,
        show_frame: false,
        bloom: true,
        exposure: 1.0,
    };

    /// The stage's views: the morning sun.
    pub const STAGE: Self = Self { time_of_day: TimeOfDay::Morning, ..Self::DAY };

    /// The sampling lab's views: black and white squares, so no bloom, and
    /// an exposure that keeps white below the shoulder of the tone curve.
    pub const LAB: Self = Self { bloom: false, exposure: 0.5, ..Self::DAY };
}
