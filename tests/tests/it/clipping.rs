//! The two ways of clipping give the same picture: WebGPU clip distances
//! (where the adapter has them) and a discard in the fragment shader.

use common::headless::{RenderRequest, render_image};
use common::{Chapter, Gpu, GpuNeeds, chapter::view_index, wgpu};
use snapshots::snapshot::{Tolerance, compare};
use water::WaterChapter;

#[test]
fn clip_distances_and_discard_agree() {
    let with = Gpu::headless(GpuNeeds { required: wgpu::Features::CLIP_DISTANCES, ..Default::default() })
        .expect("lavapipe has clip distances");
    let without = Gpu::headless(GpuNeeds::default()).unwrap();
    assert!(!without.device.features().contains(wgpu::Features::CLIP_DISTANCES));
    // The refraction picture is all clipping: everything above the water is cut away.
    let view = view_index::<WaterChapter>("refraction").unwrap();
    let request = RenderRequest {
        width: 320,
        height: 180,
        time: WaterChapter::SNAPSHOT_TIME,
        view,
        camera: None,
        antialiasing: common::Antialiasing::Off,
    };
    let (a, b) = (
        render_image::<WaterChapter>(&with, &request).unwrap(),
        render_image::<WaterChapter>(&without, &request).unwrap(),
    );
    // Two blank pictures would agree too: each must show the ground, rocks
    // and haze in many colours, not a cleared target (measured: 1,966
    // colours, and 57,400 of the 57,600 pixels unlike the top-left one).
    for (name, picture) in [("clip distances", &a), ("discard", &b)] {
        let colours: std::collections::HashSet<[u8; 4]> = picture.pixels().map(|p| p.0).collect();
        let background = *picture.get_pixel(0, 0);
        let other = picture.pixels().filter(|p| **p != background).count();
        eprintln!("{name}: {} colours, {other} pixels unlike the top-left one", colours.len());
        assert!(colours.len() > 1000 && other > 50_000, "{name}: {} colours, {other} pixels", colours.len());
    }
    let (comparison, _) = compare(&a, &b);
    assert!(comparison.passes(Tolerance::DEFAULT), "{comparison}");
}
