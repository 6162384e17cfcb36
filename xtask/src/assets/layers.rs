//! The side-scroller's background (chapter 10): three layers of landscape
//! to stand at different distances behind the level, far mountains, middle
//! hills with floating islands, and a near forest. Each is 1024 × 256,
//! tiles left to right, and is transparent where the sky shows through.

use std::path::Path;

use anyhow::Context as _;

use super::{hash, mix, smoothstep, tileable_noise2};

const WIDTH: u32 = 1024;
const HEIGHT: u32 = 256;

/// Ridge noise along x that tiles every `WIDTH` pixels: octaves of
/// tileable value noise, in about 0..1.
fn ridge(x: f32, octaves: &[(i32, f32)], salt: u32) -> f32 {
    let u = x / WIDTH as f32;
    octaves.iter().map(|&(period, weight)| weight * tileable_noise2(u * period as f32, 0.5, (period, 1), salt)).sum()
}

/// A pixel of a layer: sRGB colour (0..1) and coverage.
type Pixel = ([f32; 3], f32);

/// Blue-grey mountains with snow, fading towards their feet.
fn far(x: u32, y: u32) -> Pixel {
    let (fx, fy) = (x as f32, y as f32);
    let top = 40.0 + 150.0 * (1.0 - ridge(fx, &[(3, 0.55), (7, 0.3), (19, 0.15)], 71));
    let cover = smoothstep(top - 1.0, top + 1.0, fy);
    let depth = ((fy - top) / (HEIGHT as f32 - top)).clamp(0.0, 1.0);
    let rock = mix([0.50, 0.56, 0.66], [0.70, 0.75, 0.82], depth);
    let snow = smoothstep(170.0, 110.0, top) * (1.0 - smoothstep(0.0, 18.0, fy - top));
    (mix(rock, [0.92, 0.94, 0.97], snow * 0.85), cover)
}

/// Green hills, and above them islands floating in the air, as in the
/// engine project's background.
fn middle(x: u32, y: u32) -> Pixel {
    let (fx, fy) = (x as f32, y as f32);
    let top = 150.0 + 70.0 * (1.0 - ridge(fx, &[(4, 0.6), (11, 0.3), (29, 0.1)], 72));
    let hills = smoothstep(top - 1.0, top + 1.0, fy);
    let grass = mix([0.36, 0.52, 0.36], [0.28, 0.40, 0.32], ((fy - top) / 60.0).clamp(0.0, 1.0));
    // Three islands per tile: a flat grassy top, a rocky cone below.
    let mut island: Pixel = ([0.0; 3], 0.0);
    for k in 0..3u32 {
        let centre = WIDTH as f32 * (k as f32 + 0.3 + 0.4 * hash(k * 31 + 5)) / 3.0;
        let (half, top_y) = (40.0 + 30.0 * hash(k * 17 + 9), 50.0 + 40.0 * hash(k * 13 + 2));
        // Across the tile's seam: measure x the short way round.
        let dx = ((fx - centre + WIDTH as f32 / 2.0).rem_euclid(WIDTH as f32)) - WIDTH as f32 / 2.0;
        let t = dx.abs() / half;
        let depth = fy - top_y;
        let bottom = 14.0 + 50.0 * (1.0 - t * t).max(0.0);
        if t < 1.0 && depth >= 0.0 && depth < bottom {
            let colour = if depth < 6.0 {
                [0.40, 0.58, 0.36]
            } else {
                mix([0.52, 0.46, 0.40], [0.40, 0.36, 0.34], depth / bottom)
            };
            island = (colour, 1.0);
        }
    }
    if island.1 > 0.0 { island } else { (grass, hills) }
}

/// A forest edge of dark conifers on a dark green bank.
fn near(x: u32, y: u32) -> Pixel {
    let (fx, fy) = (x as f32, y as f32);
    let bank = 200.0 + 20.0 * (1.0 - ridge(fx, &[(5, 0.7), (13, 0.3)], 73));
    let mut cover = smoothstep(bank - 1.0, bank + 1.0, fy);
    // A tree every 32 pixels, each its own height, a triangle standing on the bank.
    let slot = (x / 32) as f32;
    for k in [-1.0f32, 0.0, 1.0] {
        let index = (slot + k).rem_euclid(WIDTH as f32 / 32.0) as u32;
        let centre = (slot + k) * 32.0 + 16.0 + 10.0 * (hash(index * 7 + 1) - 0.5);
        let height = 70.0 + 80.0 * hash(index * 11 + 3);
        let base = 215.0;
        let up = (base - fy) / height;
        if (0.0..1.0).contains(&up) && (fx - centre).abs() < 18.0 * (1.0 - up) {
            cover = 1.0;
        }
    }
    let shade = 0.8 + 0.2 * tileable_noise2(fx / 16.0, fy / 16.0, ((WIDTH / 16) as i32, (HEIGHT / 16) as i32), 74);
    ([0.10 * shade, 0.22 * shade, 0.16 * shade], cover)
}

type Layer = fn(u32, u32) -> Pixel;

/// (file stem, painter, what it is).
const LAYERS: [(&str, Layer, &str); 3] = [
    ("far", far, "far mountains with snow, blue-grey"),
    ("middle", middle, "green hills and three floating islands"),
    ("near", near, "a forest edge of dark conifers"),
];

/// The provenance table's rows for these files.
pub fn provenance() -> String {
    LAYERS
        .iter()
        .map(|(name, _, what)| {
            format!("| `layers/{name}.png` | parallax layer, {WIDTH} × {HEIGHT}, tiles left to right: {what} | painted in `xtask/src/assets/layers.rs`; alpha 0 where the sky shows |\n")
        })
        .collect()
}

/// Writes every layer under `dir`.
pub fn paint(dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir)?;
    for (name, layer, _) in LAYERS {
        let image = image::RgbaImage::from_fn(WIDTH, HEIGHT, |x, y| {
            let (colour, cover) = layer(x, y);
            let [r, g, b] = colour.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
            image::Rgba([r, g, b, (cover.clamp(0.0, 1.0) * 255.0).round() as u8])
        });
        let path = dir.join(format!("{name}.png"));
        image.save(&path).with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
