//! Worked solutions to the exercises of book page 03, compiled and checked
//! with the chapter's other tests: the page includes them by anchor, and
//! each test asserts the figure its solution states.

use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::noise::{Fbm, perlin3};

/// A field of 8 × 8 chunks (513² samples) without the cliff, with `fbm`.
fn patch(fbm: Fbm) -> TerrainSettings {
    TerrainSettings { chunks_per_side: 8, cliff_height: 0.0, fbm, ..Default::default() }
}

// ANCHOR: steepness
/// Exercise 1: the share of a field's samples steep enough for bare rock
/// (a slope over 35°, where `ground_colour` starts mixing it in), and the
/// mean slope in degrees.
fn steepness(field: &HeightField) -> (f32, f32) {
    let (mut rock, mut sum) = (0, 0.0);
    for z in 0..i64::from(field.size) {
        for x in 0..i64::from(field.size) {
            let slope = field.normal(x, z).y.acos().to_degrees();
            rock += usize::from(slope > 35.0);
            sum += slope;
        }
    }
    let samples = field.heights.len() as f32;
    (rock as f32 / samples, sum / samples)
}
// ANCHOR_END: steepness

#[test]
fn exercise_1_persistence_07_is_mountains_and_03_is_dunes() {
    let fbm = TerrainSettings::default().fbm;
    let measure = |persistence| steepness(&HeightField::generate(patch(Fbm { persistence, ..fbm })));
    let [(rough_rock, rough_slope), (default_rock, default_slope), (smooth_rock, smooth_slope)] =
        [0.7, 0.5, 0.3].map(measure);
    eprintln!(
        "persistence 0.7: {:.1} % rock, mean slope {rough_slope:.1}°; 0.5: {:.1} %, {default_slope:.1}°; \
         0.3: {:.2} %, {smooth_slope:.1}°",
        rough_rock * 100.0,
        default_rock * 100.0,
        smooth_rock * 100.0
    );
    // 0.7: rough ground, a sixth of it bare rock, slopes of 24° on average;
    // 0.3: smooth swells of 8°, no rock at all. (The default 0.5: 10°.)
    assert!((rough_rock - 0.174).abs() < 0.005 && (rough_slope - 24.4).abs() < 0.2);
    assert!(smooth_rock < 0.0005 && (smooth_slope - 7.7).abs() < 0.2);
    assert!(default_rock < 0.0005 && (default_slope - 10.4).abs() < 0.2);
}

// ANCHOR: ridged
/// Exercise 2: ridged noise. Each octave is 1 − |noise|: where the noise
/// crosses zero, |noise| has a crease, and 1 − |noise| a sharp crest.
/// Summed and normalised as `Fbm::sample` sums plain noise.
fn ridged(fbm: &Fbm, x: f64, y: f64, z: f64) -> f64 {
    let (mut sum, mut total, mut amplitude, mut frequency) = (0.0, 0.0, 1.0, 1.0);
    for _ in 0..fbm.octaves {
        sum += amplitude * (1.0 - perlin3(x * frequency, y * frequency, z).abs());
        total += amplitude;
        amplitude *= fbm.persistence;
        frequency *= fbm.lacunarity;
    }
    sum / total
}

/// A height field of ridged noise, sampled where `TerrainSettings::height_at`
/// samples fBm (same scale, slice and height; no cliff), and moved from
/// 0‥1 to −1‥1 like fBm, so the colours by height still fit.
fn ridged_field(settings: TerrainSettings) -> HeightField {
    let scale = f64::from(settings.spacing) / f64::from(settings.feature_size);
    let slice = f64::from(settings.seed) * 7.31 + 0.5;
    let size = settings.samples();
    let heights = (0..size * size)
        .map(|i| {
            let (x, z) = (f64::from(i % size) * scale, f64::from(i / size) * scale);
            (2.0 * ridged(&settings.fbm, x, z, slice) - 1.0) as f32 * settings.height
        })
        .collect();
    HeightField { settings, size, heights }
}
// ANCHOR_END: ridged

// ANCHOR: sharpest_crest
/// Exercise 2: how sharp the sharpest crest is. Along every row, the
/// slope up to a sample and the slope down from it, as angles: their
/// difference is how much the ground bends there, within one metre.
fn sharpest_crest(field: &HeightField) -> f32 {
    let spacing = field.settings.spacing;
    let mut sharpest = 0.0f32;
    for z in 0..i64::from(field.size) {
        for x in 1..i64::from(field.size) - 1 {
            let up = ((field.height(x, z) - field.height(x - 1, z)) / spacing).atan();
            let down = ((field.height(x + 1, z) - field.height(x, z)) / spacing).atan();
            sharpest = sharpest.max((up - down).to_degrees());
        }
    }
    sharpest
}
// ANCHOR_END: sharpest_crest

#[test]
fn exercise_2_ridged_noise_has_crests_sharper_than_fbm_ever_bends() {
    let settings = patch(TerrainSettings::default().fbm);
    let (smooth, ridges) = (sharpest_crest(&HeightField::generate(settings)), sharpest_crest(&ridged_field(settings)));
    eprintln!("the sharpest bend in one metre: fBm {smooth:.1}°, ridged {ridges:.1}°");
    // fBm's fade curve makes every octave smooth: the ground bends by 3.8°
    // at most across a metre. Ridged noise folds by 57° at its crests.
    assert!((smooth - 3.8).abs() < 0.1 && (ridges - 57.5).abs() < 0.5, "fBm {smooth}°, ridged {ridges}°");
}
