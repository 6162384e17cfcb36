//! Chapter 06: a sky box. Two cube maps, day and night, blended by the time
//! of day and turning with it; the sun painted in the day sky is the light
//! the ground is lit by, and the fog takes the colour of the sky's horizon.
//! The scene is chapter 05's Mars plain, under a `Sky` that chapter 07 reuses.

use std::f32::consts::TAU;

use common::chapter::uniform_entry;
use common::glam::{Mat4, Quat, Vec3};
use common::texture::{ColorSpace, Texture, cubemap_from_images, decode_faces, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, ShaderError, ShaderFile, Target, View, anyhow, egui, fullscreen,
    image, shader, wgpu,
};
use fog::FogSettings;
use instancing::{DrawCalls, MarsPlain, Setup, plain_camera};
use terrain::{KEEP_ALL, Sun, Viewpoint};

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
    shader!("skybox/sky.wgsl", imports: ["common/fullscreen.wgsl"])
}

// ANCHOR: pipeline
fn sky_pipeline(
    gpu: &Gpu,
    layout: &wgpu::PipelineLayout,
    format: wgpu::TextureFormat,
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
        fullscreen::pipeline(&gpu.device, "sky", layout, &module, "fs_sky", format.into(), Some(depth))
    })
    .map_err(ShaderError)
}
// ANCHOR_END: pipeline

/// The sky's uniform for one camera. A frame that draws the sky from several
/// cameras has one each, like chapter 03's terrain viewpoints.
pub struct SkyViewpoint {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
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
    layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    format: wgpu::TextureFormat,
}
// ANCHOR_END: sky

impl Sky {
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat) -> anyhow::Result<Self> {
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
        let pipeline = sky_pipeline(gpu, &layout, format)?;
        Ok(Self { day, night, horizons, bind_group_layout, layout, pipeline, format })
    }

    pub fn viewpoint(&self, device: &wgpu::Device) -> SkyViewpoint {
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
        SkyViewpoint { uniform, bind_group }
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

    /// Draws the sky wherever the depth buffer still holds 1: call it after
    /// everything else in the pass.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &SkyViewpoint) {
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &viewpoint.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }

    pub fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.pipeline = sky_pipeline(gpu, &self.layout, self.format)?;
        Ok(())
    }
}

pub const VIEWS: &[View] = &[
    View::mode("day", "mid-morning: the sun high in the east, the plain in full light"),
    View::preset("dusk", "facing west as the sun sets in its blue Martian halo"),
    View::mode("night", "stars over the plain, lit by the sky alone"),
];

/// Time of day each view starts at.
fn start_phase(view: &str) -> f32 {
    match view {
        "dusk" => 0.745,
        "night" => 0.02,
        _ => 0.40,
    }
}

/// The plain's camera, turned to face the sunset: west (−x), a little
/// south, a little up.
fn dusk_camera(field: &terrain::heightfield::HeightField, aspect: f32) -> Camera {
    Camera { yaw: 0.95f32.atan2(-0.3), pitch: 4f32.to_radians(), ..plain_camera(field, aspect) }
}

pub struct SkyboxChapter {
    pub plain: MarsPlain,
    pub sky: Sky,
    pub camera: Camera,
    pub controller: FlyController,
    pub fog: FogSettings,
    pub rocks: Setup,
    /// The time of day at scene time 0, and how long a day lasts (s).
    pub start_phase: f32,
    pub day_seconds: f32,
    /// The time of day of the last frame (0 midnight, 0.5 noon).
    phase: f32,
    viewpoint: (Viewpoint, SkyViewpoint),
    depth: wgpu::TextureView,
    target: Target,
    draw_calls: DrawCalls,
}

impl SkyboxChapter {
    // ANCHOR: time_of_day
    /// The time of day at scene time `time`: 0 midnight, 0.5 noon.
    pub fn phase_at(&self, time: f32) -> f32 {
        (self.start_phase + time / self.day_seconds).rem_euclid(1.0)
    }
    // ANCHOR_END: time_of_day
}

impl Chapter for SkyboxChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0107; outliers at most 0.1%.
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.016, outliers: 0.002 };
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "06 · Sky box";
    const VIEWS: &'static [View] = VIEWS;
    const SNAPSHOT_TIME: f32 = 0.0;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn gpu_needs() -> common::GpuNeeds {
        terrain::gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    fn prepare(gpu: &Gpu) -> Option<common::Preparation> {
        terrain::TerrainData::prepare(gpu, terrain::heightfield::TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let plain = MarsPlain::new(gpu, target.format)?;
        let sky = Sky::new(gpu, target.format)?;
        Ok(Self {
            camera: plain_camera(plain.terrain.field(), target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            fog: FogSettings::HAZE,
            rocks: instancing::Setup { rocks: 200_000, mode: instancing::Mode::Instanced, terrain: true },
            start_phase: start_phase("day"),
            day_seconds: 240.0,
            phase: start_phase("day"),
            viewpoint: (plain.terrain.viewpoint(&gpu.device), sky.viewpoint(&gpu.device)),
            depth: depth_view(&gpu.device, target.width, target.height),
            plain,
            sky,
            target,
            draw_calls: DrawCalls::default(),
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
    }

    fn apply_view(&mut self, view: usize) {
        self.start_phase = start_phase(VIEWS[view].name);
    }

    fn reset_camera(&mut self, view: usize) {
        let (field, aspect) = (self.plain.terrain.field(), self.target.aspect());
        self.camera = match VIEWS[view].name {
            "dusk" => dusk_camera(field, aspect),
            _ => plain_camera(field, aspect),
        };
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        // The time of day sets the light on the ground and the fog's colour.
        self.phase = self.phase_at(frame.time);
        self.camera.far = self.fog.far_plane();
        self.plain.set_air(&gpu.queue, self.fog, self.sky.fog_colour(self.phase));
        let (ground, sky) = &mut self.viewpoint;
        self.plain.aim(&gpu.queue, ground, &self.camera, sun_at(self.phase), KEEP_ALL);
        self.sky.aim(&gpu.queue, sky, &self.camera, self.phase);
        // The clear colour is never seen: the sky covers whatever the plain leaves.
        let mut pass = frame.scene_pass("plain and sky", terrain::SKY, &self.depth);
        self.draw_calls = self.plain.draw(&mut pass, ground, self.rocks);
        self.sky.draw(&mut pass, sky);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let hours = self.phase * 24.0;
        ui.label(format!("time of day {:02}:{:02}", hours as u32, ((hours.fract()) * 60.0) as u32));
        ui.add(egui::Slider::new(&mut self.start_phase, 0.0..=1.0).text("time of day at t = 0"));
        ui.add(egui::Slider::new(&mut self.day_seconds, 10.0..=1200.0).logarithmic(true).text("day length (s)"));
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        let max = self.plain.rocks_placed();
        ui.add(egui::Slider::new(&mut self.rocks.rocks, 0..=max).logarithmic(true).text("rocks"));
        ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=200.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        let calls = self.draw_calls;
        format!(
            "time of day {:.3}; {} rocks; {} draw calls ({} terrain chunks, {} for the rocks, 1 for the sky)",
            self.phase,
            self.rocks.rocks.min(self.plain.rocks_placed()),
            calls.total() + 1,
            calls.terrain,
            calls.rocks
        )
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.plain.reload_shaders(gpu)?;
        self.sky.reload_shaders(gpu)
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
