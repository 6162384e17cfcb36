//! Chapter 06's `day` is chapter 05's plain under a sky, from the same
//! camera: it draws the rocks chapter 05's `default` view draws, graded on
//! the GPU, as chapter 05's pages say. (Chapter 05's own tests check its
//! counts; this one needs both chapters, so it lives here.)

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Target};
use instancing::InstancingChapter;
use skybox::SkyboxChapter;

/// The last word of `text` read as a number, commas allowed (`line` is
/// where it came from, for the message).
fn last_number(text: &str, line: &str) -> u64 {
    let number = text.rsplit(' ').next().unwrap_or_default();
    number.replace(',', "").parse().unwrap_or_else(|_| panic!("`{number}` in `{line}`"))
}

/// The text of a stats line before `phrase`.
fn before<'a>(line: &'a str, phrase: &str) -> &'a str {
    &line[..line.find(phrase).unwrap_or_else(|| panic!("no{phrase} in `{line}`"))]
}

/// The number before " rock triangles" in a stats line.
fn rock_triangles(line: &str) -> u64 {
    last_number(before(line, " rock triangles"), line)
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

/// The rocks drawn in a stats line: the number before "of … rocks drawn".
fn rocks_drawn(line: &str) -> u64 {
    last_number(before(line, " rocks drawn").rsplit(" of ").nth(1).unwrap_or_default(), line)
}

#[test]
fn the_full_detail_line_counts_the_rocks_its_chunks_drew() {
    // The full-detail view culls by chunk on the CPU and draws every rock
    // kept whole; its stats line once asked the GPU's lists, which that
    // frame never filled, and said 0. The rocks nearest the start and a
    // small picture keep it cheap: the counts do not depend on the size.
    const ROCKS: u32 = 20_000;
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };

    let mut sky: SkyboxChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let full = common::chapter::view_index::<SkyboxChapter>("full-detail").unwrap();
    sky.select_view(full);
    sky.rocks.rocks = ROCKS;
    capture(gpu, &mut sky, target, (0.0, full), Default::default()).unwrap();
    let line = sky.stats(gpu);

    // Chapter 05's own full-detail view, from the same camera, on the same rocks.
    let mut plain: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let view = common::chapter::view_index::<InstancingChapter>("full-detail").unwrap();
    plain.select_view(view);
    plain.setup.rocks = ROCKS;
    plain.setup.terrain = false;
    capture(gpu, &mut plain, target, (0.0, view), Default::default()).unwrap();
    let chunks = plain.plain.rocks_drawn_now(gpu, plain.viewpoint(), plain.setup);
    eprintln!("chapter 05's full-detail: {chunks:?}; chapter 06: {line}");
    assert!(chunks.levels.is_none() && chunks.rocks > 0, "culled by chunk: {chunks:?}");
    assert_eq!(rocks_drawn(&line), u64::from(chunks.rocks), "{line}");
    assert_eq!(rock_triangles(&line), chunks.triangles, "{line}");
}
