//! Showing the depth buffer: a full-screen pass reads it, with a few
//! numbers (near, far, the distance shown as white, raw or linear), and
//! draws it as grey.

use common::wgpu;

/// The depth buffer, the numbers and a sampler: group 0 of `depth.wgsl`.
pub fn depth_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("depth view"),
        entries: &[
            wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    // Depth read as unfilterable floats (see depth.wgsl).
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            },
            wgpu::BindGroupLayoutEntry {
                binding: 1,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(16),
                },
                count: None,
            },
            wgpu::BindGroupLayoutEntry {
                binding: 2,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
                count: None,
            },
        ],
    })
}

/// The bind group that lets the full-screen pass read `depth`, with the
/// numbers in `params`. Made again whenever the depth buffer is.
pub fn depth_group(
    gpu: &common::Gpu,
    layout: &wgpu::BindGroupLayout,
    depth: &wgpu::TextureView,
    params: &wgpu::Buffer,
) -> wgpu::BindGroup {
    // Nearest is the default filter: each pixel reads exactly its texel.
    let nearest = gpu.device.create_sampler(&wgpu::SamplerDescriptor { label: Some("nearest"), ..Default::default() });
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("depth view"),
        layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(depth) },
            wgpu::BindGroupEntry { binding: 1, resource: params.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&nearest) },
        ],
    })
}
