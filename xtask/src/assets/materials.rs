//! The city's materials for chapter 09: for each, an albedo map (sRGB) and
//! a tangent-space normal map (linear), 256² and tileable. Each is painted
//! as a colour and a height field; the normal map is the height field's
//! slope, by wrapped central differences.
//!
//! Normal maps follow the OpenGL convention, as Blender and glTF do: red is
//! +u (right in the image), green is up the image, blue is out of the
//! surface, each mapped from −1..1 to 0..255.

use std::path::Path;

use anyhow::Context as _;

use super::{hash, mix, smoothstep, tileable_fbm, tileable_noise, tileable_noise2};

pub const SIZE: u32 = 256;

/// A material as painted: linear-light colour per texel (converted to sRGB
/// when written), a glow mask (the albedo map's alpha), and a height field.
struct Painting {
    colour: Vec<[f32; 3]>,
    glow: Vec<f32>,
    height: Vec<f32>,
    /// How steep the height field's slopes come out in the normal map.
    strength: f32,
}

impl Painting {
    fn new(strength: f32, paint: impl Fn(u32, u32) -> ([f32; 3], f32, f32)) -> Self {
        let mut painting = Painting { colour: Vec::new(), glow: Vec::new(), height: Vec::new(), strength };
        for y in 0..SIZE {
            for x in 0..SIZE {
                let (colour, glow, height) = paint(x, y);
                painting.colour.push(colour);
                painting.glow.push(glow);
                painting.height.push(height);
            }
        }
        painting
    }

    fn height_at(&self, x: i64, y: i64) -> f32 {
        let size = SIZE as i64;
        self.height[(y.rem_euclid(size) * size + x.rem_euclid(size)) as usize]
    }

    fn albedo(&self) -> image::RgbaImage {
        image::RgbaImage::from_fn(SIZE, SIZE, |x, y| {
            let i = (y * SIZE + x) as usize;
            let [r, g, b] = self.colour[i].map(|c| (encode_srgb(c) * 255.0).round() as u8);
            image::Rgba([r, g, b, (self.glow[i].clamp(0.0, 1.0) * 255.0).round() as u8])
        })
    }

    fn normal_map(&self) -> image::RgbImage {
        image::RgbImage::from_fn(SIZE, SIZE, |x, y| {
            let (x, y) = (x as i64, y as i64);
            // Slopes along +u (right) and up the image (−y), wrapping.
            let right = (self.height_at(x + 1, y) - self.height_at(x - 1, y)) * 0.5;
            let up = (self.height_at(x, y - 1) - self.height_at(x, y + 1)) * 0.5;
            let n = super::normalize([-right * self.strength, -up * self.strength, 1.0]);
            image::Rgb(n.map(|c| ((c * 0.5 + 0.5) * 255.0).round() as u8))
        })
    }
}

/// Linear light to the sRGB curve (IEC 61966-2-1).
fn encode_srgb(linear: f32) -> f32 {
    let c = linear.clamp(0.0, 1.0);
    if c <= 0.003_130_8 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 }
}

/// An sRGB colour as an artist would pick it, to linear light.
fn srgb(rgb: [u8; 3]) -> [f32; 3] {
    rgb.map(|c| {
        let c = c as f32 / 255.0;
        if c <= 0.040_45 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
    })
}

fn scale(c: [f32; 3], k: f32) -> [f32; 3] {
    c.map(|v| v * k)
}

/// Running-bond brick: 4 bricks across and 16 courses per tile, every other
/// course shifted by half a brick; recessed mortar; each brick its own shade.
fn brick() -> Painting {
    let (brick_w, course) = (SIZE / 4, SIZE / 16);
    Painting::new(6.0, |x, y| {
        let row = y / course;
        let shifted = x + if row % 2 == 1 { brick_w / 2 } else { 0 };
        let column = (shifted / brick_w) % 4;
        let (bx, by) = ((shifted % brick_w) as f32, (y % course) as f32);
        // Distance in texels to the nearest mortar joint (3 texels wide).
        let edge = bx.min(brick_w as f32 - 1.0 - bx).min(by).min(course as f32 - 1.0 - by) - 1.0;
        let face = smoothstep(0.0, 2.0, edge);
        let id = row * 4 + column;
        let shade = 0.75 + 0.5 * hash(id.wrapping_mul(2_654_435_761));
        let grain = tileable_fbm(x as f32 / SIZE as f32 * 4.0 % 1.0, y as f32 / SIZE as f32 * 4.0 % 1.0, 11);
        let clay = scale(mix(srgb([150, 62, 42]), srgb([118, 52, 38]), hash(id ^ 0x9e37)), shade * (0.8 + 0.4 * grain));
        let mortar = scale(srgb([150, 146, 138]), 0.85 + 0.3 * grain);
        let colour = mix(mortar, clay, face);
        (colour, 0.0, face * (0.9 + 0.2 * grain))
    })
}

/// Cast concrete: a mottled grey, formwork joints every 2 m (the tile is
/// 4 m, so two per tile each way) and the tie holes between them.
fn concrete() -> Painting {
    Painting::new(3.0, |x, y| {
        let (u, v) = (x as f32 / SIZE as f32, y as f32 / SIZE as f32);
        let mottle = tileable_fbm(u, v, 21);
        let fine = tileable_noise(u * 64.0, v * 64.0, 64, 22);
        let joint = |t: u32| {
            let d = (t % (SIZE / 2)) as f32;
            let d = d.min(SIZE as f32 / 2.0 - d);
            1.0 - smoothstep(0.5, 1.5, d)
        };
        let joints = joint(x).max(joint(y));
        // Tie holes: small round pits on a 1 m grid, between the joints.
        let (hx, hy) = ((x % 64) as f32 - 32.0, (y % 64) as f32 - 32.0);
        let hole = 1.0 - smoothstep(1.5, 2.5, (hx * hx + hy * hy).sqrt());
        let base = scale(srgb([128, 126, 120]), 0.8 + 0.35 * mottle + 0.1 * fine);
        let colour = scale(base, 1.0 - 0.35 * joints - 0.5 * hole);
        (colour, 0.0, 0.3 * fine + 0.2 * mottle - 0.8 * joints - 0.8 * hole)
    })
}

/// Metal cladding: 2 × 2 panels per tile with grooved seams, a row of rivets
/// along each panel's edges, and brushing along u.
fn metal() -> Painting {
    let panel = SIZE / 2;
    Painting::new(5.0, |x, y| {
        let (px, py) = ((x % panel) as f32, (y % panel) as f32);
        let edge = px.min(panel as f32 - 1.0 - px).min(py).min(panel as f32 - 1.0 - py);
        let seam = 1.0 - smoothstep(0.0, 2.0, edge);
        // Rivets every 16 texels, 5 texels in from the edge.
        let along = |t: f32| ((t + 8.0) % 16.0 - 8.0).abs();
        let near_x = (px - 5.0).abs().min((panel as f32 - 6.0 - px).abs());
        let near_y = (py - 5.0).abs().min((panel as f32 - 6.0 - py).abs());
        let r1 = (near_x * near_x + along(py) * along(py)).sqrt();
        let r2 = (near_y * near_y + along(px) * along(px)).sqrt();
        let rivet = 1.0 - smoothstep(1.0, 2.2, r1.min(r2));
        let (u, v) = (x as f32 / SIZE as f32, y as f32 / SIZE as f32);
        // Brushing: noise stretched 16 times along u.
        let brushed = tileable_noise2(u * 4.0, v * 128.0, (4, 128), 31) * 0.6
            + tileable_noise2(u * 8.0, v * 256.0, (8, 256), 32) * 0.4;
        let tint = 0.9 + 0.2 * hash((x / panel + 2 * (y / panel)).wrapping_mul(97));
        let base = scale(srgb([150, 156, 166]), tint * (0.85 + 0.25 * brushed));
        let colour = scale(base, 1.0 - 0.5 * seam + 0.15 * rivet);
        (colour, 0.0, 0.1 * brushed - seam + 0.6 * rivet)
    })
}

/// Asphalt 12 m across (v) and 12 m along (u): edge lines 0.8 m in from
/// each side, a dashed centre line (3 m dashes, 3 m gaps), worn in places.
fn road() -> Painting {
    let metres = |t: u32| (t as f32 + 0.5) / SIZE as f32 * 12.0;
    Painting::new(2.5, move |x, y| {
        let (u, v) = (x as f32 / SIZE as f32, y as f32 / SIZE as f32);
        let (along, across) = (metres(x), metres(y));
        let line = |centre: f32| 1.0 - smoothstep(0.06, 0.11, (across - centre).abs());
        let edges = line(0.8).max(line(11.2));
        let dash = if along % 6.0 < 3.0 { line(6.0) } else { 0.0 };
        let wear = smoothstep(0.35, 0.6, tileable_fbm(u, v, 41));
        let paint = edges.max(dash) * (0.55 + 0.45 * wear);
        let aggregate = tileable_noise(u * 128.0, v * 128.0, 128, 42);
        let patches = tileable_fbm(u, v, 43);
        let asphalt = scale(srgb([58, 58, 62]), 0.7 + 0.35 * aggregate + 0.3 * patches);
        let colour = mix(asphalt, srgb([226, 222, 208]), paint);
        (colour, 0.0, 0.5 * aggregate + 0.4 * paint)
    })
}

/// An office facade 16 m square: 4 bays by 4 storeys of windows in metal
/// frames on light panels. The alpha channel says which windows are lit at
/// night, and how brightly: each window decides by a hash.
fn facade() -> Painting {
    let cell = SIZE / 4;
    Painting::new(4.0, move |x, y| {
        let (cx, cy) = ((x % cell) as f32, (y % cell) as f32);
        let window_id = (x / cell) + 4 * (y / cell);
        // The glass: 44 × 34 texels, 10 from the cell's left, 12 from its top.
        let inside = |t: f32, start: f32, length: f32| t >= start && t < start + length;
        let glass = inside(cx, 10.0, 44.0) && inside(cy, 12.0, 34.0);
        let frame = inside(cx, 7.0, 50.0) && inside(cy, 9.0, 40.0) && !glass;
        let mullion = glass && (cx - 32.0).abs() < 1.0;
        let (u, v) = (x as f32 / SIZE as f32, y as f32 / SIZE as f32);
        let grain = tileable_fbm(u, v, 51);
        let panel = scale(srgb([122, 120, 114]), 0.85 + 0.25 * grain);
        let metal = srgb([52, 56, 64]);
        // Glass reflects the sky: lighter towards the top of each pane.
        let sky = mix(srgb([92, 112, 134]), srgb([36, 46, 60]), (cy - 12.0) / 34.0);
        let lit = hash(window_id.wrapping_mul(0x2c1b_3c6d) ^ 0x51);
        let glow = if glass && !mullion && lit > 0.55 { 0.55 + 0.45 * hash(window_id ^ 0x77) } else { 0.0 };
        let (colour, height) = if mullion || frame {
            (metal, 0.6)
        } else if glass {
            (sky, -1.0)
        } else {
            (panel, 0.1 * grain + if (cy - 58.0).abs() < 1.5 { -0.5 } else { 0.0 })
        };
        (colour, glow, height)
    })
}

/// A wooden crate's side, one tile per 1 m face: a frame of boards round
/// the edge, horizontal boards inside, and a diagonal brace; grain along
/// each board, dark gaps between them.
fn wood() -> Painting {
    let border = 28.0;
    Painting::new(5.0, move |x, y| {
        let (fx, fy) = (x as f32 + 0.5, y as f32 + 0.5);
        let size = SIZE as f32;
        let to_edge = fx.min(size - fx).min(fy).min(size - fy);
        let in_frame = to_edge < border;
        // The brace runs from the lower left to the upper right, 30 texels wide.
        let brace = ((fx - (size - fy)).abs() / std::f32::consts::SQRT_2) < 15.0 && !in_frame;
        let board_width = (size - 2.0 * border) / 4.0;
        // Distance to the nearest gap, and which board, for each part.
        let (gap, board, along) = if in_frame {
            let horizontal = fy.min(size - fy) < border && to_edge == fy.min(size - fy);
            let across = if horizontal { fy.min(size - fy) } else { fx.min(size - fx) };
            let id = if horizontal { u32::from(fy > size / 2.0) } else { 2 + u32::from(fx > size / 2.0) };
            (across.min(border - across), id, if horizontal { fx } else { fy })
        } else if brace {
            let across = (fx - (size - fy)) / std::f32::consts::SQRT_2 + 15.0;
            (across.min(30.0 - across), 9, (fx + (size - fy)) / std::f32::consts::SQRT_2)
        } else {
            let within = (fy - border).rem_euclid(board_width);
            (within.min(board_width - within), 4 + ((fy - border) / board_width) as u32, fx)
        };
        let (u, v) = (x as f32 / size, y as f32 / size);
        // Grain: noise stretched along the board, offset per board.
        let grain = tileable_noise2(along / size * 4.0, board as f32 * 2.0 + 0.5, (4, 64), 61) * 0.5
            + tileable_noise2(along / size * 32.0, board as f32 * 5.0 + 0.5, (32, 64), 62) * 0.5;
        let shade = 0.8 + 0.35 * hash(board.wrapping_mul(2_246_822_519) ^ 0x33);
        let dirt = tileable_fbm(u, v, 63);
        let timber = scale(mix(srgb([168, 124, 78]), srgb([126, 88, 52]), grain), shade * (0.85 + 0.25 * dirt));
        let seam = 1.0 - smoothstep(0.5, 2.0, gap);
        let colour = scale(timber, 1.0 - 0.7 * seam);
        let raised = if in_frame || brace { 0.5 } else { 0.0 };
        (colour, 0.0, raised + 0.15 * grain - seam)
    })
}

type Painter = fn() -> Painting;

/// (folder name, painter, what it is, for the provenance table).
const MATERIALS: [(&str, Painter, &str); 6] = [
    ("brick", brick, "running-bond brick, 4 bricks × 16 courses per tile, recessed mortar, a shade per brick"),
    (
        "concrete",
        concrete,
        "cast concrete: mottled grey (tileable value noise), formwork joints every half tile, tie holes",
    ),
    ("metal", metal, "metal cladding: 2 × 2 panels with grooved seams, rivets along their edges, brushed along u"),
    (
        "road",
        road,
        "asphalt with edge lines and a dashed centre line; u along the road, v across it, one tile 12 m square",
    ),
    (
        "facade",
        facade,
        "office facade, 4 × 4 windows in metal frames; alpha marks the windows lit at night (a hash per window)",
    ),
    (
        "wood",
        wood,
        "a crate's side (chapter 10): a frame of boards, four boards inside and a diagonal brace, grain along each",
    ),
];

/// The provenance table's rows for these files.
pub fn provenance() -> String {
    MATERIALS
        .iter()
        .map(|(name, _, what)| format!("| `textures/{name}/{{albedo,normal}}.png` | {what} | painted colour and height field; normal map from the height by wrapped central differences |\n"))
        .collect()
}

/// Writes `albedo.png` and `normal.png` for every material under `dir`.
pub fn paint(dir: &Path) -> anyhow::Result<()> {
    for (name, painter, _) in MATERIALS {
        let folder = dir.join(name);
        std::fs::create_dir_all(&folder)?;
        let painting = painter();
        let albedo = folder.join("albedo.png");
        painting.albedo().save(&albedo).with_context(|| format!("cannot write {}", albedo.display()))?;
        let normal = folder.join("normal.png");
        painting.normal_map().save(&normal).with_context(|| format!("cannot write {}", normal.display()))?;
        println!("wrote {} and {}", albedo.display(), normal.display());
    }
    Ok(())
}
