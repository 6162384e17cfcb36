//! The snapshot test against real references: the ocean's sun disc and
//! the sail's rope, painted out, and what each rule makes of them.

use common::image;
use snapshots::reference_path;
use snapshots::snapshot::{self, Rule, Tolerance};

/// The ocean's default view with its sun's disc painted out (each of its
/// pixels given the sky's colour 24 pixels to the left): a small object,
/// 253 pixels here, that the whole-picture figures did not catch.
#[test]
fn the_sun_disc_gone_from_the_ocean_fails_its_snapshot() {
    let reference = image::open(reference_path("voronoi-water", "default")).expect("the reference").to_rgba8();
    // The disc: the brightest pixel of the sky (above the horizon at
    // y = 140) and the pixels around it brighter than the sky beside it.
    let brightness = |p: &image::Rgba<u8>| u32::from(p.0[0]) + u32::from(p.0[1]) + u32::from(p.0[2]);
    let (cx, cy) = (0..reference.width())
        .flat_map(|x| (0..140).map(move |y| (x, y)))
        .max_by_key(|&(x, y)| brightness(reference.get_pixel(x, y)))
        .expect("a sky");
    let mut painted = reference.clone();
    let mut changed = 0;
    for y in cy.saturating_sub(16)..cy + 16 {
        for x in cx.saturating_sub(16)..cx + 16 {
            let sky = *reference.get_pixel(x - 24, y);
            if brightness(reference.get_pixel(x, y)) > brightness(&sky) + 30 {
                painted.put_pixel(x, y, sky);
                changed += 1;
            }
        }
    }
    assert!((150..400).contains(&changed), "the disc found at ({cx}, {cy}) is {changed} pixels");
    let (comparison, _) = snapshot::compare(&reference, &painted);
    assert!(
        comparison.mean <= Tolerance::DEFAULT.mean && comparison.outliers <= Tolerance::DEFAULT.outliers,
        "the whole-picture figures alone see it now: {comparison}; this test no longer shows the patch at work"
    );
    assert!(!comparison.passes(Tolerance::DEFAULT), "{changed} pixels of sun gone passed: {comparison}");
}

/// The sail's sheet, a rope one or two pixels wide running 70 pixels
/// from the boom's end down to the stern, painted out of the ocean's
/// `sail` reference: each of its pixels given the colour between its
/// neighbours two pixels to the left and right. FLIP's tolerance cannot
/// see it go (too thin for a 16×16 patch, too few pixels for the mean);
/// the exact comparison, which holds on the reference's own adapter,
/// does.
#[test]
fn the_sails_rope_gone_fails_the_exact_comparison_where_flip_passes() {
    let path = reference_path("voronoi-water", "sail");
    let reference = image::open(&path).expect("the reference").to_rgba8();
    let near = |a: &image::Rgba<u8>, b: &image::Rgba<u8>, levels: u8| (0..3).all(|c| a.0[c].abs_diff(b.0[c]) <= levels);
    // The rope: in the box between the boom's end and the stern, the
    // pixels unlike both neighbours where the two are alike (a thin
    // line across smooth water, cloth or sky).
    let mut painted = reference.clone();
    let mut changed = 0;
    for y in 214..290 {
        for x in 504..522 {
            let (left, pixel, right) =
                (reference.get_pixel(x - 2, y), reference.get_pixel(x, y), reference.get_pixel(x + 2, y));
            if near(left, right, 6) && !near(pixel, left, 20) && !near(pixel, right, 20) {
                let between = |c: usize| ((u16::from(left.0[c]) + u16::from(right.0[c])) / 2) as u8;
                painted.put_pixel(x, y, image::Rgba([between(0), between(1), between(2), 255]));
                changed += 1;
            }
        }
    }
    assert!((70..140).contains(&changed), "the rope found is {changed} pixels");
    let scratch = std::env::temp_dir().join(format!("rope-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).unwrap();
    let copy = scratch.join("sail.png");
    std::fs::copy(&path, &copy).unwrap();
    let by_flip = snapshot::check(&painted, &copy, Rule::Perceptual(Tolerance::DEFAULT));
    assert!(by_flip.is_ok(), "FLIP's tolerance sees the rope now: {by_flip:?}; this test no longer shows the gap");
    let exact = snapshot::check(&painted, &copy, Rule::Exact).map(|c| c.mean);
    let Err(snapshot::SnapshotError::NotExact { pixels, .. }) = exact else {
        panic!("the rope gone passed: {exact:?}")
    };
    assert_eq!(pixels, changed);
    std::fs::remove_dir_all(scratch).unwrap();
}
