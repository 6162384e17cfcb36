//! Post-process anti-aliasing: FXAA (Lottes 2009), a pass over the
//! finished picture that finds edges by the contrast between a pixel and
//! its neighbours and blends across them. It works on any picture, whatever
//! drew it, for the cost of one full-screen pass; what it cannot know is
//! where an edge really runs inside a pixel, so it guesses from the
//! staircase, and it softens whatever looks like an edge: a thin line, text.
//! [`crate::PostChain`] runs it last when the frame asks for it
//! ([`common::Frame::antialiasing`]).

use common::chapter::{FILTERABLE, sampler_entry, texture_entry};
use common::{Drawn, Frame, Gpu, Reloadable, ShaderError, fullscreen, shader, wgpu};

// ANCHOR: fxaa
/// The FXAA pass. In: a picture in the target's format, given as an
/// [`Fxaa::input`]; out: the same picture, edges blended, in `frame.target`.
pub struct Fxaa {
    layout: wgpu::BindGroupLayout,
    /// Made again when fxaa.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    sampler: wgpu::Sampler,
}

impl Fxaa {
    /// The pass into targets of `format`.
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("fxaa"),
            entries: &[texture_entry(0, FILTERABLE), sampler_entry(1)],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("fxaa"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| {
            let module = shader!("lighting/fxaa.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
            gpu.catch_validation(|| {
                fullscreen::pipeline(&gpu.device, "fxaa", &pipeline_layout, &module, "fs_fxaa", format.into(), None)
            })
            .map_err(ShaderError)
        })?;
        // Bilinear: the pass reads between pixels, and the blend is that
        // read (half a pixel across an edge is half of each side).
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("fxaa"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Ok(Self { layout, pipeline, sampler })
    }

    /// What the pass reads: `picture`, a single-sampled texture of the
    /// target's format.
    pub fn input(&self, device: &wgpu::Device, picture: &wgpu::TextureView) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("fxaa"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(picture) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&self.sampler) },
            ],
        })
    }

    /// Draws `input`'s picture into `frame.target` with its edges blended;
    /// counted in `frame.drawn` as "fxaa".
    pub fn draw(&self, frame: &mut Frame, input: &wgpu::BindGroup) {
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "fxaa", frame.target, None);
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(0, input, &[]);
        pass.draw(0..3, 0..1);
        frame.drawn.add("fxaa", Drawn::FULL_SCREEN);
    }
}
// ANCHOR_END: fxaa
