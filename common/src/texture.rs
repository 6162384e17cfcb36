//! Loading images into GPU textures, the sRGB transfer function and a
//! mip level made in linear light, and the depth buffer helper.

use std::path::Path;

use anyhow::Context as _;

/// The depth format every chapter uses: 32-bit float, nothing to pack.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// How the texels of an image are to be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorSpace {
    /// Colour pictures: stored sRGB-encoded, and the sampler decodes to
    /// linear light so that lighting maths is right.
    Srgb,
    /// Data (normal maps, height maps, DuDv maps): used as stored.
    Linear,
}

// ANCHOR: transfer
/// The sRGB transfer function (IEC 61966-2-1), decoding: a stored value
/// `v` (0..1, a byte over 255) to the light it stands for (0..1).
pub fn srgb_to_linear(v: f32) -> f32 {
    if v <= 0.040_45 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
}

/// The sRGB transfer function, encoding: light `l` (0..1) to the value
/// stored for it (0..1).
pub fn linear_to_srgb(l: f32) -> f32 {
    if l <= 0.003_130_8 { 12.92 * l } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 }
}
// ANCHOR_END: transfer

// ANCHOR: half_size
/// The next mip level of an sRGB picture, on the CPU: half as wide and
/// high (at least 1), each texel the mean of the 2 × 2 texels above it
/// (clamped at an odd edge), averaged in linear light (alpha as it is):
/// averaging the stored bytes would darken every level.
pub fn half_size_srgb(above: &image::RgbaImage) -> image::RgbaImage {
    let decode = |c: u8| srgb_to_linear(f32::from(c) / 255.0);
    let encode = |c: f32| (linear_to_srgb(c).clamp(0.0, 1.0) * 255.0).round() as u8;
    let (width, height) = ((above.width() / 2).max(1), (above.height() / 2).max(1));
    image::RgbaImage::from_fn(width, height, |x, y| {
        let texels = [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(dx, dy)| {
            above.get_pixel((2 * x + dx).min(above.width() - 1), (2 * y + dy).min(above.height() - 1)).0
        });
        let mean = |channel: usize, linear: bool| {
            let sum: f32 =
                texels.iter().map(|t| if linear { decode(t[channel]) } else { f32::from(t[channel]) / 255.0 }).sum();
            sum / 4.0
        };
        image::Rgba([
            encode(mean(0, true)),
            encode(mean(1, true)),
            encode(mean(2, true)),
            (mean(3, false) * 255.0).round() as u8,
        ])
    })
}
// ANCHOR_END: half_size

/// Reads a PNG or JPEG into RGBA8. Errors name the file and the reason.
pub fn load_rgba(path: &Path) -> anyhow::Result<image::RgbaImage> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    decode_named(&path.display().to_string(), &bytes)
}

/// Decodes `bytes`, reporting a failure as "`name` is not a readable PNG or
/// JPEG" with the decoder's reason: how every asset error reads. On the
/// desktop BMP and TGA are read too (older exporters' MTL files name them);
/// TGA has no signature to be known by, so its name's extension says.
pub fn decode_named(name: &str, bytes: &[u8]) -> anyhow::Result<image::RgbaImage> {
    let decoded = match (image::guess_format(bytes), image::ImageFormat::from_path(name)) {
        (Err(_), Ok(format)) => {
            image::load_from_memory_with_format(bytes, format).map(|i| i.to_rgba8()).map_err(anyhow::Error::from)
        }
        _ => decode_rgba(bytes),
    };
    decoded.with_context(|| format!("{name} is not a readable PNG or JPEG{READABLE_TOO}"))
}

/// The other formats `decode_named` reads, for its message.
#[cfg(not(target_arch = "wasm32"))]
const READABLE_TOO: &str = " (nor BMP or TGA)";
#[cfg(target_arch = "wasm32")]
const READABLE_TOO: &str = "";

/// Decodes an encoded image already in memory (for assets embedded with
/// `include_bytes!`).
pub fn decode_rgba(bytes: &[u8]) -> anyhow::Result<image::RgbaImage> {
    Ok(image::load_from_memory(bytes)?.to_rgba8())
}

/// A texture with the view and sampler a shader binds.
pub struct Texture {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub sampler: wgpu::Sampler,
}

impl Texture {
    /// Uploads an RGBA8 image (one mip level) with a linear, repeating sampler.
    pub fn from_image(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        image: &image::RgbaImage,
        space: ColorSpace,
        label: &str,
    ) -> Self {
        let format = match space {
            ColorSpace::Srgb => wgpu::TextureFormat::Rgba8UnormSrgb,
            ColorSpace::Linear => wgpu::TextureFormat::Rgba8Unorm,
        };
        let size = wgpu::Extent3d { width: image.width(), height: image.height(), depth_or_array_layers: 1 };
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        queue.write_texture(
            texture.as_image_copy(),
            image.as_raw(),
            wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * image.width()), rows_per_image: None },
            size,
        );
        let view = texture.create_view(&Default::default());
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some(label),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Self { texture, view, sampler }
    }

    /// Decodes an embedded image (`include_bytes!`), named for errors.
    pub fn from_bytes(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        name: &str,
        bytes: &[u8],
        space: ColorSpace,
    ) -> anyhow::Result<Self> {
        Ok(Self::from_image(device, queue, &decode_named(name, bytes)?, space, name))
    }

    /// Loads an image file; see [`load_rgba`] for the errors.
    pub fn from_file(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        path: &Path,
        space: ColorSpace,
    ) -> anyhow::Result<Self> {
        let image = load_rgba(path)?;
        Ok(Self::from_image(device, queue, &image, space, &path.display().to_string()))
    }
}

/// Decodes six cube faces, each given as (file name for errors, encoded
/// PNG or JPEG bytes), and checks that they are square and the same size.
pub fn decode_faces(faces: &[(&str, &[u8]); 6]) -> anyhow::Result<[image::RgbaImage; 6]> {
    let images = faces.iter().map(|(name, bytes)| decode_named(name, bytes)).collect::<anyhow::Result<Vec<_>>>()?;
    let size = images[0].width();
    if let Some(((name, _), image)) = faces.iter().zip(&images).find(|(_, i)| i.dimensions() != (size, size)) {
        anyhow::bail!("{name} is {}x{}, but cube faces must all be {size}x{size}", image.width(), image.height());
    }
    Ok(images.try_into().expect("six faces in, six images out"))
}

/// A cube map from six square faces in WebGPU's order (+x, −x, +y, −y, +z,
/// −z), each given as (file name for errors, encoded PNG or JPEG bytes).
/// Sampled with a direction instead of coordinates, as skies are.
pub fn cubemap(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    faces: &[(&str, &[u8]); 6],
    space: ColorSpace,
) -> anyhow::Result<Texture> {
    Ok(cubemap_from_images(device, queue, &decode_faces(faces)?, space, faces[0].0))
}

/// A cube map from six faces already decoded (see [`decode_faces`]).
pub fn cubemap_from_images(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    images: &[image::RgbaImage; 6],
    space: ColorSpace,
    label: &str,
) -> Texture {
    let size = images[0].width();
    let format = match space {
        ColorSpace::Srgb => wgpu::TextureFormat::Rgba8UnormSrgb,
        ColorSpace::Linear => wgpu::TextureFormat::Rgba8Unorm,
    };
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 6 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (layer, image) in images.iter().enumerate() {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: 0,
                origin: wgpu::Origin3d { x: 0, y: 0, z: layer as u32 },
                aspect: wgpu::TextureAspect::All,
            },
            image.as_raw(),
            wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * size), rows_per_image: None },
            wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
        );
    }
    let view = texture.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::Cube),
        ..Default::default()
    });
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("cubemap"),
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        ..Default::default()
    });
    Texture { texture, view, sampler }
}

/// The usual depth test: keep a fragment nearer than what is stored, and
/// store its depth (chapter 02 explains it).
pub fn depth_test() -> Option<wgpu::DepthStencilState> {
    Some(wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(true),
        depth_compare: Some(wgpu::CompareFunction::Less),
        stencil: Default::default(),
        bias: Default::default(),
    })
}

/// A depth buffer the size of the colour target.
pub fn depth_view(device: &wgpu::Device, width: u32, height: u32) -> wgpu::TextureView {
    device
        .create_texture(&wgpu::TextureDescriptor {
            label: Some("depth"),
            size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            // Sampled too, so debug views can show what the depth test saw.
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        })
        .create_view(&Default::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_file_error_names_the_file() {
        let error = load_rgba(Path::new("no/such/rock.png")).unwrap_err();
        let message = format!("{error:#}");
        assert!(message.contains("no/such/rock.png"), "{message}");
        assert!(message.contains("No such file"), "{message}");
    }

    #[test]
    fn corrupt_file_error_names_the_file_and_the_reason() {
        let path = std::env::temp_dir().join(format!("corrupt-{}.png", std::process::id()));
        std::fs::write(&path, b"\x89PNG\r\n\x1a\nthis is not a png").unwrap();
        let message = format!("{:#}", load_rgba(&path).unwrap_err());
        std::fs::remove_file(&path).unwrap();
        assert!(message.contains(&path.display().to_string()), "{message}");
        assert!(message.contains("not a readable PNG or JPEG"), "{message}");
    }

    #[test]
    fn decodes_what_it_encodes() {
        let image = image::RgbaImage::from_fn(3, 2, |x, y| image::Rgba([x as u8 * 80, y as u8 * 200, 7, 255]));
        let mut png = Vec::new();
        image.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png).unwrap();
        assert_eq!(decode_rgba(&png).unwrap(), image);
    }
}
