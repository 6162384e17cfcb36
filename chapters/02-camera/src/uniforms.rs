//! The camera and the objects as the shaders see them, and one buffer for
//! every object's uniforms, each picked per draw by a dynamic offset.

use common::glam::Mat4;
use common::{Camera, wgpu};

use crate::scene::{GROUND_COLOR, Placement, ground_model};

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

// ANCHOR: normal_matrix
impl ObjectUniform {
    /// An object's uniform: its model matrix, the normal matrix made from
    /// it (the inverse transpose, which keeps normals perpendicular to a
    /// surface scaled unevenly), and its colour.
    pub fn new(model: Mat4, color: [f32; 4]) -> Self {
        Self { model: model.to_cols_array_2d(), normal_matrix: model.inverse().transpose().to_cols_array_2d(), color }
    }
}
// ANCHOR_END: normal_matrix

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

/// The scene's uniforms on the GPU: the camera's buffer and bind group
/// (group 0), and one buffer holding the ground's and every object's
/// uniforms with the bind group that reads one of them (group 1).
pub struct SceneUniforms {
    camera_buffer: wgpu::Buffer,
    camera_group: wgpu::BindGroup,
    object_buffer: wgpu::Buffer,
    object_group: wgpu::BindGroup,
    /// Bytes between consecutive objects in `object_buffer`.
    object_stride: u32,
    /// The scene pipelines' layout: the camera's group, then an object's.
    pub pipeline_layout: wgpu::PipelineLayout,
}

impl SceneUniforms {
    /// Room for the ground and `objects` objects.
    pub fn new(device: &wgpu::Device, objects: usize) -> Self {
        let camera_layout = uniform_layout(device, "camera", false, std::mem::size_of::<CameraUniform>());
        let object_layout = uniform_layout(device, "object", true, std::mem::size_of::<ObjectUniform>());
        let camera_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("camera"),
            size: std::mem::size_of::<CameraUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let object_stride = object_stride(device);
        let object_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("objects"),
            size: u64::from(object_stride) * (objects as u64 + 1),
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let camera_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("camera"),
            layout: &camera_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: camera_buffer.as_entire_binding() }],
        });
        let object_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("objects"),
            layout: &object_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                // The binding is one object wide; the dynamic offset slides it.
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &object_buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<ObjectUniform>() as u64),
                }),
            }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("scene"),
            bind_group_layouts: &[Some(&camera_layout), Some(&object_layout)],
            immediate_size: 0,
        });
        Self { camera_buffer, camera_group, object_buffer, object_group, object_stride, pipeline_layout }
    }

    // ANCHOR: update_uniforms
    /// Writes the camera, the ground (slot 0) and every object at scene
    /// time `time` (slots 1 and on): two `write_buffer` calls a frame.
    pub fn write(&self, queue: &wgpu::Queue, camera: &Camera, objects: &[Placement], time: f32) {
        let camera = CameraUniform {
            view_proj: camera.view_projection().to_cols_array_2d(),
            eye: camera.position.extend(1.0).into(),
        };
        queue.write_buffer(&self.camera_buffer, 0, bytemuck::bytes_of(&camera));

        let stride = self.object_stride as usize;
        let mut bytes = vec![0u8; stride * (objects.len() + 1)];
        let ground = ObjectUniform::new(ground_model(), GROUND_COLOR);
        let placed =
            objects.iter().map(|o| ObjectUniform::new(o.model(time), [o.color[0], o.color[1], o.color[2], 0.0]));
        for (slot, object) in std::iter::once(ground).chain(placed).enumerate() {
            bytes[slot * stride..][..std::mem::size_of::<ObjectUniform>()].copy_from_slice(bytemuck::bytes_of(&object));
        }
        queue.write_buffer(&self.object_buffer, 0, &bytes);
    }
    // ANCHOR_END: update_uniforms

    // ANCHOR: bind
    /// Binds the camera (group 0) for the draws that follow.
    pub fn bind_camera(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &self.camera_group, &[]);
    }

    /// Binds slot `slot`'s uniforms (0 the ground, then the objects) for
    /// the next draw: the same bind group, slid along the buffer by a
    /// dynamic offset.
    pub fn bind_object(&self, pass: &mut wgpu::RenderPass<'_>, slot: usize) {
        pass.set_bind_group(1, &self.object_group, &[slot as u32 * self.object_stride]);
    }
    // ANCHOR_END: bind
}
