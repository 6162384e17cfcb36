//! Passes that shade every pixel of a target once: debug views, the sky,
//! post-processing. The vertex half is `shaders/common/fullscreen.wgsl`;
//! a shader imports it and wraps `fullscreen_triangle` in a `vs_fullscreen`
//! entry point (naga_oil keeps no entry points from imported modules).

/// The WGSL module, for `shader!(…, imports: [...])` lists: import it as
/// `"common/fullscreen.wgsl"`.
pub const MODULE: &str = "common/fullscreen.wgsl";

/// A pipeline that runs `vs_fullscreen` and `fragment_entry` of `module`
/// over the whole target: no vertex buffers, no culling, one sample a pixel.
pub fn pipeline(
    device: &wgpu::Device,
    label: &str,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    fragment_entry: &str,
    target: wgpu::ColorTargetState,
    depth_stencil: Option<wgpu::DepthStencilState>,
) -> wgpu::RenderPipeline {
    let pipeline = Pipeline { label, layout, module, fragment_entry, target, depth_stencil };
    multisampled_pipeline(device, pipeline, Default::default())
}

/// [`pipeline`]'s arguments bar the device, for [`multisampled_pipeline`].
pub struct Pipeline<'a> {
    pub label: &'a str,
    pub layout: &'a wgpu::PipelineLayout,
    pub module: &'a wgpu::ShaderModule,
    pub fragment_entry: &'a str,
    pub target: wgpu::ColorTargetState,
    pub depth_stencil: Option<wgpu::DepthStencilState>,
}

/// [`pipeline`] for a pass of `multisample`'s samples a pixel
/// ([`crate::SceneTargets::multisample`]): a background drawn inside a
/// multisampled scene pass (chapter 08's sky, chapter 11's atmosphere).
pub fn multisampled_pipeline(
    device: &wgpu::Device,
    Pipeline { label, layout, module, fragment_entry, target, depth_stencil }: Pipeline<'_>,
    multisample: wgpu::MultisampleState,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_fullscreen"),
            buffers: &[],
            compilation_options: Default::default(),
        },
        primitive: Default::default(),
        depth_stencil,
        multisample,
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fragment_entry),
            targets: &[Some(target)],
            compilation_options: Default::default(),
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Begins a pass that draws over `target`: cleared to `clear`, or kept as it
/// is with `None` (to draw on top of what a pass before left there).
pub fn pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    timer: &crate::PassTimer,
    label: &'static str,
    target: &wgpu::TextureView,
    clear: Option<wgpu::Color>,
) -> wgpu::RenderPass<'e> {
    let load = clear.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear);
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: target,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
        })],
        timestamp_writes: timer.pass(label),
        ..Default::default()
    })
}
