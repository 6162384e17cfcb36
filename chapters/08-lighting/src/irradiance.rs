//! The sky as a light for physically based shading: its radiance, a
//! gradient from horizon to zenith over a darker ground, projected on nine
//! spherical harmonics by a compute shader (`irradiance.wgsl`) whenever the
//! sky's colours change, so that a surface facing any way gets the light
//! that sky sends it (Ramamoorthi and Hanrahan 2001). In: the sky's
//! colours; out: a storage buffer of nine coefficients, which
//! `lights.wgsl` reads.

use common::chapter::uniform_entry;
use common::glam::Vec3;
use common::{Gpu, PassTimer, ShaderError, shader, wgpu};

/// What the ground below the horizon sends back of the sky's light: a
/// stand-in for the city and its fields, which this chapter does not
/// render into a sky map.
pub const GROUND_REFLECTANCE: f32 = 0.2;

/// The sky's colours, linear RGB: `SkyColours` in irradiance.wgsl.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkyColours {
    pub horizon: Vec3,
    pub zenith: Vec3,
    pub ground: Vec3,
}

impl SkyColours {
    /// The sky of `day`, over ground that reflects [`GROUND_REFLECTANCE`] of the horizon's light.
    pub fn of(day: &crate::lights::Daylight) -> Self {
        Self { horizon: day.horizon, zenith: day.zenith, ground: day.horizon * GROUND_REFLECTANCE }
    }

    /// `SkyColours` in irradiance.wgsl and prefilter.wgsl.
    pub(crate) fn to_gpu(self) -> [[f32; 4]; 3] {
        [self.horizon.extend(0.0).into(), self.zenith.extend(0.0).into(), self.ground.extend(0.0).into()]
    }
}

// ANCHOR: irradiance
/// Nine spherical-harmonic coefficients of the sky's radiance, kept on the
/// GPU and projected again when the sky changes.
pub struct SkyIrradiance {
    colours: wgpu::Buffer,
    /// Nine `vec4<f32>`: the coefficients' RGB (w unused).
    pub coefficients: wgpu::Buffer,
    pipeline: wgpu::ComputePipeline,
    group: wgpu::BindGroup,
    projected: Option<SkyColours>,
}

impl SkyIrradiance {
    pub fn new(gpu: &Gpu) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let colours = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("sky colours"),
            size: 48,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let coefficients = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("sky harmonics"),
            size: 9 * 16,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sky harmonics"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::COMPUTE, 48),
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: false },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
            ],
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sky harmonics"),
            layout: &layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: colours.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: coefficients.as_entire_binding() },
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("sky harmonics"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let module = shader!("lighting/irradiance.wgsl", imports: ["lighting/sky_light.wgsl"]).module(gpu)?;
        let pipeline = gpu
            .catch_validation(|| {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("sky harmonics"),
                    layout: Some(&pipeline_layout),
                    module: &module,
                    entry_point: Some("cs_project"),
                    compilation_options: Default::default(),
                    cache: None,
                })
            })
            .map_err(ShaderError)?;
        Ok(Self { colours, coefficients, pipeline, group, projected: None })
    }

    /// Forgets the sky last computed, so that the next `update` computes
    /// it whatever it is.
    pub fn forget(&mut self) {
        self.projected = None;
    }

    /// Projects `sky` if it differs from the sky last projected: one
    /// workgroup's dispatch, submitted before the frame that reads it.
    pub fn update(&mut self, gpu: &Gpu, sky: SkyColours, timer: &PassTimer) {
        if self.projected == Some(sky) {
            return;
        }
        gpu.queue.write_buffer(&self.colours, 0, bytemuck::cast_slice(&sky.to_gpu()));
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("sky harmonics"),
                timestamp_writes: timer.compute_pass("sky harmonics"),
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &self.group, &[]);
            pass.dispatch_workgroups(1, 1, 1);
        }
        gpu.queue.submit([encoder.finish()]);
        self.projected = Some(sky);
    }
}
// ANCHOR_END: irradiance
