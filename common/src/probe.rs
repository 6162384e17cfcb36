//! The probe: for tests that drive a window from outside (`--probe PATH`,
//! and the browser test through the page), one line with what they cannot
//! see in pixels, written whole each frame: frames drawn and skipped, the
//! surface's size, the view, whether egui has the keyboard, the input the
//! chapter was given, memory and the camera.

use std::path::PathBuf;

use crate::memory::MemoryUse;
use crate::{Camera, Input};

/// Where the probe line goes, and what it adds up from frame to frame.
pub struct Probe {
    path: Option<PathBuf>,
    /// The most keys the chapter saw held at once.
    held_seen: usize,
    /// How far (in pixels) the mouse has turned the view in all.
    looked: f32,
}

/// What the runner reports after a frame.
pub struct Report<'a> {
    pub drawn: u64,
    pub skipped: u64,
    /// The surface's size in pixels.
    pub surface: (u32, u32),
    pub view: &'static str,
    /// Whether egui has the keyboard (a text field has focus).
    pub typing: bool,
    pub memory: MemoryUse,
    pub camera: Option<&'a Camera>,
}

impl Probe {
    /// A probe writing to `path`; with `None`, to nothing on the desktop
    /// (a page always has the line as `data-probe`).
    pub fn new(path: Option<PathBuf>) -> Self {
        Self { path, held_seen: 0, looked: 0.0 }
    }

    /// Whether anyone reads the line: reading memory and the camera for it
    /// is skipped otherwise.
    pub fn is_read(&self) -> bool {
        cfg!(target_arch = "wasm32") || self.path.is_some()
    }

    /// Takes note of the input the chapter is given this frame.
    pub fn saw(&mut self, input: &Input) {
        self.held_seen = self.held_seen.max(input.held_count());
        self.looked += input.look.length();
    }

    /// Writes the line for `report`. A file that cannot be written is
    /// reported once, then the probe writes to it no more.
    pub fn write(&mut self, report: &Report) {
        let line = self.line(report);
        // In a browser the test reads the line from the page instead.
        #[cfg(target_arch = "wasm32")]
        crate::web::set_state("probe", line.trim_end());
        let Some(path) = &self.path else { return };
        let partial = path.with_extension("partial");
        if std::fs::write(&partial, line).and_then(|()| std::fs::rename(&partial, path)).is_err() {
            eprintln!("cannot write the probe file {}", path.display());
            self.path = None;
        }
    }

    fn line(&self, report: &Report) -> String {
        let camera = match report.camera {
            Some(c) => {
                format!("{:.4} {:.4} {:.4} {:.5} {:.5}", c.position.x, c.position.y, c.position.z, c.yaw, c.pitch)
            }
            None => "none".into(),
        };
        format!(
            "drawn={} skipped={} surface={}x{} view={} typing={} held={} looked={:.0} {} camera={camera}\n",
            report.drawn,
            report.skipped,
            report.surface.0,
            report.surface.1,
            report.view,
            u8::from(report.typing),
            self.held_seen,
            self.looked,
            report.memory.probe_fields(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_reads_as_the_window_tests_parse_it() {
        let mut probe = Probe::new(None);
        let mut input = Input::default();
        input.look = glam::Vec2::new(3.0, 4.0);
        probe.saw(&input);
        let camera = Camera {
            position: glam::Vec3::new(1.0, 2.0, 3.0),
            yaw: 0.5,
            pitch: -0.25,
            ..Camera::looking_at(glam::Vec3::ZERO, glam::Vec3::NEG_Z, 1.0)
        };
        let memory = MemoryUse { process: Some(1234), heap: Some(567), gpu: None };
        let report = Report {
            drawn: 7,
            skipped: 2,
            surface: (800, 600),
            view: "default",
            typing: true,
            memory,
            camera: Some(&camera),
        };
        let line = probe.line(&report);
        assert_eq!(
            line,
            "drawn=7 skipped=2 surface=800x600 view=default typing=1 held=0 looked=5 \
             memory=1234 heap=567 gpu=n/a camera=1.0000 2.0000 3.0000 0.50000 -0.25000\n"
        );
        assert_eq!(MemoryUse::from_probe(&line), Some(memory));
        let none = probe.line(&Report { camera: None, ..report });
        assert!(none.ends_with(" camera=none\n"), "{none}");
    }
}
