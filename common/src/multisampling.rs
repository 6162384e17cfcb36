//! Multisampling (MSAA): the scene is drawn into a picture that keeps
//! several samples a pixel, and the pass ends by resolving them, averaging
//! each pixel's samples into the single-sampled picture the next step
//! reads. A triangle's coverage is tested at every sample, its fragment
//! shader runs once a pixel, so an edge gets as many shades as there are
//! samples for about the cost of the extra memory. Chapter 02 explains it;
//! every chapter draws its scene through [`SceneTargets`].

use std::sync::Mutex;

use crate::Gpu;
use crate::texture::DEPTH_FORMAT;

/// The colour target a chapter draws into: the window's surface or an
/// offscreen texture. Pipelines are built for `format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Target {
    pub format: wgpu::TextureFormat,
    pub width: u32,
    pub height: u32,
    /// Samples a pixel asked for the scene (multisampling, chapter 02):
    /// [`SAMPLES`], or 1 for none. The chapter's
    /// [`SceneTargets`] grants it where the adapter can, and its pipelines
    /// draw with what it granted.
    pub samples: u32,
}

impl Target {
    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height.max(1) as f32
    }
}

/// The sample count the chapters ask for: WebGPU guarantees 4 for the
/// usual colour formats and for depth, and WebGL2 allows at least 4.
pub const SAMPLES: u32 = 4;

/// How edges are smoothed: `--antialiasing`, and the overlay's switch.
/// Multisampling is chapter 02's; the post-process pass (FXAA) is chapter
/// 08's, run by the post chain that chapters 08 to 11 share, so only they
/// offer [`Antialiasing::Post`] and [`Antialiasing::Both`]
/// ([`crate::Chapter::POST_ANTIALIASING`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Antialiasing {
    /// One sample a pixel: every edge a staircase.
    Off,
    /// [`SAMPLES`] samples a pixel, resolved at the end of the scene pass.
    #[default]
    Msaa,
    /// One sample a pixel, then a pass over the finished picture that
    /// finds its edges and blends across them (FXAA, chapter 08).
    Post,
    /// Multisampling, then the post-process pass as well.
    Both,
}

impl Antialiasing {
    /// Every setting, in the overlay's order.
    pub const ALL: [Self; 4] = [Self::Off, Self::Msaa, Self::Post, Self::Both];

    /// The samples a pixel this asks for.
    pub const fn samples(self) -> u32 {
        match self {
            Self::Off | Self::Post => 1,
            Self::Msaa | Self::Both => SAMPLES,
        }
    }

    /// Whether the finished picture goes through the post-process pass.
    pub const fn post(self) -> bool {
        matches!(self, Self::Post | Self::Both)
    }

    /// What the overlay's switch calls it.
    pub const fn label(self) -> &'static str {
        match self {
            Self::Off => "1 sample",
            Self::Msaa => "MSAA 4×",
            Self::Post => "FXAA",
            Self::Both => "both",
        }
    }

    /// The settings a chapter offers: all four with a post chain, else
    /// the two without the post-process pass.
    pub fn offered(post_chain: bool) -> impl Iterator<Item = Self> {
        Self::ALL.into_iter().filter(move |a| post_chain || !a.post())
    }
}

/// `asked` if the adapter can multisample both `format` and the depth
/// format with that many samples, else 1 (the GL backend cannot for some
/// formats); the overlay says so.
pub fn samples_for(adapter: &wgpu::Adapter, format: wgpu::TextureFormat, asked: u32) -> u32 {
    let supports = |format| adapter.get_texture_format_features(format).flags.sample_count_supported(asked);
    if asked > 1 && supports(format) && supports(DEPTH_FORMAT) { asked } else { 1 }
}

/// The pipeline state for drawing into a pass of `samples` samples a pixel.
pub fn multisample(samples: u32) -> wgpu::MultisampleState {
    wgpu::MultisampleState { count: samples, ..Default::default() }
}

// ANCHOR: scene_targets
/// What a scene is drawn into before it reaches its picture: a colour
/// buffer of [`Target::samples`] samples a pixel (none at 1 sample, where
/// the scene is drawn into the picture itself) and a depth buffer of as
/// many. In: the target's size, format and sample count; out: each pass
/// [`SceneTargets::pass`] begins ends in the picture it is given.
pub struct SceneTargets {
    samples: u32,
    /// The format the scene is drawn in, and its size.
    format: wgpu::TextureFormat,
    size: wgpu::Extent3d,
    device: wgpu::Device,
    /// The samples, until the pass resolves them; none at 1 sample. Made
    /// for the first picture they are resolved into, and again if a later
    /// one is a texture of another format (see [`SceneTargets::samples_resolved_into`]).
    colour: Mutex<Option<(wgpu::TextureFormat, wgpu::TextureView)>>,
    /// `None` for a scene drawn without a depth test (chapter 01).
    depth: Option<wgpu::TextureView>,
}

impl SceneTargets {
    /// Colour samples and a depth buffer for `target`: as many samples as
    /// it asks for where the adapter can multisample its format and
    /// depth, else one ([`SceneTargets::samples`] says which).
    pub fn new(gpu: &Gpu, target: Target) -> Self {
        Self::make(gpu, target, true)
    }

    /// [`SceneTargets::new`] without a depth buffer, for a scene drawn
    /// without a depth test.
    pub fn without_depth(gpu: &Gpu, target: Target) -> Self {
        Self::make(gpu, target, false)
    }

    fn make(gpu: &Gpu, target: Target, with_depth: bool) -> Self {
        let samples = samples_for(&gpu.adapter, target.format, target.samples.max(1));
        let size =
            wgpu::Extent3d { width: target.width.max(1), height: target.height.max(1), depth_or_array_layers: 1 };
        // A single-sampled depth buffer can be read as a texture (chapter
        // 02's depth view) or copied out (chapter 08's stats); a
        // multisampled one would need a shader of its own, so views that
        // read depth draw with one sample instead (a resolved depth is not
        // a depth: chapter 08's stats draw the city again to count).
        let readable = if samples == 1 {
            wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC
        } else {
            wgpu::TextureUsages::empty()
        };
        let depth = with_depth.then(|| {
            gpu.device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some("depth"),
                    size,
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format: DEPTH_FORMAT,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT | readable,
                    view_formats: &[],
                })
                .create_view(&Default::default())
        });
        Self { samples, format: target.format, size, device: gpu.device.clone(), colour: Mutex::new(None), depth }
    }

    /// The samples for a pass resolved into `picture`. They are stored in
    /// the format of `picture`'s texture and seen in the scene's: a WebGPU
    /// canvas is a plain `bgra8unorm` texture that the scene draws into
    /// through an sRGB view, and a resolve between textures of different
    /// formats is left to each API, which do not agree (Vulkan's gives
    /// darker pictures: gpuweb issue 2729).
    fn samples_resolved_into(&self, picture: &wgpu::TextureView) -> wgpu::TextureView {
        let stored = picture.texture().format();
        let mut colour = self.colour.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((format, view)) = &*colour
            && *format == stored
        {
            return view.clone();
        }
        let view_formats: &[wgpu::TextureFormat] = if stored == self.format { &[] } else { &[self.format] };
        let view = self
            .device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("samples"),
                size: self.size,
                mip_level_count: 1,
                sample_count: self.samples,
                dimension: wgpu::TextureDimension::D2,
                format: stored,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats,
            })
            .create_view(&wgpu::TextureViewDescriptor { format: Some(self.format), ..Default::default() });
        *colour = Some((stored, view.clone()));
        view
    }

    // ANCHOR_END: scene_targets

    /// Samples a pixel: what every pipeline drawing in these passes must say.
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// The pipeline state for drawing into these targets.
    pub fn multisample(&self) -> wgpu::MultisampleState {
        multisample(self.samples)
    }

    /// The depth buffer (single-sampled, and readable, at 1 sample).
    pub fn depth(&self) -> Option<&wgpu::TextureView> {
        self.depth.as_ref()
    }

    /// The colour attachment's view and resolve target for a pass that
    /// ends in `picture`: the samples, resolved into `picture`, or at one
    /// sample `picture` itself (for a pass written out in full: chapter 01).
    pub fn colour_attachment<'a>(
        &self,
        picture: &'a wgpu::TextureView,
    ) -> (wgpu::TextureView, Option<&'a wgpu::TextureView>) {
        if self.samples == 1 { (picture.clone(), None) } else { (self.samples_resolved_into(picture), Some(picture)) }
    }

    /// Begins a pass that ends in `picture`: cleared to `clear` and depth
    /// to the far plane, or with `None` kept as the last pass left both (to
    /// draw on top). With several samples the pass draws into the samples
    /// and resolves them into `picture` when it ends; the samples are kept
    /// for a pass that goes on drawing.
    pub fn pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        timer: &crate::PassTimer,
        label: &'static str,
        picture: &wgpu::TextureView,
        clear: Option<wgpu::Color>,
    ) -> wgpu::RenderPass<'e> {
        let (view, resolve_target) = self.colour_attachment(picture);
        let (load, depth_load) = match clear {
            Some(colour) => (wgpu::LoadOp::Clear(colour), wgpu::LoadOp::Clear(1.0)),
            None => (wgpu::LoadOp::Load, wgpu::LoadOp::Load),
        };
        encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(label),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: self.depth.as_ref().map(|view| wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: Some(wgpu::Operations { load: depth_load, store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: timer.pass(label),
            ..Default::default()
        })
    }
}
