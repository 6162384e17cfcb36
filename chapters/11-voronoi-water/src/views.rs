//! The chapter's views, each written once in a typed table: the settings a
//! view applies (what the frame shows; the diagram's method, sites and
//! texture; the water's processing; the sea's grid; the day) and, for a
//! preset, where the camera goes. Every lesson names the views that show
//! its idea: the diagram's steps full screen, the grid from above, the
//! sail close by, the sunset at noon and by night, and the bench's
//! diagrams of many sizes.

use common::ViewRow;

use crate::atmosphere::DAY_SECONDS;
use crate::camera_presets::CameraPreset;
use crate::sites;
use crate::voronoi::{Method, VoronoiSettings};
use crate::water_texture::{Picture, Processing};

// ANCHOR: views
/// Every view, once: what it shows, and for a preset where the camera goes.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 26] = [
    ViewRow::preset(
        "default",
        "sunset: the boat sails into the sun over the Voronoi sea",
        Settings::SUNSET,
        CameraPreset::Sunset,
    ),
    ViewRow::mode(
        "noon",
        "the same sea at noon, the sun 60° high",
        Settings { day_start: 0.5 - SNAPSHOT_TIME / DAY_SECONDS, ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "night",
        "night: the moon's light, the sky from the gradient's dark end",
        Settings { day_start: 0.95 - SNAPSHOT_TIME / DAY_SECONDS, ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "voronoi",
        "the raw diagram by cones of 8 segments, a hue per cell, tiled 1.5 times down",
        Settings::diagram(Method::Cones, sites::DEFAULT_COUNT, 512),
    ),
    ViewRow::mode(
        "blurred",
        "the cells in the sea's shades, box-blurred twice",
        Settings { show: Show::Picture(Picture::Blurred), ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "edges",
        "Sobel's edges of the blurred cells: the lines of foam",
        Settings { show: Show::Picture(Picture::Edges), ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "cells",
        "an id buffer: each pixel's nearest site as red = i % 256, green = i / 256",
        Settings {
            voronoi: VoronoiSettings { method: Method::ExactCones, ..VoronoiSettings::DEFAULT },
            show: Show::Cells,
            ..Settings::SUNSET
        },
    ),
    ViewRow::mode(
        "jfa",
        "the raw diagram by jump flooding, a hue per cell",
        Settings::diagram(Method::JumpFlooding, sites::DEFAULT_COUNT, 512),
    ),
    ViewRow::mode(
        "shadow-map",
        "the sun's depth, fitted tightly around the boat",
        Settings { show: Show::ShadowMap, ..Settings::SUNSET },
    ),
    ViewRow::mode(
        "bloom-only",
        "what bloom adds: the sun and the glints on the water",
        Settings { show: Show::BloomOnly, ..Settings::SUNSET },
    ),
    ViewRow::preset(
        "grid",
        "the sea's grid as wires, seen from high up: it follows the boat",
        Settings { wires: true, ..Settings::SUNSET },
        CameraPreset::High,
    ),
    ViewRow::mode(
        "small-grid",
        "the seed's magic carpet: a grid of 24 m, three boat lengths",
        Settings { small_grid: true, ..Settings::SUNSET },
    ),
    ViewRow::preset(
        "sail",
        "close by the boat's side: the sail filled by the wind, the sailor at the helm",
        Settings::SUNSET,
        CameraPreset::Sail,
    ),
    ViewRow::no_aa_from("default", Settings::SUNSET, CameraPreset::Sunset),
    ViewRow::bench("cones-64-512", "64 sites by cones at 512²", Settings::diagram(Method::Cones, 64, 512)),
    ViewRow::bench("jfa-64-512", "64 sites by jump flooding at 512²", Settings::diagram(Method::JumpFlooding, 64, 512)),
    ViewRow::bench("cones-1024-512", "1,024 sites by cones at 512²", Settings::diagram(Method::Cones, 1024, 512)),
    ViewRow::bench(
        "jfa-1024-512",
        "1,024 sites by jump flooding at 512²",
        Settings::diagram(Method::JumpFlooding, 1024, 512),
    ),
    ViewRow::bench("cones-16384-512", "16,384 sites by cones at 512²", Settings::diagram(Method::Cones, 16384, 512)),
    ViewRow::bench(
        "jfa-16384-512",
        "16,384 sites by jump flooding at 512²",
        Settings::diagram(Method::JumpFlooding, 16384, 512),
    ),
    ViewRow::bench("cones-64-1024", "64 sites by cones at 1024²", Settings::diagram(Method::Cones, 64, 1024)),
    ViewRow::bench(
        "jfa-64-1024",
        "64 sites by jump flooding at 1024²",
        Settings::diagram(Method::JumpFlooding, 64, 1024),
    ),
    ViewRow::bench("cones-1024-1024", "1,024 sites by cones at 1024²", Settings::diagram(Method::Cones, 1024, 1024)),
    ViewRow::bench(
        "jfa-1024-1024",
        "1,024 sites by jump flooding at 1024²",
        Settings::diagram(Method::JumpFlooding, 1024, 1024),
    ),
    ViewRow::bench("cones-16384-1024", "16,384 sites by cones at 1024²", Settings::diagram(Method::Cones, 16384, 1024)),
    ViewRow::bench(
        "jfa-16384-1024",
        "16,384 sites by jump flooding at 1024²",
        Settings::diagram(Method::JumpFlooding, 16384, 1024),
    ),
];
// ANCHOR_END: views

/// What the frame shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Show {
    /// The sea, the boat, the sky.
    Scene,
    /// A picture of the water texture's chain, full screen.
    Picture(Picture),
    /// The diagram's ids at the target's size, exactly.
    Cells,
    /// The shadow map, full screen.
    ShadowMap,
    /// What bloom adds, alone.
    BloomOnly,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub voronoi: VoronoiSettings,
    /// Sites in the diagram.
    pub sites: u32,
    /// The water texture's side, texels.
    pub texture_size: u32,
    pub processing: Processing,
    pub show: Show,
    /// The time of day at scene time 0 (0.25 sunrise, 0.5 noon, 0.75 sunset).
    pub day_start: f32,
    /// The day moves on with scene time, a day every [`DAY_SECONDS`].
    pub day_runs: bool,
    /// The grid moves in whole cells (off: by fractions, and the waves swim).
    pub snap_grid: bool,
    pub small_grid: bool,
    pub wires: bool,
    pub textured_sea: bool,
    pub shadows: bool,
    pub bloom: bool,
}

/// Scene time of the snapshots, seconds.
pub const SNAPSHOT_TIME: f32 = 20.0;

impl Settings {
    /// Sunset over the Voronoi sea: what the chapter starts with.
    pub const SUNSET: Self = Self {
        voronoi: VoronoiSettings::DEFAULT,
        sites: sites::DEFAULT_COUNT,
        texture_size: 512,
        processing: Processing::DEFAULT,
        show: Show::Scene,
        // At the snapshot time the sun stands 4.6° above the horizon.
        day_start: 0.735 - SNAPSHOT_TIME / DAY_SECONDS,
        day_runs: true,
        snap_grid: true,
        small_grid: false,
        wires: false,
        textured_sea: true,
        shadows: true,
        bloom: true,
    };

    /// The raw diagram of `sites` sites by `method` in a texture
    /// `texture_size` texels wide, a hue per cell, full screen.
    pub const fn diagram(method: Method, sites: u32, texture_size: u32) -> Self {
        Self {
            voronoi: VoronoiSettings { method, ..VoronoiSettings::DEFAULT },
            sites,
            texture_size,
            processing: Processing { water_colours: false, ..Processing::DEFAULT },
            show: Show::Picture(Picture::Colours),
            ..Self::SUNSET
        }
    }
}

#[cfg(test)]
mod tests {
    // The sail view is a preset seen at the snapshot time: a fact of the
    // view table and the camera presets together.
    use common::glam::Vec2;

    use super::SNAPSHOT_TIME;
    use crate::camera_presets::SAIL_ORBIT;
    use crate::{boat, sail};

    #[test]
    fn the_sail_view_looks_at_the_side_the_sail_fills_towards() {
        let heading = boat::on_course(SNAPSHOT_TIME).heading;
        let across = sail::wind_across(heading, sail::wind());
        assert!(across.abs() > 0.5, "at the snapshot the wind is only {across} across the sail");
        let ahead = boat::forward(heading);
        let filled_side = Vec2::new(-ahead.y, ahead.x) * across.signum();
        let back = SAIL_ORBIT.back();
        let eye = Vec2::new(back.x, back.z).normalize();
        // Within 45° of that side: the belly faces the eye.
        let off = eye.angle_to(filled_side).abs().to_degrees();
        assert!(off < 45.0, "the eye is {off}° off the side the sail fills to");
    }
}
