//! The sky as a mirror for physically based shading: the sky drawn into a
//! cube map whose mip levels hold it blurred as GGX blurs it at rising
//! roughness (Karis 2013's prefiltered environment), by a compute shader
//! (`prefilter.wgsl`) whenever the sky's colours change. A surface looks
//! up the direction it reflects the eye to at the level of its roughness,
//! and multiplies by the split-sum table's f0 × A + B. In: the sky's
//! colours; out: a cube texture and its sampler, which `lights.wgsl` reads.

use common::chapter::uniform_entry;
use common::wgpu::util::DeviceExt as _;
use common::{Gpu, PassTimer, ShaderError, shader, wgpu};

use crate::irradiance::SkyColours;

// ANCHOR: prefiltered_sky
/// The sky in a cube map with one mip level per roughness, kept on the GPU
/// and blurred again when the sky changes.
pub struct PrefilteredSky {
    colours: wgpu::Buffer,
    /// All six faces and all levels, as a cube: what `lights.wgsl` samples.
    pub view: wgpu::TextureView,
    /// Linear between texels and between levels.
    pub sampler: wgpu::Sampler,
    pipeline: wgpu::ComputePipeline,
    /// One per level: its roughness, and its six faces to write.
    levels: Vec<wgpu::BindGroup>,
    filtered: Option<SkyColours>,
}

impl PrefilteredSky {
    /// Texels along a side of level 0's faces: the sky as a mirror shows it.
    pub const SIZE: u32 = 64;
    /// 64, 32, 16 and 8 texels a side: roughness 0, ⅓, ⅔ and 1. Not down
    /// to one texel: a face of one or two texels is one or four values,
    /// and where a driver filters each face alone (llvmpipe's OpenGL did
    /// here) the roughest spheres showed the cube's faces as patches.
    pub const LEVELS: u32 = 4;
    pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

    /// The roughness level `level` is blurred for: evenly from 0 at the
    /// top to 1 at the last, as `lights.wgsl` reads them back.
    pub fn roughness_of(level: u32) -> f32 {
        level as f32 / (Self::LEVELS - 1) as f32
    }

    pub fn new(gpu: &Gpu) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let colours = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("prefiltered sky colours"),
            size: 48,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("prefiltered sky"),
            size: wgpu::Extent3d { width: Self::SIZE, height: Self::SIZE, depth_or_array_layers: 6 },
            mip_level_count: Self::LEVELS,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: Self::FORMAT,
            usage: wgpu::TextureUsages::STORAGE_BINDING
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("prefiltered sky"),
            dimension: Some(wgpu::TextureViewDimension::Cube),
            ..Default::default()
        });
        let compute = wgpu::ShaderStages::COMPUTE;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("prefiltered sky"),
            entries: &[
                uniform_entry(0, compute, 48),
                uniform_entry(1, compute, 16),
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: compute,
                    ty: wgpu::BindingType::StorageTexture {
                        access: wgpu::StorageTextureAccess::WriteOnly,
                        format: Self::FORMAT,
                        view_dimension: wgpu::TextureViewDimension::D2Array,
                    },
                    count: None,
                },
            ],
        });
        let levels = (0..Self::LEVELS)
            .map(|level| {
                let roughness = [Self::roughness_of(level), 0.0, 0.0, 0.0];
                let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("prefiltered sky level"),
                    contents: bytemuck::cast_slice(&roughness),
                    usage: wgpu::BufferUsages::UNIFORM,
                });
                let faces = texture.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("prefiltered sky level"),
                    dimension: Some(wgpu::TextureViewDimension::D2Array),
                    base_mip_level: level,
                    mip_level_count: Some(1),
                    ..Default::default()
                });
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("prefiltered sky level"),
                    layout: &layout,
                    entries: &[
                        wgpu::BindGroupEntry { binding: 0, resource: colours.as_entire_binding() },
                        wgpu::BindGroupEntry { binding: 1, resource: uniform.as_entire_binding() },
                        wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&faces) },
                    ],
                })
            })
            .collect();
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("prefiltered sky"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let module = shader!("lighting/prefilter.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl"])
            .module(gpu)?;
        let pipeline = gpu
            .catch_validation(|| {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("prefiltered sky"),
                    layout: Some(&pipeline_layout),
                    module: &module,
                    entry_point: Some("cs_prefilter"),
                    compilation_options: Default::default(),
                    cache: None,
                })
            })
            .map_err(ShaderError)?;
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("prefiltered sky"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        Ok(Self { colours, view, sampler, pipeline, levels, filtered: None })
    }

    /// Forgets the sky last computed, so that the next `update` computes
    /// it whatever it is.
    pub fn forget(&mut self) {
        self.filtered = None;
    }

    /// Blurs `sky` into every level if it differs from the sky last
    /// blurred: one dispatch a level, submitted before the frame that
    /// reads them.
    pub fn update(&mut self, gpu: &Gpu, sky: SkyColours, timer: &PassTimer) {
        if self.filtered == Some(sky) {
            return;
        }
        gpu.queue.write_buffer(&self.colours, 0, bytemuck::cast_slice(&sky.to_gpu()));
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("prefiltered sky"),
                timestamp_writes: timer.compute_pass("prefiltered sky"),
            });
            pass.set_pipeline(&self.pipeline);
            for (level, group) in self.levels.iter().enumerate() {
                let side = (Self::SIZE >> level).max(1);
                pass.set_bind_group(0, group, &[]);
                pass.dispatch_workgroups(side.div_ceil(8), side.div_ceil(8), 6);
            }
        }
        gpu.queue.submit([encoder.finish()]);
        self.filtered = Some(sky);
    }
}
// ANCHOR_END: prefiltered_sky
