//! The real tone map pass (tonemap.wgsl, through `ToneMap`) against
//! `aces_fit`, its Rust mirror that the book's plot is drawn from: known
//! HDR values in, read back as 32-bit floats, at several exposures.

use common::headless::read_floats;
use common::{Antialiasing, DrawCounts, Frame, Gpu, GpuNeeds, PassTimer, wgpu};
use lighting::post::{PostOutput, ToneMap, aces_fit};

/// Grey light values, each exactly representable in 16-bit floats (the
/// HDR target's), from deep shadow to a lamp's core.
const LIGHT: [f32; 9] = [0.0, 0.015625, 0.0625, 0.25, 0.5, 1.0, 2.0, 8.0, 64.0];

fn texture(gpu: &Gpu, format: wgpu::TextureFormat, usage: wgpu::TextureUsages, width: u32) -> wgpu::Texture {
    gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("tone map test"),
        size: wgpu::Extent3d { width, height: 1, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

#[test]
fn the_tone_map_pass_draws_aces_fit_of_the_exposed_light() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let width = LIGHT.len() as u32;
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let hdr = texture(&gpu, wgpu::TextureFormat::Rgba16Float, usage, width);
    let texels: Vec<u8> =
        LIGHT.iter().flat_map(|&x| [x, x, x, 1.0]).flat_map(|v| half::f16::from_f32(v).to_le_bytes()).collect();
    gpu.queue.write_texture(
        hdr.as_image_copy(),
        &texels,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(width * 8), rows_per_image: None },
        hdr.size(),
    );
    // No bloom: a black bloom level (new textures are zeros), weighted 0.
    let bloom = texture(&gpu, wgpu::TextureFormat::Rgba16Float, usage, 1);
    // 32-bit floats out, linear: what the curve gives, before any sRGB
    // encoding or rounding to 8 bits.
    let format = wgpu::TextureFormat::Rgba32Float;
    let target = texture(&gpu, format, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC, width);
    let view = |t: &wgpu::Texture| t.create_view(&Default::default());
    let tone_map = ToneMap::new(&gpu, format, &view(&hdr), &view(&bloom)).unwrap();
    let target_view = view(&target);

    let mut worst = 0.0f32;
    for exposure in [1.0, 0.25, 4.0] {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        let (timer, drawn) = (PassTimer::off(), DrawCounts::new());
        let mut frame = Frame {
            encoder: &mut encoder,
            target: &target_view,
            time: 0.0,
            view: 0,
            timer: &timer,
            drawn: &drawn,
            antialiasing: Antialiasing::Off,
        };
        tone_map.draw(&gpu, &mut frame, &target_view, exposure, 0.0, PostOutput::Picture);
        gpu.queue.submit([encoder.finish()]);
        let drawn = read_floats(&gpu, &target).unwrap();
        for (&light, texel) in LIGHT.iter().zip(&drawn) {
            let expected = aces_fit(light * exposure);
            for &channel in &texel[..3] {
                worst = worst.max((channel - expected).abs());
                assert!(
                    (channel - expected).abs() < 1e-5,
                    "light {light} at exposure {exposure}: the pass drew {channel}, aces_fit says {expected}"
                );
            }
        }
    }
    eprintln!("tone map pass against aces_fit: largest difference {worst:e}");
}
