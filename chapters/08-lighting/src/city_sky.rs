//! The sky over the city: a gradient from the horizon to the zenith by time
//! of day, and the sun's disc, drawn last into an HDR scene pass at the far
//! plane. In: a camera and the daylight; out: the sky in the pass. Chapters
//! 09 and 10 draw it behind their scenes too.

use common::chapter::uniform_entry;
use common::glam::{Mat4, Vec3};
use common::{Camera, Drawn, Gpu, Reloadable, ShaderError, fullscreen, shader, wgpu};

use crate::lights::Daylight;
use crate::post::HDR_FORMAT;
use crate::scene_lights::SceneLights;

// ANCHOR: sky
/// `Sky` in sky.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SkyUniform {
    clip_to_world: [[f32; 4]; 4],
    horizon: [f32; 4],
    zenith: [f32; 4],
}

/// The sky over the city: a gradient from the horizon to the zenith by
/// time of day, and the sun. Drawn last in a scene pass whose group 0 is a
/// [`SceneLights`] (for the sun); it binds its own group 1.
pub struct CitySky {
    uniform: wgpu::Buffer,
    group: wgpu::BindGroup,
    /// Made again when sky.wgsl or the lights' module is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
}

impl CitySky {
    /// The sky for an HDR pass of `multisample`'s samples a pixel
    /// ([`crate::HdrTarget::multisample`]).
    pub fn new(gpu: &Gpu, lights: &SceneLights, multisample: wgpu::MultisampleState) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let size = std::mem::size_of::<SkyUniform>();
        let group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sky"),
            entries: &[uniform_entry(0, wgpu::ShaderStages::FRAGMENT, size)],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("sky"),
            size: size as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sky"),
            layout: &group_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("sky"),
            bind_group_layouts: &[Some(&lights.layout), Some(&group_layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &layout, multisample))?;
        Ok(Self { uniform, group, pipeline })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        multisample: wgpu::MultisampleState,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module =
            shader!("lighting/sky.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl", "common/fullscreen.wgsl"]).module(gpu)?;
        // At the far plane, behind everything drawn before it.
        let depth = wgpu::DepthStencilState {
            format: common::texture::DEPTH_FORMAT,
            depth_write_enabled: Some(false),
            depth_compare: Some(wgpu::CompareFunction::LessEqual),
            stencil: Default::default(),
            bias: Default::default(),
        };
        gpu.catch_validation(|| {
            let sky = fullscreen::Pipeline {
                label: "sky",
                layout,
                module: &module,
                fragment_entry: "fs_sky",
                target: HDR_FORMAT.into(),
                depth_stencil: Some(depth),
            };
            fullscreen::multisampled_pipeline(&gpu.device, sky, multisample)
        })
        .map_err(ShaderError)
    }

    /// The sky as `camera` sees it at this time of day.
    pub fn write(&self, gpu: &Gpu, camera: &Camera, day: &Daylight) {
        let turn_only = Mat4::look_to_rh(Vec3::ZERO, camera.forward(), Vec3::Y);
        let sky = SkyUniform {
            clip_to_world: (camera.projection() * turn_only).inverse().to_cols_array_2d(),
            horizon: day.horizon.extend(1.0).into(),
            zenith: day.zenith.extend(1.0).into(),
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&sky));
    }

    /// Draws the sky behind what the pass drew before; returns what that drew.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>) -> Drawn {
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(1, &self.group, &[]);
        pass.draw(0..3, 0..1);
        Drawn::FULL_SCREEN
    }
}
// ANCHOR_END: sky
