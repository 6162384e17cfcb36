//! Colour from gradients, as the seed did it: the sky, the sun's light, the
//! sun's disc and the islands each look their colour up in a picture, by
//! the sun's height. Tuning a sunset is then painting a gradient, not
//! editing numbers in a shader. The pictures are painted by `cargo xtask
//! assets`; the shader reads three of them, and the CPU reads the sun's
//! light, which is one colour per frame.

use common::chapter::{FILTERABLE, sampler_entry, texture_entry, uniform_entry};
use common::glam::{Mat4, Vec3};
use common::image::RgbaImage;
use common::texture::ColorSpace;
use common::{Camera, Drawn, Gpu, Reloadable, ShaderError, anyhow, fullscreen, shader, wgpu};
use lighting::lights::Daylight;

/// The gradients, embedded so the binary runs from anywhere.
const SKY: &[u8] = include_bytes!("../../../assets/gradients/sky.png");
const SUNLIGHT: &[u8] = include_bytes!("../../../assets/gradients/sunlight.png");
const SUN: &[u8] = include_bytes!("../../../assets/gradients/sun.png");
const ISLANDS: &[u8] = include_bytes!("../../../assets/gradients/islands.png");

// ANCHOR: sun_path
/// A day lasts this long while time runs, seconds.
pub const DAY_SECONDS: f32 = 240.0;

/// Towards the sun at `phase` of the day (0.25 sunrise in the east, 0.5
/// noon, 0.75 sunset in the west): a circle tilted 30° from the zenith
/// towards the south, so noon is 60° high.
pub fn sun_direction(phase: f32) -> Vec3 {
    let angle = std::f32::consts::TAU * (phase - 0.25);
    let tilt = 30f32.to_radians();
    let overhead = Vec3::new(0.0, tilt.cos(), tilt.sin());
    (Vec3::X * angle.cos() + overhead * angle.sin()).normalize()
}

/// Where a direction's height lands on the gradients' axis: 0 straight
/// below, 0.5 on the horizon, 1 overhead.
pub fn gradient_u(towards_sun: Vec3) -> f32 {
    0.5 + 0.5 * towards_sun.y
}
// ANCHOR_END: sun_path

/// A gradient on the CPU, read as the GPU reads it: texel centres,
/// linear filtering in linear light, clamped at the ends.
pub struct Gradient(RgbaImage);

impl Gradient {
    pub fn decode(name: &str, bytes: &[u8]) -> anyhow::Result<Self> {
        Ok(Self(common::texture::decode_named(name, bytes)?))
    }

    /// The colour at (u, v), each 0..1, linear RGB.
    pub fn at(&self, u: f32, v: f32) -> Vec3 {
        let (w, h) = self.0.dimensions();
        let texel = |x: i64, y: i64| {
            let p = self.0.get_pixel(x.clamp(0, w as i64 - 1) as u32, y.clamp(0, h as i64 - 1) as u32);
            textures::materials::srgb(p[0], p[1], p[2])
        };
        let (x, y) = (u.clamp(0.0, 1.0) * w as f32 - 0.5, v.clamp(0.0, 1.0) * h as f32 - 0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (x0, y0) = (x0 as i64, y0 as i64);
        let top = texel(x0, y0).lerp(texel(x0 + 1, y0), fx);
        let bottom = texel(x0, y0 + 1).lerp(texel(x0 + 1, y0 + 1), fx);
        top.lerp(bottom, fy)
    }
}

/// The four gradients on the CPU.
pub struct Gradients {
    pub sky: Gradient,
    pub sunlight: Gradient,
    pub sun: Gradient,
    pub islands: Gradient,
}

impl Gradients {
    pub fn load() -> anyhow::Result<Self> {
        Ok(Self {
            sky: Gradient::decode("assets/gradients/sky.png", SKY)?,
            sunlight: Gradient::decode("assets/gradients/sunlight.png", SUNLIGHT)?,
            sun: Gradient::decode("assets/gradients/sun.png", SUN)?,
            islands: Gradient::decode("assets/gradients/islands.png", ISLANDS)?,
        })
    }

    // ANCHOR: daylight
    /// The light of the frame, for chapter 08's light loop: the sun's by
    /// day and the moon's, opposite it, by night, coloured by the sunlight
    /// gradient; the sky's light from the sky gradient half-way up.
    pub fn daylight(&self, towards_sun: Vec3) -> Daylight {
        let u = gradient_u(towards_sun);
        let direction = if towards_sun.y >= 0.0 { towards_sun } else { -towards_sun };
        Daylight {
            direction,
            sun: self.sunlight.at(u, 0.5) * SUN_STRENGTH,
            ambient: self.sky.at(u, 0.5) * SKY_STRENGTH,
            horizon: self.sky.at(u, 1.0),
            zenith: self.sky.at(u, 0.0),
            night: 0.0,
        }
    }
    // ANCHOR_END: daylight
}

/// How bright the sun's light is for a gradient value of 1.
pub const SUN_STRENGTH: f32 = 2.5;
/// How much the sky's colour lights surfaces the sun does not reach.
pub const SKY_STRENGTH: f32 = 0.5;

/// `Atmosphere` in atmosphere.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct AtmosphereUniform {
    inverse_view_proj: [[f32; 4]; 4],
    eye: [f32; 4],
    sun: [f32; 4],
    fog: [f32; 4],
}

/// How thick the haze is: at 300 m, 30 % of a colour is left.
pub const FOG_DENSITY: f32 = 0.004;

// ANCHOR: piece
/// The gradients on the GPU with the frame's sun and camera: group 1 of
/// every shader that imports `voronoi_water::atmosphere` (the sky, the
/// sea, the islands). Input: the camera and the sun; output: the group.
pub struct Atmosphere {
    uniform: wgpu::Buffer,
    pub layout: wgpu::BindGroupLayout,
    pub group: wgpu::BindGroup,
    pub gradients: Gradients,
}
// ANCHOR_END: piece

impl Atmosphere {
    pub fn new(gpu: &Gpu) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let gradients = Gradients::load()?;
        let stages = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("atmosphere"),
            entries: &[
                uniform_entry(0, stages, std::mem::size_of::<AtmosphereUniform>()),
                texture_entry(1, FILTERABLE),
                texture_entry(2, FILTERABLE),
                texture_entry(3, FILTERABLE),
                sampler_entry(4),
            ],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("atmosphere"),
            size: std::mem::size_of::<AtmosphereUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let upload = |gradient: &Gradient, label| {
            common::texture::Texture::from_image(device, &gpu.queue, &gradient.0, ColorSpace::Srgb, label).view
        };
        let views = [upload(&gradients.sky, "sky gradient"), upload(&gradients.sun, "sun gradient")];
        let islands = upload(&gradients.islands, "island gradient");
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("gradients"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("atmosphere"),
            layout: &layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&views[0]) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&views[1]) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(&islands) },
                wgpu::BindGroupEntry { binding: 4, resource: wgpu::BindingResource::Sampler(&sampler) },
            ],
        });
        Ok(Self { uniform, layout, group, gradients })
    }

    /// Writes the frame's camera and sun.
    pub fn write(&self, gpu: &Gpu, camera: &Camera, towards_sun: Vec3) {
        let inverse: Mat4 = camera.view_projection().inverse();
        // The disc is 1.2° across: twice the real sun's, for a picture.
        let disc = 0.6f32.to_radians().cos();
        let uniform = AtmosphereUniform {
            inverse_view_proj: inverse.to_cols_array_2d(),
            eye: camera.position.extend(1.0).into(),
            sun: towards_sun.extend(gradient_u(towards_sun)).into(),
            fog: [FOG_DENSITY, disc, 0.0, 0.0],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }
}

// ANCHOR: sky
/// The sky, drawn first into the scene pass, under everything.
pub struct Sky {
    /// Made again when sky.wgsl or the atmosphere's module is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
}
// ANCHOR_END: sky

impl Sky {
    /// The sky for an HDR pass of `multisample`'s samples a pixel
    /// ([`lighting::HdrTarget::multisample`]).
    pub fn new(
        gpu: &Gpu,
        lights: &wgpu::BindGroupLayout,
        atmosphere: &Atmosphere,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("sky"),
            bind_group_layouts: &[Some(lights), Some(&atmosphere.layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &layout, multisample))?;
        Ok(Self { pipeline })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        multisample: wgpu::MultisampleState,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!(
            "voronoi-water/sky.wgsl",
            imports: ["common/fullscreen.wgsl", "voronoi-water/atmosphere.wgsl"]
        )
        .module(gpu)?;
        // Under everything: neither tests nor writes depth.
        let depth = wgpu::DepthStencilState {
            depth_write_enabled: Some(false),
            depth_compare: Some(wgpu::CompareFunction::Always),
            ..common::texture::depth_test().expect("a depth test")
        };
        gpu.catch_validation(|| {
            let sky = fullscreen::Pipeline {
                label: "sky",
                layout,
                module: &module,
                fragment_entry: "fs_sky",
                target: lighting::HDR_FORMAT.into(),
                depth_stencil: Some(depth),
            };
            fullscreen::multisampled_pipeline(&gpu.device, sky, multisample)
        })
        .map_err(ShaderError)
    }

    /// Draws the sky behind what the pass drew before; returns what that drew.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, atmosphere: &Atmosphere) -> Drawn {
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(1, &atmosphere.group, &[]);
        pass.draw(0..3, 0..1);
        Drawn::FULL_SCREEN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sun_rises_in_the_east_and_sets_in_the_west() {
        assert!(sun_direction(0.25).y.abs() < 1e-6 && sun_direction(0.25).x > 0.99);
        assert!(sun_direction(0.75).y.abs() < 1e-6 && sun_direction(0.75).x < -0.99);
        let noon = sun_direction(0.5);
        assert!((noon.y.asin().to_degrees() - 60.0).abs() < 0.01);
        assert!(sun_direction(0.0).y < -0.8, "midnight: the sun far below");
    }

    #[test]
    fn gradients_are_read_as_the_gpu_reads_them() {
        let g = Gradients::load().unwrap();
        // At a texel's centre the answer is that texel, decoded.
        let (w, _) = g.sunlight.0.dimensions();
        let p = g.sunlight.0.get_pixel(10, 0);
        let centre = g.sunlight.at((10.5) / w as f32, 0.5);
        assert!((centre.x - textures::materials::srgb(p[0], p[1], p[2]).x).abs() < 1e-6);
        // Beyond the ends, the end texels, decoded: not a blend with the
        // other end, as a wrapping read would give (and give at u = 0 too).
        let end = |x: u32| {
            let p = g.sunlight.0.get_pixel(x, 0);
            textures::materials::srgb(p[0], p[1], p[2])
        };
        assert_eq!(g.sunlight.at(-1.0, 0.0), end(0));
        assert_eq!(g.sunlight.at(0.0, 0.0), end(0));
        assert_eq!(g.sunlight.at(2.0, 0.0), end(w - 1));
        assert_ne!(end(0), end(w - 1), "the test needs ends that differ");
    }

    #[test]
    fn noon_is_brighter_than_sunset_and_night_darkest() {
        let g = Gradients::load().unwrap();
        let brightness = |phase| g.daylight(sun_direction(phase)).sun.length();
        assert!(brightness(0.5) > brightness(0.74));
        assert!(brightness(0.74) > brightness(0.0));
        // By night the light comes from above: the moon.
        assert!(g.daylight(sun_direction(0.0)).direction.y > 0.0);
    }
}
