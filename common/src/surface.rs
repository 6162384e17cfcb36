//! How a window's (or a canvas's) surface is set up, shared by the window
//! runner and the browser's still picture: the formats the chapter and the
//! overlay draw in, and presenting in step with the display.

use anyhow::anyhow;

use crate::Gpu;

// ANCHOR: surface
/// How a window's (or canvas's) surface is set up, as (configuration, the
/// format chapters draw in, the overlay's format).
pub(crate) fn surface_config(
    gpu: &Gpu,
    surface: &wgpu::Surface,
    width: u32,
    height: u32,
) -> anyhow::Result<(wgpu::SurfaceConfiguration, wgpu::TextureFormat, wgpu::TextureFormat)> {
    let caps = surface.get_capabilities(&gpu.adapter);
    let first = caps
        .formats
        .first()
        .copied()
        .ok_or_else(|| anyhow!("{} cannot draw into this window (it offers no surface formats)", gpu.describe()))?;
    // Chapters output linear colour and let an sRGB view encode it;
    // WebGPU canvases are never sRGB, but can be viewed as sRGB.
    let srgb = caps.formats.iter().copied().find(|f| f.is_srgb());
    let views = gpu.downlevel().flags.contains(wgpu::DownlevelFlags::SURFACE_VIEW_FORMATS);
    let (format, scene_format, overlay_format) = match srgb {
        // WebGL2 cannot view a surface in another format: the overlay
        // draws into the sRGB surface as it is (egui handles both).
        Some(srgb) if !views => (srgb, srgb, srgb),
        Some(srgb) => (srgb, srgb, srgb.remove_srgb_suffix()),
        None if views => (first, first.add_srgb_suffix(), first),
        // Nothing encodes sRGB here: pictures come out too dark, but come out.
        None => (first, first, first),
    };
    let config = wgpu::SurfaceConfiguration {
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        format,
        width: width.max(1),
        height: height.max(1),
        // Fifo is always there and waits for vsync; lavapipe lists
        // Immediate first, which would spin the CPU for nothing.
        present_mode: wgpu::PresentMode::Fifo,
        desired_maximum_frame_latency: 2,
        alpha_mode: wgpu::CompositeAlphaMode::Auto,
        color_space: Default::default(),
        view_formats: [scene_format, overlay_format].into_iter().filter(|f| *f != format).collect(),
    };
    Ok((config, scene_format, overlay_format))
}
// ANCHOR_END: surface
