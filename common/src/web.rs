//! The page a chapter runs in, as the runners see it: the `data-`
//! attributes that tell a test (or a curious reader) what the chapter is
//! doing, errors and panics shown in the page, the canvas, what the URL
//! chose (the backends, a notice), and long preparation run a step at a
//! time between paints. The entry that reads the URL and starts a runner
//! is `browser.rs`; this module is below both runners.

use std::cell::RefCell;

use anyhow::{Context as _, anyhow};
use wasm_bindgen::JsCast as _;

use crate::Gpu;
use crate::preparation::Step;

const WEBGL_ADVICE: &str = "\n\nThis browser offers no WebGPU, and this chapter needs more than WebGL2 \
     gives (the book's page on running in the browser says what). Open it in a browser with WebGPU: \
     Chrome or Edge 113 or later, Safari 26 or later, Firefox 141 or later on Windows.";

thread_local! {
    static BACKENDS: RefCell<wgpu::Backends> = const { RefCell::new(wgpu::Backends::BROWSER_WEBGPU.union(wgpu::Backends::GL)) };
    static NOTICE: RefCell<Option<String>> = const { RefCell::new(None) };
    /// The page fell back to WebGL2: a panic then says what to use instead.
    static ON_WEBGL: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

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
    set_notice(notice);
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

/// Makes a panic show in the page (and on the console), with what to use
/// instead when the page fell back to WebGL2.
pub(crate) fn show_panics() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        let advice = if ON_WEBGL.get() { WEBGL_ADVICE } else { "" };
        show_error(&format!("the chapter panicked: {info}{advice}"));
    }));
}

/// Narrows the backends the page may use to the URL's `backend=` value.
pub(crate) fn set_backends(value: &str) -> Result<(), String> {
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

/// Sets the note for the overlay's status line and the page's
/// `data-notice`.
pub(crate) fn set_notice(notice: String) {
    set_state("notice", &notice);
    NOTICE.with(|n| *n.borrow_mut() = Some(notice));
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
/// Runs a chapter's preparation ([`crate::Chapter::prepare`]) a step at a time
/// and returns what it made. Between steps the page gets its thread back:
/// it paints the progress message, and handles input, resizes and the
/// test's questions. `data-progress` says how far it got.
pub async fn prepare<T: 'static>(gpu: &Gpu, mut preparation: crate::Preparation<T>) -> T {
    let message = web_sys::window().and_then(|w| w.document()).and_then(|d| d.get_element_by_id("message"));
    for steps in 0.. {
        let done = match preparation.step(gpu) {
            Step::Progress(done) => done,
            // Nothing was to be done.
            Step::Done(prepared) if steps == 0 => return prepared,
            Step::Done(prepared) => {
                set_state("progress", "1.000");
                // Making the chapter is a task of its own.
                next_task().await;
                return prepared;
            }
        };
        set_state("progress", &format!("{done:.3}"));
        if let Some(message) = &message {
            message.set_text_content(Some(&format!("{}… {:.0} %", preparation.what, 100.0 * done.min(1.0))));
        }
        next_task().await;
    }
    unreachable!("a preparation ends")
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

// ANCHOR: stored_edits
/// The prefix of the page's storage keys that hold a chapter's shader
/// edits, one key per file: `shader-edit:CHAPTER:PATH`. The page's script
/// (`xtask/src/web.rs`) writes a shared link's edits there before the
/// program starts, and reads them to make a link.
fn edit_key_prefix(chapter: &str) -> String {
    format!("shader-edit:{chapter}:")
}

/// The reader's edits to `chapter`'s shaders kept by the page, by path.
pub fn stored_edits(chapter: &str) -> Vec<(String, String)> {
    let Some(storage) = web_sys::window().and_then(|w| w.local_storage().ok().flatten()) else { return Vec::new() };
    let prefix = edit_key_prefix(chapter);
    let mut edits = Vec::new();
    for i in 0..storage.length().unwrap_or(0) {
        let Some(key) = storage.key(i).ok().flatten() else { continue };
        if let (Some(path), Some(text)) = (key.strip_prefix(&prefix), storage.get_item(&key).ok().flatten()) {
            edits.push((path.to_string(), text));
        }
    }
    edits.sort();
    set_edited(&edits);
    edits
}

/// Keeps `edits` as the reader's edits to `chapter`'s shaders, in place of
/// the ones kept before: they survive a reload of the page.
pub fn store_edits(chapter: &str, edits: &[(String, String)]) {
    if let Some(storage) = web_sys::window().and_then(|w| w.local_storage().ok().flatten()) {
        let prefix = edit_key_prefix(chapter);
        let old: Vec<String> = (0..storage.length().unwrap_or(0))
            .filter_map(|i| storage.key(i).ok().flatten())
            .filter(|key| key.starts_with(&prefix))
            .collect();
        for key in old {
            let _ = storage.remove_item(&key);
        }
        for (path, text) in edits {
            let _ = storage.set_item(&format!("{prefix}{path}"), text);
        }
    }
    set_edited(edits);
}
// ANCHOR_END: stored_edits

/// `data-edited`: the files the page runs edited, which its banner names.
fn set_edited(edits: &[(String, String)]) {
    let paths: Vec<&str> = edits.iter().map(|(path, _)| path.as_str()).collect();
    set_state("edited", &paths.join(" "));
}

/// Asks the page's script to put the stored edits into the URL and copy it.
pub fn share_edits() {
    let Some(window) = web_sys::window() else { return };
    let share = js_sys::Reflect::get(&window, &"shareShaderEdits".into()).ok();
    match share.and_then(|f| f.dyn_into::<js_sys::Function>().ok()) {
        Some(share) => drop(share.call0(&window)),
        None => log::warn!("this page has no shareShaderEdits(): a page built by `cargo xtask book` has"),
    }
}

/// What the shader panel shows, for tests that read the page:
/// `data-shader-error` (empty when the last build worked),
/// `data-shader-error-line` and `data-edit-to-frame-ms`.
pub fn show_editor_state(editor: &crate::editor::ShaderEditor) {
    let error = editor.error();
    let state = |key: &str, value: String| set_state(key, &value);
    state("shaderError", error.map_or_else(String::new, |e| e.message.clone()));
    state("shaderErrorLine", error.and_then(|e| e.line).map_or_else(String::new, |line| line.to_string()));
    state("shaderFile", editor.selected().unwrap_or_default().to_string());
    state("editsBuilt", editor.builds.to_string());
    if let Some(took) = editor.last_edit_to_frame {
        state("editToFrameMs", format!("{:.1}", took.as_secs_f64() * 1000.0));
    }
}

/// Puts `text` on the browser's clipboard (`navigator.clipboard.writeText`),
/// where the page may: a browser without it, or one that refuses (no
/// secure context, no recent click), leaves the clipboard as it was and
/// says so on the console, never more.
pub fn copy_text(text: &str) {
    let Some(window) = web_sys::window() else { return };
    let get = |target: &wasm_bindgen::JsValue, key: &str| js_sys::Reflect::get(target, &key.into()).ok();
    let clipboard = get(&window, "navigator").and_then(|n| get(&n, "clipboard")).filter(|c| !c.is_undefined());
    let Some(clipboard) = clipboard else {
        log::warn!("this browser gives the page no clipboard: copy the text from the overlay");
        return;
    };
    let write = get(&clipboard, "writeText").and_then(|f| f.dyn_into::<js_sys::Function>().ok());
    let written = write.and_then(|write| write.call1(&clipboard, &text.into()).ok());
    if let Some(promise) = written.and_then(|p| p.dyn_into::<js_sys::Promise>().ok()) {
        wasm_bindgen_futures::spawn_local(async move {
            if wasm_bindgen_futures::JsFuture::from(promise).await.is_err() {
                log::warn!("the browser refused to copy to the clipboard: copy the text from the overlay");
            }
        });
    }
}
