//! Bloom: the bright parts of an HDR picture, blurred wide and added back,
//! the way a camera's lens and our eyes spread very bright light.
//!
//! A piece with explicit inputs (an HDR texture view and `BloomSettings`)
//! and one output (a half-size texture to add to the picture), so that
//! chapter 11 can reuse it. The blur is a chain of downsamples and
//! upsamples, as in Jimenez's "Next Generation Post Processing in Call of
//! Duty: Advanced Warfare" (2014): each halving of the size doubles the
//! reach of a fixed small filter, so a wide blur costs little.

use common::chapter::{FILTERABLE, sampler_entry, texture_entry, uniform_entry};
use common::wgpu::util::DeviceExt as _;
use common::{Drawn, Gpu, PassCount, PassTimer, Reloadable, ShaderError, ShaderFile, fullscreen, shader, wgpu};

/// The name the chain's passes are timed and counted by, as one.
const CHAIN: &str = "bloom chain";

/// What the overlay changes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BloomSettings {
    /// Light whose largest channel is below this does not bloom.
    pub threshold: f32,
    /// Width of the soft knee around the threshold, so that the cut is not hard.
    pub knee: f32,
    /// How much of the blurred light is added back.
    pub strength: f32,
    /// How much each coarser level weighs against the finer one on the way
    /// up (0 a tight glow, 1 all wide haze). Any value keeps the energy.
    pub spread: f32,
}

impl BloomSettings {
    /// What the chapter starts with.
    pub const DEFAULT: Self = Self { threshold: 1.0, knee: 0.5, strength: 0.6, spread: 0.6 };
}

impl Default for BloomSettings {
    fn default() -> Self {
        Self::DEFAULT
    }
}

// ANCHOR: bright
impl BloomSettings {
    /// The part of a colour that blooms: none below the threshold, all of
    /// the excess above it, and a quadratic knee between (as in Unreal's
    /// and Unity's bloom). Scales the colour, so hue is kept. The shader's
    /// `bright_part` is the same formula.
    pub fn bright_part(&self, rgb: [f32; 3]) -> [f32; 3] {
        let brightness = rgb[0].max(rgb[1]).max(rgb[2]);
        let soft = (brightness - self.threshold + self.knee).clamp(0.0, 2.0 * self.knee);
        let soft = soft * soft / (4.0 * self.knee + 1e-5);
        let weight = soft.max(brightness - self.threshold) / brightness.max(1e-5);
        rgb.map(|c| c * weight)
    }
}
// ANCHOR_END: bright

/// `Params` in bloom.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Params {
    threshold: f32,
    knee: f32,
    /// 1 for the first pass, which also takes out the bright part.
    prefilter: u32,
    _padding: u32,
}

fn bloom_shader() -> ShaderFile {
    shader!("lighting/bloom.wgsl", imports: ["common/fullscreen.wgsl"])
}

// ANCHOR: downsample_taps
/// The 13 bilinear taps of `fs_downsample` in bloom.wgsl, which makes every
/// level after the first: (offset in texels of the level it reads, weight).
/// Each tap lands where four texels meet and averages them, so the taps
/// form five overlapping 2 × 2 boxes: the middle one, of the four inner
/// taps, weighs 1/2, and the four corner boxes 1/8 each. The weights sum
/// to 1. For the book's figure; a test holds it to the shader.
pub const DOWNSAMPLE_TAPS: [([f32; 2], f32); 13] = [
    ([0.0, 0.0], 0.125),
    ([-1.0, -1.0], 0.125),
    ([1.0, -1.0], 0.125),
    ([-1.0, 1.0], 0.125),
    ([1.0, 1.0], 0.125),
    ([-2.0, -2.0], 0.03125),
    ([2.0, -2.0], 0.03125),
    ([-2.0, 2.0], 0.03125),
    ([2.0, 2.0], 0.03125),
    ([0.0, -2.0], 0.0625),
    ([-2.0, 0.0], 0.0625),
    ([2.0, 0.0], 0.0625),
    ([0.0, 2.0], 0.0625),
];
// ANCHOR_END: downsample_taps

/// The most halvings; beyond six, a 1280-wide picture's blur is already
/// wider than a tenth of the screen.
pub const MAX_LEVELS: usize = 6;

/// Sizes of the chain's levels for a `width` × `height` picture: half, a
/// quarter… never below one texel, whatever the window's size (a window
/// resized to 1 × 1 still has a valid chain of one 1 × 1 level).
pub fn level_sizes(width: u32, height: u32) -> Vec<(u32, u32)> {
    let mut sizes = vec![((width / 2).max(1), (height / 2).max(1))];
    while sizes.len() < MAX_LEVELS {
        let (w, h) = *sizes.last().expect("the first level exists");
        if w < 4 || h < 4 {
            break;
        }
        sizes.push((w / 2, h / 2));
    }
    sizes
}

struct Level {
    view: wgpu::TextureView,
    /// Reading this level (as the source of the next pass).
    read: wgpu::BindGroup,
    size: (u32, u32),
}

// ANCHOR: piece
/// The bloom chain for pictures of one size.
pub struct Bloom {
    /// `Rg11b10Ufloat` where the adapter can render to it (4 bytes a texel),
    /// else `Rgba16Float` (8).
    pub format: wgpu::TextureFormat,
    levels: Vec<Level>,
    params: [wgpu::Buffer; 2],
    layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    /// Downsample and upsample, made again when bloom.wgsl is saved (hot reload).
    pipelines: Reloadable<(wgpu::RenderPipeline, wgpu::RenderPipeline)>,
}
// ANCHOR_END: piece

impl Bloom {
    /// The device features the bloom can use if the adapter has them.
    pub const OPTIONAL_FEATURES: wgpu::Features = wgpu::Features::RG11B10UFLOAT_RENDERABLE;

    pub fn new(gpu: &Gpu, width: u32, height: u32) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let format = if device.features().contains(wgpu::Features::RG11B10UFLOAT_RENDERABLE) {
            wgpu::TextureFormat::Rg11b10Ufloat
        } else {
            wgpu::TextureFormat::Rgba16Float
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("bloom"),
            entries: &[
                texture_entry(0, FILTERABLE),
                sampler_entry(1),
                uniform_entry(2, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<Params>()),
            ],
        });
        let params = [0, 1].map(|prefilter| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("bloom params"),
                contents: bytemuck::bytes_of(&Params { threshold: 1.0, knee: 0.5, prefilter, _padding: 0 }),
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            })
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("bloom"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("bloom"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &pipeline_layout, format))?;
        let mut bloom = Self { format, levels: Vec::new(), params, layout, sampler, pipelines };
        bloom.resize(device, width, height);
        Ok(bloom)
    }

    fn pipelines(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<(wgpu::RenderPipeline, wgpu::RenderPipeline), ShaderError> {
        let module = bloom_shader().module(gpu)?;
        // Upsampling blends into the level below: result = up × spread + level × (1 − spread).
        let mix = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::Constant,
            dst_factor: wgpu::BlendFactor::OneMinusConstant,
            operation: wgpu::BlendOperation::Add,
        };
        let blended = wgpu::ColorTargetState {
            format,
            blend: Some(wgpu::BlendState { color: mix, alpha: mix }),
            write_mask: wgpu::ColorWrites::ALL,
        };
        gpu.catch_validation(|| {
            (
                fullscreen::pipeline(&gpu.device, "bloom down", layout, &module, "fs_downsample", format.into(), None),
                fullscreen::pipeline(&gpu.device, "bloom up", layout, &module, "fs_upsample", blended, None),
            )
        })
        .map_err(ShaderError)
    }

    /// Makes the chain's textures for pictures of `width` × `height`.
    pub fn resize(&mut self, device: &wgpu::Device, width: u32, height: u32) {
        self.levels = level_sizes(width, height)
            .into_iter()
            .map(|size| {
                let view = device
                    .create_texture(&wgpu::TextureDescriptor {
                        label: Some("bloom level"),
                        size: wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 },
                        mip_level_count: 1,
                        sample_count: 1,
                        dimension: wgpu::TextureDimension::D2,
                        format: self.format,
                        usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                            | wgpu::TextureUsages::TEXTURE_BINDING
                            | wgpu::TextureUsages::COPY_SRC,
                        view_formats: &[],
                    })
                    .create_view(&Default::default());
                let read = self.read_group(device, &view, 0);
                Level { view, read, size }
            })
            .collect();
    }

    fn read_group(&self, device: &wgpu::Device, view: &wgpu::TextureView, params: usize) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("bloom read"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&self.sampler) },
                wgpu::BindGroupEntry { binding: 2, resource: self.params[params].as_entire_binding() },
            ],
        })
    }

    /// The blurred bright light, half the picture's size: add it back
    /// (times `BloomSettings::strength`) before tone mapping.
    pub fn output(&self) -> &wgpu::TextureView {
        &self.levels[0].view
    }

    /// The chain's level sizes, largest first.
    pub fn sizes(&self) -> Vec<(u32, u32)> {
        self.levels.iter().map(|l| l.size).collect()
    }

    // ANCHOR: render
    /// Records the chain: the bright part of `source` (an HDR picture of
    /// the size given to `new` or `resize`) downsampled level by level, then
    /// upsampled back, each level blended into the one above. Timed as one
    /// span, "bloom chain", and counted as one: a full-screen triangle a
    /// pass.
    pub fn render(
        &self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        source: &wgpu::TextureView,
        settings: &BloomSettings,
    ) -> PassCount {
        let params = Params { threshold: settings.threshold, knee: settings.knee.max(1e-4), prefilter: 1, _padding: 0 };
        gpu.queue.write_buffer(&self.params[1], 0, bytemuck::bytes_of(&params));
        let first = self.read_group(&gpu.device, source, 1);
        let (downsample, upsample) = self.pipelines.get();
        let passes = 2 * self.levels.len() - 1;
        let mut index = 0;
        let mut drawn = Drawn::NOTHING;
        // Down: source → level 0 (taking out the bright part), level i → level i + 1.
        for (i, level) in self.levels.iter().enumerate() {
            let input = if i == 0 { &first } else { &self.levels[i - 1].read };
            let mut pass = self.pass(encoder, timer, &level.view, index, passes, true);
            pass.set_pipeline(&downsample);
            pass.set_bind_group(0, input, &[]);
            pass.draw(0..3, 0..1);
            drawn += Drawn::FULL_SCREEN;
            index += 1;
        }
        // Up: level i + 1 → blended into level i, from the smallest.
        for i in (0..self.levels.len() - 1).rev() {
            let mut pass = self.pass(encoder, timer, &self.levels[i].view, index, passes, false);
            pass.set_pipeline(&upsample);
            pass.set_blend_constant(wgpu::Color {
                r: f64::from(settings.spread),
                g: f64::from(settings.spread),
                b: f64::from(settings.spread),
                a: f64::from(settings.spread),
            });
            pass.set_bind_group(0, &self.levels[i + 1].read, &[]);
            pass.draw(0..3, 0..1);
            drawn += Drawn::FULL_SCREEN;
            index += 1;
        }
        PassCount { pass: CHAIN, drawn }
    }
    // ANCHOR_END: render

    fn pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        timer: &PassTimer,
        target: &wgpu::TextureView,
        index: usize,
        passes: usize,
        clear: bool,
    ) -> wgpu::RenderPass<'e> {
        let load = if clear { wgpu::LoadOp::Clear(wgpu::Color::BLACK) } else { wgpu::LoadOp::Load };
        encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("bloom"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
            })],
            timestamp_writes: timer.chain(CHAIN, index, passes),
            ..Default::default()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_halve_and_never_reach_zero() {
        assert_eq!(level_sizes(1280, 720), vec![(640, 360), (320, 180), (160, 90), (80, 45), (40, 22), (20, 11)]);
        assert_eq!(level_sizes(1, 1), vec![(1, 1)]);
        assert_eq!(level_sizes(7, 3), vec![(3, 1)]);
        for (w, h) in [(1, 900), (900, 1), (2, 2), (9, 9)] {
            assert!(level_sizes(w, h).iter().all(|&(a, b)| a > 0 && b > 0));
        }
    }

    #[test]
    fn the_downsample_taps_are_the_shaders_and_keep_the_light() {
        let weight = |offset: [f32; 2]| DOWNSAMPLE_TAPS.iter().find(|(o, _)| *o == offset).map(|(_, w)| *w).unwrap();
        let total: f32 = DOWNSAMPLE_TAPS.iter().map(|(_, w)| w).sum();
        assert_eq!(total, 1.0);
        // Taps of one kind (centre, inner, corners, sides) weigh the same, as
        // the shader sums each kind before weighting it.
        for (offset, w) in DOWNSAMPLE_TAPS {
            let [x, y] = offset.map(f32::abs);
            let kind = if x == y { [x, y] } else { [0.0, 2.0] };
            assert_eq!(w, weight(kind), "{offset:?}");
        }
        let line = format!(
            "centre * {} + inner * {} + corners * {} + sides * {}",
            weight([0.0, 0.0]),
            weight([1.0, 1.0]),
            weight([2.0, 2.0]),
            weight([0.0, 2.0])
        );
        let shader = bloom_shader().embedded;
        assert!(shader.contains(&line), "bloom.wgsl no longer weighs its taps as {line}");
        let downsample =
            &shader[shader.find("fn fs_downsample").unwrap()..shader.find("ANCHOR_END: downsample").unwrap()];
        for ([x, y], _) in DOWNSAMPLE_TAPS {
            let tap = format!("tap(uv, texel, {x:?}, {y:?})");
            assert!(downsample.contains(&tap), "fs_downsample has no {tap}");
        }
        assert_eq!(downsample.matches("tap(uv, texel,").count(), DOWNSAMPLE_TAPS.len());
    }

    #[test]
    fn only_light_above_the_threshold_blooms() {
        let settings = BloomSettings::default();
        assert_eq!(settings.bright_part([0.0; 3]), [0.0; 3]);
        assert_eq!(settings.bright_part([0.4, 0.3, 0.2]), [0.0; 3], "below the knee: nothing");
        let bright = settings.bright_part([4.0, 2.0, 1.0]);
        assert!(
            (bright[0] - 3.0).abs() < 1e-4 && (bright[1] - 1.5).abs() < 1e-4,
            "the excess, in the same hue: {bright:?}"
        );
        let knee = settings.bright_part([1.0, 1.0, 1.0])[0];
        assert!(knee > 0.0 && knee < 0.2, "a soft start at the threshold: {knee}");
    }
}
