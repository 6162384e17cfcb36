//! One rock as the GPU reads it, a small record per instance, and a
//! million of them scattered over the whole map, each on the ground and off
//! the slopes. Same seed, same rocks.

use common::wgpu;
use terrain::heightfield::{HeightField, TerrainSettings};

use crate::rng::Rng;

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
/// 60,000 a square kilometre.
pub const MAX_ROCKS: u32 = 1_000_000;

/// How many rocks the scatter tries to place on a map of `settings`: as
/// many a chunk as on the default map, so a million there.
pub fn rocks_on_map(settings: &TerrainSettings) -> usize {
    const DEFAULT_CHUNKS: u64 = 64 * 64;
    (u64::from(MAX_ROCKS) * u64::from(settings.chunks_per_side.pow(2)) / DEFAULT_CHUNKS) as usize
}
/// The seed of the rocks' scatter and of their mesh.
pub const SEED: u64 = 5;

#[cfg(test)]
mod tests {
    use super::*;

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
