//! Chapter 08: culling lights per cluster gives the same picture as the
//! naive loop over every light, at 256 lights, within the snapshot
//! tolerance (by construction it should be the same bytes: a light left out
//! of a cluster's list adds exactly zero there).

use common::headless::{RenderRequest, render_image};
use common::{Chapter, chapter::view_index};
use lighting::LightingChapter;
use snapshots::snapshot::{Tolerance, compare};

#[test]
fn culled_lights_draw_what_the_naive_loop_draws() {
    let gpu = snapshots::lease(LightingChapter::gpu_needs()).unwrap();
    let render = |view| {
        let view = view_index::<LightingChapter>(view).unwrap();
        let request = RenderRequest { width: 640, height: 360, time: LightingChapter::SNAPSHOT_TIME, view };
        render_image::<LightingChapter>(&gpu, &request).unwrap()
    };
    let (culled, naive) = (render("lights-256"), render("naive-256"));
    let (comparison, _) = compare(&naive, &culled);
    let identical = culled == naive;
    eprintln!("256 lights, culled against naive: {comparison}; identical bytes: {identical}");
    assert!(comparison.passes(Tolerance::DEFAULT), "{comparison}");
}
