//! The chapter itself: the camera, the overlay's controls, and
//! `impl Chapter`, which draws the field of primitives and, for the depth
//! views, the depth buffer over it.

use common::{
    Camera, Chapter, Drawn, FlyController, Frame, Gpu, Input, Mesh, Preparation, Reloadable, SceneTargets, Target,
    View, anyhow, egui, fullscreen, primitives, views_of, wgpu,
};

use crate::camera_presets::start_camera;
use crate::depth_display::DepthDisplay;
use crate::pipeline::Pipelines;
use crate::scene::{Placement, Shape, scene};
use crate::uniforms::SceneUniforms;
use crate::views::{Display, Settings, VIEW_TABLE};

const SKY: wgpu::Color = wgpu::Color { r: 0.30, g: 0.42, b: 0.60, a: 1.0 };

pub struct CameraChapter {
    pub settings: Settings,
    pub camera: Camera,
    pub controller: FlyController,
    objects: Vec<Placement>,
    meshes: Vec<Mesh>,
    ground_mesh: Mesh,
    uniforms: SceneUniforms,
    /// The scene's samples and depth, resolved into the frame.
    scene: SceneTargets,
    /// One sample a pixel, for the depth views: they read the depth buffer
    /// as data, and a multisampled one would need a shader of its own.
    depth_scene: SceneTargets,
    depth_display: DepthDisplay,
    pipelines: Reloadable<Pipelines>,
    target: Target,
}

impl Chapter for CameraChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "02 · Camera, transforms and depth";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
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
        let uniforms = SceneUniforms::new(device, objects.len());

        let scene = SceneTargets::new(gpu, target);
        let depth_scene = SceneTargets::new(gpu, Target { samples: 1, ..target });
        let depth_display = DepthDisplay::new(gpu, depth_scene.depth().expect("made with a depth buffer"));

        let layouts = [uniforms.pipeline_layout.clone(), depth_display.pipeline_layout(device)];
        let (format, multisample) = (target.format, scene.multisample());
        let pipelines = Reloadable::new(gpu, move |gpu| {
            let [scene_layout, depth_layout] = &layouts;
            Pipelines::build(gpu, scene_layout, depth_layout, format, multisample)
        })?;

        Ok(Self {
            settings: Settings::DEFAULT,
            camera: start_camera(target.aspect()),
            controller: FlyController::default(),
            objects,
            meshes,
            ground_mesh,
            uniforms,
            scene,
            depth_scene,
            depth_display,
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
        self.depth_display.read(gpu, self.depth_scene.depth().expect("made with a depth buffer"));
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
        let display = self.settings.display;
        self.uniforms.write(&gpu.queue, &self.camera, &self.objects, frame.time);
        self.depth_display.write(&gpu.queue, &self.camera, display == Display::DepthRaw);
        let pipelines = self.pipelines.get();
        // The depth views read the depth buffer: they draw at one sample.
        let reads_depth = display.reads_depth();
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
            // ANCHOR: draw_objects
            self.uniforms.bind_camera(&mut pass);
            // Slot 0 is the ground; each object's uniforms follow in order.
            self.uniforms.bind_object(&mut pass, 0);
            // Each draw says what it drew: the overlay and the bench count triangles per pass.
            let mut drawn = self.ground_mesh.draw(&mut pass, 0..1);
            for (i, object) in self.objects.iter().enumerate() {
                self.uniforms.bind_object(&mut pass, i + 1);
                drawn += self.meshes[object.shape as usize].draw(&mut pass, 0..1);
            }
            // ANCHOR_END: draw_objects
            frame.drawn.add("scene", drawn);
        }
        if reads_depth {
            let mut pass = fullscreen::pass(frame.encoder, frame.timer, "depth view", frame.target, None);
            pass.set_pipeline(&pipelines.depth_view);
            pass.set_bind_group(0, self.depth_display.group(), &[]);
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
