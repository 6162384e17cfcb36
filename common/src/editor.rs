//! The shader panel: a chapter's WGSL, edited beside its picture, in the
//! window and on the book's pages alike. An edit goes where hot reload's
//! saved files go ([`Gpu::edit_shader`]): composed with its modules,
//! validated, and built into every pipeline made from the file or from a
//! file that imports it, while the last good pipelines keep drawing if it
//! fails. This module is the panel around that entry point: the file list,
//! the code editor with line numbers and colours, errors at their line,
//! revert, save (desktop) and share (browser).

use std::collections::HashMap;

use egui::text::{CCursor, CCursorRange, LayoutJob};
use egui::{Color32, FontId, TextFormat};
use web_time::{Duration, Instant};

use crate::{Gpu, ShaderError, ShaderFile};

// ANCHOR: pause_before_build
/// How long typing must pause before an edit is built (Ctrl+Enter builds
/// at once): long enough not to rebuild on every key, short enough to feel
/// live.
pub const PAUSE_BEFORE_BUILD: Duration = Duration::from_millis(400);
// ANCHOR_END: pause_before_build

/// An error, as the panel shows it: the message, and the line (1-based) in
/// the file it names, when that is the file being edited.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PanelError {
    pub message: String,
    pub line: Option<usize>,
}

/// What the panel asks of the runner after a frame of its UI.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Request {
    #[default]
    Nothing,
    /// Write this text to the file at `path` under `shaders/` (desktop).
    Save { path: String, text: String },
    /// Put the edits in the page's URL and copy it (browser).
    Share,
}

/// The panel's state: which file is open, the text being typed, what was
/// last built, and the last error.
#[derive(Default)]
pub struct ShaderEditor {
    pub open: bool,
    /// The chapter's files (its own and the modules they import), by path.
    files: Vec<ShaderFile>,
    /// The open file's path.
    selected: Option<&'static str>,
    /// Text typed per file, kept while another file is open.
    buffers: HashMap<&'static str, String>,
    /// When typing last changed the open file and it has not been built yet.
    typed_at: Option<Instant>,
    /// When the open file should be built from: Ctrl+Enter's moment.
    build_from: Option<Instant>,
    error: Option<PanelError>,
    /// A character index to put the cursor at, once the editor exists.
    cursor_to: Option<usize>,
    focus_editor: bool,
    status: String,
    /// How long the last build took, from the end of typing (or
    /// Ctrl+Enter) to the frame drawn with it: see [`ShaderEditor::drew`].
    pub last_edit_to_frame: Option<Duration>,
    /// Builds done, failed ones included.
    pub builds: u64,
    /// Counts every change to what the panel shows (a build, an error, the
    /// file opened, a new edit-to-frame figure), so that a page reports
    /// its state only when it changed.
    revision: u64,
    built_at: Option<Instant>,
}

impl ShaderEditor {
    /// A closed panel. [`ShaderEditor::open_on`] opens it.
    pub fn new() -> Self {
        Self::default()
    }

    /// Opens the panel on the file at `path` (`--edit`, `?edit=`), with
    /// the cursor at the first occurrence of `at` if given. Call once the
    /// chapter exists; an unknown file is an error that lists the known ones.
    pub fn open_on(&mut self, gpu: &Gpu, path: &str, at: Option<&str>) -> Result<(), ShaderError> {
        self.refresh_files(gpu);
        let Some(file) = self.files.iter().find(|file| file.path == path) else {
            let names: Vec<&str> = self.files.iter().map(|file| file.path).collect();
            return Err(ShaderError(format!(
                "no shader {path} in this chapter; its shaders are: {}",
                names.join(", ")
            )));
        };
        let path = file.path;
        self.select(gpu, path);
        if let Some(at) = at {
            let text = &self.buffers[path];
            self.cursor_to = text.find(at).map(|byte| text[..byte].chars().count());
        }
        self.open = true;
        self.focus_editor = true;
        Ok(())
    }

    /// See the `revision` field: equal revisions show the same state.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The file open now, if any.
    pub fn selected(&self) -> Option<&'static str> {
        self.selected
    }

    /// The text in the editor for the open file.
    pub fn text(&self) -> Option<&str> {
        self.selected.and_then(|path| self.buffers.get(path)).map(String::as_str)
    }

    /// The error shown under the editor.
    pub fn error(&self) -> Option<&PanelError> {
        self.error.as_ref()
    }

    /// Replaces the open file's text, as typing does: built after the pause.
    pub fn type_text(&mut self, text: &str) {
        if let Some(path) = self.selected {
            self.buffers.insert(path, text.to_string());
            self.typed_at = Some(Instant::now());
        }
    }

    /// Builds the open file's text at the next update (Ctrl+Enter).
    pub fn build_now(&mut self) {
        self.build_from = Some(Instant::now());
    }

    fn refresh_files(&mut self, gpu: &Gpu) {
        self.files = gpu.shader_files();
    }

    fn select(&mut self, gpu: &Gpu, path: &'static str) {
        if !self.buffers.contains_key(path) {
            let text = gpu.shader_text(path).unwrap_or_default();
            self.buffers.insert(path, text);
        }
        self.selected = Some(path);
        self.error = None;
        self.revision += 1;
    }

    fn shipped(&self, path: &str) -> Option<&'static str> {
        self.files.iter().find(|file| file.path == path).map(|file| file.embedded)
    }

    // ANCHOR: update
    /// Builds the open file once typing has paused (or at once after
    /// Ctrl+Enter). Call every frame, before the chapter draws.
    pub fn update(&mut self, gpu: &Gpu) {
        // A page's device may reject a pipeline after the build returned.
        for message in gpu.late_shader_errors() {
            let line = self.selected.and_then(|path| error_line(&message, path));
            self.status = "not built: the last good version keeps drawing".into();
            self.error = Some(PanelError { message: format!("the pipeline could not be created: {message}"), line });
            self.revision += 1;
        }
        // Typing ended a pause ago, or Ctrl+Enter was pressed: that moment
        // (the last key) starts the clock of `last_edit_to_frame`.
        let paused = self.typed_at.filter(|at| at.elapsed() >= PAUSE_BEFORE_BUILD);
        let Some(started) = self.build_from.take().or(paused) else { return };
        self.typed_at = None;
        let (Some(path), Some(text)) = (self.selected, self.text().map(str::to_string)) else { return };
        self.apply(gpu, path, &text);
        self.built_at = Some(started);
    }
    // ANCHOR_END: update

    /// Builds `text` as the file at `path`; an edit back to the file's own
    /// text is no edit.
    fn apply(&mut self, gpu: &Gpu, path: &'static str, text: &str) {
        let own = gpu.shader_root().and_then(|root| std::fs::read_to_string(root.join(path)).ok());
        let is_own = own.as_deref().unwrap_or(self.shipped(path).unwrap_or_default()) == text;
        let result = gpu.edit_shader(path, if is_own { None } else { Some(text) });
        self.builds += 1;
        self.revision += 1;
        match result {
            Ok(rebuilt) => {
                self.error = None;
                self.status = format!("built {path}: {rebuilt} pipeline set(s) rebuilt");
            }
            Err(ShaderError(message)) => {
                let line = error_line(&message, path);
                self.status = "not built: the last good version keeps drawing".into();
                self.error = Some(PanelError { message, line });
            }
        }
    }

    /// Returns the open file to the text it shipped with.
    pub fn revert(&mut self, gpu: &Gpu) {
        let Some(path) = self.selected else { return };
        let shipped = self.shipped(path).unwrap_or_default().to_string();
        self.buffers.insert(path, shipped.clone());
        self.typed_at = None;
        self.apply(gpu, path, &shipped);
        self.status = format!("{path} is back to its shipped text");
    }

    /// The runner drew a frame: the first one after a build measures the
    /// time from the end of typing to the picture.
    pub fn drew(&mut self) {
        if let Some(started) = self.built_at.take() {
            self.last_edit_to_frame = Some(started.elapsed());
            self.revision += 1;
        }
    }

    /// Whether the panel's text for `path` differs from the file it edits.
    pub fn is_edited(&self, gpu: &Gpu, path: &str) -> bool {
        gpu.shader_edits().iter().any(|(edited, _)| edited == path)
    }

    /// Draws the panel (when open) and returns what the runner should do.
    /// `can_save`: the desktop with a source tree; `can_share`: a page.
    /// The panel opens on `main` (see [`main_file`]) unless told otherwise.
    pub fn ui(
        &mut self,
        ctx: &egui::Context,
        gpu: &Gpu,
        main: Option<&'static str>,
        can_save: bool,
        can_share: bool,
    ) -> Request {
        if !self.open {
            return Request::Nothing;
        }
        if self.files.is_empty() {
            self.refresh_files(gpu);
        }
        if self.selected.is_none()
            && let Some(main) = main
        {
            self.select(gpu, main);
        }
        let mut request = Request::Nothing;
        let mut open = self.open;
        // On the right, beside the chapter's panel, leaving some picture.
        let screen = ctx.content_rect();
        let size = egui::vec2((screen.width() * 0.55).min(600.0), (screen.height() - 24.0).clamp(120.0, 440.0));
        egui::Window::new("Shaders")
            .open(&mut open)
            .default_pos([(screen.width() - size.x - 12.0).max(0.0), 12.0])
            .default_size(size)
            .show(ctx, |ui| request = self.panel(ui, gpu, can_save, can_share));
        self.open = open;
        request
    }

    fn panel(&mut self, ui: &mut egui::Ui, gpu: &Gpu, can_save: bool, can_share: bool) -> Request {
        let mut request = Request::Nothing;
        let Some(path) = self.selected else {
            ui.label("this chapter builds no pipelines from WGSL files");
            return request;
        };
        ui.horizontal(|ui| {
            let mut chosen = path;
            egui::ComboBox::from_id_salt("shader file").selected_text(path).width(260.0).show_ui(ui, |ui| {
                for file in &self.files {
                    let edited = if self.is_edited(gpu, file.path) { " (edited)" } else { "" };
                    ui.selectable_value(&mut chosen, file.path, format!("{}{edited}", file.path));
                }
            });
            if chosen != path {
                self.select(gpu, chosen);
            }
            if ui.button("build").on_hover_text("Ctrl+Enter; edits also build after a pause in typing").clicked() {
                self.build_now();
            }
            if ui.button("revert").on_hover_text("back to the text this file shipped with").clicked() {
                self.revert(gpu);
            }
            if can_save && ui.button("save").on_hover_text("write this text to shaders/").clicked() {
                request = Request::Save { path: path.to_string(), text: self.text().unwrap_or_default().to_string() };
            }
            if can_share && ui.button("share").on_hover_text("put your edits in the page's link, and copy it").clicked()
            {
                request = Request::Share;
            }
        });
        // Ctrl+Enter is the panel's, before the editor could take the Enter.
        if ui.input_mut(|i| i.consume_key(egui::Modifiers::COMMAND, egui::Key::Enter)) {
            self.build_now();
        }
        let error_line = self.error.as_ref().and_then(|error| error.line);
        let text = self.buffers.entry(path).or_default();
        let lines = text.lines().count().max(1) + usize::from(text.ends_with('\n'));
        let editor_height = (ui.available_height() - if self.error.is_some() { 110.0 } else { 24.0 }).max(80.0);
        let mut changed = false;
        // Lines never wrap (scroll sideways instead): a wrapped line would
        // put the numbers beside the wrong lines.
        egui::ScrollArea::both().id_salt(path).max_height(editor_height).show(ui, |ui| {
            ui.horizontal_top(|ui| {
                let numbers: String = (1..=lines).map(|n| format!("{n:>4}\n")).collect();
                ui.add(
                    egui::Label::new(egui::RichText::new(numbers).monospace().color(Color32::GRAY)).selectable(false),
                );
                let mut layouter = |ui: &egui::Ui, buffer: &dyn egui::TextBuffer, _wrap: f32| {
                    let mut job = highlight(buffer.as_str(), error_line);
                    job.wrap.max_width = f32::INFINITY;
                    ui.fonts_mut(|fonts| fonts.layout_job(job))
                };
                let output = egui::TextEdit::multiline(text)
                    .id_salt(("shader editor", path))
                    .code_editor()
                    .lock_focus(true)
                    .desired_width(f32::INFINITY)
                    .layouter(&mut layouter)
                    .show(ui);
                changed = output.response.response.changed();
                if self.focus_editor {
                    output.response.response.request_focus();
                    self.focus_editor = false;
                }
                if let Some(at) = self.cursor_to.take() {
                    let mut state = output.state;
                    state.cursor.set_char_range(Some(CCursorRange::one(CCursor::new(at))));
                    state.store(ui.ctx(), output.response.response.id);
                    // Bring the place into view, a few lines below the top.
                    let place = output.galley.pos_from_cursor(CCursor::new(at)).translate(output.galley_pos.to_vec2());
                    ui.scroll_to_rect(place, Some(egui::Align::Center));
                }
            });
        });
        if changed {
            self.typed_at = Some(Instant::now());
        }
        if let Some(error) = &self.error {
            let place = error.line.map_or_else(String::new, |line| format!(" (line {line})"));
            ui.colored_label(
                Color32::from_rgb(255, 110, 90),
                format!("not built{place}: the last good version keeps drawing"),
            );
            egui::ScrollArea::vertical().id_salt("shader error").max_height(80.0).show(ui, |ui| {
                ui.label(egui::RichText::new(&error.message).monospace().size(11.0));
            });
        } else {
            ui.small(&self.status);
        }
        request
    }
}

// ANCHOR: absorb_saved
/// Hot reload meets the panel's "save": of the `changed` files the watcher
/// reports, those that now hold exactly the text the panel saved (`saved`,
/// by path) are already built, so they are taken out of `changed` and out
/// of `saved`; nothing reloads twice. `read` reads a file as it is now.
pub fn absorb_saved(
    saved: &mut Vec<(String, String)>,
    changed: &mut Vec<String>,
    read: impl Fn(&str) -> Option<String>,
) {
    changed.retain(|file| {
        let now = read(file);
        match saved.iter().position(|(path, text)| path == file && Some(text) == now.as_ref()) {
            Some(i) => {
                saved.remove(i);
                false
            }
            None => true,
        }
    });
}
// ANCHOR_END: absorb_saved

/// The file chapter `C`'s panel opens on: the one it names
/// ([`crate::Chapter::MAIN_SHADER`]), else `shaders/NAME/NAME.wgsl` or
/// `shaders/NAME/scene.wgsl`, else the first of its own files that is not
/// a module, else its first file.
pub fn main_file<C: crate::Chapter>(gpu: &Gpu) -> Option<&'static str> {
    main_file_of(&crate::chapter::About::of::<C>(), gpu)
}

/// [`main_file`], whatever the chapter's type.
pub fn main_file_of(about: &crate::chapter::About, gpu: &Gpu) -> Option<&'static str> {
    let files = gpu.shader_files();
    let named = |path: &str| files.iter().find(|file| file.path == path).map(|file| file.path);
    let own = format!("{}/", about.name);
    about
        .main_shader
        .and_then(named)
        .or_else(|| named(&format!("{own}{}.wgsl", about.name)))
        .or_else(|| named(&format!("{own}scene.wgsl")))
        .or_else(|| {
            let mut own_files = files.iter().filter(|file| file.path.starts_with(&own));
            own_files.find(|file| !file.embedded.contains("#define_import_path")).map(|file| file.path)
        })
        .or(files.first().map(|file| file.path))
}

// ANCHOR: error_line
/// The line (1-based) an error names in the file at `path`: naga and
/// naga_oil print `path:LINE:COLUMN` for the file where the problem is,
/// in that file's own lines, so an error in an imported module is not
/// put on a line of the file importing it.
pub fn error_line(message: &str, path: &str) -> Option<usize> {
    let after = message.split(&format!("{path}:")).nth(1)?;
    let digits: String = after.chars().take_while(char::is_ascii_digit).collect();
    digits.parse().ok()
}
// ANCHOR_END: error_line

/// WGSL's words, for colouring: the keywords, then the built-in types.
const KEYWORDS: &[&str] = &[
    "alias",
    "break",
    "case",
    "const",
    "const_assert",
    "continue",
    "continuing",
    "default",
    "diagnostic",
    "discard",
    "else",
    "enable",
    "false",
    "fn",
    "for",
    "if",
    "let",
    "loop",
    "override",
    "requires",
    "return",
    "struct",
    "switch",
    "true",
    "var",
    "while",
];
const TYPES: &[&str] = &[
    "array",
    "atomic",
    "bool",
    "f16",
    "f32",
    "i32",
    "mat2x2",
    "mat2x3",
    "mat2x4",
    "mat3x2",
    "mat3x3",
    "mat3x4",
    "mat4x2",
    "mat4x3",
    "mat4x4",
    "ptr",
    "sampler",
    "sampler_comparison",
    "u32",
    "vec2",
    "vec3",
    "vec4",
    "vec2f",
    "vec3f",
    "vec4f",
    "vec2i",
    "vec3i",
    "vec4i",
    "vec2u",
    "vec3u",
    "vec4u",
    "mat4x4f",
    "mat3x3f",
];

/// Lays out WGSL with colours: comments, keywords, types (and textures),
/// attributes, numbers and naga_oil's `#` directives; the line `error_line`
/// (1-based) gets a red background.
pub fn highlight(text: &str, error_line: Option<usize>) -> LayoutJob {
    let font = FontId::monospace(12.0);
    let colour = |kind: Kind| match kind {
        Kind::Plain => Color32::from_gray(215),
        Kind::Comment => Color32::from_rgb(120, 140, 120),
        Kind::Keyword => Color32::from_rgb(200, 140, 230),
        Kind::Type => Color32::from_rgb(110, 190, 230),
        Kind::Attribute => Color32::from_rgb(230, 190, 100),
        Kind::Number => Color32::from_rgb(180, 220, 140),
        Kind::Directive => Color32::from_rgb(240, 150, 110),
    };
    let mut job = LayoutJob::default();
    let mut line = 1;
    for (kind, piece) in tokens(text) {
        // Split at line ends so that the error line's background is its own.
        for part in piece.split_inclusive('\n') {
            let background =
                if Some(line) == error_line { Color32::from_rgb(110, 30, 30) } else { Color32::TRANSPARENT };
            let format = TextFormat { font_id: font.clone(), color: colour(kind), background, ..Default::default() };
            job.append(part, 0.0, format);
            if part.ends_with('\n') {
                line += 1;
            }
        }
    }
    job
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Plain,
    Comment,
    Keyword,
    Type,
    Attribute,
    Number,
    Directive,
}

/// Splits WGSL into coloured pieces that together are the whole text.
fn tokens(text: &str) -> Vec<(Kind, &str)> {
    let mut pieces = Vec::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let start = i;
        let rest = &text[i..];
        let kind = if rest.starts_with("//") || (rest.starts_with('#') && (i == 0 || bytes[i - 1] == b'\n')) {
            i += rest.find('\n').unwrap_or(rest.len());
            if rest.starts_with('#') { Kind::Directive } else { Kind::Comment }
        } else if let Some(body) = rest.strip_prefix("/*") {
            i += body.find("*/").map_or(rest.len(), |end| end + 4);
            Kind::Comment
        } else if bytes[i].is_ascii_alphabetic() || bytes[i] == b'_' || bytes[i] == b'@' {
            i += 1;
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            let word = &text[start..i];
            if word.starts_with('@') {
                Kind::Attribute
            } else if KEYWORDS.contains(&word) {
                Kind::Keyword
            } else if TYPES.contains(&word) || word.starts_with("texture_") {
                Kind::Type
            } else {
                Kind::Plain
            }
        } else if bytes[i].is_ascii_digit() {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'.') {
                i += 1;
            }
            Kind::Number
        } else {
            // Anything else up to the next character that may start a token.
            i += rest.chars().next().map_or(1, char::len_utf8);
            while i < bytes.len() && !(bytes[i].is_ascii_alphanumeric() || b"_@/#".contains(&bytes[i])) {
                i += text[i..].chars().next().map_or(1, char::len_utf8);
            }
            Kind::Plain
        };
        pieces.push((kind, &text[start..i]));
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_error_line_is_read_for_the_file_named() {
        let message = "error: expected ';'\n  ┌─ triangle/triangle.wgsl:17:5\n   │\n17 │     let x = 1\n";
        assert_eq!(error_line(message, "triangle/triangle.wgsl"), Some(17));
        // An error in another file puts no mark in this one.
        assert_eq!(error_line(message, "common/fullscreen.wgsl"), None);
    }

    #[test]
    fn tokens_cover_the_text_and_colour_what_they_should() {
        let wgsl =
            "#import common::x\n// light\n@fragment fn fs(v: vec3<f32>) -> f32 { return 1.5e0 * v.x; }\n/* a\nb */";
        let pieces = tokens(wgsl);
        assert_eq!(pieces.iter().map(|(_, p)| *p).collect::<String>(), wgsl);
        let kind_of = |word: &str| pieces.iter().find(|(_, p)| *p == word).map(|(k, _)| *k);
        assert_eq!(kind_of("#import common::x"), Some(Kind::Directive));
        assert_eq!(kind_of("// light"), Some(Kind::Comment));
        assert_eq!(kind_of("@fragment"), Some(Kind::Attribute));
        assert_eq!(kind_of("fn"), Some(Kind::Keyword));
        assert_eq!(kind_of("vec3"), Some(Kind::Type));
        assert_eq!(kind_of("1.5e0"), Some(Kind::Number));
        assert_eq!(kind_of("/* a\nb */"), Some(Kind::Comment));
    }

    #[test]
    fn a_saved_file_reloads_once_and_a_later_edit_on_disk_reloads() {
        let disk = std::cell::RefCell::new(String::from("saved text"));
        let read = |_: &str| Some(disk.borrow().clone());
        let mut saved = vec![("a/b.wgsl".to_string(), "saved text".to_string())];
        // The watcher reports the save: already built, nothing to reload.
        let mut changed = vec!["a/b.wgsl".to_string(), "a/c.wgsl".to_string()];
        absorb_saved(&mut saved, &mut changed, read);
        assert_eq!(changed, ["a/c.wgsl"], "the saved file is not rebuilt; another changed one is");
        assert!(saved.is_empty(), "a save is absorbed once");
        // Someone edits the file in their editor afterwards: that reloads.
        *disk.borrow_mut() = "their text".into();
        let mut changed = vec!["a/b.wgsl".to_string()];
        absorb_saved(&mut saved, &mut changed, read);
        assert_eq!(changed, ["a/b.wgsl"]);
        // A save the file no longer holds (changed again before the watcher spoke) reloads too.
        let mut saved = vec![("a/b.wgsl".to_string(), "saved text".to_string())];
        absorb_saved(&mut saved, &mut changed, read);
        assert_eq!(changed, ["a/b.wgsl"]);
    }

    #[test]
    fn only_the_error_line_is_marked() {
        let job = highlight("fn a() {}\n// two\nlet b = 2;\n", Some(2));
        let marked: String = job
            .sections
            .iter()
            .filter(|s| s.format.background != Color32::TRANSPARENT)
            .map(|s| &job.text[s.byte_range.start.0..s.byte_range.end.0])
            .collect();
        assert_eq!(marked, "// two\n");
    }
}
