//! The Mars plain so far: chapter 03's terrain in chapter 04's fog, strewn
//! with this chapter's rocks, culled by chunk and drawn instanced (a call
//! per run of visible groups, or all of them in one indirect call), one call
//! per rock, or flat. Chapters 05, 06 and 07 each own one and draw it
//! through explicit inputs.

use std::sync::Arc;

use common::glam::{Vec3, Vec4};
use common::texture::depth_test;
use common::{Camera, Gpu, Reloadable, ShaderError, ShaderFile, Vertex, anyhow, shader, wgpu};
use fog::{FogBinding, FogSettings, fog_shader};
use terrain::heightfield::HeightField;
use terrain::{Detail, Sun, TerrainData, TerrainRenderer, Viewpoint};

use crate::rock_field::{MAX_ONE_PER_DRAW, MAX_ROCKS, RockField, RockInstance};
use crate::rock_groups::{RockRuns, visible_runs};

/// Standing on the plain, eyes 3.5 m up, looking across the rocks at the cliff.
pub fn plain_camera(field: &HeightField, aspect: f32) -> Camera {
    let s = field.settings;
    let x = s.extent() * 0.47 + 60.0;
    let z = s.cliff_line(x) + 230.0;
    let eye = Vec3::new(x, field.height_at(x, z) + 3.5, z);
    let ahead = Vec3::new(x + 40.0, 0.0, z - 200.0);
    let target = Vec3::new(ahead.x, field.height_at(ahead.x, ahead.z) + 2.0, ahead.z);
    Camera { far: fog::MAX_FAR, near: 0.1, ..Camera::looking_at(eye, target, aspect) }
}

/// How the rocks are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// One instanced draw call per run of rocks to draw (all of them, or
    /// the visible groups, neighbours in the buffer joined).
    Instanced,
    /// The same runs in one `multi_draw_indexed_indirect` call, from a list
    /// of draws written to a buffer each frame (`MarsPlain::write_draw_list`).
    Indirect,
    /// One draw call per rock, each with its own uniform offset.
    OnePerDraw,
    /// Instanced, with a flat colour and no lighting or fog: the floor.
    Flat,
    /// Instanced, each rock in its chunk group's colour.
    Groups,
}

/// What a view shows: how many rocks are in the world (the first of the
/// buffer, nearest the start), how they are drawn, whether only the groups
/// in view are drawn, and whether the terrain is drawn too (the bench views
/// leave it out so that the numbers are the rocks' alone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    pub rocks: u32,
    pub mode: Mode,
    pub terrain: bool,
    /// Draw only the rock groups whose box the camera's frustum keeps.
    pub cull: bool,
}

impl Setup {
    /// The plain as the book shows it: the terrain and a million rocks over
    /// the whole map, the groups in view drawn instanced.
    pub const DEFAULT: Self = Self { rocks: MAX_ROCKS, mode: Mode::Instanced, terrain: true, cull: true };
}

/// What a device drawing the plain needs: chapter 03's needs, and indirect
/// draws that may start past instance 0, for `Mode::Indirect` (without
/// them, that mode draws as `Instanced` does).
pub fn gpu_needs() -> common::GpuNeeds {
    let terrain = terrain::gpu_needs();
    common::GpuNeeds { optional: terrain.optional | wgpu::Features::INDIRECT_FIRST_INSTANCE, ..terrain }
}

fn rocks_shader() -> ShaderFile {
    shader!("instancing/rocks.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl"])
}

/// The plain's pipelines: the terrain in fog, and the rocks drawn three ways.
#[derive(Clone)]
struct Pipelines {
    terrain: wgpu::RenderPipeline,
    instanced: wgpu::RenderPipeline,
    one_per_draw: wgpu::RenderPipeline,
    flat: wgpu::RenderPipeline,
    groups: wgpu::RenderPipeline,
}

fn rock_pipeline(
    gpu: &Gpu,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    format: wgpu::TextureFormat,
    vertex_entry: &str,
    fragment_entry: &str,
) -> wgpu::RenderPipeline {
    let instanced = vertex_entry == "vs_instanced";
    let buffers = [Some(Vertex::LAYOUT), instanced.then_some(RockInstance::LAYOUT)];
    gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(vertex_entry),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vertex_entry),
            buffers: if instanced { &buffers } else { &buffers[..1] },
            compilation_options: Default::default(),
        },
        primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
        depth_stencil: depth_test(),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fragment_entry),
            targets: &[Some(format.into())],
            compilation_options: Default::default(),
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Draw calls recorded for one picture of the plain, and the rocks drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawCalls {
    /// One per terrain chunk in view.
    pub terrain: u32,
    /// One per run of rock groups, one in all (indirect), or one per rock.
    pub rocks: u32,
    /// Rocks drawn: the world's (`Setup::rocks`), less the culled groups'.
    pub rocks_drawn: u32,
    /// Rock groups (chunks with rocks) drawn.
    pub rock_groups: u32,
}

impl DrawCalls {
    pub fn total(&self) -> u32 {
        self.terrain + self.rocks
    }
}

// ANCHOR: mars_plain
/// The Mars plain: chapter 03's terrain in chapter 04's fog, strewn with this
/// chapter's rocks. Chapters 05, 06 and 07 each own one and draw it through
/// explicit inputs: a viewpoint aimed from a camera, the sun, the air, and
/// what the picture should show.
pub struct MarsPlain {
    pub terrain: TerrainRenderer,
    rocks: Arc<RockField>,
    /// The fog's uniform (group 1), the same for every picture of a frame.
    pub fog: FogBinding,
    singles_group: wgpu::BindGroup,
    /// The draws of `Mode::Indirect`, written each frame: one
    /// `DrawIndexedIndirectArgs` per run, at most one per group.
    draw_list: wgpu::Buffer,
    /// Whether indirect draws may start at an instance other than 0 (the
    /// `INDIRECT_FIRST_INSTANCE` feature); without it `Mode::Indirect` draws
    /// as `Mode::Instanced` does.
    indirect_ok: bool,
    /// Rebuilt when fog.wgsl, rocks.wgsl or terrain.wgsl is saved (hot reload).
    pipelines: Reloadable<Pipelines>,
}
// ANCHOR_END: mars_plain

impl MarsPlain {
    /// The plain of `terrain` (what `TerrainData::prepare` made), for
    /// targets of `format`.
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat, terrain: Arc<TerrainData>) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let terrain = TerrainRenderer::new(gpu, terrain);
        let rocks = RockField::get(gpu, terrain.field(), terrain.chunk_bounds());
        let draw_list = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("rock draw list"),
            size: (rocks.groups.len().max(1) * std::mem::size_of::<wgpu::util::DrawIndexedIndirectArgs>()) as u64,
            usage: wgpu::BufferUsages::INDIRECT | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let indirect_ok = device.features().contains(wgpu::Features::INDIRECT_FIRST_INSTANCE);
        let fog = FogBinding::new(device);
        let single_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("one rock"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: true,
                    min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<RockInstance>() as u64),
                },
                count: None,
            }],
        });
        let layout = |label, groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        let shared = [Some(&terrain.bind_group_layout), Some(&fog.layout)];
        let layouts =
            [layout("rocks", &shared), layout("one rock per draw", &[shared[0], shared[1], Some(&single_layout)])];
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &layouts, format))?;
        let singles_group = Self::singles_group(device, &single_layout, &rocks);
        Ok(Self { terrain, rocks, fog, singles_group, draw_list, indirect_ok, pipelines })
    }

    fn pipelines(
        gpu: &Gpu,
        layouts: &[wgpu::PipelineLayout; 2],
        format: wgpu::TextureFormat,
    ) -> Result<Pipelines, ShaderError> {
        let terrain = TerrainRenderer::pipeline(gpu, &fog_shader(), &layouts[0], format)?;
        let module = rocks_shader().module(gpu)?;
        gpu.catch_validation(|| Pipelines {
            terrain,
            instanced: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_main"),
            one_per_draw: rock_pipeline(gpu, &module, &layouts[1], format, "vs_single", "fs_main"),
            flat: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_flat"),
            groups: rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", "fs_groups"),
        })
        .map_err(ShaderError)
    }

    fn singles_group(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, rocks: &RockField) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("one rock"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &rocks.singles,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<RockInstance>() as u64),
                }),
            }],
        })
    }

    /// How many rocks there are to draw.
    pub fn rocks_placed(&self) -> u32 {
        self.rocks.placed
    }

    /// Rock groups with rocks in them, of the first `count` rocks.
    pub fn rock_groups(&self, count: u32) -> u32 {
        visible_runs(&self.rocks.groups, count, None).groups
    }

    /// The rocks, grouped by chunk.
    pub fn rock_field(&self) -> &RockField {
        &self.rocks
    }

    /// Bytes of the buffers this plain made on the GPU, by our own count:
    /// (the terrain's maps and patch grid, rocks and their draw list).
    /// Uniforms and each viewpoint's patch list come on top; they are kilobytes.
    pub fn gpu_bytes(&self) -> (u64, u64) {
        (self.terrain.data().maps.gpu_bytes(), self.rocks.gpu_bytes() + self.draw_list.size())
    }

    /// Makes the terrain again from `self.terrain.settings`, and the rocks on it.
    pub fn regenerate(&mut self, gpu: &Gpu) {
        self.terrain.regenerate(gpu);
        self.rocks = RockField::get(gpu, self.terrain.field(), self.terrain.chunk_bounds());
        let layout = self.pipelines.get().one_per_draw.get_bind_group_layout(2);
        self.singles_group = Self::singles_group(&gpu.device, &layout, &self.rocks);
    }

    /// Sets the air every picture of this frame is seen through: `fog`, in
    /// the colour `fog_colour` (linear RGB).
    pub fn set_air(&self, queue: &wgpu::Queue, fog: FogSettings, fog_colour: [f32; 3]) {
        self.fog.write_with_colour(queue, fog, fog_colour);
    }

    /// Aims `viewpoint` from `camera`, for a picture drawn as finely as
    /// `detail` asks, lit by `sun`, keeping what `clip` keeps.
    pub fn aim(&self, gpu: &Gpu, viewpoint: &mut Viewpoint, camera: &Camera, detail: Detail, sun: Sun, clip: Vec4) {
        self.terrain.aim(gpu, viewpoint, camera, detail, sun, clip);
    }

    /// The rocks `setup` draws from `viewpoint`: the first `setup.rocks`
    /// (at most `MAX_ONE_PER_DRAW` one call per rock), less the groups the
    /// viewpoint's frustum culls when `setup.cull`.
    pub fn rock_runs(&self, viewpoint: &Viewpoint, setup: Setup) -> RockRuns {
        let most = if setup.mode == Mode::OnePerDraw { MAX_ONE_PER_DRAW } else { u32::MAX };
        let count = setup.rocks.min(self.rocks.placed).min(most);
        visible_runs(&self.rocks.groups, count, setup.cull.then(|| viewpoint.frustum()))
    }

    // ANCHOR: write_draw_list
    /// For `Mode::Indirect`: writes this frame's draws from `viewpoint`, one
    /// record of five numbers per run, which `draw` then hands the GPU in
    /// one call. Call it after `aim`, for the one viewpoint drawn in that
    /// mode (the list is the plain's, not the viewpoint's).
    pub fn write_draw_list(&self, queue: &wgpu::Queue, viewpoint: &Viewpoint, setup: Setup) {
        let draws: Vec<u8> = (self.rock_runs(viewpoint, setup).runs.iter())
            .flat_map(|run| {
                let draw = wgpu::util::DrawIndexedIndirectArgs {
                    index_count: self.rocks.mesh.index_count,
                    instance_count: run.len() as u32,
                    first_index: 0,
                    base_vertex: 0,
                    first_instance: run.start,
                };
                draw.as_bytes().to_vec()
            })
            .collect();
        queue.write_buffer(&self.draw_list, 0, &draws);
    }
    // ANCHOR_END: write_draw_list

    // ANCHOR: draw
    /// Records the terrain (unless `setup` leaves it out) and `setup.rocks`
    /// rocks into `pass`, as seen from `viewpoint`.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &Viewpoint, setup: Setup) -> DrawCalls {
        // Group 0 (camera, sun) and group 1 (fog) serve the terrain and the rocks alike.
        pass.set_bind_group(1, &self.fog.group, &[]);
        self.terrain.bind(pass, viewpoint);
        let mut calls = DrawCalls::default();
        if setup.terrain {
            pass.set_pipeline(&self.pipelines.get().terrain);
            calls.terrain = self.terrain.draw(pass, viewpoint).draws;
        }
        let drawn = self.rock_runs(viewpoint, setup);
        calls.rocks = self.draw_rocks(pass, setup.mode, &drawn);
        (calls.rocks_drawn, calls.rock_groups) = (drawn.rocks, drawn.groups);
        calls
    }
    // ANCHOR_END: draw

    // ANCHOR: draw_rocks
    /// Draws the rocks of `drawn`'s runs; returns the number of draw calls.
    fn draw_rocks(&self, pass: &mut wgpu::RenderPass<'_>, mode: Mode, drawn: &RockRuns) -> u32 {
        let mesh = &self.rocks.mesh;
        let pipelines = self.pipelines.get();
        pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
        pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        match mode {
            Mode::Indirect if self.indirect_ok => {
                pass.set_pipeline(&pipelines.instanced);
                pass.set_vertex_buffer(1, self.rocks.instances.slice(..));
                // One call: the GPU reads each run's draw from the list.
                pass.multi_draw_indexed_indirect(&self.draw_list, 0, drawn.runs.len() as u32);
                1
            }
            Mode::Instanced | Mode::Indirect | Mode::Flat | Mode::Groups => {
                pass.set_pipeline(match mode {
                    Mode::Flat => &pipelines.flat,
                    Mode::Groups => &pipelines.groups,
                    _ => &pipelines.instanced,
                });
                pass.set_vertex_buffer(1, self.rocks.instances.slice(..));
                // One call per run of rocks; the GPU loops over its instances itself.
                for run in &drawn.runs {
                    pass.draw_indexed(0..mesh.index_count, 0, run.clone());
                }
                drawn.runs.len() as u32
            }
            Mode::OnePerDraw => {
                pass.set_pipeline(&pipelines.one_per_draw);
                for i in drawn.runs.iter().flat_map(|run| run.clone()) {
                    // A bind group change and a draw per rock, validated and
                    // recorded one by one: this is the cost instancing removes.
                    pass.set_bind_group(2, &self.singles_group, &[i * self.rocks.single_stride]);
                    pass.draw_indexed(0..mesh.index_count, 0, 0..1);
                }
                drawn.rocks
            }
        }
    }
    // ANCHOR_END: draw_rocks
}
