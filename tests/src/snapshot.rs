//! Comparing a rendered picture with its reference: exactly (within one
//! colour level) on the adapter the reference was made on, which draws the
//! same bytes every run, and elsewhere by NVIDIA's FLIP metric, which
//! scores differences the way a viewer would notice them.

use std::fmt;
use std::path::{Path, PathBuf};

use common::image;

pub use common::chapter::Tolerance;

/// The FLIP figures of one comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    pub mean: f32,
    pub p99: f32,
    pub max: f32,
    /// Fraction of pixels above [`Tolerance::OUTLIER_ERROR`].
    pub outliers: f32,
    /// The mean over the worst [`Tolerance::PATCH`]-pixel square.
    pub patch: f32,
}

impl Comparison {
    /// Identical pictures (rounding aside).
    pub const SAME: Self = Self { mean: 0.0, p99: 0.0, max: 0.0, outliers: 0.0, patch: 0.0 };

    pub fn passes(&self, tolerance: Tolerance) -> bool {
        self.mean <= tolerance.mean && self.outliers <= tolerance.outliers && self.patch <= tolerance.patch
    }
}

impl fmt::Display for Comparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "FLIP mean {:.5}, p99 {:.4}, max {:.4}, {:.3}% of pixels above {}, worst {p}×{p} patch {:.3}",
            self.mean,
            self.p99,
            self.max,
            100.0 * self.outliers,
            Tolerance::OUTLIER_ERROR,
            self.patch,
            p = Tolerance::PATCH
        )
    }
}

/// How a picture must match its reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rule {
    /// Every pixel within [`SAME_COLOUR`] of the reference in every
    /// channel: on the adapter the reference was made on (the bless log
    /// says which), where a picture is the same bytes run after run. A
    /// one-pixel line of any length gone fails it.
    Exact,
    /// FLIP within a tolerance: on any other adapter, whose rasteriser
    /// rounds and places edges its own way.
    Perceptual(Tolerance),
}

impl fmt::Display for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Exact => write!(f, "exact (the adapter it was made on)"),
            Self::Perceptual(_) => write!(f, "by FLIP (another adapter than the one it was made on)"),
        }
    }
}

/// How many pixels of `actual` differ from `reference` (same size) by more
/// than [`SAME_COLOUR`] in some channel, and the largest difference.
pub fn beyond_rounding(reference: &image::RgbaImage, actual: &image::RgbaImage) -> (usize, u8) {
    reference.pixels().zip(actual.pixels()).fold((0, 0), |(count, worst), (a, b)| {
        let most = (0..3).map(|c| a.0[c].abs_diff(b.0[c])).max().unwrap_or(0);
        if most > SAME_COLOUR { (count + 1, worst.max(most)) } else { (count, worst) }
    })
}

/// Why a snapshot did not pass.
#[derive(Debug)]
pub enum SnapshotError {
    /// There is no reference image: a failure, never a silent pass.
    Missing {
        reference: PathBuf,
        actual: PathBuf,
    },
    Unreadable {
        reference: PathBuf,
        reason: String,
    },
    WrongSize {
        reference: PathBuf,
        expected: (u32, u32),
        found: (u32, u32),
        actual: PathBuf,
    },
    TooDifferent {
        comparison: Comparison,
        tolerance: Tolerance,
        actual: PathBuf,
        diff: PathBuf,
    },
    /// On the adapter the reference was made on, pixels moved by more than
    /// rounding.
    NotExact {
        pixels: usize,
        worst: u8,
        comparison: Comparison,
        actual: PathBuf,
        diff: PathBuf,
    },
    CannotWrite {
        path: PathBuf,
        reason: String,
    },
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Missing { reference, actual } => write!(
                f,
                "no reference image {}; the picture rendered now is {} (look at it, then `cargo xtask snapshot --bless`)",
                reference.display(),
                actual.display()
            ),
            Self::Unreadable { reference, reason } => {
                write!(f, "cannot read reference {}: {reason}", reference.display())
            }
            Self::WrongSize { reference, expected, found, actual } => write!(
                f,
                "{} is {}x{} but the render is {}x{} (written to {})",
                reference.display(),
                expected.0,
                expected.1,
                found.0,
                found.1,
                actual.display()
            ),
            Self::TooDifferent { comparison, tolerance, actual, diff } => write!(
                f,
                "{comparison} (allowed: mean {}, {}% above {}, patch {}); actual: {}, FLIP error map: {}",
                tolerance.mean,
                100.0 * tolerance.outliers,
                Tolerance::OUTLIER_ERROR,
                tolerance.patch,
                actual.display(),
                diff.display()
            ),
            Self::NotExact { pixels, worst, comparison, actual, diff } => write!(
                f,
                "{pixels} pixels differ by more than {SAME_COLOUR} colour level (up to {worst}), on the adapter the \
                 reference was made on, which must draw it within {SAME_COLOUR} ({comparison}); actual: {}, FLIP \
                 error map: {}",
                actual.display(),
                diff.display()
            ),
            Self::CannotWrite { path, reason } => write!(f, "cannot write {}: {reason}", path.display()),
        }
    }
}

impl std::error::Error for SnapshotError {}

/// `tests/snapshots/x/view.png` → `tests/snapshots/x/view-<suffix>.png`.
pub fn sibling(reference: &Path, suffix: &str) -> PathBuf {
    let stem = reference.file_stem().unwrap_or_default().to_string_lossy();
    reference.with_file_name(format!("{stem}-{suffix}.png"))
}

fn save(image: &image::RgbaImage, path: &Path) -> Result<(), SnapshotError> {
    image.save(path).map_err(|e| SnapshotError::CannotWrite { path: path.into(), reason: e.to_string() })
}

fn rgb(image: &image::RgbaImage) -> nv_flip::FlipImageRgb8 {
    let data: Vec<u8> = image.pixels().flat_map(|p| [p[0], p[1], p[2]]).collect();
    nv_flip::FlipImageRgb8::with_data(image.width(), image.height(), &data)
}

/// The most a channel may differ by and still count as the same colour:
/// one level of 255. Software rasterisers on two machines round a few
/// colours differently by that much (lavapipe on two EPYC machines turned
/// chapter 09's pale checker squares from 232 to 233 red: a third of the
/// picture, FLIP mean 0.012), which no viewer sees and no bug makes alone.
pub const SAME_COLOUR: u8 = 1;

/// Scores `actual` against `reference` (same size) and returns the figures
/// and FLIP's colour-mapped error image. Pixels within [`SAME_COLOUR`] of
/// the reference in every channel count as equal. Pictures with the same
/// colours score zero without running FLIP (about 0.2 s a picture), which
/// is what a snapshot on the adapter that made its reference scores every
/// time.
pub fn compare(reference: &image::RgbaImage, actual: &image::RgbaImage) -> (Comparison, image::RgbImage) {
    let same = |a: &image::Rgba<u8>, b: &image::Rgba<u8>| (0..3).all(|c| a.0[c].abs_diff(b.0[c]) <= SAME_COLOUR);
    let same_colours = reference.dimensions() == actual.dimensions()
        && reference.pixels().zip(actual.pixels()).all(|(a, b)| same(a, b));
    if same_colours {
        return (Comparison::SAME, image::RgbImage::new(actual.width(), actual.height()));
    }
    // FLIP sees the differences that are more than rounding.
    let mut rounded = actual.clone();
    for (mine, theirs) in rounded.pixels_mut().zip(reference.pixels()) {
        if same(mine, theirs) {
            *mine = *theirs;
        }
    }
    flip(reference, &rounded)
}

/// [`compare`] by FLIP, whatever the pictures.
pub fn flip(reference: &image::RgbaImage, actual: &image::RgbaImage) -> (Comparison, image::RgbImage) {
    let error = nv_flip::flip(rgb(reference), rgb(actual), nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    let values = error.to_vec();
    let mut pool = nv_flip::FlipPool::from_image(&error);
    let comparison = Comparison {
        mean: pool.mean(),
        p99: pool.get_percentile(0.99, false),
        max: pool.max_value(),
        outliers: values.iter().filter(|&&e| e > Tolerance::OUTLIER_ERROR).count() as f32 / values.len() as f32,
        patch: worst_patch(&values, error.width(), error.height()),
    };
    let heat = error.apply_color_lut(&nv_flip::magma_lut());
    let diff = image::RgbImage::from_raw(heat.width(), heat.height(), heat.to_vec()).expect("FLIP returns w*h*3 bytes");
    (comparison, diff)
}

/// The largest mean of `error` (a `width` × `height` map, row by row) over
/// any [`Tolerance::PATCH`]-pixel square, at every position: with a
/// summed-area table each square's sum is four lookups.
pub fn worst_patch(error: &[f32], width: u32, height: u32) -> f32 {
    worst_square(error, width, height).0
}

/// [`worst_patch`], and where its square's top left corner is.
fn worst_square(values: &[f32], width: u32, height: u32) -> (f32, u32, u32) {
    let (w, h) = (width as usize, height as usize);
    let side = (Tolerance::PATCH as usize).min(w).min(h);
    if side == 0 {
        return (0.0, 0, 0);
    }
    // sums[y][x]: the sum over the rectangle above and left of (x, y), in f64
    // so that 360,000 small values add up without losing the small ones.
    let mut sums = vec![0.0f64; (w + 1) * (h + 1)];
    for y in 0..h {
        let mut row = 0.0;
        for x in 0..w {
            row += f64::from(values[y * w + x]);
            sums[(y + 1) * (w + 1) + x + 1] = sums[y * (w + 1) + x + 1] + row;
        }
    }
    let at = |x: usize, y: usize| sums[y * (w + 1) + x];
    let mut worst = (0.0f64, 0, 0);
    for y in 0..=h - side {
        for x in 0..=w - side {
            let sum = at(x + side, y + side) - at(x, y + side) - at(x + side, y) + at(x, y);
            if sum > worst.0 {
                worst = (sum, x, y);
            }
        }
    }
    ((worst.0 / (side * side) as f64) as f32, worst.1 as u32, worst.2 as u32)
}

// ANCHOR: tells_apart
/// Whether the snapshot test tells `a` from `b` (same size): would a view
/// whose reference is `a` fail, drawing `b`? Two views that it cannot tell
/// apart leave one of them unchecked.
///
/// FLIP on the whole picture takes about 0.2 s, and a chapter's twelve views
/// make 66 pairs, so first the square where the colours differ most is
/// scored with a margin around it (FLIP's filters reach a few pixels, the
/// margin is 32): a patch there past the tolerance settles it. Otherwise
/// the whole pictures are compared.
pub fn tells_apart(a: &image::RgbaImage, b: &image::RgbaImage, tolerance: Tolerance) -> bool {
    assert_eq!(a.dimensions(), b.dimensions(), "views are rendered at one size");
    let colour_difference: Vec<f32> = a
        .pixels()
        .zip(b.pixels())
        .map(|(p, q)| (0..3).map(|c| p.0[c].abs_diff(q.0[c])).max().unwrap_or(0) as f32)
        .collect();
    let (_, x, y) = worst_square(&colour_difference, a.width(), a.height());
    const MARGIN: u32 = 32;
    let (left, top) = (x.saturating_sub(MARGIN), y.saturating_sub(MARGIN));
    let (right, bottom) =
        ((x + Tolerance::PATCH + MARGIN).min(a.width()), (y + Tolerance::PATCH + MARGIN).min(a.height()));
    let crop = |picture: &image::RgbaImage| {
        image::imageops::crop_imm(picture, left, top, right - left, bottom - top).to_image()
    };
    if compare(&crop(a), &crop(b)).0.patch > tolerance.patch {
        return true;
    }
    !compare(a, b).0.passes(tolerance)
}
// ANCHOR_END: tells_apart

/// Checks `actual` against the reference PNG by `rule`. On failure the
/// rendered picture is written beside the reference as `<view>-actual.png`,
/// with the FLIP error map as `<view>-diff.png`. Stale ones are removed on
/// success.
pub fn check(actual: &image::RgbaImage, reference: &Path, rule: Rule) -> Result<Comparison, SnapshotError> {
    let actual_path = sibling(reference, "actual");
    let diff_path = sibling(reference, "diff");
    if !reference.exists() {
        if let Some(dir) = actual_path.parent() {
            let _ = std::fs::create_dir_all(dir);
        }
        save(actual, &actual_path)?;
        return Err(SnapshotError::Missing { reference: reference.into(), actual: actual_path });
    }
    let expected = image::open(reference)
        .map_err(|e| SnapshotError::Unreadable { reference: reference.into(), reason: e.to_string() })?
        .to_rgba8();
    if expected.dimensions() != actual.dimensions() {
        save(actual, &actual_path)?;
        return Err(SnapshotError::WrongSize {
            reference: reference.into(),
            expected: expected.dimensions(),
            found: actual.dimensions(),
            actual: actual_path,
        });
    }
    let (comparison, diff) = compare(&expected, actual);
    let (pixels, worst) = beyond_rounding(&expected, actual);
    let passes = match rule {
        Rule::Exact => pixels == 0,
        Rule::Perceptual(tolerance) => comparison.passes(tolerance),
    };
    if passes {
        let _ = std::fs::remove_file(&actual_path);
        let _ = std::fs::remove_file(&diff_path);
        return Ok(comparison);
    }
    save(actual, &actual_path)?;
    diff.save(&diff_path).map_err(|e| SnapshotError::CannotWrite { path: diff_path.clone(), reason: e.to_string() })?;
    Err(match rule {
        Rule::Exact => SnapshotError::NotExact { pixels, worst, comparison, actual: actual_path, diff: diff_path },
        Rule::Perceptual(tolerance) => {
            SnapshotError::TooDifferent { comparison, tolerance, actual: actual_path, diff: diff_path }
        }
    })
}
