//! The chapter's views, written once as a table: what each decides (how
//! the ground is coloured, levels of detail or full detail, the picture
//! from overhead) and, for the one preset, where it puts the camera. Each
//! lesson of the book names the views that show its idea.

use common::ViewRow;

use crate::cameras::CameraPreset;
use crate::terrain_renderer::Shading;

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// How the ground is coloured.
    pub shading: Shading,
    /// Levels of detail (true), or every chunk in view at full detail.
    pub lod: bool,
    /// Look from 4 km overhead at what the flying camera draws.
    pub from_above: bool,
}

impl Settings {
    pub const DEFAULT: Self = Self { shading: Shading::Shaded, lod: true, from_above: false };
}

// Every view but `close-up` is a mode: a way of drawing what the flying
// camera sees. `quadtree` too: it shows that camera's patches from above.

/// Every view, with the settings it applies and, for a preset, its camera.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 8] = [
    ViewRow::mode("default", "the terrain, coloured by height and slope, with its cliff", Settings::DEFAULT),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "full-detail",
        "the same picture with every chunk in view at full detail: many times the triangles",
        Settings { lod: false, ..Settings::DEFAULT },
    )
    .same_picture_as("default"),
    ViewRow::mode(
        "lod-levels",
        "a colour per level of detail, blending into the next where the mesh morphs",
        Settings { shading: Shading::Levels, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "wireframe",
        "the triangles drawn, the lines fading out as cells shrink from 2.5 to 1.4 pixels across",
        Settings { shading: Shading::Wireframe, ..Settings::DEFAULT },
    ),
    ViewRow::preset(
        "close-up",
        "the wireframe from the foot of the cliff, where the 1 m cells are large",
        Settings { shading: Shading::Wireframe, ..Settings::DEFAULT },
        CameraPreset::CloseUp,
    ),
    ViewRow::mode(
        "normals",
        "normals from the whole height field: the same at every level of detail",
        Settings { shading: Shading::Normals, ..Settings::DEFAULT },
    ),
    ViewRow::mode(
        "quadtree",
        "from 4 km above: the patches your camera draws, a colour per level; nothing where it culls",
        Settings { shading: Shading::Levels, from_above: true, ..Settings::DEFAULT },
    ),
];
