//! Mipmaps, made on the GPU when a texture loads: each level half the size
//! of the one above, drawn by a full-screen pass that averages the level
//! above in 2 × 2 blocks. Render passes rather than a compute shader,
//! because a compute shader cannot write an sRGB texture (storage textures
//! have no sRGB formats), and a render target can: the averaging then
//! happens in linear light, as it must.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use common::chapter::{FILTERABLE, sampler_entry, texture_entry};
use common::{Drawn, Gpu, Reloadable, ShaderError, fullscreen, shader, wgpu};

/// Levels in a full chain for a `width × height` texture, down to 1 × 1.
pub fn level_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// How a level is averaged from the one above.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Averaging {
    /// Colours (and the albedo's alpha), averaged as they are.
    Colour,
    /// Tangent-space normals: averaged, then made unit length again.
    Normals,
}

// ANCHOR: maker
/// Builds the mip chains of textures: one small pipeline per format and
/// kind of averaging, made when first needed.
pub struct MipMaker {
    layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    /// Made again, with none of its pipelines yet, when mipmap.wgsl is
    /// saved (hot reload).
    pipelines: Reloadable<Arc<MipPipelines>>,
}

/// mipmap.wgsl's module and the pipelines made from it so far.
struct MipPipelines {
    module: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    made: Mutex<HashMap<(wgpu::TextureFormat, Averaging), wgpu::RenderPipeline>>,
}

impl MipPipelines {
    fn new(gpu: &Gpu, layout: &wgpu::PipelineLayout) -> Result<Arc<Self>, ShaderError> {
        let module = shader!("textures/mipmap.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        let pipelines = Self { module, layout: layout.clone(), made: Mutex::default() };
        // The two that textures in sRGB and normal maps need, made now: an
        // edit that breaks them is an error here, not a panic later.
        gpu.catch_validation(|| {
            pipelines.get(&gpu.device, wgpu::TextureFormat::Rgba8UnormSrgb, Averaging::Colour);
            pipelines.get(&gpu.device, wgpu::TextureFormat::Rgba8Unorm, Averaging::Normals);
        })
        .map_err(ShaderError)?;
        Ok(Arc::new(pipelines))
    }

    fn get(&self, device: &wgpu::Device, format: wgpu::TextureFormat, averaging: Averaging) -> wgpu::RenderPipeline {
        let mut made = self.made.lock().unwrap_or_else(|e| e.into_inner());
        let pipeline = made.entry((format, averaging)).or_insert_with(|| {
            let entry = match averaging {
                Averaging::Colour => "fs_colour",
                Averaging::Normals => "fs_normal",
            };
            fullscreen::pipeline(device, "mip level", &self.layout, &self.module, entry, format.into(), None)
        });
        pipeline.clone()
    }
}

impl MipMaker {
    pub fn new(gpu: &Gpu) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("mip level above"),
            entries: &[texture_entry(0, FILTERABLE), sampler_entry(1)],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mipmaps"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("mipmaps"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let pipelines = Reloadable::new(gpu, move |gpu| MipPipelines::new(gpu, &pipeline_layout))?;
        Ok(Self { layout, sampler, pipelines })
    }

    /// Records the passes that fill levels 1.. of `texture` from level 0.
    /// The texture needs `RENDER_ATTACHMENT` and `TEXTURE_BINDING` usage.
    /// Returns what they drew: a full-screen triangle a level.
    pub fn generate(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        texture: &wgpu::Texture,
        averaging: Averaging,
    ) -> Drawn {
        let pipeline = self.pipelines.get().get(device, texture.format(), averaging);
        let level_view = |level| {
            texture.create_view(&wgpu::TextureViewDescriptor {
                base_mip_level: level,
                mip_level_count: Some(1),
                ..Default::default()
            })
        };
        let mut drawn = Drawn::NOTHING;
        for level in 1..texture.mip_level_count() {
            let above = level_view(level - 1);
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("mip level above"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&above) },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&self.sampler) },
                ],
            });
            let target = level_view(level);
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("mip level"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                ..Default::default()
            });
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &group, &[]);
            pass.draw(0..3, 0..1);
            drawn += Drawn::FULL_SCREEN;
        }
        drawn
    }
}
// ANCHOR_END: maker

// ANCHOR: reference
/// The CPU's answer for one level of an sRGB picture: each texel the mean
/// of a 2 × 2 block of the level above, averaged in linear light (alpha as
/// it is), `common::texture::half_size_srgb`. The test compares the GPU's
/// levels with this.
pub use common::texture::half_size_srgb as box_filter_srgb;
// ANCHOR_END: reference

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chains_go_down_to_one_texel() {
        assert_eq!(level_count(256, 256), 9);
        assert_eq!(level_count(1, 1), 1);
        assert_eq!(level_count(1000, 600), 10);
        assert_eq!(level_count(3, 1), 2);
    }

    #[test]
    fn the_cpu_box_filter_averages_light_not_numbers() {
        // Black and white texels average to middle grey in light: 188 in
        // sRGB, not 128.
        let image = common::image::RgbaImage::from_fn(2, 2, |x, _| {
            let c = if x == 0 { 0 } else { 255 };
            common::image::Rgba([c, c, c, 255])
        });
        assert_eq!(box_filter_srgb(&image).get_pixel(0, 0).0, [188, 188, 188, 255]);
    }
}
