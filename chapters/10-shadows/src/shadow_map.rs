//! The shadow map: the scene's depth as the sun sees it, rendered first,
//! then read by every lit fragment. This module renders the depth inside
//! the sun's box (fitted by the `light_box` module) with a bias, and binds
//! the map for the main pass with the settings its filters need.

use common::chapter::{storage_entry, texture_entry, uniform_entry};
use common::{Drawn, Gpu, PassCount, PassTimer, Reloadable, ShaderError, shader, wgpu};
use textures::DrawList;
use textures::mesh::{ModelInstance, TexturedVertex};

// The box is the map's input: chapter 11 and the diagrams import both from here.
pub use crate::light_box::{LightBox, fit_light};

// ANCHOR: settings
/// A depth format: the map stores one distance per texel, nothing else.
pub const SHADOW_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// The sizes the overlay offers, in texels along each side.
pub const SIZES: [u32; 4] = [512, 1024, 2048, 4096];
pub const DEFAULT_SIZE: u32 = 2048;

/// How a fragment turns the map into light.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    /// No lookup: everything in full sun (the bench's baseline).
    Off,
    /// One comparison: in or out, with the map's texels for edges.
    Hard,
    /// Nine comparisons a texel apart, averaged.
    Pcf3x3,
    /// Sixteen comparisons on a Poisson disk, turned per pixel (the seed's).
    Poisson,
    /// Poisson, widened by the distance to the blocker (contact hardening).
    Pcss,
}

impl Filter {
    pub const ALL: [Filter; 5] = [Filter::Off, Filter::Hard, Filter::Pcf3x3, Filter::Poisson, Filter::Pcss];

    pub fn label(self) -> &'static str {
        match self {
            Filter::Off => "off",
            Filter::Hard => "hard (1 tap)",
            Filter::Pcf3x3 => "3×3 PCF",
            Filter::Poisson => "Poisson, 16 taps",
            Filter::Pcss => "PCSS",
        }
    }
}

/// Two ways of keeping a surface from shadowing itself. `constant` and
/// `slope_scale` go to the shadow pass's depth-bias state: the rasteriser
/// pushes each stored depth away from the sun by `constant` of the depth
/// format's smallest steps plus `slope_scale` times the triangle's depth
/// slope (how much its depth changes per texel). `normal_offset` moves
/// the point a fragment looks up along its normal, in shadow-map texels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bias {
    pub constant: i32,
    pub slope_scale: f32,
    pub normal_offset: f32,
}

impl Bias {
    /// None at all: acne.
    pub const NONE: Bias = Bias { constant: 0, slope_scale: 0.0, normal_offset: 0.0 };
    /// Enough, and no more: the chapter's default.
    pub const DEFAULT: Bias = Bias { constant: 0, slope_scale: 1.5, normal_offset: 1.0 };
    /// Far too much: shadows come loose from what casts them.
    pub const TOO_MUCH: Bias = Bias { constant: 60_000, slope_scale: 1.5, normal_offset: 1.0 };
}

/// Which faces the shadow pass leaves out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cull {
    /// Those facing away from the sun, as the main pass does.
    Back,
    /// Those facing the sun: the map keeps the far sides of solids.
    Front,
    None,
}

/// Everything the shadow pass and the lookups depend on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowSettings {
    /// Texels along each side, as asked for (clamped when the map is made).
    pub size: u32,
    pub filter: Filter,
    pub bias: Bias,
    pub cull: Cull,
    /// Poisson's disk radius, in texels.
    pub radius: f32,
    /// PCSS: penumbra width per metre between blocker and receiver. The
    /// sun's disk is 0.53° wide, tan 0.53° = 0.0093; a wider light softens more.
    pub light_width: f32,
}

impl ShadowSettings {
    /// A 2048² map, looked up on a Poisson disk, with enough bias.
    pub const DEFAULT: Self = Self {
        size: DEFAULT_SIZE,
        filter: Filter::Poisson,
        bias: Bias::DEFAULT,
        cull: Cull::Back,
        radius: 2.0,
        light_width: 0.04,
    };
}

impl Default for ShadowSettings {
    fn default() -> Self {
        Self::DEFAULT
    }
}
// ANCHOR_END: settings

// ANCHOR: clamp
/// The size the map will have: `requested`, kept within the chapter's
/// range and the adapter's largest texture, with a note when it had to be
/// changed.
pub fn clamp_size(requested: u32, adapter_max: u32) -> (u32, Option<String>) {
    let largest = SIZES[SIZES.len() - 1].min(adapter_max);
    let size = requested.clamp(SIZES[0].min(largest), largest);
    let note = (size != requested).then(|| {
        format!(
            "a {requested}² shadow map was asked for; this chapter takes {}² to {}² and this adapter at most {adapter_max}²: using {size}²",
            SIZES[0],
            SIZES[SIZES.len() - 1]
        )
    });
    (size, note)
}
// ANCHOR_END: clamp

// ANCHOR: uniform
/// `Shadow` in shadow.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ShadowUniform {
    light_view_proj: [[f32; 4]; 4],
    options: [u32; 4],
    params: [f32; 4],
    extent: [f32; 4],
}
// ANCHOR_END: uniform

/// The map, the samplers that read it, and the pass that renders it.
/// Inputs: the light's box, the settings, and what casts shadows; output:
/// [`ShadowMap::group`], group 3 of any shader that imports
/// `shadows::shadow`. A piece of its own, so that chapter 11 can cast
/// shadows too.
pub struct ShadowMap {
    /// Texels along each side, after clamping.
    pub size: u32,
    /// What clamping the requested size had to say, if anything.
    pub note: Option<String>,
    pub view: wgpu::TextureView,
    uniform: wgpu::Buffer,
    compare_nearest: wgpu::Sampler,
    compare_linear: wgpu::Sampler,
    /// Reads one depth texel as a float, for PCSS's blocker search.
    depth_nearest: wgpu::Sampler,
    pub layout: wgpu::BindGroupLayout,
    pub group: wgpu::BindGroup,
    caster_layout: wgpu::PipelineLayout,
    caster_group: wgpu::BindGroup,
    /// The shadow pass's pipeline, with the bias and culling it was made
    /// with: made again when they change (the old one is dropped) and when
    /// caster.wgsl is saved (hot reload).
    caster: (Bias, Cull, Reloadable<wgpu::RenderPipeline>),
}

/// What the shadow pass's pipeline is made for: the depth bias and the
/// culling. The normal offset is the lookups' business: changing it makes
/// no new pipeline.
fn caster_key(settings: &ShadowSettings) -> (Bias, Cull) {
    (Bias { normal_offset: 0.0, ..settings.bias }, settings.cull)
}

/// A sampler that reads one texel, read by fragment shaders: a depth map
/// bound as plain floats goes through one (chapter 02's depth view).
fn nearest_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
        count: None,
    }
}

/// A comparison sampler read by fragment shaders.
fn comparison_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
        count: None,
    }
}

impl ShadowMap {
    pub fn new(gpu: &Gpu, requested_size: u32) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let (size, note) = clamp_size(requested_size, device.limits().max_texture_dimension_2d);
        // ANCHOR: samplers
        // Comparison samplers: a lookup returns how many of the texels it
        // reads pass `depth <= stored`, not the depth itself.
        let comparison = |filter| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some("shadow comparison"),
                mag_filter: filter,
                min_filter: filter,
                compare: Some(wgpu::CompareFunction::LessEqual),
                ..Default::default()
            })
        };
        let compare_nearest = comparison(wgpu::FilterMode::Nearest);
        let compare_linear = comparison(wgpu::FilterMode::Linear);
        // ANCHOR_END: samplers
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shadow"),
            entries: &[
                texture_entry(0, wgpu::TextureSampleType::Depth),
                comparison_entry(1),
                comparison_entry(2),
                // Storage, not uniform: `sunlit` switches on the filter (see `storage_entry`).
                storage_entry(3, fragment),
                // The map again, as floats read through "nearest", for PCSS.
                texture_entry(4, wgpu::TextureSampleType::Float { filterable: false }),
                nearest_entry(5),
                // And once more for the blended comparisons (GLSL reads a
                // texture through one sampler only).
                texture_entry(6, wgpu::TextureSampleType::Depth),
            ],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shadow"),
            size: std::mem::size_of::<ShadowUniform>() as u64,
            // The caster pass reads its first 64 bytes as a uniform.
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let caster_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shadow caster"),
            entries: &[uniform_entry(0, wgpu::ShaderStages::VERTEX, 64)],
        });
        let caster_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadow caster"),
            layout: &caster_group_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &uniform,
                    offset: 0,
                    size: wgpu::BufferSize::new(64),
                }),
            }],
        });
        let caster_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadow caster"),
            bind_group_layouts: &[Some(&caster_group_layout)],
            immediate_size: 0,
        });
        let (bias, cull) = caster_key(&ShadowSettings::DEFAULT);
        let caster = (bias, cull, Self::caster(gpu, &caster_layout, bias, cull)?);
        let view = Self::texture(device, size);
        let depth_nearest =
            device.create_sampler(&wgpu::SamplerDescriptor { label: Some("depth"), ..Default::default() });
        let samplers = [&compare_nearest, &compare_linear, &depth_nearest];
        let group = Self::group(device, &layout, &view, samplers, &uniform);
        Ok(Self {
            size,
            note,
            view,
            uniform,
            compare_nearest,
            compare_linear,
            depth_nearest,
            layout,
            group,
            caster_layout,
            caster_group,
            caster,
        })
    }

    // ANCHOR: texture
    /// The map: a depth texture the shadow pass renders into and the main
    /// pass samples.
    fn texture(device: &wgpu::Device, size: u32) -> wgpu::TextureView {
        device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("shadow map"),
                size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: SHADOW_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            })
            .create_view(&Default::default())
    }
    // ANCHOR_END: texture

    fn group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        view: &wgpu::TextureView,
        [nearest, linear, depth_nearest]: [&wgpu::Sampler; 3],
        uniform: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadow"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(nearest) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(linear) },
                wgpu::BindGroupEntry { binding: 3, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 4, resource: wgpu::BindingResource::TextureView(view) },
                wgpu::BindGroupEntry { binding: 5, resource: wgpu::BindingResource::Sampler(depth_nearest) },
                wgpu::BindGroupEntry { binding: 6, resource: wgpu::BindingResource::TextureView(view) },
            ],
        })
    }

    fn samplers(&self) -> [&wgpu::Sampler; 3] {
        [&self.compare_nearest, &self.compare_linear, &self.depth_nearest]
    }

    /// Makes the map `requested` texels square (clamped), if it is not already.
    pub fn resize(&mut self, device: &wgpu::Device, requested: u32) {
        let (size, note) = clamp_size(requested, device.limits().max_texture_dimension_2d);
        self.note = note;
        if size == self.size {
            return;
        }
        self.size = size;
        self.view = Self::texture(device, size);
        self.group = Self::group(device, &self.layout, &self.view, self.samplers(), &self.uniform);
    }

    /// The shadow pass's pipeline for `bias` and `cull`, kept up to date
    /// with caster.wgsl.
    fn caster(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        bias: Bias,
        cull: Cull,
    ) -> Result<Reloadable<wgpu::RenderPipeline>, ShaderError> {
        let layout = layout.clone();
        Reloadable::new(gpu, move |gpu| Self::caster_pipeline(gpu, &layout, bias, cull))
    }

    // ANCHOR: caster_pipeline
    /// The shadow pass's pipeline: vertices only, into the depth format,
    /// with the bias in its depth-stencil state.
    fn caster_pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        bias: Bias,
        cull: Cull,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!("shadows/caster.wgsl", imports: ["textures/surface.wgsl"]).module(gpu)?;
        // An edit that validates but has no `vs_caster`, say, is an error,
        // not a panic: the last good pipeline keeps drawing.
        gpu.catch_validation(|| {
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("shadow caster"),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_caster"),
                    buffers: &[Some(TexturedVertex::LAYOUT), Some(ModelInstance::LAYOUT)],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState {
                    cull_mode: match cull {
                        Cull::Back => Some(wgpu::Face::Back),
                        Cull::Front => Some(wgpu::Face::Front),
                        Cull::None => None,
                    },
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: SHADOW_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: Default::default(),
                    bias: wgpu::DepthBiasState { constant: bias.constant, slope_scale: bias.slope_scale, clamp: 0.0 },
                }),
                multisample: Default::default(),
                fragment: None,
                multiview_mask: None,
                cache: None,
            })
        })
        .map_err(ShaderError)
    }
    // ANCHOR_END: caster_pipeline

    /// Writes this frame's box and settings for both passes.
    pub fn write(&self, gpu: &Gpu, light: &LightBox, settings: &ShadowSettings) {
        let filter = Filter::ALL.iter().position(|f| *f == settings.filter).unwrap_or(0) as u32;
        let uniform = ShadowUniform {
            light_view_proj: light.view_proj.to_cols_array_2d(),
            options: [filter, self.size, 0, 0],
            params: [light.texel, settings.bias.normal_offset, settings.radius, settings.light_width],
            extent: [light.depth, 0.0, 0.0, 0.0],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }

    // ANCHOR: render
    /// The shadow pass: the depth of every model in `casters`, as the sun
    /// sees it (their materials play no part). Returns what it drew.
    pub fn render(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        settings: &ShadowSettings,
        casters: &DrawList,
    ) -> PassCount {
        let (bias, cull) = caster_key(settings);
        if (self.caster.0, self.caster.1) != (bias, cull) {
            // While caster.wgsl is broken on disk (the window says why), the
            // last good pipeline keeps drawing and the next frame tries again.
            if let Ok(pipeline) = Self::caster(gpu, &self.caster_layout, bias, cull) {
                self.caster = (bias, cull, pipeline);
            }
        }
        let pipeline = self.caster.2.get();
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadow map"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: timer.pass("shadow map"),
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &self.caster_group, &[]);
        pass.set_vertex_buffer(1, casters.instances.slice(..));
        let mut drawn = Drawn::NOTHING;
        for draw in casters.draws.iter().filter(|d| !d.instances.is_empty()) {
            pass.set_vertex_buffer(0, draw.model.vertices.slice(..));
            pass.set_index_buffer(draw.model.indices.slice(..), wgpu::IndexFormat::Uint32);
            for part in &draw.model.parts {
                pass.draw_indexed(part.indices.clone(), 0, draw.instances.clone());
                drawn += Drawn::triangle_list(part.indices.clone(), draw.instances.clone());
            }
        }
        PassCount { pass: "shadow map", drawn }
    }
    // ANCHOR_END: render
}

/// The `shadow-map` view: the map drawn full screen, its depths stretched
/// over a range so that the level's shapes stand out.
pub struct MapView {
    layout: wgpu::BindGroupLayout,
    /// Made again when show_depth.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    uniform: wgpu::Buffer,
    nearest: wgpu::Sampler,
}

impl MapView {
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shadow map view"),
            entries: &[
                // Plain floats through "nearest", as show_depth.wgsl says.
                texture_entry(0, wgpu::TextureSampleType::Float { filterable: false }),
                uniform_entry(1, wgpu::ShaderStages::FRAGMENT, 16),
                nearest_entry(2),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadow map view"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shadow map view"),
            size: 16,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &pipeline_layout, format))?;
        let nearest = device.create_sampler(&wgpu::SamplerDescriptor { label: Some("nearest"), ..Default::default() });
        Ok(Self { layout, pipeline, uniform, nearest })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!("shadows/show_depth.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        gpu.catch_validation(|| {
            common::fullscreen::pipeline(
                &gpu.device,
                "shadow map view",
                layout,
                &module,
                "fs_depth",
                format.into(),
                None,
            )
        })
        .map_err(ShaderError)
    }

    /// Draws `map` over the frame's target, depths `range.0` black to
    /// `range.1` white, for a target `aspect` wide per unit of height.
    pub fn draw(&self, gpu: &Gpu, frame: &mut common::Frame, map: &ShadowMap, range: (f32, f32), aspect: f32) {
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::cast_slice(&[range.0, range.1, aspect, 0.0]));
        let group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadow map view"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&map.view) },
                wgpu::BindGroupEntry { binding: 1, resource: self.uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&self.nearest) },
            ],
        });
        let mut pass = common::fullscreen::pass(
            frame.encoder,
            frame.timer,
            "shadow map view",
            frame.target,
            Some(wgpu::Color::BLACK),
        );
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(0, &group, &[]);
        pass.draw(0..3, 0..1);
        frame.drawn.add("shadow map view", Drawn::FULL_SCREEN);
    }
}
