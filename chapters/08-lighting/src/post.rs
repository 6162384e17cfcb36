//! Post-processing: from the HDR picture a scene is drawn into to the frame
//! on the screen. One piece, [`PostChain`], owns the steps: the
//! [`HdrTarget`] (colour in 16-bit floats, drawn with several samples a
//! pixel and resolved, and depth), the [`Bloom`] chain
//! over its bright parts, the [`ToneMap`] that adds the bloom, exposes
//! and tone-maps, and, when the frame asks for it, the [`Fxaa`] pass that
//! smooths the finished picture's edges. Made with the target, resized
//! with it; each frame the scene is drawn into [`PostChain::hdr`] and
//! [`PostChain::finish`] turns it into what [`PostSettings`] names.
//! Chapters 08 to 11 finish their frames with it.

use std::sync::OnceLock;

use common::chapter::{FILTERABLE, sampler_entry, texture_entry, uniform_entry};
use common::{Drawn, Frame, Gpu, Reloadable, SceneTargets, ShaderError, Target, fullscreen, shader, wgpu};

use crate::bloom::{Bloom, BloomSettings};
use crate::fxaa::Fxaa;

/// The HDR picture the scene is drawn into: its samples and depth buffer
/// ([`SceneTargets`], four samples a pixel unless the target asks for one
/// or the adapter cannot multisample [`HDR_FORMAT`]), and the picture they
/// are resolved into, which the bloom and the tone map read.
pub struct HdrTarget {
    /// The scene's samples and depth; every pipeline drawing in
    /// [`HdrTarget::pass`] says [`SceneTargets::multisample`].
    pub scene: SceneTargets,
    /// The resolved picture, one sample a pixel.
    pub colour: wgpu::TextureView,
}

/// 16-bit floats per channel: room for light far brighter than white.
pub const HDR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

impl HdrTarget {
    /// The HDR picture for `target`'s size and sample count.
    pub fn new(gpu: &Gpu, target: Target) -> Self {
        let (width, height) = (target.width.max(1), target.height.max(1));
        let colour = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("hdr"),
            size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: HDR_FORMAT,
            // Copied out only by tests, which read the light itself.
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let scene = SceneTargets::new(gpu, Target { format: HDR_FORMAT, ..target });
        Self { scene, colour: colour.create_view(&Default::default()) }
    }

    /// Begins the scene's pass: the samples cleared to `clear` and depth
    /// to the far plane, resolved into [`HdrTarget::colour`] at its end.
    pub fn pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        timer: &common::PassTimer,
        label: &'static str,
        clear: wgpu::Color,
    ) -> wgpu::RenderPass<'e> {
        self.scene.pass(encoder, timer, label, &self.colour, Some(clear))
    }

    /// The pipeline state for drawing in [`HdrTarget::pass`].
    pub fn multisample(&self) -> wgpu::MultisampleState {
        self.scene.multisample()
    }

    /// The depth buffer as data (chapter 08's stats, the tests), where it
    /// is one: at one sample a pixel. A multisampled depth buffer cannot be
    /// copied out, and no resolve makes it one depth a pixel (an average of
    /// an edge's depths is a depth of neither surface), so with several
    /// samples this is `None`.
    pub fn depth_texture(&self) -> Option<&wgpu::Texture> {
        (self.scene.samples() == 1).then(|| self.scene.depth().map(|view| view.texture())).flatten()
    }
}

// ANCHOR: output
/// What [`PostChain::finish`] puts in the target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PostOutput {
    /// The picture and its bloom, exposed and tone-mapped.
    Picture,
    /// The bloom alone, exposed and tone-mapped (black without bloom).
    BloomOnly,
    /// The HDR picture as it is, neither exposed nor tone-mapped: for
    /// pictures whose colours are data (a heat map, a tangent frame).
    RawHdr,
}

impl PostOutput {
    /// `Composite::mode` in tonemap.wgsl.
    fn shader_mode(self) -> u32 {
        match self {
            Self::Picture => 0,
            Self::BloomOnly => 1,
            Self::RawHdr => 2,
        }
    }
}

/// How a frame is finished.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PostSettings {
    pub output: PostOutput,
    /// The light is scaled by this before the tone curve.
    pub exposure: f32,
    /// The bloom, or `None` for none. [`PostOutput::RawHdr`] shows no
    /// bloom, and the chain is not run for it.
    pub bloom: Option<BloomSettings>,
}
// ANCHOR_END: output

// ANCHOR: post
/// The HDR target, the bloom over it, the tone map and the FXAA pass into
/// the frame's target, for pictures of one size. In: the scene, drawn into
/// [`PostChain::hdr`]; [`PostSettings`]; `frame.antialiasing`. Out: the
/// frame in `frame.target`.
pub struct PostChain {
    hdr: HdrTarget,
    bloom: Bloom,
    tone_map: ToneMap,
    fxaa: Fxaa,
    target: Target,
    /// The tone-mapped picture FXAA reads, made the first time a frame
    /// asks for FXAA (most frames do not), and again after a resize.
    tone_mapped: OnceLock<(wgpu::TextureView, wgpu::BindGroup)>,
}

impl PostChain {
    /// The device features the chain can use if the adapter has them.
    pub const OPTIONAL_FEATURES: wgpu::Features = Bloom::OPTIONAL_FEATURES;

    /// The chain for `target`: its size, and the format the frame ends in.
    pub fn new(gpu: &Gpu, target: Target) -> Result<Self, ShaderError> {
        let hdr = HdrTarget::new(gpu, target);
        let bloom = Bloom::new(gpu, target.width, target.height)?;
        let tone_map = ToneMap::new(gpu, target.format, &hdr.colour, bloom.output())?;
        let fxaa = Fxaa::new(gpu, target.format)?;
        Ok(Self { hdr, bloom, tone_map, fxaa, target, tone_mapped: OnceLock::new() })
    }

    /// Makes the pictures again for `target`'s size (its format stays the
    /// one given to `new`, and its samples a pixel too: the pipelines
    /// drawing into [`PostChain::hdr`] were made for them).
    pub fn resize(&mut self, gpu: &Gpu, target: Target) {
        let samples = self.hdr.scene.samples();
        self.hdr = HdrTarget::new(gpu, Target { samples, ..target });
        self.bloom.resize(&gpu.device, target.width, target.height);
        self.tone_map.set_inputs(&gpu.device, &self.hdr.colour, self.bloom.output());
        self.target = Target { samples, ..target };
        self.tone_mapped = OnceLock::new();
    }

    /// Where the scene is drawn: the HDR samples and depth buffer, and the
    /// colour they are resolved into.
    pub fn hdr(&self) -> &HdrTarget {
        &self.hdr
    }

    /// The bloom chain: its format and level sizes, and its last output.
    pub fn bloom(&self) -> &Bloom {
        &self.bloom
    }

    /// Records the end of the frame: the bloom over the HDR picture (if
    /// `settings` asks for it and the output shows it), then the tone map
    /// into `frame.target`, or, when `frame.antialiasing` asks for the
    /// post-process pass, into a picture of its own that FXAA reads and
    /// smooths into `frame.target`; each counted in `frame.drawn`. A raw
    /// HDR output is data, not a picture, and FXAA leaves it alone.
    pub fn finish(&self, gpu: &Gpu, frame: &mut Frame, settings: &PostSettings) {
        let bloom = settings.bloom.filter(|_| settings.output != PostOutput::RawHdr);
        if let Some(bloom) = &bloom {
            frame.drawn.extend([self.bloom.render(gpu, frame.encoder, frame.timer, &self.hdr.colour, bloom)]);
        }
        let strength = bloom.map_or(0.0, |b| b.strength);
        if !frame.antialiasing.post() || settings.output == PostOutput::RawHdr {
            let target = frame.target;
            self.tone_map.draw(gpu, frame, target, settings.exposure, strength, settings.output);
            return;
        }
        let (tone_mapped, fxaa_input) = self.tone_mapped.get_or_init(|| {
            let picture = self.picture(gpu, "tone mapped");
            let input = self.fxaa.input(&gpu.device, &picture);
            (picture, input)
        });
        self.tone_map.draw(gpu, frame, tone_mapped, settings.exposure, strength, settings.output);
        self.fxaa.draw(frame, fxaa_input);
    }

    /// A single-sampled picture of the target's size and format that a
    /// pass can draw into and the next read.
    fn picture(&self, gpu: &Gpu, label: &str) -> wgpu::TextureView {
        let Target { format, width, height, .. } = self.target;
        gpu.device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width: width.max(1), height: height.max(1), depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            })
            .create_view(&Default::default())
    }
}
// ANCHOR_END: post

// ANCHOR: aces_fit
/// Narkowicz's fit of the ACES filmic curve (2016), for one channel: the
/// same formula and constants as `aces` in tonemap.wgsl, here for the
/// book's plot of it and for the test that runs the real tone map pass
/// against it. The fit is already pre-exposed: 1 maps to about 0.8.
pub fn aces_fit(x: f32) -> f32 {
    ((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)).clamp(0.0, 1.0)
}
// ANCHOR_END: aces_fit

/// `Composite` in tonemap.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct CompositeUniform {
    exposure: f32,
    bloom_strength: f32,
    mode: u32,
    _padding: u32,
}

// ANCHOR: tonemap
/// From an HDR picture and its bloom to the screen: add the bloom, expose,
/// tone-map (ACES, Narkowicz's fit). Inputs: the two textures (given when
/// it is made, and again after a resize), exposure, bloom strength, what to
/// show; output: the target it draws into. The last step of [`PostChain`].
pub struct ToneMap {
    layout: wgpu::BindGroupLayout,
    /// Made again when tonemap.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    uniform: wgpu::Buffer,
    sampler: wgpu::Sampler,
    group: wgpu::BindGroup,
}

impl ToneMap {
    /// The tone map from `hdr` and `bloom` into targets of `format`.
    pub fn new(
        gpu: &Gpu,
        format: wgpu::TextureFormat,
        hdr: &wgpu::TextureView,
        bloom: &wgpu::TextureView,
    ) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("tone map"),
            entries: &[
                texture_entry(0, FILTERABLE),
                texture_entry(1, FILTERABLE),
                sampler_entry(2),
                uniform_entry(3, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<CompositeUniform>()),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("tone map"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &pipeline_layout, format))?;
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("composite"),
            size: std::mem::size_of::<CompositeUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("tone map"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let group = Self::group(device, &layout, &sampler, &uniform, hdr, bloom);
        Ok(Self { layout, pipeline, uniform, sampler, group })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!("lighting/tonemap.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        gpu.catch_validation(|| {
            fullscreen::pipeline(&gpu.device, "tone map", layout, &module, "fs_composite", format.into(), None)
        })
        .map_err(ShaderError)
    }

    fn group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        sampler: &wgpu::Sampler,
        uniform: &wgpu::Buffer,
        hdr: &wgpu::TextureView,
        bloom: &wgpu::TextureView,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("tone map"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(hdr) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(bloom) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(sampler) },
                wgpu::BindGroupEntry { binding: 3, resource: uniform.as_entire_binding() },
            ],
        })
    }

    /// Points the tone map at new inputs (the pictures made again after a resize).
    pub fn set_inputs(&mut self, device: &wgpu::Device, hdr: &wgpu::TextureView, bloom: &wgpu::TextureView) {
        self.group = Self::group(device, &self.layout, &self.sampler, &self.uniform, hdr, bloom);
    }

    /// Draws `output` into `into` (a picture of the format the tone map was
    /// made for), the bloom weighted by `bloom_strength` and the light
    /// scaled by `exposure`; counted in `frame.drawn` as "tone map".
    pub fn draw(
        &self,
        gpu: &Gpu,
        frame: &mut Frame,
        into: &wgpu::TextureView,
        exposure: f32,
        bloom_strength: f32,
        output: PostOutput,
    ) {
        let uniform = CompositeUniform { exposure, bloom_strength, mode: output.shader_mode(), _padding: 0 };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "tone map", into, None);
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(0, &self.group, &[]);
        pass.draw(0..3, 0..1);
        frame.drawn.add("tone map", Drawn::FULL_SCREEN);
    }
}
// ANCHOR_END: tonemap
