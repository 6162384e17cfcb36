//! The snapshot comparison itself: identical pictures score zero, one
//! level of rounding is the same colour, a small object gone fails by its
//! patch, the worst patch is the worst square's mean, a missing reference
//! or another size fails, and a failure writes the actual picture and
//! FLIP's map.

use std::path::PathBuf;

use common::image;
use snapshots::snapshot::Rule;
use snapshots::snapshot::{SnapshotError, Tolerance, check, compare, flip, worst_patch};

fn scene(shift: u32) -> image::RgbaImage {
    image::RgbaImage::from_fn(64, 48, |x, y| {
        let inside = (20 + shift..40 + shift).contains(&x) && (10..30).contains(&y);
        if inside { image::Rgba([230, 120, 30, 255]) } else { image::Rgba([20, 30, 60, 255]) }
    })
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("snapshot-test-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn identical_pictures_score_zero() {
    let (comparison, _) = compare(&scene(0), &scene(0));
    assert_eq!(comparison.mean, 0.0);
    // The shortcut agrees with FLIP itself.
    let (by_flip, _) = flip(&scene(0), &scene(0));
    assert_eq!((by_flip.mean, by_flip.outliers), (0.0, 0.0));
    assert!(by_flip.max <= f32::MIN_POSITIVE, "FLIP's pool starts its maximum at the smallest float");
    assert!(comparison.passes(Tolerance::DEFAULT));
}

#[test]
fn one_level_of_rounding_is_the_same_colour_and_two_are_not() {
    let nudged = |by: u8| {
        let mut picture = scene(0);
        for pixel in picture.pixels_mut() {
            pixel.0[0] += by;
        }
        picture
    };
    // Every pixel one level off: equal, however much of the picture it is.
    assert_eq!(compare(&scene(0), &nudged(1)).0.mean, 0.0);
    // Two levels are a difference FLIP scores, and the shortcut no longer applies.
    let (two, _) = compare(&scene(0), &nudged(2));
    assert!(two.mean > 0.0, "{two}");
    // Rounding beside a real change leaves the real change to FLIP.
    let mut moved = scene(6);
    moved.pixels_mut().for_each(|p| p.0[1] += 1);
    let (real, _) = compare(&scene(0), &moved);
    assert!(!real.passes(Tolerance::DEFAULT), "{real}");
}

/// An 800 × 450 dusk sky with a small bright disc of radius 6 (113
/// pixels), or without it.
fn sky(with_sun: bool) -> image::RgbaImage {
    image::RgbaImage::from_fn(800, 450, |x, y| {
        let (dx, dy) = (x as f32 - 600.0, y as f32 - 120.0);
        let sun = with_sun && dx * dx + dy * dy <= 36.0;
        if sun { image::Rgba([255, 236, 200, 255]) } else { image::Rgba([40 + (y / 6) as u8, 60, 110, 255]) }
    })
}

#[test]
fn a_small_object_gone_fails_by_its_patch_alone() {
    let (comparison, _) = compare(&sky(true), &sky(false));
    // Too few pixels for the mean or the share of outliers…
    assert!(comparison.mean <= Tolerance::DEFAULT.mean, "{comparison}");
    assert!(comparison.outliers <= Tolerance::DEFAULT.outliers, "{comparison}");
    // …but all in one place.
    assert!(comparison.patch > Tolerance::DEFAULT.patch, "{comparison}");
    assert!(!comparison.passes(Tolerance::DEFAULT));
}

#[test]
fn the_worst_patch_is_the_mean_over_the_worst_square() {
    // A 16×16 square of error 1 at an odd place in a 40×30 map, and noise of 0.01.
    let (w, h) = (40u32, 30u32);
    let mut error = vec![0.01f32; (w * h) as usize];
    for y in 7..23 {
        for x in 13..29 {
            error[(y * w + x) as usize] = 1.0;
        }
    }
    assert!((worst_patch(&error, w, h) - 1.0).abs() < 1e-6);
    // Half of it: the best square still holds 8 × 16 of the ones.
    for y in 7..23 {
        for x in 21..29 {
            error[(y * w + x) as usize] = 0.01;
        }
    }
    let expected = (128.0 + 128.0 * 0.01) / 256.0;
    assert!((worst_patch(&error, w, h) - expected).abs() < 1e-6, "{}", worst_patch(&error, w, h));
}

#[test]
fn a_missing_reference_fails_and_writes_the_actual_picture() {
    let dir = temp_dir("missing");
    let reference = dir.join("view.png");
    let error = check(&scene(0), &reference, Rule::Perceptual(Tolerance::DEFAULT)).unwrap_err();
    assert!(matches!(error, SnapshotError::Missing { .. }), "{error}");
    assert!(dir.join("view-actual.png").exists());
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_moved_object_fails_with_actual_and_diff_written() {
    let dir = temp_dir("moved");
    let reference = dir.join("view.png");
    scene(0).save(&reference).unwrap();
    assert!(check(&scene(0), &reference, Rule::Perceptual(Tolerance::DEFAULT)).is_ok());
    let error = check(&scene(6), &reference, Rule::Perceptual(Tolerance::DEFAULT)).unwrap_err();
    let SnapshotError::TooDifferent { comparison, .. } = &error else { panic!("{error}") };
    assert!(comparison.outliers > 0.05, "{comparison}");
    assert!(dir.join("view-actual.png").exists() && dir.join("view-diff.png").exists());
    // Passing again clears the stale failure pictures.
    assert!(check(&scene(0), &reference, Rule::Perceptual(Tolerance::DEFAULT)).is_ok());
    assert!(!dir.join("view-actual.png").exists());
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_different_size_fails() {
    let dir = temp_dir("size");
    let reference = dir.join("view.png");
    scene(0).save(&reference).unwrap();
    let small = image::RgbaImage::new(8, 8);
    assert!(matches!(
        check(&small, &reference, Rule::Perceptual(Tolerance::DEFAULT)),
        Err(SnapshotError::WrongSize { .. })
    ));
    std::fs::remove_dir_all(dir).unwrap();
}
