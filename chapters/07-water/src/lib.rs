//! Chapter 07: water. A lake on the Mars plain, drawn from two extra
//! pictures of the scene each frame (one reflected in the water, one seen
//! through it), mixed by the Fresnel effect, rippled by a DuDv map, lit
//! by a normal map, and moved by eight sine waves. The Mars scene, complete.

pub mod waves;

use common::chapter::{scene_pass, uniform_entry};
use common::glam::{Vec2, Vec4};
use common::texture::{ColorSpace, Texture, depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, Frame, Gpu, Input, Mesh, MeshData, ShaderError, ShaderFile, Target, View, anyhow, egui,
    primitives, shader, wgpu,
};
use skybox::SkyboxChapter;
use terrain::heightfield::HeightField;
use terrain::{KEEP_ALL, SKY};

pub const VIEWS: &[View] = &[
    View { name: "default", about: "the lake: reflection and refraction mixed by Fresnel, ripples and waves" },
    View { name: "reflection", about: "the reflection picture, full screen: the scene above the water, from below it" },
    View { name: "refraction", about: "the refraction picture, full screen: the scene below the water" },
    View { name: "waves", about: "the geometric waves three times as strong" },
    View { name: "no-fresnel", about: "reflection and refraction half and half at every angle" },
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
    fn new(device: &wgpu::Device, format: wgpu::TextureFormat, width: u32, height: u32) -> Self {
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
    shader!("water/water.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl"])
}

fn show_shader() -> ShaderFile {
    shader!("water/show.wgsl")
}

pub struct WaterChapter {
    /// Chapter 06's scene: the plain under the sky.
    pub sky: SkyboxChapter,
    pub settings: WaterSettings,
    pub level: f32,
    /// The lake's centre (x, z) and side, metres.
    pub centre: Vec2,
    pub size: f32,
    grid: Mesh,
    reflection: Picture,
    refraction: Picture,
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

fn texture_entry(binding: u32, sample_type: wgpu::TextureSampleType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

fn sampler_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        count: None,
    }
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
        self.reflection = Picture::new(device, self.target.format, size.0, size.1);
        self.refraction = Picture::new(device, self.target.format, size.0, size.1);
        self.water_group = self.water_group(device);
        self.show_groups =
            show_groups(device, &self.show_layout, [&self.reflection, &self.refraction], &self.clamp_sampler);
    }

    // ANCHOR: picture
    /// Renders the plain and the sky from `camera` into `picture`, keeping
    /// only what `clip` keeps, and submits it at once: the uniforms are
    /// rewritten for the next picture, and a write lands before the next
    /// submission, not before the last.
    fn take_picture(
        &mut self,
        gpu: &Gpu,
        frame: &Frame,
        label: &'static str,
        picture: &Picture,
        camera: &Camera,
        clip: Vec4,
    ) {
        self.sky.prepare(gpu, camera, clip);
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(label) });
        {
            let mut pass = scene_pass(&mut encoder, frame.timer, label, &picture.colour, SKY, &picture.depth);
            self.sky.draw(&mut pass);
        }
        gpu.queue.submit([encoder.finish()]);
    }
    // ANCHOR_END: picture

    /// Draws picture `which` (0 reflection, 1 refraction) over the whole frame.
    fn show(&self, frame: &mut Frame, which: usize) {
        let mut pass = frame.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("show picture"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: frame.target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(SKY), store: wgpu::StoreOp::Store },
            })],
            ..Default::default()
        });
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
    let water = water_shader().module(&gpu.device)?;
    let show = show_shader().module(&gpu.device)?;
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
        let picture = gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("show picture"),
            layout: Some(show_layout),
            vertex: wgpu::VertexState {
                module: &show,
                entry_point: Some("vs_show"),
                buffers: &[],
                compilation_options: Default::default(),
            },
            primitive: Default::default(),
            depth_stencil: None,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &show,
                entry_point: Some("fs_show"),
                targets: &[Some(format.into())],
                compilation_options: Default::default(),
            }),
            multiview_mask: None,
            cache: None,
        });
        (surface, picture)
    })
    .map_err(ShaderError)
}

impl Chapter for WaterChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "07 · Water";
    const VIEWS: &'static [View] = VIEWS;
    const SNAPSHOT_TIME: f32 = 0.0;
    const KEYS: &'static [(&'static str, &'static str)] = common::FlyController::KEYS;
    const BENCH_FRAMES: u32 = 5;

    /// Clip distances where the adapter has them; a fragment discard otherwise.
    fn gpu_needs() -> common::GpuNeeds {
        common::GpuNeeds { required: wgpu::Features::empty(), optional: wgpu::Features::CLIP_DISTANCES }
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let sky = SkyboxChapter::new(gpu, target)?;
        let (centre, size, level) = find_lake(&sky.plain.terrain.field, &sky.plain.camera);
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
            bind_group_layouts: &[
                Some(&sky.plain.terrain.bind_group_layout),
                Some(&sky.plain.fog_binding.layout),
                Some(&water_layout),
            ],
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
        let reflection = Picture::new(device, target.format, pictures_size.0, pictures_size.1);
        let refraction = Picture::new(device, target.format, pictures_size.0, pictures_size.1);
        let textures = [&reflection.colour, &refraction.colour, &refraction.depth, &dudv.view, &normal_map.view];
        let water_group = water_group(device, &water_layout, &uniform, textures, [&dudv.sampler, &clamp_sampler]);
        let show_groups = show_groups(device, &show_layout, [&reflection, &refraction], &clamp_sampler);
        Ok(Self {
            sky,
            settings,
            level,
            centre,
            size,
            grid,
            reflection,
            refraction,
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
        self.sky.resize(gpu, target);
        self.resize_pictures(&gpu.device);
    }

    fn select_view(&mut self, view: usize) {
        self.sky.select_view(0);
        self.settings = WaterSettings::default();
        let mut height = 18.0;
        match VIEWS[view].name {
            "waves" => {
                self.settings.wave_strength = 3.0;
                height = 6.0;
            }
            "no-fresnel" => self.settings.fresnel = false,
            _ => {}
        }
        let field = &self.sky.plain.terrain.field;
        self.sky.plain.camera = lake_camera(field, self.centre, self.size, self.level, height, self.target.aspect());
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.sky.update(input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.resize_pictures(&gpu.device);
        self.sky.set_time(frame.time);
        let camera = self.sky.plain.camera;
        let bias = 0.5; // a little overlap, so that waves do not open gaps at the shore
        // 1. The reflection: from below the water, keeping what is above it.
        let above = Vec4::new(0.0, 1.0, 0.0, -self.level + bias);
        let (reflection, refraction) = (self.reflection.clone(), self.refraction.clone());
        self.take_picture(gpu, frame, "reflection", &reflection, &mirrored(&camera, self.level), above);
        // 2. The refraction: from the camera, keeping what is below the water.
        let below = Vec4::new(0.0, -1.0, 0.0, self.level + bias);
        self.take_picture(gpu, frame, "refraction", &refraction, &camera, below);

        match VIEWS[frame.view].name {
            "reflection" => return self.show(frame, 0),
            "refraction" => return self.show(frame, 1),
            _ => {}
        }

        // 3. The scene itself, whole.
        self.sky.prepare(gpu, &camera, KEEP_ALL);
        let depth = self.sky.plain.depth();
        {
            let mut pass = frame.scene_pass("plain and sky", SKY, &depth);
            self.sky.draw(&mut pass);
        }

        // 4. The water on top, reading both pictures.
        let lake = waves::lake_waves();
        let uniform = WaterUniform {
            level_time: [
                self.level,
                frame.time,
                self.settings.wave_strength,
                f32::from(u8::from(self.settings.fresnel)),
            ],
            ripples: [self.settings.ripples, 18.0, camera.near, self.sky.plain.camera.far],
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
        self.sky.plain.terrain.bind(&mut pass);
        pass.set_bind_group(1, &self.sky.plain.fog_binding.group, &[]);
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
        self.sky.ui(ui);
    }

    fn stats(&self) -> String {
        format!("pictures {}×{}; {}", self.pictures_size.0, self.pictures_size.1, self.sky.stats())
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.sky.reload_shaders(gpu)?;
        (self.pipeline, self.show_pipeline) =
            build_pipelines(gpu, &self.pipeline_layout, &self.show_pipeline_layout, self.target.format)?;
        Ok(())
    }
}
