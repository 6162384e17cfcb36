//! Chapter 11's colours: a boat on a toon sea from sunset to night, with
//! every colour looked up in a gradient rather than written in a shader.
//! Four pictures, 8-bit sRGB, hand-tuned key colours eased into each other
//! by smoothstep: the sky, the light the sun (or the moon) throws, the
//! sun's (or the moon's) disc, and the islands by height.
//!
//! The sun's height, shared by three of them, runs across the picture as
//! u = 0.5 + 0.5 sin(the sun's elevation): 0 with the sun straight below
//! (midnight), 0.5 with it on the horizon, 1 with it overhead. Pixels are
//! read at their centres, u = (x + 0.5) / width, as the GPU samples them,
//! so the horizon falls between columns 127 and 128.

use std::path::Path;

use anyhow::Context as _;

use super::{mix, smoothstep};

/// Width of every gradient: one column per 1/256 of the u axis.
const WIDTH: u32 = 256;
/// Rows of the sky gradient, from the zenith down to the horizon.
const SKY_HEIGHT: u32 = 64;

/// The keys either side of `x` among `keys` (ascending by `at`), and how
/// far `x` is from the first to the second, eased by smoothstep so the
/// colours glide through each key. Before the first key and after the
/// last, that key alone.
fn between<K>(keys: &[K], at: impl Fn(&K) -> f32, x: f32) -> (&K, &K, f32) {
    let next = keys.iter().position(|k| at(k) > x).unwrap_or(keys.len());
    if next == 0 {
        return (&keys[0], &keys[0], 0.0);
    }
    if next == keys.len() {
        return (&keys[next - 1], &keys[next - 1], 0.0);
    }
    let (a, b) = (&keys[next - 1], &keys[next]);
    (a, b, smoothstep(at(a), at(b), x))
}

/// A colour ramp through `keys`, (position, sRGB colour).
fn ramp(keys: &[(f32, [f32; 3])], x: f32) -> [f32; 3] {
    let (a, b, t) = between(keys, |k| k.0, x);
    mix(a.1, b.1, t)
}

/// The sky at one height of the sun: its colour straight up, in the
/// middle rows, and at the horizon, and how high (in sin of the view's
/// elevation) the horizon's colour reaches before it has faded to 1/e.
struct SkyKey {
    u: f32,
    zenith: [f32; 3],
    middle: [f32; 3],
    horizon: [f32; 3],
    band: f32,
}

const fn key(u: f32, zenith: [f32; 3], middle: [f32; 3], horizon: [f32; 3], band: f32) -> SkyKey {
    SkyKey { u, zenith, middle, horizon, band }
}

/// Navy night, the glow of dusk with the sun a few degrees down, sunset
/// with the sun on the horizon, a peachy morning, and cartoon blue day.
const SKY: [SkyKey; 7] = [
    key(0.00, [0.015, 0.022, 0.070], [0.025, 0.040, 0.110], [0.050, 0.080, 0.180], 0.30),
    key(0.42, [0.020, 0.030, 0.090], [0.030, 0.050, 0.130], [0.060, 0.090, 0.200], 0.30),
    key(0.465, [0.070, 0.070, 0.220], [0.300, 0.180, 0.360], [0.800, 0.400, 0.280], 0.10),
    key(0.505, [0.180, 0.200, 0.480], [0.720, 0.420, 0.550], [1.000, 0.600, 0.300], 0.12),
    key(0.555, [0.240, 0.380, 0.780], [0.800, 0.620, 0.680], [1.000, 0.800, 0.550], 0.16),
    key(0.62, [0.250, 0.550, 0.950], [0.550, 0.760, 0.980], [0.880, 0.950, 1.000], 0.22),
    key(1.00, [0.220, 0.520, 0.950], [0.500, 0.740, 0.980], [0.860, 0.940, 1.000], 0.22),
];

/// The sky's colour with the sun at `u` (the shared axis), looking `up`
/// above the horizon (sin of the view's elevation, 0..1): the middle
/// colour shading into the zenith's, and the horizon's colour laid over it,
/// strongest at the horizon and fading upwards.
fn sky(u: f32, up: f32) -> [f32; 3] {
    let (a, b, t) = between(&SKY, |k| k.u, u);
    let at = |k: &SkyKey| {
        let dome = mix(k.middle, k.zenith, smoothstep(0.05, 0.9, up));
        mix(dome, k.horizon, (-up / k.band).exp())
    };
    mix(at(a), at(b), t)
}

/// The light on surfaces: the moon's, cool and dim, while the sun is below
/// (the moon stands opposite it, so highest at midnight); darkest in the
/// twilight just before the sun rises, when neither lights much; deep red
/// just above the horizon, gold, then warm white by day.
const SUNLIGHT: [(f32, [f32; 3]); 7] = [
    (0.00, [0.17, 0.21, 0.34]),
    (0.45, [0.16, 0.20, 0.32]),
    (0.49, [0.08, 0.07, 0.10]),
    (0.52, [0.95, 0.45, 0.20]),
    (0.60, [1.00, 0.76, 0.42]),
    (0.70, [1.00, 0.96, 0.88]),
    (1.00, [1.00, 0.97, 0.90]),
];

/// The moon's disc, drawn while the sun is below the horizon.
const MOON: [f32; 3] = [0.75, 0.80, 0.90];

/// The sun's disc from the horizon (u = 0.5) up: deep red-orange, orange,
/// yellow, near white.
const SUN: [(f32, [f32; 3]); 5] = [
    (0.50, [1.00, 0.35, 0.10]),
    (0.53, [1.00, 0.48, 0.16]),
    (0.60, [1.00, 0.72, 0.30]),
    (0.80, [1.00, 0.97, 0.85]),
    (1.00, [1.00, 0.98, 0.90]),
];

/// The disc's colour with the sun at `u`: the moon below 0.5, the sun
/// above, blended across the four columns nearest the horizon.
fn disc(u: f32) -> [f32; 3] {
    let half = 2.0 / WIDTH as f32;
    mix(MOON, ramp(&SUN, u.max(0.5)), smoothstep(0.5 - half, 0.5 + half, u))
}

/// The ground by height as a fraction of the island's peak (0 at the
/// waterline, 1 at the summit): wet then dry sand, lush toon grass,
/// darker forest, grey-brown rock and a pale bare top.
const ISLANDS: [(f32, [f32; 3]); 11] = [
    (0.00, [0.76, 0.68, 0.50]),
    (0.03, [0.94, 0.87, 0.66]),
    (0.08, [0.94, 0.87, 0.66]),
    (0.13, [0.40, 0.68, 0.27]),
    (0.45, [0.30, 0.62, 0.25]),
    (0.60, [0.16, 0.42, 0.18]),
    (0.67, [0.17, 0.38, 0.18]),
    (0.75, [0.50, 0.45, 0.40]),
    (0.88, [0.56, 0.52, 0.47]),
    (0.95, [0.70, 0.67, 0.62]),
    (1.00, [0.74, 0.71, 0.66]),
];

/// The shared axis, as the provenance spells it.
const U: &str = "the sun's height u = 0.5 + 0.5 sin(elevation), 0 straight below, 0.5 on the horizon, 1 overhead";

/// (file stem, width × height, what it is and what its axes mean; `{U}`
/// stands for the sun's height axis).
const FILES: [(&str, &str, &str); 4] = [
    (
        "sky",
        "256 × 64",
        "the sky's colour; across: {U}; down: the view's elevation, row 0 the zenith, the last row the horizon \
         (v = 1 − sin of the view's elevation); navy night, an orange glow on the horizon with pink above at sunset, \
         cartoon blue by day",
    ),
    (
        "sunlight",
        "256 × 1",
        "the light the sun, or the moon while the sun is down, throws on surfaces; across: {U}; dim \
         cool moonlight, darkest in twilight, deep red-orange just above the horizon, gold, warm white",
    ),
    (
        "sun",
        "256 × 1",
        "the colour of the disc drawn in the sky; across: {U}; the pale moon below the horizon, \
         then the sun, deep red-orange at the horizon to near-white yellow overhead",
    ),
    (
        "islands",
        "256 × 1",
        "the islands' ground; across: height as a fraction of the island's peak, 0 at the waterline, 1 at the \
         summit; wet and dry sand, toon greens, darker forest, grey-brown rock, a pale top",
    ),
];

/// The provenance table's rows for these files.
pub fn provenance() -> String {
    FILES
        .iter()
        .map(|(name, size, what)| {
            format!(
                "| `gradients/{name}.png` | chapter 11's gradient, {size}, sRGB: {what} | painted in \
                 `xtask/src/assets/gradients.rs`: hand-tuned key colours eased into each other by smoothstep, \
                 each pixel taken at its centre |\n",
                what = what.replace("{U}", U)
            )
        })
        .collect()
}

/// Writes the four gradients under `dir`.
pub fn paint(dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir)?;
    // The centre of pixel `i` of `n`, in 0..1.
    let centre = |i: u32, n: u32| (i as f32 + 0.5) / n as f32;
    let row =
        |paint: fn(f32) -> [f32; 3]| image::RgbImage::from_fn(WIDTH, 1, move |x, _| pixel(paint(centre(x, WIDTH))));
    let images = [
        (
            "sky",
            image::RgbImage::from_fn(WIDTH, SKY_HEIGHT, |x, y| {
                pixel(sky(centre(x, WIDTH), 1.0 - centre(y, SKY_HEIGHT)))
            }),
        ),
        ("sunlight", row(|u| ramp(&SUNLIGHT, u))),
        ("sun", row(disc)),
        ("islands", row(|h| ramp(&ISLANDS, h))),
    ];
    for (name, image) in images {
        let path = dir.join(format!("{name}.png"));
        image.save(&path).with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// An sRGB colour in 0..1 as 8-bit.
fn pixel(colour: [f32; 3]) -> image::Rgb<u8> {
    image::Rgb(colour.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8))
}
