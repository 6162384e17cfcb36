//! The browser: the page a chapter runs in. URL parameters stand in for
//! flags, the console for the terminal, and the page's `data-` attributes
//! tell a test (or a curious reader) what the chapter is doing.
//!
//! `?view=NAME` opens the live chapter in that view. `?view=NAME&time=T`
//! draws one still picture instead, through the same steps as
//! `--screenshot` (a new chapter at the canvas size, the view, one frame at
//! scene time T), with no overlay: the browser test compares it with the
//! snapshot. `size=WxH` sets that picture's size, `backend=webgl2` skips
//! WebGPU.

use std::cell::RefCell;
use std::process::ExitCode;

use anyhow::{Context as _, anyhow};
use wasm_bindgen::JsCast as _;

use crate::args::{Args, check_size};
use crate::{Chapter, Gpu, PassTimer, Target};

/// The URL parameters a chapter page understands.
const PARAMETERS: &[&str] = &["view", "time", "size", "backend"];

const WEBGL_ADVICE: &str = "\n\nThis browser offers no WebGPU, and this chapter needs more than WebGL2 \
     gives (the book's page on running in the browser says what). Open it in a browser with WebGPU: \
     Chrome or Edge 113 or later, Safari 26 or later, Firefox 141 or later on Windows.";

/// Called once the device exists: on WebGL2, the overlay says so, and a
/// later failure says what to use instead.
pub fn note_backend(gpu: &Gpu) {
    if gpu.adapter.get_info().backend != wgpu::Backend::Gl {
        return;
    }
    ON_WEBGL.set(true);
    let webgl = "running on WebGL2: this browser offers no WebGPU";
    log::warn!("{webgl}");
    let notice = match notice() {
        Some(earlier) => format!("{webgl}; {earlier}"),
        None => webgl.to_string(),
    };
    set_state("notice", &notice);
    NOTICE.with(|n| *n.borrow_mut() = Some(notice));
}

/// Recorded once the live runner has drawn its first frame: the page's
/// status becomes `running`, and `data-first-frame-ms` says how long after
/// the page began loading that was.
pub fn first_frame(adapter: &str) {
    let now = web_sys::window().and_then(|w| w.performance()).map_or(f64::NAN, |p| p.now());
    set_state("firstFrameMs", &format!("{now:.0}"));
    set_state("adapter", adapter);
    set_state("status", "running");
}

thread_local! {
    static BACKENDS: RefCell<wgpu::Backends> = const { RefCell::new(wgpu::Backends::BROWSER_WEBGPU.union(wgpu::Backends::GL)) };
    static NOTICE: RefCell<Option<String>> = const { RefCell::new(None) };
    /// The page fell back to WebGL2: a panic then says what to use instead.
    static ON_WEBGL: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// What a still picture keeps alive so that the canvas keeps showing it.
    static KEPT: RefCell<Vec<Box<dyn std::any::Any>>> = const { RefCell::new(Vec::new()) };
}

/// Runs chapter `C` in the page: what `common::run` does in a browser.
pub fn run<C: Chapter>() -> ExitCode {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        let advice = if ON_WEBGL.get() { WEBGL_ADVICE } else { "" };
        show_error(&format!("the chapter panicked: {info}{advice}"));
    }));
    let _ = console_log::init_with_level(log::Level::Warn);
    set_state("status", "starting");
    let (args, picture) = match page_args::<C>() {
        Ok(parsed) => parsed,
        Err(message) => {
            show_error(&message);
            return ExitCode::SUCCESS;
        }
    };
    if picture {
        wasm_bindgen_futures::spawn_local(async move {
            match still_picture::<C>(&args).await {
                Ok(()) => set_state("status", "picture"),
                Err(error) => show_error(&format!("{error:#}")),
            }
        });
    } else if let Err(error) = crate::window::spawn::<C>(&args) {
        show_error(&format!("{error:#}"));
    }
    // The page has no exit code: errors are shown in it.
    ExitCode::SUCCESS
}

// ANCHOR: page_args
/// Reads the page's URL into the flags a chapter binary takes, so that a
/// bad value gets the same message as a bad flag. True when a `time` was
/// given: then the page shows a still picture.
fn page_args<C: Chapter>() -> Result<(Args, bool), String> {
    let search = web_sys::window().and_then(|w| w.location().search().ok()).unwrap_or_default();
    let params =
        web_sys::UrlSearchParams::new_with_str(&search).map_err(|_| format!("cannot read the URL {search}"))?;
    let mut flags = vec![C::NAME.to_string()];
    let mut unknown = Vec::new();
    let mut picture = false;
    let entries = js_sys::try_iter(params.as_ref()).ok().flatten().into_iter().flatten();
    for entry in entries.flatten() {
        let pair: js_sys::Array = entry.unchecked_into();
        let (name, value) = (pair.get(0).as_string().unwrap_or_default(), pair.get(1).as_string().unwrap_or_default());
        match name.as_str() {
            "backend" => set_backends(&value)?,
            // For the browser test: a panic's message must reach the page.
            "panic" => panic!("a panic on purpose: the URL asked for one with panic={value}"),
            "view" | "time" | "size" => {
                picture |= name == "time";
                flags.push(format!("--{name}"));
                flags.push(value);
            }
            _ => unknown.push(name),
        }
    }
    if !unknown.is_empty() {
        let notice = format!(
            "ignored unknown URL parameter{} {}; this page understands {}",
            if unknown.len() > 1 { "s" } else { "" },
            unknown.join(", "),
            PARAMETERS.join(", ")
        );
        log::warn!("{notice}");
        set_state("notice", &notice);
        NOTICE.with(|n| *n.borrow_mut() = Some(notice));
    }
    let args = Args::parse_from_for::<C>(&flags).map_err(|error| {
        let text = error.to_string();
        let text = text.lines().filter(|l| !l.contains("--help")).collect::<Vec<_>>().join("\n");
        format!("bad URL parameter in {search}: {}", text.trim().trim_start_matches("error: ").replace("'--", "'"))
    })?;
    Ok((args, picture))
}
// ANCHOR_END: page_args

fn set_backends(value: &str) -> Result<(), String> {
    let backends = match value {
        "webgpu" => wgpu::Backends::BROWSER_WEBGPU,
        "webgl2" => wgpu::Backends::GL,
        _ => return Err(format!("bad URL parameter backend={value}: the backends are webgpu and webgl2")),
    };
    BACKENDS.with(|b| *b.borrow_mut() = backends);
    Ok(())
}

/// The backends the page may use (`backend=` narrows them).
pub fn backends() -> wgpu::Backends {
    BACKENDS.with(|b| *b.borrow())
}

/// A note for the overlay's status line (an unknown URL parameter).
pub fn notice() -> Option<String> {
    NOTICE.with(|n| n.borrow().clone())
}

/// The page's `<canvas id="chapter">`, made if the page has none.
pub fn canvas() -> anyhow::Result<web_sys::HtmlCanvasElement> {
    let document = web_sys::window().and_then(|w| w.document()).context("no document to draw in")?;
    if let Some(canvas) = document.get_element_by_id("chapter") {
        return canvas.dyn_into().map_err(|_| anyhow!("#chapter is not a canvas"));
    }
    let canvas: web_sys::HtmlCanvasElement =
        document.create_element("canvas").map_err(|_| anyhow!("cannot make a canvas"))?.unchecked_into();
    canvas.set_id("chapter");
    document
        .body()
        .context("the page has no body")?
        .append_child(&canvas)
        .map_err(|_| anyhow!("cannot add a canvas"))?;
    Ok(canvas)
}

/// The chapter the page runs: its body's `data-chapter` (every chapter's
/// page loads the same program, the book's `live`).
pub fn page_chapter() -> String {
    web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.body())
        .and_then(|body| body.dataset().get("chapter"))
        .unwrap_or_default()
}

/// Sets `data-KEY` on the page's body: `status` (starting, picture, error),
/// `probe` (the live runner's state line), `error`, `notice`.
pub fn set_state(key: &str, value: &str) {
    if let Some(body) = web_sys::window().and_then(|w| w.document()).and_then(|d| d.body()) {
        let _ = body.dataset().set(key, value);
    }
}

/// Shows `message` in the page, where the picture would be, and on the console.
pub fn show_error(message: &str) {
    web_sys::console::error_1(&message.into());
    set_state("status", "error");
    set_state("error", message);
    let document = web_sys::window().and_then(|w| w.document());
    if let Some(element) = document.and_then(|d| d.get_element_by_id("message")) {
        element.set_text_content(Some(message));
        let _ = element.set_attribute("class", "error");
    }
}

// ANCHOR: prepare
/// Runs the chapter's [`Chapter::prepare`] a step at a time. Between steps
/// the page gets its thread back: it paints the progress message, and
/// handles input, resizes and the test's questions. `data-progress` says
/// how far it got.
pub async fn prepare<C: Chapter>(gpu: &Gpu) {
    let Some(mut preparation) = C::prepare(gpu) else { return };
    let message = web_sys::window().and_then(|w| w.document()).and_then(|d| d.get_element_by_id("message"));
    loop {
        let done = preparation.step(gpu);
        set_state("progress", &format!("{done:.3}"));
        if let Some(message) = &message {
            message.set_text_content(Some(&format!("{}… {:.0} %", preparation.what, 100.0 * done.min(1.0))));
        }
        // After the last step too: making the chapter is a task of its own.
        next_task().await;
        if done >= 1.0 {
            return;
        }
    }
}

/// Resolves in a later task of the page's event loop, after the browser
/// has had its chance to paint and to handle input.
async fn next_task() {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        if let Some(window) = web_sys::window() {
            let _ = window.set_timeout_with_callback(&resolve);
        }
    });
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}
// ANCHOR_END: prepare

// ANCHOR: still
/// What `--screenshot` does, into the canvas: the chapter made at the
/// picture's size, switched to the view, one frame at the given time.
async fn still_picture<C: Chapter>(args: &Args) -> anyhow::Result<()> {
    let canvas = canvas()?;
    let (width, height) = (args.size.width, args.size.height);
    canvas.set_width(width);
    canvas.set_height(height);
    // One canvas pixel per screen pixel, whatever the display's density.
    let ratio = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
    let style = canvas.style();
    let _ = style.set_property("width", &format!("{}px", f64::from(width) / ratio));
    let _ = style.set_property("height", &format!("{}px", f64::from(height) / ratio));

    let instance = crate::gpu::window_instance(wgpu::InstanceDescriptor::new_without_display_handle()).await;
    let surface =
        instance.create_surface(wgpu::SurfaceTarget::Canvas(canvas)).context("cannot draw into the canvas")?;
    let gpu = Gpu::open(instance, Some(&surface), C::gpu_needs()).await?;
    note_backend(&gpu);
    check_size(&gpu, args.size)?;
    prepare::<C>(&gpu).await;
    let (config, scene_format, _) = crate::window::surface_config(&gpu, &surface, width, height)?;
    surface.configure(&gpu.device, &config);

    let view = args.view_index::<C>();
    let time = args.time.unwrap_or(C::SNAPSHOT_TIME);
    let target = Target { format: scene_format, width, height };
    let mut chapter = crate::chapter::create::<C>(&gpu, target, &args.chapter_flags)?;
    crate::chapter::show_view(&mut chapter, view);
    let frame = match surface.get_current_texture() {
        wgpu::CurrentSurfaceTexture::Success(frame) | wgpu::CurrentSurfaceTexture::Suboptimal(frame) => frame,
        other => anyhow::bail!("the canvas gave no texture to draw into ({other:?})"),
    };
    let frame_view =
        frame.texture.create_view(&wgpu::TextureViewDescriptor { format: Some(scene_format), ..Default::default() });
    crate::headless::draw_frame(&gpu, &mut chapter, &frame_view, time, view, &PassTimer::off());
    gpu.queue.present(frame);
    log::info!("{} {} at {time} s on {}", C::NAME, C::VIEWS[view].name, gpu.describe());
    set_state("adapter", &gpu.describe());
    // Dropping the device could blank the canvas: the page keeps them.
    KEPT.with(|kept| {
        kept.borrow_mut().extend([Box::new(gpu) as Box<dyn std::any::Any>, Box::new(surface), Box::new(chapter)])
    });
    Ok(())
}
// ANCHOR_END: still
