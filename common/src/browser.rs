//! The browser's entry point: what `common::run` does in a page, as
//! `cli.rs` does it on the desktop. URL parameters stand in for flags, the
//! console for the terminal.
//!
//! `?view=NAME` opens the live chapter in that view. `?view=NAME&time=T`
//! draws one still picture instead, through the same steps as
//! `--screenshot` (a new chapter at the canvas size, the view, one frame at
//! scene time T), with no overlay: the browser test compares it with the
//! snapshot. `size=WxH` sets that picture's size, `backend=webgl2` skips
//! WebGPU. `edit=FILE` opens the shader panel on FILE, with the cursor at
//! the first occurrence of `at=TEXT` if given. `camera=X,Y,Z,YAW,PITCH`
//! looks from there, as `--camera` does.

use std::cell::RefCell;
use std::process::ExitCode;

use anyhow::Context as _;
use wasm_bindgen::JsCast as _;

use crate::args::{Args, check_size};
use crate::chapter::About;
use crate::web::{self, canvas, note_backend, prepare, set_state, show_error};
use crate::{Gpu, PassTimer, Target};

/// The URL parameters a chapter page understands.
const PARAMETERS: &[&str] = &["view", "time", "size", "camera", "antialiasing", "backend", "edit", "at"];

thread_local! {
    /// What a still picture keeps alive so that the canvas keeps showing it.
    static KEPT: RefCell<Vec<Box<dyn std::any::Any>>> = const { RefCell::new(Vec::new()) };
}

/// Runs the chapter `about` tells of in the page: what `common::run` does
/// in a browser.
pub fn run(about: About) -> ExitCode {
    web::show_panics();
    let _ = console_log::init_with_level(log::Level::Warn);
    set_state("status", "starting");
    let (args, picture) = match page_args(&about) {
        Ok(parsed) => parsed,
        Err(message) => {
            show_error(&message);
            return ExitCode::SUCCESS;
        }
    };
    if picture {
        wasm_bindgen_futures::spawn_local(async move {
            match still_picture(&about, &args).await {
                Ok(()) => set_state("status", "picture"),
                Err(error) => show_error(&format!("{error:#}")),
            }
        });
    } else if let Err(error) = crate::window::spawn(about, &args) {
        show_error(&format!("{error:#}"));
    }
    // The page has no exit code: errors are shown in it.
    ExitCode::SUCCESS
}

// ANCHOR: page_args
/// Reads the page's URL into the flags a chapter binary takes, so that a
/// bad value gets the same message as a bad flag. True when a `time` was
/// given: then the page shows a still picture.
fn page_args(about: &About) -> Result<(Args, bool), String> {
    let search = web_sys::window().and_then(|w| w.location().search().ok()).unwrap_or_default();
    let params =
        web_sys::UrlSearchParams::new_with_str(&search).map_err(|_| format!("cannot read the URL {search}"))?;
    let mut flags = vec![about.name.to_string()];
    let mut unknown = Vec::new();
    let mut picture = false;
    let mut at = None;
    let entries = js_sys::try_iter(params.as_ref()).ok().flatten().into_iter().flatten();
    for entry in entries.flatten() {
        let pair: js_sys::Array = entry.unchecked_into();
        let (name, value) = (pair.get(0).as_string().unwrap_or_default(), pair.get(1).as_string().unwrap_or_default());
        match name.as_str() {
            "backend" => web::set_backends(&value)?,
            // For the browser test: a panic's message must reach the page.
            "panic" => panic!("a panic on purpose: the URL asked for one with panic={value}"),
            "at" => at = Some(value),
            "view" | "time" | "size" | "camera" | "antialiasing" | "edit" => {
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
        web::set_notice(notice);
    }
    let args = Args::parse_from_of(about, &flags).map_err(|error| {
        let text = error.to_string();
        let text = text.lines().filter(|l| !l.contains("--help")).collect::<Vec<_>>().join("\n");
        format!("bad URL parameter in {search}: {}", text.trim().trim_start_matches("error: ").replace("'--", "'"))
    })?;
    let args = Args { edit_at: at, ..args };
    Ok((args, picture))
}
// ANCHOR_END: page_args

// ANCHOR: still
/// What `--screenshot` does, into the canvas: the chapter made at the
/// picture's size, switched to the view, one frame at the given time.
async fn still_picture(about: &About, args: &Args) -> anyhow::Result<()> {
    let canvas = canvas()?;
    let (width, height) = (args.size.width, args.size.height);
    canvas.set_width(width);
    canvas.set_height(height);
    // One canvas pixel per screen pixel, whatever the display's density.
    let ratio = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
    let style = canvas.style();
    let _ = style.set_property("width", &format!("{}px", f64::from(width) / ratio));
    let _ = style.set_property("height", &format!("{}px", f64::from(height) / ratio));

    let desc = wgpu::InstanceDescriptor {
        backends: web::backends(),
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    };
    let instance = crate::gpu::window_instance(desc).await;
    let surface =
        instance.create_surface(wgpu::SurfaceTarget::Canvas(canvas)).context("cannot draw into the canvas")?;
    let gpu = Gpu::open(instance, Some(&surface), (about.gpu_needs)()).await?;
    note_backend(&gpu);
    check_size(&gpu, args.size)?;
    let prepared = prepare(&gpu, (about.prepare)(&gpu)).await;
    let (config, scene_format, _) = crate::surface::surface_config(&gpu, &surface, width, height)?;
    surface.configure(&gpu.device, &config);

    let view = args.view_index_in(about.views);
    let time = args.time.unwrap_or(about.snapshot_time);
    let samples = about.views[view].samples(args.antialiasing);
    let target = Target { format: scene_format, width, height, samples };
    let mut chapter = about.create_prepared(&gpu, target, prepared, &args.chapter_flags)?;
    crate::chapter::start(chapter.as_mut(), view, args.camera)?;
    let frame = match surface.get_current_texture() {
        wgpu::CurrentSurfaceTexture::Success(frame) | wgpu::CurrentSurfaceTexture::Suboptimal(frame) => frame,
        other => anyhow::bail!("the canvas gave no texture to draw into ({other:?})"),
    };
    let frame_view =
        frame.texture.create_view(&wgpu::TextureViewDescriptor { format: Some(scene_format), ..Default::default() });
    crate::headless::draw_frame(
        &gpu,
        chapter.as_mut(),
        &frame_view,
        (time, view),
        args.antialiasing,
        &PassTimer::off(),
    );
    gpu.queue.present(frame);
    log::info!("{} {} at {time} s on {}", about.name, about.views[view].name, gpu.describe());
    set_state("adapter", &gpu.describe());
    // Dropping the device could blank the canvas: the page keeps them.
    KEPT.with(|kept| {
        kept.borrow_mut().extend([Box::new(gpu) as Box<dyn std::any::Any>, Box::new(surface), Box::new(chapter)])
    });
    Ok(())
}
// ANCHOR_END: still
