//! Issue 35's promise, for the chapters that draw the Mars plain: each
//! default view, with chapter 03's terrain at its levels of detail and
//! chapter 05's rocks graded on the GPU, looks like the same view drawn as
//! before either had levels of detail (the `full-detail` bench views:
//! every chunk in view at full detail, the rocks culled by chunk and drawn
//! whole): mean FLIP at most 0.02. (Chapters 03 and 04 have a
//! `full-detail` snapshot view that the snapshot test holds to the
//! default's picture.)

use common::headless::{OFFSCREEN_FORMAT, RenderRequest, render_image};
use common::{Chapter, Target};
use snapshots::snapshot::compare;

/// The most the two pictures may differ.
const MOST_MEAN_FLIP: f32 = 0.02;

/// The chapter's first view and its `full-detail` view, at the snapshots'
/// size, compared; returns the comparison's mean.
fn default_against_full_detail<C: Chapter>() -> f32 {
    let gpu = snapshots::lease(C::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, ..snapshots::target() };
    let full = common::chapter::view_index::<C>("full-detail").expect("a full-detail view");
    let picture = |view| {
        let request = RenderRequest {
            width: target.width,
            height: target.height,
            time: C::SNAPSHOT_TIME,
            view,
            camera: None,
            antialiasing: common::Antialiasing::Msaa,
        };
        render_image::<C>(&gpu, &request).unwrap()
    };
    let (lod, whole) = (picture(0), picture(full));
    assert_ne!(lod, whole, "{}: the levels change some pixels, so the comparison means something", C::NAME);
    let (flip, _) = compare(&whole, &lod);
    eprintln!("{}: {} against full-detail: {flip}", C::NAME, C::VIEWS[0].name);
    assert!(flip.mean <= MOST_MEAN_FLIP, "{}: {flip}", C::NAME);
    flip.mean
}

#[test]
fn the_plain_looks_the_same_at_its_levels_of_detail() {
    default_against_full_detail::<instancing::InstancingChapter>();
}

#[test]
fn the_plain_under_its_sky_looks_the_same_at_its_levels_of_detail() {
    default_against_full_detail::<skybox::SkyboxChapter>();
}

#[test]
fn the_lake_looks_the_same_at_its_levels_of_detail() {
    default_against_full_detail::<water::WaterChapter>();
}
