//! Worked solutions to the exercises of chapter 07's lessons. Each makes
//! the change its exercise asks for and asserts the figure the lesson's
//! solution states, so that the solutions are built and checked with the chapter.
//! They live in the library's own test build (this chapter has no
//! integration-test binary, and one more would be one more link of wgpu),
//! and change shaders by text edits of the real files, composed and
//! validated by naga as the chapter's loader does: an edit whose text is
//! no longer in the shader fails here instead of rotting on the page.

use std::f32::consts::TAU;

use common::book_figures::median_ms;
use common::glam::{DVec2, Vec2, Vec3};
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::image::RgbaImage;
use common::texture::srgb_to_linear;
use common::{Camera, Chapter, Gpu, ShaderFile, Target, shader};

use crate::WaterChapter;
use crate::water_renderer::{TEXTURE_TILE_METRES, WaterSettings};
use crate::waves::{self, Wave};

/// `file` with `edits` made to its own text, composed with its imports and
/// validated by naga. Each edit's `before` must occur exactly once.
fn compiles_with(file: ShaderFile, edits: &[(&str, &str)]) {
    let mut text = file.embedded.to_string();
    for (before, after) in edits {
        assert_eq!(text.matches(before).count(), 1, "{} should hold `{before}` once", file.path);
        text = text.replacen(before, after, 1);
    }
    let imports: Vec<(&str, String)> = file.imports.iter().map(|i| (i.path, i.embedded.to_string())).collect();
    common::shader::compose_with(&text, file.path, &imports, &[]).unwrap_or_else(|e| panic!("{e}"));
}

/// The water's shader, with the modules it imports.
const WATER: ShaderFile =
    shader!("water/water.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "water/waves.wgsl"]);

/// The median of a pass's row in the chapter's bench table, milliseconds.
fn bench_median(view: &str, what: &str) -> f32 {
    let table = include_str!("../../../book/src/bench/water.md");
    median_ms(table, view, &format!("{what} |")).expect("a row of the water bench table") as f32
}

/// The triangles a pass drew in a view, from the bench table's triangles
/// table (`| view | pass | draws | triangles |`).
fn bench_triangles(view: &str, pass: &str) -> f32 {
    let table = include_str!("../../../book/src/bench/water.md");
    let below = &table[table.find("Triangles drawn").expect("the water bench's triangles table")..];
    let row = below.lines().find(|line| line.starts_with(&format!("| {view} | {pass} |"))).expect("a triangles row");
    row.split('|').nth(4).unwrap().trim().replace(',', "").parse().unwrap()
}

// ANCHOR: quarter
/// Two pictures, exercise 1: the bytes the reflection and refraction pictures take for
/// a `target` at `resolution` (the overlay's slider): each a colour
/// texture of the target's format and a depth buffer, `resolution` of the
/// target's width and height.
fn picture_bytes(target: Target, resolution: f32) -> u64 {
    let (width, height) = ((target.width as f32 * resolution) as u64, (target.height as f32 * resolution) as u64);
    let colour = u64::from(target.format.block_copy_size(None).unwrap());
    let depth = u64::from(common::texture::DEPTH_FORMAT.block_copy_size(None).unwrap());
    2 * width * height * (colour + depth)
}

/// What a screenful of pixels costs a scene pass, in milliseconds,
/// estimated from the bench's `no-aa` view (one sample a pixel in every
/// pass): a pass costs so much a pixel and so much a triangle, and the main
/// pass (1280 × 720) and the reflection pass (a quarter of those pixels, and
/// its own triangles: the scene from below the water, clipped, at its own
/// levels of detail) are two equations for the two.
fn screenful_of_pixels_ms() -> f32 {
    let (main, reflection) =
        (bench_median("no-aa", "GPU: plain and sky pass"), bench_median("no-aa", "GPU: reflection pass"));
    let (main_triangles, reflection_triangles) =
        (bench_triangles("no-aa", "plain and sky"), bench_triangles("no-aa", "reflection"));
    let per_triangle = (reflection - main / 4.0) / (reflection_triangles - main_triangles / 4.0);
    main - per_triangle * main_triangles
}

/// What the pictures' passes would save at `resolution` instead of 0.5,
/// in milliseconds: their pixels' share of [`screenful_of_pixels_ms`].
fn pass_time_saved(resolution: f32) -> f32 {
    2.0 * screenful_of_pixels_ms() * (0.25 - resolution * resolution)
}

/// What the water looks like with the pictures at `resolution`: the
/// default view at 320 × 180, without rocks (they cost seconds to draw
/// and add nothing to the question).
fn lake_at(gpu: &Gpu, chapter: &mut WaterChapter, resolution: f32) -> common::image::RgbaImage {
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    chapter.settings.water.resolution = resolution;
    capture(gpu, chapter, target, (0.0, 0), Default::default()).unwrap()
}
// ANCHOR_END: quarter

#[test]
fn pictures_exercise_1_quarter_resolution_pictures_save_memory_and_frame_time() {
    let target = Target { format: common::wgpu::TextureFormat::Bgra8UnormSrgb, width: 1280, height: 720, samples: 1 };
    let (half, quarter) = (picture_bytes(target, 0.5), picture_bytes(target, 0.25));
    let saved = pass_time_saved(0.25);
    let frame = bench_median("no-aa", "frame (CPU+GPU)");
    println!(
        "pictures: {half} bytes at half resolution, {quarter} at a quarter; the passes would save about \
         {saved:.1} ms of a {frame:.0} ms frame"
    );
    // Two pictures, each 4 bytes of colour and 4 of depth a pixel: at half
    // of 1280 × 720, 640 × 360 of them; at a quarter, 320 × 180.
    assert_eq!((half, quarter), (2 * 640 * 360 * (4 + 4), 2 * 320 * 180 * (4 + 4)));
    // The page computes its figures from the same rows with `{{#figure}}`
    // when the book is built; here the estimate must at least be a saving,
    // and the split between pixels and triangles must hold together: the
    // reflection, with a quarter of the pixels, takes more than a quarter of
    // the main pass (it draws more than a quarter of the triangles), and
    // the main pass's pixels cost more than its triangles, as the page says.
    let main = bench_median("no-aa", "GPU: plain and sky pass");
    let pixels = screenful_of_pixels_ms();
    assert!(bench_median("no-aa", "GPU: reflection pass") > main / 4.0);
    assert!(pixels < main && pixels > 2.0 * (main - pixels), "{pixels} ms of pixels in a {main} ms pass");
    assert!(saved > 0.0 && saved < frame, "{saved} ms of a {frame} ms frame");
    // What it costs: the pixels that change, and by how much (of 255).
    let gpu = Gpu::headless(WaterChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let mut chapter = common::chapter::create::<WaterChapter>(&gpu, target, &Default::default()).unwrap();
    chapter.select_view(0);
    chapter.rocks.rocks = 0;
    let (sharp, coarse) = (lake_at(&gpu, &mut chapter, 0.5), lake_at(&gpu, &mut chapter, 0.25));
    let changes: Vec<u8> = sharp
        .pixels()
        .zip(coarse.pixels())
        .map(|(a, b)| (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap())
        .filter(|d| *d > 0)
        .collect();
    let share = changes.len() as f64 / (320.0 * 180.0);
    let mean = changes.iter().map(|d| f64::from(*d)).sum::<f64>() / changes.len() as f64;
    let worst = changes.iter().copied().max().unwrap();
    // Where: the first row that changes, and how many of the changes are
    // within 20 rows of it (the far shore's reflection).
    let rows: Vec<u32> = (0..320 * 180)
        .filter(|&i| sharp.as_raw()[4 * i..4 * i + 3] != coarse.as_raw()[4 * i..4 * i + 3])
        .map(|i| i as u32 / 320)
        .collect();
    let first = rows[0];
    let difference = |i: usize| (0..3).map(|c| sharp.as_raw()[4 * i + c].abs_diff(coarse.as_raw()[4 * i + c])).max();
    let worst_row = (0..320 * 180).max_by_key(|&i| difference(i)).unwrap() as u32 / 320;
    println!(
        "at a quarter: {:.1} % of the pixels change, by {mean:.2} on average, {worst} at most (row {worst_row}); \
         none above row {first}",
        share * 100.0
    );
    measured::FIRST_ROW_THAT_CHANGES.check("the first row that changes", first);
    assert!(worst_row < first + 20, "the largest change is at row {worst_row}, not by the far shore (row {first})");
    measured::SHARE_THAT_CHANGES.check("the share of pixels that change", share);
    measured::MEAN_CHANGE.check("the mean change, of 255", mean);
    measured::LARGEST_CHANGE.check("the largest change, of 255", worst);
}

/// Measured: what the pictures' exercise 1 got by drawing the lake at half
/// and a quarter resolution, copied with the lesson's solution, which says
/// they are measured (`common::book_figures::Measured`: change detectors).
mod measured {
    use common::book_figures::Measured;

    /// Of 180 rows, where the water begins: the far shore's reflection.
    pub const FIRST_ROW_THAT_CHANGES: Measured = Measured::new(93.0, 0.0);
    pub const SHARE_THAT_CHANGES: Measured = Measured::new(0.157, 0.02);
    pub const MEAN_CHANGE: Measured = Measured::new(2.44, 0.3);
    pub const LARGEST_CHANGE: Measured = Measured::new(42.0, 8.0);
}

// ANCHOR: fresnel
/// The surface, exercise 1: the Mars project's mix in water.wgsl, the cosine itself…
const COSINE_MIX: (&str, &str) =
    ("fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(to_eye, n), 0.0), 5.0);", "fresnel = 1.0 - max(dot(to_eye, n), 0.0);");

/// …and the three mixes as the share of the reflection, for a view
/// direction at `cos_theta` to the water's normal.
fn schlick(cos_theta: f32) -> f32 {
    0.02 + 0.98 * (1.0 - cos_theta).powi(5)
}

fn cosine_mix(cos_theta: f32) -> f32 {
    1.0 - cos_theta
}

fn no_fresnel(_: f32) -> f32 {
    0.5
}

/// The share of the reflection each mix gives the default view's lake, row
/// by row from the bottom of the picture to where the lake ends (520 m
/// square, the camera 41.6 m inside its southern edge, 18 m above the
/// water, looking at the water 322 m away): at the bottom row, and the
/// mean over the rows that show the lake.
fn reflection_shares(mix: fn(f32) -> f32) -> (f32, f32) {
    let camera = Camera::looking_at(Vec3::new(0.0, 18.0, 0.0), Vec3::new(0.0, 0.0, -322.4), 16.0 / 9.0);
    let inverse = camera.view_projection().inverse();
    let mut shares = Vec::new();
    for row in (0..720).rev() {
        let y = 1.0 - (row as f32 + 0.5) / 720.0 * 2.0;
        let near = inverse.project_point3(Vec3::new(0.0, y, 0.0));
        let d = (inverse.project_point3(Vec3::new(0.0, y, 1.0)) - near).normalize();
        if d.y >= 0.0 || -(near + d * (-near.y / d.y)).z > crate::lake::LAKE_SIZE_METRES - 41.6 {
            break;
        }
        shares.push(mix(-d.y));
    }
    (shares[0], shares.iter().sum::<f32>() / shares.len() as f32)
}
// ANCHOR_END: fresnel

#[test]
fn surface_exercise_1_the_cosine_mix_is_nearer_no_fresnel_than_schlick() {
    compiles_with(WATER, &[COSINE_MIX]);
    let (by_schlick, by_cosine, by_halves) =
        (reflection_shares(schlick), reflection_shares(cosine_mix), reflection_shares(no_fresnel));
    println!(
        "reflection at the bottom row and on average: Schlick {by_schlick:.3?}, cosine {by_cosine:.3?}, \
         none {by_halves:.3?}"
    );
    assert!((by_schlick.0 - SCHLICK_AT_BOTTOM).abs() < 0.002 && (by_cosine.0 - COSINE_AT_BOTTOM).abs() < 0.002);
    assert!((by_schlick.1 - SCHLICK_MEAN).abs() < 0.005 && (by_cosine.1 - COSINE_MEAN).abs() < 0.005);
    // At 60° from the normal, the page's figure.
    assert!((cosine_mix(0.5) - 0.5).abs() < 1e-6 && (schlick(0.5) - 0.0506).abs() < 1e-3);
}

/// The share of the reflection at the bottom row of the picture, 57° from
/// the normal, by Schlick and by the cosine.
const SCHLICK_AT_BOTTOM: f32 = 0.039;
const COSINE_AT_BOTTOM: f32 = 0.452;

/// The mean share of the reflection over the lake's rows, by Schlick and by the cosine.
const SCHLICK_MEAN: f32 = 0.247;
const COSINE_MEAN: f32 = 0.688;

// ANCHOR: gerstner
/// Waves, exercise 1: Gerstner waves. Each wave also moves the surface's points
/// along its direction, by Qᵢ Aᵢ cos(phase), towards its crests (Fournier
/// and Reeves 1986; Finch 2004). With Qᵢ Aᵢ kᵢ = `steepness` / 8 for the
/// eight waves, the sum can never fold over while `steepness` ≤ 1.
fn gerstner(waves: &[Wave], p: Vec2, time: f32, steepness: f32) -> Vec3 {
    let mut moved = p;
    for w in waves {
        let k = TAU / w.wavelength;
        let phase = k * (w.direction.dot(p) - w.speed * time);
        moved += steepness / (k * waves.len() as f32) * phase.cos() * w.direction;
    }
    Vec3::new(moved.x, waves::height(waves, p.x, p.y, time), moved.y)
}

/// The same in water.wgsl: the offset, and the vertex moved by it.
const GERSTNER: [(&str, &str); 2] = [
    (
        "@vertex\nfn vs_water(",
        "// Gerstner: each wave moves a point towards its crests as well as up.
fn gerstner_offset(p: vec2<f32>, time: f32, steepness: f32) -> vec2<f32> {
    var offset = vec2<f32>(0.0);
    for (var i = 0u; i < 8u; i++) {
        let wave = water.waves[i];
        let k = 6.2831853 / wave.w;
        let phase = k * (dot(wave.xy, p) - water.speeds[i / 4u][i % 4u] * time);
        offset += steepness / (k * 8.0) * cos(phase) * wave.xy;
    }
    return offset;
}

@vertex\nfn vs_water(",
    ),
    (
        "let world = vec3<f32>(p.x, water.level_time.x + strength * height, p.y);",
        "let moved = p + strength * gerstner_offset(p, water.level_time.y, 1.0);
    let world = vec3<f32>(moved.x, water.level_time.x + strength * height, moved.y);",
    ),
];

/// Along a line across the lake in the wind's direction: the share of its
/// length where the surface stands above its mean level, and the least
/// stretch of the surface (below zero it would have folded over).
fn crest_share_and_least_stretch(steepness: f32) -> (f32, f32) {
    let waves = waves::lake_waves();
    let along = Vec2::new(0.6f32.cos(), -0.6f32.sin());
    let points: Vec<Vec3> = (0..20_000).map(|i| gerstner(&waves, along * (i as f32 * 0.01), 3.0, steepness)).collect();
    let (mut above, mut total, mut least) = (0.0, 0.0, f32::MAX);
    for pair in points.windows(2) {
        let step = Vec2::new(pair[1].x - pair[0].x, pair[1].z - pair[0].z).dot(along);
        least = least.min(step / 0.01);
        total += step;
        if pair[0].y + pair[1].y > 0.0 {
            above += step;
        }
    }
    (above / total, least)
}
// ANCHOR_END: gerstner

#[test]
fn waves_exercise_1_gerstner_waves_have_narrower_crests() {
    compiles_with(WATER, &GERSTNER);
    let (sine, _) = crest_share_and_least_stretch(0.0);
    let (sharp, stretch) = crest_share_and_least_stretch(1.0);
    println!("share of the line above the mean: sines {sine:.3}, Gerstner {sharp:.3}; least stretch {stretch:.3}");
    assert!((sine - SINE_CREST_SHARE).abs() < 0.005 && (sharp - GERSTNER_CREST_SHARE).abs() < 0.005);
    assert!((stretch - 0.496).abs() < 0.01, "squeezed to {stretch} at the crests, never folded");
}

/// The share of a line across the lake above the mean level, with sines
/// (Gerstner's steepness 0) and with Gerstner's steepness 1.
const SINE_CREST_SHARE: f32 = 0.528;
const GERSTNER_CREST_SHARE: f32 = 0.454;

// ANCHOR: no_refraction
/// The surface, exercise 2: the water without the refraction picture: the reflection
/// alone, laid over the scene (which has the lake bed in it) with Fresnel
/// as its opacity. The depth under the surface came from the refraction
/// pass, so the shallows' fade and the murk of deep water go with it.
const REFLECTION_ONLY: [(&str, &str); 2] = [
    ("    var colour = mix(refraction, reflection, fresnel);", "    var colour = reflection;"),
    ("    return vec4<f32>(colour, shallow);", "    return vec4<f32>(colour, fresnel);"),
];
// ANCHOR_END: no_refraction

#[test]
fn surface_exercise_2_without_the_refraction_picture_the_water_loses_its_depth() {
    compiles_with(WATER, &REFLECTION_ONLY);
    // The pass's share of the frame is on the page, from the bench table
    // by `{{#figure}}`.
}

// ANCHOR: texture_period
/// Seed 003, exercise 1: `fs_texture` at lake point `uv` (in tiles of its
/// first read) and time 0, its second read at `frequency` times the first's
/// (the shader's 1.5, or the exercise's 1.25), each read taking the nearest
/// texel and wrapping as the repeating sampler does.
fn seed_003_colour(texture: &RgbaImage, uv: DVec2, push: f64, frequency: f64) -> [u8; 3] {
    let texel = |p: DVec2| {
        let (width, height) = (f64::from(texture.width()), f64::from(texture.height()));
        let (x, y) = ((p.x * width).floor().rem_euclid(width), (p.y * height).floor().rem_euclid(height));
        texture.get_pixel(x as u32, y as u32).0
    };
    // The first read pushes the second by its green and blue, in linear light.
    let first = texel(uv);
    let [green, blue] = [first[1], first[2]].map(|c| f64::from(srgb_to_linear(f32::from(c) / 255.0)));
    let moved = uv + DVec2::new(-green, blue) * push;
    let [r, g, b, _] = texel(moved * frequency);
    [r, g, b]
}

/// The fewest whole tiles after which the water repeats (up to 8): the
/// first read repeats every tile, the second every 1/`frequency` of one.
fn repeats_after_tiles(texture: &RgbaImage, frequency: f64) -> Option<u32> {
    let push = f64::from(WaterSettings::DEFAULT.texture_push);
    let points: Vec<DVec2> =
        (0..2000).map(|i| DVec2::new(0.013 + 0.0731 * f64::from(i), 0.291 + 0.0419 * f64::from(i))).collect();
    (1..=8).find(|&tiles| {
        let shift = DVec2::splat(f64::from(tiles));
        let differ = (points.iter())
            .filter(|&&p| {
                seed_003_colour(texture, p, push, frequency) != seed_003_colour(texture, p + shift, push, frequency)
            })
            .count();
        // A point on a texel's very edge may round the other way: a few in 2,000.
        differ <= 10
    })
}
// ANCHOR_END: texture_period

/// The second read at 1.25 times the first's frequency, in water.wgsl.
const SECOND_READ_AT_1_25: (&str, &str) =
    ("const SECOND_READ_FREQUENCY: f32 = 1.5;", "const SECOND_READ_FREQUENCY: f32 = 1.25;");

#[test]
fn seed_003_exercise_1_at_a_quarter_more_the_water_repeats_every_48_m() {
    compiles_with(WATER, &[SECOND_READ_AT_1_25]);
    let texture =
        common::texture::decode_named("assets/water/texture.png", include_bytes!("../../../assets/water/texture.png"))
            .unwrap();
    // Worked by hand: whole tiles for the first read, and whole tiles of
    // the second, n × 1.25: n = 4, 48 m; at the shader's 1.5, n = 2, 24 m.
    let (now, edited) = (repeats_after_tiles(&texture, 1.5), repeats_after_tiles(&texture, 1.25));
    println!("the water repeats after {now:?} tiles at 1.5, {edited:?} at 1.25 (a tile is {TEXTURE_TILE_METRES} m)");
    assert_eq!(now, Some(2));
    assert_eq!(edited, Some(4));
    assert_eq!(4.0 * TEXTURE_TILE_METRES, 48.0);
}
