//! Chapter 04: exponential distance fog. Chapter 03's terrain, seen
//! through air that thickens with distance and fades into the sky, which
//! also lets the far plane come in and the distant chunks go.

use common::chapter::uniform_entry;
use common::texture::depth_view;
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, ShaderError, ShaderFile, Target, View, anyhow, egui, shader,
    wgpu,
};
use terrain::heightfield::TerrainSettings;
use terrain::{KEEP_ALL, SKY, Shading, Sun, TerrainRenderer, Viewpoint, start_camera};

pub const VIEWS: &[View] = &[
    View::mode("default", "the terrain in a light haze, fading into the sky"),
    View::mode("no-fog", "the same view without fog: a hard edge where the world ends"),
    View::mode("dense", "a dust storm: thick fog, and a far plane pulled in to 588 m"),
];

// ANCHOR: settings
/// The two numbers of exponential fog: visibility = exp(−(distance · density)^gradient).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogSettings {
    /// Per metre.
    pub density: f32,
    pub gradient: f32,
}

impl FogSettings {
    pub const HAZE: Self = Self { density: 0.0015, gradient: 1.5 };
    pub const NONE: Self = Self { density: 0.0, gradient: 1.5 };
    pub const DUST_STORM: Self = Self { density: 0.004, gradient: 2.0 };

    /// How much of a surface at `distance` metres shows through.
    pub fn visibility(&self, distance: f32) -> f32 {
        (-(distance * self.density).powf(self.gradient)).exp()
    }

    /// The distance beyond which less than 1/255 of a surface shows, so
    /// that an 8-bit picture cannot tell it from the sky: solve
    /// (d · density)^gradient = ln 255 for d.
    pub fn opaque_distance(&self) -> f32 {
        if self.density <= 0.0 { f32::INFINITY } else { 255f32.ln().powf(1.0 / self.gradient) / self.density }
    }

    /// Where to put the camera's far plane in this fog: nothing beyond the
    /// opaque distance can be seen, so nothing there needs drawing.
    pub fn far_plane(&self) -> f32 {
        self.opaque_distance().min(MAX_FAR)
    }
}
// ANCHOR_END: settings

/// `Fog` in fog.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FogUniform {
    colour: [f32; 4],
    density: f32,
    gradient: f32,
    _padding: [f32; 2],
}

/// The farthest the camera ever draws, fog or not.
pub const MAX_FAR: f32 = 3000.0;

/// The terrain shader with fog (`fog.wgsl`, importing `terrain.wgsl`).
pub fn fog_shader() -> ShaderFile {
    shader!("fog/fog.wgsl", imports: ["terrain/terrain.wgsl"])
}

/// The fog uniform and its bind group (group 1 of fog.wgsl), for this
/// chapter and for later ones whose objects stand in the same air.
pub struct FogBinding {
    pub layout: wgpu::BindGroupLayout,
    buffer: wgpu::Buffer,
    pub group: wgpu::BindGroup,
}

impl FogBinding {
    pub fn new(device: &wgpu::Device) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("fog"),
            entries: &[uniform_entry(0, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<FogUniform>())],
        });
        let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("fog"),
            contents: &[0; std::mem::size_of::<FogUniform>()],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("fog"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
        });
        Self { layout, buffer, group }
    }

    /// Writes `settings`, with the clear colour `SKY` as the fog colour.
    pub fn write(&self, queue: &wgpu::Queue, settings: FogSettings) {
        self.write_with_colour(queue, settings, [SKY.r as f32, SKY.g as f32, SKY.b as f32]);
    }

    /// Writes `settings` with fog of `colour` (linear RGB), for skies that change.
    pub fn write_with_colour(&self, queue: &wgpu::Queue, settings: FogSettings, colour: [f32; 3]) {
        let fog = FogUniform {
            colour: [colour[0], colour[1], colour[2], 1.0],
            density: settings.density,
            gradient: settings.gradient,
            _padding: [0.0; 2],
        };
        queue.write_buffer(&self.buffer, 0, bytemuck::bytes_of(&fog));
    }
}

pub struct FogChapter {
    pub terrain: TerrainRenderer,
    pub fog: FogSettings,
    pub camera: Camera,
    pub controller: FlyController,
    fog_binding: FogBinding,
    viewpoint: Viewpoint,
    layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    depth: wgpu::TextureView,
    target: Target,
    pub drawn: usize,
    regenerate_requested: bool,
}

impl Chapter for FogChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "04 · Fog";
    const VIEWS: &'static [View] = VIEWS;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 10;

    fn gpu_needs() -> common::GpuNeeds {
        terrain::gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    fn prepare(gpu: &Gpu) -> Option<common::Preparation> {
        terrain::TerrainData::prepare(gpu, TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let terrain = TerrainRenderer::new(gpu, TerrainSettings::default());
        let fog_binding = FogBinding::new(device);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("fog"),
            bind_group_layouts: &[Some(&terrain.bind_group_layout), Some(&fog_binding.layout)],
            immediate_size: 0,
        });
        let pipeline = terrain.pipeline(gpu, &fog_shader(), &layout, target.format)?;
        Ok(Self {
            camera: start_camera(terrain.field(), target.aspect()),
            controller: FlyController { speed: 40.0, ..Default::default() },
            fog: FogSettings::HAZE,
            viewpoint: terrain.viewpoint(device),
            terrain,
            fog_binding,
            layout,
            pipeline,
            depth: depth_view(device, target.width, target.height),
            target,
            drawn: 0,
            regenerate_requested: false,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
    }

    fn apply_view(&mut self, view: usize) {
        self.fog = match VIEWS[view].name {
            "no-fog" => FogSettings::NONE,
            "dense" => FogSettings::DUST_STORM,
            _ => FogSettings::HAZE,
        };
    }

    fn reset_camera(&mut self, _view: usize) {
        self.camera = start_camera(self.terrain.field(), self.target.aspect());
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        if std::mem::take(&mut self.regenerate_requested) {
            self.terrain.regenerate(gpu);
        }
        // Nothing past the opaque distance can be seen: stop drawing there.
        self.camera.far = self.fog.far_plane();
        self.fog_binding.write(&gpu.queue, self.fog);
        self.terrain.aim(&gpu.queue, &mut self.viewpoint, &self.camera, Sun::AFTERNOON, Shading::Shaded, KEEP_ALL);

        // Clear to the fog colour: where there is no ground, the fog's
        // "infinitely far" is what shows.
        let mut pass = frame.scene_pass("terrain", SKY, &self.depth);
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(1, &self.fog_binding.group, &[]);
        self.drawn = self.terrain.draw(&mut pass, &self.viewpoint);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("density (per m)"));
        ui.add(egui::Slider::new(&mut self.fog.gradient, 0.5..=4.0).text("gradient"));
        ui.label(format!(
            "opaque beyond {:.0} m; far plane {:.0} m; chunks drawn {} / {}",
            self.fog.opaque_distance(),
            self.camera.far,
            self.drawn,
            self.terrain.mesh().bounds.len()
        ));
        ui.collapsing("terrain", |ui| {
            self.regenerate_requested |= self.terrain.settings_ui(ui);
        });
        ui.add(egui::Slider::new(&mut self.controller.speed, 5.0..=400.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        format!("far plane {:.0} m; {}", self.camera.far, self.terrain.stats(self.drawn))
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.pipeline = self.terrain.pipeline(gpu, &fog_shader(), &self.layout, self.target.format)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visibility_falls_from_one_to_nothing() {
        let fog = FogSettings::HAZE;
        assert_eq!(fog.visibility(0.0), 1.0);
        assert!(fog.visibility(100.0) > fog.visibility(1000.0));
        // At 1/density metres the exponent is 1 whatever the gradient: e⁻¹.
        let one_over_e = fog.visibility(1.0 / fog.density);
        assert!((one_over_e - (-1f32).exp()).abs() < 1e-6);
        assert_eq!(FogSettings::NONE.visibility(1e6), 1.0);
    }

    #[test]
    fn the_opaque_distance_is_where_one_255th_is_left() {
        for fog in [FogSettings::HAZE, FogSettings::DUST_STORM] {
            let d = fog.opaque_distance();
            assert!((fog.visibility(d) - 1.0 / 255.0).abs() < 1e-5, "{fog:?}");
        }
        assert!(FogSettings::NONE.opaque_distance().is_infinite());
        assert!((FogSettings::DUST_STORM.opaque_distance() - 588.0).abs() < 1.0);
    }
}
