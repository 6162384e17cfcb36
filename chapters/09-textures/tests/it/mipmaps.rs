//! The GPU's mip levels against the CPU's: every level of an sRGB texture
//! is the 2 × 2 box filter of the level above, averaged in linear light;
//! every level of a normal map is the average direction, made unit length.

use common::glam::Vec3;
use common::headless::read_level_bytes;
use common::image::{Rgba, RgbaImage};
use common::texture::ColorSpace;
use common::{Gpu, GpuNeeds};
use textures::materials::{Uploader, upload};
use textures::mipmaps::{MipMaker, box_filter_srgb};

/// A fixed noisy picture (a hash per texel), so that every block differs.
fn noise(size: u32, salt: u32) -> RgbaImage {
    RgbaImage::from_fn(size, size, |x, y| {
        let mut h = (x * 7919 + y * 104_729 + salt).wrapping_mul(2_654_435_761);
        let mut next = || {
            h ^= h >> 13;
            h = h.wrapping_mul(0x5bd1_e995);
            (h >> 24) as u8
        };
        Rgba([next(), next(), next(), next()])
    })
}

fn levels(gpu: &Gpu, image: &RgbaImage, space: ColorSpace) -> Vec<RgbaImage> {
    let mut mips = MipMaker::new(gpu).unwrap();
    let mut up = Uploader::new(gpu, &mut mips, &textures::builtin::read);
    let texture = upload(&mut up, image, space, "test");
    up.finish();
    (0..texture.texture.mip_level_count())
        .map(|level| {
            let bytes = read_level_bytes(gpu, &texture.texture, level, 4).unwrap();
            let size = (image.width() >> level).max(1);
            RgbaImage::from_raw(size, size, bytes).unwrap()
        })
        .collect()
}

fn largest_difference(a: &RgbaImage, b: &RgbaImage) -> u8 {
    a.as_raw().iter().zip(b.as_raw()).map(|(x, y)| x.abs_diff(*y)).max().unwrap_or(0)
}

// ANCHOR: test
#[test]
fn each_srgb_level_is_the_box_filter_of_the_one_above_in_linear_light() {
    let gpu = Gpu::headless(GpuNeeds::default()).unwrap();
    let levels = levels(&gpu, &noise(64, 1), ColorSpace::Srgb);
    assert_eq!(levels.len(), 7, "64, 32, 16, 8, 4, 2, 1");
    for n in 1..levels.len() {
        let expected = box_filter_srgb(&levels[n - 1]);
        let off = largest_difference(&levels[n], &expected);
        // The GPU filters in more precision than 8 bits before encoding:
        // one step of rounding either way.
        assert!(off <= 1, "level {n}: {off} steps from the CPU's box filter");
    }
}
// ANCHOR_END: test

#[test]
fn normal_map_levels_average_the_directions_and_stay_unit_length() {
    let gpu = Gpu::headless(GpuNeeds::default()).unwrap();
    // Random directions in the upper half (z > 0), encoded 0..255.
    let image = RgbaImage::from_fn(32, 32, |x, y| {
        let p = noise(32, 2).get_pixel(x, y).0;
        let n = Vec3::new(p[0] as f32 / 255.0 - 0.5, p[1] as f32 / 255.0 - 0.5, 0.4 + p[2] as f32 / 510.0).normalize();
        let e = |c: f32| ((c * 0.5 + 0.5) * 255.0).round() as u8;
        Rgba([e(n.x), e(n.y), e(n.z), 255])
    });
    let levels = levels(&gpu, &image, ColorSpace::Linear);
    let decode = |p: &Rgba<u8>| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32) / 127.5 - 1.0;
    for n in 1..levels.len() {
        for (x, y, got) in levels[n].enumerate_pixels() {
            let above = &levels[n - 1];
            let sum: Vec3 = [(0, 0), (1, 0), (0, 1), (1, 1)]
                .iter()
                .map(|(dx, dy)| decode(above.get_pixel(2 * x + dx, 2 * y + dy)))
                .sum();
            let expected = sum.normalize();
            let got = decode(got);
            assert!((got.length() - 1.0).abs() < 0.02, "level {n} ({x}, {y}): length {}", got.length());
            assert!(got.angle_between(expected).to_degrees() < 1.5, "level {n} ({x}, {y}): {got} against {expected}");
        }
    }
}
