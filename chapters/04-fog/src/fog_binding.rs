//! The fog on the GPU: its uniform and bind group (group 1 of `fog.wgsl`),
//! and the terrain shader that reads it, for this chapter and for later
//! ones whose objects stand in the same air.

use common::chapter::uniform_entry;
use common::wgpu::util::DeviceExt as _;
use common::{ShaderFile, shader, wgpu};
use terrain::SKY;

use crate::fog_settings::FogSettings;

/// `Fog` in fog.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FogUniform {
    colour: [f32; 4],
    density: f32,
    gradient: f32,
    _padding: [f32; 2],
}

/// The terrain shader with fog (`fog.wgsl`, importing `terrain.wgsl`).
pub fn fog_shader() -> ShaderFile {
    shader!("fog/fog.wgsl", imports: ["terrain/terrain.wgsl"])
}

/// The fog uniform and its bind group (group 1 of fog.wgsl), for this
/// chapter and for later ones whose objects stand in the same air.
pub struct FogBinding {
    pub layout: wgpu::BindGroupLayout,
    buffer: wgpu::Buffer,
    pub group: wgpu::BindGroup,
}

impl FogBinding {
    pub fn new(device: &wgpu::Device) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("fog"),
            entries: &[uniform_entry(0, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<FogUniform>())],
        });
        let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("fog"),
            contents: &[0; std::mem::size_of::<FogUniform>()],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("fog"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
        });
        Self { layout, buffer, group }
    }

    /// Writes `settings`, with the clear colour `SKY` as the fog colour.
    pub fn write(&self, queue: &wgpu::Queue, settings: FogSettings) {
        self.write_with_colour(queue, settings, [SKY.r as f32, SKY.g as f32, SKY.b as f32]);
    }

    /// Writes `settings` with fog of `colour` (linear RGB), for skies that change.
    pub fn write_with_colour(&self, queue: &wgpu::Queue, settings: FogSettings, colour: [f32; 3]) {
        let fog = FogUniform {
            colour: [colour[0], colour[1], colour[2], 1.0],
            density: settings.density,
            gradient: settings.gradient,
            _padding: [0.0; 2],
        };
        queue.write_buffer(&self.buffer, 0, bytemuck::bytes_of(&fog));
    }
}
