//! The lights of a frame on the GPU: group 0 of `lights.wgsl`, which every
//! lit shader of chapters 08 to 11 imports. In: a camera, the daylight,
//! the lights and their cluster lists, and how the light loop runs
//! (`LoopOptions`); out: one bind group and its layout.

use common::chapter::{FILTERABLE, sampler_entry, storage_entry, texture_entry};
use common::{Camera, Gpu, ShaderError, wgpu};

use crate::clusters::{self, CLUSTERS, ClusterLists};
use crate::irradiance::{SkyColours, SkyIrradiance};
use crate::lights::{Daylight, GpuLight, Light};
use crate::pbr::BrdfTable;
use crate::prefiltered_sky::PrefilteredSky;

/// Which highlight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Highlight {
    /// The mirror direction against the view: (r · v)^s.
    Phong,
    /// The half vector against the normal: (n · h)^s.
    BlinnPhong,
    /// Not a highlight alone but a whole model: microfacets with GGX's
    /// distribution, Smith's visibility and Schlick's Fresnel, diffuse and
    /// specular sharing the light between them (`pbr.rs`).
    CookTorrance,
}

impl Highlight {
    /// `options.z` in lights.wgsl.
    fn code(self) -> u32 {
        match self {
            Highlight::Phong => 0,
            Highlight::BlinnPhong => 1,
            Highlight::CookTorrance => 2,
        }
    }
}

/// The most lights the buffer holds: the city's own, then beacons.
pub const MAX_LIGHTS: u32 = 1024;

// ANCHOR: frame_uniform
/// `Frame` in lights.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FrameUniform {
    view_proj: [[f32; 4]; 4],
    view: [[f32; 4]; 4],
    eye: [f32; 4],
    sun_direction: [f32; 4],
    sun_colour: [f32; 4],
    ambient: [f32; 4],
    options: [u32; 4],
    depth: [f32; 4],
    grid: [u32; 4],
}
// ANCHOR_END: frame_uniform

/// How the light loop runs this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoopOptions {
    pub culling: bool,
    pub highlight: Highlight,
    pub heat_map: bool,
}

/// What the lit chapters (08-11) need of an adapter that is less than a
/// full WebGPU one: storage buffers read by vertex and fragment shaders,
/// where the lights, their cluster lists and the values shaders branch on
/// live (`common::pipeline::storage_entry` says why), and compute shaders,
/// which make the split-sum table, the sky's irradiance and the
/// prefiltered sky. WebGL2 has none of them.
pub const DOWNLEVEL: wgpu::DownlevelFlags = wgpu::DownlevelFlags::VERTEX_STORAGE
    .union(wgpu::DownlevelFlags::FRAGMENT_STORAGE)
    .union(wgpu::DownlevelFlags::COMPUTE_SHADERS);

/// The least the lit chapters draw with: a WebGPU adapter's defaults
/// (chapter 10's lantern reads all 8 storage buffers a fragment stage may
/// have; chapters 10 and 11 use all 4 bind groups). An OpenGL adapter
/// with less is refused in one line that names each limit it lacks.
pub const LIMITS: wgpu::Limits = wgpu::Limits::defaults();

/// What a lit chapter (08-11) asks of an adapter: [`DOWNLEVEL`] and
/// [`LIMITS`], and the post chain's optional features where it has them.
pub fn gpu_needs() -> common::GpuNeeds {
    common::GpuNeeds {
        required: wgpu::Features::empty(),
        optional: crate::post::PostChain::OPTIONAL_FEATURES,
        downlevel: DOWNLEVEL,
        limits: LIMITS,
    }
}

// ANCHOR: scene_lights
/// The lights of a frame on the GPU: group 0 of `lights.wgsl`, with the
/// frame's camera and sun, every light, and the cluster lists. A piece with
/// explicit inputs, which chapter 09's textured city uses as it is.
pub struct SceneLights {
    frame: wgpu::Buffer,
    lights: wgpu::Buffer,
    ranges: wgpu::Buffer,
    indices: wgpu::Buffer,
    brdf_table: BrdfTable,
    sky: SkyIrradiance,
    sky_mirror: PrefilteredSky,
    pub layout: wgpu::BindGroupLayout,
    pub group: wgpu::BindGroup,
}

impl SceneLights {
    /// Computes the split-sum table (a compute pass) and readies the sky's
    /// harmonics and its prefiltered cube, which the first `write` fills:
    /// it fails where `brdf_table.wgsl`, `irradiance.wgsl` or
    /// `prefilter.wgsl` does.
    pub fn new(gpu: &Gpu) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let stages = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("lights"),
            entries: &[
                storage_entry(0, stages),
                storage_entry(1, stages),
                storage_entry(2, stages),
                storage_entry(3, stages),
                // Gouraud and flat shading light vertices, so the table is read there too.
                wgpu::BindGroupLayoutEntry { visibility: stages, ..texture_entry(4, FILTERABLE) },
                wgpu::BindGroupLayoutEntry { visibility: stages, ..sampler_entry(5) },
                storage_entry(6, stages),
                wgpu::BindGroupLayoutEntry {
                    binding: 7,
                    visibility: stages,
                    ty: wgpu::BindingType::Texture {
                        sample_type: FILTERABLE,
                        view_dimension: wgpu::TextureViewDimension::Cube,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry { visibility: stages, ..sampler_entry(8) },
            ],
        });
        let buffer = |label, size: u64, usage| {
            device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size, usage, mapped_at_creation: false })
        };
        let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
        // Storage, not uniform: see `frame` in lights.wgsl.
        let frame = buffer("frame", std::mem::size_of::<FrameUniform>() as u64, storage);
        let lights = buffer("lights", u64::from(MAX_LIGHTS) * 64, storage);
        let ranges = buffer("cluster ranges", CLUSTERS as u64 * 8, storage);
        let indices = buffer("cluster lights", 4 * 4096, storage);
        let brdf_table = BrdfTable::new(gpu)?;
        let sky = SkyIrradiance::new(gpu)?;
        let sky_mirror = PrefilteredSky::new(gpu)?;
        let group = Self::group(device, &layout, [&frame, &lights, &ranges, &indices], &brdf_table, &sky, &sky_mirror);
        Ok(Self { frame, lights, ranges, indices, brdf_table, sky, sky_mirror, layout, group })
    }

    fn group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        buffers: [&wgpu::Buffer; 4],
        table: &BrdfTable,
        sky: &SkyIrradiance,
        sky_mirror: &PrefilteredSky,
    ) -> wgpu::BindGroup {
        let mut entries: Vec<wgpu::BindGroupEntry> = buffers
            .iter()
            .enumerate()
            .map(|(i, b)| wgpu::BindGroupEntry { binding: i as u32, resource: b.as_entire_binding() })
            .collect();
        entries.push(wgpu::BindGroupEntry { binding: 4, resource: wgpu::BindingResource::TextureView(&table.view) });
        entries.push(wgpu::BindGroupEntry { binding: 5, resource: wgpu::BindingResource::Sampler(&table.sampler) });
        entries.push(wgpu::BindGroupEntry { binding: 6, resource: sky.coefficients.as_entire_binding() });
        entries
            .push(wgpu::BindGroupEntry { binding: 7, resource: wgpu::BindingResource::TextureView(&sky_mirror.view) });
        entries
            .push(wgpu::BindGroupEntry { binding: 8, resource: wgpu::BindingResource::Sampler(&sky_mirror.sampler) });
        device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some("lights"), layout, entries: &entries })
    }

    /// Makes the next `write` compute the sky's light again even if the
    /// sky has not changed: for the bench, which measures what a turning
    /// day costs at a fixed scene time.
    pub fn forget_sky(&mut self) {
        self.sky.forget();
        self.sky_mirror.forget();
    }

    /// Computes the sky's light (its harmonics and its prefiltered cube)
    /// if the sky of `day` differs from the last one, timing the passes on
    /// `timer`; `write` does it untimed otherwise.
    pub fn update_sky(&mut self, gpu: &Gpu, day: &Daylight, timer: &common::PassTimer) {
        let sky = SkyColours::of(day);
        self.sky.update(gpu, sky, timer);
        self.sky_mirror.update(gpu, sky, timer);
    }

    /// Writes the frame: the camera, the daylight, `lights` (at most
    /// `MAX_LIGHTS`), their cluster lists, and how the loop runs.
    pub fn write(
        &mut self,
        gpu: &Gpu,
        camera: &Camera,
        day: &Daylight,
        lights: &[Light],
        lists: &ClusterLists,
        options: LoopOptions,
    ) {
        let count = lights.len().min(MAX_LIGHTS as usize);
        let frame = FrameUniform {
            view_proj: camera.view_projection().to_cols_array_2d(),
            view: camera.view().to_cols_array_2d(),
            eye: camera.position.extend(1.0).into(),
            sun_direction: day.direction.extend(0.0).into(),
            sun_colour: day.sun.extend(1.0).into(),
            ambient: day.ambient.extend(1.0).into(),
            options: [count as u32, u32::from(options.culling), options.highlight.code(), u32::from(options.heat_map)],
            depth: [camera.near, camera.far, (camera.far / camera.near).ln(), day.night],
            grid: [clusters::GRID[0], clusters::GRID[1], clusters::GRID[2], 0],
        };
        gpu.queue.write_buffer(&self.frame, 0, bytemuck::bytes_of(&frame));
        self.update_sky(gpu, day, &common::PassTimer::off());
        let gpu_lights: Vec<GpuLight> = lights[..count].iter().map(Light::to_gpu).collect();
        if !gpu_lights.is_empty() {
            gpu.queue.write_buffer(&self.lights, 0, bytemuck::cast_slice(&gpu_lights));
        }
        // ANCHOR: write_lists
        if options.culling {
            let needed = (lists.indices.len().max(1) * 4) as u64;
            if needed > self.indices.size() {
                // Grow to the next power of two, and point the bind group at the new buffer.
                self.indices = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("cluster lights"),
                    size: needed.next_power_of_two(),
                    usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                });
                let buffers = [&self.frame, &self.lights, &self.ranges, &self.indices];
                let (table, sky, mirror) = (&self.brdf_table, &self.sky, &self.sky_mirror);
                self.group = Self::group(&gpu.device, &self.layout, buffers, table, sky, mirror);
            }
            gpu.queue.write_buffer(&self.ranges, 0, bytemuck::cast_slice(&lists.ranges));
            if !lists.indices.is_empty() {
                gpu.queue.write_buffer(&self.indices, 0, bytemuck::cast_slice(&lists.indices));
            }
        }
        // ANCHOR_END: write_lists
    }
}
// ANCHOR_END: scene_lights
