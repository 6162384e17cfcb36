//! The Voronoi diagram on the GPU, two ways: by drawing a cone per site
//! with a depth test (Hoff et al. 1999), and by jump flooding (Rong & Tan
//! 2006). Either way the answer is an id texture: each pixel holds the
//! index of the site nearest it, under the tile's wrap-around distance.

use common::chapter::uniform_entry;
use common::glam::Vec2;
use common::{Drawn, Gpu, PassCount, PassTimer, Reloadable, ShaderError, shader, wgpu};

use crate::sites;

/// The id texture's format: one site index per pixel.
pub const ID_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
/// What a pixel no site reached holds.
pub const NONE: u32 = u32::MAX;

/// How the diagram is made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// A cone of `segments` triangles per site, its depth interpolated
    /// across them: a polygon's distance, which gives the seed's wavy edges.
    Cones,
    /// Cones whose fragments work out the true distance: exact to the
    /// pixel whatever the segment count.
    ExactCones,
    /// Jump flooding, with `extra_pass` adding one more pass of step 1
    /// (JFA+1), which mends most of its errors.
    JumpFlooding,
}

impl Method {
    pub fn label(self) -> &'static str {
        match self {
            Method::Cones => "cones",
            Method::ExactCones => "cones, exact depth",
            Method::JumpFlooding => "jump flooding",
        }
    }
}

/// What the diagram is made with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VoronoiSettings {
    pub method: Method,
    /// Triangles around each cone (the seed used 8).
    pub segments: u32,
    /// Each cone's radius as a multiple of the covering radius: below 1,
    /// holes can open where no cone reaches.
    pub radius_scale: f32,
    /// Draw every site again at the 8 neighbouring tile offsets, so the
    /// diagram wraps; off, the tile's edges show seams.
    pub tile_copies: bool,
    /// JFA+1: one more step-1 pass after the usual ones.
    pub extra_pass: bool,
}

impl VoronoiSettings {
    /// Cones of 8 segments, as the seed drew them, tiled.
    pub const DEFAULT: Self =
        Self { method: Method::Cones, segments: 8, radius_scale: 1.0, tile_copies: true, extra_pass: false };
}

impl Default for VoronoiSettings {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// `Cones` in cones.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ConesUniform {
    radius: [f32; 4],
    counts: [u32; 4],
}

/// Jump flooding's passes per picture: one per halving of the step, from
/// half the picture's longer side (rounded up to a power of two) down to 1,
/// plus JFA+1's.
pub fn jump_steps(width: u32, height: u32, extra_pass: bool) -> Vec<u32> {
    let longest = width.max(height).next_power_of_two();
    let mut steps: Vec<u32> =
        std::iter::successors(Some((longest / 2).max(1)), |s| (*s > 1).then_some(s / 2)).collect();
    if extra_pass {
        steps.push(1);
    }
    steps
}

/// The ping-pong textures jump flooding works in (the cones draw into the
/// first), and their sizes.
struct Targets {
    width: u32,
    height: u32,
    ids: [wgpu::Texture; 2],
    views: [wgpu::TextureView; 2],
    depth: wgpu::TextureView,
    /// For each step, the group that reads texture `i % 2` with that step.
    step_groups: Vec<wgpu::BindGroup>,
}

// ANCHOR: piece
/// Makes the diagram. Inputs: the sites (tile coordinates) and the
/// settings; output: [`Voronoi::ids`], a site index per pixel.
pub struct Voronoi {
    sites: wgpu::Buffer,
    capacity: u32,
    uniform: wgpu::Buffer,
    sites_layout: wgpu::BindGroupLayout,
    sites_group: wgpu::BindGroup,
    step_layout: wgpu::BindGroupLayout,
    /// Cones, exact cones, jump flooding's seeds and its step, made again
    /// when cones.wgsl or jump_flood.wgsl is saved (hot reload).
    pipelines: Reloadable<[wgpu::RenderPipeline; 4]>,
    targets: Targets,
    /// Which of the two textures holds the last diagram.
    result: usize,
    /// The cones' radius last frame, for the overlay (tile units).
    pub cone_radius: f32,
}
// ANCHOR_END: piece

impl Voronoi {
    pub fn new(gpu: &Gpu, width: u32, height: u32) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let stages = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let sites_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("voronoi sites"),
            entries: &[
                uniform_entry(0, stages, std::mem::size_of::<ConesUniform>()),
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: stages,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: true },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
            ],
        });
        let step_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("jump flooding step"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::FRAGMENT, 16),
                common::chapter::texture_entry(1, wgpu::TextureSampleType::Uint),
            ],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("cones"),
            size: std::mem::size_of::<ConesUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let capacity = sites::DEFAULT_COUNT;
        let sites = Self::site_buffer(device, capacity);
        let sites_group = Self::sites_group(device, &sites_layout, &uniform, &sites);
        let cones_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("cones"),
            bind_group_layouts: &[Some(&sites_layout)],
            immediate_size: 0,
        });
        let flood_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("jump flooding"),
            bind_group_layouts: &[Some(&sites_layout), Some(&step_layout)],
            immediate_size: 0,
        });
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &cones_layout, &flood_layout))?;
        let targets = Self::targets(device, &step_layout, width, height, false);
        Ok(Self {
            sites,
            capacity,
            uniform,
            sites_layout,
            sites_group,
            step_layout,
            pipelines,
            targets,
            result: 0,
            cone_radius: 0.0,
        })
    }

    fn site_buffer(device: &wgpu::Device, capacity: u32) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("voronoi sites"),
            size: u64::from(capacity.max(1)) * 8,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn sites_group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        uniform: &wgpu::Buffer,
        sites: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("voronoi sites"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: sites.as_entire_binding() },
            ],
        })
    }

    fn pipelines(
        gpu: &Gpu,
        cones_layout: &wgpu::PipelineLayout,
        flood_layout: &wgpu::PipelineLayout,
    ) -> Result<[wgpu::RenderPipeline; 4], ShaderError> {
        let device = &gpu.device;
        let cones = shader!("voronoi-water/cones.wgsl").module(gpu)?;
        let flood = shader!("voronoi-water/jump_flood.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        let id_target = Some(wgpu::ColorTargetState::from(ID_FORMAT));
        let pipeline = |label, layout, module, (vertex, fragment), topology, depth: bool| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module,
                    entry_point: Some(vertex),
                    buffers: &[],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { topology, ..Default::default() },
                depth_stencil: depth.then(common::texture::depth_test).flatten(),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module,
                    entry_point: Some(fragment),
                    targets: std::slice::from_ref(&id_target),
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let triangles = wgpu::PrimitiveTopology::TriangleList;
        gpu.catch_validation(|| {
            [
                pipeline("cones", cones_layout, &cones, ("vs_cone", "fs_cone"), triangles, true),
                pipeline("exact cones", cones_layout, &cones, ("vs_cone", "fs_cone_exact"), triangles, true),
                // The seeds read only the sites: the cones' layout.
                pipeline(
                    "jump flooding seeds",
                    cones_layout,
                    &flood,
                    ("vs_seed", "fs_seed"),
                    wgpu::PrimitiveTopology::PointList,
                    false,
                ),
                pipeline("jump flooding step", flood_layout, &flood, ("vs_fullscreen", "fs_step"), triangles, false),
            ]
        })
        .map_err(ShaderError)
    }

    fn targets(
        device: &wgpu::Device,
        step_layout: &wgpu::BindGroupLayout,
        width: u32,
        height: u32,
        extra_pass: bool,
    ) -> Targets {
        let (width, height) = (width.max(1), height.max(1));
        let texture = |label| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: ID_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            })
        };
        let ids = [texture("voronoi ids"), texture("voronoi ids (jump flooding)")];
        let views = [ids[0].create_view(&Default::default()), ids[1].create_view(&Default::default())];
        let steps = jump_steps(width, height, extra_pass);
        // One 256-byte slot per step: uniform offsets must be aligned.
        let slot = u64::from(device.limits().min_uniform_buffer_offset_alignment).max(16);
        let mut contents = vec![0u8; slot as usize * steps.len()];
        for (i, step) in steps.iter().enumerate() {
            let at = i * slot as usize;
            contents[at..at + 4].copy_from_slice(&step.to_le_bytes());
        }
        let step_uniforms = wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("jump flooding steps"),
                contents: &contents,
                usage: wgpu::BufferUsages::UNIFORM,
            },
        );
        let step_groups = (0..steps.len())
            .map(|i| {
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("jump flooding step"),
                    layout: step_layout,
                    entries: &[
                        wgpu::BindGroupEntry {
                            binding: 0,
                            resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                                buffer: &step_uniforms,
                                offset: i as u64 * slot,
                                size: wgpu::BufferSize::new(16),
                            }),
                        },
                        wgpu::BindGroupEntry {
                            binding: 1,
                            resource: wgpu::BindingResource::TextureView(&views[i % 2]),
                        },
                    ],
                })
            })
            .collect();
        let depth = common::texture::depth_view(device, width, height);
        Targets { width, height, ids, views, depth, step_groups }
    }

    /// The diagram's size in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.targets.width, self.targets.height)
    }

    /// The last diagram: a site index per pixel ([`NONE`] where no site
    /// reached).
    pub fn ids(&self) -> &wgpu::TextureView {
        &self.targets.views[self.result]
    }

    /// The texture behind [`Voronoi::ids`], for reading it back.
    pub fn ids_texture(&self) -> &wgpu::Texture {
        &self.targets.ids[self.result]
    }

    // ANCHOR: render
    /// Makes the diagram of `sites` (tile coordinates) at `width` × `height`;
    /// returns what its passes drew.
    pub fn render(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        sites: &[Vec2],
        (width, height): (u32, u32),
        settings: &VoronoiSettings,
    ) -> PassCount {
        let device = &gpu.device;
        let steps = jump_steps(width.max(1), height.max(1), settings.extra_pass);
        if (width.max(1), height.max(1)) != self.size() || steps.len() != self.targets.step_groups.len() {
            self.targets = Self::targets(device, &self.step_layout, width, height, settings.extra_pass);
        }
        if sites.len() as u32 > self.capacity {
            self.capacity = (sites.len() as u32).next_power_of_two();
            self.sites = Self::site_buffer(device, self.capacity);
            self.sites_group = Self::sites_group(device, &self.sites_layout, &self.uniform, &self.sites);
        }
        if !sites.is_empty() {
            gpu.queue.write_buffer(&self.sites, 0, bytemuck::cast_slice(sites));
        }
        let count = sites.len() as u32;
        match settings.method {
            Method::Cones | Method::ExactCones => self.draw_cones(gpu, encoder, timer, sites, settings),
            Method::JumpFlooding => self.flood(encoder, timer, count, steps.len()),
        }
    }
    // ANCHOR_END: render

    // ANCHOR: draw_cones
    fn draw_cones(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        sites: &[Vec2],
        settings: &VoronoiSettings,
    ) -> PassCount {
        let segments = settings.segments.clamp(3, 256);
        // The polygon's sides come closer to the site than its corners, by
        // cos(π / segments): put the corners farther out, so that even the
        // sides reach the covering radius.
        let reach = sites::covering_radius(sites) * settings.radius_scale;
        let corner = reach / (std::f32::consts::PI / segments as f32).cos();
        self.cone_radius = reach;
        let copies = if settings.tile_copies { 9 } else { 1 };
        let uniform = ConesUniform { radius: [corner, 1.0 / corner, 0.0, 0.0], counts: [segments, copies, 0, 0] };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("voronoi cones"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &self.targets.views[0],
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(none_colour()), store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.targets.depth,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: timer.pass("voronoi cones"),
            ..Default::default()
        });
        let [cones, exact_cones, ..] = self.pipelines.get();
        let exact = settings.method == Method::ExactCones;
        pass.set_pipeline(if exact { &exact_cones } else { &cones });
        pass.set_bind_group(0, &self.sites_group, &[]);
        pass.draw(0..3 * segments, 0..sites.len() as u32 * copies);
        self.result = 0;
        PassCount {
            pass: "voronoi cones",
            drawn: Drawn::triangle_list(0..3 * segments, 0..sites.len() as u32 * copies),
        }
    }
    // ANCHOR_END: draw_cones

    // ANCHOR: flood
    fn flood(&mut self, encoder: &mut wgpu::CommandEncoder, timer: &PassTimer, count: u32, steps: usize) -> PassCount {
        let passes = steps + 1;
        let timing = |index| timer.chain("jump flooding", index, passes);
        let [.., seeds, step] = self.pipelines.get();
        // The sites into texture 0, everything else "no site yet".
        {
            let load = wgpu::LoadOp::Clear(none_colour());
            let mut pass = id_pass(encoder, &self.targets.views[0], load, timing(0));
            pass.set_pipeline(&seeds);
            pass.set_bind_group(0, &self.sites_group, &[]);
            pass.draw(0..count, 0..1);
        }
        // The sites are points; every step after them is one full-screen triangle.
        let mut drawn = Drawn::POINTS_OR_LINES;
        // Each step reads one texture and writes the other.
        for i in 0..steps {
            let mut pass = id_pass(encoder, &self.targets.views[(i + 1) % 2], wgpu::LoadOp::Load, timing(i + 1));
            pass.set_pipeline(&step);
            pass.set_bind_group(0, &self.sites_group, &[]);
            pass.set_bind_group(1, &self.targets.step_groups[i], &[]);
            pass.draw(0..3, 0..1);
            drawn += Drawn::FULL_SCREEN;
        }
        self.result = steps % 2;
        PassCount { pass: "jump flooding", drawn }
    }
    // ANCHOR_END: flood
}

/// A pass that draws into an id texture, without depth.
fn id_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    view: &wgpu::TextureView,
    load: wgpu::LoadOp<wgpu::Color>,
    timestamp_writes: Option<wgpu::RenderPassTimestampWrites<'_>>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("jump flooding"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
        })],
        timestamp_writes,
        ..Default::default()
    })
}

/// [`NONE`] as a clear colour: integer targets take the clear value's
/// channels as whole numbers.
fn none_colour() -> wgpu::Color {
    wgpu::Color { r: f64::from(NONE), g: 0.0, b: 0.0, a: 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jump_flooding_halves_its_step_down_to_one() {
        assert_eq!(jump_steps(512, 512, false), vec![256, 128, 64, 32, 16, 8, 4, 2, 1]);
        assert_eq!(jump_steps(800, 450, true), vec![512, 256, 128, 64, 32, 16, 8, 4, 2, 1, 1]);
        assert_eq!(jump_steps(1, 1, false), vec![1]);
    }
}
