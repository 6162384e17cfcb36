//! The water of a lake, for any chapter that has the scene to reflect: two
//! offscreen pictures (the reflection and the refraction), and a surface
//! that reads them through projective texturing, rippled by a DuDv map, lit
//! by a normal map, mixed by Fresnel and moved by the lake's waves.

use common::chapter::{sampler_entry, texture_entry, uniform_entry};
use common::glam::Vec2;
use common::texture::{ColorSpace, Texture, depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Frame, Gpu, Mesh, MeshData, Reloadable, ShaderError, ShaderFile, Target, anyhow, fullscreen, primitives,
    shader, wgpu,
};
use instancing::MarsPlain;
use terrain::{SKY, Viewpoint};

use crate::waves;

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

impl WaterSettings {
    pub const DEFAULT: Self = Self { resolution: 0.5, wave_strength: 1.0, fresnel: true, ripples: 0.012 };
}

impl Default for WaterSettings {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// An offscreen picture of the scene, with its own depth buffer. (Cloning
/// copies two reference-counted handles, not the textures.)
#[derive(Clone)]
pub struct Picture {
    pub colour: wgpu::TextureView,
    pub depth: wgpu::TextureView,
}

impl Picture {
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat, (width, height): (u32, u32)) -> Self {
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
    shader!("water/water.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "water/waves.wgsl"])
}

fn show_shader() -> ShaderFile {
    shader!("water/show.wgsl", imports: ["common/fullscreen.wgsl"])
}

/// The water of one lake: its grid, the reflection and refraction pictures
/// it reads (drawn by whoever composes it, from cameras of their choosing),
/// the DuDv and normal maps, and the pipelines that draw the surface or
/// show a picture full screen. Per frame: the level, the time, the camera
/// and the settings (`aim`), then a pass to draw into (`draw`).
pub struct WaterRenderer {
    grid: Mesh,
    /// The scene above the water, seen from below it.
    pub reflection: Picture,
    /// The scene below the water.
    pub refraction: Picture,
    pictures_size: (u32, u32),
    dudv: Texture,
    normal_map: Texture,
    clamp_sampler: wgpu::Sampler,
    uniform: wgpu::Buffer,
    water_layout: wgpu::BindGroupLayout,
    water_group: wgpu::BindGroup,
    show_layout: wgpu::BindGroupLayout,
    show_groups: [wgpu::BindGroup; 2],
    /// The surface's pipeline and the one that shows a picture, rebuilt
    /// when water.wgsl, show.wgsl or a module they import is saved (hot reload).
    pipelines: Reloadable<(wgpu::RenderPipeline, wgpu::RenderPipeline)>,
}

impl WaterRenderer {
    /// The water of a square lake `size` metres across around `centre`
    /// (x, z), for targets like `target`, its pictures `resolution` of the
    /// target's size. The surface is drawn with `plain`'s groups 0 (the
    /// terrain's viewpoint) and 1 (the fog).
    pub fn new(
        gpu: &Gpu,
        plain: &MarsPlain,
        centre: Vec2,
        size: f32,
        target: Target,
        resolution: f32,
    ) -> anyhow::Result<Self> {
        let device = &gpu.device;
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
        let format = target.format;
        let pipelines =
            Reloadable::new(gpu, move |gpu| build_pipelines(gpu, &pipeline_layout, &show_pipeline_layout, format))?;
        let pictures_size = picture_size(target, resolution);
        let reflection = Picture::new(device, target.format, pictures_size);
        let refraction = Picture::new(device, target.format, pictures_size);
        let textures = [&reflection.colour, &refraction.colour, &refraction.depth, &dudv.view, &normal_map.view];
        let water_group = water_group(device, &water_layout, &uniform, textures, [&dudv.sampler, &clamp_sampler]);
        let show_groups = show_groups(device, &show_layout, [&reflection, &refraction], &clamp_sampler);
        Ok(Self {
            grid,
            reflection,
            refraction,
            pictures_size,
            dudv,
            normal_map,
            clamp_sampler,
            uniform,
            water_layout,
            water_group,
            show_layout,
            show_groups,
            pipelines,
        })
    }

    /// The size of the reflection and refraction pictures, in pixels.
    pub fn pictures_size(&self) -> (u32, u32) {
        self.pictures_size
    }

    /// (Re)creates the two pictures when the resolution setting or the
    /// screen's size changes.
    pub fn resize_pictures(&mut self, device: &wgpu::Device, target: Target, resolution: f32) {
        let size = picture_size(target, resolution);
        if size == self.pictures_size {
            return;
        }
        self.pictures_size = size;
        self.reflection = Picture::new(device, target.format, size);
        self.refraction = Picture::new(device, target.format, size);
        let textures = [
            &self.reflection.colour,
            &self.refraction.colour,
            &self.refraction.depth,
            &self.dudv.view,
            &self.normal_map.view,
        ];
        let samplers = [&self.dudv.sampler, &self.clamp_sampler];
        self.water_group = water_group(device, &self.water_layout, &self.uniform, textures, samplers);
        self.show_groups =
            show_groups(device, &self.show_layout, [&self.reflection, &self.refraction], &self.clamp_sampler);
    }

    /// Draws picture `which` (0 reflection, 1 refraction) over the whole frame.
    pub fn show(&self, frame: &mut Frame, which: usize) {
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "show picture", frame.target, Some(SKY));
        pass.set_pipeline(&self.pipelines.get().1);
        pass.set_bind_group(0, &self.show_groups[which], &[]);
        pass.draw(0..3, 0..1);
    }

    // ANCHOR: aim
    /// Writes the water's uniform: its `level`, the scene `time`, the
    /// camera's near and far planes, the lake's waves and `settings`.
    pub fn aim(&self, queue: &wgpu::Queue, level: f32, time: f32, camera: &Camera, settings: WaterSettings) {
        let lake = waves::lake_waves();
        let uniform = WaterUniform {
            level_time: [level, time, settings.wave_strength, f32::from(u8::from(settings.fresnel))],
            ripples: [settings.ripples, 18.0, camera.near, camera.far],
            waves: lake.map(|w| [w.direction.x, w.direction.y, w.amplitude, w.wavelength]),
            speeds: [
                [lake[0].speed, lake[1].speed, lake[2].speed, lake[3].speed],
                [lake[4].speed, lake[5].speed, lake[6].speed, lake[7].speed],
            ],
        };
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }
    // ANCHOR_END: aim

    /// Draws the surface into `pass`, seen from `ground` (a viewpoint of
    /// `plain`'s terrain, aimed from the same camera as `aim`), in `plain`'s fog.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, plain: &MarsPlain, ground: &Viewpoint) {
        pass.set_pipeline(&self.pipelines.get().0);
        plain.terrain.bind(pass, ground);
        pass.set_bind_group(1, &plain.fog.group, &[]);
        pass.set_bind_group(2, &self.water_group, &[]);
        self.grid.draw(pass, 0..1);
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
