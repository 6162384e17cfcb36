//! The rocks: one small record per rock, read by the GPU once per instance;
//! a million of them scattered over the plain; and the `RockField` that
//! holds them on the GPU, made once and shared.

use std::sync::Arc;

use common::wgpu::util::DeviceExt as _;
use common::{Gpu, Mesh, wgpu};
use terrain::heightfield::HeightField;

use crate::mars_plain::plain_camera;
use crate::rng::Rng;
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

/// Up to `count` rocks scattered over a 1.6 km square of the plain in front
/// of the start camera, each on the ground, half buried, never on a steep
/// slope. Placement is uniform, so the first n of them are a fair sample at
/// any n: the rock-count slider just draws fewer. A random place on a slope
/// is rejected and another tried; on terrain that is steep almost
/// everywhere (the sliders can make it so) that could go on for ever, so
/// after `ATTEMPTS_PER_ROCK × count` tries the scatter stops, with fewer rocks.
pub fn scatter(field: &HeightField, count: usize, seed: u64) -> Vec<RockInstance> {
    let mut rng = Rng::new(seed);
    let centre = plain_camera(field, 1.0).position;
    let mut rocks = Vec::with_capacity(count);
    for _ in 0..count.saturating_mul(ATTEMPTS_PER_ROCK) {
        if rocks.len() == count {
            break;
        }
        let x = centre.x + rng.range(-800.0, 800.0);
        let z = centre.z + rng.range(-1400.0, 200.0);
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

/// The most rocks the instance buffer holds, and the most drawn one by one.
pub const MAX_ROCKS: u32 = 1_000_000;
pub const MAX_ONE_PER_DRAW: u32 = 20_000;
/// The seed of the rocks' scatter and of their mesh.
pub(crate) const SEED: u64 = 5;

/// The rocks on the GPU: the one mesh, every rock's instance record, and
/// the first `MAX_ONE_PER_DRAW` of them again, one per 256-byte uniform
/// slot, for the one-draw-per-rock comparison. Made once per terrain and
/// device, and shared (a million rocks take a moment to scatter).
pub struct RockField {
    pub(crate) mesh: Mesh,
    pub(crate) instances: wgpu::Buffer,
    pub(crate) singles: wgpu::Buffer,
    pub(crate) single_stride: u32,
    /// How many rocks the scatter placed (fewer than `MAX_ROCKS` only on
    /// terrain too steep for them).
    pub placed: u32,
}

impl RockField {
    pub fn get(gpu: &Gpu, field: &HeightField) -> Arc<Self> {
        gpu.cached((field.settings, SEED), || {
            let device = &gpu.device;
            let rocks = scatter(field, MAX_ROCKS as usize, SEED);
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
                mesh: rock_mesh(SEED).upload(device, "rock"),
                instances,
                singles,
                single_stride,
                placed: rocks.len() as u32,
            }
        })
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
    fn a_prefix_of_the_rocks_is_the_smaller_scatter() {
        let field = HeightField::generate(TerrainSettings { chunks_per_side: 64, ..Default::default() });
        assert_eq!(scatter(&field, 500, SEED)[..], scatter(&field, 2_000, SEED)[..500]);
    }
}
