//! Chapter 05: the rocks graded by size on the GPU (three levels of detail,
//! none below a pixel) look like every rock drawn at full detail: mean FLIP
//! at most 0.02, in chapter 05's default view (against the GPU's own
//! full-detail picture and against the chunk groups culled on the CPU) and
//! in chapter 07's lake, whose reflection and refraction are culled at the
//! water's clip plane and graded at their own half height.

use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Target, image};
use instancing::{Culling, InstancingChapter, Setup};
use snapshots::snapshot::{Tolerance, compare};
use water::WaterChapter;

/// The most the graded picture may differ from the full-detail one.
const MOST_MEAN_FLIP: f32 = 0.02;

/// Colours in `picture`, and pixels unlike its top-left one: a blank or
/// one-colour picture would agree with anything.
fn busy(picture: &image::RgbaImage) -> bool {
    let colours: std::collections::HashSet<[u8; 4]> = picture.pixels().map(|p| p.0).collect();
    let background = *picture.get_pixel(0, 0);
    colours.len() > 1000 && picture.pixels().filter(|p| **p != background).count() > picture.len() / 8
}

#[test]
fn graded_rocks_look_like_every_rock_at_full_detail() {
    let gpu = snapshots::lease(InstancingChapter::gpu_needs()).unwrap();
    // The snapshots' size, where the views are checked.
    let target = Target { format: OFFSCREEN_FORMAT, ..snapshots::target() };
    let mut chapter: InstancingChapter = common::chapter::create(&gpu, target, &Default::default()).unwrap();
    let mut picture = |culling| {
        chapter.setup = Setup { culling, ..Setup::DEFAULT };
        let picture =
            capture(&gpu, &mut chapter, target, (InstancingChapter::SNAPSHOT_TIME, 0), Default::default()).unwrap();
        (picture, chapter.draw_calls.rocks)
    };
    let ((graded, calls), (full, _), (by_chunk, runs)) =
        (picture(Culling::PerRock), picture(Culling::PerRockFullDetail), picture(Culling::Chunks));
    assert_eq!(calls, 3, "the graded picture came from the GPU's lists");
    assert!(runs > 3, "the chunk groups' picture came from the CPU's runs");
    assert!(busy(&graded) && busy(&full));
    assert_ne!(graded, full, "grading changes some pixels, so the comparison means something");
    let (against_full, _) = compare(&full, &graded);
    let (against_chunks, _) = compare(&by_chunk, &graded);
    // The same rocks at full detail, culled per rock or per chunk: only
    // rocks the frustum test keeps and no pixel shows differ between them.
    let (full_against_chunks, _) = compare(&by_chunk, &full);
    eprintln!("graded against full detail: {against_full}");
    eprintln!("graded against the chunk groups: {against_chunks}");
    eprintln!("full detail against the chunk groups: {full_against_chunks}");
    assert!(against_full.mean <= MOST_MEAN_FLIP, "{against_full}");
    assert!(against_chunks.mean <= MOST_MEAN_FLIP, "{against_chunks}");
    // Nor can the snapshot test tell them apart: the chapter's
    // `cpu-culling` view draws `default`'s picture by another method.
    assert!(against_chunks.passes(Tolerance::DEFAULT), "{against_chunks}");
    assert!(full_against_chunks.mean <= 0.001, "{full_against_chunks}");
}

#[test]
fn the_lake_with_graded_rocks_looks_like_the_lake_with_every_rock_at_full_detail() {
    let gpu = snapshots::lease(WaterChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, ..snapshots::target() };
    let mut chapter: WaterChapter = common::chapter::create(&gpu, target, &Default::default()).unwrap();
    let mut picture = |culling| {
        chapter.rocks = Setup { culling, ..Setup::DEFAULT };
        capture(&gpu, &mut chapter, target, (WaterChapter::SNAPSHOT_TIME, 0), Default::default()).unwrap()
    };
    // Graded last, so that the counts below are the graded frame's.
    let (full, graded) = (picture(Culling::PerRockFullDetail), picture(Culling::PerRock));
    assert!(busy(&graded));
    // Each picture culled its own rocks: the refraction, which keeps what
    // is under the water, and the reflection, which keeps what is above it
    // but sees it at half the height, fewer than the main picture.
    let line = chapter.stats(&gpu);
    let count = |picture: &str| -> u32 {
        let after = line.split_once(&format!("{picture} ")).unwrap_or_else(|| panic!("no {picture} in `{line}`")).1;
        after.split(' ').next().unwrap_or_default().replace(',', "").parse().unwrap()
    };
    let (reflection, refraction, main) = (count("reflection"), count("refraction"), count("plain and sky"));
    eprintln!("rocks drawn: reflection {reflection}, refraction {refraction}, main {main}");
    assert!(0 < refraction && refraction * 5 < main, "{line}");
    assert!(0 < reflection && reflection < main, "{line}");
    let (comparison, _) = compare(&full, &graded);
    eprintln!("the lake, graded against full detail: {comparison}");
    assert!(comparison.mean <= MOST_MEAN_FLIP, "{comparison}");
    assert!(comparison.passes(Tolerance::DEFAULT), "{comparison}");
}

/// Culling only leaves out what no pixel shows: the default view drawn with
/// every rock of the world (culling off) and with the rocks the GPU's
/// frustum test keeps (at full detail, so that grading is not in play), and
/// by the CPU's chunk groups, are the same picture. At the snapshots' size
/// a rock the frustum test wrongly drops may show in no pixel, so the
/// counts are checked another way by chapter 05's recount
/// (`culling_checks.rs`), which projects the outline of each rock's sphere
/// on the CPU and allows a pixel at the picture's edges, and by its rocks
/// placed by hand, some just past an edge and still kept.
#[test]
fn culling_leaves_out_no_rock_a_pixel_shows() {
    let gpu = snapshots::lease(InstancingChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, ..snapshots::target() };
    let mut chapter: InstancingChapter = common::chapter::create(&gpu, target, &Default::default()).unwrap();
    let mut picture = |culling| {
        chapter.setup = Setup { culling, ..Setup::DEFAULT };
        let picture =
            capture(&gpu, &mut chapter, target, (InstancingChapter::SNAPSHOT_TIME, 0), Default::default()).unwrap();
        (picture, chapter.stats(&gpu))
    };
    let (all, all_stats) = picture(Culling::Off);
    let (per_rock, per_rock_stats) = picture(Culling::PerRockFullDetail);
    let (by_chunk, by_chunk_stats) = picture(Culling::Chunks);
    eprintln!("off: {all_stats}\nper rock: {per_rock_stats}\nby chunk: {by_chunk_stats}");
    assert!(busy(&all));
    let differing =
        |a: &image::RgbaImage, b: &image::RgbaImage| a.pixels().zip(b.pixels()).filter(|(a, b)| a != b).count();
    assert_eq!(differing(&all, &per_rock), 0, "the GPU's frustum test left out a rock a pixel shows");
    assert_eq!(differing(&all, &by_chunk), 0, "the chunk groups left out a rock a pixel shows");
}
