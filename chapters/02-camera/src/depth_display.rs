//! Showing the depth buffer: a full-screen pass reads it, with a few
//! numbers (near, far, the distance shown as white, raw or linear), and
//! draws it as grey.

use common::wgpu::util::DeviceExt as _;
use common::{Camera, Gpu, wgpu};

/// The distance the depth view shows as white, in metres.
pub const WHITE_AT: f32 = 25.0;

/// What the depth views need on the GPU: their numbers, and the bind group
/// that lets the full-screen pass read the depth buffer with them.
pub struct DepthDisplay {
    params: wgpu::Buffer,
    layout: wgpu::BindGroupLayout,
    group: wgpu::BindGroup,
}

impl DepthDisplay {
    /// Reads `depth`, a single-sampled depth buffer.
    pub fn new(gpu: &Gpu, depth: &wgpu::TextureView) -> Self {
        let layout = depth_group_layout(&gpu.device);
        let params = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("depth view"),
            contents: &[0; 16],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let group = depth_group(gpu, &layout, depth, &params);
        Self { params, layout, group }
    }

    /// The depth view pipeline's layout: this bind group alone.
    pub fn pipeline_layout(&self, device: &wgpu::Device) -> wgpu::PipelineLayout {
        device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("depth view"),
            bind_group_layouts: &[Some(&self.layout)],
            immediate_size: 0,
        })
    }

    /// Reads `depth` from now on: the depth buffer is made again with the
    /// picture's size.
    pub fn read(&mut self, gpu: &Gpu, depth: &wgpu::TextureView) {
        self.group = depth_group(gpu, &self.layout, depth, &self.params);
    }

    /// Writes the numbers for `camera`: its near and far planes, the
    /// distance shown as white, and whether to show the stored value
    /// (`raw`) or the distance.
    pub fn write(&self, queue: &wgpu::Queue, camera: &Camera, raw: bool) {
        let params = [camera.near, camera.far, WHITE_AT, f32::from_bits(u32::from(raw))];
        queue.write_buffer(&self.params, 0, bytemuck::cast_slice(&params));
    }

    /// The bind group for the full-screen pass (group 0 of `depth.wgsl`).
    pub fn group(&self) -> &wgpu::BindGroup {
        &self.group
    }
}

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

// ANCHOR: depth_group
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
// ANCHOR_END: depth_group
