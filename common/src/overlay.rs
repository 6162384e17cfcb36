//! The egui overlay drawn over every chapter in a window: egui's renderer
//! and input, and the panel it shows (frame times, the view selector, the
//! chapter's own controls, shader errors and key help).

use std::collections::VecDeque;

use winit::window::Window;

use crate::chapter::{About, Runnable};
use crate::draw_counts::{thousands, total};
use crate::memory::MemoryUse;
use crate::{CameraPlace, Gpu, PassCount};

/// Keys the window runner handles for every chapter (its `window_event`),
/// as the key help lists them after the chapter's own.
const RUNNER_KEYS: &[(&str, &str)] = &[
    ("F1", "show or hide this help"),
    ("F2", "hide or show the overlay, to see the picture whole (also while typing)"),
    ("F12", "save a screenshot (PNG) of the scene"),
    ("P", "pause or resume scene time"),
    ("Tab", "lock the pointer for mouse look (Esc unlocks)"),
    ("Esc", "unlock the pointer, or quit"),
];

/// egui's input state, context and wgpu renderer for one window.
pub struct Overlay {
    pub ctx: egui::Context,
    state: egui_winit::State,
    renderer: egui_wgpu::Renderer,
}

impl Overlay {
    /// `format` must be a non-sRGB format: egui blends in gamma space.
    pub fn new(window: &Window, gpu: &Gpu, format: wgpu::TextureFormat) -> Self {
        let ctx = egui::Context::default();
        let max_side = gpu.device.limits().max_texture_dimension_2d as usize;
        let state = egui_winit::State::new(
            ctx.clone(),
            egui::ViewportId::ROOT,
            window,
            Some(window.scale_factor() as f32),
            window.theme(),
            Some(max_side),
        );
        let renderer = egui_wgpu::Renderer::new(&gpu.device, format, egui_wgpu::RendererOptions::default());
        Self { ctx, state, renderer }
    }

    /// Feeds a window event to egui; true when egui used it.
    pub fn on_event(&mut self, window: &Window, event: &winit::event::WindowEvent) -> bool {
        self.state.on_window_event(window, event).consumed
    }

    /// Runs the UI and records drawing it over `target` (loading, not
    /// clearing). `size` is the target's size in pixels: egui's clip
    /// rectangles are cut to it, so they always fit the surface drawn into,
    /// even in a frame where the window has already changed size again.
    pub fn draw(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: [u32; 2],
        window: &Window,
        ui: impl FnMut(&egui::Context),
    ) -> Vec<wgpu::CommandBuffer> {
        let raw = self.state.take_egui_input(window);
        let mut output = self.ctx.run_pass(raw, ui);
        self.state.handle_platform_output(window, output.platform_output);
        let jobs = self.ctx.tessellate(output.shapes, output.pixels_per_point);
        // Every texture delta must be applied (and drained: egui asserts that
        // none is dropped unapplied), or glyphs go missing.
        for (id, deltas) in output.textures_delta.set.drain() {
            for delta in &deltas {
                self.renderer.update_texture(&gpu.device, &gpu.queue, id, delta);
            }
        }
        let screen = egui_wgpu::ScreenDescriptor { size_in_pixels: size, pixels_per_point: output.pixels_per_point };
        let extra = self.renderer.update_buffers(&gpu.device, &gpu.queue, encoder, &jobs, &screen);
        {
            let mut pass = encoder
                .begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("egui overlay"),
                    color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                        view: target,
                        depth_slice: None,
                        resolve_target: None,
                        ops: wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store },
                    })],
                    ..Default::default()
                })
                .forget_lifetime();
            self.renderer.render(&mut pass, &jobs, &screen);
        }
        for id in output.textures_delta.free.drain() {
            self.renderer.free_texture(&id);
        }
        extra
    }
}

/// The last few seconds of frame times, for the FPS readout and graph.
#[derive(Default)]
pub struct FrameHistory {
    millis: VecDeque<f32>,
}

impl FrameHistory {
    const LEN: usize = 240;

    pub fn push(&mut self, seconds: f32) {
        if self.millis.len() == Self::LEN {
            self.millis.pop_front();
        }
        self.millis.push_back(seconds * 1000.0);
    }

    /// Mean frame time over the last 60 frames, in milliseconds.
    pub fn mean_ms(&self) -> f32 {
        let recent = self.millis.iter().rev().take(60);
        let n = recent.len().max(1) as f32;
        recent.sum::<f32>() / n
    }

    /// A small line graph of frame times, scaled to the slowest frame shown.
    pub fn graph(&self, ui: &mut egui::Ui) {
        let size = egui::vec2(ui.available_width().max(200.0), 48.0);
        let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 2.0, egui::Color32::from_black_alpha(120));
        let top = self.millis.iter().copied().fold(1.0f32, f32::max) * 1.1;
        let points: Vec<egui::Pos2> = self
            .millis
            .iter()
            .enumerate()
            .map(|(i, ms)| {
                let x = rect.left() + rect.width() * i as f32 / (Self::LEN - 1) as f32;
                egui::pos2(x, rect.bottom() - rect.height() * ms / top)
            })
            .collect();
        painter.add(egui::Shape::line(points, egui::Stroke::new(1.5, egui::Color32::LIGHT_GREEN)));
        painter.text(
            rect.left_top() + egui::vec2(4.0, 2.0),
            egui::Align2::LEFT_TOP,
            format!("{top:.1} ms"),
            egui::FontId::monospace(10.0),
            egui::Color32::GRAY,
        );
    }
}

/// Puts `text` on the clipboard: the system's on the desktop (egui-winit
/// hands it over), and in a page the browser's too (egui-winit keeps it
/// to itself there).
fn copy(ctx: &egui::Context, text: String) {
    #[cfg(target_arch = "wasm32")]
    crate::web::copy_text(&text);
    ctx.copy_text(text);
}

/// One line per pass: the triangles and draw calls of the last frame, and
/// their sum when there are several passes.
fn triangle_lines(ui: &mut egui::Ui, drawn: &[PassCount]) {
    if drawn.is_empty() {
        return;
    }
    let line = |what: &str, count: crate::Drawn| {
        let calls = if count.draws == 1 { "draw" } else { "draws" };
        format!("{what}: {} triangles, {} {calls}", thousands(count.triangles), count.draws)
    };
    let mut text: Vec<String> = drawn.iter().map(|p| line(p.pass, p.drawn)).collect();
    if drawn.len() > 1 {
        text.push(line("all passes", total(drawn)));
    }
    ui.small(text.join("\n"))
        .on_hover_text("counted from the draws each pass recorded in the last frame (--bench prints the same)");
}

/// The overlay's panel: what it shows and edits, borrowed for one frame.
pub struct Panel<'a> {
    /// The chapter's constants: its title, views and keys.
    pub about: &'a About,
    pub chapter: &'a mut dyn Runnable,
    pub view: &'a mut usize,
    pub time: &'a mut f32,
    pub paused: &'a mut bool,
    pub history: &'a FrameHistory,
    pub shader_error: Option<&'a str>,
    pub show_help: &'a mut bool,
    /// Whether the shader panel is open.
    pub shaders_open: bool,
    pub status: &'a str,
    pub adapter: String,
    pub memory: MemoryUse,
    /// What each pass of the last frame drew, as the chapter counted it.
    pub drawn: &'a [PassCount],
    /// How edges are smoothed where the view does not decide it, and
    /// whether the adapter can multisample the picture's format.
    pub antialiasing: &'a mut crate::Antialiasing,
    pub can_multisample: bool,
}

impl Panel<'_> {
    /// The anti-aliasing switch: one sample a pixel or multisampling
    /// (chapter 02), and in chapters with a post chain the post-process
    /// pass, alone or after multisampling (chapter 08). Switching the
    /// samples makes the chapter again, since pipelines are built for one
    /// number of samples; switching the post pass does not.
    fn antialiasing_switch(&mut self, ui: &mut egui::Ui) {
        let view = self.about.views[*self.view];
        ui.horizontal(|ui| {
            ui.label("edges:");
            ui.add_enabled_ui(view.antialiasing.is_none(), |ui| {
                for choice in crate::Antialiasing::offered(self.about.post_antialiasing) {
                    let about = if choice.samples() == self.antialiasing.samples() {
                        "the post-process pass switches from one frame to the next"
                    } else {
                        "another number of samples makes the chapter again: its own controls return to where they start"
                    };
                    ui.radio_value(self.antialiasing, choice, choice.label()).on_hover_text(about);
                }
            });
        });
        if let Some(own) = view.antialiasing {
            ui.small(format!("this view draws as \"{}\" says, whatever the switch says", own.label()));
        } else if self.antialiasing.samples() > 1 && !self.can_multisample {
            ui.small("this adapter cannot multisample the picture's format: one sample a pixel");
        }
    }

    /// Draws the chapter's window (time, frame times, memory, view, camera,
    /// the chapter's own controls, a shader error, the status line) and,
    /// when asked for, the key help. True when the shader panel's switch
    /// was clicked.
    pub fn show(&mut self, ctx: &egui::Context) -> bool {
        let mut toggle_shaders = false;
        let about = self.about;
        egui::Window::new(about.title).default_pos([12.0, 12.0]).default_width(260.0).show(ctx, |ui| {
            // Scene time is an input like any other: type or drag it.
            ui.horizontal(|ui| {
                ui.label("time");
                ui.add(egui::DragValue::new(self.time).speed(0.05).suffix(" s").max_decimals(2));
                ui.checkbox(self.paused, "paused (P)");
            });
            let ms = self.history.mean_ms();
            ui.label(format!("{:.0} FPS  ·  {ms:.2} ms  ·  {}", 1000.0 / ms.max(1e-3), self.adapter));
            self.history.graph(ui);
            ui.small(format!("memory: {}", self.memory.describe()))
                .on_hover_text("read twice a second; it should not grow while nothing changes");
            let before = *self.view;
            egui::ComboBox::from_label("view").selected_text(about.views[*self.view].name).show_ui(ui, |ui| {
                for (i, view) in about.views.iter().enumerate() {
                    ui.selectable_value(self.view, i, view.name).on_hover_text(view.about);
                }
            });
            if *self.view != before {
                self.chapter.select_view(*self.view);
            }
            ui.small(about.views[*self.view].about);
            self.antialiasing_switch(ui);
            triangle_lines(ui, self.drawn);
            if let Some(camera) = self.chapter.camera_mut() {
                // The text `--camera` takes, so what is shown can be typed
                // or pasted back: the same place in any run of the chapter.
                let flag = format!("--camera {}", CameraPlace::of(camera));
                ui.horizontal(|ui| {
                    ui.monospace(&flag).on_hover_text(
                        "where the eye is (x, y, z in metres) and where it looks (yaw, pitch in degrees), \
                         as the --camera flag takes it",
                    );
                    if ui.small_button("copy").on_hover_text("copy this flag, to look from here again").clicked() {
                        copy(ui.ctx(), flag);
                    }
                });
                if ui.button("reset camera").on_hover_text("back to where this view starts").clicked() {
                    self.chapter.reset_camera(*self.view);
                }
            }
            let mut open = self.shaders_open;
            if ui
                .toggle_value(&mut open, "edit shaders")
                .on_hover_text("edit this chapter's WGSL beside its picture")
                .clicked()
            {
                toggle_shaders = true;
            }
            ui.separator();
            self.chapter.ui(ui);
            if let Some(error) = self.shader_error {
                ui.separator();
                ui.colored_label(
                    egui::Color32::from_rgb(255, 110, 90),
                    "Shader error — still drawing the last good version:",
                );
                ui.label(egui::RichText::new(error).monospace().size(11.0));
            }
            ui.separator();
            ui.small(format!("F1 help · F12 screenshot · Esc quit\n{}", self.status));
        });
        egui::Window::new("Keys").open(self.show_help).default_pos([300.0, 12.0]).show(ctx, |ui| {
            egui::Grid::new("keys").striped(true).show(ui, |ui| {
                for (key, what) in about.keys.iter().chain(RUNNER_KEYS) {
                    ui.monospace(*key);
                    ui.label(*what);
                    ui.end_row();
                }
            });
        });
        toggle_shaders
    }
}
