//! The Mars plain so far: chapter 03's terrain in chapter 04's fog, strewn
//! with this chapter's rocks, culled per rock and graded by size on the GPU,
//! or culled by chunk on the CPU and drawn instanced (a call per run of
//! visible groups, or all of them in one indirect call), one call per rock,
//! or flat. Chapters 05, 06 and 07 each own one and draw it through
//! explicit inputs, one `PlainViewpoint` per picture.

use std::ops::Range;
use std::sync::Arc;

use common::glam::Vec4;
use common::texture::depth_test;
use common::{Camera, Drawn, Gpu, PassTimer, Reloadable, ShaderError, ShaderFile, Vertex, anyhow, shader, wgpu};
use fog::{FogBinding, FogSettings, fog_shader};
use terrain::{Detail, Sun, TerrainData, TerrainRenderer, Viewpoint};

use crate::capabilities::missing_capability;
use crate::rock_culling::{RockCulling, RockLists, RockSource};
use crate::rock_field::{MAX_ONE_PER_DRAW, RockField};
use crate::rock_groups::{RockRuns, visible_runs};
use crate::rock_mesh::LEVELS;
use crate::rock_scatter::{MAX_ROCKS, RockInstance, rocks_on_map};
use crate::size_on_screen::{Grading, Picture};

/// How the rocks are drawn and coloured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Instanced: per level of detail when the GPU culls them, else one
    /// call per run of rocks to draw (all of them, or the visible groups,
    /// neighbours in the buffer joined).
    Instanced,
    /// The chunk groups' runs in one `multi_draw_indexed_indirect` call,
    /// from a list of draws the CPU writes each frame (`MarsPlain::cull`).
    Indirect,
    /// One draw call per rock, each with its own uniform offset.
    OnePerDraw,
    /// Instanced, with a flat colour and no lighting or fog: the floor.
    Flat,
    /// Instanced, each rock in its chunk group's colour.
    Groups,
    /// Instanced, each rock in its level of detail's colour.
    Levels,
}

/// Which rocks a picture leaves out before drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Culling {
    /// None: every rock of the world is drawn.
    Off,
    /// On the CPU, by chunk: the groups whose box the frustum keeps.
    Chunks,
    /// On the GPU, rock by rock: the frustum, the clip plane and the size
    /// on screen, each rock drawn at the level of detail its size asks.
    /// `Mode::Indirect` and `Mode::OnePerDraw` cull by chunk instead, and
    /// so does a device without what the compute pass needs.
    PerRock,
    /// As `PerRock`, with the frustum and the clip plane alone: every rock
    /// in view at full detail, however small (`Grading::FULL_DETAIL`).
    PerRockFullDetail,
}

/// What a view shows: how many rocks are in the world (the first of the
/// buffer, nearest the start), how they are drawn, which are culled, and
/// whether the terrain is drawn too (the bench views leave it out so that
/// the numbers are the rocks' alone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    pub rocks: u32,
    pub mode: Mode,
    pub terrain: bool,
    pub culling: Culling,
    /// The terrain's every chunk in view at full detail (chapter 03's
    /// `full-detail`), not at its levels of detail.
    pub full_detail: bool,
}

impl Setup {
    /// The plain as the book shows it: the terrain and a million rocks over
    /// the whole map, culled and graded on the GPU.
    pub const DEFAULT: Self =
        Self { rocks: MAX_ROCKS, mode: Mode::Instanced, terrain: true, culling: Culling::PerRock, full_detail: false };

    /// `self` as the plain was drawn before it had levels of detail: the
    /// terrain's every chunk in view at full detail, the rocks culled by
    /// chunk and every one in view drawn whole. What the levels save is the
    /// difference between the two.
    pub const fn at_full_detail(self) -> Self {
        Self { culling: Culling::Chunks, full_detail: true, ..self }
    }

    /// How finely this setup draws the terrain, in a picture `height` pixels high.
    pub fn detail(&self, height: u32) -> Detail {
        if self.full_detail { Detail::full(height) } else { Detail::lod(height) }
    }
}

/// What a device drawing the plain needs: chapter 03's needs, and indirect
/// draws that may start past instance 0, for `Mode::Indirect` (without
/// them, that mode draws as `Instanced` does). The GPU's culling needs no
/// feature: its indirect draws all start at instance 0.
pub fn gpu_needs() -> common::GpuNeeds {
    let terrain = terrain::gpu_needs();
    common::GpuNeeds { optional: terrain.optional | wgpu::Features::INDIRECT_FIRST_INSTANCE, ..terrain }
}

fn rocks_shader() -> ShaderFile {
    shader!("instancing/rocks.wgsl", imports: ["terrain/terrain.wgsl", "fog/fog.wgsl", "instancing/rock.wgsl"])
}

/// The fragment functions of rocks.wgsl, one per way of colouring a rock.
const COLOURINGS: [&str; 4] = ["fs_main", "fs_flat", "fs_groups", "fs_levels"];

/// Which of `COLOURINGS` a mode draws with.
fn colouring(mode: Mode) -> usize {
    match mode {
        Mode::Instanced | Mode::Indirect | Mode::OnePerDraw => 0,
        Mode::Flat => 1,
        Mode::Groups => 2,
        Mode::Levels => 3,
    }
}

/// The plain's pipelines: the terrain in fog, and the rocks drawn from the
/// instance buffer, one per call, or from the GPU's lists, in each colouring.
#[derive(Clone)]
struct Pipelines {
    terrain: wgpu::RenderPipeline,
    instanced: [wgpu::RenderPipeline; 4],
    one_per_draw: wgpu::RenderPipeline,
    /// None where the device cannot cull on the GPU.
    culled: Option<[wgpu::RenderPipeline; 4]>,
}

// ANCHOR: rock_pipeline
/// A pipeline that draws the rock with `vertex_entry` and `fragment_entry`
/// of rocks.wgsl. The instanced one reads two vertex buffers, the mesh's
/// (stepped per vertex) and the rocks' records (stepped per instance);
/// the others read the mesh alone and find their rock elsewhere.
fn rock_pipeline(
    gpu: &Gpu,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    (format, samples): (wgpu::TextureFormat, u32),
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
        multisample: common::multisampling::multisample(samples),
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
// ANCHOR_END: rock_pipeline

/// What one picture drew of the rocks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RocksDrawn {
    pub rocks: u32,
    pub triangles: u64,
    /// Rocks at each level of detail, finest first, where the GPU graded
    /// them; `None` where every rock drawn was the full rock.
    pub levels: Option<[u32; LEVELS]>,
}

/// Draw calls recorded for one picture of the plain, and the rocks drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawCalls {
    /// One instanced call for every patch of the terrain in view.
    pub terrain: u32,
    /// The terrain's triangles: every patch's.
    pub terrain_triangles: u64,
    /// One per run of rock groups, one in all (indirect), one per rock, or
    /// one per level of detail (culled on the GPU).
    pub rocks: u32,
    /// What the rocks' calls drew: counted as they were recorded where the
    /// CPU culls, read back a frame or two late where the GPU does (`None`
    /// until the first count comes back).
    pub rocks_drawn: Option<RocksDrawn>,
    /// Rock groups (chunks with rocks) drawn, where the CPU culls by chunk.
    pub rock_groups: u32,
}

impl DrawCalls {
    pub fn total(&self) -> u32 {
        self.terrain + self.rocks
    }

    /// The calls and triangles, for the pass's count: the rocks' as far as
    /// they are known (read back late where the GPU culls).
    pub fn drawn(&self) -> Drawn {
        let terrain = Drawn::counted(self.total(), self.terrain_triangles);
        match self.rocks_drawn {
            // Graded by the GPU: its counts, read back from an earlier frame.
            Some(rocks) if rocks.levels.is_some() => terrain.and_read_back(rocks.triangles),
            Some(rocks) => Drawn::counted(self.total(), self.terrain_triangles + rocks.triangles),
            None => terrain,
        }
    }
}

// ANCHOR: plain_viewpoint
/// Everything one picture of the plain needs of its own: the terrain's
/// uniforms, and where the GPU culls the rocks, the lists and draws that
/// the compute pass fills. A frame that draws the plain several times
/// (chapter 07's reflection, refraction and main picture) has one of these
/// per picture, records all of them into one encoder and submits once.
pub struct PlainViewpoint {
    /// Group 0 of terrain.wgsl for this picture, which the fog, the rocks
    /// and the water read too.
    pub ground: Viewpoint,
    /// Where the GPU culls: this picture's lists and indirect draws.
    rocks: Option<RockLists>,
    /// For `Mode::Indirect`: this picture's draws of the chunk groups,
    /// written by the CPU. `None` without indirect draws.
    draw_list: Option<wgpu::Buffer>,
    /// Where the picture was last aimed from.
    picture: Option<Picture>,
    /// Samples a pixel of the picture's pass: which pipelines draw it.
    samples: u32,
}
// ANCHOR_END: plain_viewpoint

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
    /// The compute pass that culls the rocks, and every rock bound for it;
    /// `None` where the device lacks what it needs.
    culling: Option<(RockCulling, wgpu::BindGroup)>,
    /// Why the rocks are culled by chunk on the CPU where a view asks for
    /// the GPU: which capability the device lacks.
    culling_missing: Option<String>,
    /// Whether indirect draws may start at an instance other than 0 (the
    /// `INDIRECT_FIRST_INSTANCE` feature); without it `Mode::Indirect` draws
    /// as `Mode::Instanced` does.
    indirect_ok: bool,
    /// For each sample count the plain's pictures are drawn with (one,
    /// and chapter 07's four for the main pass beside its one-sample
    /// pictures); rebuilt when fog.wgsl, rocks.wgsl, rock.wgsl or
    /// terrain.wgsl is saved (hot reload).
    pipelines: Reloadable<Vec<(u32, Pipelines)>>,
}
// ANCHOR_END: mars_plain

impl MarsPlain {
    /// The plain of `terrain` (what `TerrainData::prepare` made), for
    /// targets of `format` drawn with each of `samples` samples a pixel.
    pub fn new(
        gpu: &Gpu,
        format: wgpu::TextureFormat,
        samples: &[u32],
        terrain: Arc<TerrainData>,
    ) -> anyhow::Result<Self> {
        Self::with_capabilities(gpu, (format, samples), terrain, &gpu.downlevel())
    }

    /// `new`, as if the device had only `downlevel`'s capabilities: a test
    /// takes away what the GPU's culling needs to see the plain fall back.
    pub fn with_capabilities(
        gpu: &Gpu,
        (format, samples): (wgpu::TextureFormat, &[u32]),
        terrain: Arc<TerrainData>,
        downlevel: &wgpu::DownlevelCapabilities,
    ) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let terrain = TerrainRenderer::new(gpu, terrain);
        let rocks = RockField::get(gpu, terrain.field(), terrain.chunk_bounds());
        let indirect_ok = device.features().contains(wgpu::Features::INDIRECT_FIRST_INSTANCE)
            && downlevel.flags.contains(wgpu::DownlevelFlags::INDIRECT_EXECUTION);
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
        let rock_bytes = rocks.instances.size();
        let culling_missing = missing_capability(downlevel, &device.limits(), rock_bytes);
        let culling = match culling_missing {
            None => {
                let culling = RockCulling::new(gpu, rocks.levels.each_ref().map(|mesh| mesh.index_count))?;
                let group = culling.rocks_group(device, &rocks.instances);
                Some((culling, group))
            }
            Some(_) => None,
        };
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
        let culled_layout = culling.as_ref().map(|(culling, _)| {
            layout("culled rocks", &[shared[0], shared[1], Some(&culling.draw_layout), Some(&culling.rocks_layout)])
        });
        let samples = samples.to_vec();
        let pipelines = Reloadable::new(gpu, move |gpu| {
            let each =
                |&count: &u32| Ok((count, Self::pipelines(gpu, &layouts, culled_layout.as_ref(), (format, count))?));
            samples.iter().map(each).collect::<Result<Vec<_>, ShaderError>>()
        })?;
        let singles_group = Self::singles_group(device, &single_layout, &rocks);
        Ok(Self { terrain, rocks, fog, singles_group, culling, culling_missing, indirect_ok, pipelines })
    }

    fn pipelines(
        gpu: &Gpu,
        layouts: &[wgpu::PipelineLayout; 2],
        culled_layout: Option<&wgpu::PipelineLayout>,
        format: (wgpu::TextureFormat, u32),
    ) -> Result<Pipelines, ShaderError> {
        let terrain = TerrainRenderer::pipeline(gpu, &fog_shader(), &layouts[0], format)?;
        let module = rocks_shader().module(gpu)?;
        gpu.catch_validation(|| Pipelines {
            terrain,
            instanced: COLOURINGS.map(|fs| rock_pipeline(gpu, &module, &layouts[0], format, "vs_instanced", fs)),
            one_per_draw: rock_pipeline(gpu, &module, &layouts[1], format, "vs_single", "fs_main"),
            culled: culled_layout
                .map(|layout| COLOURINGS.map(|fs| rock_pipeline(gpu, &module, layout, format, "vs_culled", fs))),
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

    /// The pipelines for pictures of `samples` samples a pixel (the first
    /// set where the plain was made for no such count).
    fn pipelines_for(&self, samples: u32) -> Pipelines {
        let all = self.pipelines.get();
        let found = all.iter().find(|(count, _)| *count == samples).unwrap_or(&all[0]);
        found.1.clone()
    }

    /// A new set of everything one more picture of the plain needs, for a
    /// pass of `samples` samples a pixel.
    pub fn viewpoint(&self, device: &wgpu::Device, samples: u32) -> PlainViewpoint {
        // As many rocks as the map can hold, so that regenerating the
        // terrain (which keeps the number of chunks) never outgrows the lists.
        let capacity = rocks_on_map(&self.terrain.field().settings) as u32;
        let draw_list = self.indirect_ok.then(|| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("rock draw list"),
                size: (self.rocks.groups.len().max(1) * std::mem::size_of::<wgpu::util::DrawIndexedIndirectArgs>())
                    as u64,
                usage: wgpu::BufferUsages::INDIRECT | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        });
        PlainViewpoint {
            ground: self.terrain.viewpoint(device),
            rocks: self.culling.as_ref().map(|(culling, _)| culling.lists(device, capacity)),
            draw_list,
            picture: None,
            samples,
        }
    }

    /// Bytes of the buffers one picture's viewpoint holds for the rocks:
    /// the GPU's lists and draws, and the CPU's draw list.
    pub fn viewpoint_bytes(&self, viewpoint: &PlainViewpoint) -> u64 {
        let lists = viewpoint.rocks.as_ref().map_or(0, RockLists::gpu_bytes);
        lists + viewpoint.draw_list.as_ref().map_or(0, wgpu::Buffer::size)
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

    /// Triangles of the rock at each level of detail, finest first.
    pub fn rock_triangles(&self) -> [u32; LEVELS] {
        self.rocks.levels.each_ref().map(|mesh| mesh.index_count / 3)
    }

    /// Why this plain culls its rocks by chunk on the CPU where a view asks
    /// for the GPU, in one line; `None` where the GPU can cull them.
    pub fn culling_fallback(&self) -> Option<String> {
        self.culling_missing.as_ref().map(|missing| format!("rocks culled by chunk on the CPU: {missing}"))
    }

    /// Bytes of the buffers this plain made on the GPU, by our own count:
    /// (the terrain's maps and patch grid, rocks and what the culling
    /// shares). Uniforms, each viewpoint's patch list and each viewpoint's
    /// rock lists come on top.
    pub fn gpu_bytes(&self) -> (u64, u64) {
        let culling = self.culling.as_ref().map_or(0, |(culling, _)| culling.gpu_bytes());
        (self.terrain.data().maps.gpu_bytes(), self.rocks.gpu_bytes() + culling)
    }

    /// Makes the terrain again from `self.terrain.settings`, and the rocks on it.
    pub fn regenerate(&mut self, gpu: &Gpu) {
        self.terrain.regenerate(gpu);
        self.rocks = RockField::get(gpu, self.terrain.field(), self.terrain.chunk_bounds());
        let layout = self.pipelines_for(1).one_per_draw.get_bind_group_layout(2);
        self.singles_group = Self::singles_group(&gpu.device, &layout, &self.rocks);
        if let Some((culling, group)) = &mut self.culling {
            *group = culling.rocks_group(&gpu.device, &self.rocks.instances);
        }
    }

    /// Sets the air every picture of this frame is seen through: `fog`, in
    /// the colour `fog_colour` (linear RGB).
    pub fn set_air(&self, queue: &wgpu::Queue, fog: FogSettings, fog_colour: [f32; 3]) {
        self.fog.write_with_colour(queue, fog, fog_colour);
    }

    /// Aims `viewpoint` from `camera`, for a picture drawn as finely as
    /// `detail` asks (its height in pixels decides the rocks' sizes on
    /// screen), lit by `sun`, keeping what `clip` keeps.
    pub fn aim(
        &self,
        gpu: &Gpu,
        viewpoint: &mut PlainViewpoint,
        camera: &Camera,
        detail: Detail,
        sun: Sun,
        clip: Vec4,
    ) {
        self.terrain.aim(gpu, &mut viewpoint.ground, camera, detail, sun, clip);
        viewpoint.picture = Some(Picture { camera: *camera, height: detail.picture_height, clip });
    }

    /// Whether `setup` draws its rocks from the GPU's lists.
    fn culls_on_gpu(&self, setup: Setup) -> bool {
        matches!(setup.culling, Culling::PerRock | Culling::PerRockFullDetail)
            && self.culling.is_some()
            && !matches!(setup.mode, Mode::Indirect | Mode::OnePerDraw)
    }

    /// The first `setup.rocks` rocks, at most as many as there are.
    fn rocks_in_world(&self, setup: Setup) -> u32 {
        setup.rocks.min(self.rocks.placed)
    }

    /// The rocks `setup` draws from `viewpoint` where the CPU culls: the
    /// first `setup.rocks` (at most `MAX_ONE_PER_DRAW` one call per rock),
    /// less the groups the viewpoint's frustum culls unless culling is off.
    pub fn rock_runs(&self, viewpoint: &PlainViewpoint, setup: Setup) -> RockRuns {
        let most = if setup.mode == Mode::OnePerDraw { MAX_ONE_PER_DRAW } else { u32::MAX };
        let count = self.rocks_in_world(setup).min(most);
        let frustum = (setup.culling != Culling::Off).then(|| viewpoint.ground.frustum());
        visible_runs(&self.rocks.groups, count, frustum)
    }

    // ANCHOR: cull
    /// Prepares this picture's rocks, after `aim` and before the render
    /// pass that draws them: where the GPU culls, records the compute pass
    /// into `encoder`; for `Mode::Indirect`, writes the picture's list of
    /// draws.
    pub fn cull(
        &self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        viewpoint: &mut PlainViewpoint,
        setup: Setup,
    ) {
        if let (true, Some((culling, group)), Some(lists), Some(picture)) =
            (self.culls_on_gpu(setup), &self.culling, &mut viewpoint.rocks, &viewpoint.picture)
        {
            let grading = if setup.culling == Culling::PerRock { Grading::LOD } else { Grading::FULL_DETAIL };
            let rocks = RockSource { group, sphere: self.rocks.sphere, count: self.rocks_in_world(setup) };
            culling.aim(&gpu.queue, lists, picture, &rocks, grading);
            culling.cull(gpu, encoder, timer, lists, &rocks);
        } else if setup.mode == Mode::Indirect {
            self.write_draw_list(&gpu.queue, viewpoint, setup);
        }
    }
    // ANCHOR_END: cull

    // ANCHOR: write_draw_list
    /// For `Mode::Indirect`: writes this picture's draws, one record of five
    /// numbers per run, which `draw` then hands the GPU in one call.
    fn write_draw_list(&self, queue: &wgpu::Queue, viewpoint: &PlainViewpoint, setup: Setup) {
        let Some(draw_list) = &viewpoint.draw_list else { return };
        let draws: Vec<u8> = (self.rock_runs(viewpoint, setup).runs.iter())
            .flat_map(|run| {
                let draw = wgpu::util::DrawIndexedIndirectArgs {
                    index_count: self.rocks.mesh().index_count,
                    instance_count: run.len() as u32,
                    first_index: 0,
                    base_vertex: 0,
                    first_instance: run.start,
                };
                draw.as_bytes().to_vec()
            })
            .collect();
        queue.write_buffer(draw_list, 0, &draws);
    }
    // ANCHOR_END: write_draw_list

    // ANCHOR: draw
    /// Records the terrain (unless `setup` leaves it out) and `setup.rocks`
    /// rocks into `pass`, as seen from `viewpoint`.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, viewpoint: &PlainViewpoint, setup: Setup) -> DrawCalls {
        // Group 0 (camera, sun) and group 1 (fog) serve the terrain and the rocks alike.
        pass.set_bind_group(1, &self.fog.group, &[]);
        self.terrain.bind(pass, &viewpoint.ground);
        let mut calls = DrawCalls::default();
        if setup.terrain {
            pass.set_pipeline(&self.pipelines_for(viewpoint.samples).terrain);
            let drawn = self.terrain.draw(pass, &viewpoint.ground);
            (calls.terrain, calls.terrain_triangles) = (drawn.draws, drawn.triangles);
        }
        if let (true, Some((culling, group)), Some(lists)) = (self.culls_on_gpu(setup), &self.culling, &viewpoint.rocks)
        {
            let pipelines = self.pipelines_for(viewpoint.samples);
            let Some(culled) = &pipelines.culled else { return calls };
            pass.set_pipeline(&culled[colouring(setup.mode)]);
            let rocks = RockSource { group, sphere: self.rocks.sphere, count: self.rocks_in_world(setup) };
            culling.draw(pass, lists, &rocks, &self.rocks.levels);
            calls.rocks = LEVELS as u32;
            calls.rocks_drawn = lists.late_counts().map(|levels| self.graded(levels));
        } else {
            let drawn = self.rock_runs(viewpoint, setup);
            calls.rocks = self.draw_rocks(pass, viewpoint, setup.mode, &drawn);
            calls.rocks_drawn = Some(self.full_detail(drawn.rocks));
            calls.rock_groups = drawn.groups;
        }
        calls
    }
    // ANCHOR_END: draw

    /// What `setup` drew of the rocks in `viewpoint`'s last picture: where
    /// the GPU culls, waiting for it to finish and reading its counts back
    /// (for `--bench`'s figures and the tests; the overlay reads them late).
    pub fn rocks_drawn_now(&self, gpu: &Gpu, viewpoint: &PlainViewpoint, setup: Setup) -> RocksDrawn {
        match (&viewpoint.rocks, self.culls_on_gpu(setup)) {
            (Some(lists), true) => self.graded(lists.counts_now(gpu)),
            _ => self.full_detail(self.rock_runs(viewpoint, setup).rocks),
        }
    }

    /// The lists and draws the GPU culled `viewpoint`'s rocks into, where
    /// it does: for the tests.
    pub fn rock_lists<'v>(&self, viewpoint: &'v PlainViewpoint) -> Option<&'v RockLists> {
        viewpoint.rocks.as_ref()
    }

    fn graded(&self, levels: [u32; LEVELS]) -> RocksDrawn {
        let triangles = self.rock_triangles();
        RocksDrawn {
            rocks: levels.iter().sum(),
            triangles: (0..LEVELS).map(|l| u64::from(levels[l]) * u64::from(triangles[l])).sum(),
            levels: Some(levels),
        }
    }

    fn full_detail(&self, rocks: u32) -> RocksDrawn {
        RocksDrawn { rocks, triangles: u64::from(rocks) * u64::from(self.rock_triangles()[0]), levels: None }
    }

    // ANCHOR: draw_rocks
    /// Draws the rocks of `drawn`'s runs, where the CPU culls, in `mode`'s
    /// way; returns the number of draw calls.
    fn draw_rocks(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        viewpoint: &PlainViewpoint,
        mode: Mode,
        drawn: &RockRuns,
    ) -> u32 {
        let pipelines = self.pipelines_for(viewpoint.samples);
        match (mode, &viewpoint.draw_list) {
            (Mode::Indirect, Some(draw_list)) if self.indirect_ok => {
                self.draw_indirect(pass, &pipelines.instanced[colouring(mode)], draw_list, drawn)
            }
            (Mode::OnePerDraw, _) => self.draw_one_per_rock(pass, &pipelines.one_per_draw, drawn),
            _ => self.draw_runs(pass, &pipelines.instanced[colouring(mode)], drawn),
        }
    }
    // ANCHOR_END: draw_rocks

    // ANCHOR: draw_instanced
    /// Sets up `pass` to draw the rock instanced: the mesh in vertex buffer
    /// 0, which steps once per vertex, and every rock's record in vertex
    /// buffer 1, which steps once per instance (`RockInstance::LAYOUT`).
    fn bind_instanced(&self, pass: &mut wgpu::RenderPass<'_>, pipeline: &wgpu::RenderPipeline) {
        let mesh = self.rocks.mesh();
        pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
        pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        pass.set_pipeline(pipeline);
        pass.set_vertex_buffer(1, self.rocks.instances.slice(..));
    }

    /// Draws the rocks `instances` of the buffer in one call: the mesh's
    /// 60 indices, base vertex 0, and the range of instances. The GPU loops
    /// over the instances itself, running the 60 vertices for each.
    fn draw_instanced(&self, pass: &mut wgpu::RenderPass<'_>, instances: Range<u32>) {
        pass.draw_indexed(0..self.rocks.mesh().index_count, 0, instances);
    }
    // ANCHOR_END: draw_instanced

    // ANCHOR: draw_one_per_rock
    /// The comparison: every rock of `drawn` with a draw call of its own,
    /// its record read from its uniform slot at a dynamic offset, as
    /// chapter 02 placed its primitives. Returns the number of calls.
    fn draw_one_per_rock(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        pipeline: &wgpu::RenderPipeline,
        drawn: &RockRuns,
    ) -> u32 {
        let mesh = self.rocks.mesh();
        pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
        pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        pass.set_pipeline(pipeline);
        for i in drawn.runs.iter().flat_map(|run| run.clone()) {
            // A bind group change and a draw per rock, validated and
            // recorded one by one: this is the cost instancing removes.
            pass.set_bind_group(2, &self.singles_group, &[i * self.rocks.single_stride]);
            pass.draw_indexed(0..mesh.index_count, 0, 0..1);
        }
        drawn.rocks
    }
    // ANCHOR_END: draw_one_per_rock

    // ANCHOR: draw_runs
    /// One instanced call per run of rocks: every rock in one call where
    /// nothing is culled, a call per run of neighbouring groups where the
    /// CPU culls by chunk. Returns the number of calls.
    fn draw_runs(&self, pass: &mut wgpu::RenderPass<'_>, pipeline: &wgpu::RenderPipeline, drawn: &RockRuns) -> u32 {
        self.bind_instanced(pass, pipeline);
        for run in &drawn.runs {
            self.draw_instanced(pass, run.clone());
        }
        drawn.runs.len() as u32
    }
    // ANCHOR_END: draw_runs

    // ANCHOR: draw_indirect
    /// All the runs in one call: the GPU reads each run's draw, five
    /// numbers, from `draw_list`, which `write_draw_list` filled.
    fn draw_indirect(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        pipeline: &wgpu::RenderPipeline,
        draw_list: &wgpu::Buffer,
        drawn: &RockRuns,
    ) -> u32 {
        self.bind_instanced(pass, pipeline);
        pass.multi_draw_indexed_indirect(draw_list, 0, drawn.runs.len() as u32);
        1
    }
    // ANCHOR_END: draw_indirect
}
