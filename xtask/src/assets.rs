//! `cargo xtask assets`: paints every texture the book uses, from code.
//! Deterministic (no clock, fixed hashes), so running it again rewrites the
//! same bytes; the files are committed under `assets/` with this provenance.

use std::path::Path;

use anyhow::Context as _;

mod gradients;
mod layers;
mod materials;
pub mod models;

/// Cube face order as WebGPU expects it, with the direction through pixel
/// (u, v) of each face, u and v in −1..1 (v down the image).
type FaceDirection = fn(f32, f32) -> [f32; 3];

const FACES: [(&str, FaceDirection); 6] = [
    ("px", |u, v| [1.0, -v, -u]),
    ("nx", |u, v| [-1.0, -v, u]),
    ("py", |u, v| [u, 1.0, v]),
    ("ny", |u, v| [u, -1.0, -v]),
    ("pz", |u, v| [u, -v, 1.0]),
    ("nz", |u, v| [-u, -v, -1.0]),
];

/// Face size in pixels: about a third of a degree per pixel.
const FACE_SIZE: u32 = 256;

fn normalize(d: [f32; 3]) -> [f32; 3] {
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    [d[0] / l, d[1] / l, d[2] / l]
}

fn mix(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t]
}

fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// A fixed integer hash to [0, 1): the same on every machine.
fn hash(mut x: u32) -> f32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    (x >> 8) as f32 / (1u32 << 24) as f32
}

/// Smooth value noise on a 3D lattice, for faint dust in the day sky.
fn value_noise(p: [f32; 3]) -> f32 {
    let cell = p.map(f32::floor);
    let f = [p[0] - cell[0], p[1] - cell[1], p[2] - cell[2]].map(|t| t * t * (3.0 - 2.0 * t));
    let corner = |dx: i32, dy: i32, dz: i32| {
        let (x, y, z) = (cell[0] as i32 + dx, cell[1] as i32 + dy, cell[2] as i32 + dz);
        hash(
            (x as u32).wrapping_mul(73_856_093)
                ^ (y as u32).wrapping_mul(19_349_663)
                ^ (z as u32).wrapping_mul(83_492_791),
        )
    };
    let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
    let x00 = lerp(corner(0, 0, 0), corner(1, 0, 0), f[0]);
    let x10 = lerp(corner(0, 1, 0), corner(1, 1, 0), f[0]);
    let x01 = lerp(corner(0, 0, 1), corner(1, 0, 1), f[0]);
    let x11 = lerp(corner(0, 1, 1), corner(1, 1, 1), f[0]);
    lerp(lerp(x00, x10, f[1]), lerp(x01, x11, f[1]), f[2])
}

/// The Martian day atmosphere in sRGB 0..1: butterscotch, darker towards
/// the zenith, with faint dust. No sun: the sky shader draws it where the
/// light comes from, so that the two cannot disagree.
fn day_sky(d: [f32; 3]) -> [f32; 3] {
    let horizon = [0.80, 0.60, 0.44];
    let zenith = [0.56, 0.40, 0.30];
    let ground = [0.42, 0.30, 0.22];
    let up = d[1];
    let colour = if up >= 0.0 {
        mix(horizon, zenith, smoothstep(0.0, 0.9, up))
    } else {
        mix(horizon, ground, smoothstep(0.0, 0.3, -up))
    };
    let dust = value_noise([d[0] * 5.0 + 11.0, d[1] * 9.0, d[2] * 5.0]) * 0.5
        + value_noise([d[0] * 13.0, d[1] * 21.0 + 3.0, d[2] * 13.0]) * 0.5;
    mix(colour, [0.86, 0.68, 0.52], 0.25 * dust * smoothstep(0.0, 0.3, up))
}

/// The night sky: stars on near black, all the way round, since the sky
/// turns and any part of it may rise. Stars are scattered by a hash of the
/// pixel (about one pixel in 300).
fn night_sky(_: [f32; 3], pixel_id: u32) -> [f32; 3] {
    let background = [0.03, 0.03, 0.05];
    if hash(pixel_id) <= 0.9967 {
        return background;
    }
    let brightness = 0.35 + 0.65 * hash(pixel_id ^ 0x5bd1_e995).powi(3);
    let tint = hash(pixel_id.wrapping_mul(31));
    mix(background, mix([0.85, 0.88, 1.0], [1.0, 0.86, 0.7], tint), brightness)
}

/// Value noise that tiles: the lattice wraps every `period` cells, so the
/// texture's right edge meets its left and its bottom its top.
fn tileable_noise(x: f32, y: f32, period: i32, salt: u32) -> f32 {
    tileable_noise2(x, y, (period, period), salt)
}

/// [`tileable_noise`] with its own period across and down, for noise
/// stretched one way (brushed metal).
fn tileable_noise2(x: f32, y: f32, (period_x, period_y): (i32, i32), salt: u32) -> f32 {
    let (cx, cy) = (x.floor() as i32, y.floor() as i32);
    let (fx, fy) = (x - cx as f32, y - cy as f32);
    let (sx, sy) = (fx * fx * (3.0 - 2.0 * fx), fy * fy * (3.0 - 2.0 * fy));
    let corner = |dx: i32, dy: i32| {
        let (ix, iy) = ((cx + dx).rem_euclid(period_x) as u32, (cy + dy).rem_euclid(period_y) as u32);
        hash(ix.wrapping_mul(73_856_093) ^ iy.wrapping_mul(19_349_663) ^ salt.wrapping_mul(83_492_791))
    };
    let top = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * sx;
    let bottom = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * sx;
    top + (bottom - top) * sy
}

/// Three octaves of tileable noise at `u, v` in 0..1, in about 0..1.
fn tileable_fbm(u: f32, v: f32, salt: u32) -> f32 {
    [(4, 0.55), (8, 0.3), (16, 0.15)]
        .iter()
        .map(|&(period, weight)| weight * tileable_noise(u * period as f32, v * period as f32, period, salt))
        .sum()
}

/// The water's textures, 256² and tileable: the DuDv map stores a
/// distortion (du, dv) in red and green around 0.5; the normal map stores
/// the surface normal of a noise height field h with x in red, z in green
/// and up in blue, each mapped from −1..1 to 0..1; the texture is seed
/// 003's style's picture of water ([`water_colour`]).
fn paint_water(dir: &Path) -> anyhow::Result<()> {
    const SIZE: u32 = 256;
    std::fs::create_dir_all(dir)?;
    let at = |x: u32, y: u32, salt| tileable_fbm(x as f32 / SIZE as f32, y as f32 / SIZE as f32, salt);
    let dudv = image::RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let (du, dv) = (at(x, y, 1), at(x, y, 2));
        image::Rgb([(du * 255.0).round() as u8, (dv * 255.0).round() as u8, 0])
    });
    let height = |x: u32, y: u32| at(x % SIZE, y % SIZE, 3);
    let normal = image::RgbImage::from_fn(SIZE, SIZE, |x, y| {
        // Central differences, wrapping at the edges like the texture does.
        let dx = height(x + 1, y) - height(x + SIZE - 1, y);
        let dz = height(x, y + 1) - height(x, y + SIZE - 1);
        let n = normalize([-dx * 12.0, 1.0, -dz * 12.0]);
        image::Rgb([n[0], n[2], n[1]].map(|c| ((c * 0.5 + 0.5) * 255.0).round() as u8))
    });
    let texture = image::RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let colour = water_colour(x as f32 / SIZE as f32, y as f32 / SIZE as f32);
        image::Rgb(colour.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8))
    });
    for (name, image) in [("dudv.png", dudv), ("normal.png", normal), ("texture.png", texture)] {
        let path = dir.join(name);
        image.save(&path).with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// The nearest and second-nearest distances from (x, y) to points
/// scattered one per unit cell, the cells repeating every `period` (Worley's
/// cellular noise, tileable): a cell's point comes from a hash of its index
/// wrapped by the period, so the cells past the right edge hold the same
/// points as those at the left edge.
fn tileable_cells(x: f32, y: f32, period: i32, salt: u32) -> (f32, f32) {
    let (cx, cy) = (x.floor() as i32, y.floor() as i32);
    let (mut nearest, mut second) = (f32::MAX, f32::MAX);
    for dy in -1..=1 {
        for dx in -1..=1 {
            let (ix, iy) = (cx + dx, cy + dy);
            let (wx, wy) = (ix.rem_euclid(period) as u32, iy.rem_euclid(period) as u32);
            let key = wx.wrapping_mul(73_856_093) ^ wy.wrapping_mul(19_349_663) ^ salt.wrapping_mul(83_492_791);
            let (px, py) = (ix as f32 + hash(key), iy as f32 + hash(key ^ 0x9e37_79b9));
            let d = ((px - x) * (px - x) + (py - y) * (py - y)).sqrt();
            if d < nearest {
                (nearest, second) = (d, nearest);
            } else if d < second {
                second = d;
            }
        }
    }
    (nearest, second)
}

// ANCHOR: water_texture
/// Seed 003's look, our own picture of it: the colour (sRGB, 0..1) of the
/// tiled water texture at (u, v) in 0..1. Deep teal-blue, lighter where a
/// slow noise field rises, with a net of bright lines where the light
/// gathers under the ripples (caustics: the edges between Worley cells,
/// where the nearest two points are nearly as near, bent by noise so the
/// net is not a tiling of polygons). Green and blue matter beyond their
/// colour: the shader offsets its second read by them, so they carry
/// different fields: green mostly the caustic net, blue a noise field of
/// its own. Everything here repeats with period 1 in u and v, so the
/// texture tiles.
fn water_colour(u: f32, v: f32) -> [f32; 3] {
    // Worley cells across the texture (and so across a tile).
    const CELLS: i32 = 6;
    let depth = tileable_fbm(u, v, 4);
    let tint = tileable_fbm(u, v, 5);
    // Bend the cells by noise that tiles too: whole periods still line up.
    let (bend_u, bend_v) = (tileable_fbm(u, v, 6) - 0.5, tileable_fbm(u, v, 7) - 0.5);
    let (nearest, second) =
        tileable_cells((u + 0.25 * bend_u) * CELLS as f32, (v + 0.25 * bend_v) * CELLS as f32, CELLS, 8);
    let caustic = 1.0 - smoothstep(0.0, 0.14, second - nearest);
    let base = mix([0.05, 0.24, 0.36], [0.12, 0.38, 0.40], smoothstep(0.25, 0.75, depth));
    // The caustic light is mostly red and green, and blue follows its own
    // field: green and blue then correlate by about 0.4, not 1.
    let (light, blue) = ([0.28, 0.32, 0.12].map(|c| c * caustic), 0.45 * (tint - 0.5));
    [base[0] + light[0], base[1] + light[1], base[2] + light[2] + blue]
}
// ANCHOR_END: water_texture

fn paint_cubemap(dir: &Path, paint: impl Fn([f32; 3], u32) -> [f32; 3]) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir)?;
    for (face_index, (name, direction)) in FACES.iter().enumerate() {
        let image = image::RgbImage::from_fn(FACE_SIZE, FACE_SIZE, |x, y| {
            let u = 2.0 * (x as f32 + 0.5) / FACE_SIZE as f32 - 1.0;
            let v = 2.0 * (y as f32 + 0.5) / FACE_SIZE as f32 - 1.0;
            let id = (face_index as u32 * FACE_SIZE + y) * FACE_SIZE + x;
            let c = paint(normalize(direction(u, v)), id.wrapping_mul(2_654_435_761));
            image::Rgb(c.map(|t| (t.clamp(0.0, 1.0) * 255.0).round() as u8))
        });
        let path = dir.join(format!("{name}.png"));
        image.save(&path).with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

const PROVENANCE: &str = "\
# Assets

Every file here is painted by code in this repository, `xtask/src/assets.rs`,
run by `cargo xtask assets`. Nothing is downloaded or copied from elsewhere.
The generator uses fixed hashes and no clock, so running it again writes the
same bytes.

| files | what | how |
|---|---|---|
| `skybox/day/{px,nx,py,ny,pz,nz}.png` | Martian day atmosphere, 6 × 256² cube faces | horizon-to-zenith butterscotch gradient, darker below the horizon, faint value-noise dust; no sun (the sky shader draws it where the light is) |
| `skybox/night/{px,nx,py,ny,pz,nz}.png` | star field, 6 × 256² cube faces | near black, stars where a per-pixel hash exceeds 0.9967, all the way round |
| `water/dudv.png` | DuDv distortion map, 256², tileable | two independent tileable value-noise fields (3 octaves, periods 4, 8, 16) in red and green, 0.5 meaning no distortion |
| `water/normal.png` | water normal map, 256², tileable | normals of a third tileable noise field by wrapped central differences; red = x, green = z, blue = up |
| `water/texture.png` | chapter 07's seed-003 style: a water picture, 256², sRGB, tileable | deep teal-blue shaded by tileable value noise, a net of bright caustic lines (edges of tileable Worley cells, period 6, bent by noise), blue shifted by a noise field of its own so that green and blue, which the shader offsets its second read by, differ |
";

const PROVENANCE_NOTES: &str = "
Faces are in WebGPU's order (+x, −x, +y, −y, +z, −z); the direction
through pixel (u, v) of each face is in `FACES` in the generator.

The city's textures (`textures/`, chapter 09) are 256², tileable, painted
in `xtask/src/assets/materials.rs`: albedo in sRGB (its alpha, where used,
marks what glows at night), normal maps in tangent space with the OpenGL
convention (red +u, green up the image, blue out of the surface). The
models (`models/`) are Wavefront OBJ with MTL materials whose texture paths
are relative to the MTL file.
";

pub fn generate() -> anyhow::Result<()> {
    paint_all(&crate::root().join("assets"))
}

/// Paints every asset under `root` (a folder laid out like `assets/`).
fn paint_all(root: &Path) -> anyhow::Result<()> {
    paint_cubemap(&root.join("skybox/day"), |d, _| day_sky(d))?;
    paint_cubemap(&root.join("skybox/night"), night_sky)?;
    paint_water(&root.join("water"))?;
    materials::paint(&root.join("textures"))?;
    models::write(&root.join("models"))?;
    layers::paint(&root.join("layers"))?;
    gradients::paint(&root.join("gradients"))?;
    let readme = format!(
        "{PROVENANCE}{}{}{}{}{PROVENANCE_NOTES}",
        materials::provenance(),
        models::provenance(),
        layers::provenance(),
        gradients::provenance()
    );
    std::fs::write(root.join("README.md"), readme)?;
    println!("wrote {}", root.join("README.md").display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The committed assets are exactly what the generator paints: nobody
    /// edited a texture by hand, and nobody changed the generator without
    /// running it.
    #[test]
    fn committed_assets_match_the_generator() {
        let fresh = std::env::temp_dir().join(format!("assets-{}", std::process::id()));
        paint_all(&fresh).unwrap();
        let committed = crate::root().join("assets");
        let mut checked = 0;
        let mut stack = vec![fresh.clone()];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).unwrap() {
                let path = entry.unwrap().path();
                if path.is_dir() {
                    stack.push(path);
                    continue;
                }
                let relative = path.strip_prefix(&fresh).unwrap();
                let on_disk = std::fs::read(committed.join(relative))
                    .unwrap_or_else(|e| panic!("assets/{}: {e}; run `cargo xtask assets`", relative.display()));
                assert!(
                    on_disk == std::fs::read(&path).unwrap(),
                    "assets/{} differs from the generator's; run `cargo xtask assets`",
                    relative.display()
                );
                checked += 1;
            }
        }
        std::fs::remove_dir_all(fresh).unwrap();
        assert_eq!(
            checked, 57,
            "12 cube faces, 3 water maps, 6 × 2 textures, 11 models with their MTL, 3 parallax layers, 4 gradients, and the README"
        );
    }

    /// The water texture tiles: across its edges (last column to first,
    /// last row to first) it changes no more than between neighbouring
    /// texels inside it. And its green and blue, which chapter 07 offsets
    /// its second read by, are not one field twice: a texture whose green
    /// followed its blue would push every texel along one diagonal only.
    #[test]
    fn the_water_texture_tiles_and_its_green_and_blue_differ() {
        const SIZE: usize = 256;
        let at = |x: usize, y: usize| water_colour(x as f32 / SIZE as f32, y as f32 / SIZE as f32);
        let step = |a: [f32; 3], b: [f32; 3]| (0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f32::max);
        let inside = (0..SIZE - 1)
            .flat_map(|y| (0..SIZE - 1).map(move |x| (x, y)))
            .map(|(x, y)| step(at(x, y), at(x + 1, y)).max(step(at(x, y), at(x, y + 1))))
            .fold(0.0, f32::max);
        let across =
            (0..SIZE).map(|i| step(at(SIZE - 1, i), at(0, i)).max(step(at(i, SIZE - 1), at(i, 0)))).fold(0.0, f32::max);
        assert!(across <= inside, "across the edges {across}, inside {inside}");
        let texels: Vec<[f32; 3]> = (0..SIZE * SIZE).map(|i| at(i % SIZE, i / SIZE)).collect();
        let mean = |c: usize| texels.iter().map(|t| t[c]).sum::<f32>() / texels.len() as f32;
        let (green, blue) = (mean(1), mean(2));
        let covariance = |a: usize, ma: f32, b: usize, mb: f32| {
            texels.iter().map(|t| (t[a] - ma) * (t[b] - mb)).sum::<f32>() / texels.len() as f32
        };
        let correlation =
            covariance(1, green, 2, blue) / (covariance(1, green, 1, green) * covariance(2, blue, 2, blue)).sqrt();
        assert!(correlation < 0.6, "green and blue correlate by {correlation}");
    }
}
