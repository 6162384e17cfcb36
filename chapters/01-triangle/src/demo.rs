//! The chapter itself: the overlay's colour pickers, and `impl Chapter`,
//! which puts the vertex buffer and the two pipelines together into a
//! frame.

use common::wgpu::util::DeviceExt as _;
use common::{
    Chapter, Drawn, Frame, Gpu, Preparation, Reloadable, SceneTargets, Target, View, anyhow, egui, views_of, wgpu,
};

use crate::pipeline::build_pipelines;
use crate::vertex::{ColoredVertex, TRIANGLE};
use crate::views::{Settings, VIEW_TABLE};

/// The background, a dark blue-grey (linear RGB).
const CLEAR: wgpu::Color = wgpu::Color { r: 0.02, g: 0.025, b: 0.04, a: 1.0 };

pub struct Triangle {
    pub settings: Settings,
    vertices: wgpu::Buffer,
    corners: [ColoredVertex; 3],
    /// The smooth and the flat pipeline, rebuilt whenever triangle.wgsl is
    /// saved while the window is open (hot reload).
    pipelines: Reloadable<[wgpu::RenderPipeline; 2]>,
    /// Where the triangle is drawn before it reaches the target: four
    /// samples a pixel, so that its edges are smoothed (chapter 02).
    scene: SceneTargets,
}

impl Chapter for Triangle {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    const TITLE: &'static str = "01 · The first triangle";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }

    /// Nothing takes long enough to prepare in steps.
    type Prepared = ();

    fn prepare(_gpu: &Gpu) -> Preparation<()> {
        Preparation::ready(())
    }

    // ANCHOR: new
    fn new(gpu: &Gpu, target: Target, (): ()) -> anyhow::Result<Self> {
        let vertices = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("triangle vertices"),
            contents: bytemuck::cast_slice(&TRIANGLE),
            // COPY_DST so the colour pickers in the overlay can rewrite it.
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        });
        let scene = SceneTargets::without_depth(gpu, target);
        let (format, multisample) = (target.format, scene.multisample());
        let pipelines = Reloadable::new(gpu, move |gpu| build_pipelines(gpu, format, multisample))?;
        Ok(Self { settings: Settings::DEFAULT, vertices, corners: TRIANGLE, pipelines, scene })
    }
    // ANCHOR_END: new

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.scene = SceneTargets::without_depth(gpu, target);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        gpu.queue.write_buffer(&self.vertices, 0, bytemuck::cast_slice(&self.corners));
        // With several samples a pixel, the pass draws into the samples and
        // averages them into the target as it ends (the resolve).
        let (view, resolve_target) = self.scene.colour_attachment(frame.target);
        let mut pass = frame.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("triangle"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(CLEAR), store: wgpu::StoreOp::Store },
            })],
            timestamp_writes: frame.timer.pass("triangle"),
            ..Default::default()
        });
        let [smooth, flat] = self.pipelines.get();
        pass.set_pipeline(if self.settings.interpolate { &smooth } else { &flat });
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.draw(0..3, 0..1);
        // Three vertices, one instance: one triangle, for the overlay's count.
        frame.drawn.add("triangle", Drawn::triangle_list(0..3, 0..1));
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label("Corner colours (linear RGB):");
        ui.horizontal(|ui| {
            for corner in &mut self.corners {
                ui.color_edit_button_rgb(&mut corner.color);
            }
        });
        if ui.button("reset").clicked() {
            self.corners = TRIANGLE;
        }
    }
}
