//! Chapter 08: culling lights per cluster draws the same picture as the
//! naive loop over every light, at 256 lights, byte for byte (book page 08).
//! By construction: a light left out of a cluster's list adds exactly zero
//! there, and the culled loop adds the others in the same order as the
//! naive one.

use common::headless::{RenderRequest, render_image};
use common::{Chapter, chapter::view_index};
use lighting::LightingChapter;
use snapshots::snapshot::compare;

#[test]
fn culled_lights_draw_the_same_bytes_as_the_naive_loop() {
    let gpu = snapshots::lease(LightingChapter::gpu_needs()).unwrap();
    let render = |view| {
        let view = view_index::<LightingChapter>(view).unwrap();
        let request = RenderRequest {
            width: 640,
            height: 360,
            time: LightingChapter::SNAPSHOT_TIME,
            view,
            camera: None,
            antialiasing: common::Antialiasing::Off,
        };
        render_image::<LightingChapter>(&gpu, &request).unwrap()
    };
    let (culled, naive) = (render("lights-256"), render("naive-256"));
    // Two blank pictures would be the same bytes too: the night city must
    // show something.
    let first = naive.get_pixel(0, 0);
    assert!(naive.pixels().any(|p| p != first), "the naive-256 picture is one colour");
    let differing = culled.pixels().zip(naive.pixels()).filter(|(a, b)| a != b).count();
    let (comparison, _) = compare(&naive, &culled);
    eprintln!("256 lights, culled against naive: {differing} pixels differ; {comparison}");
    assert_eq!(culled.dimensions(), naive.dimensions());
    assert_eq!(differing, 0, "culled and naive differ in {differing} pixels: {comparison}");
}
