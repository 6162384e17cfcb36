//! The windowed runner: a winit event loop that draws a chapter every frame,
//! with the overlay, hot-reloaded shaders, screenshots and key help.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

use anyhow::{Context as _, anyhow};
use winit::application::ApplicationHandler;
use winit::event::{DeviceEvent, ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{KeyCode, PhysicalKey};
use winit::window::{CursorGrabMode, Window, WindowId};

use crate::args::{Args, check_size};
use crate::chapter::show_view;
use crate::overlay::{FrameHistory, Overlay};
use crate::shader::{self, ShaderWatcher};
use crate::{Chapter, Frame, Gpu, Input, PassTimer, Target};

/// Keys the runner handles for every chapter.
const RUNNER_KEYS: &[(&str, &str)] = &[
    ("F1", "show or hide this help"),
    ("F12", "save a screenshot (PNG) of the scene"),
    ("P", "pause or resume scene time"),
    ("Tab", "lock the pointer for mouse look (Esc unlocks)"),
    ("Esc", "unlock the pointer, or quit"),
];

/// Opens a window and runs chapter `C` until it is closed.
pub fn run<C: Chapter>(args: &Args) -> anyhow::Result<()> {
    let event_loop = EventLoop::new().map_err(|e| {
        anyhow!(
            "cannot open a window ({e}). With no display, render headless instead: \
             --screenshot out.png (or run under `xvfb-run -a`)"
        )
    })?;
    let mut app = App::<C> { args: args.clone(), running: None, error: None };
    event_loop.run_app(&mut app).context("the event loop failed")?;
    app.error.map_or(Ok(()), Err)
}

struct App<C: Chapter> {
    args: Args,
    running: Option<Running<C>>,
    error: Option<anyhow::Error>,
}

/// Everything that exists while the window is open.
struct Running<C: Chapter> {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    /// The surface's format without sRGB encoding, for the overlay.
    overlay_format: wgpu::TextureFormat,
    gpu: Gpu,
    chapter: C,
    overlay: Overlay,
    input: Input,
    view: usize,
    time: f32,
    paused: bool,
    last_frame: Instant,
    history: FrameHistory,
    watcher: Option<ShaderWatcher>,
    shader_error: Option<String>,
    show_help: bool,
    frames_left: Option<u32>,
    pointer_locked: bool,
    dragging: bool,
    /// Where the pointer is now, in physical pixels.
    cursor: winit::dpi::PhysicalPosition<f64>,
    /// The window is covered or minimised: nothing to draw.
    occluded: bool,
    status: String,
    /// Frames drawn, and frames skipped because the window had no area.
    drawn: u64,
    skipped: u64,
    probe: Option<PathBuf>,
}

impl<C: Chapter> ApplicationHandler for App<C> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() {
            return;
        }
        match Running::<C>::open(event_loop, &self.args) {
            Ok(running) => self.running = Some(running),
            Err(error) => {
                self.error = Some(error);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(app) = &mut self.running else { return };
        let egui_used = app.overlay.on_event(&app.window, &event);
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            // The surface follows the window's size at the start of each frame.
            WindowEvent::Resized(_) => app.window.request_redraw(),
            WindowEvent::Occluded(occluded) => app.occluded = occluded,
            WindowEvent::Focused(false) => {
                // Key-up and button-up events will go to another window.
                app.input.release_all();
                app.dragging = false;
            }
            WindowEvent::KeyboardInput { event, .. } => {
                let PhysicalKey::Code(key) = event.physical_key else { return };
                // A release always reaches the input state, whoever has the
                // keyboard now: a key held down must never stay held.
                if event.state == ElementState::Released {
                    app.input.key_up(key);
                    return;
                }
                if app.overlay.ctx.egui_wants_keyboard_input() {
                    return; // typing into a text field
                }
                match key {
                    KeyCode::Escape if app.pointer_locked => app.lock_pointer(false),
                    KeyCode::Escape => event_loop.exit(),
                    KeyCode::F1 => app.show_help = !app.show_help,
                    KeyCode::F12 => app.screenshot(),
                    KeyCode::KeyP if !event.repeat => app.paused = !app.paused,
                    KeyCode::Tab if !event.repeat => app.lock_pointer(!app.pointer_locked),
                    _ => app.input.key_down(key),
                }
            }
            WindowEvent::CursorMoved { position, .. } => app.cursor = position,
            WindowEvent::MouseInput { state, button: MouseButton::Left, .. } => {
                // Over the overlay, the press is egui's. Ask where the pointer
                // is now: at a few frames a second it has moved since egui
                // last looked.
                let scale = app.window.scale_factor();
                let point = egui::pos2((app.cursor.x / scale) as f32, (app.cursor.y / scale) as f32);
                let layer = app.overlay.ctx.layer_id_at(point);
                let on_overlay = layer.is_some_and(|layer| layer.order != egui::Order::Background);
                app.dragging = state == ElementState::Pressed && !on_overlay;
            }
            WindowEvent::MouseWheel { delta, .. } if !egui_used => {
                app.input.scroll += match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                };
            }
            WindowEvent::RedrawRequested => {
                if let Err(error) = app.frame() {
                    self.error = Some(error);
                    event_loop.exit();
                } else if app.frames_left == Some(0) {
                    event_loop.exit();
                }
            }
            _ => {}
        }
    }

    fn device_event(&mut self, _: &ActiveEventLoop, _: winit::event::DeviceId, event: DeviceEvent) {
        // Raw mouse motion keeps working when the pointer is locked.
        if let (Some(app), DeviceEvent::MouseMotion { delta }) = (&mut self.running, event)
            && (app.dragging || app.pointer_locked)
        {
            app.input.look += glam::Vec2::new(delta.0 as f32, delta.1 as f32);
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        let Some(app) = &self.running else { return };
        if app.has_area() {
            event_loop.set_control_flow(ControlFlow::Poll);
            app.window.request_redraw();
        } else {
            // Minimised or covered: look again now and then instead of
            // spinning; a resize or an expose event wakes the loop sooner.
            event_loop.set_control_flow(ControlFlow::WaitUntil(Instant::now() + Duration::from_millis(200)));
        }
    }
}

impl<C: Chapter> Running<C> {
    fn open(event_loop: &ActiveEventLoop, args: &Args) -> anyhow::Result<Self> {
        let attributes = Window::default_attributes()
            .with_title(format!("{} — From Triangle to Ocean", C::TITLE))
            .with_inner_size(winit::dpi::PhysicalSize::new(args.size.width, args.size.height));
        let window = Arc::new(event_loop.create_window(attributes).context("cannot create a window")?);
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle_from_env(Box::new(
            event_loop.owned_display_handle(),
        )));
        let surface = instance.create_surface(window.clone()).context("cannot create a surface for the window")?;
        let gpu = pollster::block_on(Gpu::open(instance, Some(&surface), C::gpu_needs()))?;
        check_size(&gpu, args.size)?;
        log::info!("adapter: {}", gpu.describe());

        let caps = surface.get_capabilities(&gpu.adapter);
        // Chapters output linear colour and let an sRGB target encode it.
        let format =
            caps.formats.iter().copied().find(|f| f.is_srgb()).or(caps.formats.first().copied()).ok_or_else(|| {
                anyhow!("{} cannot draw into this window (it offers no surface formats)", gpu.describe())
            })?;
        let overlay_format = format.remove_srgb_suffix();
        let size = window.inner_size();
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width: size.width.max(1),
            height: size.height.max(1),
            // Fifo is always there and waits for vsync; lavapipe lists
            // Immediate first, which would spin the CPU for nothing.
            present_mode: wgpu::PresentMode::Fifo,
            desired_maximum_frame_latency: 2,
            alpha_mode: wgpu::CompositeAlphaMode::Auto,
            color_space: Default::default(),
            view_formats: if overlay_format == format { vec![] } else { vec![overlay_format] },
        };
        surface.configure(&gpu.device, &config);

        let view = args.view_index::<C>();
        let target = Target { format, width: config.width, height: config.height };
        let mut chapter = crate::chapter::create::<C>(&gpu, target, &args.chapter_flags)?;
        show_view(&mut chapter, view);
        let overlay = Overlay::new(&window, &gpu, overlay_format);

        let watcher = ShaderWatcher::start();
        shader::read_from(watcher.as_ref().map(|_| PathBuf::from(shader::SHADER_DIR)));
        let status = match &watcher {
            Some(watcher) => format!("watching {} for edits", watcher.dir.display()),
            None => "shaders are built in (no source tree to watch)".into(),
        };
        Ok(Self {
            window,
            surface,
            config,
            overlay_format,
            gpu,
            chapter,
            overlay,
            input: Input::default(),
            view,
            time: args.time.unwrap_or(0.0),
            paused: false,
            last_frame: Instant::now(),
            history: FrameHistory::default(),
            watcher,
            shader_error: None,
            show_help: false,
            frames_left: args.frames,
            pointer_locked: false,
            dragging: false,
            cursor: Default::default(),
            occluded: false,
            status,
            drawn: 0,
            skipped: 0,
            probe: args.probe.clone(),
        })
    }

    fn target(&self) -> Target {
        Target { format: self.config.format, width: self.config.width, height: self.config.height }
    }

    /// Whether there is anything to draw into: a minimised window reports
    /// a size of 0×0 on some platforms and `Occluded` on others.
    fn has_area(&self) -> bool {
        let size = self.window.inner_size();
        size.width > 0 && size.height > 0 && !self.occluded && self.window.is_minimized() != Some(true)
    }

    /// Makes the surface, and the chapter's size-dependent resources, match
    /// the window as it is now.
    fn match_window_size(&mut self) {
        let size = self.window.inner_size();
        if (size.width, size.height) == (self.config.width, self.config.height) {
            return;
        }
        self.config.width = size.width;
        self.config.height = size.height;
        self.surface.configure(&self.gpu.device, &self.config);
        self.chapter.resize(&self.gpu, self.target());
    }

    fn lock_pointer(&mut self, lock: bool) {
        let grabbed = if lock {
            self.window
                .set_cursor_grab(CursorGrabMode::Locked)
                .or_else(|_| self.window.set_cursor_grab(CursorGrabMode::Confined))
                .is_ok()
        } else {
            let _ = self.window.set_cursor_grab(CursorGrabMode::None);
            false
        };
        self.pointer_locked = grabbed;
        self.window.set_cursor_visible(!grabbed);
    }

    fn reload_shaders(&mut self) {
        let Some(watcher) = &self.watcher else { return };
        let changed = watcher.changed();
        if changed.is_empty() {
            return;
        }
        match self.chapter.reload_shaders(&self.gpu) {
            Ok(()) => {
                if self.shader_error.take().is_some() {
                    eprintln!("shaders fixed: reloaded");
                }
                self.status = format!("reloaded after editing {}", changed[0].display());
            }
            Err(error) => {
                // Keep drawing with the last pipelines that worked.
                eprintln!("shader error, keeping the last good pipeline:\n{error}");
                self.shader_error = Some(error.0);
            }
        }
    }

    fn screenshot(&mut self) {
        let path = PathBuf::from(format!("{}-{}-{:.2}s.png", C::NAME, C::VIEWS[self.view].name, self.time));
        let target = self.target();
        let result = crate::headless::capture(&self.gpu, &mut self.chapter, target, self.time, self.view)
            .and_then(|image| image.save(&path).with_context(|| format!("cannot write {}", path.display())));
        self.status = match result {
            Ok(()) => format!("saved {}", path.display()),
            Err(error) => format!("screenshot failed: {error:#}"),
        };
        println!("{}", self.status);
    }

    /// Draws a frame if the window can show one, and reports to the probe.
    fn frame(&mut self) -> anyhow::Result<()> {
        if self.draw()? {
            self.drawn += 1;
            if let Some(n) = &mut self.frames_left {
                *n = n.saturating_sub(1);
            }
        } else {
            self.skipped += 1;
        }
        self.write_probe();
        Ok(())
    }

    // ANCHOR: frame
    /// Returns false when there was nothing to draw into.
    fn draw(&mut self) -> anyhow::Result<bool> {
        let now = Instant::now();
        // After a pause (minimised, dragged, a breakpoint) the first frame
        // would otherwise jump: no step is longer than a quarter second.
        let dt = (now - self.last_frame).as_secs_f32().min(0.25);
        self.last_frame = now;
        if !self.has_area() {
            return Ok(false);
        }
        // One size is the truth for the whole frame: the surface's, made to
        // match the window here, before anything is drawn into it.
        self.match_window_size();
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(frame) | wgpu::CurrentSurfaceTexture::Suboptimal(frame) => frame,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => return Ok(false),
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                // The window changed under us: configure again, draw next time.
                self.surface.configure(&self.gpu.device, &self.config);
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Validation => anyhow::bail!("the surface texture failed validation"),
        };

        self.history.push(dt);
        if !self.paused {
            self.time += dt;
        }
        self.reload_shaders();
        self.chapter.update(&self.input, dt);
        self.input.end_frame();

        let scene_view = frame.texture.create_view(&Default::default());
        let overlay_view = frame
            .texture
            .create_view(&wgpu::TextureViewDescriptor { format: Some(self.overlay_format), ..Default::default() });
        let mut encoder = self.gpu.device.create_command_encoder(&Default::default());
        let timer = PassTimer::off();
        self.chapter.render(
            &self.gpu,
            &mut Frame { encoder: &mut encoder, target: &scene_view, time: self.time, view: self.view, timer: &timer },
        );
        let size = [self.config.width, self.config.height];
        let extra = {
            let Self { overlay, window, gpu, .. } = self;
            let mut ui_state = UiState {
                chapter: &mut self.chapter,
                view: &mut self.view,
                time: &mut self.time,
                paused: &mut self.paused,
                history: &self.history,
                shader_error: self.shader_error.as_deref(),
                show_help: &mut self.show_help,
                status: &self.status,
                adapter: gpu.adapter.get_info().name,
            };
            overlay.draw(gpu, &mut encoder, &overlay_view, size, window, |ctx| ui_state.show(ctx))
        };
        self.gpu.queue.submit(extra.into_iter().chain([encoder.finish()]));
        self.window.pre_present_notify();
        self.gpu.queue.present(frame);
        Ok(true)
    }
    // ANCHOR_END: frame

    /// For tests that drive the window from outside (`--probe PATH`): one
    /// line with what they cannot see in pixels, written whole each frame.
    fn write_probe(&mut self) {
        let Some(path) = &self.probe else { return };
        let camera = match self.chapter.camera_mut() {
            Some(c) => {
                format!("{:.4} {:.4} {:.4} {:.5} {:.5}", c.position.x, c.position.y, c.position.z, c.yaw, c.pitch)
            }
            None => "none".into(),
        };
        let line = format!(
            "drawn={} skipped={} surface={}x{} view={} typing={} camera={camera}\n",
            self.drawn,
            self.skipped,
            self.config.width,
            self.config.height,
            C::VIEWS[self.view].name,
            u8::from(self.overlay.ctx.egui_wants_keyboard_input()),
        );
        let partial = path.with_extension("partial");
        if std::fs::write(&partial, line).and_then(|()| std::fs::rename(&partial, path)).is_err() {
            eprintln!("cannot write the probe file {}", path.display());
            self.probe = None;
        }
    }
}

/// What the overlay shows and edits, borrowed for one frame.
struct UiState<'a, C: Chapter> {
    chapter: &'a mut C,
    view: &'a mut usize,
    time: &'a mut f32,
    paused: &'a mut bool,
    history: &'a FrameHistory,
    shader_error: Option<&'a str>,
    show_help: &'a mut bool,
    status: &'a str,
    adapter: String,
}

impl<C: Chapter> UiState<'_, C> {
    fn show(&mut self, ctx: &egui::Context) {
        egui::Window::new(C::TITLE).default_pos([12.0, 12.0]).default_width(260.0).show(ctx, |ui| {
            // Scene time is an input like any other: type or drag it.
            ui.horizontal(|ui| {
                ui.label("time");
                ui.add(egui::DragValue::new(self.time).speed(0.05).suffix(" s").max_decimals(2));
                ui.checkbox(self.paused, "paused (P)");
            });
            let ms = self.history.mean_ms();
            ui.label(format!("{:.0} FPS  ·  {ms:.2} ms  ·  {}", 1000.0 / ms.max(1e-3), self.adapter));
            self.history.graph(ui);
            let before = *self.view;
            egui::ComboBox::from_label("view").selected_text(C::VIEWS[*self.view].name).show_ui(ui, |ui| {
                for (i, view) in C::VIEWS.iter().enumerate() {
                    ui.selectable_value(self.view, i, view.name).on_hover_text(view.about);
                }
            });
            if *self.view != before {
                show_view(self.chapter, *self.view);
            }
            ui.small(C::VIEWS[*self.view].about);
            if let Some(c) = self.chapter.camera_mut() {
                ui.horizontal(|ui| {
                    ui.monospace(format!(
                        "eye {:.1} {:.1} {:.1}  yaw {:.0}° pitch {:.0}°",
                        c.position.x,
                        c.position.y,
                        c.position.z,
                        c.yaw.to_degrees(),
                        c.pitch.to_degrees()
                    ));
                });
                if ui.button("reset camera").on_hover_text("back to where this view starts").clicked() {
                    self.chapter.reset_camera(*self.view);
                }
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
                for (key, what) in C::KEYS.iter().chain(RUNNER_KEYS) {
                    ui.monospace(*key);
                    ui.label(*what);
                    ui.end_row();
                }
            });
        });
    }
}
