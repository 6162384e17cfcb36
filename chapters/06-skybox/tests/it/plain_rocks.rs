//! Chapter 06's `day` is chapter 05's plain under a sky, from the same
//! camera: it draws the rocks chapter 05's `default` view draws, graded on
//! the GPU, as chapter 05's pages say. (Chapter 05's own tests check its
//! counts; this one needs both chapters, so it lives here.)

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Target};
use instancing::InstancingChapter;
use skybox::SkyboxChapter;

/// The number before " rock triangles" in a stats line.
fn rock_triangles(line: &str) -> u64 {
    let before = &line[..line.find(" rock triangles").unwrap_or_else(|| panic!("no rock triangles in `{line}`"))];
    let number = before.rsplit(' ').next().unwrap_or_default();
    number.replace(',', "").parse().unwrap_or_else(|_| panic!("`{number}` in `{line}`"))
}

#[test]
fn the_day_draws_the_rock_triangles_of_chapter_05s_default_view() {
    // The budget's picture size: the lent GPU's figures are at 1920 × 1080.
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 1920, height: 1080, samples: 1 };
    let mut plain: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let view = common::chapter::view_index::<InstancingChapter>("default").unwrap();
    plain.select_view(view);
    // The rocks alone: the terrain changes no count and costs lavapipe seconds.
    plain.setup.terrain = false;
    capture(gpu, &mut plain, target, (0.0, view), Default::default()).unwrap();
    let graded = plain.plain.rocks_drawn_now(gpu, plain.viewpoint(), plain.setup);
    assert!(graded.levels.is_some(), "graded on the GPU");

    let mut sky: SkyboxChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let day = common::chapter::view_index::<SkyboxChapter>("day").unwrap();
    sky.select_view(day);
    let picture = capture(gpu, &mut sky, target, (0.0, day), Default::default()).unwrap();
    assert!(picture.pixels().any(|p| p != picture.get_pixel(0, 0)));
    let line = sky.stats(gpu);
    eprintln!("chapter 05's default: {graded:?}; chapter 06: {line}");
    assert_eq!(rock_triangles(&line), graded.triangles, "{line}");
}
