//! Islands on the horizon: a bump of chapter 03's fractal Perlin noise,
//! meshed on the CPU, coloured by height from a gradient in the shader.
//! They stand at fixed places on the sea's period, so the sea repeats
//! with them; each is drawn at its copy nearest the boat.

use common::glam::{Vec2, Vec3};
use common::noise::Fbm;
use common::{Drawn, Gpu, Reloadable, ShaderError, shader, wgpu};
use lighting::{HDR_FORMAT, SceneLights};

use crate::atmosphere::Atmosphere;
use crate::sea::PERIOD_METRES;

/// An island: its centre on the sea, how far it reaches, how high its summit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Island {
    pub centre: Vec2,
    pub radius: f32,
    pub summit: f32,
}

/// The islands around the boat's course.
pub const ISLANDS: [Island; 5] = [
    Island { centre: Vec2::new(1790.0, 2000.0), radius: 70.0, summit: 34.0 },
    Island { centre: Vec2::new(2240.0, 1760.0), radius: 55.0, summit: 22.0 },
    Island { centre: Vec2::new(2330.0, 2290.0), radius: 90.0, summit: 48.0 },
    Island { centre: Vec2::new(1900.0, 2380.0), radius: 40.0, summit: 15.0 },
    Island { centre: Vec2::new(2050.0, 1700.0), radius: 30.0, summit: 11.0 },
];

/// Samples along each side of an island's mesh.
const SAMPLES: u32 = 64;

/// A vertex of an island: where, its normal, and its height as a fraction
/// of the summit (what the gradient is looked up by).
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct IslandVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub height: f32,
}

// ANCHOR: shape
/// The ground's height at `p` (metres from the centre) of an island: a
/// dome that falls to 2 m under the water at its rim, roughened by
/// chapter 03's fBm so its slopes have gullies and its coast bays.
pub fn ground(island: &Island, seed: f64, p: Vec2) -> f32 {
    let fbm = Fbm { octaves: 4, persistence: 0.5, lacunarity: 2.0 };
    let r = p.length() / island.radius;
    let dome = (1.0 - r * r).max(0.0).powf(1.5);
    let rough = fbm.sample(f64::from(p.x) / 40.0, f64::from(p.y) / 40.0, seed) as f32;
    island.summit * dome * (0.75 + 0.5 * rough) - 2.0
}
// ANCHOR_END: shape

/// An island's mesh: vertices over its square, and triangle indices.
pub fn mesh(island: &Island, seed: f64) -> (Vec<IslandVertex>, Vec<u32>) {
    let step = 2.0 * island.radius / (SAMPLES - 1) as f32;
    let at = |i: u32, j: u32| Vec2::new(i as f32 * step - island.radius, j as f32 * step - island.radius);
    let mut vertices = Vec::new();
    for j in 0..SAMPLES {
        for i in 0..SAMPLES {
            let p = at(i, j);
            let h = ground(island, seed, p);
            let e = step / 2.0;
            let dx = ground(island, seed, p + Vec2::new(e, 0.0)) - ground(island, seed, p - Vec2::new(e, 0.0));
            let dz = ground(island, seed, p + Vec2::new(0.0, e)) - ground(island, seed, p - Vec2::new(0.0, e));
            let normal = Vec3::new(-dx, 2.0 * e, -dz).normalize();
            vertices.push(IslandVertex {
                position: [p.x, h, p.y],
                normal: normal.into(),
                height: (h / island.summit).max(0.0),
            });
        }
    }
    let mut indices = Vec::new();
    for j in 0..SAMPLES - 1 {
        for i in 0..SAMPLES - 1 {
            let (a, b, c, d) = (j * SAMPLES + i, j * SAMPLES + i + 1, (j + 1) * SAMPLES + i, (j + 1) * SAMPLES + i + 1);
            indices.extend_from_slice(&[a, c, b, b, c, d]);
        }
    }
    (vertices, indices)
}

/// Where to draw `island` for a boat at `boat`: its copy, one sea period
/// over or not, nearest the boat.
pub fn nearest_copy(island: &Island, boat: Vec2) -> Vec2 {
    let shift = ((boat - island.centre) / PERIOD_METRES).round() * PERIOD_METRES;
    island.centre + shift
}

// ANCHOR: piece
/// Draws the islands. Inputs: the boat's position, the lights (group 0)
/// and the atmosphere (group 1).
pub struct IslandRenderer {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    /// Each island's first index and index count.
    ranges: Vec<std::ops::Range<u32>>,
    offsets: wgpu::Buffer,
    /// Made again when islands.wgsl or a module it imports is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
}
// ANCHOR_END: piece

impl IslandRenderer {
    /// The islands for an HDR pass of `multisample`'s samples a pixel
    /// ([`lighting::HdrTarget::multisample`]).
    pub fn new(
        gpu: &Gpu,
        lights: &SceneLights,
        atmosphere: &Atmosphere,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let (mut vertices, mut indices, mut ranges) = (Vec::new(), Vec::new(), Vec::new());
        for (k, island) in ISLANDS.iter().enumerate() {
            let (v, i) = mesh(island, 0.37 + k as f64 * 1.31);
            let base = vertices.len() as u32;
            let first = indices.len() as u32;
            vertices.extend(v);
            indices.extend(i.iter().map(|i| i + base));
            ranges.push(first..indices.len() as u32);
        }
        let buffer = |label, contents: &[u8], usage| {
            wgpu::util::DeviceExt::create_buffer_init(
                device,
                &wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage },
            )
        };
        let vertices = buffer("islands", bytemuck::cast_slice(&vertices), wgpu::BufferUsages::VERTEX);
        let indices = buffer("islands", bytemuck::cast_slice(&indices), wgpu::BufferUsages::INDEX);
        let offsets = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("island offsets"),
            size: (ISLANDS.len() * 12) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("islands"),
            bind_group_layouts: &[Some(&lights.layout), Some(&atmosphere.layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &layout, multisample))?;
        Ok(Self { vertices, indices, ranges, offsets, pipeline })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        multisample: wgpu::MultisampleState,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!(
            "voronoi-water/islands.wgsl",
            imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl", "voronoi-water/atmosphere.wgsl"]
        )
        .module(gpu)?;
        let buffers = [
            Some(wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<IslandVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32],
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: 12,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &wgpu::vertex_attr_array![3 => Float32x3],
            }),
        ];
        gpu.catch_validation(|| {
            common::chapter::mesh_pipeline(
                &gpu.device,
                layout,
                &module,
                ("vs_island", "fs_island"),
                &buffers,
                HDR_FORMAT.into(),
                multisample,
            )
        })
        .map_err(ShaderError)
    }

    /// Places each island's copy nearest `boat`.
    pub fn write(&self, gpu: &Gpu, boat: Vec2) {
        let offsets: Vec<[f32; 3]> = ISLANDS
            .iter()
            .map(|island| {
                let c = nearest_copy(island, boat);
                [c.x, 0.0, c.y]
            })
            .collect();
        gpu.queue.write_buffer(&self.offsets, 0, bytemuck::cast_slice(&offsets));
    }

    /// Draws each island at its copy nearest the boat; returns what that drew.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, atmosphere: &Atmosphere) -> Drawn {
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(1, &atmosphere.group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_vertex_buffer(1, self.offsets.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        let mut drawn = Drawn::NOTHING;
        for (k, range) in self.ranges.iter().enumerate() {
            let k = k as u32;
            pass.draw_indexed(range.clone(), 0, k..k + 1);
            drawn += Drawn::triangle_list(range.clone(), k..k + 1);
        }
        drawn
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn islands_rise_from_under_the_water() {
        for (k, island) in ISLANDS.iter().enumerate() {
            let seed = 0.37 + k as f64 * 1.31;
            assert!(ground(island, seed, Vec2::ZERO) > island.summit * 0.5, "island {k} has no summit");
            assert!(ground(island, seed, Vec2::new(island.radius, 0.0)) < 0.0, "island {k} ends above water");
        }
    }

    #[test]
    fn the_nearest_copy_is_within_half_a_period() {
        let island = ISLANDS[0];
        for boat in [Vec2::new(10.0, 4000.0), Vec2::new(2048.0, 2048.0), Vec2::new(4090.0, 5.0)] {
            let d = nearest_copy(&island, boat) - boat;
            assert!(d.abs().max_element() <= PERIOD_METRES / 2.0);
        }
    }
}
