//! The chapter's views, written once: each names the settings it applies
//! and, for a preset, where it puts the camera. `Settings` is everything a
//! view decides (time of day, where the light loop runs, which highlight,
//! culling, bloom, what reaches the screen); the overlay edits the same
//! fields.

use common::{Antialiasing, ViewRow};

use crate::bloom::BloomSettings;
use crate::camera_presets::CameraPreset;
use crate::frame_lights::LightCount;
use crate::light_terms::LightTerm;
use crate::lights::TimeOfDay;
use crate::scene_lights::Highlight;

// ANCHOR: views
/// Every view, once: what it shows, and for a preset where the camera goes.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 38] = [
    ViewRow::mode("day", "the city at noon, from above", Settings::DAY),
    ViewRow::mode("night", "the city at night: street lamps, lit buildings, headlights, bloom", Settings::NIGHT),
    ViewRow::preset(
        "flat",
        "the glass sphere in the morning sun, flat shaded: one colour per face",
        Settings { shading: Shading::Flat, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "gouraud",
        "the same, lit per vertex and blended: the highlight smears over the facets",
        Settings { shading: Shading::Gouraud, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "phong",
        "the same, lit per fragment: a round, sharp highlight (Phong's mirror direction)",
        Settings { shading: Shading::Phong, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "blinn-phong",
        "the same with Blinn-Phong's half vector: a wider, softer highlight",
        Settings { shading: Shading::Phong, highlight: Highlight::BlinnPhong, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "cook-torrance",
        "the same, physically based: smooth glass's small, bright highlight and the sky it reflects at the rim",
        Settings { shading: Shading::Phong, highlight: Highlight::CookTorrance, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "spheres",
        "physically based, in the morning: roughness rising from 0 to 1 left to right, red paint above and gold below; the first gold sphere a mirror",
        Settings { highlight: Highlight::CookTorrance, material_spheres: true, ..Settings::SPHERE },
        CameraPreset::MaterialSpheres,
    ),
    ViewRow::mode(
        "pbr-day",
        "the day view, physically based: metal, glass and paint by roughness and metalness, lit by sun and sky",
        Settings { highlight: Highlight::CookTorrance, ..Settings::DAY },
    ),
    ViewRow::mode(
        "pbr-night",
        "the night view, physically based: the same lights through the same clusters",
        Settings { highlight: Highlight::CookTorrance, ..Settings::NIGHT },
    ),
    ViewRow::preset(
        "ambient",
        "the phong view's ambient term alone: albedo times the sky's light, the same on every side",
        Settings { display: Display::Term(LightTerm::Ambient), ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "diffuse",
        "its diffuse term alone: Lambert's, brightest where the surface faces the sun",
        Settings { display: Display::Term(LightTerm::Diffuse), ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "specular",
        "its specular term alone: the highlights",
        Settings { display: Display::Term(LightTerm::Specular), ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::mode(
        "no-bloom",
        "the night city without bloom: lights are bright dots",
        Settings { bloom_on: false, ..Settings::NIGHT },
    ),
    ViewRow::mode(
        "bloom-only",
        "the blurred bright light the bloom adds, alone",
        Settings { display: Display::BloomOnly, ..Settings::NIGHT },
    ),
    ViewRow::mode(
        "light-tiles",
        "lights each fragment visits, as a heat map (black 0, blue few, red 24 or more)",
        Settings { display: Display::LightTiles, ..Settings::NIGHT },
    ),
    ViewRow::preset(
        "follow",
        "at night, behind a car, with its headlights on the road",
        Settings::NIGHT,
        CameraPreset::Follow,
    ),
    ViewRow::preset(
        "street",
        "at eye height in the avenue at evening, looking north: lamps coming on, towers against the sky",
        Settings { time_of_day: TimeOfDay::Evening, ..Settings::DAY },
        CameraPreset::Street,
    ),
    ViewRow::preset(
        "rooftop",
        "on the roof of the tallest tower in the morning, looking over the middle of the city",
        Settings { time_of_day: TimeOfDay::Morning, ..Settings::DAY },
        CameraPreset::Rooftop,
    ),
    ViewRow::preset(
        "lollipop",
        "at night beside the lollipop's glowing ball, 74 m up, looking down on the blocks it lights",
        Settings::NIGHT,
        CameraPreset::Lollipop,
    ),
    ViewRow::preset(
        "hill",
        "on the hill at the city's north-east corner in the morning, looking south along its edge",
        Settings { time_of_day: TimeOfDay::Morning, ..Settings::DAY },
        CameraPreset::Hill,
    ),
    ViewRow::preset(
        "drone",
        "at noon, riding beside a drone as it bobs, looking past it into the city",
        Settings::DAY,
        CameraPreset::Drone,
    ),
    ViewRow::preset(
        "skyline",
        "at night from the south-east edge of the city, at eye height: the skyline",
        Settings::NIGHT,
        CameraPreset::Skyline,
    ),
    ViewRow::preset(
        "landscape",
        "in the morning over the countryside north of the city: the river at its tide, beaches, trees, the road on its bridge",
        Settings { time_of_day: TimeOfDay::Morning, ..Settings::DAY },
        CameraPreset::Landscape,
    ),
    ViewRow::preset(
        "billboard",
        "at night in front of the billboard on the hill across the river, lit by its three spot lights",
        Settings::NIGHT,
        CameraPreset::Billboard,
    ),
    ViewRow::preset(
        "moving-parts",
        "in the evening, the tallest tower from over the avenue: the crown turning on its roof, the neon sign riding up its face",
        Settings { time_of_day: TimeOfDay::Evening, ..Settings::DAY },
        CameraPreset::MovingParts,
    ),
    ViewRow::no_aa("day", Settings::DAY),
    ViewRow::mode(
        "fxaa",
        "the first view with one sample a pixel and FXAA over the finished picture instead of multisampling",
        Settings::DAY,
    )
    .same_picture_as("day")
    .antialiasing(Antialiasing::Post),
    ViewRow::bench(
        "sky-every-frame",
        "bench: pbr-day with the sky's harmonics and prefiltered cube computed again every frame, as when the day turns",
        Settings { highlight: Highlight::CookTorrance, sky_every_frame: true, ..Settings::DAY },
    ),
    ViewRow::bench("lights-1", "bench: the night city with 1 light, culled", Settings::bench(1, true)),
    ViewRow::bench("lights-16", "bench: 16 lights, culled per cluster", Settings::bench(16, true)),
    ViewRow::bench("lights-64", "bench: 64 lights, culled per cluster", Settings::bench(64, true)),
    ViewRow::bench("lights-256", "bench: 256 lights, culled per cluster", Settings::bench(256, true)),
    ViewRow::bench("lights-1024", "bench: 1024 lights, culled per cluster", Settings::bench(1024, true)),
    ViewRow::bench("naive-16", "bench: 16 lights, every fragment visits every light", Settings::bench(16, false)),
    ViewRow::bench("naive-64", "bench: 64 lights, every fragment visits every light", Settings::bench(64, false)),
    ViewRow::bench("naive-256", "bench: 256 lights, every fragment visits every light", Settings::bench(256, false)),
    ViewRow::bench("naive-1024", "bench: 1024 lights, every fragment visits every light", Settings::bench(1024, false)),
];
// ANCHOR_END: views

/// How surfaces are lit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shading {
    /// Once per face: one normal and one colour per triangle.
    Flat,
    /// Once per vertex; colours interpolated.
    Gouraud,
    /// Once per fragment; normals interpolated.
    Phong,
}

/// What reaches the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    Scene,
    /// One term of the light that surfaces reflect, alone: without the
    /// other two, the glow of emissive materials, or the sky.
    Term(LightTerm),
    BloomOnly,
    LightTiles,
}

/// Everything a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub time_of_day: TimeOfDay,
    /// Seconds in a day when the time of day is `Auto`.
    pub day_seconds: f32,
    pub shading: Shading,
    pub highlight: Highlight,
    /// Highlights at all (off: diffuse light only).
    pub highlights: bool,
    /// Cluster lists (true) or every light for every fragment (false).
    pub culling: bool,
    pub lights: LightCount,
    pub bloom_on: bool,
    pub bloom: BloomSettings,
    pub display: Display,
    pub exposure: f32,
    /// The countryside, the billboard and its spots around the city (off:
    /// the city alone, as the bench measures its lights).
    pub countryside: bool,
    /// The two rows of material spheres south of the city (`material_spheres`).
    pub material_spheres: bool,
    /// The sky's light computed again every frame, as if the day turned:
    /// the bench's measure of what that costs.
    pub sky_every_frame: bool,
}

impl Settings {
    /// The night city, as `night` shows it; the other views change a few
    /// of these.
    pub const NIGHT: Self = Self {
        time_of_day: TimeOfDay::Night,
        day_seconds: 120.0,
        shading: Shading::Phong,
        highlight: Highlight::BlinnPhong,
        highlights: true,
        culling: true,
        lights: LightCount::City,
        bloom_on: true,
        bloom: BloomSettings::DEFAULT,
        display: Display::Scene,
        exposure: 1.0,
        countryside: true,
        material_spheres: false,
        sky_every_frame: false,
    };

    /// The city at noon: what the chapter starts with.
    pub const DAY: Self = Self { time_of_day: TimeOfDay::Noon, ..Self::NIGHT };

    /// One light, the morning sun, so that shading is all there is to see:
    /// the glass sphere's views, with Phong's highlight unless they say otherwise.
    pub const SPHERE: Self = Self {
        time_of_day: TimeOfDay::Morning,
        lights: LightCount::First(0),
        highlight: Highlight::Phong,
        ..Self::NIGHT
    };

    /// The bench's night city with the first `lights` lights, culled per
    /// cluster or (`culling` false) visited by every fragment; the city
    /// alone, so that every covered pixel is one the lights are meant for.
    pub const fn bench(lights: u32, culling: bool) -> Self {
        Self { lights: LightCount::First(lights), culling, countryside: false, ..Self::NIGHT }
    }
}
