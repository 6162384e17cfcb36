//! The rocks culled and graded on the GPU, the course's first compute
//! shader: per picture, a compute pass tests every rock against the frustum
//! and the clip plane, measures it in pixels, drops the ones smaller than a
//! pixel and appends the others to the list of their level of detail,
//! counting them into that level's indirect draw. The render pass then draws
//! each level with one `draw_indexed_indirect`, and the CPU never learns how
//! many rocks there were unless it reads the counts back, a frame late.

use common::glam::Vec4;
use common::wgpu::util::DeviceExt as _;
use common::{Gpu, Mesh, PassTimer, Reloadable, ShaderError, ShaderFile, shader, wgpu};

use crate::read_back::{LateCounts, read_buffer};
use crate::rock_mesh::LEVELS;
use crate::size_on_screen::{Grading, Picture};

/// Invocations per workgroup: `@workgroup_size(64)` in cull.wgsl. A
/// multiple of the 32 or 64 lanes a GPU runs together, and well inside
/// WebGPU's least limit of 256 invocations per workgroup.
pub const WORKGROUP_SIZE: u32 = 64;

// ANCHOR: culling_input
/// `Culling` in rock.wgsl: what one picture asks of the rocks, in a small
/// read-only storage buffer.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct CullingInput {
    view: [[f32; 4]; 4],
    /// tan(half the field of view) across and up, near, far.
    frustum: [f32; 4],
    clip: [f32; 4],
    /// The eye, and the pixels per radian at the picture's centre.
    eye: [f32; 4],
    sphere: [f32; 4],
    sizes: [f32; 4],
    /// Rocks to test, and u32s from one level's list to the next.
    counts: [u32; 4],
}
// ANCHOR_END: culling_input

/// The rocks one picture culls: the buffer that holds them (group 1 of
/// cull.wgsl, group 3 of the culled draws), the sphere around the rock in
/// its own space, and how many of them, from the first.
pub struct RockSource<'a> {
    pub group: &'a wgpu::BindGroup,
    pub sphere: Vec4,
    pub count: u32,
}

// ANCHOR: rock_culling
/// The compute pass that culls the rocks, and the layouts that one
/// picture's lists and draws are bound with. One per plain; each picture
/// has its own `RockLists`.
pub struct RockCulling {
    /// Rebuilt when cull.wgsl or rock.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::ComputePipeline>,
    /// Compute group 0: a picture's input, lists and draws.
    picture_layout: wgpu::BindGroupLayout,
    /// Compute group 1 and the culled draws' group 3: every rock.
    pub rocks_layout: wgpu::BindGroupLayout,
    /// The culled draws' group 2: one level's list, the input, the level.
    pub draw_layout: wgpu::BindGroupLayout,
    /// Each level's number, at the device's alignment for uniform offsets.
    level_numbers: wgpu::Buffer,
    level_stride: u64,
    /// Indices of each level's mesh: the first number of its indirect draw.
    index_counts: [u32; LEVELS],
    /// The device's limit on workgroups along one side of a dispatch.
    max_workgroups: u32,
}
// ANCHOR_END: rock_culling

/// One picture's part of the culling: its input, the three lists the
/// compute pass fills, the indirect draws it counts into, and their
/// counts read back late for the overlay. Chapter 07 records three
/// pictures before one submit, so each needs its own.
pub struct RockLists {
    input: wgpu::Buffer,
    lists: wgpu::Buffer,
    draws: wgpu::Buffer,
    picture_group: wgpu::BindGroup,
    draw_groups: [wgpu::BindGroup; LEVELS],
    /// u32s from one level's list to the next.
    stride: u32,
    /// The most rocks one list holds: every rock there is.
    capacity: u32,
    late: LateCounts,
}

/// Bytes `offset..offset + size` of `buffer`, to bind.
fn slice(buffer: &wgpu::Buffer, offset: u64, size: u64) -> wgpu::BindingResource<'_> {
    wgpu::BindingResource::Buffer(wgpu::BufferBinding { buffer, offset, size: wgpu::BufferSize::new(size) })
}

/// The bytes of one `DrawIndexedIndirectArgs`: five 32-bit numbers.
const DRAW_BYTES: u64 = std::mem::size_of::<wgpu::util::DrawIndexedIndirectArgs>() as u64;

fn cull_shader() -> ShaderFile {
    shader!("instancing/cull.wgsl", imports: ["instancing/rock.wgsl"])
}

// ANCHOR: storage_entry
/// A storage buffer at `binding`, seen by the `visibility` stages: any
/// size (`min_binding_size: None`, the shader's runtime-sized array takes
/// what is bound), read-only or written.
fn storage(binding: u32, visibility: wgpu::ShaderStages, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}
// ANCHOR_END: storage_entry

impl RockCulling {
    /// The culling for rocks drawn with meshes of `index_counts` indices,
    /// finest first.
    pub fn new(gpu: &Gpu, index_counts: [u32; LEVELS]) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        // ANCHOR: compute_layouts
        let picture_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("rock culling: one picture"),
            entries: &[
                storage(0, wgpu::ShaderStages::COMPUTE, true),
                storage(1, wgpu::ShaderStages::COMPUTE, false),
                storage(2, wgpu::ShaderStages::COMPUTE, false),
            ],
        });
        let rocks_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("every rock"),
            entries: &[storage(0, wgpu::ShaderStages::COMPUTE | wgpu::ShaderStages::VERTEX, true)],
        });
        // ANCHOR_END: compute_layouts
        let draw_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("one level's rocks"),
            entries: &[
                storage(1, wgpu::ShaderStages::VERTEX, true),
                storage(2, wgpu::ShaderStages::VERTEX, true),
                common::pipeline::uniform_entry(3, wgpu::ShaderStages::VERTEX, 16),
            ],
        });
        let level_stride = 16u64.next_multiple_of(u64::from(device.limits().min_uniform_buffer_offset_alignment));
        let mut numbers = vec![0u8; level_stride as usize * LEVELS];
        for level in 0..LEVELS {
            let at = level * level_stride as usize;
            numbers[at..at + 4].copy_from_slice(&(level as u32).to_le_bytes());
        }
        let level_numbers = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("level numbers"),
            contents: &numbers,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        // ANCHOR: compute_pipeline
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("rock culling"),
            bind_group_layouts: &[Some(&picture_layout), Some(&rocks_layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| {
            let module = cull_shader().module(gpu)?;
            gpu.catch_validation(|| {
                gpu.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("cull rocks"),
                    layout: Some(&layout),
                    module: &module,
                    entry_point: Some("cull_rocks"),
                    compilation_options: Default::default(),
                    cache: None,
                })
            })
            .map_err(ShaderError)
        })?;
        // ANCHOR_END: compute_pipeline
        Ok(Self {
            pipeline,
            picture_layout,
            rocks_layout,
            draw_layout,
            level_numbers,
            level_stride,
            index_counts,
            max_workgroups: device.limits().max_compute_workgroups_per_dimension,
        })
    }

    /// Bytes of the buffers the culling shares between pictures.
    pub fn gpu_bytes(&self) -> u64 {
        self.level_numbers.size()
    }

    /// The bind group of every rock: `instances`, the rock field's buffer.
    pub fn rocks_group(&self, device: &wgpu::Device, instances: &wgpu::Buffer) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("every rock"),
            layout: &self.rocks_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: instances.as_entire_binding() }],
        })
    }

    // ANCHOR: lists
    /// A picture's lists and draws, for up to `capacity` rocks. The three
    /// lists share one buffer; each starts at a multiple of the device's
    /// alignment for storage offsets, so that each can be bound on its own
    /// and every indirect draw can start at instance 0.
    pub fn lists(&self, device: &wgpu::Device, capacity: u32) -> RockLists {
        let list_bytes = list_bytes(capacity, device.limits().min_storage_buffer_offset_alignment);
        let input = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("rock culling"),
            size: std::mem::size_of::<CullingInput>() as u64,
            // Storage, not uniform: the shaders branch on it (see cull.wgsl).
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let lists = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("rocks kept, by level"),
            size: list_bytes * LEVELS as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        // The draws start with every level's index count and no instances;
        // the compute pass counts the instances in.
        let draws: Vec<u8> = (self.index_counts.iter())
            .flat_map(|&index_count| {
                let draw = wgpu::util::DrawIndexedIndirectArgs {
                    index_count,
                    instance_count: 0,
                    first_index: 0,
                    base_vertex: 0,
                    first_instance: 0,
                };
                draw.as_bytes().to_vec()
            })
            .collect();
        let draws = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("rock draws, by level"),
            contents: &draws,
            usage: wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::INDIRECT
                | wgpu::BufferUsages::COPY_DST
                | wgpu::BufferUsages::COPY_SRC,
        });
        let picture_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("rock culling: one picture"),
            layout: &self.picture_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: input.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: lists.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: draws.as_entire_binding() },
            ],
        });
        let draw_groups = std::array::from_fn(|level| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("one level's rocks"),
                layout: &self.draw_layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 1, resource: slice(&lists, level as u64 * list_bytes, list_bytes) },
                    wgpu::BindGroupEntry { binding: 2, resource: input.as_entire_binding() },
                    wgpu::BindGroupEntry {
                        binding: 3,
                        resource: slice(&self.level_numbers, level as u64 * self.level_stride, 16),
                    },
                ],
            })
        });
        let late = LateCounts::new(device, LEVELS as u64 * DRAW_BYTES);
        RockLists { input, lists, draws, picture_group, draw_groups, stride: (list_bytes / 4) as u32, capacity, late }
    }
    // ANCHOR_END: lists

    /// Writes what `picture` asks of `lists`: test the first `rocks.count`
    /// rocks (at most the lists' capacity), graded by `grading`.
    pub fn aim(&self, queue: &wgpu::Queue, lists: &RockLists, picture: &Picture, rocks: &RockSource, grading: Grading) {
        let camera = &picture.camera;
        let tan_y = (camera.fov_y / 2.0).tan();
        let g = grading;
        let input = CullingInput {
            view: camera.view().to_cols_array_2d(),
            frustum: [tan_y * camera.aspect, tan_y, camera.near, camera.far],
            clip: picture.clip.into(),
            eye: camera.position.extend(picture.pixels_per_radian()).into(),
            sphere: rocks.sphere.into(),
            sizes: [g.full, g.coarse, g.drawn, g.whole],
            counts: [rocks.count.min(lists.capacity), lists.stride, 0, 0],
        };
        queue.write_buffer(&lists.input, 0, bytemuck::bytes_of(&input));
    }

    // ANCHOR: cull
    /// Records the culling of `rocks` into `encoder`, before the render pass
    /// that draws them: the counts back to zero, the compute pass, and a
    /// copy of the counts for the overlay to read a frame or two later.
    /// wgpu sees the compute pass write the lists and draws and the render
    /// pass read them, and puts a barrier between the two passes.
    pub fn cull(
        &self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        lists: &mut RockLists,
        rocks: &RockSource,
    ) {
        lists.late.collect(&gpu.device);
        for level in 0..LEVELS as u64 {
            // The instance count, the second number of each draw.
            encoder.clear_buffer(&lists.draws, level * DRAW_BYTES + 4, Some(4));
        }
        let count = rocks.count.min(lists.capacity);
        // ANCHOR: dispatch
        if count > 0 {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("rock culling"),
                timestamp_writes: timer.compute_pass("rock culling"),
            });
            pass.set_pipeline(&self.pipeline.get());
            pass.set_bind_group(0, &lists.picture_group, &[]);
            pass.set_bind_group(1, rocks.group, &[]);
            let (x, y) = dispatch_size(count, self.max_workgroups);
            pass.dispatch_workgroups(x, y, 1);
        }
        // ANCHOR_END: dispatch
        lists.late.copy(encoder, &lists.draws);
    }
    // ANCHOR_END: cull

    // ANCHOR: draw
    /// Draws the rocks `lists` kept into `pass`, each level with its mesh
    /// from `meshes` and one indirect draw whose instance count the compute
    /// pass wrote; `pass` has the culled rocks' pipeline and groups 0 and 1.
    pub fn draw(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        lists: &RockLists,
        rocks: &RockSource,
        meshes: &[Mesh; LEVELS],
    ) {
        pass.set_bind_group(3, rocks.group, &[]);
        for (level, mesh) in meshes.iter().enumerate() {
            pass.set_bind_group(2, &lists.draw_groups[level], &[]);
            pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
            pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed_indirect(&lists.draws, level as u64 * DRAW_BYTES);
        }
    }
    // ANCHOR_END: draw
}

// ANCHOR: list_bytes
/// Bytes of one level's list of up to `capacity` rocks, 4 bytes a rock,
/// rounded up to `alignment` (the device's `min_storage_buffer_offset_alignment`)
/// so that the next level's list may start where this one ends.
pub fn list_bytes(capacity: u32, alignment: u32) -> u64 {
    (u64::from(capacity.max(1)) * 4).next_multiple_of(u64::from(alignment))
}
// ANCHOR_END: list_bytes

// ANCHOR: dispatch_size
/// The workgroups for `rocks` rocks, `WORKGROUP_SIZE` to a group, as a
/// grid (x, y): one row where the device allows that many along x
/// (WebGPU guarantees 65,535, which is 4,194,240 rocks), more rows where not.
pub fn dispatch_size(rocks: u32, max_per_dimension: u32) -> (u32, u32) {
    let groups = rocks.div_ceil(WORKGROUP_SIZE);
    let x = groups.min(max_per_dimension.max(1));
    (x, groups.div_ceil(x.max(1)))
}
// ANCHOR_END: dispatch_size

impl RockLists {
    /// Bytes of this picture's buffers: the lists, the draws, the input
    /// and the buffers the counts are read back through.
    pub fn gpu_bytes(&self) -> u64 {
        self.lists.size() + self.draws.size() + self.input.size() + self.late.gpu_bytes()
    }

    /// Rocks kept at each level, finest first, by the latest count that has
    /// come back from the GPU (a frame or two late), without waiting.
    pub fn late_counts(&self) -> Option<[u32; LEVELS]> {
        // Each draw is five numbers; the instance count is the second.
        self.late.latest().map(|draws| std::array::from_fn(|level| draws[level * 5 + 1]))
    }

    /// Rocks kept at each level by the last culling submitted, waiting for
    /// the GPU to finish it: for `--bench`'s figures and the tests.
    pub fn counts_now(&self, gpu: &Gpu) -> [u32; LEVELS] {
        let draws: Vec<u32> = read_buffer(gpu, &self.draws, LEVELS as u64 * DRAW_BYTES);
        std::array::from_fn(|level| draws[level * 5 + 1])
    }

    /// The indirect draws as the GPU holds them, five numbers a level
    /// (`DrawIndexedIndirectArgs`), waiting for the GPU: for the tests.
    pub fn draws_now(&self, gpu: &Gpu) -> Vec<u32> {
        read_buffer(gpu, &self.draws, LEVELS as u64 * DRAW_BYTES)
    }

    /// The rocks each level's list holds, as indices into the rock buffer,
    /// waiting for the GPU: for the tests.
    pub fn lists_now(&self, gpu: &Gpu) -> [Vec<u32>; LEVELS] {
        let counts = self.counts_now(gpu);
        let all: Vec<u32> = read_buffer(gpu, &self.lists, self.lists.size());
        std::array::from_fn(|level| {
            let start = level * self.stride as usize;
            all[start..start + counts[level] as usize].to_vec()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_million_rocks_fit_one_row_of_workgroups_and_more_need_rows() {
        // 1,000,000 / 64 = 15,625 workgroups: one row under WebGPU's 65,535.
        assert_eq!(dispatch_size(1_000_000, 65_535), (15_625, 1));
        // A device allowing 10,000 along x: two rows, the last partly idle.
        assert_eq!(dispatch_size(1_000_000, 10_000), (10_000, 2));
        assert_eq!(dispatch_size(64, 65_535), (1, 1));
        assert_eq!(dispatch_size(65, 65_535), (2, 1));
        assert_eq!(dispatch_size(0, 65_535), (0, 0));
    }
}
