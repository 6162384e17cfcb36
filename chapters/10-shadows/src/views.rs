//! The chapter's views, written once: what each shows, the settings it
//! applies (the shadow map's filter, size and bias, the lantern's cube,
//! the time of day, the debug drawings) and, for the one preset, where the
//! camera goes. Each lesson of the chapter teaches some of these views.

use common::ViewRow;
use common::glam::Vec3;

use crate::camera_presets::{CAMERA_DISTANCE, CLOSE_UP_DISTANCE, CameraPreset};
use crate::point_shadow::PointShadowSettings;
use crate::shadow_map::{self, Bias, Filter, ShadowSettings};

// ANCHOR: views
/// Every view, once, with what it shows. All but `lantern` are modes: the
/// side camera follows the player whatever the view.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 16] = [
    ViewRow::mode(
        "default",
        "the game mid-jump, with soft shadows that harden where they touch (PCSS)",
        Settings::DEFAULT,
    ),
    // The filters side by side, on a 512² map (texels of 8.8 cm), seen
    // from close up: big enough to see what each filter does to them.
    ViewRow::mode(
        "hard",
        "one comparison per pixel: the shadow map's texels are the shadow's edge",
        Settings::close_up(Filter::Hard),
    ),
    ViewRow::mode(
        "pcf-3x3",
        "nine comparisons a texel apart, averaged: a soft edge one texel wide",
        Settings::close_up(Filter::Pcf3x3),
    ),
    ViewRow::mode(
        "poisson",
        "sixteen comparisons on a Poisson disk, turned per pixel: the seed's filter",
        Settings::close_up(Filter::Poisson),
    ),
    ViewRow::mode("acne", "no bias: lit surfaces shadow themselves in stripes", Settings::hard_with(Bias::NONE)),
    ViewRow::mode(
        "peter-panning",
        "far too much bias: shadows come loose from what casts them",
        Settings::hard_with(Bias::TOO_MUCH),
    ),
    ViewRow::mode(
        "shadow-map",
        "the sun's depth, full screen: near the sun dark, far light",
        Settings { show: Show::ShadowMap, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "lantern",
        "the lantern in the tunnel at nightfall: its light stops at the ceiling, and the rock casts a shadow",
        Settings::LANTERN,
        CameraPreset::Lantern,
    ),
    ViewRow::mode(
        "cube-shadow-map",
        "the lantern's six shadow-map faces unfolded in a cross: near the light dark, far light",
        Settings { show: Show::CubeMap, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "light-frustum",
        "the sun's box (yellow) around the part of the level the camera sees (cyan)",
        Settings { light_box: true, camera_distance: 60.0, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "collision-boxes",
        "the boxes the physics works with, drawn over the scene",
        Settings { collision_boxes: true, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "parallax",
        "the background layers tinted by depth: red near, green middle, blue far",
        Settings { tint_layers: true, ..Settings::DEFAULT },
    ),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::bench("map-1024", "Poisson filtering with a 1024² shadow map", Settings::filtered(Filter::Poisson, 1024)),
    ViewRow::bench("map-4096", "Poisson filtering with a 4096² shadow map", Settings::filtered(Filter::Poisson, 4096)),
    ViewRow::bench(
        "no-shadows",
        "no lookup at all, nor the lantern's cube: what the filters are measured against",
        Settings { lantern: PointShadowSettings::OFF, ..Settings::filtered(Filter::Off, shadow_map::DEFAULT_SIZE) },
    ),
];
// ANCHOR_END: views

// ANCHOR: settings
/// What the camera shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Show {
    /// The lit scene.
    Scene,
    /// The shadow map, full screen.
    ShadowMap,
    /// How much sun reaches each pixel (red), whether its surface faces
    /// the sun (green) and how much of the lantern's light arrives (blue),
    /// unlit: what the shadow tests count.
    Sunlit,
    /// The lantern's cube shadow map, unfolded, full screen.
    CubeMap,
}

/// What the sun's box is fitted to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fit {
    /// The part of the level the camera sees.
    Visible,
    /// The whole level: simpler, and every texel three times as coarse.
    WholeLevel,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub shadow: ShadowSettings,
    /// The lantern's cube shadow map.
    pub lantern: PointShadowSettings,
    pub fit: Fit,
    /// The time of day as a phase (0.25 sunrise, 0.5 noon, 0.75 sunset).
    pub phase: f32,
    /// Whether the sun moves on by itself, a day every [`DAY_SECONDS`].
    pub sun_moves: bool,
    pub show: Show,
    pub collision_boxes: bool,
    pub light_box: bool,
    pub tint_layers: bool,
    /// How far behind the level the camera stands, metres.
    pub camera_distance: f32,
    pub bloom: bool,
}

impl Settings {
    /// The game mid-jump in soft shadows: what the chapter starts with.
    pub const DEFAULT: Self = Self {
        shadow: ShadowSettings { filter: Filter::Pcss, ..ShadowSettings::DEFAULT },
        lantern: PointShadowSettings::DEFAULT,
        fit: Fit::Visible,
        // Nine in the morning: the sun 35° high, on the left, in front.
        phase: 0.375,
        sun_moves: false,
        show: Show::Scene,
        collision_boxes: false,
        light_box: false,
        tint_layers: false,
        camera_distance: CAMERA_DISTANCE,
        bloom: true,
    };

    /// The `lantern` view: the default scene at nightfall, when the
    /// lantern is the only light.
    pub const LANTERN: Self = Self { phase: 0.8, ..Self::DEFAULT };

    /// The default scene with the shadow map looked up by `filter` in a
    /// `size`² map.
    pub const fn filtered(filter: Filter, size: u32) -> Self {
        Self { shadow: ShadowSettings { filter, size, ..Self::DEFAULT.shadow }, ..Self::DEFAULT }
    }

    /// The scene with a 512² map looked up by `filter`, seen from
    /// [`CLOSE_UP_DISTANCE`]: the sun's box is still fitted to the game's
    /// camera, so its texels are as large as in the game, and large on screen.
    pub const fn close_up(filter: Filter) -> Self {
        Self { camera_distance: CLOSE_UP_DISTANCE, ..Self::filtered(filter, 512) }
    }

    /// The default scene with hard shadows and `bias`.
    pub const fn hard_with(bias: Bias) -> Self {
        Self { shadow: ShadowSettings { filter: Filter::Hard, bias, ..Self::DEFAULT.shadow }, ..Self::DEFAULT }
    }
}
// ANCHOR_END: settings

impl Fit {
    /// The points the sun's box is fitted around: the `visible` part of
    /// the level, or the eight corners of `bounds`, the whole level.
    pub fn focus(self, visible: &[Vec3; 8], bounds: (Vec3, Vec3)) -> Vec<Vec3> {
        match self {
            Fit::Visible => visible.to_vec(),
            Fit::WholeLevel => (0..8)
                .map(|i| {
                    let pick = |bit, lo: f32, hi: f32| if i & bit == 0 { lo } else { hi };
                    Vec3::new(
                        pick(1, bounds.0.x, bounds.1.x),
                        pick(2, bounds.0.y, bounds.1.y),
                        pick(4, bounds.0.z, bounds.1.z),
                    )
                })
                .collect(),
        }
    }
}

/// How long a day lasts when the sun moves, seconds.
pub const DAY_SECONDS: f32 = 120.0;
