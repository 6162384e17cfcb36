//! Chapter 08: lighting. A futuristic city by day and by night: the sun by
//! time of day, hundreds of street lamps, lit buildings and car headlights,
//! shaded flat, per vertex (Gouraud) or per fragment (Phong), with Phong or
//! Blinn-Phong highlights; rendered in HDR, with bloom and tone mapping; and
//! the lights culled per cluster, so that a fragment only visits the few
//! that can reach it.

pub mod bloom;
pub mod city;
pub mod clusters;
pub mod lights;
pub mod paths;

use common::chapter::{FILTERABLE, mesh_pipeline, sampler_entry, storage_entry, texture_entry, uniform_entry};
use common::glam::{Mat3, Mat4, Vec3};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, Mesh, MeshData, ShaderError, ShaderFile, Target, Vertex, View,
    anyhow, egui, fullscreen, shader, wgpu, winit::keyboard::KeyCode,
};

use bloom::{Bloom, BloomSettings};
use city::{City, Clocks, Material, Piece, Shape, Traffic};
use clusters::{CLUSTERS, ClusterLists};
use lights::{Daylight, GpuLight, Light, TimeOfDay, daylight};

// ANCHOR: views
pub const VIEWS: &[View] = &[
    View::mode("day", "the city at noon, from above"),
    View::mode("night", "the city at night: street lamps, lit buildings, headlights, bloom"),
    View::preset("flat", "the glass sphere in the morning sun, flat shaded: one colour per face"),
    View::preset("gouraud", "the same, lit per vertex and blended: the highlight smears over the facets"),
    View::preset("phong", "the same, lit per fragment: a round, sharp highlight (Phong's mirror direction)"),
    View::preset("blinn-phong", "the same with Blinn-Phong's half vector: a wider, softer highlight"),
    View::mode("no-bloom", "the night city without bloom: lights are bright dots"),
    View::mode("bloom-only", "the blurred bright light the bloom adds, alone"),
    View::mode("light-tiles", "lights each fragment visits, as a heat map (black 0, blue few, red 24 or more)"),
    View::preset("follow", "at night, behind a car, with its headlights on the road"),
    View::bench("lights-1", "bench: the night city with 1 light, culled"),
    View::bench("lights-16", "bench: 16 lights, culled per cluster"),
    View::bench("lights-64", "bench: 64 lights, culled per cluster"),
    View::bench("lights-256", "bench: 256 lights, culled per cluster"),
    View::bench("lights-1024", "bench: 1024 lights, culled per cluster"),
    View::bench("naive-16", "bench: 16 lights, every fragment visits every light"),
    View::bench("naive-64", "bench: 64 lights, every fragment visits every light"),
    View::bench("naive-256", "bench: 256 lights, every fragment visits every light"),
    View::bench("naive-1024", "bench: 1024 lights, every fragment visits every light"),
];
// ANCHOR_END: views

/// How surfaces are lit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shading {
    /// Once per face: one normal and one colour per triangle.
    Flat,
    /// Once per vertex; colours interpolated.
    Gouraud,
    /// Once per fragment; normals interpolated.
    Phong,
}

/// Which highlight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Highlight {
    /// The mirror direction against the view: (r · v)^s.
    Phong,
    /// The half vector against the normal: (n · h)^s.
    BlinnPhong,
}

/// What reaches the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    Scene,
    BloomOnly,
    LightTiles,
}

/// How many lights shine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightCount {
    /// The city's own: lamps, buildings, cars and drones.
    City,
    /// The first n of the city's lights and then of extra beacons: the bench's counts.
    First(u32),
}

/// The most lights the buffer holds: the city's own, then beacons.
pub const MAX_LIGHTS: u32 = 1024;

/// Everything a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub time_of_day: TimeOfDay,
    /// Seconds in a day when the time of day is `Auto`.
    pub day_seconds: f32,
    pub shading: Shading,
    pub highlight: Highlight,
    /// Highlights at all (off: diffuse light only).
    pub highlights: bool,
    /// Cluster lists (true) or every light for every fragment (false).
    pub culling: bool,
    pub lights: LightCount,
    pub bloom_on: bool,
    pub bloom: BloomSettings,
    pub display: Display,
    pub exposure: f32,
}

impl Settings {
    /// The settings view `name` shows, whatever came before.
    pub fn for_view(name: &str) -> Self {
        let mut s = Self {
            time_of_day: TimeOfDay::Night,
            day_seconds: 120.0,
            shading: Shading::Phong,
            highlight: Highlight::BlinnPhong,
            highlights: true,
            culling: true,
            lights: LightCount::City,
            bloom_on: true,
            bloom: BloomSettings::default(),
            display: Display::Scene,
            exposure: 1.0,
        };
        match name {
            "day" => s.time_of_day = TimeOfDay::Noon,
            "flat" | "gouraud" | "phong" | "blinn-phong" => {
                // One light, the morning sun, so that shading is all there is to see.
                s.time_of_day = TimeOfDay::Morning;
                s.lights = LightCount::First(0);
                s.shading = match name {
                    "flat" => Shading::Flat,
                    "gouraud" => Shading::Gouraud,
                    _ => Shading::Phong,
                };
                s.highlight = if name == "blinn-phong" { Highlight::BlinnPhong } else { Highlight::Phong };
            }
            "no-bloom" => s.bloom_on = false,
            "bloom-only" => s.display = Display::BloomOnly,
            "light-tiles" => s.display = Display::LightTiles,
            _ => {}
        }
        if let Some(count) = name.strip_prefix("lights-").and_then(|n| n.parse().ok()) {
            s.lights = LightCount::First(count);
        }
        if let Some(count) = name.strip_prefix("naive-").and_then(|n| n.parse().ok()) {
            s.lights = LightCount::First(count);
            s.culling = false;
        }
        s
    }
}

// ANCHOR: instance
/// One piece as the GPU reads it (`Instance` in city.wgsl): its model
/// matrix, the inverse transpose of its upper 3 × 3 for normals (one
/// column per 16 bytes), and its material. 128 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuInstance {
    pub model: [[f32; 4]; 4],
    pub normal: [[f32; 4]; 3],
    pub material: u32,
    pub _padding: [u32; 3],
}

impl GpuInstance {
    pub fn of(piece: &Piece) -> Self {
        let normal = Mat3::from_mat4(piece.model).inverse().transpose();
        Self {
            model: piece.model.to_cols_array_2d(),
            normal: [
                normal.x_axis.extend(0.0).into(),
                normal.y_axis.extend(0.0).into(),
                normal.z_axis.extend(0.0).into(),
            ],
            material: piece.material as u32,
            _padding: [0; 3],
        }
    }

    const ATTRIBUTES: [wgpu::VertexAttribute; 8] = [
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 0, shader_location: 3 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 16, shader_location: 4 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 32, shader_location: 5 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 48, shader_location: 6 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 64, shader_location: 7 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 80, shader_location: 8 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 96, shader_location: 9 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Uint32, offset: 112, shader_location: 10 },
    ];

    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<GpuInstance>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &Self::ATTRIBUTES,
    };
}
// ANCHOR_END: instance

// ANCHOR: faceted
/// The same triangles, each with three vertices of its own carrying the
/// face's normal: what flat shading needs, since a shared vertex can only
/// have one normal.
pub fn faceted(mesh: &MeshData) -> MeshData {
    let mut flat = MeshData::default();
    for triangle in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [0, 1, 2].map(|k| mesh.vertices[triangle[k] as usize]);
        let [pa, pb, pc] = [a, b, c].map(|v| Vec3::from(v.position));
        let normal = (pb - pa).cross(pc - pa).normalize_or_zero();
        for v in [a, b, c] {
            flat.indices.push(flat.vertices.len() as u32);
            flat.vertices.push(Vertex { normal: normal.into(), ..v });
        }
    }
    flat
}
// ANCHOR_END: faceted

/// `Material` in city.wgsl: 32 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMaterial {
    pub albedo: [f32; 3],
    pub specular: f32,
    pub emissive: [f32; 3],
    pub shininess: f32,
}

// ANCHOR: frame_uniform
/// `Frame` in lights.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FrameUniform {
    view_proj: [[f32; 4]; 4],
    view: [[f32; 4]; 4],
    eye: [f32; 4],
    sun_direction: [f32; 4],
    sun_colour: [f32; 4],
    ambient: [f32; 4],
    options: [u32; 4],
    depth: [f32; 4],
    grid: [u32; 4],
}
// ANCHOR_END: frame_uniform

/// How the light loop runs this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoopOptions {
    pub culling: bool,
    pub highlight: Highlight,
    pub heat_map: bool,
}

// ANCHOR: scene_lights
/// The lights of a frame on the GPU: group 0 of `lights.wgsl`, with the
/// frame's camera and sun, every light, and the cluster lists. A piece with
/// explicit inputs, which chapter 09's textured city uses as it is.
pub struct SceneLights {
    frame: wgpu::Buffer,
    lights: wgpu::Buffer,
    ranges: wgpu::Buffer,
    indices: wgpu::Buffer,
    pub layout: wgpu::BindGroupLayout,
    pub group: wgpu::BindGroup,
}

impl SceneLights {
    pub fn new(device: &wgpu::Device) -> Self {
        let stages = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("lights"),
            entries: &[
                storage_entry(0, stages),
                storage_entry(1, stages),
                storage_entry(2, stages),
                storage_entry(3, stages),
            ],
        });
        let buffer = |label, size: u64, usage| {
            device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size, usage, mapped_at_creation: false })
        };
        let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
        // Storage, not uniform: see `frame` in lights.wgsl.
        let frame = buffer("frame", std::mem::size_of::<FrameUniform>() as u64, storage);
        let lights = buffer("lights", u64::from(MAX_LIGHTS) * 64, storage);
        let ranges = buffer("cluster ranges", CLUSTERS as u64 * 8, storage);
        let indices = buffer("cluster lights", 4 * 4096, storage);
        let group = Self::group(device, &layout, [&frame, &lights, &ranges, &indices]);
        Self { frame, lights, ranges, indices, layout, group }
    }

    fn group(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, buffers: [&wgpu::Buffer; 4]) -> wgpu::BindGroup {
        let entries: Vec<wgpu::BindGroupEntry> = buffers
            .iter()
            .enumerate()
            .map(|(i, b)| wgpu::BindGroupEntry { binding: i as u32, resource: b.as_entire_binding() })
            .collect();
        device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some("lights"), layout, entries: &entries })
    }

    /// Writes the frame: the camera, the daylight, `lights` (at most
    /// `MAX_LIGHTS`), their cluster lists, and how the loop runs.
    pub fn write(
        &mut self,
        gpu: &Gpu,
        camera: &Camera,
        day: &Daylight,
        lights: &[Light],
        lists: &ClusterLists,
        options: LoopOptions,
    ) {
        let count = lights.len().min(MAX_LIGHTS as usize);
        let frame = FrameUniform {
            view_proj: camera.view_projection().to_cols_array_2d(),
            view: camera.view().to_cols_array_2d(),
            eye: camera.position.extend(1.0).into(),
            sun_direction: day.direction.extend(0.0).into(),
            sun_colour: day.sun.extend(1.0).into(),
            ambient: day.ambient.extend(1.0).into(),
            options: [
                count as u32,
                u32::from(options.culling),
                u32::from(options.highlight == Highlight::BlinnPhong),
                u32::from(options.heat_map),
            ],
            depth: [camera.near, camera.far, (camera.far / camera.near).ln(), day.night],
            grid: [clusters::GRID[0], clusters::GRID[1], clusters::GRID[2], 0],
        };
        gpu.queue.write_buffer(&self.frame, 0, bytemuck::bytes_of(&frame));
        let gpu_lights: Vec<GpuLight> = lights[..count].iter().map(Light::to_gpu).collect();
        if !gpu_lights.is_empty() {
            gpu.queue.write_buffer(&self.lights, 0, bytemuck::cast_slice(&gpu_lights));
        }
        if options.culling {
            let needed = (lists.indices.len().max(1) * 4) as u64;
            if needed > self.indices.size() {
                // Grow to the next power of two, and point the bind group at the new buffer.
                self.indices = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("cluster lights"),
                    size: needed.next_power_of_two(),
                    usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                });
                self.group =
                    Self::group(&gpu.device, &self.layout, [&self.frame, &self.lights, &self.ranges, &self.indices]);
            }
            gpu.queue.write_buffer(&self.ranges, 0, bytemuck::cast_slice(&lists.ranges));
            if !lists.indices.is_empty() {
                gpu.queue.write_buffer(&self.indices, 0, bytemuck::cast_slice(&lists.indices));
            }
        }
    }
}
// ANCHOR_END: scene_lights

/// `Composite` in tonemap.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct CompositeUniform {
    exposure: f32,
    bloom_strength: f32,
    mode: u32,
    _padding: u32,
}

// ANCHOR: tonemap
/// From an HDR picture and its bloom to the screen: add the bloom, expose,
/// tone-map (ACES, Narkowicz's fit). Inputs: the two textures, exposure,
/// bloom strength; output: the target it draws into.
pub struct ToneMap {
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    uniform: wgpu::Buffer,
    sampler: wgpu::Sampler,
    group: Option<wgpu::BindGroup>,
    format: wgpu::TextureFormat,
}

impl ToneMap {
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("tone map"),
            entries: &[
                texture_entry(0, FILTERABLE),
                texture_entry(1, FILTERABLE),
                sampler_entry(2),
                uniform_entry(3, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<CompositeUniform>()),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("tone map"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = Self::pipeline(gpu, &pipeline_layout, format)?;
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("composite"),
            size: std::mem::size_of::<CompositeUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("tone map"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Ok(Self { layout, pipeline_layout, pipeline, uniform, sampler, group: None, format })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!("lighting/tonemap.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        gpu.catch_validation(|| {
            fullscreen::pipeline(&gpu.device, "tone map", layout, &module, "fs_composite", format.into(), None)
        })
        .map_err(ShaderError)
    }

    pub fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.pipeline = Self::pipeline(gpu, &self.pipeline_layout, self.format)?;
        Ok(())
    }

    /// Points the tone map at its inputs (again after a resize).
    pub fn set_inputs(&mut self, device: &wgpu::Device, hdr: &wgpu::TextureView, bloom: &wgpu::TextureView) {
        self.group = Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("tone map"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(hdr) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(bloom) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&self.sampler) },
                wgpu::BindGroupEntry { binding: 3, resource: self.uniform.as_entire_binding() },
            ],
        }));
    }

    /// Draws the composite into `frame.target`; `mode` 0 is the picture,
    /// 1 the bloom alone, 2 the HDR picture untouched.
    pub fn draw(&self, gpu: &Gpu, frame: &mut Frame, exposure: f32, bloom_strength: f32, mode: u32) {
        let uniform = CompositeUniform { exposure, bloom_strength, mode, _padding: 0 };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "tone map", frame.target, None);
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, self.group.as_ref().expect("inputs are set at creation and on resize"), &[]);
        pass.draw(0..3, 0..1);
    }
}
// ANCHOR_END: tonemap

/// The HDR picture the scene is drawn into, and its depth buffer (which
/// `stats` reads back). Chapter 09 draws its textured city into one too.
pub struct HdrTarget {
    pub colour: wgpu::TextureView,
    pub depth_texture: wgpu::Texture,
    pub depth: wgpu::TextureView,
}

/// 16-bit floats per channel: room for light far brighter than white.
pub const HDR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

impl HdrTarget {
    pub fn new(device: &wgpu::Device, width: u32, height: u32) -> Self {
        let texture = |label, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let attach = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let colour = texture("hdr", HDR_FORMAT, attach | wgpu::TextureUsages::TEXTURE_BINDING);
        let depth_texture = texture("depth", common::texture::DEPTH_FORMAT, attach | wgpu::TextureUsages::COPY_SRC);
        Self {
            colour: colour.create_view(&Default::default()),
            depth: depth_texture.create_view(&Default::default()),
            depth_texture,
        }
    }
}

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
    layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
}

impl CitySky {
    pub fn new(gpu: &Gpu, lights: &SceneLights) -> Result<Self, ShaderError> {
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
        let pipeline = Self::pipeline(gpu, &layout)?;
        Ok(Self { uniform, group, layout, pipeline })
    }

    fn pipeline(gpu: &Gpu, layout: &wgpu::PipelineLayout) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module =
            shader!("lighting/sky.wgsl", imports: ["lighting/lights.wgsl", "common/fullscreen.wgsl"]).module(gpu)?;
        // At the far plane, behind everything drawn before it.
        let depth = wgpu::DepthStencilState {
            format: common::texture::DEPTH_FORMAT,
            depth_write_enabled: Some(false),
            depth_compare: Some(wgpu::CompareFunction::LessEqual),
            stencil: Default::default(),
            bias: Default::default(),
        };
        gpu.catch_validation(|| {
            fullscreen::pipeline(&gpu.device, "sky", layout, &module, "fs_sky", HDR_FORMAT.into(), Some(depth))
        })
        .map_err(ShaderError)
    }

    pub fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.pipeline = Self::pipeline(gpu, &self.layout)?;
        Ok(())
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

    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(1, &self.group, &[]);
        pass.draw(0..3, 0..1);
    }
}
// ANCHOR_END: sky

fn city_shader() -> ShaderFile {
    shader!("lighting/city.wgsl", imports: ["lighting/lights.wgsl"])
}

struct Pipelines {
    flat: wgpu::RenderPipeline,
    gouraud: wgpu::RenderPipeline,
    phong: wgpu::RenderPipeline,
}

fn build_pipelines(gpu: &Gpu, layout: &wgpu::PipelineLayout) -> Result<Pipelines, ShaderError> {
    let module = city_shader().module(gpu)?;
    let buffers = [Some(Vertex::LAYOUT), Some(GpuInstance::LAYOUT)];
    let mesh = |entries| mesh_pipeline(&gpu.device, layout, &module, entries, &buffers, HDR_FORMAT.into());
    gpu.catch_validation(|| Pipelines {
        flat: mesh(("vs_flat", "fs_flat")),
        gouraud: mesh(("vs_gouraud", "fs_gouraud")),
        phong: mesh(("vs_phong", "fs_phong")),
    })
    .map_err(ShaderError)
}

/// The city's meshes, smooth and faceted, and the instance buffer.
struct CityMeshes {
    smooth: Vec<Mesh>,
    faceted: Vec<Mesh>,
    instances: wgpu::Buffer,
    /// Per shape, which instances it draws this frame.
    ranges: Vec<std::ops::Range<u32>>,
    /// The pieces that never move, grouped by shape, ready to copy.
    still: Vec<Vec<GpuInstance>>,
}

impl CityMeshes {
    fn new(device: &wgpu::Device, city: &City) -> Self {
        let smooth = Shape::ALL.iter().map(|s| s.mesh().upload(device, &format!("{s:?}"))).collect();
        let faceted = Shape::ALL.iter().map(|s| faceted(&s.mesh()).upload(device, &format!("{s:?} faceted"))).collect();
        let still = Shape::ALL
            .iter()
            .map(|shape| city.pieces.iter().filter(|p| p.shape == *shape).map(GpuInstance::of).collect())
            .collect();
        let instances = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("city instances"),
            size: (city.pieces.len() as u64 + 1024) * std::mem::size_of::<GpuInstance>() as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Self { smooth, faceted, instances, ranges: Vec::new(), still }
    }

    /// Writes this frame's instances: the still pieces and the moving ones,
    /// grouped by shape, so that each shape is one instanced draw.
    fn write(&mut self, gpu: &Gpu, moving: &[Piece]) {
        let mut all = Vec::new();
        self.ranges.clear();
        for (i, shape) in Shape::ALL.iter().enumerate() {
            let start = all.len() as u32;
            all.extend_from_slice(&self.still[i]);
            all.extend(moving.iter().filter(|p| p.shape == *shape).map(GpuInstance::of));
            self.ranges.push(start..all.len() as u32);
        }
        let bytes = (all.len() * std::mem::size_of::<GpuInstance>()) as u64;
        if bytes > self.instances.size() {
            self.instances = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("city instances"),
                size: bytes.next_power_of_two(),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
        }
        gpu.queue.write_buffer(&self.instances, 0, bytemuck::cast_slice(&all));
    }

    /// One instanced draw per shape.
    fn draw(&self, pass: &mut wgpu::RenderPass<'_>, faceted: bool) {
        pass.set_vertex_buffer(1, self.instances.slice(..));
        let meshes = if faceted { &self.faceted } else { &self.smooth };
        for (mesh, range) in meshes.iter().zip(&self.ranges) {
            if !range.is_empty() {
                mesh.draw(pass, range.clone());
            }
        }
    }
}

/// The city's materials as they look at this time of day (lamps and
/// windows glow only as night falls), with or without highlights.
fn materials(night: f32, highlights: bool) -> Vec<GpuMaterial> {
    Material::ALL
        .iter()
        .map(|m| {
            let s = m.surface();
            let glow = if s.at_night { night } else { 1.0 };
            GpuMaterial {
                albedo: s.albedo.into(),
                specular: if highlights { s.specular } else { 0.0 },
                emissive: (s.emissive * glow).into(),
                shininess: s.shininess,
            }
        })
        .collect()
}

// ANCHOR: cameras
/// High over the south-west corner, looking at the middle of the city.
pub fn aerial_camera(aspect: f32) -> Camera {
    Camera {
        near: 0.5,
        far: 900.0,
        ..Camera::looking_at(Vec3::new(-190.0, 120.0, 230.0), Vec3::new(0.0, 10.0, 0.0), aspect)
    }
}

/// Standing in the road along x = 0, at the southern edge, looking north.
pub fn street_camera(aspect: f32) -> Camera {
    Camera {
        near: 0.3,
        far: 900.0,
        ..Camera::looking_at(Vec3::new(-3.0, 1.8, 185.0), Vec3::new(-3.0, 8.0, 0.0), aspect)
    }
}

/// Close to the glass sphere, from the south-west, with the morning sun on it.
pub fn sphere_camera(city: &City, aspect: f32) -> Camera {
    let centre = city.sphere_building + Vec3::Y * 24.0;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + Vec3::new(-18.0, 6.0, 34.0), centre, aspect) }
}

/// Behind and above a car, looking where it goes.
pub fn follow_camera(car: &paths::Pose, aspect: f32) -> Camera {
    let ahead = car.forward();
    let eye = car.position - ahead * 12.0 + Vec3::Y * 4.5;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(eye, car.position + ahead * 12.0, aspect) }
}
// ANCHOR_END: cameras

// ANCHOR: frame_lights
/// The lights of this frame: the moving ones (cars, drones), then the
/// still ones (street lamps and lit buildings, which come on as night falls,
/// `night` from 0 by day to 1), then beacons, up to the view's count. A
/// light that is off is not in the list at all: it would cost the loop
/// without adding anything.
pub fn frame_lights(city: &City, traffic: &Traffic, beacons: &[Light], count: LightCount, night: f32) -> Vec<Light> {
    let dimmed = |light: &Light| Light { colour: light.colour * night, ..*light };
    let fixed = city.fixed_lights.iter().filter(|_| night > 0.0).map(dimmed);
    let all = traffic.lights.iter().copied().chain(fixed);
    match count {
        LightCount::City => all.collect(),
        LightCount::First(n) => all.chain(beacons.iter().copied()).take(n.min(MAX_LIGHTS) as usize).collect(),
    }
}
// ANCHOR_END: frame_lights

/// Small coloured lights scattered over the city: not part of its design,
/// there to fill the bench's larger light counts.
pub fn beacons(count: usize) -> Vec<Light> {
    let mut rng = instancing::Rng::new(21);
    (0..count)
        .map(|_| {
            let hue = rng.unit();
            Light {
                position: Vec3::new(rng.range(-170.0, 170.0), rng.range(1.0, 50.0), rng.range(-170.0, 170.0)),
                colour: Vec3::new(0.3 + 0.7 * hue, 0.5, 1.0 - 0.6 * hue) * rng.range(20.0, 60.0),
                range: rng.range(6.0, 22.0),
                kind: lights::LightKind::Point,
            }
        })
        .collect()
}

pub struct LightingChapter {
    pub city: City,
    pub settings: Settings,
    pub clocks: Clocks,
    pub camera: Camera,
    pub controller: FlyController,
    /// The camera rides behind the first car (the `follow` preset).
    pub follow: bool,
    /// Scene time of the last frame, for pausing and the follow camera.
    last_time: f32,
    beacons: Vec<Light>,
    meshes: CityMeshes,
    scene_lights: SceneLights,
    materials: wgpu::Buffer,
    sky: CitySky,
    city_group: wgpu::BindGroup,
    layout: wgpu::PipelineLayout,
    pipelines: Pipelines,
    hdr: HdrTarget,
    pub bloom: Bloom,
    tone_map: ToneMap,
    target: Target,
    /// The cluster lists of the last frame, and how many lights it had.
    last_lists: ClusterLists,
    last_light_count: usize,
}

impl Chapter for LightingChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0086; outliers at most 0.1%.
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.013, outliers: 0.002 };
    const TITLE: &'static str = "08 · Lighting";
    const VIEWS: &'static [View] = VIEWS;
    const SNAPSHOT_TIME: f32 = 6.0;
    const BENCH_FRAMES: u32 = 5;
    const BENCH_BASELINE: Option<&'static str> = Some("lights-1");
    const KEYS: &'static [(&'static str, &'static str)] = &[
        ("W A S D / arrows", "move (leaves the car you follow)"),
        ("E / Space, Q / Shift+Space", "rise, fall"),
        ("left drag, or Tab to lock", "look around"),
        ("[", "pause or resume the drones"),
        ("]", "pause or resume the cars"),
    ];

    fn gpu_needs() -> common::GpuNeeds {
        common::GpuNeeds { required: wgpu::Features::empty(), optional: Bloom::OPTIONAL_FEATURES }
    }

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let city = City::new();
        let scene_lights = SceneLights::new(device);
        let materials = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("materials"),
            contents: bytemuck::cast_slice(&materials(0.0, true)),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        });
        let city_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("city"),
            entries: &[storage_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT)],
        });
        let city_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("city"),
            layout: &city_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: materials.as_entire_binding() }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("city"),
            bind_group_layouts: &[Some(&scene_lights.layout), Some(&city_layout)],
            immediate_size: 0,
        });
        let pipelines = build_pipelines(gpu, &layout)?;
        let sky = CitySky::new(gpu, &scene_lights)?;
        let hdr = HdrTarget::new(device, target.width, target.height);
        let bloom = Bloom::new(gpu, target.width, target.height)?;
        let mut tone_map = ToneMap::new(gpu, target.format)?;
        tone_map.set_inputs(device, &hdr.colour, bloom.output());
        Ok(Self {
            camera: aerial_camera(target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            settings: Settings::for_view("day"),
            clocks: Clocks::default(),
            follow: false,
            last_time: 0.0,
            beacons: beacons(MAX_LIGHTS as usize),
            meshes: CityMeshes::new(device, &city),
            city,
            scene_lights,
            materials,
            sky,
            city_group,
            layout,
            pipelines,
            hdr,
            bloom,
            tone_map,
            target,
            last_lists: ClusterLists::default(),
            last_light_count: 0,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.hdr = HdrTarget::new(&gpu.device, target.width, target.height);
        self.bloom.resize(&gpu.device, target.width, target.height);
        self.tone_map.set_inputs(&gpu.device, &self.hdr.colour, self.bloom.output());
    }

    fn select_view(&mut self, view: usize) {
        self.settings = Settings::for_view(VIEWS[view].name);
    }

    fn reset_camera(&mut self, view: usize) {
        let aspect = self.target.aspect();
        self.follow = VIEWS[view].name == "follow";
        self.camera = match VIEWS[view].name {
            "flat" | "gouraud" | "phong" | "blinn-phong" => sphere_camera(&self.city, aspect),
            "follow" => {
                let traffic = self.city.traffic(self.clocks.cars.time(self.last_time), 0.0);
                follow_camera(&traffic.cars[0], aspect)
            }
            _ => aerial_camera(aspect),
        };
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        let moving = [KeyCode::KeyW, KeyCode::KeyA, KeyCode::KeyS, KeyCode::KeyD, KeyCode::ArrowUp, KeyCode::ArrowDown];
        if moving.iter().any(|&k| input.held(k)) {
            self.follow = false;
        }
        if input.pressed(KeyCode::BracketLeft) {
            self.clocks.drones.set_paused(!self.clocks.drones.is_paused(), self.last_time);
        }
        if input.pressed(KeyCode::BracketRight) {
            self.clocks.cars.set_paused(!self.clocks.cars.is_paused(), self.last_time);
        }
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.last_time = frame.time;
        let s = self.settings;
        let day = daylight(s.time_of_day.phase(frame.time, s.day_seconds));
        let traffic = self.city.traffic(self.clocks.cars.time(frame.time), self.clocks.drones.time(frame.time));
        if self.follow {
            self.camera = follow_camera(&traffic.cars[0], self.target.aspect());
        }
        let camera = self.camera;

        // The frame's lights, culled into cluster lists on the CPU.
        let lights = frame_lights(&self.city, &traffic, &self.beacons, s.lights, day.night);
        self.last_lists = if s.culling {
            frame.timer.cpu("light culling", || clusters::cull(&camera, &lights))
        } else {
            ClusterLists::default()
        };
        self.last_light_count = lights.len();
        let options =
            LoopOptions { culling: s.culling, highlight: s.highlight, heat_map: s.display == Display::LightTiles };
        self.scene_lights.write(gpu, &camera, &day, &lights, &self.last_lists, options);
        self.meshes.write(gpu, &traffic.pieces());
        gpu.queue.write_buffer(&self.materials, 0, bytemuck::cast_slice(&materials(day.night, s.highlights)));
        self.sky.write(gpu, &camera, &day);

        // The scene, in HDR.
        {
            let black = wgpu::Color::BLACK;
            let mut pass = common::chapter::scene_pass(
                frame.encoder,
                frame.timer,
                "scene",
                &self.hdr.colour,
                black,
                &self.hdr.depth,
            );
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            pass.set_bind_group(1, &self.city_group, &[]);
            pass.set_pipeline(match s.shading {
                Shading::Flat => &self.pipelines.flat,
                Shading::Gouraud => &self.pipelines.gouraud,
                Shading::Phong => &self.pipelines.phong,
            });
            self.meshes.draw(&mut pass, s.shading == Shading::Flat);
            self.sky.draw(&mut pass);
        }

        // Bloom, then tone mapping to the target.
        let bloom = s.bloom_on && s.display != Display::LightTiles;
        if bloom {
            self.bloom.render(gpu, frame.encoder, frame.timer, &self.hdr.colour, &s.bloom);
        }
        let mode = match s.display {
            Display::Scene => 0,
            Display::BloomOnly => 1,
            Display::LightTiles => 2,
        };
        let strength = if bloom { s.bloom.strength } else { 0.0 };
        self.tone_map.draw(gpu, frame, s.exposure, strength, mode);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            ui.label("time of day");
            for time in TimeOfDay::ALL {
                ui.radio_value(&mut s.time_of_day, time, format!("{time:?}").to_lowercase());
            }
        });
        ui.horizontal(|ui| {
            ui.label("shading");
            ui.radio_value(&mut s.shading, Shading::Flat, "flat");
            ui.radio_value(&mut s.shading, Shading::Gouraud, "Gouraud");
            ui.radio_value(&mut s.shading, Shading::Phong, "Phong");
        });
        ui.horizontal(|ui| {
            ui.label("highlight");
            ui.radio_value(&mut s.highlight, Highlight::Phong, "Phong");
            ui.radio_value(&mut s.highlight, Highlight::BlinnPhong, "Blinn-Phong");
            ui.checkbox(&mut s.highlights, "on");
        });
        let city_lights =
            self.city.fixed_lights.len() as u32 + 2 * self.city.cars.len() as u32 + self.city.drones.len() as u32;
        let mut count = match s.lights {
            LightCount::City => city_lights,
            LightCount::First(n) => n,
        };
        if ui.add(egui::Slider::new(&mut count, 0..=MAX_LIGHTS).text("lights")).changed() {
            s.lights = if count == city_lights { LightCount::City } else { LightCount::First(count) };
        }
        ui.checkbox(&mut s.culling, "cull lights per cluster (off: every fragment visits every light)");
        ui.checkbox(&mut s.bloom_on, "bloom");
        ui.add(egui::Slider::new(&mut s.bloom.threshold, 0.2..=4.0).text("bloom threshold"));
        ui.add(egui::Slider::new(&mut s.bloom.strength, 0.0..=2.0).text("bloom strength"));
        ui.add(egui::Slider::new(&mut s.bloom.spread, 0.0..=1.0).text("bloom spread"));
        ui.add(egui::Slider::new(&mut s.exposure, 0.1..=4.0).logarithmic(true).text("exposure"));
        ui.horizontal(|ui| {
            ui.radio_value(&mut s.display, Display::Scene, "picture");
            ui.radio_value(&mut s.display, Display::BloomOnly, "bloom only");
            ui.radio_value(&mut s.display, Display::LightTiles, "lights per fragment");
        });
        let time = self.last_time;
        ui.horizontal(|ui| {
            let mut cars = self.clocks.cars.is_paused();
            if ui.checkbox(&mut cars, "pause cars (])").changed() {
                self.clocks.cars.set_paused(cars, time);
            }
            let mut drones = self.clocks.drones.is_paused();
            if ui.checkbox(&mut drones, "pause drones ([)").changed() {
                self.clocks.drones.set_paused(drones, time);
            }
        });
        let aspect = self.target.aspect();
        ui.horizontal(|ui| {
            ui.label("camera");
            if ui.button("aerial").clicked() {
                (self.camera, self.follow) = (aerial_camera(aspect), false);
            }
            if ui.button("street").clicked() {
                (self.camera, self.follow) = (street_camera(aspect), false);
            }
            if ui.button("follow a car").clicked() {
                self.follow = true;
            }
        });
        let listed = self.last_lists.indices.len();
        ui.label(format!(
            "{} lights; {} cluster entries ({:.1} per cluster); bloom {:?}, {} levels",
            self.last_light_count,
            listed,
            listed as f32 / CLUSTERS as f32,
            self.bloom.format,
            self.bloom.sizes().len()
        ));
    }

    fn stats(&mut self, gpu: &Gpu) -> String {
        let per_pixel = lights_per_pixel(
            gpu,
            &self.hdr,
            &self.camera,
            &self.last_lists,
            self.last_light_count,
            self.settings.culling,
        );
        let count = self.last_light_count;
        format!(
            "{count} light{}; lights visited per covered pixel: {}; bloom in {:?}",
            if count == 1 { "" } else { "s" },
            per_pixel.map_or("n/a".into(), |v| format!("{v:.2}")),
            self.bloom.format
        )
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        let pipelines = build_pipelines(gpu, &self.layout)?;
        self.sky.reload_shaders(gpu)?;
        self.bloom.reload_shaders(gpu)?;
        self.tone_map.reload_shaders(gpu)?;
        self.pipelines = pipelines;
        Ok(())
    }
}

/// The average number of lights the loop visits per pixel that shows the
/// city (not the sky) in the last frame: from its depth buffer, each
/// pixel's cluster, and that cluster's list.
fn lights_per_pixel(
    gpu: &Gpu,
    hdr: &HdrTarget,
    camera: &Camera,
    lists: &ClusterLists,
    light_count: usize,
    culling: bool,
) -> Option<f64> {
    // Copying a depth texture out is optional on downlevel backends (GL):
    // without it the figure is "n/a" rather than a wgpu validation panic.
    let copies = wgpu::DownlevelFlags::DEPTH_TEXTURE_AND_BUFFER_COPIES;
    if !gpu.adapter.get_downlevel_capabilities().flags.contains(copies) {
        return None;
    }
    let depths = common::headless::read_floats(gpu, &hdr.depth_texture).ok()?;
    let (width, height) = (hdr.depth_texture.width(), hdr.depth_texture.height());
    let (near, far) = (camera.near, camera.far);
    let (mut visited, mut pixels) = (0u64, 0u64);
    for (i, depth) in depths.iter().map(|d| d[0]).enumerate() {
        if depth >= 1.0 {
            continue;
        }
        pixels += 1;
        if !culling {
            visited += light_count as u64;
            continue;
        }
        // Back from stored depth to distance (chapter 02), and to the pixel's cluster.
        let distance = near * far / (far - depth * (far - near));
        let (x, y) = ((i as u32 % width) * clusters::GRID[0] / width, (i as u32 / width) * clusters::GRID[1] / height);
        let z = clusters::slice(distance, near, far).clamp(0, clusters::GRID[2] as i32 - 1) as u32;
        let cluster = ((z * clusters::GRID[1] + y) * clusters::GRID[0] + x) as usize;
        visited += u64::from(lists.ranges.get(cluster).map_or(0, |r| r[1]));
    }
    (pixels > 0).then(|| visited as f64 / pixels as f64)
}
