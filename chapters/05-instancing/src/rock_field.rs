//! The rocks: one small record per rock, read by the GPU once per instance;
//! a million of them scattered over the whole map; and the `RockField` that
//! holds them on the GPU, grouped by terrain chunk, made once and shared.

use std::sync::Arc;

use common::glam::Vec3;
use common::wgpu::util::DeviceExt as _;
use common::{Gpu, Mesh, wgpu};
use terrain::chunks::Aabb;
use terrain::heightfield::{HeightField, TerrainSettings};

use crate::mars_plain::plain_camera;
use crate::rng::Rng;
use crate::rock_groups::{RockGroup, group_by_chunk};
use crate::rock_mesh::rock_mesh;

// ANCHOR: instance
/// One rock as the GPU reads it (`Rock` in rocks.wgsl): 32 bytes, against
/// 64 for a full model matrix. A million rocks are 32 MB.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RockInstance {
    pub position: [f32; 3],
    pub yaw: f32,
    pub scale: [f32; 3],
    pub shade: f32,
}

impl RockInstance {
    /// `step_mode: Instance`: the GPU moves to the next `RockInstance` once
    /// per instance, while the mesh's vertices (buffer 0) step per vertex.
    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<RockInstance>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &wgpu::vertex_attr_array![3 => Float32x4, 4 => Float32x4],
    };
}
// ANCHOR_END: instance

// ANCHOR: scatter
/// How many places a rock may try before the scatter gives up on it.
pub const ATTEMPTS_PER_ROCK: usize = 20;

/// Up to `count` rocks scattered over the whole map, each on the ground,
/// half buried, never on a steep slope. A random place on a slope
/// is rejected and another tried; on terrain that is steep almost
/// everywhere (the sliders can make it so) that could go on for ever, so
/// after `ATTEMPTS_PER_ROCK × count` tries the scatter stops, with fewer rocks.
pub fn scatter(field: &HeightField, count: usize, seed: u64) -> Vec<RockInstance> {
    let mut rng = Rng::new(seed);
    let extent = field.settings.extent();
    let mut rocks = Vec::with_capacity(count);
    for _ in 0..count.saturating_mul(ATTEMPTS_PER_ROCK) {
        if rocks.len() == count {
            break;
        }
        let (x, z) = (rng.range(0.0, extent), rng.range(0.0, extent));
        // Dust does not stay on steep slopes, and neither do rocks.
        let normal = field.normal((x / field.settings.spacing) as i64, (z / field.settings.spacing) as i64);
        if normal.y < 0.9 {
            continue;
        }
        // Many small rocks, a few large ones.
        let size = 0.3 + 1.8 * rng.unit().powi(2);
        let scale = [size * rng.range(0.8, 1.5), size * rng.range(0.7, 1.3), size * rng.range(0.8, 1.5)];
        let y = field.height_at(x, z) - 0.15 * scale[1];
        rocks.push(RockInstance {
            position: [x, y, z],
            yaw: rng.range(0.0, std::f32::consts::TAU),
            scale,
            shade: rng.unit(),
        });
    }
    rocks
}
// ANCHOR_END: scatter

/// The rocks on the default map (64 × 64 chunks, 4 km a side): about
/// 60,000 a square kilometre. And the most drawn one by one.
pub const MAX_ROCKS: u32 = 1_000_000;
pub const MAX_ONE_PER_DRAW: u32 = 20_000;

/// How many rocks the scatter tries to place on a map of `settings`: as
/// many a chunk as on the default map, so a million there.
pub fn rocks_on_map(settings: &TerrainSettings) -> usize {
    const DEFAULT_CHUNKS: u64 = 64 * 64;
    (u64::from(MAX_ROCKS) * u64::from(settings.chunks_per_side.pow(2)) / DEFAULT_CHUNKS) as usize
}
/// The seed of the rocks' scatter and of their mesh.
pub(crate) const SEED: u64 = 5;

// ANCHOR: rock_field
/// The rocks on the GPU: the one mesh, every rock's instance record grouped
/// by terrain chunk, and the first `MAX_ONE_PER_DRAW` of them again, one per
/// 256-byte uniform slot, for the one-draw-per-rock comparison. Made once
/// per terrain and device, and shared (a million rocks take a moment to
/// scatter).
pub struct RockField {
    pub(crate) mesh: Mesh,
    pub(crate) instances: wgpu::Buffer,
    pub(crate) singles: wgpu::Buffer,
    pub(crate) single_stride: u32,
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
    /// chunks' boxes are `chunk_bounds` (chapter 03's `TerrainMesh::bounds`).
    pub fn get(gpu: &Gpu, field: &HeightField, chunk_bounds: &[Aabb]) -> Arc<Self> {
        gpu.cached((field.settings, SEED), || {
            let device = &gpu.device;
            let mesh = rock_mesh(SEED);
            let scattered = scatter(field, rocks_on_map(&field.settings), SEED);
            // The farthest any rock reaches from where it stands: the mesh's
            // radius, stretched by the largest scale of any rock.
            let radius = mesh.vertices.iter().map(|v| Vec3::from(v.position).length()).fold(0.0, f32::max);
            let stretch = scattered.iter().flat_map(|r| r.scale).fold(0.0, f32::max);
            let start = plain_camera(field, 1.0).position;
            let (rocks, groups) = group_by_chunk(&scattered, &field.settings, chunk_bounds, radius * stretch, start);
            let instances = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("rock instances"),
                contents: bytemuck::cast_slice(&rocks),
                usage: wgpu::BufferUsages::VERTEX,
            });
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
            Self {
                mesh: mesh.upload(device, "rock"),
                instances,
                singles,
                single_stride,
                groups,
                placed: rocks.len() as u32,
            }
        })
    }

    /// Bytes of the buffers the rocks hold on the GPU: the mesh, the
    /// instances and the one-per-draw slots.
    pub fn gpu_bytes(&self) -> u64 {
        let mesh = self.mesh.vertex_buffer.size() + self.mesh.index_buffer.size();
        mesh + self.instances.size() + self.singles.size()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use terrain::heightfield::TerrainSettings;

    #[test]
    fn rocks_sit_on_the_ground_and_avoid_the_cliff() {
        let field = HeightField::generate(TerrainSettings::default());
        let rocks = scatter(&field, 2_000, SEED);
        assert_eq!(rocks, scatter(&field, 2_000, SEED), "same seed, same rocks");
        for rock in &rocks {
            let [x, y, z] = rock.position;
            let ground = field.height_at(x, z);
            assert!(y <= ground && y > ground - 1.0, "rock at {y} m, ground at {ground} m");
            let n = field.normal(x as i64, z as i64);
            assert!(n.y >= 0.9);
        }
    }

    #[test]
    fn the_scatter_gives_up_where_the_ground_is_too_steep() {
        // A ramp rising 1.2 m per metre everywhere: no slope under 25°.
        let settings = TerrainSettings::default();
        let size = settings.samples();
        let heights = (0..size * size).map(|i| 1.2 * (i % size) as f32).collect();
        let field = HeightField { settings, size, heights };
        assert!(scatter(&field, 1_000, SEED).is_empty(), "no rock belongs on this slope, and the scatter must stop");
        // Where half the ground is flat, the scatter still fills its count.
        let half: Vec<f32> =
            (0..size * size).map(|i| if i % size < size / 2 { 0.0 } else { 1.2 * (i % size) as f32 }).collect();
        let field = HeightField { settings, size, heights: half };
        assert_eq!(scatter(&field, 1_000, SEED).len(), 1_000);
    }

    #[test]
    fn rocks_cover_the_whole_map() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 16, ..Default::default() });
        let rocks = scatter(&field, rocks_on_map(&field.settings), SEED);
        assert_eq!(rocks_on_map(&TerrainSettings::default()), MAX_ROCKS as usize);
        assert_eq!(rocks.len(), 62_500, "a million a 64 × 64-chunk map, a sixteenth on 16 × 16");
        // Every one of the 4 × 4 quarters of the map has its share, give or
        // take what the cliff and the slopes refuse.
        let quarter = field.settings.extent() / 4.0;
        let mut counts = [0usize; 16];
        for rock in &rocks {
            let cell = |v: f32| ((v / quarter) as usize).min(3);
            counts[cell(rock.position[2]) * 4 + cell(rock.position[0])] += 1;
        }
        assert!(counts.iter().all(|&c| c > rocks.len() / 16 / 2), "{counts:?}");
    }

    #[test]
    fn a_prefix_of_the_rocks_is_the_smaller_scatter() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 64, ..Default::default() });
        assert_eq!(scatter(&field, 500, SEED)[..], scatter(&field, 2_000, SEED)[..500]);
    }
}
