//! Gouraud against Phong on the coarse glass sphere (24 × 12 quads) under
//! one light, the morning sun, seen with the sun behind the camera so that
//! the whole visible side is lit. Lit per fragment, the highlight peaks far
//! higher than lit per vertex, where it is averaged away between vertices
//! 15° apart; with highlights off, the two agree. And the `ambient`,
//! `diffuse` and `specular` views add up to the `phong` view's light.

use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, capture, read_floats};
use common::{Camera, Chapter, Gpu, Target, chapter::view_index, image};
use lighting::LightingChapter;
use lighting::lights::{TimeOfDay, daylight};

const SIZE: (u32, u32) = (480, 270);

/// Measured: what the light-arriving lesson quotes of the three terms'
/// test, copied from a run (`common::book_figures::Measured`: change
/// detectors); the page says they are measured.
mod measured {
    use common::book_figures::Measured;

    /// The pixels of the phong view that show the city and its countryside.
    pub const CITY_PIXELS: Measured = Measured::new(99676.0, 200.0);
    /// Those of them that are the sum of the three terms.
    pub const SUM_OF_TERMS: Measured = Measured::new(98736.0, 200.0);
}

/// Renders `view` looking at the sphere from the sun's side, with or
/// without highlights, at `exposure`, without bloom (which would spread a
/// highlight into its surroundings).
fn render(gpu: &Gpu, chapter: &mut LightingChapter, view: &str, highlights: bool, exposure: f32) -> image::RgbaImage {
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1, samples: 1 };
    let index = view_index::<LightingChapter>(view).unwrap();
    chapter.select_view(index);
    let sun = daylight(TimeOfDay::Morning.phase(0.0, 1.0)).direction;
    let centre = chapter.city.sphere_building + Vec3::Y * 24.0;
    chapter.camera =
        Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + sun * 45.0, centre, target.aspect()) };
    chapter.settings.highlights = highlights;
    chapter.settings.exposure = exposure;
    chapter.settings.bloom_on = false;
    capture(gpu, chapter, target, (LightingChapter::SNAPSHOT_TIME, index), Default::default()).unwrap()
}

/// The pixels inside a disc around the picture's centre, well inside the
/// sphere's outline (radius 14 m at 45 m: 81 pixels of 270; this disc is 59).
fn on_the_sphere(image: &image::RgbaImage) -> Vec<image::Rgba<u8>> {
    let (w, h) = image.dimensions();
    let radius = h as f32 * 0.22;
    image
        .enumerate_pixels()
        .filter(|(x, y, _)| (*x as f32 - w as f32 / 2.0).hypot(*y as f32 - h as f32 / 2.0) < radius)
        .map(|(_, _, p)| *p)
        .collect()
}

fn luminance(p: &image::Rgba<u8>) -> f32 {
    0.2126 * f32::from(p[0]) + 0.7152 * f32::from(p[1]) + 0.0722 * f32::from(p[2])
}

#[test]
fn phong_peaks_higher_than_gouraud_and_their_diffuse_light_agrees() {
    let gpu = Gpu::headless(LightingChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1, samples: 1 };
    let mut chapter = LightingChapter::new(&gpu, target, ()).unwrap();

    // The highlight is tens of times brighter than white in HDR: at the usual
    // exposure both peaks clip to 255. At 1/200 of it neither does.
    let dim = 0.005;
    let peak = |image: &image::RgbaImage| on_the_sphere(image).iter().map(luminance).fold(0.0, f32::max);
    let phong = peak(&render(&gpu, &mut chapter, "phong", true, dim));
    let gouraud = peak(&render(&gpu, &mut chapter, "gouraud", true, dim));
    eprintln!("highlight peak: Phong {phong:.1}, Gouraud {gouraud:.1} (of 255, at 1/200 exposure)");
    // The page's figures, measured on lavapipe: 196.0 against 17.4. At its
    // peak a highlight is flat, so where the pixel centres fall moves it by
    // a fraction of a level; what another GPU may change is its pow and exp
    // by a few ulps and the rounding of each channel to 8 bits: a level or
    // two. 3 levels for Phong's, 1 for Gouraud's (a light 10 % brighter
    // moves them by 5 and 2).
    assert!((phong - 196.0).abs() <= 3.0, "Phong's highlight peaks at {phong:.1}, not 196");
    assert!((gouraud - 17.4).abs() <= 1.0, "Gouraud's highlight peaks at {gouraud:.1}, not 17");

    let phong = on_the_sphere(&render(&gpu, &mut chapter, "phong", false, 1.0));
    let gouraud = on_the_sphere(&render(&gpu, &mut chapter, "gouraud", false, 1.0));
    let differences: Vec<f32> = phong
        .iter()
        .zip(&gouraud)
        .map(|(a, b)| (0..3).map(|c| (f32::from(a[c]) - f32::from(b[c])).abs()).fold(0.0, f32::max))
        .collect();
    let mean = differences.iter().sum::<f32>() / differences.len() as f32;
    let max = differences.iter().copied().fold(0.0, f32::max);
    eprintln!(
        "diffuse only, {} pixels of the sphere: mean difference {mean:.2} of 255, largest {max}",
        differences.len()
    );
    // Interpolating N · L between vertices 15° apart instead of per pixel
    // changes it by at most 1 − cos 7.5° ≈ 0.9 %: a level or two of 255
    // (measured: 0.89 on average, 2 at most, the page's figure).
    assert!(mean < 1.0 && max <= 2.0, "diffuse light should agree: mean {mean}, largest difference {max}");
}

/// The `phong` view's HDR light, pixel by pixel, and its depth (1 where
/// the sky is), after drawing `view` at the snapshot's time and camera.
fn hdr_light(gpu: &Gpu, chapter: &mut LightingChapter, view: &str) -> (Vec<[f32; 4]>, Vec<f32>) {
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1, samples: 1 };
    let index = view_index::<LightingChapter>(view).unwrap();
    chapter.select_view(index);
    capture(gpu, chapter, target, (LightingChapter::SNAPSHOT_TIME, index), Default::default()).unwrap();
    let light = read_floats(gpu, chapter.post.hdr().colour.texture()).unwrap();
    let depth = read_floats(gpu, chapter.post.hdr().depth_texture().expect("one sample a pixel"))
        .unwrap()
        .iter()
        .map(|d| d[0])
        .collect();
    (light, depth)
}

#[test]
fn the_ambient_diffuse_and_specular_views_add_up_to_the_picture() {
    let gpu = Gpu::headless(LightingChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1, samples: 1 };
    let mut chapter = LightingChapter::new(&gpu, target, ()).unwrap();
    let (picture, depth) = hdr_light(&gpu, &mut chapter, "phong");
    let terms = ["ambient", "diffuse", "specular"].map(|view| hdr_light(&gpu, &mut chapter, view).0);

    // Where the city is (not the sky), the picture is the three terms plus
    // the glow of emissive materials, and nothing else: equal within the
    // rounding of 16-bit floats (three sums rounded against one), or
    // brighter where something glows.
    let (mut city, mut equal, mut brighter) = (0, 0, 0);
    for (i, full) in picture.iter().enumerate().filter(|(i, _)| depth[*i] < 1.0) {
        city += 1;
        let parts: Vec<f32> = (0..3).map(|c| terms.iter().map(|t| t[i][c]).sum()).collect();
        let close = (0..3).all(|c| (full[c] - parts[c]).abs() <= 2e-3 * full[c].abs() + 1e-4);
        if close {
            equal += 1;
        } else if (0..3).all(|c| full[c] >= parts[c]) {
            brighter += 1;
        } else {
            panic!("pixel {i}: the picture {full:?} is darker than its three terms {parts:?}");
        }
    }
    let share = equal as f32 / city as f32;
    eprintln!("{city} pixels of city: {equal} are the sum of the three terms ({share:.4}), {brighter} brighter (glow)");
    assert!(share > 0.9, "only {share} of the city's pixels are the sum of their terms");
    measured::CITY_PIXELS.check("the pixels of city in the phong view", city);
    measured::SUM_OF_TERMS.check("the pixels of city that are the sum of their three terms", equal);
}
