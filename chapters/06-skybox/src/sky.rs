//! The sky: day and night cube maps, blended by the time of day and
//! turning with it, the sun painted where the light comes from, and the
//! colour of the horizon that the fog must fade to. Inputs: a camera and
//! the time of day, through a `SkyViewpoint` per camera.

use std::f32::consts::TAU;

use common::chapter::uniform_entry;
use common::glam::{Mat4, Quat, Vec3};
use common::texture::{ColorSpace, Texture, cubemap_from_images, decode_faces};
use common::wgpu::util::DeviceExt as _;
use common::{Camera, Drawn, Gpu, Reloadable, ShaderError, ShaderFile, anyhow, fullscreen, image, shader, wgpu};

use crate::sun_path::{celestial_turn, day_blend, sun_at};

// ANCHOR: faces
/// One face of a sky under `assets/skybox/`: its name, for errors, and its
/// bytes, embedded so that the binary runs from anywhere.
macro_rules! face {
    ($sky:literal, $face:literal) => {
        (
            concat!("assets/skybox/", $sky, "/", $face, ".png"),
            include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/skybox/", $sky, "/", $face, ".png"))
                .as_slice(),
        )
    };
}

/// The six faces of a sky in WebGPU's order: +x, −x, +y, −y, +z, −z.
macro_rules! sky {
    ($sky:literal) => {
        [
            face!($sky, "px"),
            face!($sky, "nx"),
            face!($sky, "py"),
            face!($sky, "ny"),
            face!($sky, "pz"),
            face!($sky, "nz"),
        ]
    };
}

pub const DAY: [(&str, &[u8]); 6] = sky!("day");
pub const NIGHT: [(&str, &[u8]); 6] = sky!("night");
// ANCHOR_END: faces

// ANCHOR: horizon
/// The average colour of a sky's horizon (the middle rows of its four side
/// faces), in linear RGB: what the fog must fade to, measured from the
/// pictures themselves so that the two cannot drift apart.
pub fn horizon_colour(faces: &[image::RgbaImage; 6]) -> [f32; 3] {
    let mut sum = [0.0f64; 3];
    let mut count = 0.0;
    for image in [&faces[0], &faces[1], &faces[4], &faces[5]] {
        let middle = image.height() / 2;
        for y in middle - 2..middle + 2 {
            for x in 0..image.width() {
                let p = image.get_pixel(x, y);
                for c in 0..3 {
                    sum[c] += f64::from(srgb_to_linear(p[c]));
                }
                count += 1.0;
            }
        }
    }
    sum.map(|s| (s / count) as f32)
}

fn srgb_to_linear(byte: u8) -> f32 {
    let c = f32::from(byte) / 255.0;
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}
// ANCHOR_END: horizon

/// `Sky` in sky.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SkyUniform {
    clip_to_world: [[f32; 4]; 4],
    world_to_day: [[f32; 4]; 4],
    world_to_stars: [[f32; 4]; 4],
    sun: [f32; 4],
}

// ANCHOR: dust_drift
/// The day atmosphere's slow drift about the vertical: a tenth of a turn a day.
fn dust_drift(phase: f32) -> Quat {
    Quat::from_rotation_y(TAU * 0.1 * phase)
}
// ANCHOR_END: dust_drift

fn sky_shader() -> ShaderFile {
    shader!("skybox/sky.wgsl", imports: ["common/fullscreen.wgsl"])
}

// ANCHOR: pipeline
fn sky_pipeline(
    gpu: &Gpu,
    layout: &wgpu::PipelineLayout,
    (format, samples): (wgpu::TextureFormat, u32),
) -> Result<wgpu::RenderPipeline, ShaderError> {
    let module = sky_shader().module(gpu)?;
    // Test against the scene's depth, but leave it alone: the sky is at the
    // far plane, and passes only where the buffer still says 1.
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
            target: format.into(),
            depth_stencil: Some(depth),
        };
        fullscreen::multisampled_pipeline(&gpu.device, sky, common::multisampling::multisample(samples))
    })
    .map_err(ShaderError)
}
// ANCHOR_END: pipeline

/// The sky's uniform for one camera. A frame that draws the sky from several
/// cameras has one each, like chapter 03's terrain viewpoints.
pub struct SkyViewpoint {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    /// Samples a pixel of the picture's pass: which pipeline draws it.
    samples: u32,
}

// ANCHOR: sky
/// The sky: day and night cube maps, the sun, and the colour of the
/// horizon for the fog. Inputs: a camera and the time of day.
pub struct Sky {
    day: Texture,
    night: Texture,
    /// Day and night horizon colours, measured from the cube maps.
    horizons: [[f32; 3]; 2],
    bind_group_layout: wgpu::BindGroupLayout,
    /// One for each sample count the sky's pictures are drawn with;
    /// rebuilt when sky.wgsl is saved (hot reload).
    pipeline: Reloadable<Vec<(u32, wgpu::RenderPipeline)>>,
}
// ANCHOR_END: sky

impl Sky {
    /// The sky, for pictures of `format` drawn with each of `samples`
    /// samples a pixel.
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat, samples: &[u32]) -> anyhow::Result<Self> {
        let device = &gpu.device;
        // Decoded once: for the cube maps and to measure their horizons.
        let (day_faces, night_faces) = (decode_faces(&DAY)?, decode_faces(&NIGHT)?);
        let day = cubemap_from_images(device, &gpu.queue, &day_faces, ColorSpace::Srgb, "day sky");
        let night = cubemap_from_images(device, &gpu.queue, &night_faces, ColorSpace::Srgb, "night sky");
        let horizons = [horizon_colour(&day_faces), horizon_colour(&night_faces)];
        let cube = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension: wgpu::TextureViewDimension::Cube,
                multisampled: false,
            },
            count: None,
        };
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sky"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<SkyUniform>()),
                cube(1),
                cube(2),
                wgpu::BindGroupLayoutEntry {
                    binding: 3,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("sky"),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let samples = samples.to_vec();
        let pipeline = Reloadable::new(gpu, move |gpu| {
            let each = |&count: &u32| Ok((count, sky_pipeline(gpu, &layout, (format, count))?));
            samples.iter().map(each).collect::<Result<Vec<_>, ShaderError>>()
        })?;
        Ok(Self { day, night, horizons, bind_group_layout, pipeline })
    }

    /// The uniform for one more picture of the sky, drawn in a pass of
    /// `samples` samples a pixel.
    pub fn viewpoint(&self, device: &wgpu::Device, samples: u32) -> SkyViewpoint {
        let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("sky"),
            contents: &[0; std::mem::size_of::<SkyUniform>()],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sky"),
            layout: &self.bind_group_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&self.day.view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&self.night.view) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.day.sampler) },
            ],
        });
        SkyViewpoint { uniform, bind_group, samples }
    }

    // ANCHOR: fog_colour
    /// The colour the fog must have at time of day `phase`: between the
    /// night and day horizons, as much day as the sky shows.
    pub fn fog_colour(&self, phase: f32) -> [f32; 3] {
        let blend = day_blend(sun_at(phase));
        let [day, night] = self.horizons;
        [0, 1, 2].map(|c| night[c] + (day[c] - night[c]) * blend)
    }
    // ANCHOR_END: fog_colour

    // ANCHOR: aim
    /// Writes the sky's uniform for drawing it from `camera` at time of day `phase`.
    pub fn aim(&self, queue: &wgpu::Queue, viewpoint: &SkyViewpoint, camera: &Camera, phase: f32) {
        let turn_only = Mat4::look_to_rh(Vec3::ZERO, camera.forward(), Vec3::Y);
        let sun = sun_at(phase);
        let uniform = SkyUniform {
            clip_to_world: (camera.projection() * turn_only).inverse().to_cols_array_2d(),
            world_to_day: Mat4::from_quat(dust_drift(phase).inverse()).to_cols_array_2d(),
            world_to_stars: Mat4::from_quat(celestial_turn(phase).inverse()).to_cols_array_2d(),
            sun: sun.direction.normalize().extend(day_blend(sun)).into(),
        };
        queue.write_buffer(&viewpoint.uniform, 0, bytemuck::bytes_of(&uniform));
    }
    // ANCHOR_END: aim

    /// Draws the sky wherever the depth buffer still holds 1: call it after
    /// everything else in the pass.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &SkyViewpoint) -> Drawn {
        let pipelines = self.pipeline.get();
        let found = pipelines.iter().find(|(count, _)| *count == viewpoint.samples).unwrap_or(&pipelines[0]);
        pass.set_pipeline(&found.1);
        pass.set_bind_group(0, &viewpoint.bind_group, &[]);
        pass.draw(0..3, 0..1);
        Drawn::FULL_SCREEN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horizons_are_butterscotch_by_day_and_dark_by_night() {
        let day = horizon_colour(&decode_faces(&DAY).unwrap());
        let night = horizon_colour(&decode_faces(&NIGHT).unwrap());
        assert!(day[0] > day[1] && day[1] > day[2] && day[0] > 0.4, "{day:?}");
        assert!(night.iter().all(|&c| c < 0.01), "{night:?}");
    }
}
