//! The chapter itself: what each view decides, the views, the camera, the
//! overlay's controls, and `impl Chapter`, which draws the field of
//! primitives and, for the depth views, the depth buffer over it.

use common::glam::{Mat4, Vec3};
use common::wgpu::util::DeviceExt as _;
use common::{
    Camera, Chapter, Drawn, FlyController, Frame, Gpu, Input, Mesh, Preparation, Reloadable, SceneTargets, ShaderError,
    Target, View, ViewRow, anyhow, egui, fullscreen, primitives, shader, views_of, wgpu,
};

use crate::depth_display::{depth_group, depth_group_layout};
use crate::pipeline::scene_pipeline;
use crate::scene::{Placement, Shape, scene};
use crate::uniforms::{CameraUniform, ObjectUniform, object_stride, uniform_layout};

/// What the picture shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    /// The scene, lit by a fixed sun.
    Shaded,
    /// World-space normals as colours.
    Normals,
    /// The depth buffer as distance.
    Depth,
    /// The depth buffer as stored.
    DepthRaw,
}

/// What a view decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    pub display: Display,
}

impl Settings {
    pub const DEFAULT: Self = Self { display: Display::Shaded };
}

/// No view of this chapter places the camera (every one is a mode): this
/// enum has no values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {}

impl CameraPreset {
    pub fn camera(self, _aspect: f32) -> Camera {
        match self {}
    }
}

/// Every view, with the settings it applies.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 5] = [
    ViewRow::mode("default", "the field of primitives, lit by a fixed sun", Settings::DEFAULT),
    ViewRow::no_aa("default", Settings::DEFAULT),
    ViewRow::mode(
        "depth",
        "the depth buffer as distance: black near, white at 25 m",
        Settings { display: Display::Depth },
    ),
    ViewRow::mode(
        "depth-raw",
        "the depth buffer as stored: almost everything is nearly 1",
        Settings { display: Display::DepthRaw },
    ),
    ViewRow::mode("normals", "world-space normals as colours", Settings { display: Display::Normals }),
];

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

/// The chapter's pipelines, kept in a `Reloadable`: rebuilt when their WGSL
/// is saved (hot reload).
#[derive(Clone)]
struct Pipelines {
    shaded: wgpu::RenderPipeline,
    normals: wgpu::RenderPipeline,
    /// `shaded` at one sample a pixel, for the depth views' scene pass.
    one_sample: wgpu::RenderPipeline,
    depth_view: wgpu::RenderPipeline,
}

pub struct CameraChapter {
    pub settings: Settings,
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
    /// The scene's samples and depth, resolved into the frame.
    scene: SceneTargets,
    /// One sample a pixel, for the depth views: they read the depth buffer
    /// as data, and a multisampled one would need a shader of its own.
    depth_scene: SceneTargets,
    depth_params: wgpu::Buffer,
    depth_group_layout: wgpu::BindGroupLayout,
    depth_group: wgpu::BindGroup,
    pipelines: Reloadable<Pipelines>,
    target: Target,
}

impl CameraChapter {
    fn build_pipelines(
        gpu: &Gpu,
        layouts: &[wgpu::PipelineLayout; 2],
        format: wgpu::TextureFormat,
        multisample: wgpu::MultisampleState,
    ) -> Result<Pipelines, ShaderError> {
        let scene = shader!("camera/scene.wgsl").module(gpu)?;
        let depth = shader!("camera/depth.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        gpu.catch_validation(|| Pipelines {
            shaded: scene_pipeline(&gpu.device, &layouts[0], &scene, format, "fs_main", multisample),
            normals: scene_pipeline(&gpu.device, &layouts[0], &scene, format, "fs_normals", multisample),
            one_sample: scene_pipeline(&gpu.device, &layouts[0], &scene, format, "fs_main", Default::default()),
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
    fn write_uniforms(&self, gpu: &Gpu, time: f32) {
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

        let raw = u32::from(self.settings.display == Display::DepthRaw);
        let params = [self.camera.near, self.camera.far, 25.0, f32::from_bits(raw)];
        gpu.queue.write_buffer(&self.depth_params, 0, bytemuck::cast_slice(&params));
    }
    // ANCHOR_END: update_uniforms
}

impl Chapter for CameraChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "02 · Camera, transforms and depth";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);
    const SNAPSHOT_TIME: f32 = 2.0;
    const KEYS: &'static [(&'static str, &'static str)] = FlyController::KEYS;

    /// Nothing takes long enough to prepare in steps.
    type Prepared = ();

    fn prepare(_gpu: &Gpu) -> Preparation<()> {
        Preparation::ready(())
    }

    fn new(gpu: &Gpu, target: Target, (): ()) -> anyhow::Result<Self> {
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

        let depth_group_layout = depth_group_layout(device);
        let depth_params = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("depth view"),
            contents: &[0; 16],
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let scene = SceneTargets::new(gpu, target);
        let depth_scene = SceneTargets::new(gpu, Target { samples: 1, ..target });
        let depth = depth_scene.depth().expect("made with a depth buffer");
        let depth_group = depth_group(gpu, &depth_group_layout, depth, &depth_params);

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
        let (format, multisample) = (target.format, scene.multisample());
        let pipelines = Reloadable::new(gpu, move |gpu| Self::build_pipelines(gpu, &layouts, format, multisample))?;

        Ok(Self {
            settings: Settings::DEFAULT,
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
            scene,
            depth_scene,
            depth_params,
            depth_group_layout,
            depth_group,
            pipelines,
            target,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        // The sample count stays the one the pipelines were made for.
        let samples = self.scene.samples();
        self.scene = SceneTargets::new(gpu, Target { samples, ..target });
        self.depth_scene = SceneTargets::new(gpu, Target { samples: 1, ..target });
        let depth = self.depth_scene.depth().expect("made with a depth buffer");
        self.depth_group = depth_group(gpu, &self.depth_group_layout, depth, &self.depth_params);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
    }

    fn reset_camera(&mut self, view: usize) {
        let aspect = self.target.aspect();
        self.camera = match VIEW_TABLE[view].camera {
            Some(preset) => preset.camera(aspect),
            None => start_camera(aspect),
        };
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn update(&mut self, input: &Input, dt: f32) {
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.write_uniforms(gpu, frame.time);
        let display = self.settings.display;
        let pipelines = self.pipelines.get();
        // The depth views read the depth buffer: they draw at one sample.
        let reads_depth = matches!(display, Display::Depth | Display::DepthRaw);
        let scene = if reads_depth { &self.depth_scene } else { &self.scene };
        {
            // With several samples a pixel, the pass draws into the samples
            // and averages them into the target as it ends (the resolve).
            let (view, resolve_target) = scene.colour_attachment(frame.target);
            let mut pass = frame.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("scene"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Clear(SKY), store: wgpu::StoreOp::Store },
                })],
                // Every frame starts with all depths at the far plane (1.0).
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: scene.depth().expect("made with a depth buffer"),
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                timestamp_writes: frame.timer.pass("scene"),
                ..Default::default()
            });
            let pipeline = match display {
                _ if reads_depth => &pipelines.one_sample,
                Display::Normals => &pipelines.normals,
                _ => &pipelines.shaded,
            };
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &self.camera_group, &[]);
            pass.set_bind_group(1, &self.object_group, &[0]);
            // Each draw says what it drew: the overlay and the bench count triangles per pass.
            let mut drawn = self.ground_mesh.draw(&mut pass, 0..1);
            for (i, object) in self.objects.iter().enumerate() {
                let offset = (i as u32 + 1) * self.object_stride;
                pass.set_bind_group(1, &self.object_group, &[offset]);
                drawn += self.meshes[object.shape as usize].draw(&mut pass, 0..1);
            }
            frame.drawn.add("scene", drawn);
        }
        if reads_depth {
            let mut pass = fullscreen::pass(frame.encoder, frame.timer, "depth view", frame.target, None);
            pass.set_pipeline(&pipelines.depth_view);
            pass.set_bind_group(0, &self.depth_group, &[]);
            pass.draw(0..3, 0..1);
            frame.drawn.add("depth view", Drawn::FULL_SCREEN);
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
}
