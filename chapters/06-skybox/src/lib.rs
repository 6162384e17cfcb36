//! Chapter 06: a sky box. Two cube maps, day and night, blended by the time
//! of day and turning with it; the sun painted in the day sky is the light
//! the ground is lit by, and the fog takes the colour of the sky's horizon.
//! The scene is chapter 05's Mars plain.

use std::f32::consts::TAU;

use common::chapter::uniform_entry;
use common::glam::{Mat4, Quat, Vec3, Vec4};
use common::texture::{ColorSpace, cubemap_from_images, decode_faces};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, Frame, Gpu, Input, ShaderError, ShaderFile, Target, View, anyhow, egui, image, shader, wgpu,
};
use instancing::InstancingChapter;
use terrain::{KEEP_ALL, Sun};

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

// ANCHOR: sun_path
/// Where the sun rises: on the eastern horizon (+x), a little south (+z).
pub const SUNRISE: Vec3 = Vec3::new(0.957_826_3, 0.0, 0.287_347_9); // normalize(1, 0, 0.3)

/// The turn of the sky, sun and stars, at a time of day (`phase`: 0
/// midnight, 0.25 sunrise, 0.5 noon, 0.75 sunset): about the z (north–south)
/// axis, which carries the sun from the eastern horizon up over the southern
/// sky and down in the west (−x).
pub fn celestial_turn(phase: f32) -> Quat {
    Quat::from_rotation_z(TAU * (phase - 0.25))
}

/// The light at a time of day: the sun, turned with the sky, fading out as
/// it sinks below the horizon. The sky shader draws the sun in this very
/// direction, so what lights the ground is what the sky shows.
pub fn sun_at(phase: f32) -> Sun {
    let direction = celestial_turn(phase) * SUNRISE;
    Sun { direction, strength: smoothstep(-0.05, 0.15, direction.y) }
}

/// How much of the day sky shows, from the sun's height.
pub fn day_blend(sun: Sun) -> f32 {
    smoothstep(-0.15, 0.1, sun.direction.y)
}
// ANCHOR_END: sun_path

fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let t = ((x - edge0) / (edge1 - edge0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

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

pub const VIEWS: &[View] = &[
    View { name: "day", about: "mid-morning: the sun high in the east, the plain in full light" },
    View { name: "dusk", about: "facing west as the sun sets in its blue Martian halo" },
    View { name: "night", about: "stars over the plain, lit by the sky alone" },
];

/// Time of day each view starts at.
fn start_phase(view: &str) -> f32 {
    match view {
        "dusk" => 0.745,
        "night" => 0.02,
        _ => 0.40,
    }
}

/// `Sky` in sky.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SkyUniform {
    clip_to_world: [[f32; 4]; 4],
    world_to_day: [[f32; 4]; 4],
    world_to_stars: [[f32; 4]; 4],
    sun: [f32; 4],
}

/// The day atmosphere's slow drift about the vertical: a tenth of a turn a day.
fn dust_drift(phase: f32) -> Quat {
    Quat::from_rotation_y(TAU * 0.1 * phase)
}

fn sky_shader() -> ShaderFile {
    shader!("skybox/sky.wgsl")
}

pub struct SkyboxChapter {
    /// Chapter 05's scene: terrain, fog and rocks.
    pub plain: InstancingChapter,
    /// The time of day at scene time 0, and how long a day lasts (s).
    pub start_phase: f32,
    pub day_seconds: f32,
    horizons: [[f32; 3]; 2],
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    format: wgpu::TextureFormat,
    phase: f32,
}

impl SkyboxChapter {
    // ANCHOR: time_of_day
    /// Sets the time of day from scene time: the sun, the light on the
    /// ground, and the fog colour between the night and day horizons.
    pub fn set_time(&mut self, time: f32) {
        self.phase = (self.start_phase + time / self.day_seconds).rem_euclid(1.0);
        let sun = sun_at(self.phase);
        let blend = day_blend(sun);
        let [day, night] = self.horizons;
        self.plain.sun = sun;
        self.plain.fog_colour = [0, 1, 2].map(|c| night[c] + (day[c] - night[c]) * blend);
    }
    // ANCHOR_END: time_of_day

    /// Writes the uniforms for drawing the plain and the sky from `camera`.
    pub fn prepare(&mut self, gpu: &Gpu, camera: &Camera, clip: Vec4) {
        self.plain.prepare(gpu, camera, clip);
        let turn_only = Mat4::look_to_rh(Vec3::ZERO, camera.forward(), Vec3::Y);
        let sun = self.plain.sun;
        let uniform = SkyUniform {
            clip_to_world: (camera.projection() * turn_only).inverse().to_cols_array_2d(),
            world_to_day: Mat4::from_quat(dust_drift(self.phase).inverse()).to_cols_array_2d(),
            world_to_stars: Mat4::from_quat(celestial_turn(self.phase).inverse()).to_cols_array_2d(),
            sun: sun.direction.normalize().extend(day_blend(sun)).into(),
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }

    /// Draws the plain, then the sky wherever the plain left the depth at 1.
    pub fn draw(&mut self, pass: &mut wgpu::RenderPass<'_>) {
        self.plain.draw(pass);
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

// ANCHOR: pipeline
fn sky_pipeline(
    gpu: &Gpu,
    layout: &wgpu::PipelineLayout,
    format: wgpu::TextureFormat,
) -> Result<wgpu::RenderPipeline, ShaderError> {
    let module = sky_shader().module(&gpu.device)?;
    gpu.catch_validation(|| {
        gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("sky"),
            layout: Some(layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_sky"),
                buffers: &[],
                compilation_options: Default::default(),
            },
            primitive: Default::default(),
            // Test against the scene's depth, but leave it alone: the sky is
            // at the far plane, and passes only where the buffer still says 1.
            depth_stencil: Some(wgpu::DepthStencilState {
                format: common::texture::DEPTH_FORMAT,
                depth_write_enabled: Some(false),
                depth_compare: Some(wgpu::CompareFunction::LessEqual),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_sky"),
                targets: &[Some(format.into())],
                compilation_options: Default::default(),
            }),
            multiview_mask: None,
            cache: None,
        })
    })
    .map_err(ShaderError)
}
// ANCHOR_END: pipeline

impl Chapter for SkyboxChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "06 · Sky box";
    const VIEWS: &'static [View] = VIEWS;
    const SNAPSHOT_TIME: f32 = 0.0;
    const KEYS: &'static [(&'static str, &'static str)] = common::FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let plain = InstancingChapter::new(gpu, target)?;
        // Decoded once: for the cube maps and to measure their horizons.
        let (day_faces, night_faces) = (decode_faces(&DAY)?, decode_faces(&NIGHT)?);
        let day = cubemap_from_images(device, &gpu.queue, &day_faces, ColorSpace::Srgb, "day sky");
        let night = cubemap_from_images(device, &gpu.queue, &night_faces, ColorSpace::Srgb, "night sky");
        let horizons = [horizon_colour(&day_faces), horizon_colour(&night_faces)];

        let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("sky"),
            contents: &[0; std::mem::size_of::<SkyUniform>()],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
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
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sky"),
            layout: &bind_group_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&day.view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&night.view) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&day.sampler) },
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("sky"),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let pipeline = sky_pipeline(gpu, &layout, target.format)?;
        Ok(Self {
            plain,
            start_phase: start_phase("day"),
            day_seconds: 240.0,
            horizons,
            uniform,
            bind_group,
            layout,
            pipeline,
            format: target.format,
            phase: 0.0,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.plain.resize(gpu, target);
    }

    fn select_view(&mut self, view: usize) {
        self.plain.select_view(0);
        let name = VIEWS[view].name;
        self.start_phase = start_phase(name);
        if name == "dusk" {
            // Turn to face the sunset: west (−x), a little south, a little up.
            self.plain.camera.yaw = 0.95f32.atan2(-0.3);
            self.plain.camera.pitch = 4f32.to_radians();
        }
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.plain.update(input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.set_time(frame.time);
        let camera = self.plain.camera;
        self.prepare(gpu, &camera, KEEP_ALL);
        let depth = self.plain.depth();
        // The clear colour is never seen: the sky covers whatever the plain leaves.
        let mut pass = frame.scene_pass("plain and sky", terrain::SKY, &depth);
        self.draw(&mut pass);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let hours = self.phase * 24.0;
        ui.label(format!("time of day {:02}:{:02}", hours as u32, ((hours.fract()) * 60.0) as u32));
        ui.add(egui::Slider::new(&mut self.start_phase, 0.0..=1.0).text("time of day at t = 0"));
        ui.add(egui::Slider::new(&mut self.day_seconds, 10.0..=1200.0).logarithmic(true).text("day length (s)"));
        ui.separator();
        self.plain.ui(ui);
    }

    fn stats(&self) -> String {
        format!("time of day {:.3}; {}", self.phase, self.plain.stats())
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.plain.reload_shaders(gpu)?;
        self.pipeline = sky_pipeline(gpu, &self.layout, self.format)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sun_rises_in_the_east_peaks_at_noon_and_sets_in_the_west() {
        let at = |phase| sun_at(phase).direction;
        assert!(at(0.25).y.abs() < 1e-5 && at(0.25).x > 0.9, "sunrise in the east");
        assert!(at(0.5).y > 0.95, "noon overhead");
        assert!(at(0.75).y.abs() < 1e-5 && at(0.75).x < -0.9, "sunset in the west");
        assert!(at(0.0).y < -0.9, "midnight below");
        assert_eq!(sun_at(0.5).strength, 1.0);
        assert_eq!(sun_at(0.0).strength, 0.0);
        assert_eq!(day_blend(sun_at(0.5)), 1.0);
        assert_eq!(day_blend(sun_at(0.0)), 0.0);
    }

    #[test]
    fn horizons_are_butterscotch_by_day_and_dark_by_night() {
        let day = horizon_colour(&decode_faces(&DAY).unwrap());
        let night = horizon_colour(&decode_faces(&NIGHT).unwrap());
        assert!(day[0] > day[1] && day[1] > day[2] && day[0] > 0.4, "{day:?}");
        assert!(night.iter().all(|&c| c < 0.01), "{night:?}");
    }
}
