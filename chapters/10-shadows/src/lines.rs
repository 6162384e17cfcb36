//! Lines over the finished picture, for seeing what the game and the
//! shadows work with: the collision boxes and the sun's box.

use common::chapter::uniform_entry;
use common::glam::{Mat4, Vec3, Vec4};
use common::{Drawn, Gpu, PassCount, Reloadable, ShaderError, shader, wgpu};

use crate::game::Game;
use crate::physics::Aabb;

/// A corner of a line.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LineVertex {
    pub position: [f32; 3],
    pub colour: [f32; 4],
}

/// Segments to draw, two vertices each.
#[derive(Clone, Debug, Default)]
pub struct LineList(pub Vec<LineVertex>);

impl LineList {
    pub fn segment(&mut self, a: Vec3, b: Vec3, colour: Vec4) {
        self.0.push(LineVertex { position: a.into(), colour: colour.into() });
        self.0.push(LineVertex { position: b.into(), colour: colour.into() });
    }

    /// The outline of a rectangle at depth `z`.
    pub fn rectangle(&mut self, min: Vec3, max: Vec3, colour: Vec4) {
        let c = [min, Vec3::new(max.x, min.y, min.z), max, Vec3::new(min.x, max.y, min.z)];
        for i in 0..4 {
            self.segment(c[i], c[(i + 1) % 4], colour);
        }
    }

    /// The twelve edges of a box given by its corners, indexed by bits
    /// (bit 0: x, bit 1: y, bit 2: z), as `LightBox::corners` gives them.
    pub fn box_edges(&mut self, corners: &[Vec3; 8], colour: Vec4) {
        for i in 0..8 {
            for bit in [1, 2, 4] {
                if i & bit == 0 {
                    self.segment(corners[i], corners[i | bit], colour);
                }
            }
        }
    }

    /// The collision boxes as the physics sees them, in the plane z = 0:
    /// the `solids` green, the player's box yellow when it stands on
    /// something and red in the air.
    pub fn collision_boxes(solids: &[Aabb], game: &Game) -> Self {
        let mut list = LineList::default();
        let solid = Vec4::new(0.2, 1.0, 0.3, 1.0);
        for aabb in solids {
            list.rectangle(aabb.min.extend(0.0), aabb.max.extend(0.0), solid);
        }
        let player = if game.on_floor { Vec4::new(1.0, 0.85, 0.1, 1.0) } else { Vec4::new(1.0, 0.25, 0.2, 1.0) };
        list.rectangle(game.player.aabb.min.extend(0.0), game.player.aabb.max.extend(0.0), player);
        list
    }
}

/// Draws a [`LineList`] into a target of the given format.
pub struct Lines {
    /// Made again when lines.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
    uniform: wgpu::Buffer,
    group: wgpu::BindGroup,
    vertices: wgpu::Buffer,
}

impl Lines {
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("lines"),
            entries: &[uniform_entry(0, wgpu::ShaderStages::VERTEX, 64)],
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("lines"),
            size: 64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("lines"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("lines"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| Self::pipeline(gpu, &pipeline_layout, format))?;
        let vertices = Self::buffer(device, 256);
        Ok(Self { pipeline, uniform, group, vertices })
    }

    fn buffer(device: &wgpu::Device, count: u64) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("lines"),
            size: count * std::mem::size_of::<LineVertex>() as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn pipeline(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!("shadows/lines.wgsl").module(gpu)?;
        gpu.catch_validation(|| {
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("lines"),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_line"),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: std::mem::size_of::<LineVertex>() as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x4],
                    })],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { topology: wgpu::PrimitiveTopology::LineList, ..Default::default() },
                depth_stencil: None,
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_line"),
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
        })
        .map_err(ShaderError)
    }

    /// Draws `list` over `target`, seen through `view_proj`.
    pub fn draw(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &common::PassTimer,
        target: &wgpu::TextureView,
        view_proj: Mat4,
        list: &LineList,
    ) -> Option<PassCount> {
        if list.0.is_empty() {
            return None;
        }
        let bytes = std::mem::size_of_val(list.0.as_slice()) as u64;
        if bytes > self.vertices.size() {
            self.vertices = Self::buffer(&gpu.device, (list.0.len() as u64).next_power_of_two());
        }
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&view_proj.to_cols_array_2d()));
        gpu.queue.write_buffer(&self.vertices, 0, bytemuck::cast_slice(&list.0));
        let mut pass = common::fullscreen::pass(encoder, timer, "lines", target, None);
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(0, &self.group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.draw(0..list.0.len() as u32, 0..1);
        Some(PassCount { pass: "lines", drawn: Drawn::POINTS_OR_LINES })
    }
}
