//! Multisampling measured on a known edge: the flat triangle (one colour on
//! the clear colour) against the share of each pixel it covers, worked out
//! exactly by clipping the pixel's square to the triangle. With one sample
//! a pixel is all triangle or all background, wrong by its coverage or by
//! what it lacks of full; with four samples, each edge pixel takes one
//! of five shades and the error falls to less than half.

use common::glam::Vec2;
use common::headless::{RenderRequest, render_image};
use common::texture::srgb_to_linear;
use common::{Antialiasing, Chapter, Gpu};
use triangle::{TRIANGLE, Triangle};

const SIZE: (u32, u32) = (200, 150);
/// The red of the clear colour behind the triangle, and of its first
/// corner, which the flat view paints it with (linear).
const BACKGROUND_RED: f32 = 0.02;
const TRIANGLE_RED: f32 = 1.0;

/// The area of the convex polygon `points`.
fn area(points: &[Vec2]) -> f32 {
    let n = points.len();
    (0..n).map(|i| points[i].perp_dot(points[(i + 1) % n])).sum::<f32>().abs() / 2.0
}

/// `polygon` clipped to the side of the line `a` → `b` where `inside` is
/// (Sutherland and Hodgman, one edge).
fn clip(polygon: &[Vec2], a: Vec2, b: Vec2, inside: Vec2) -> Vec<Vec2> {
    let side = |p: Vec2| (b - a).perp_dot(p - a) * (b - a).perp_dot(inside - a);
    let mut out = Vec::new();
    for i in 0..polygon.len() {
        let (p, q) = (polygon[i], polygon[(i + 1) % polygon.len()]);
        let (sp, sq) = (side(p), side(q));
        if sp >= 0.0 {
            out.push(p);
        }
        if (sp >= 0.0) != (sq >= 0.0) {
            out.push(p + (q - p) * (sp / (sp - sq)));
        }
    }
    out
}

/// The share of pixel (`x`, `y`) inside the triangle, exactly.
fn coverage(corners: [Vec2; 3], x: u32, y: u32) -> f32 {
    let (x, y) = (x as f32, y as f32);
    let mut pixel = vec![Vec2::new(x, y), Vec2::new(x + 1.0, y), Vec2::new(x + 1.0, y + 1.0), Vec2::new(x, y + 1.0)];
    let centre = (corners[0] + corners[1] + corners[2]) / 3.0;
    for i in 0..3 {
        pixel = clip(&pixel, corners[i], corners[(i + 1) % 3], centre);
        if pixel.is_empty() {
            return 0.0;
        }
    }
    area(&pixel)
}

/// The mean error of the picture's coverage, read from its red, against
/// the exact one, over the pixels an edge crosses; and how many different
/// shades those pixels have.
fn edge_error(antialiasing: Antialiasing) -> (f32, usize) {
    let gpu = Gpu::headless(Triangle::gpu_needs()).unwrap();
    let flat = common::chapter::view_index::<Triangle>("flat").unwrap();
    let request = RenderRequest { width: SIZE.0, height: SIZE.1, time: 0.0, view: flat, camera: None, antialiasing };
    let picture = render_image::<Triangle>(&gpu, &request).unwrap();
    // Clip space to pixels: y points down, the picture spans -1..1.
    let corners = TRIANGLE.map(|corner| {
        Vec2::new((corner.position[0] + 1.0) / 2.0 * SIZE.0 as f32, (1.0 - corner.position[1]) / 2.0 * SIZE.1 as f32)
    });
    let (mut error, mut edge_pixels, mut shades) = (0.0, 0, std::collections::BTreeSet::new());
    for (x, y, pixel) in picture.enumerate_pixels() {
        let exact = coverage(corners, x, y);
        if exact <= 0.0 || exact >= 1.0 {
            continue;
        }
        let red = srgb_to_linear(f32::from(pixel[0]) / 255.0);
        let seen = (red - BACKGROUND_RED) / (TRIANGLE_RED - BACKGROUND_RED);
        error += (seen - exact).abs();
        edge_pixels += 1;
        shades.insert(pixel[0]);
    }
    assert!(edge_pixels > 300, "the edges cross {edge_pixels} pixels");
    (error / edge_pixels as f32, shades.len())
}

#[test]
fn four_samples_follow_the_edge_more_than_twice_as_closely_as_one() {
    let (aliased, aliased_shades) = edge_error(Antialiasing::Off);
    let (smoothed, smoothed_shades) = edge_error(Antialiasing::Msaa);
    eprintln!(
        "mean coverage error along the edges: {aliased:.3} with one sample ({aliased_shades} shades), \
         {smoothed:.3} with four ({smoothed_shades} shades)"
    );
    // One sample: each pixel is 0 or 1, wrong by its coverage or by what
    // it lacks of 1: between 0 and a half, 0.17 on average on these edges
    // (measured; a quarter if coverages were spread evenly).
    assert!((0.1..0.35).contains(&aliased), "{aliased}");
    assert_eq!(aliased_shades, 2, "one sample: triangle or background");
    // Four samples: the coverage in quarters, 0.07 off on average here
    // (measured), where the samples fall unevenly along a slanted edge.
    assert!(smoothed < aliased / 2.0, "{smoothed} against {aliased}");
    assert!(smoothed_shades >= 5, "{smoothed_shades} shades: none, a quarter, a half, three quarters, all");
}

/// The `no-aa` view is drawn with one sample whatever the run asks for,
/// as the default view is with `--antialiasing off`; the default view with
/// four samples is another picture.
#[test]
fn the_no_aa_view_draws_one_sample_whatever_the_run_asks() {
    let gpu = Gpu::headless(Triangle::gpu_needs()).unwrap();
    let view = |name| common::chapter::view_index::<Triangle>(name).unwrap();
    let picture = |view, antialiasing| {
        let request = RenderRequest { width: 96, height: 54, time: 0.0, view, camera: None, antialiasing };
        render_image::<Triangle>(&gpu, &request).unwrap()
    };
    let one_sample = picture(view("default"), Antialiasing::Off);
    // Compared with `==`: a failed `assert_eq!` would print every pixel.
    assert!(picture(view("no-aa"), Antialiasing::Msaa) == one_sample, "no-aa, asked for four samples, drew four");
    assert!(
        picture(view("no-aa"), Antialiasing::Off) == one_sample,
        "no-aa, asked for one sample, drew another picture"
    );
    assert!(picture(view("default"), Antialiasing::Msaa) != one_sample, "the default view with four samples drew one");
}
