//! The bloom piece on pictures made by hand: a single bright pixel spreads
//! into a symmetric blob, black stays black, and the bloom adds no more
//! light than the bright part of the picture times the strength.

use common::headless::read_floats;
use common::{Gpu, GpuNeeds, PassTimer, wgpu};
use lighting::bloom::{Bloom, BloomSettings};

const SIZE: u32 = 128;

/// An HDR picture (Rgba16Float) with the given pixels lit, black elsewhere.
fn picture(gpu: &Gpu, lit: &[((u32, u32), [f32; 3])]) -> wgpu::Texture {
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("test picture"),
        size: wgpu::Extent3d { width: SIZE, height: SIZE, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba16Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let mut texels = vec![half::f16::ZERO; (SIZE * SIZE * 4) as usize];
    for &((x, y), rgb) in lit {
        let at = ((y * SIZE + x) * 4) as usize;
        for c in 0..3 {
            texels[at + c] = half::f16::from_f32(rgb[c]);
        }
    }
    let bytes: Vec<u8> = texels.iter().flat_map(|h| h.to_le_bytes()).collect();
    gpu.queue.write_texture(
        texture.as_image_copy(),
        &bytes,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(SIZE * 8), rows_per_image: None },
        texture.size(),
    );
    texture
}

/// Runs the bloom over `source`; returns its output (half size) as RGB rows.
fn bloom_of(gpu: &Gpu, bloom: &Bloom, source: &wgpu::Texture, settings: &BloomSettings) -> Vec<[f32; 4]> {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let view = source.create_view(&Default::default());
    bloom.render(gpu, &mut encoder, &PassTimer::off(), &view, settings);
    gpu.queue.submit([encoder.finish()]);
    read_floats(gpu, bloom.output().texture()).unwrap()
}

fn devices() -> Vec<Gpu> {
    // With the small float format where the adapter renders to it, and the fallback.
    let with = Gpu::headless(GpuNeeds { optional: Bloom::OPTIONAL_FEATURES, ..Default::default() }).unwrap();
    let without = Gpu::headless(GpuNeeds::default()).unwrap();
    vec![with, without]
}

#[test]
fn both_formats_are_exercised_where_the_adapter_has_the_small_one() {
    let formats: Vec<wgpu::TextureFormat> = devices().iter().map(|gpu| Bloom::new(gpu, 8, 8).unwrap().format).collect();
    let has = devices()[0].adapter.features().contains(wgpu::Features::RG11B10UFLOAT_RENDERABLE);
    let expected = if has { wgpu::TextureFormat::Rg11b10Ufloat } else { wgpu::TextureFormat::Rgba16Float };
    assert_eq!(formats, vec![expected, wgpu::TextureFormat::Rgba16Float]);
    eprintln!("bloom formats: {formats:?}");
}

#[test]
fn black_stays_black() {
    for gpu in devices() {
        let bloom = Bloom::new(&gpu, SIZE, SIZE).unwrap();
        let output = bloom_of(&gpu, &bloom, &picture(&gpu, &[]), &BloomSettings::default());
        assert!(output.iter().all(|t| t[0] == 0.0 && t[1] == 0.0 && t[2] == 0.0), "{:?}", bloom.format);
    }
}

#[test]
fn one_bright_pixel_spreads_into_a_symmetric_blob() {
    for gpu in devices() {
        let bloom = Bloom::new(&gpu, SIZE, SIZE).unwrap();
        let output = bloom_of(&gpu, &bloom, &picture(&gpu, &[((63, 63), [50.0; 3])]), &BloomSettings::default());
        let half = (SIZE / 2) as usize;
        let at = |x: usize, y: usize| output[y * half + x][0];
        // The pixel lands in half-size texel (31, 31): the blob is centred there.
        let peak = at(31, 31);
        assert!(peak > 0.0);
        let (mut mass, mut centre) = (0.0f64, (0.0f64, 0.0f64));
        for y in 0..half {
            for x in 0..half {
                let v = f64::from(at(x, y));
                mass += v;
                centre.0 += v * x as f64;
                centre.1 += v * y as f64;
            }
        }
        let centre = (centre.0 / mass, centre.1 / mass);
        assert!((centre.0 - 31.0).abs() < 0.6 && (centre.1 - 31.0).abs() < 0.6, "centred at {centre:?}");
        // It has spread: light well away from the pixel, falling with distance.
        assert!(at(31 + 6, 31) > 0.0 && at(31 + 6, 31) < at(31 + 2, 31) && at(31 + 2, 31) < peak);
        // And it is the same either way: left and right, up and down, along the diagonals.
        for d in 1..12 {
            for (a, b) in
                [((31 + d, 31), (31 - d, 31)), ((31, 31 + d), (31, 31 - d)), ((31 + d, 31 + d), (31 - d, 31 - d))]
            {
                let (p, q) = (at(a.0, a.1), at(b.0, b.1));
                assert!((p - q).abs() <= 0.02 * peak, "{:?}: {p} at {a:?} but {q} at {b:?}", bloom.format);
            }
        }
    }
}

/// The bloom may add the bright part times the strength and a hundredth
/// more, for the rounding of small floats (10 bits of mantissa at most)...
const ROUNDING_ALLOWANCE: f64 = 1.01;
/// ...and must keep at least this much of it: little light is lost on the way.
const LEAST_KEPT: f64 = 0.9;

#[test]
fn the_bloom_adds_no_more_light_than_the_bright_part_times_the_strength() {
    let settings = BloomSettings { strength: 0.6, ..Default::default() };
    let lit =
        [((40, 50), [6.0, 3.0, 1.0]), ((70, 64), [2.0, 2.0, 2.0]), ((64, 80), [20.0, 0.5, 0.5]), ((90, 30), [0.8; 3])];
    for gpu in devices() {
        let bloom = Bloom::new(&gpu, SIZE, SIZE).unwrap();
        let output = bloom_of(&gpu, &bloom, &picture(&gpu, &lit), &settings);
        // The composite adds strength × the output, enlarged to full size: a
        // half-size texel covers four pixels.
        let added: f64 =
            output.iter().map(|t| f64::from(t[0] + t[1] + t[2]) * 4.0 * f64::from(settings.strength)).sum();
        let bright: f64 =
            lit.iter().map(|(_, rgb)| settings.bright_part(*rgb).iter().map(|&c| f64::from(c)).sum::<f64>()).sum();
        let budget = bright * f64::from(settings.strength);
        assert!(
            added <= budget * ROUNDING_ALLOWANCE,
            "{:?}: the bloom adds {added}, the bright part times the strength is {budget}",
            bloom.format
        );
        assert!(added >= budget * LEAST_KEPT, "{:?}: the bloom lost light: {added} of {budget}", bloom.format);
    }
}
