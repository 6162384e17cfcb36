//! The chapter's views, written once: each names the rocks it draws and
//! how (a `Setup` of the Mars plain). None places the camera: every view
//! is a mode, so a learner keeps their place while comparing. The lessons
//! name each view where they teach it.

use common::ViewRow;

use crate::cameras::CameraPreset;
use crate::mars_plain::{Culling, Mode, Setup};

/// Every view, with the rocks it draws and how. The bench views leave the
/// terrain out and draw every one of their rocks (the first of the buffer,
/// nearest the start, not culled), so that their numbers are the rocks' alone.
pub const VIEW_TABLE: [ViewRow<Setup, CameraPreset>; 13] = [
    ViewRow::mode(
        "default",
        "the Mars plain: terrain, fog and a million rocks over the whole map, culled and graded rock by rock on the GPU",
        Setup::DEFAULT,
    ),
    ViewRow::no_aa("default", Setup::DEFAULT),
    ViewRow::mode(
        "cpu-culling",
        "the same plain, the rocks culled by chunk group on the CPU and every one in view drawn at full detail",
        Setup { culling: Culling::Chunks, ..Setup::DEFAULT },
    )
    .same_picture_as("default"),
    ViewRow::bench(
        "full-detail",
        "bench: the plain as drawn before levels of detail, terrain and rocks at full detail",
        Setup::DEFAULT.at_full_detail(),
    ),
    ViewRow::mode(
        "lod-levels",
        "each rock the GPU kept in its level's colour: red the full rock, yellow the octahedron, blue the tetrahedron",
        Setup { mode: Mode::Levels, ..Setup::DEFAULT },
    ),
    ViewRow::mode(
        "multi-draw",
        "the chunk groups in view, every group's draw in one indirect call",
        Setup { mode: Mode::Indirect, culling: Culling::Chunks, ..Setup::DEFAULT },
    )
    .same_picture_as("cpu-culling"),
    ViewRow::mode(
        "rock-chunks",
        "each rock drawn in the colour of its chunk group",
        Setup { mode: Mode::Groups, culling: Culling::Chunks, ..Setup::DEFAULT },
    ),
    ViewRow::mode(
        "naive",
        "the plain with the 2,000 rocks nearest the start, one draw call each",
        Setup { rocks: 2_000, mode: Mode::OnePerDraw, terrain: true, culling: Culling::Off, full_detail: false },
    ),
    ViewRow::mode(
        "rocks-10k",
        "bench: 10,000 rocks, instanced, no terrain",
        Setup { rocks: 10_000, mode: Mode::Instanced, terrain: false, culling: Culling::Off, full_detail: false },
    ),
    // Measured, not a snapshot: past its 100,000 rocks (730 m around the
    // start) the haze hides most of what `rocks-1m` adds, so the two
    // pictures are too alike to check one against the other.
    ViewRow::bench(
        "rocks-100k",
        "bench: 100,000 rocks, instanced, no terrain",
        Setup { rocks: 100_000, mode: Mode::Instanced, terrain: false, culling: Culling::Off, full_detail: false },
    ),
    ViewRow::mode(
        "rocks-1m",
        "bench: 1,000,000 rocks, instanced, no terrain",
        Setup { rocks: 1_000_000, mode: Mode::Instanced, terrain: false, culling: Culling::Off, full_detail: false },
    ),
    ViewRow::mode(
        "naive-10k",
        "bench: 10,000 rocks, one draw call each, no terrain",
        Setup { rocks: 10_000, mode: Mode::OnePerDraw, terrain: false, culling: Culling::Off, full_detail: false },
    )
    .same_picture_as("rocks-10k"),
    ViewRow::mode(
        "flat-1m",
        "bench: 1,000,000 rocks, instanced, flat colour: the cost floor",
        Setup { rocks: 1_000_000, mode: Mode::Flat, terrain: false, culling: Culling::Off, full_detail: false },
    ),
];
