//! The rocks on the GPU: the meshes of their three levels of detail, every
//! rock's instance record grouped by terrain chunk, made once per terrain
//! and device and shared.

use std::sync::Arc;

use common::glam::{Vec3, Vec4};
use common::wgpu::util::DeviceExt as _;
use common::{Gpu, Mesh, wgpu};
use terrain::chunks::Aabb;
use terrain::heightfield::HeightField;

use crate::cameras::plain_camera;
use crate::rock_groups::{RockGroup, group_by_chunk};
use crate::rock_mesh::{LEVELS, box_centre, rock_levels};
use crate::rock_scatter::{RockInstance, SEED, rocks_on_map, scatter};

/// The most rocks drawn one call each (the comparison's uniform slots).
pub const MAX_ONE_PER_DRAW: u32 = 20_000;

// ANCHOR: rock_field
/// The rocks on the GPU: the rock's mesh at each level of detail, every
/// rock's instance record grouped by terrain chunk, and the first
/// `MAX_ONE_PER_DRAW` of them again, one per 256-byte uniform slot, for the
/// one-draw-per-rock comparison. Made once per terrain and device, and
/// shared (a million rocks take a moment to scatter).
pub struct RockField {
    /// The rock, finest first (`rock_levels`).
    pub(crate) levels: [Mesh; LEVELS],
    /// Every rock's record: a vertex buffer stepped per instance, and a
    /// storage buffer that the culling's compute pass reads.
    pub(crate) instances: wgpu::Buffer,
    pub(crate) singles: wgpu::Buffer,
    pub(crate) single_stride: u32,
    /// The sphere around the rock at every level, in the rock's own space:
    /// xyz its centre, w its radius. A rock's own sphere is this one
    /// stretched by its largest scale.
    pub sphere: Vec4,
    /// One group per terrain chunk, nearest the start camera first: which
    /// instances it holds, and the box they fit in.
    pub groups: Vec<RockGroup>,
    /// How many rocks the scatter placed (fewer than `rocks_on_map` only on
    /// terrain too steep for them).
    pub placed: u32,
}
// ANCHOR_END: rock_field

impl RockField {
    /// The rocks of the terrain whose height field is `field` and whose
    /// chunks' boxes are `chunk_bounds` (chapter 03's `TerrainRenderer::chunk_bounds`).
    pub fn get(gpu: &Gpu, field: &HeightField, chunk_bounds: &[Aabb]) -> Arc<Self> {
        gpu.cached((field.settings, SEED), || {
            let device = &gpu.device;
            let levels = rock_levels(SEED);
            let mesh = &levels[0];
            let scattered = scatter(field, rocks_on_map(&field.settings), SEED);
            // The farthest any rock reaches from where it stands: the full
            // mesh's radius (the chunk groups are drawn at full detail),
            // stretched by the largest scale of any rock.
            let radius = mesh.vertices.iter().map(|v| Vec3::from(v.position).length()).fold(0.0, f32::max);
            let stretch = scattered.iter().flat_map(|r| r.scale).fold(0.0, f32::max);
            let start = plain_camera(field, 1.0).position;
            let (rocks, groups) = group_by_chunk(&scattered, &field.settings, chunk_bounds, radius * stretch, start);
            // ANCHOR: instance_buffer
            // Every rock's 32 bytes, one after another: the instanced draws
            // read it as vertex buffer 1, the GPU's culling as storage.
            let instances = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("rock instances"),
                contents: bytemuck::cast_slice(&rocks),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::STORAGE,
            });
            // ANCHOR_END: instance_buffer
            let single_stride = (std::mem::size_of::<RockInstance>() as u32)
                .next_multiple_of(device.limits().min_uniform_buffer_offset_alignment);
            let mut slots = vec![0u8; single_stride as usize * MAX_ONE_PER_DRAW as usize];
            for (slot, rock) in slots.chunks_exact_mut(single_stride as usize).zip(&rocks) {
                slot[..std::mem::size_of::<RockInstance>()].copy_from_slice(bytemuck::bytes_of(rock));
            }
            let singles = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("one rock per slot"),
                contents: &slots,
                usage: wgpu::BufferUsages::UNIFORM,
            });
            let centre = box_centre(mesh);
            let reach = levels.iter().flat_map(|level| &level.vertices);
            let radius = reach.map(|v| (Vec3::from(v.position) - centre).length()).fold(0.0, f32::max);
            Self {
                levels: levels.each_ref().map(|level| level.upload(device, "rock")),
                sphere: centre.extend(radius),
                instances,
                singles,
                single_stride,
                groups,
                placed: rocks.len() as u32,
            }
        })
    }

    /// Bytes of the buffers the rocks hold on the GPU: the meshes, the
    /// instances and the one-per-draw slots.
    pub fn gpu_bytes(&self) -> u64 {
        let meshes: u64 = self.levels.iter().map(|mesh| mesh.vertex_buffer.size() + mesh.index_buffer.size()).sum();
        meshes + self.instances.size() + self.singles.size()
    }

    /// The rock's full-detail mesh, the one the chunk groups draw.
    pub(crate) fn mesh(&self) -> &Mesh {
        &self.levels[0]
    }
}
