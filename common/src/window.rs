//! The windowed runner: a winit event loop that draws a chapter every frame,
//! with the overlay, hot-reloaded shaders, screenshots and key help. The
//! same runner drives a chapter in a browser tab, where the window is a
//! canvas, the device arrives asynchronously and there is no source tree to
//! watch; the few differences are marked `target_arch = "wasm32"`.
//!
//! What the overlay's panel shows is `overlay.rs`'s, how the surface is set
//! up `surface.rs`'s, and the line for tests `probe.rs`'s: this module is
//! the event loop and the frame.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use web_time::{Duration, Instant};

use anyhow::{Context as _, anyhow};
use winit::application::ApplicationHandler;
use winit::event::{DeviceEvent, ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop, EventLoopProxy};
use winit::keyboard::{KeyCode, PhysicalKey};
use winit::window::{CursorGrabMode, Window, WindowId};

use crate::args::{Args, check_size};
use crate::chapter::{About, Runnable};
use crate::editor::{Request, ShaderEditor};
use crate::memory::MemoryUse;
use crate::overlay::{FrameHistory, Overlay, Panel};
use crate::probe::{self, Probe};
use crate::shader;
use crate::surface::surface_config;
use crate::{DrawCounts, Frame, Gpu, Input, PassCount, PassTimer, Target};

/// Opens a window and runs the chapter `about` tells of until it is closed.
#[cfg(not(target_arch = "wasm32"))]
pub fn run(about: About, args: &Args) -> anyhow::Result<()> {
    let event_loop = EventLoop::with_user_event().build().map_err(|e| {
        anyhow!(
            "cannot open a window ({e}). With no display, render headless instead: \
             --screenshot out.png (or run under `xvfb-run -a`)"
        )
    })?;
    let mut app = App::new(about, args, &event_loop);
    event_loop.run_app(&mut app).context("the event loop failed")?;
    app.error.map_or(Ok(()), Err)
}

/// Runs the chapter `about` tells of in the page's canvas. This returns at
/// once: the browser owns the event loop and calls back into it every frame.
#[cfg(target_arch = "wasm32")]
pub fn spawn(about: About, args: &Args) -> anyhow::Result<()> {
    use winit::platform::web::EventLoopExtWebSys as _;
    let event_loop = EventLoop::with_user_event().build().map_err(|e| anyhow!("cannot start the event loop: {e}"))?;
    let app = App::new(about, args, &event_loop);
    event_loop.spawn_app(app);
    Ok(())
}

struct App {
    about: About,
    args: Args,
    running: Option<Running>,
    error: Option<anyhow::Error>,
    /// Delivers the opened window once its device exists (at once on the
    /// desktop, a few promises later in the browser).
    proxy: EventLoopProxy<Opened>,
    opening: bool,
}

/// The window, its surface and device, ready or failed.
struct Opened(anyhow::Result<Running>);

impl App {
    fn new(about: About, args: &Args, event_loop: &EventLoop<Opened>) -> Self {
        Self { about, args: args.clone(), running: None, error: None, proxy: event_loop.create_proxy(), opening: false }
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: anyhow::Error) {
        // In a browser there is no terminal to exit to: the page says it.
        #[cfg(target_arch = "wasm32")]
        crate::web::show_error(&format!("{error:#}"));
        self.error = Some(error);
        event_loop.exit();
    }
}

/// Everything that exists while the window is open.
struct Running {
    /// The chapter's constants, and how to make it again.
    about: About,
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    /// The format the chapter draws in: the surface's, seen as sRGB.
    scene_format: wgpu::TextureFormat,
    /// How the scene's edges are smoothed (`--antialiasing`, and the
    /// overlay's switch), where the view does not decide it.
    antialiasing: crate::Antialiasing,
    /// The samples a pixel the chapter's pipelines were made for.
    chapter_samples: u32,
    /// Whether the adapter can multisample the scene's format (asked once).
    can_multisample: bool,
    /// The chapter's own flags, to make it again with.
    chapter_flags: crate::chapter::FlagValues,
    /// The surface's format without sRGB encoding, for the overlay.
    overlay_format: wgpu::TextureFormat,
    gpu: Gpu,
    chapter: Box<dyn Runnable>,
    overlay: Overlay,
    input: Input,
    view: usize,
    time: f32,
    paused: bool,
    last_frame: Instant,
    history: FrameHistory,
    watcher: Option<shader::ShaderWatcher>,
    /// The last reload's error, and the files it was reloading: they are
    /// reloaded again with the next edit, so the error clears only once
    /// every one of them builds.
    shader_error: Option<(String, Vec<String>)>,
    show_help: bool,
    /// F2 hides the overlay (its windows keep their state).
    overlay_hidden: bool,
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
    /// What each pass of the last frame drew, for the overlay.
    last_counts: Vec<PassCount>,
    probe: Probe,
    /// Whether the GPU has finished the last frame submitted (browser only).
    last_frame_done: Arc<AtomicBool>,
    /// What the overlay shows of memory, and when it was last read.
    memory: MemoryUse,
    memory_read: Option<Instant>,
    /// The shader panel, and the file it opens on.
    editor: ShaderEditor,
    main_shader: Option<&'static str>,
    /// Files the panel saved, with the text saved: when the watcher then
    /// reports them, they already agree, and nothing reloads twice.
    saved: Vec<(String, String)>,
    /// The panel's revision the page last reported (browser): its edits
    /// are stored and its state shown only when that changes.
    reported: Option<u64>,
}

impl ApplicationHandler<Opened> for App {
    // ANCHOR: resumed
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() || self.opening {
            return;
        }
        let opening = match Opening::start(self.about, event_loop, &self.args) {
            Ok(opening) => opening,
            Err(error) => return self.fail(event_loop, error),
        };
        // A page's motion events count only while the document has focus,
        // which an embedded frame or a test browser may never get.
        #[cfg(target_arch = "wasm32")]
        event_loop.listen_device_events(winit::event_loop::DeviceEvents::Always);
        self.opening = true;
        let proxy = self.proxy.clone();
        let open = async move {
            // Only fails once the loop has ended, when nobody waits for it.
            let _ = proxy.send_event(Opened(opening.finish().await));
        };
        #[cfg(not(target_arch = "wasm32"))]
        pollster::block_on(open);
        #[cfg(target_arch = "wasm32")]
        wasm_bindgen_futures::spawn_local(open);
    }
    // ANCHOR_END: resumed

    fn user_event(&mut self, event_loop: &ActiveEventLoop, Opened(result): Opened) {
        self.opening = false;
        match result {
            Ok(running) => {
                running.window.request_redraw();
                self.running = Some(running);
            }
            Err(error) => self.fail(event_loop, error),
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
                // Not text: works while typing into the shader panel.
                if key == KeyCode::F2 {
                    app.overlay_hidden = !app.overlay_hidden;
                    return;
                }
                if app.overlay.ctx.egui_wants_keyboard_input() {
                    return; // typing into a text field
                }
                match key {
                    KeyCode::Escape if app.pointer_locked => app.lock_pointer(false),
                    // A page is closed by its tab, not by a key.
                    KeyCode::Escape if cfg!(target_arch = "wasm32") => {}
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
                    self.fail(event_loop, error);
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

/// A window whose device is still being asked for.
struct Opening {
    about: About,
    window: Arc<Window>,
    instance: wgpu::InstanceDescriptor,
    args: Args,
}

impl Opening {
    /// Creates the window: on the desktop at `--size`; in a browser it is
    /// the page's canvas, as large as the page lays it out.
    fn start(about: About, event_loop: &ActiveEventLoop, args: &Args) -> anyhow::Result<Self> {
        let attributes = Window::default_attributes().with_title(format!("{} — From Triangle to Ocean", about.title));
        #[cfg(not(target_arch = "wasm32"))]
        let attributes = attributes.with_inner_size(winit::dpi::PhysicalSize::new(args.size.width, args.size.height));
        #[cfg(target_arch = "wasm32")]
        let attributes = {
            use winit::platform::web::WindowAttributesExtWebSys as _;
            attributes.with_canvas(Some(crate::web::canvas()?))
        };
        let window = Arc::new(event_loop.create_window(attributes).context("cannot create a window")?);
        let instance =
            wgpu::InstanceDescriptor::new_with_display_handle_from_env(Box::new(event_loop.owned_display_handle()));
        // In a browser the page's URL may narrow the backends (`?backend=`).
        #[cfg(target_arch = "wasm32")]
        let instance = wgpu::InstanceDescriptor { backends: crate::web::backends(), ..instance };
        Ok(Self { about, window, instance, args: args.clone() })
    }

    /// Asks for a device that can draw into the window, then builds the
    /// chapter and the overlay for it.
    async fn finish(self) -> anyhow::Result<Running> {
        let Self { about, window, instance, args } = self;
        let instance = crate::gpu::window_instance(instance).await;
        let surface = instance.create_surface(window.clone());
        // In a browser, a canvas no backend can draw into means no WebGPU and no WebGL2.
        #[cfg(target_arch = "wasm32")]
        let surface = surface.map_err(|e| crate::NoAdapter::none(e.to_string()))?;
        #[cfg(not(target_arch = "wasm32"))]
        let surface = surface.context("cannot create a surface for the window")?;
        let gpu = Gpu::open(instance, Some(&surface), (about.gpu_needs)()).await?;
        #[cfg(target_arch = "wasm32")]
        crate::web::note_backend(&gpu);
        check_size(&gpu, args.size)?;
        log::info!("adapter: {}", gpu.describe());
        // Long work in steps, so that the page shows progress; the desktop
        // does it in one go.
        #[cfg(target_arch = "wasm32")]
        let prepared = crate::web::prepare(&gpu, (about.prepare)(&gpu)).await;
        #[cfg(not(target_arch = "wasm32"))]
        let prepared = (about.prepare)(&gpu).finish(&gpu);

        let size = window.inner_size();
        let (config, scene_format, overlay_format) = surface_config(&gpu, &surface, size.width, size.height)?;
        surface.configure(&gpu.device, &config);

        let view = args.view_index_in(about.views);
        let target = Target {
            format: scene_format,
            width: config.width,
            height: config.height,
            samples: about.views[view].samples(args.antialiasing),
        };
        // Shaders are read from the source tree from the start, so that an
        // edit saved before this run is what the first frame shows.
        let watcher = shader::ShaderWatcher::start();
        gpu.read_shaders_from(watcher.as_ref().map(|_| PathBuf::from(shader::SHADER_DIR)));
        // A page starts with the reader's stored edits, or a shared link's.
        #[cfg(target_arch = "wasm32")]
        gpu.start_with_shader_edits(crate::web::stored_edits(about.name));
        let restored = !gpu.shader_edits().is_empty();
        let mut edits_failed = None;
        let mut chapter = match about.create_prepared(&gpu, target, prepared, &args.chapter_flags) {
            Err(error) if restored => {
                // Edits that no longer build must not keep the chapter from starting.
                gpu.drop_shader_edits();
                edits_failed = Some(format!("the stored shader edits did not build, so they are set aside: {error:#}"));
                let prepared = (about.prepare)(&gpu).finish(&gpu);
                about.create_prepared(&gpu, target, prepared, &args.chapter_flags)?
            }
            made => made?,
        };
        crate::chapter::start(chapter.as_mut(), view, args.camera)?;
        let overlay = Overlay::new(&window, &gpu, overlay_format);
        let mut editor = ShaderEditor::new();
        let main_shader = crate::editor::main_file_of(&about, &gpu);
        if let Some(file) = &args.edit {
            // `--edit` alone: the chapter's main file.
            let file = if file.is_empty() { main_shader.unwrap_or_default() } else { file };
            editor
                .open_on(&gpu, file, args.edit_at.as_deref())
                .map_err(|e| crate::args::UsageError(format!("--edit {file}: {e}")))?;
        }
        let status = match &watcher {
            Some(watcher) => format!("watching {} for edits", watcher.dir.display()),
            None => "shaders are built in (no source tree to watch)".into(),
        };
        // An unknown URL parameter is worth more than the line above.
        #[cfg(target_arch = "wasm32")]
        let status = crate::web::notice().unwrap_or(status);
        let status = edits_failed.unwrap_or(status);
        Ok(Running {
            about,
            window,
            surface,
            config,
            scene_format,
            overlay_format,
            antialiasing: args.antialiasing,
            chapter_samples: target.samples,
            can_multisample: crate::multisampling::samples_for(
                &gpu.adapter,
                scene_format,
                crate::multisampling::SAMPLES,
            ) > 1,
            chapter_flags: args.chapter_flags.clone(),
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
            overlay_hidden: false,
            frames_left: args.frames,
            pointer_locked: false,
            dragging: false,
            cursor: Default::default(),
            occluded: false,
            status,
            drawn: 0,
            skipped: 0,
            last_counts: Vec::new(),
            probe: Probe::new(args.probe.clone()),
            last_frame_done: Arc::new(AtomicBool::new(true)),
            memory: MemoryUse::default(),
            memory_read: None,
            editor,
            main_shader,
            saved: Vec::new(),
            reported: None,
        })
    }
}

impl Running {
    fn target(&self) -> Target {
        Target {
            format: self.scene_format,
            width: self.config.width,
            height: self.config.height,
            samples: self.about.views[self.view].samples(self.antialiasing),
        }
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

    /// Makes the chapter again when the view or the overlay's switch asks
    /// for another number of samples a pixel than its pipelines were made
    /// for, in the same view and with the same camera. The chapter's own
    /// controls return to where they start.
    fn match_samples(&mut self) {
        let target = self.target();
        if target.samples == self.chapter_samples {
            return;
        }
        let camera = self.chapter.camera_mut().map(|camera| *camera);
        let prepared = (self.about.prepare)(&self.gpu).finish(&self.gpu);
        match self.about.create_prepared(&self.gpu, target, prepared, &self.chapter_flags) {
            Ok(mut chapter) => {
                chapter.select_view(self.view);
                if let (Some(camera), Some(placed)) = (camera, chapter.camera_mut()) {
                    *placed = camera;
                }
                self.chapter = chapter;
                self.chapter_samples = target.samples;
            }
            Err(error) => {
                self.status = format!("cannot draw with {} samples a pixel: {error:#}", target.samples);
                self.chapter_samples = target.samples;
            }
        }
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
        // Paths under `shaders/`, as `ShaderFile`s name them.
        let mut files: Vec<String> = changed
            .iter()
            .filter_map(|path| path.strip_prefix(&watcher.dir).ok())
            .map(|path| path.to_string_lossy().replace('\\', "/"))
            .collect();
        // A file the panel saved holds what is already built from it.
        crate::editor::absorb_saved(&mut self.saved, &mut files, |file| {
            std::fs::read_to_string(watcher.dir.join(file)).ok()
        });
        if files.is_empty() {
            return;
        }
        if let Some((_, failing)) = &self.shader_error {
            files.extend(failing.iter().filter(|f| !files.contains(f)).cloned().collect::<Vec<_>>());
        }
        let names: Vec<&str> = files.iter().map(String::as_str).collect();
        match self.gpu.reload_shaders(&names) {
            Ok(_) => {
                if self.shader_error.take().is_some() {
                    eprintln!("shaders fixed: reloaded");
                }
                self.status = format!("reloaded after editing {}", changed[0].display());
            }
            Err(error) => {
                // Keep drawing with the last pipelines that worked.
                eprintln!("shader error, keeping the last good pipeline:\n{error}");
                self.shader_error = Some((error.0, files));
            }
        }
    }

    fn screenshot(&mut self) {
        if cfg!(target_arch = "wasm32") {
            // Reading the picture back would block the page's only thread.
            self.status = "F12 saves screenshots on the desktop (`cargo run -p <chapter>`)".into();
            return;
        }
        let path =
            PathBuf::from(format!("{}-{}-{:.2}s.png", self.about.name, self.about.views[self.view].name, self.time));
        let target = self.target();
        let result = crate::headless::capture(
            &self.gpu,
            self.chapter.as_mut(),
            target,
            (self.time, self.view),
            self.antialiasing,
        )
        .and_then(|image| image.save(&path).with_context(|| format!("cannot write {}", path.display())));
        self.status = match result {
            Ok(()) => format!("saved {}", path.display()),
            Err(error) => format!("screenshot failed: {error:#}"),
        };
        println!("{}", self.status);
    }

    /// Draws a frame if the window can show one, and reports to the probe.
    fn frame(&mut self) -> anyhow::Result<()> {
        // A frame still in flight on the GPU: neither drawn nor skipped,
        // `about_to_wait` asks again. A canvas with no area is counted
        // skipped at once, whatever is in flight: once it collapses nothing
        // asks again until it has an area (the browser test's flake, when
        // the collapse came while a frame was in flight).
        if self.has_area() && !self.gpu_caught_up() {
            return Ok(());
        }
        if self.draw()? {
            self.drawn += 1;
            #[cfg(target_arch = "wasm32")]
            if self.drawn == 1 {
                crate::web::first_frame(&self.gpu.describe());
            }
            if let Some(n) = &mut self.frames_left {
                *n = n.saturating_sub(1);
            }
        } else {
            self.skipped += 1;
        }
        self.write_probe();
        Ok(())
    }

    /// Whether the last frame submitted has finished on the GPU. On the
    /// desktop `get_current_texture` blocks when frames pile up, so it is
    /// always true there. A browser never blocks: it queues whatever a page
    /// submits, and a frame slower than the display would put input seconds
    /// behind the picture. So the browser keeps one frame in flight.
    fn gpu_caught_up(&self) -> bool {
        if cfg!(not(target_arch = "wasm32")) {
            return true;
        }
        // WebGL2 learns of finished work (its fences) only when polled.
        let _ = self.gpu.device.poll(wgpu::PollType::Poll);
        self.last_frame_done.load(Ordering::Acquire)
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
        if self.memory_read.is_none_or(|read| now - read >= Duration::from_millis(500)) {
            (self.memory, self.memory_read) = (MemoryUse::now(&self.gpu.device), Some(now));
        }
        if !self.paused {
            self.time += dt;
        }
        self.reload_shaders();
        self.editor.update(&self.gpu);
        self.chapter.update(&self.input, dt);
        self.probe.saw(&self.input);
        self.input.end_frame();

        let scene_view = frame
            .texture
            .create_view(&wgpu::TextureViewDescriptor { format: Some(self.scene_format), ..Default::default() });
        let overlay_view = frame
            .texture
            .create_view(&wgpu::TextureViewDescriptor { format: Some(self.overlay_format), ..Default::default() });
        let mut encoder = self.gpu.device.create_command_encoder(&Default::default());
        let timer = PassTimer::off();
        let counts = DrawCounts::new();
        self.chapter.render(
            &self.gpu,
            &mut Frame {
                encoder: &mut encoder,
                target: &scene_view,
                time: self.time,
                view: self.view,
                timer: &timer,
                drawn: &counts,
                antialiasing: self.about.views[self.view].smoothing(self.antialiasing),
            },
        );
        self.last_counts = counts.take();
        let size = [self.config.width, self.config.height];
        let can_save = self.watcher.is_some();
        let can_share = cfg!(target_arch = "wasm32");
        let main_shader = self.main_shader;
        let mut request = Request::Nothing;
        let extra = {
            let Self { overlay, window, gpu, editor, .. } = self;
            let mut panel = Panel {
                about: &self.about,
                chapter: self.chapter.as_mut(),
                view: &mut self.view,
                time: &mut self.time,
                paused: &mut self.paused,
                history: &self.history,
                shader_error: self.shader_error.as_ref().map(|(error, _)| error.as_str()),
                show_help: &mut self.show_help,
                shaders_open: editor.open,
                status: &self.status,
                adapter: gpu.adapter.get_info().name,
                memory: self.memory,
                drawn: &self.last_counts,
                antialiasing: &mut self.antialiasing,
                can_multisample: self.can_multisample,
            };
            let hidden = self.overlay_hidden;
            overlay.draw(gpu, &mut encoder, &overlay_view, size, window, |ctx| {
                if hidden {
                    return;
                }
                if panel.show(ctx) {
                    editor.open = !editor.open;
                }
                request = editor.ui(ctx, gpu, main_shader, can_save, can_share);
            })
        };
        self.gpu.queue.submit(extra.into_iter().chain([encoder.finish()]));
        if cfg!(target_arch = "wasm32") {
            self.last_frame_done.store(false, Ordering::Release);
            let done = self.last_frame_done.clone();
            self.gpu.queue.on_submitted_work_done(move || done.store(true, Ordering::Release));
        }
        self.window.pre_present_notify();
        self.gpu.queue.present(frame);
        self.editor.drew();
        self.answer(request);
        self.match_samples();
        Ok(true)
    }
    // ANCHOR_END: frame

    /// Does what the shader panel asked for, and (in a page) keeps the
    /// reader's edits in the page's storage when they changed.
    fn answer(&mut self, request: Request) {
        match request {
            Request::Nothing => {}
            Request::Save { path, text } => {
                let file = PathBuf::from(shader::SHADER_DIR).join(&path);
                match std::fs::write(&file, &text) {
                    Ok(()) => {
                        // The file now holds the edit: build from the file again.
                        let _ = self.gpu.set_shader_edit(&path, None);
                        self.status = format!("saved {}", file.display());
                        self.saved.push((path, text));
                    }
                    Err(error) => self.status = format!("cannot save {}: {error}", file.display()),
                }
            }
            Request::Share => {
                #[cfg(target_arch = "wasm32")]
                crate::web::share_edits();
            }
        }
        // A page keeps the reader's edits and shows the panel's state.
        if cfg!(target_arch = "wasm32") && self.reported != Some(self.editor.revision()) {
            #[cfg(target_arch = "wasm32")]
            {
                crate::web::store_edits(self.about.name, &self.gpu.shader_edits());
                crate::web::show_editor_state(&self.editor);
            }
            self.reported = Some(self.editor.revision());
        }
    }

    /// Tells the probe how the frame went, when anyone reads it.
    fn write_probe(&mut self) {
        if !self.probe.is_read() {
            return;
        }
        let report = probe::Report {
            drawn: self.drawn,
            skipped: self.skipped,
            surface: (self.config.width, self.config.height),
            view: self.about.views[self.view].name,
            typing: self.overlay.ctx.egui_wants_keyboard_input(),
            memory: MemoryUse::now(&self.gpu.device),
            camera: self.chapter.camera_mut().map(|camera| &*camera),
        };
        self.probe.write(&report);
    }
}
