//! Chapter 07: water. A lake on the Mars plain, drawn from two extra
//! pictures of the scene each frame (one reflected in the water, one seen
//! through it), mixed by the Fresnel effect, rippled by a DuDv map, lit
//! by a normal map, and moved by eight sine waves. The Mars scene, complete.

pub mod waves;

use common::chapter::{sampler_entry, scene_pass, texture_entry, uniform_entry};
use common::glam::{Vec2, Vec4};
use common::texture::{ColorSpace, Texture, depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, Mesh, MeshData, PassTimer, ShaderError, ShaderFile, Target,
    View, anyhow, egui, fullscreen, primitives, shader, wgpu,
};
use fog::FogSettings;
use instancing::{MarsPlain, Mode, Setup, plain_camera};
use skybox::{Sky, SkyViewpoint, sun_at};
use terrain::heightfield::HeightField;
use terrain::{KEEP_ALL, SKY, Viewpoint};

pub const VIEWS: &[View] = &[
    View::mode("default", "the lake: reflection and refraction mixed by Fresnel, ripples and waves"),
    View::mode("reflection", "the reflection picture, full screen: the scene above the water, from below it"),
    View::mode("refraction", "the refraction picture, full screen: the scene below the water"),
    View::preset("waves", "the geometric waves three times as strong, seen from 6 m above the water"),
    View::mode("no-fresnel", "reflection and refraction half and half at every angle"),
];

/// What the overlay changes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaterSettings {
    /// Size of the reflection and refraction pictures, as a fraction of the screen's.
    pub resolution: f32,
    /// 0 flat, 1 the lake's waves.
    pub wave_strength: f32,
    pub fresnel: bool,
    /// DuDv distortion of the pictures, in texture units.
    pub ripples: f32,
}

impl Default for WaterSettings {
    fn default() -> Self {
        Self { resolution: 0.5, wave_strength: 1.0, fresnel: true, ripples: 0.012 }
    }
}

// ANCHOR: lake
/// Where the lake is: a square 520 m across, 260 m ahead of `camera`, its
/// level at the 30th percentile of the ground's heights in that square, so
/// that the lowest third of it is under water.
pub fn find_lake(field: &HeightField, camera: &Camera) -> (Vec2, f32, f32) {
    let forward = Vec2::new(camera.forward().x, camera.forward().z).normalize();
    let centre = Vec2::new(camera.position.x, camera.position.z) + forward * 260.0;
    let size = 520.0;
    let mut heights: Vec<f32> = (0..64 * 64)
        .map(|i| {
            let p = centre + (Vec2::new((i % 64) as f32, (i / 64) as f32) / 63.0 - 0.5) * size;
            field.height_at(p.x, p.y)
        })
        .collect();
    heights.sort_by(f32::total_cmp);
    (centre, size, heights[heights.len() * 3 / 10])
}

/// Standing at the lake's southern shore, `height` metres above the water,
/// looking north across it towards the cliff.
pub fn lake_camera(field: &HeightField, centre: Vec2, size: f32, level: f32, height: f32, aspect: f32) -> Camera {
    let eye = Vec2::new(centre.x, centre.y + 0.42 * size);
    let eye = common::glam::Vec3::new(eye.x, (level + height).max(field.height_at(eye.x, eye.y) + 2.0), eye.y);
    let target = common::glam::Vec3::new(centre.x, level, centre.y - 0.2 * size);
    Camera { far: 3000.0, near: 0.1, ..Camera::looking_at(eye, target, aspect) }
}

/// The camera mirrored in the water: as far below the surface as the real
/// one is above it, looking as far up as the real one looks down.
pub fn mirrored(camera: &Camera, level: f32) -> Camera {
    let mut mirror = *camera;
    mirror.position.y = 2.0 * level - camera.position.y;
    mirror.pitch = -camera.pitch;
    mirror
}
// ANCHOR_END: lake

/// An offscreen picture of the scene, with its own depth buffer. (Cloning
/// copies two reference-counted handles, not the textures.)
#[derive(Clone)]
struct Picture {
    colour: wgpu::TextureView,
    depth: wgpu::TextureView,
}

impl Picture {
    fn new(device: &wgpu::Device, format: wgpu::TextureFormat, (width, height): (u32, u32)) -> Self {
        let colour = device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("water picture"),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            })
            .create_view(&Default::default());
        Self { colour, depth: depth_view(device, width, height) }
    }
}

/// The uniforms for drawing the plain and the sky from one camera. The
/// frame draws three pictures, each from its own camera, so it keeps three
/// of these, and all three pictures are recorded before one submit.
struct Eye {
    ground: Viewpoint,
    sky: SkyViewpoint,
}

/// `Water` in water.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct WaterUniform {
    level_time: [f32; 4],
    ripples: [f32; 4],
    waves: [[f32; 4]; 8],
    speeds: [[f32; 4]; 2],
}

fn water_shader() -> ShaderFile {
    shader!("water/water.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "water/waves.wgsl"])
}

fn show_shader() -> ShaderFile {
    shader!("water/show.wgsl", imports: ["common/fullscreen.wgsl"])
}

/// Which of the frame's pictures an `Eye` draws.
const REFLECTION: usize = 0;
const REFRACTION: usize = 1;
const MAIN: usize = 2;

/// The time of day the lake is seen at (mid-morning, chapter 06's `day`).
const START_PHASE: f32 = 0.40;

pub struct WaterChapter {
    pub plain: MarsPlain,
    pub sky: Sky,
    pub camera: Camera,
    pub controller: FlyController,
    pub fog: FogSettings,
    pub rocks: Setup,
    pub settings: WaterSettings,
    /// Seconds in a day (chapter 06's slider).
    pub day_seconds: f32,
    pub level: f32,
    /// The lake's centre (x, z) and side, metres.
    pub centre: Vec2,
    pub size: f32,
    grid: Mesh,
    eyes: [Eye; 3],
    reflection: Picture,
    refraction: Picture,
    depth: wgpu::TextureView,
    dudv: Texture,
    normal_map: Texture,
    clamp_sampler: wgpu::Sampler,
    uniform: wgpu::Buffer,
    water_layout: wgpu::BindGroupLayout,
    water_group: wgpu::BindGroup,
    pipeline_layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    show_layout: wgpu::BindGroupLayout,
    show_groups: [wgpu::BindGroup; 2],
    show_pipeline_layout: wgpu::PipelineLayout,
    show_pipeline: wgpu::RenderPipeline,
    target: Target,
    pictures_size: (u32, u32),
}

impl WaterChapter {
    fn water_group(&self, device: &wgpu::Device) -> wgpu::BindGroup {
        let textures = [
            &self.reflection.colour,
            &self.refraction.colour,
            &self.refraction.depth,
            &self.dudv.view,
            &self.normal_map.view,
        ];
        water_group(device, &self.water_layout, &self.uniform, textures, [&self.dudv.sampler, &self.clamp_sampler])
    }

    /// (Re)creates the two pictures when the resolution setting or the
    /// screen's size changes.
    fn resize_pictures(&mut self, device: &wgpu::Device) {
        let size = picture_size(self.target, self.settings.resolution);
        if size == self.pictures_size {
            return;
        }
        self.pictures_size = size;
        self.reflection = Picture::new(device, self.target.format, size);
        self.refraction = Picture::new(device, self.target.format, size);
        self.water_group = self.water_group(device);
        self.show_groups =
            show_groups(device, &self.show_layout, [&self.reflection, &self.refraction], &self.clamp_sampler);
    }

    // ANCHOR: picture
    /// Records the plain and the sky, seen from `camera` through eye `eye`,
    /// into `colour` and `depth`, keeping only what `clip` keeps. Each
    /// picture has its own eye, so its uniforms are not overwritten by the
    /// next picture's before the one submit at the end of the frame.
    #[allow(clippy::too_many_arguments)]
    fn take_picture(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        (label, eye): (&'static str, usize),
        (colour, depth): (&wgpu::TextureView, &wgpu::TextureView),
        camera: &Camera,
        clip: Vec4,
        phase: f32,
    ) {
        let Eye { ground, sky } = &mut self.eyes[eye];
        self.plain.aim(&gpu.queue, ground, camera, sun_at(phase), clip);
        self.sky.aim(&gpu.queue, sky, camera, phase);
        let mut pass = scene_pass(encoder, timer, label, colour, SKY, depth);
        self.plain.draw(&mut pass, ground, self.rocks);
        self.sky.draw(&mut pass, sky);
    }
    // ANCHOR_END: picture

    /// Draws picture `which` (0 reflection, 1 refraction) over the whole frame.
    fn show(&self, frame: &mut Frame, which: usize) {
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "show picture", frame.target, Some(SKY));
        pass.set_pipeline(&self.show_pipeline);
        pass.set_bind_group(0, &self.show_groups[which], &[]);
        pass.draw(0..3, 0..1);
    }
}

fn picture_size(target: Target, resolution: f32) -> (u32, u32) {
    let scale = resolution.clamp(0.1, 1.0);
    (((target.width as f32 * scale) as u32).max(1), ((target.height as f32 * scale) as u32).max(1))
}

/// The water's bind group: the uniform, the two pictures, the refraction's
/// depth, the DuDv and normal maps, and a repeating and a clamping sampler.
fn water_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniform: &wgpu::Buffer,
    textures: [&wgpu::TextureView; 5],
    samplers: [&wgpu::Sampler; 2],
) -> wgpu::BindGroup {
    let mut entries = vec![wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() }];
    for (i, view) in textures.into_iter().enumerate() {
        entries
            .push(wgpu::BindGroupEntry { binding: 1 + i as u32, resource: wgpu::BindingResource::TextureView(view) });
    }
    for (i, sampler) in samplers.into_iter().enumerate() {
        entries.push(wgpu::BindGroupEntry { binding: 6 + i as u32, resource: wgpu::BindingResource::Sampler(sampler) });
    }
    device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some("water"), layout, entries: &entries })
}

/// Bind groups that let the show pipeline read each picture.
fn show_groups(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    pictures: [&Picture; 2],
    sampler: &wgpu::Sampler,
) -> [wgpu::BindGroup; 2] {
    pictures.map(|picture| {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("show picture"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&picture.colour) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(sampler) },
            ],
        })
    })
}

fn build_pipelines(
    gpu: &Gpu,
    layout: &wgpu::PipelineLayout,
    show_layout: &wgpu::PipelineLayout,
    format: wgpu::TextureFormat,
) -> Result<(wgpu::RenderPipeline, wgpu::RenderPipeline), ShaderError> {
    let water = water_shader().module(gpu)?;
    let show = show_shader().module(gpu)?;
    gpu.catch_validation(|| {
        let surface = gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("water"),
            layout: Some(layout),
            vertex: wgpu::VertexState {
                module: &water,
                entry_point: Some("vs_water"),
                buffers: &[Some(common::Vertex::LAYOUT)],
                compilation_options: Default::default(),
            },
            primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
            depth_stencil: depth_test(),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &water,
                entry_point: Some("fs_water"),
                // Alpha blending: shallow water lets the lake bed behind it show.
                targets: &[Some(wgpu::ColorTargetState {
                    format,
                    blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                    write_mask: wgpu::ColorWrites::ALL,
                })],
                compilation_options: Default::default(),
            }),
            multiview_mask: None,
            cache: None,
        });
        let picture =
            fullscreen::pipeline(&gpu.device, "show picture", show_layout, &show, "fs_show", format.into(), None);
        (surface, picture)
    })
    .map_err(ShaderError)
}

impl Chapter for WaterChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0123; outliers at most 0.1%.
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.018, outliers: 0.002 };
    const PREPARES_IN_STEPS: bool = true;
    const TITLE: &'static str = "07 · Water";
    const VIEWS: &'static [View] = VIEWS;
    const SNAPSHOT_TIME: f32 = 0.0;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;
    const BENCH_FRAMES: u32 = 5;

    /// Clip distances where the adapter has them; a fragment discard otherwise.
    fn gpu_needs() -> common::GpuNeeds {
        terrain::gpu_needs()
    }

    /// The terrain is the long part of starting: in steps, so a page shows its progress.
    fn prepare(gpu: &Gpu) -> Option<common::Preparation> {
        terrain::TerrainData::prepare(gpu, terrain::heightfield::TerrainSettings::default())
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let plain = MarsPlain::new(gpu, target.format)?;
        let sky = Sky::new(gpu, target.format)?;
        let field = plain.terrain.field();
        let (centre, size, level) = find_lake(field, &plain_camera(field, target.aspect()));
        let mut grid = primitives::plane(256);
        for v in &mut grid.vertices {
            v.position = [centre.x + v.position[0] * size, 0.0, centre.y + v.position[2] * size];
        }
        let grid = MeshData::upload(&grid, device, "water grid");

        let asset = |name, bytes| Texture::from_bytes(device, &gpu.queue, name, bytes, ColorSpace::Linear);
        let dudv = asset("assets/water/dudv.png", include_bytes!("../../../assets/water/dudv.png"))?;
        let normal_map = asset("assets/water/normal.png", include_bytes!("../../../assets/water/normal.png"))?;
        let clamp_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("clamp"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("water"),
            contents: &[0; std::mem::size_of::<WaterUniform>()],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let float = wgpu::TextureSampleType::Float { filterable: true };
        let water_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("water"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT, std::mem::size_of::<WaterUniform>()),
                texture_entry(1, float),
                texture_entry(2, float),
                texture_entry(3, wgpu::TextureSampleType::Depth),
                texture_entry(4, float),
                texture_entry(5, float),
                sampler_entry(6),
                sampler_entry(7),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("water"),
            bind_group_layouts: &[Some(&plain.terrain.bind_group_layout), Some(&plain.fog.layout), Some(&water_layout)],
            immediate_size: 0,
        });
        let show_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("show picture"),
            entries: &[texture_entry(0, float), sampler_entry(1)],
        });
        let show_pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("show picture"),
            bind_group_layouts: &[Some(&show_layout)],
            immediate_size: 0,
        });
        let (pipeline, show_pipeline) = build_pipelines(gpu, &pipeline_layout, &show_pipeline_layout, target.format)?;
        let settings = WaterSettings::default();
        let pictures_size = picture_size(target, settings.resolution);
        let reflection = Picture::new(device, target.format, pictures_size);
        let refraction = Picture::new(device, target.format, pictures_size);
        let textures = [&reflection.colour, &refraction.colour, &refraction.depth, &dudv.view, &normal_map.view];
        let water_group = water_group(device, &water_layout, &uniform, textures, [&dudv.sampler, &clamp_sampler]);
        let show_groups = show_groups(device, &show_layout, [&reflection, &refraction], &clamp_sampler);
        let eyes = std::array::from_fn(|_| Eye { ground: plain.terrain.viewpoint(device), sky: sky.viewpoint(device) });
        let camera = lake_camera(field, centre, size, level, 18.0, target.aspect());
        Ok(Self {
            plain,
            sky,
            camera,
            controller: FlyController { speed: 10.0, ..Default::default() },
            fog: FogSettings::HAZE,
            rocks: Setup { rocks: 200_000, mode: Mode::Instanced, terrain: true },
            settings,
            day_seconds: 240.0,
            level,
            centre,
            size,
            grid,
            eyes,
            reflection,
            refraction,
            depth: depth_view(device, target.width, target.height),
            dudv,
            normal_map,
            clamp_sampler,
            uniform,
            water_group,
            water_layout,
            pipeline_layout,
            pipeline,
            show_groups,
            show_layout,
            show_pipeline_layout,
            show_pipeline,
            target,
            pictures_size,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
        self.resize_pictures(&gpu.device);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = WaterSettings::default();
        match VIEWS[view].name {
            "waves" => self.settings.wave_strength = 3.0,
            "no-fresnel" => self.settings.fresnel = false,
            _ => {}
        }
    }

    fn reset_camera(&mut self, view: usize) {
        let height = if VIEWS[view].name == "waves" { 6.0 } else { 18.0 };
        let field = self.plain.terrain.field();
        self.camera = lake_camera(field, self.centre, self.size, self.level, height, self.target.aspect());
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.resize_pictures(&gpu.device);
        let phase = (START_PHASE + frame.time / self.day_seconds).rem_euclid(1.0);
        self.camera.far = self.fog.far_plane();
        self.plain.set_air(&gpu.queue, self.fog, self.sky.fog_colour(phase));
        let camera = self.camera;
        let bias = 0.5; // a little overlap, so that waves do not open gaps at the shore
        let view = VIEWS[frame.view].name;
        let (reflection, refraction) = (self.reflection.clone(), self.refraction.clone());
        // 1. The reflection: from below the water, keeping what is above it.
        if view != "refraction" {
            let above = Vec4::new(0.0, 1.0, 0.0, -self.level + bias);
            let targets = (&reflection.colour, &reflection.depth);
            let mirror = mirrored(&camera, self.level);
            self.take_picture(
                gpu,
                frame.encoder,
                frame.timer,
                ("reflection", REFLECTION),
                targets,
                &mirror,
                above,
                phase,
            );
        }
        // 2. The refraction: from the camera, keeping what is below the water.
        if view != "reflection" {
            let below = Vec4::new(0.0, -1.0, 0.0, self.level + bias);
            let targets = (&refraction.colour, &refraction.depth);
            self.take_picture(
                gpu,
                frame.encoder,
                frame.timer,
                ("refraction", REFRACTION),
                targets,
                &camera,
                below,
                phase,
            );
        }
        match view {
            "reflection" => return self.show(frame, 0),
            "refraction" => return self.show(frame, 1),
            _ => {}
        }

        // 3. The scene itself, whole.
        let depth = self.depth.clone();
        let targets = (frame.target, &depth);
        self.take_picture(gpu, frame.encoder, frame.timer, ("plain and sky", MAIN), targets, &camera, KEEP_ALL, phase);

        // 4. The water on top, reading both pictures.
        let lake = waves::lake_waves();
        let uniform = WaterUniform {
            level_time: [
                self.level,
                frame.time,
                self.settings.wave_strength,
                f32::from(u8::from(self.settings.fresnel)),
            ],
            ripples: [self.settings.ripples, 18.0, camera.near, camera.far],
            waves: lake.map(|w| [w.direction.x, w.direction.y, w.amplitude, w.wavelength]),
            speeds: [
                [lake[0].speed, lake[1].speed, lake[2].speed, lake[3].speed],
                [lake[4].speed, lake[5].speed, lake[6].speed, lake[7].speed],
            ],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        let mut pass = frame.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("water surface"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: frame.target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: frame.timer.pass("water surface"),
            ..Default::default()
        });
        pass.set_pipeline(&self.pipeline);
        self.plain.terrain.bind(&mut pass, &self.eyes[MAIN].ground);
        pass.set_bind_group(1, &self.plain.fog.group, &[]);
        pass.set_bind_group(2, &self.water_group, &[]);
        self.grid.draw(&mut pass, 0..1);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.settings;
        ui.add(egui::Slider::new(&mut s.resolution, 0.25..=1.0).text("reflection/refraction resolution"));
        let mut waves_on = s.wave_strength > 0.0;
        if ui.checkbox(&mut waves_on, "waves (off: the flat surface, textures only)").changed() {
            s.wave_strength = if waves_on { 1.0 } else { 0.0 };
        }
        ui.add(egui::Slider::new(&mut s.wave_strength, 0.0..=4.0).text("wave strength"));
        ui.add(egui::Slider::new(&mut s.ripples, 0.0..=0.05).text("ripple distortion"));
        ui.checkbox(&mut s.fresnel, "Fresnel");
        ui.label(format!(
            "water level {:.1} m; pictures {}×{}",
            self.level, self.pictures_size.0, self.pictures_size.1
        ));
        ui.separator();
        ui.add(egui::Slider::new(&mut self.day_seconds, 10.0..=1200.0).logarithmic(true).text("day length (s)"));
        ui.add(egui::Slider::new(&mut self.fog.density, 0.0..=0.01).logarithmic(true).text("fog density"));
        let max = self.plain.rocks_placed();
        ui.add(egui::Slider::new(&mut self.rocks.rocks, 0..=max).logarithmic(true).text("rocks"));
        ui.add(egui::Slider::new(&mut self.controller.speed, 2.0..=100.0).logarithmic(true).text("speed (m/s)"));
    }

    fn stats(&mut self, _gpu: &Gpu) -> String {
        format!(
            "pictures {}×{}; {} rocks in each picture",
            self.pictures_size.0,
            self.pictures_size.1,
            self.rocks.rocks.min(self.plain.rocks_placed())
        )
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.plain.reload_shaders(gpu)?;
        self.sky.reload_shaders(gpu)?;
        (self.pipeline, self.show_pipeline) =
            build_pipelines(gpu, &self.pipeline_layout, &self.show_pipeline_layout, self.target.format)?;
        Ok(())
    }
}
