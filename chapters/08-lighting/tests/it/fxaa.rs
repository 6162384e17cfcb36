//! The FXAA pass (fxaa.wgsl, through `Fxaa`) on pictures whose truth is
//! known: a straight edge drawn with one sample a pixel, against the share
//! of each pixel the bright side covers, integrated numerically here; a
//! faint texture, which its thresholds keep it from taking for edges; and
//! a line one pixel wide, which FXAA cannot tell from an edge and dims.

use common::headless::{OFFSCREEN_FORMAT, Offscreen, read_texture};
use common::texture::{linear_to_srgb, srgb_to_linear};
use common::{Antialiasing, DrawCounts, Frame, Gpu, GpuNeeds, PassTimer, Target, wgpu};
use lighting::Fxaa;

pub(crate) const SIZE: (u32, u32) = (192, 96);

/// Runs FXAA over `linear`, a picture given as one grey level (linear
/// light, 0 to 1) a pixel, row by row; returns the result the same way.
pub(crate) fn fxaa(gpu: &Gpu, linear: &[f32]) -> Vec<f32> {
    let (width, height) = SIZE;
    let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
    let input = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("fxaa test input"),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: OFFSCREEN_FORMAT,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let bytes: Vec<u8> = linear
        .iter()
        .flat_map(|&grey| {
            let encoded = (linear_to_srgb(grey) * 255.0).round() as u8;
            [encoded, encoded, encoded, 255]
        })
        .collect();
    gpu.queue.write_texture(
        input.as_image_copy(),
        &bytes,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(width * 4), rows_per_image: None },
        size,
    );
    let output = Offscreen::new(&gpu.device, Target { format: OFFSCREEN_FORMAT, width, height, samples: 1 });
    let pass = Fxaa::new(gpu, OFFSCREEN_FORMAT).unwrap();
    let group = pass.input(&gpu.device, &input.create_view(&Default::default()));
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let (timer, drawn) = (PassTimer::off(), DrawCounts::new());
    pass.draw(
        &mut Frame {
            encoder: &mut encoder,
            target: &output.view,
            time: 0.0,
            view: 0,
            timer: &timer,
            drawn: &drawn,
            antialiasing: Antialiasing::Post,
        },
        &group,
    );
    gpu.queue.submit([encoder.finish()]);
    let picture = read_texture(gpu, &output.texture).unwrap();
    picture.pixels().map(|p| srgb_to_linear(f32::from(p[0]) / 255.0)).collect()
}

/// The share of pixel (`x`, `y`) (y down) below the line through
/// `through` of slope `slope` (pixels down per pixel right), integrated
/// over 512 columns of the pixel.
fn coverage_below(through: (f32, f32), slope: f32, x: u32, y: u32) -> f32 {
    const COLUMNS: u32 = 512;
    (0..COLUMNS)
        .map(|i| {
            let column = x as f32 + (i as f32 + 0.5) / COLUMNS as f32;
            let line = through.1 + slope * (column - through.0);
            // The part of the pixel's height [y, y + 1] below (greater than) the line.
            (y as f32 + 1.0 - line).clamp(0.0, 1.0)
        })
        .sum::<f32>()
        / COLUMNS as f32
}

/// The mean error against exact coverage over the pixels the edge of slope
/// `slope` crosses, before and after FXAA, and the shades those pixels
/// take after it.
fn edge_errors(gpu: &Gpu, slope: f32) -> (f32, f32, usize) {
    let (width, height) = SIZE;
    let through = (width as f32 / 2.0 + 0.3, height as f32 / 2.0 + 0.2);
    let pixels = || (0..height).flat_map(|y| (0..width).map(move |x| (x, y)));
    let exact: Vec<f32> = pixels().map(|(x, y)| coverage_below(through, slope, x, y)).collect();
    // One sample a pixel, at its centre: all bright or all dark.
    let aliased: Vec<f32> = pixels()
        .map(|(x, y)| {
            let centre = (x as f32 + 0.5, y as f32 + 0.5);
            f32::from(centre.1 > through.1 + slope * (centre.0 - through.0))
        })
        .collect();
    let smoothed = fxaa(gpu, &aliased);
    // Away from the picture's border, where FXAA reads clamped neighbours.
    let edge: Vec<usize> = pixels()
        .enumerate()
        .filter(|&(i, (x, y))| {
            exact[i] > 0.0 && exact[i] < 1.0 && (4..width - 4).contains(&x) && (4..height - 4).contains(&y)
        })
        .map(|(i, _)| i)
        .collect();
    assert!(edge.len() > 80, "the edge crosses {} pixels", edge.len());
    let mean_error =
        |picture: &[f32]| edge.iter().map(|&i| (picture[i] - exact[i]).abs()).sum::<f32>() / edge.len() as f32;
    let shades: std::collections::BTreeSet<u32> = edge.iter().map(|&i| (smoothed[i] * 255.0).round() as u32).collect();
    (mean_error(&aliased), mean_error(&smoothed), shades.len())
}

/// The mean error against exact coverage that the full walk (fxaa.wgsl's
/// ten steps each way) leaves at each slope, near horizontal, steeper, and
/// near vertical (the other orientation): measured on lavapipe, where the
/// pass is exact arithmetic on a known picture. A walk cut short stops
/// before the end of a long step, blends it as though it were short, and
/// misses more: cut to four steps, the near-horizontal edge's error was
/// 0.104, three times 0.034; the short steps of the other two slopes end
/// within any walk.
const WALK_ERRORS: [(f32, f32); 3] = [(0.12, 0.034), (0.4, 0.078), (-3.0, 0.099)];
/// How far above its measured error an edge may land: room for another
/// driver's rounding (a shade of 255 here and there), far less than a
/// shortened walk adds.
const WALK_MARGIN: f32 = 0.02;

#[test]
fn fxaa_follows_a_straight_edge_more_closely_than_one_sample() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    for (slope, walk_error) in WALK_ERRORS {
        let (aliased, smoothed, shades) = edge_errors(&gpu, slope);
        eprintln!(
            "slope {slope}: mean coverage error {aliased:.3} with one sample, {smoothed:.3} after FXAA ({shades} shades)"
        );
        assert!(smoothed < aliased * 0.6, "slope {slope}: FXAA {smoothed} against one sample {aliased}");
        assert!(
            smoothed <= walk_error + WALK_MARGIN,
            "slope {slope}: FXAA's error {smoothed} against exact coverage, where the full walk leaves {walk_error}: \
             is the edge walk cut short?"
        );
        // One sample gives two: bright or dark. Short steps give FXAA few
        // places to be along them (4 shades at slope -3), long ones many.
        assert!(shades >= 4, "slope {slope}: {shades} shades along the edge after FXAA");
    }
}

#[test]
fn fxaa_leaves_faint_texture_alone() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let (width, height) = SIZE;
    // A ramp across the picture, even to the eye (in sRGB's encoding, which
    // is close to how light looks), with a faint checker over it: two
    // levels in 255 up and down, pixel by pixel. Every pixel stands out
    // from its neighbours, but by less than FXAA's thresholds: texture,
    // not an edge.
    let encoded = |x: u32, y: u32| {
        let checker = if (x + y).is_multiple_of(2) { 2.0 } else { -2.0 };
        ((25.0 + 200.0 * x as f32 / width as f32).round() + checker) / 255.0
    };
    let picture: Vec<f32> = (0..height).flat_map(|y| (0..width).map(move |x| srgb_to_linear(encoded(x, y)))).collect();
    let level = |g: &f32| (linear_to_srgb(*g) * 255.0).round() as u8;
    let drawn = fxaa(&gpu, &picture);
    let changed = picture.iter().zip(&drawn).filter(|(a, b)| level(a) != level(b)).count();
    assert_eq!(changed, 0, "FXAA changed {changed} pixels of a faint texture");
}

/// What FXAA costs: a bright line one pixel wide (a rope, a mast, a letter's
/// stem) has an edge on both sides and no staircase, so FXAA blends it
/// with its dark neighbours and it loses much of its light. (FXAA moves
/// no light to the neighbours to make up for it: each pixel decides alone.)
#[test]
fn fxaa_dims_a_line_one_pixel_wide() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let (width, height) = SIZE;
    let line = width / 2;
    let picture: Vec<f32> = (0..height).flat_map(|_| (0..width).map(|x| f32::from(x == line))).collect();
    let drawn = fxaa(&gpu, &picture);
    let row = (height / 2 * width) as usize;
    let peak = drawn[row + line as usize];
    let beside = drawn[row + line as usize + 1];
    eprintln!("a one-pixel line after FXAA: its pixel {peak:.3} of 1, the one beside it {beside:.3}");
    assert!((0.3..=0.8).contains(&peak), "the line's pixel keeps {peak} of its light");
    assert!(beside < 0.2, "the pixel beside the line has {beside}");
}

/// Chapters with the post chain take all four settings of `--antialiasing`,
/// multisampling by default.
#[test]
fn the_antialiasing_flag_offers_the_post_pass_here() {
    use common::args::Args;
    let parse = |args: &[&str]| Args::parse_from_for::<lighting::LightingChapter>(args).unwrap().antialiasing;
    assert_eq!(parse(&["lighting"]), Antialiasing::Msaa);
    for (value, expected) in [("off", Antialiasing::Off), ("post", Antialiasing::Post), ("both", Antialiasing::Both)] {
        assert_eq!(parse(&["lighting", "--antialiasing", value]), expected, "{value}");
    }
}
