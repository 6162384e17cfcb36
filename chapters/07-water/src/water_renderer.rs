//! The water of a lake, for any chapter that has the scene to reflect: two
//! offscreen pictures (the reflection and the refraction), and a surface
//! that reads them through projective texturing, rippled by a DuDv map, lit
//! by a normal map, mixed by Fresnel and moved by the lake's waves. Or, in
//! seed 003's style, no pictures: a tiled water texture, read twice, the
//! second read pushed aside by the first one's colours.

use common::chapter::{sampler_entry, texture_entry, uniform_entry};
use common::glam::Vec2;
use common::texture::{ColorSpace, Texture, depth_test, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Drawn, Frame, Gpu, Mesh, MeshData, Reloadable, ShaderError, ShaderFile, Target, anyhow, fullscreen,
    primitives, shader, wgpu,
};
use instancing::{MarsPlain, PlainViewpoint};
use terrain::SKY;

use crate::waves::WaveSet;

/// How the surface gets its colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// This chapter's: the reflection and refraction pictures, mixed by Fresnel.
    Pictures,
    /// Seed 003's: a tiled water texture, scrolled and pushed aside by its
    /// own colours. It needs no pictures of the scene.
    Texture,
}

/// What the overlay changes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaterSettings {
    pub style: Style,
    /// Size of the reflection and refraction pictures, as a fraction of the screen's.
    pub resolution: f32,
    /// 0 flat, 1 the lake's waves.
    pub wave_strength: f32,
    /// The eight waves, each editable in the overlay.
    pub waves: WaveSet,
    pub fresnel: bool,
    /// DuDv distortion of the pictures, in texture units.
    pub ripples: f32,
    /// How far the texture style's second read is pushed by the first
    /// one's green and blue, in tiles per unit of colour (seed 003: 0.2).
    pub texture_push: f32,
}

impl WaterSettings {
    pub const DEFAULT: Self = Self {
        style: Style::Pictures,
        resolution: 0.5,
        wave_strength: 1.0,
        waves: WaveSet::Lake,
        fresnel: true,
        ripples: 0.012,
        texture_push: 0.2,
    };
}

impl Default for WaterSettings {
    fn default() -> Self {
        Self::DEFAULT
    }
}

// ANCHOR: picture
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
// ANCHOR_END: picture

/// `Water` in water.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct WaterUniform {
    level_time: [f32; 4],
    ripples: [f32; 4],
    waves: [[f32; 4]; 8],
    speeds: [[f32; 4]; 2],
    texture: [f32; 4],
}

/// Metres of lake one tile of the water texture covers (its first read;
/// the second, at 1.5 times the frequency, two thirds of that).
pub(crate) const TEXTURE_TILE_METRES: f32 = 12.0;

fn water_shader() -> ShaderFile {
    shader!("water/water.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "water/waves.wgsl"])
}

fn show_shader() -> ShaderFile {
    shader!("water/show.wgsl", imports: ["common/fullscreen.wgsl"])
}

/// The water's pipelines: the surface in each style, and a picture shown
/// full screen. (Cloning copies handles: `Reloadable::get` hands out a copy.)
#[derive(Clone)]
struct Pipelines {
    pictures: wgpu::RenderPipeline,
    texture: wgpu::RenderPipeline,
    show: wgpu::RenderPipeline,
}

/// The water of one lake: its grid, the reflection and refraction pictures
/// it reads (drawn by whoever composes it, from cameras of their choosing),
/// the DuDv and normal maps, the water texture, and the pipelines that draw
/// the surface or show a picture full screen. Per frame: the level, the
/// time, the camera and the settings (`aim`), then a pass to draw into
/// (`draw`).
pub struct WaterRenderer {
    grid: Mesh,
    /// The scene above the water, seen from below it.
    pub reflection: Picture,
    /// The scene below the water.
    pub refraction: Picture,
    pictures_size: (u32, u32),
    dudv: Texture,
    normal_map: Texture,
    /// Seed 003's style: the water texture, with mipmaps, and its sampler.
    water_texture: (wgpu::TextureView, wgpu::Sampler),
    clamp_sampler: wgpu::Sampler,
    depth_sampler: wgpu::Sampler,
    uniform: wgpu::Buffer,
    water_layout: wgpu::BindGroupLayout,
    water_group: wgpu::BindGroup,
    show_layout: wgpu::BindGroupLayout,
    show_groups: [wgpu::BindGroup; 2],
    /// The surface's pipelines and the one that shows a picture, rebuilt
    /// when water.wgsl, show.wgsl or a module they import is saved (hot reload).
    pipelines: Reloadable<Pipelines>,
}

impl WaterRenderer {
    /// The water of a square lake `size` metres across around `centre`
    /// (x, z), for targets like `target`, its pictures `resolution` of the
    /// target's size (and of one sample a pixel: the water reads their
    /// depth). The surface is drawn with `plain`'s groups 0 (the terrain's
    /// viewpoint) and 1 (the fog), in a pass of `target.samples` samples.
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
        let water_texture = mipmapped_texture(
            device,
            &gpu.queue,
            "assets/water/texture.png",
            include_bytes!("../../../assets/water/texture.png"),
        )?;
        let clamp_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("clamp"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        // The lake bed's depth is read texel by texel: through "nearest".
        let depth_sampler =
            device.create_sampler(&wgpu::SamplerDescriptor { label: Some("depth"), ..Default::default() });
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
                // The refraction's depth buffer, read as plain floats (as
                // chapter 02's depth view does: OpenGL's GLSL cannot fetch
                // the texels of a texture declared as depth).
                texture_entry(3, wgpu::TextureSampleType::Float { filterable: false }),
                texture_entry(4, float),
                texture_entry(5, float),
                sampler_entry(6),
                sampler_entry(7),
                texture_entry(8, float),
                sampler_entry(9),
                wgpu::BindGroupLayoutEntry {
                    binding: 10,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
                    count: None,
                },
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
        // The surface is drawn in the scene's pass, with its samples.
        let format = (target.format, target.samples);
        let pipelines =
            Reloadable::new(gpu, move |gpu| build_pipelines(gpu, &pipeline_layout, &show_pipeline_layout, format))?;
        let pictures_size = picture_size(target, resolution);
        let reflection = Picture::new(device, target.format, pictures_size);
        let refraction = Picture::new(device, target.format, pictures_size);
        let textures =
            [&reflection.colour, &refraction.colour, &refraction.depth, &dudv.view, &normal_map.view, &water_texture.0];
        let samplers = [&dudv.sampler, &clamp_sampler, &water_texture.1, &depth_sampler];
        let water_group = water_group(device, &water_layout, &uniform, textures, samplers);
        let show_groups = show_groups(device, &show_layout, [&reflection, &refraction], &clamp_sampler);
        Ok(Self {
            grid,
            reflection,
            refraction,
            pictures_size,
            dudv,
            normal_map,
            water_texture,
            clamp_sampler,
            depth_sampler,
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
            &self.water_texture.0,
        ];
        let samplers = [&self.dudv.sampler, &self.clamp_sampler, &self.water_texture.1, &self.depth_sampler];
        self.water_group = water_group(device, &self.water_layout, &self.uniform, textures, samplers);
        self.show_groups =
            show_groups(device, &self.show_layout, [&self.reflection, &self.refraction], &self.clamp_sampler);
    }

    /// Draws picture `which` (0 reflection, 1 refraction) over the whole frame.
    pub fn show(&self, frame: &mut Frame, which: usize) -> Drawn {
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "show picture", frame.target, Some(SKY));
        pass.set_pipeline(&self.pipelines.get().show);
        pass.set_bind_group(0, &self.show_groups[which], &[]);
        pass.draw(0..3, 0..1);
        Drawn::FULL_SCREEN
    }

    // ANCHOR: aim
    /// Writes the water's uniform: its `level`, the scene `time`, the
    /// camera's near and far planes, and `settings` with their waves.
    pub fn aim(&self, queue: &wgpu::Queue, level: f32, time: f32, camera: &Camera, settings: WaterSettings) {
        let lake = settings.waves.waves();
        let uniform = WaterUniform {
            level_time: [level, time, settings.wave_strength, f32::from(u8::from(settings.fresnel))],
            ripples: [settings.ripples, 18.0, camera.near, camera.far],
            waves: lake.map(|w| [w.direction.x, w.direction.y, w.amplitude, w.wavelength]),
            speeds: [
                [lake[0].speed, lake[1].speed, lake[2].speed, lake[3].speed],
                [lake[4].speed, lake[5].speed, lake[6].speed, lake[7].speed],
            ],
            texture: [settings.texture_push, TEXTURE_TILE_METRES, 0.0, 0.0],
        };
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }
    // ANCHOR_END: aim

    /// Draws the surface in `style` into `pass`, seen from `viewpoint` (a
    /// viewpoint of `plain`, aimed from the same camera as `aim`: the water
    /// reads its terrain uniforms), in `plain`'s fog. `Style::Pictures` reads the reflection
    /// and refraction pictures, which must have been drawn this frame.
    pub fn draw(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        plain: &MarsPlain,
        viewpoint: &PlainViewpoint,
        style: Style,
    ) -> Drawn {
        let pipelines = self.pipelines.get();
        pass.set_pipeline(match style {
            Style::Pictures => &pipelines.pictures,
            Style::Texture => &pipelines.texture,
        });
        plain.terrain.bind(pass, &viewpoint.ground);
        pass.set_bind_group(1, &plain.fog.group, &[]);
        pass.set_bind_group(2, &self.water_group, &[]);
        self.grid.draw(pass, 0..1)
    }
}

fn picture_size(target: Target, resolution: f32) -> (u32, u32) {
    let scale = resolution.clamp(0.1, 1.0);
    (((target.width as f32 * scale) as u32).max(1), ((target.height as f32 * scale) as u32).max(1))
}

/// The water's bind group: the uniform (binding 0); the two pictures, the
/// refraction's depth, the DuDv and normal maps (1 to 5); a repeating and
/// a clamping sampler (6, 7); the water texture and its sampler (8, 9).
fn water_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniform: &wgpu::Buffer,
    textures: [&wgpu::TextureView; 6],
    samplers: [&wgpu::Sampler; 4],
) -> wgpu::BindGroup {
    let [reflection, refraction, depth, dudv, normal_map, water_texture] = textures;
    let [repeat, clamp, water_sampler, depth_sampler] = samplers;
    let texture_at =
        |binding, view| wgpu::BindGroupEntry { binding, resource: wgpu::BindingResource::TextureView(view) };
    let sampler_at =
        |binding, sampler| wgpu::BindGroupEntry { binding, resource: wgpu::BindingResource::Sampler(sampler) };
    let entries = [
        wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
        texture_at(1, reflection),
        texture_at(2, refraction),
        texture_at(3, depth),
        texture_at(4, dudv),
        texture_at(5, normal_map),
        sampler_at(6, repeat),
        sampler_at(7, clamp),
        texture_at(8, water_texture),
        sampler_at(9, water_sampler),
        sampler_at(10, depth_sampler),
    ];
    device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some("water"), layout, entries: &entries })
}

/// An sRGB picture with all its mipmaps, made on the CPU, and a repeating
/// sampler that blends between them: seen across the lake, hundreds of
/// texels fall in a pixel, and a texture with one level would sparkle as
/// it scrolls. Each level averages 2 × 2 texels of the one above in linear
/// light (averaging sRGB bytes as they are would darken every level).
fn mipmapped_texture(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    name: &str,
    bytes: &[u8],
) -> anyhow::Result<(wgpu::TextureView, wgpu::Sampler)> {
    let mut levels = vec![common::texture::decode_named(name, bytes)?];
    loop {
        let above = levels.last().expect("levels start with the picture");
        if above.width() == 1 && above.height() == 1 {
            break;
        }
        let below = common::texture::half_size_srgb(above);
        levels.push(below);
    }
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(name),
        size: wgpu::Extent3d { width: levels[0].width(), height: levels[0].height(), depth_or_array_layers: 1 },
        mip_level_count: levels.len() as u32,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8UnormSrgb,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (level, image) in levels.iter().enumerate() {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: level as u32,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            image.as_raw(),
            wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * image.width()), rows_per_image: None },
            wgpu::Extent3d { width: image.width(), height: image.height(), depth_or_array_layers: 1 },
        );
    }
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some(name),
        address_mode_u: wgpu::AddressMode::Repeat,
        address_mode_v: wgpu::AddressMode::Repeat,
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        mipmap_filter: wgpu::MipmapFilterMode::Linear,
        ..Default::default()
    });
    Ok((texture.create_view(&Default::default()), sampler))
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
    (format, samples): (wgpu::TextureFormat, u32),
) -> Result<Pipelines, ShaderError> {
    let water = water_shader().module(gpu)?;
    let show = show_shader().module(gpu)?;
    gpu.catch_validation(|| {
        let surface = |label, fragment_entry| {
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &water,
                    entry_point: Some("vs_water"),
                    buffers: &[Some(common::Vertex::LAYOUT)],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
                depth_stencil: depth_test(),
                multisample: common::multisampling::multisample(samples),
                fragment: Some(wgpu::FragmentState {
                    module: &water,
                    entry_point: Some(fragment_entry),
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
            })
        };
        Pipelines {
            pictures: surface("water", "fs_water"),
            texture: surface("water, seed 003's texture", "fs_texture"),
            show: fullscreen::pipeline(&gpu.device, "show picture", show_layout, &show, "fs_show", format.into(), None),
        }
    })
    .map_err(ShaderError)
}
