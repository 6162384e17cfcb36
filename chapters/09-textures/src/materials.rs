//! Materials on the GPU: their textures uploaded in the right colour space
//! with a full mip chain, the samplers this chapter compares, and one bind
//! group per material. A texture that cannot be read becomes a checker,
//! with a warning, and the model still shows.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use common::chapter::{FILTERABLE, storage_entry, texture_entry};
use common::glam::Vec3;
use common::image::RgbaImage;
use common::wgpu::util::DeviceExt as _;
use common::{Gpu, texture::ColorSpace, wgpu};

use crate::mesh::MaterialDesc;
use crate::mipmaps::{Averaging, MipMaker, level_count};
use crate::obj::{self, Found, ReadFile};

// ANCHOR: samplers
/// The ways of reading a texture this chapter compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SamplerMode {
    /// The nearest texel of the full-size picture: blocky up close, and
    /// far away a random pick among many texels (aliasing).
    Nearest,
    /// The four nearest texels blended: smooth up close, still aliased far away.
    Linear,
    /// Trilinear: blended within the two mip levels whose texels are
    /// nearest the pixel's size, and between them.
    Mipmaps,
    /// Trilinear, with up to 16 samples along the direction a pixel's
    /// footprint is stretched in (anisotropic filtering).
    Anisotropic,
}

impl SamplerMode {
    pub const ALL: [SamplerMode; 4] =
        [SamplerMode::Nearest, SamplerMode::Linear, SamplerMode::Mipmaps, SamplerMode::Anisotropic];

    /// The most samples anisotropic filtering takes along a footprint: 16,
    /// the most wgpu allows.
    pub const MAX_ANISOTROPY: u16 = 16;

    /// The sampler. `anisotropy` is false where the adapter cannot filter
    /// anisotropically: `Anisotropic` is then plain trilinear.
    pub fn descriptor(self, anisotropy: bool) -> wgpu::SamplerDescriptor<'static> {
        use wgpu::FilterMode::Linear;
        let repeat = wgpu::AddressMode::Repeat;
        let base = wgpu::SamplerDescriptor {
            label: Some("surface"),
            address_mode_u: repeat,
            address_mode_v: repeat,
            ..Default::default()
        };
        let only_level_0 = 0.0;
        match self {
            SamplerMode::Nearest => wgpu::SamplerDescriptor { lod_max_clamp: only_level_0, ..base },
            SamplerMode::Linear => {
                wgpu::SamplerDescriptor { mag_filter: Linear, min_filter: Linear, lod_max_clamp: only_level_0, ..base }
            }
            SamplerMode::Mipmaps | SamplerMode::Anisotropic => wgpu::SamplerDescriptor {
                mag_filter: Linear,
                min_filter: Linear,
                mipmap_filter: wgpu::MipmapFilterMode::Linear,
                anisotropy_clamp: if self == SamplerMode::Anisotropic && anisotropy { Self::MAX_ANISOTROPY } else { 1 },
                ..base
            },
        }
    }
}
// ANCHOR_END: samplers

/// A texture with a full mip chain, and views of it read both ways: as it
/// should be, and in the other colour space (the mistake one view shows).
pub struct GpuTexture {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub swapped_view: wgpu::TextureView,
}

/// What uploading textures takes: the GPU, the mip maker, an encoder for
/// the mip passes, and where files are read from.
pub struct Uploader<'a> {
    pub gpu: &'a Gpu,
    pub mips: &'a mut MipMaker,
    pub encoder: wgpu::CommandEncoder,
    pub read: ReadFile<'a>,
}

impl<'a> Uploader<'a> {
    pub fn new(gpu: &'a Gpu, mips: &'a mut MipMaker, read: ReadFile<'a>) -> Self {
        let encoder = gpu.device.create_command_encoder(&Default::default());
        Self { gpu, mips, encoder, read }
    }

    /// Submits the recorded mip passes and waits for them. Returns how long
    /// the passes alone took, in milliseconds: the texture uploads are
    /// flushed and waited for first, so they are not counted.
    pub fn finish(self) -> f64 {
        let (queue, device) = (&self.gpu.queue, &self.gpu.device);
        queue.submit([]);
        let _ = device.poll(wgpu::PollType::wait_indefinitely());
        let ((), ms) = common::timing::measure(|| {
            queue.submit([self.encoder.finish()]);
            let _ = device.poll(wgpu::PollType::wait_indefinitely());
        });
        ms
    }
}

// ANCHOR: upload
/// Uploads `image` into a texture whose texels are sRGB-encoded colours or
/// plain data, and records the passes that fill its mip chain.
pub fn upload(up: &mut Uploader, image: &RgbaImage, space: ColorSpace, label: &str) -> GpuTexture {
    let gpu = up.gpu;
    let (format, other) = match space {
        ColorSpace::Srgb => (wgpu::TextureFormat::Rgba8UnormSrgb, wgpu::TextureFormat::Rgba8Unorm),
        ColorSpace::Linear => (wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureFormat::Rgba8UnormSrgb),
    };
    let size = wgpu::Extent3d { width: image.width(), height: image.height(), depth_or_array_layers: 1 };
    let view_formats = [other];
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size,
        mip_level_count: level_count(image.width(), image.height()),
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_DST
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::RENDER_ATTACHMENT,
        // The same bytes may also be viewed in the other colour space.
        view_formats: if can_view_as_other_formats(gpu) { &view_formats } else { &[] },
    });
    gpu.queue.write_texture(
        texture.as_image_copy(),
        image.as_raw(),
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * image.width()), rows_per_image: None },
        size,
    );
    let averaging = if space == ColorSpace::Srgb { Averaging::Colour } else { Averaging::Normals };
    up.mips.generate(&gpu.device, &mut up.encoder, &texture, averaging);
    let view = texture.create_view(&Default::default());
    let swapped_view = if can_view_as_other_formats(gpu) {
        texture.create_view(&wgpu::TextureViewDescriptor { format: Some(other), ..Default::default() })
    } else {
        copy_as(up, &texture, other)
    };
    GpuTexture { texture, view, swapped_view }
}
// ANCHOR_END: upload

/// Whether a texture's bytes can be viewed in another format; OpenGL and
/// WebGL2 cannot ([`wgpu::DownlevelFlags::VIEW_FORMATS`]).
fn can_view_as_other_formats(gpu: &Gpu) -> bool {
    gpu.downlevel().flags.contains(wgpu::DownlevelFlags::VIEW_FORMATS)
}

/// Where a texture cannot be viewed in the other colour space: a copy of
/// its bytes, every mip level, in a texture of that format (copies between
/// an sRGB format and its plain twin keep the bytes). Says so once.
fn copy_as(up: &mut Uploader, texture: &wgpu::Texture, format: wgpu::TextureFormat) -> wgpu::TextureView {
    static SAID: std::sync::Once = std::sync::Once::new();
    SAID.call_once(|| {
        common::log::warn!("this adapter cannot view a texture in another format (VIEW_FORMATS): each texture is copied for the swapped colour spaces")
    });
    let copy = up.gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("in the other colour space"),
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
        size: texture.size(),
        mip_level_count: texture.mip_level_count(),
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
    });
    for level in 0..texture.mip_level_count() {
        let size = texture.size().mip_level_size(level, wgpu::TextureDimension::D2);
        up.encoder.copy_texture_to_texture(
            wgpu::TexelCopyTextureInfo { mip_level: level, ..texture.as_image_copy() },
            wgpu::TexelCopyTextureInfo { mip_level: level, ..copy.as_image_copy() },
            size,
        );
    }
    copy.create_view(&Default::default())
}

/// The texture of a missing or unreadable file: a magenta and black checker
/// of 8 × 8 squares, impossible to mistake for a real surface.
pub fn missing_checker() -> RgbaImage {
    RgbaImage::from_fn(64, 64, |x, y| {
        let on = (x / 8 + y / 8) % 2 == 0;
        common::image::Rgba(if on { [255, 0, 255, 255] } else { [16, 16, 16, 255] })
    })
}

/// Chapter 02's ground, as a texture: black and white squares, 8 × 8 of
/// them in 256² texels, the hardest picture to sample from afar.
pub fn checkerboard() -> RgbaImage {
    RgbaImage::from_fn(256, 256, |x, y| {
        let c = if (x / 32 + y / 32) % 2 == 0 { 235 } else { 20 };
        common::image::Rgba([c, c, c, 255])
    })
}

/// `Material` in textured.wgsl: 64 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct MaterialUniform {
    diffuse: [f32; 3],
    specular: f32,
    emissive: [f32; 3],
    shininess: f32,
    /// x: has a normal map, y: has an albedo map (its alpha masks the
    /// emissive light), z: emits only at night, w: vertex colours multiply
    /// the diffuse colour.
    flags: [u32; 4],
    /// Roughness and metalness for Cook-Torrance (`MaterialDesc::physical`), and padding.
    physical: [f32; 4],
}

/// One material's bind groups: as it should be, and with its textures read
/// in the wrong colour spaces; and where its maps came from.
pub struct GpuMaterial {
    pub desc: MaterialDesc,
    pub group: wgpu::BindGroup,
    pub swapped_group: wgpu::BindGroup,
    /// "albedo", "normal map", "roughness map" or "metalness map", and where it was found.
    pub maps: Vec<(&'static str, TextureSource)>,
}

/// Where a material's map came from, for the model panel.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureSource {
    /// The file the MTL names.
    AsWritten(PathBuf),
    /// Not where the MTL says: a file of the same name in another folder.
    Elsewhere { written: PathBuf, found: PathBuf },
    /// Shown as a checker: why, in a line.
    Missing(String),
}

impl std::fmt::Display for TextureSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::AsWritten(path) => write!(f, "{}", path.display()),
            Self::Elsewhere { written, found } => {
                write!(f, "{} (the MTL says {})", found.display(), written.display())
            }
            Self::Missing(why) => write!(f, "a checker: {why}"),
        }
    }
}

/// Every material of every model, and the textures they share.
pub struct Materials {
    pub layout: wgpu::BindGroupLayout,
    pub list: Vec<GpuMaterial>,
    textures: HashMap<(PathBuf, bool), (Rc<GpuTexture>, TextureSource)>,
    white: Rc<GpuTexture>,
    flat_normal: Rc<GpuTexture>,
    missing: Rc<GpuTexture>,
    /// Textures that could not be read, one line each.
    pub warnings: Vec<String>,
    /// Texels uploaded, level 0 only, for the stats.
    pub texels: u64,
}

impl Materials {
    pub fn new(up: &mut Uploader) -> Self {
        let layout = up.gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("material"),
            entries: &[
                texture_entry(0, FILTERABLE),
                texture_entry(1, FILTERABLE),
                // Storage, not uniform: the shader branches on `flags` (see `storage_entry`).
                // Gouraud shading reads the highlight's strength in the vertex shader.
                storage_entry(2, wgpu::ShaderStages::VERTEX_FRAGMENT),
                // map_Pr and map_Pm.
                texture_entry(3, FILTERABLE),
                texture_entry(4, FILTERABLE),
            ],
        });
        let one = |rgba: [u8; 4]| RgbaImage::from_pixel(1, 1, common::image::Rgba(rgba));
        let white = Rc::new(upload(up, &one([255; 4]), ColorSpace::Srgb, "white"));
        let flat_normal = Rc::new(upload(up, &one([128, 128, 255, 255]), ColorSpace::Linear, "flat"));
        let missing = Rc::new(upload(up, &missing_checker(), ColorSpace::Srgb, "missing texture"));
        Self {
            layout,
            list: Vec::new(),
            textures: HashMap::new(),
            white,
            flat_normal,
            missing,
            warnings: Vec::new(),
            texels: 0,
        }
    }

    /// Uploads an image made in code under a name materials can refer to
    /// (the checkerboard).
    pub fn insert_image(&mut self, up: &mut Uploader, name: &Path, image: &RgbaImage) {
        self.texels += u64::from(image.width()) * u64::from(image.height());
        let texture = upload(up, image, ColorSpace::Srgb, &name.display().to_string());
        let source = TextureSource::AsWritten(name.to_path_buf());
        self.textures.insert((name.to_path_buf(), true), (Rc::new(texture), source));
    }

    /// The texture at `path`, read and uploaded once however many materials
    /// use it. Where `path` does not lead to a file, one of the same name
    /// is looked for in `folders` (see [`obj::find_file`]). A checker, with
    /// a warning naming the file, if none can be read or decoded.
    fn texture(
        &mut self,
        up: &mut Uploader,
        path: &Path,
        colour: bool,
        desc: &MaterialDesc,
    ) -> (Rc<GpuTexture>, TextureSource) {
        if let Some(texture) = self.textures.get(&(path.to_path_buf(), colour)) {
            return texture.clone();
        }
        let folders: Vec<&Path> = desc.texture_folders.iter().map(PathBuf::as_path).collect();
        let material = &desc.name;
        let (bytes, source) = match obj::find_file(path, Path::new(""), &folders, up.read) {
            Found::AsWritten(found, bytes) => (Ok(bytes), TextureSource::AsWritten(found)),
            Found::Elsewhere { written, path: found, bytes } => {
                self.warnings.push(format!(
                    "material {material}: {} not found; using {}, of the same name",
                    written.display(),
                    found.display()
                ));
                (Ok(bytes), TextureSource::Elsewhere { written, found })
            }
            Found::Nowhere { error, tried } => {
                let why = format!("{error}{}", obj::also_tried(&tried[1..]));
                (Err(why.clone()), TextureSource::Missing(why))
            }
        };
        let max = up.gpu.device.limits().max_texture_dimension_2d;
        let decoded = bytes.and_then(|bytes| {
            let name = path.display().to_string();
            let image = common::texture::decode_named(&name, &bytes).map_err(|e| format!("{e:#}"))?;
            if image.width() > max || image.height() > max {
                return Err(format!(
                    "{name} is {}×{}, more than this GPU's {max} texels a side",
                    image.width(),
                    image.height()
                ));
            }
            Ok(image)
        });
        let entry = match decoded {
            Ok(image) => {
                self.texels += u64::from(image.width()) * u64::from(image.height());
                let space = if colour { ColorSpace::Srgb } else { ColorSpace::Linear };
                (Rc::new(upload(up, &image, space, &path.display().to_string())), source)
            }
            Err(reason) => {
                self.warnings.push(format!("material {material}: {reason}; showing a checker instead"));
                (self.missing.clone(), TextureSource::Missing(reason))
            }
        };
        self.textures.insert((path.to_path_buf(), colour), entry.clone());
        entry
    }

    /// Adds a material and returns its index.
    pub fn add(&mut self, up: &mut Uploader, desc: &MaterialDesc) -> usize {
        let mut maps = Vec::new();
        let albedo = match &desc.albedo_map {
            Some(path) => {
                let (texture, source) = self.texture(up, path, true, desc);
                maps.push(("albedo", source));
                texture
            }
            None => self.white.clone(),
        };
        let normal = match &desc.normal_map {
            Some(path) => {
                let (texture, source) = self.texture(up, path, false, desc);
                maps.push(("normal map", source));
                texture
            }
            None => self.flat_normal.clone(),
        };
        // Data, like a normal map; white (1) where the material has none.
        let mut data_map = |map: &Option<PathBuf>, what: &'static str| match map {
            Some(path) => {
                let (texture, source) = self.texture(up, path, false, desc);
                maps.push((what, source));
                texture
            }
            None => self.white.clone(),
        };
        let roughness = data_map(&desc.roughness_map, "roughness map");
        let metallic = data_map(&desc.metallic_map, "metalness map");
        let uniform = MaterialUniform {
            diffuse: desc.diffuse.into(),
            specular: desc.specular,
            emissive: desc.emissive.into(),
            shininess: desc.shininess,
            flags: [
                u32::from(desc.normal_map.is_some()),
                u32::from(desc.albedo_map.is_some()),
                u32::from(desc.at_night),
                u32::from(desc.vertex_colours),
            ],
            physical: {
                let (roughness, metallic) = desc.physical();
                [roughness, metallic, 0.0, 0.0]
            },
        };
        let gpu = up.gpu;
        let buffer = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(&desc.name),
            contents: bytemuck::bytes_of(&uniform),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let group = |albedo: &wgpu::TextureView, normal: &wgpu::TextureView| {
            gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(&desc.name),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(albedo) },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(normal) },
                    wgpu::BindGroupEntry { binding: 2, resource: buffer.as_entire_binding() },
                    wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(&roughness.view) },
                    wgpu::BindGroupEntry { binding: 4, resource: wgpu::BindingResource::TextureView(&metallic.view) },
                ],
            })
        };
        let material = GpuMaterial {
            desc: desc.clone(),
            group: group(&albedo.view, &normal.view),
            swapped_group: group(&albedo.swapped_view, &normal.swapped_view),
            maps,
        };
        self.list.push(material);
        self.list.len() - 1
    }
}

/// The sRGB transfer function, which lives in `common` (chapter 07's water
/// texture needs it before this chapter explains it).
pub use common::texture::{linear_to_srgb, srgb_to_linear};

/// A colour as a person picks it (sRGB, 0..255) to linear light, for
/// material colours written in code.
pub fn srgb(r: u8, g: u8, b: u8) -> Vec3 {
    Vec3::new(r as f32, g as f32, b as f32).map(|c| srgb_to_linear(c / 255.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_srgb_curve_has_its_known_values() {
        // Half the stored range is a fifth of the light; half the light is
        // stored as 0.735 (188 of 255).
        assert!((srgb_to_linear(0.5) - 0.214_04).abs() < 1e-5);
        assert!((linear_to_srgb(0.5) - 0.735_36).abs() < 1e-5);
        // The two pieces meet where the standard says, from either side.
        assert!((srgb_to_linear(0.040_45) - 0.003_130_8).abs() < 1e-6);
        assert!((linear_to_srgb(0.003_130_8) - 0.040_45).abs() < 1e-5);
        assert_eq!((srgb_to_linear(0.0), srgb_to_linear(1.0)), (0.0, 1.0));
        // Every byte survives the round trip.
        for byte in 0..=255u8 {
            let back = linear_to_srgb(srgb_to_linear(byte as f32 / 255.0)) * 255.0;
            assert_eq!(back.round() as u8, byte);
        }
    }
}
