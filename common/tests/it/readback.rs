//! Reading textures back to the CPU at widths whose rows need padding.

use common::{Gpu, GpuNeeds, headless};

fn upload(
    gpu: &Gpu,
    format: common::wgpu::TextureFormat,
    width: u32,
    height: u32,
    bytes: &[u8],
) -> common::wgpu::Texture {
    use common::wgpu;
    let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    gpu.queue.write_texture(
        texture.as_image_copy(),
        bytes,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * width), rows_per_image: None },
        size,
    );
    texture
}

/// A pattern where every byte tells its position, so a wrong row stride shows.
fn pattern(width: u32, height: u32) -> Vec<u8> {
    (0..height).flat_map(|y| (0..width).flat_map(move |x| [x as u8, y as u8, (x * 7 + y * 13) as u8, 255])).collect()
}

#[test]
fn odd_widths_read_back_exactly() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    for (width, height) in [(1, 1), (37, 5), (63, 4), (64, 3), (65, 2), (257, 3)] {
        let bytes = pattern(width, height);
        let texture = upload(&gpu, common::wgpu::TextureFormat::Rgba8Unorm, width, height, &bytes);
        let image = headless::read_texture(&gpu, &texture).unwrap();
        assert_eq!(image.dimensions(), (width, height));
        assert_eq!(image.as_raw(), &bytes, "{width}x{height}");
    }
}

#[test]
fn bgra_textures_come_back_as_rgba() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let texture = upload(&gpu, common::wgpu::TextureFormat::Bgra8Unorm, 3, 1, &[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);
    let image = headless::read_texture(&gpu, &texture).unwrap();
    assert_eq!(image.as_raw(), &[3, 2, 1, 4, 7, 6, 5, 8, 11, 10, 9, 12]);
}
