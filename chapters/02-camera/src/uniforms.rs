//! The camera and the objects as the shaders see them, and one buffer for
//! every object's uniforms, each picked per draw by a dynamic offset.

use common::wgpu;

// ANCHOR: uniforms
/// The camera as the shader sees it (`Camera` in scene.wgsl).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct CameraUniform {
    pub view_proj: [[f32; 4]; 4],
    pub eye: [f32; 4],
}

/// One object's transform and colour (`Object` in scene.wgsl).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ObjectUniform {
    pub model: [[f32; 4]; 4],
    pub normal_matrix: [[f32; 4]; 4],
    pub color: [f32; 4],
}
// ANCHOR_END: uniforms

// ANCHOR: dynamic_offsets
/// Every object's uniforms live in one buffer, each at a multiple of the
/// device's `min_uniform_buffer_offset_alignment` (256 bytes on most GPUs,
/// though `ObjectUniform` is 144), and a dynamic offset picks one per draw.
pub fn object_stride(device: &wgpu::Device) -> u32 {
    let size = std::mem::size_of::<ObjectUniform>() as u32;
    size.next_multiple_of(device.limits().min_uniform_buffer_offset_alignment)
}
// ANCHOR_END: dynamic_offsets

/// The layout of a bind group holding one uniform buffer of `size` bytes,
/// read by both stages; `dynamic` when a per-draw offset slides it.
pub fn uniform_layout(device: &wgpu::Device, label: &str, dynamic: bool, size: usize) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: dynamic,
                min_binding_size: wgpu::BufferSize::new(size as u64),
            },
            count: None,
        }],
    })
}
