//! Chapter 02: model, view and projection. A field of primitives, each
//! placed by its own model matrix, seen through a perspective camera you fly
//! with the keyboard and mouse, with a depth buffer sorting out what is in
//! front.

use std::f32::consts::PI;

use common::glam::{Mat4, Quat, Vec3};
use common::texture::{DEPTH_FORMAT, depth_view};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, Mesh, MeshData, ShaderError, Target, View, anyhow, egui,
    fullscreen, primitives, shader, wgpu,
};

pub const VIEWS: &[View] = &[
    View::mode("default", "the field of primitives, lit by a fixed sun"),
    View::mode("depth", "the depth buffer as distance: black near, white at 25 m"),
    View::mode("depth-raw", "the depth buffer as stored: almost everything is nearly 1"),
    View::mode("normals", "world-space normals as colours"),
];

// ANCHOR: uniforms
/// The camera as the shader sees it (`Camera` in scene.wgsl).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct CameraUniform {
    view_proj: [[f32; 4]; 4],
    eye: [f32; 4],
}

/// One object's transform and colour (`Object` in scene.wgsl).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ObjectUniform {
    model: [[f32; 4]; 4],
    normal_matrix: [[f32; 4]; 4],
    color: [f32; 4],
}
// ANCHOR_END: uniforms

/// The six primitives from `common::primitives`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    Cube,
    Sphere,
    Cylinder,
    Cone,
    Torus,
    Pyramid,
}

impl Shape {
    pub const ALL: [Shape; 6] =
        [Shape::Cube, Shape::Sphere, Shape::Cylinder, Shape::Cone, Shape::Torus, Shape::Pyramid];

    fn mesh(self) -> MeshData {
        match self {
            Shape::Cube => primitives::cube(),
            Shape::Sphere => primitives::uv_sphere(32, 16),
            Shape::Cylinder => primitives::cylinder(32),
            Shape::Cone => primitives::cone(32),
            Shape::Torus => primitives::torus(48, 16, 0.15),
            Shape::Pyramid => primitives::pyramid(),
        }
    }
}

// ANCHOR: placement
/// Where one object stands and how it moves.
#[derive(Clone, Copy, Debug)]
pub struct Placement {
    pub shape: Shape,
    pub position: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
    /// Turns around the object's own y axis, radians per second.
    pub spin: f32,
    pub color: [f32; 3],
}

impl Placement {
    /// Model matrix at scene time `time`: scale first, then rotate, then
    /// move. Read right to left: T · R · S applied to a vertex v is
    /// T(R(S v)), so scaling happens in the object's own axes.
    pub fn model(&self, time: f32) -> Mat4 {
        let rotation = self.rotation * Quat::from_rotation_y(self.spin * time);
        Mat4::from_translation(self.position) * Mat4::from_quat(rotation) * Mat4::from_scale(self.scale)
    }
}
// ANCHOR_END: placement

// ANCHOR: scene
/// Three rows of the six primitives: as built (front), stretched and
/// tilted (middle), and spinning at different rates (back).
pub fn scene() -> Vec<Placement> {
    let palette = [
        [0.80, 0.25, 0.20],
        [0.90, 0.60, 0.15],
        [0.30, 0.65, 0.30],
        [0.20, 0.45, 0.80],
        [0.55, 0.30, 0.75],
        [0.85, 0.80, 0.70],
    ];
    let mut objects = Vec::new();
    for (i, &shape) in Shape::ALL.iter().enumerate() {
        let x = (i as f32 - 2.5) * 2.2;
        let color = palette[i];
        let upright = Quat::IDENTITY;
        objects.push(Placement {
            shape,
            position: Vec3::new(x, 0.5, 2.0),
            rotation: upright,
            scale: Vec3::ONE,
            spin: 0.0,
            color,
        });
        objects.push(Placement {
            shape,
            position: Vec3::new(x, 0.9, -1.0),
            rotation: Quat::from_rotation_z(0.35) * Quat::from_rotation_x(-0.3),
            scale: Vec3::new(0.7, 1.6, 0.7),
            spin: 0.0,
            color,
        });
        objects.push(Placement {
            shape,
            position: Vec3::new(x, 1.2, -4.0),
            rotation: Quat::from_rotation_x(PI / 2.0 * (i % 2) as f32),
            scale: Vec3::splat(1.4),
            spin: 0.4 + 0.25 * i as f32,
            color,
        });
    }
    objects
}
// ANCHOR_END: scene

/// The ground: a 60 m square with a checker pattern.
fn ground() -> ObjectUniform {
    let model = Mat4::from_scale(Vec3::new(60.0, 1.0, 60.0));
    ObjectUniform {
        model: model.to_cols_array_2d(),
        normal_matrix: model.inverse().transpose().to_cols_array_2d(),
        color: [0.35, 0.36, 0.38, 1.0],
    }
}

/// The camera every view starts from.
fn start_camera(aspect: f32) -> Camera {
    let mut camera = Camera::looking_at(Vec3::new(-3.0, 4.0, 9.0), Vec3::new(0.0, 0.5, -1.0), aspect);
    camera.far = 200.0;
    camera
}

const SKY: wgpu::Color = wgpu::Color { r: 0.30, g: 0.42, b: 0.60, a: 1.0 };

/// Pipelines rebuilt when the WGSL changes.
struct Pipelines {
    shaded: wgpu::RenderPipeline,
    normals: wgpu::RenderPipeline,
    depth_view: wgpu::RenderPipeline,
}

pub struct CameraChapter {
    pub camera: Camera,
    pub controller: FlyController,
    objects: Vec<Placement>,
    meshes: Vec<Mesh>,
    ground_mesh: Mesh,
    camera_buffer: wgpu::Buffer,
    camera_group: wgpu::BindGroup,
    object_buffer: wgpu::Buffer,
    object_group: wgpu::BindGroup,
    /// Bytes between consecutive objects in `object_buffer`.
    object_stride: u32,
    depth: wgpu::TextureView,
    depth_params: wgpu::Buffer,
    depth_group_layout: wgpu::BindGroupLayout,
    depth_group: wgpu::BindGroup,
    layouts: [wgpu::PipelineLayout; 2],
    pipelines: Pipelines,
    target: Target,
}

// ANCHOR: dynamic_offsets
/// Every object's uniforms live in one buffer, each at a multiple of the
/// device's `min_uniform_buffer_offset_alignment` (256 bytes on most GPUs,
/// though `ObjectUniform` is 144), and a dynamic offset picks one per draw.
fn object_stride(device: &wgpu::Device) -> u32 {
    let size = std::mem::size_of::<ObjectUniform>() as u32;
    size.next_multiple_of(device.limits().min_uniform_buffer_offset_alignment)
}
// ANCHOR_END: dynamic_offsets

fn uniform_layout(device: &wgpu::Device, label: &str, dynamic: bool, size: usize) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: dynamic,
                min_binding_size: wgpu::BufferSize::new(size as u64),
            },
            count: None,
        }],
    })
}

fn depth_group(
    gpu: &Gpu,
    layout: &wgpu::BindGroupLayout,
    depth: &wgpu::TextureView,
    params: &wgpu::Buffer,
) -> wgpu::BindGroup {
    // Nearest is the default filter: each pixel reads exactly its texel.
    let nearest = gpu.device.create_sampler(&wgpu::SamplerDescriptor { label: Some("nearest"), ..Default::default() });
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("depth view"),
        layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(depth) },
            wgpu::BindGroupEntry { binding: 1, resource: params.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&nearest) },
        ],
    })
}

// ANCHOR: pipeline
fn scene_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    format: wgpu::TextureFormat,
    fragment_entry: &str,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(fragment_entry),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            buffers: &[Some(common::Vertex::LAYOUT)],
            compilation_options: Default::default(),
        },
        primitive: wgpu::PrimitiveState { cull_mode: Some(wgpu::Face::Back), ..Default::default() },
        // Keep a fragment only if it is nearer than what is already there,
        // and remember its depth for the fragments that come after it.
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
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
// ANCHOR_END: pipeline

impl CameraChapter {
    fn build_pipelines(
        gpu: &Gpu,
        layouts: &[wgpu::PipelineLayout; 2],
        format: wgpu::TextureFormat,
    ) -> Result<Pipelines, ShaderError> {
        let scene = shader!("camera/scene.wgsl").module(gpu)?;
        let depth = shader!("camera/depth.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        gpu.catch_validation(|| Pipelines {
            shaded: scene_pipeline(&gpu.device, &layouts[0], &scene, format, "fs_main"),
            normals: scene_pipeline(&gpu.device, &layouts[0], &scene, format, "fs_normals"),
            depth_view: fullscreen::pipeline(
                &gpu.device,
                "depth view",
                &layouts[1],
                &depth,
                "fs_depth",
                format.into(),
                None,
            ),
        })
        .map_err(ShaderError)
    }

    // ANCHOR: update_uniforms
    fn write_uniforms(&self, gpu: &Gpu, time: f32, view: usize) {
        let camera = CameraUniform {
            view_proj: self.camera.view_projection().to_cols_array_2d(),
            eye: self.camera.position.extend(1.0).into(),
        };
        gpu.queue.write_buffer(&self.camera_buffer, 0, bytemuck::bytes_of(&camera));

        let stride = self.object_stride as usize;
        let mut bytes = vec![0u8; stride * (self.objects.len() + 1)];
        let placed = self.objects.iter().map(|o| {
            let model = o.model(time);
            ObjectUniform {
                model: model.to_cols_array_2d(),
                normal_matrix: model.inverse().transpose().to_cols_array_2d(),
                color: [o.color[0], o.color[1], o.color[2], 0.0],
            }
        });
        for (i, object) in std::iter::once(ground()).chain(placed).enumerate() {
            bytes[i * stride..][..std::mem::size_of::<ObjectUniform>()].copy_from_slice(bytemuck::bytes_of(&object));
        }
        gpu.queue.write_buffer(&self.object_buffer, 0, &bytes);

        let raw = u32::from(VIEWS[view].name == "depth-raw");
        let params = [self.camera.near, self.camera.far, 25.0, f32::from_bits(raw)];
        gpu.queue.write_buffer(&self.depth_params, 0, bytemuck::cast_slice(&params));
    }
    // ANCHOR_END: update_uniforms
}

impl Chapter for CameraChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "02 · Camera, transforms and depth";
    const VIEWS: &'static [View] = VIEWS;
    const SNAPSHOT_TIME: f32 = 2.0;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;

    fn new(gpu: &Gpu, target: Target) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let objects = scene();
        let meshes = Shape::ALL.iter().map(|s| s.mesh().upload(device, &format!("{s:?}"))).collect();
        let ground_mesh = primitives::plane(1).upload(device, "ground");

        let camera_layout = uniform_layout(device, "camera", false, std::mem::size_of::<CameraUniform>());
        let object_layout = uniform_layout(device, "object", true, std::mem::size_of::<ObjectUniform>());
        let camera_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("camera"),
            size: std::mem::size_of::<CameraUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let object_stride = object_stride(device);
        let object_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("objects"),
            size: u64::from(object_stride) * (objects.len() as u64 + 1),
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let camera_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("camera"),
            layout: &camera_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: camera_buffer.as_entire_binding() }],
        });
        let object_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("objects"),
            layout: &object_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                // The binding is one object wide; the dynamic offset slides it.
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &object_buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<ObjectUniform>() as u64),
                }),
            }],
        });

        let depth_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("depth view"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        // Depth read as unfilterable floats (see depth.wgsl).
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: wgpu::BufferSize::new(16),
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
                    count: None,
                },
            ],
        });
        let depth_params = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("depth view"),
            contents: &[0; 16],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let depth = depth_view(device, target.width, target.height);
        let depth_group = depth_group(gpu, &depth_group_layout, &depth, &depth_params);

        let layouts = [
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("scene"),
                bind_group_layouts: &[Some(&camera_layout), Some(&object_layout)],
                immediate_size: 0,
            }),
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("depth view"),
                bind_group_layouts: &[Some(&depth_group_layout)],
                immediate_size: 0,
            }),
        ];
        let pipelines = Self::build_pipelines(gpu, &layouts, target.format)?;

        Ok(Self {
            camera: start_camera(target.aspect()),
            controller: FlyController::default(),
            objects,
            meshes,
            ground_mesh,
            camera_buffer,
            camera_group,
            object_buffer,
            object_group,
            object_stride,
            depth,
            depth_params,
            depth_group_layout,
            depth_group,
            layouts,
            pipelines,
            target,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.depth = depth_view(&gpu.device, target.width, target.height);
        self.depth_group = depth_group(gpu, &self.depth_group_layout, &self.depth, &self.depth_params);
    }

    fn reset_camera(&mut self, _view: usize) {
        self.camera = start_camera(self.target.aspect());
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.write_uniforms(gpu, frame.time, frame.view);
        let view = VIEWS[frame.view].name;
        {
            let mut pass = frame.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("scene"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: frame.target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Clear(SKY), store: wgpu::StoreOp::Store },
                })],
                // Every frame starts with all depths at the far plane (1.0).
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &self.depth,
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                timestamp_writes: frame.timer.pass("scene"),
                ..Default::default()
            });
            let pipeline = if view == "normals" { &self.pipelines.normals } else { &self.pipelines.shaded };
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &self.camera_group, &[]);
            pass.set_bind_group(1, &self.object_group, &[0]);
            self.ground_mesh.draw(&mut pass, 0..1);
            for (i, object) in self.objects.iter().enumerate() {
                let offset = (i as u32 + 1) * self.object_stride;
                pass.set_bind_group(1, &self.object_group, &[offset]);
                self.meshes[object.shape as usize].draw(&mut pass, 0..1);
            }
        }
        if view.starts_with("depth") {
            let mut pass = fullscreen::pass(frame.encoder, frame.timer, "depth view", frame.target, None);
            pass.set_pipeline(&self.pipelines.depth_view);
            pass.set_bind_group(0, &self.depth_group, &[]);
            pass.draw(0..3, 0..1);
        }
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let mut fov = self.camera.fov_y.to_degrees();
        ui.add(egui::Slider::new(&mut fov, 20.0..=120.0).text("field of view (°)"));
        self.camera.fov_y = fov.to_radians();
        ui.add(egui::Slider::new(&mut self.camera.near, 0.01..=5.0).logarithmic(true).text("near plane (m)"));
        ui.add(egui::Slider::new(&mut self.camera.far, 10.0..=2000.0).logarithmic(true).text("far plane (m)"));
        ui.add(egui::Slider::new(&mut self.controller.speed, 1.0..=50.0).text("speed (m/s)"));
    }

    fn reload_shaders(&mut self, gpu: &Gpu) -> Result<(), ShaderError> {
        self.pipelines = Self::build_pipelines(gpu, &self.layouts, self.target.format)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn model_matrix_scales_then_rotates_then_translates() {
        let placement = Placement {
            shape: Shape::Cube,
            position: Vec3::new(10.0, 0.0, 0.0),
            rotation: Quat::from_rotation_z(PI / 2.0),
            scale: Vec3::new(2.0, 1.0, 1.0),
            spin: 0.0,
            color: [1.0; 3],
        };
        // +x is doubled to (2,0,0), turned a quarter about z to (0,2,0), moved by +10 x.
        let p = placement.model(0.0).transform_point3(Vec3::X);
        assert!(p.distance(Vec3::new(10.0, 2.0, 0.0)) < 1e-5, "{p}");
    }

    #[test]
    fn spin_follows_scene_time() {
        let mut placement = scene()[2];
        placement.rotation = Quat::IDENTITY;
        placement.spin = PI / 2.0;
        let p = placement.model(1.0).transform_vector3(Vec3::X / placement.scale);
        assert!(p.distance(Vec3::NEG_Z) < 1e-5, "{p}");
    }

    #[test]
    fn the_scene_has_every_primitive_in_every_row() {
        let objects = scene();
        assert_eq!(objects.len(), 18);
        for shape in Shape::ALL {
            assert_eq!(objects.iter().filter(|o| o.shape == shape).count(), 3);
        }
    }
}
