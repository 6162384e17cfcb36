//! Gouraud against Phong on the coarse glass sphere (24 × 12 quads) under
//! one light, the morning sun, seen with the sun behind the camera so that
//! the whole visible side is lit. Lit per fragment, the highlight peaks far
//! higher than lit per vertex, where it is averaged away between vertices
//! 15° apart; with highlights off, the two agree.

use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Camera, Chapter, Gpu, Target, chapter::view_index, image};
use lighting::LightingChapter;
use lighting::lights::{TimeOfDay, daylight};

const SIZE: (u32, u32) = (480, 270);

/// Renders `view` looking at the sphere from the sun's side, with or
/// without highlights, at `exposure`, without bloom (which would spread a
/// highlight into its surroundings).
fn render(gpu: &Gpu, chapter: &mut LightingChapter, view: &str, highlights: bool, exposure: f32) -> image::RgbaImage {
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1 };
    let index = view_index::<LightingChapter>(view).unwrap();
    chapter.select_view(index);
    let sun = daylight(TimeOfDay::Morning.phase(0.0, 1.0)).direction;
    let centre = chapter.city.sphere_building + Vec3::Y * 24.0;
    chapter.camera =
        Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + sun * 45.0, centre, target.aspect()) };
    chapter.settings.highlights = highlights;
    chapter.settings.exposure = exposure;
    chapter.settings.bloom_on = false;
    capture(gpu, chapter, target, LightingChapter::SNAPSHOT_TIME, index).unwrap()
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
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1 };
    let mut chapter = LightingChapter::new(&gpu, target, ()).unwrap();

    // The highlight is tens of times brighter than white in HDR: at the usual
    // exposure both peaks clip to 255. At 1/200 of it neither does.
    let dim = 0.005;
    let peak = |image: &image::RgbaImage| on_the_sphere(image).iter().map(luminance).fold(0.0, f32::max);
    let phong = peak(&render(&gpu, &mut chapter, "phong", true, dim));
    let gouraud = peak(&render(&gpu, &mut chapter, "gouraud", true, dim));
    eprintln!("highlight peak: Phong {phong:.1}, Gouraud {gouraud:.1} (of 255, at 1/200 exposure)");
    assert!(phong > 2.0 * gouraud, "Phong's highlight peak ({phong:.1}) should be well above Gouraud's ({gouraud:.1})");

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
    // changes it by at most 1 − cos 7.5° ≈ 0.9 %: a level or two of 255.
    assert!(mean < 1.0 && max <= 3.0, "diffuse light should agree: mean {mean}, largest difference {max}");
}
