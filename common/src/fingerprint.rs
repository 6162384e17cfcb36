//! A frame's fingerprint: what a timed frame was, written beside its times
//! so that a time cannot outlive the frame it measured. A bench table's
//! rows carry the fingerprint of their view's frame; the snapshot test
//! works out every view's fingerprint again from the frame it draws (no
//! timing needed) and fails on a table row whose frame has changed since,
//! and the book marks a table it cannot measure again (a lent GPU's) with
//! what changed.
//!
//! The fingerprint of a view is taken from its frame drawn at the snapshot
//! size and time ([`SIZE`]), whatever size the bench times it at, so that
//! the snapshot run, which draws every snapshot view at that size anyway,
//! can check it: the view's settings (as the chapter's view table writes
//! them), the samples a pixel, and each pass with its draw calls and
//! triangles. A bench view (one the snapshot run does not draw) is
//! fingerprinted by its settings and samples alone.

use crate::draw_counts::thousands;
use crate::{Drawn, PassCount};

/// The size of the frame a fingerprint is taken from: the snapshots'.
pub const SIZE: (u32, u32) = (800, 450);

/// What a frame was.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fingerprint {
    /// The view's settings, as the chapter writes them (`Chapter::view_settings`).
    pub settings: String,
    /// Samples a pixel in the scene pass.
    pub samples: u32,
    /// Each pass and what it drew, in the order they were drawn; empty for
    /// a bench view, which is not drawn to be fingerprinted.
    pub passes: Vec<(String, Drawn)>,
}

impl Fingerprint {
    pub fn new(settings: String, samples: u32, passes: &[PassCount]) -> Self {
        // Triangles read back from the GPU are an earlier frame's: left out.
        let passes = passes
            .iter()
            .map(|p| (p.pass.to_string(), Drawn::counted(p.drawn.draws, p.drawn.recorded_triangles())))
            .collect();
        Self { settings, samples, passes }
    }

    /// Eight hexadecimal digits that change when any part does (FNV-1a over
    /// the parts, folded to 32 bits): the `frame` column of a bench table.
    pub fn id(&self) -> String {
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        let mut feed = |text: &str| {
            for byte in text.bytes().chain([0]) {
                hash ^= u64::from(byte);
                hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
            }
        };
        feed(&self.settings);
        feed(&self.samples.to_string());
        for (pass, drawn) in &self.passes {
            feed(pass);
            feed(&format!("{} {}", drawn.draws, drawn.triangles));
        }
        format!("{:08x}", (hash >> 32) as u32 ^ hash as u32)
    }

    /// The parts a reader can check, as a bench table's frames section
    /// writes them: `4 | terrain: 1 draw, 282,624 triangles`.
    pub fn parts(&self) -> (String, String) {
        let passes = if self.passes.is_empty() {
            "not drawn (a bench view)".to_string()
        } else {
            self.passes
                .iter()
                .map(|(pass, drawn)| {
                    let calls = if drawn.draws == 1 { "draw" } else { "draws" };
                    format!("{pass}: {} {calls}, {} triangles", drawn.draws, thousands(drawn.triangles))
                })
                .collect::<Vec<_>>()
                .join("; ")
        };
        (self.samples.to_string(), passes)
    }

    /// What differs between `self` (the frame as it is) and `then` (as a
    /// table recorded it, from its frames section), in words; empty if
    /// nothing a table records differs (then only the settings changed).
    pub fn changes_since(&self, then_samples: &str, then_passes: &str) -> Vec<String> {
        let (samples, passes) = self.parts();
        let mut changes = Vec::new();
        if samples != then_samples {
            changes.push(format!("samples a pixel: {then_samples} then, {samples} now"));
        }
        if passes != then_passes {
            changes.push(format!("drew {then_passes} then, {passes} now"));
        }
        changes
    }
}

/// The heading of a bench table's frames section, and its table's head.
pub const FRAMES_HEADING: &str = "Frames timed, each as its fingerprint describes it";

/// A bench table's frames section: a row per view, its fingerprint's id
/// and its parts.
pub fn frames_section(frames: &[(&str, Fingerprint)]) -> String {
    let mut text = format!(
        "{FRAMES_HEADING} (drawn at {} × {}, the snapshots' size; `frame` in the rows above):\n\n\
         | view | frame | samples | passes |\n|---|---|---:|---|\n",
        SIZE.0, SIZE.1
    );
    for (view, fingerprint) in frames {
        let (samples, passes) = fingerprint.parts();
        text.push_str(&format!("| {view} | {} | {samples} | {passes} |\n", fingerprint.id()));
    }
    text
}

/// A view's row in a table's frames section, as (id, samples, passes).
pub fn recorded(table: &str, view: &str) -> Option<(String, String, String)> {
    let section = &table[table.find(FRAMES_HEADING)?..];
    section.lines().find_map(|line| {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        (cells.len() == 6 && cells[1] == view)
            .then(|| (cells[2].to_string(), cells[3].to_string(), cells[4].to_string()))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(settings: &str, samples: u32, triangles: u64) -> Fingerprint {
        let count = PassCount { pass: "terrain", drawn: Drawn::counted(1, triangles) };
        Fingerprint::new(settings.into(), samples, &[count])
    }

    #[test]
    fn any_part_changes_the_id() {
        let base = frame("Settings { fog: HAZE }", 4, 282_624);
        assert_eq!(base.id(), frame("Settings { fog: HAZE }", 4, 282_624).id());
        assert_eq!(base.id().len(), 8);
        for other in [frame("Settings { fog: NONE }", 4, 282_624), frame("Settings { fog: HAZE }", 1, 282_624)] {
            assert_ne!(base.id(), other.id());
        }
        assert_ne!(base.id(), frame("Settings { fog: HAZE }", 4, 282_625).id());
        let bench = Fingerprint::new("Settings { fog: HAZE }".into(), 4, &[]);
        assert_ne!(base.id(), bench.id());
    }

    #[test]
    fn a_frames_section_is_read_back_and_its_changes_named() {
        let then = frame("s", 1, 282_624);
        let table = format!("| view | what |\n\n{}", frames_section(&[("default", then.clone())]));
        let (id, samples, passes) = recorded(&table, "default").unwrap();
        assert_eq!((id, samples.as_str(), passes.as_str()), (then.id(), "1", "terrain: 1 draw, 282,624 triangles"));
        assert_eq!(recorded(&table, "dense"), None);
        let now = frame("s", 4, 300_000);
        assert_eq!(
            now.changes_since(&samples, &passes),
            [
                "samples a pixel: 1 then, 4 now".to_string(),
                "drew terrain: 1 draw, 282,624 triangles then, terrain: 1 draw, 300,000 triangles now".to_string()
            ]
        );
        assert!(then.changes_since(&samples, &passes).is_empty());
    }
}

#[cfg(test)]
mod read_back {
    use super::*;

    #[test]
    fn triangles_read_back_late_are_left_out() {
        let late = Drawn::counted(4, 1_000).and_read_back(5_000);
        assert_eq!((late.triangles, late.recorded_triangles()), (6_000, 1_000));
        let count = PassCount { pass: "terrain and rocks", drawn: late };
        let fingerprint = Fingerprint::new("s".into(), 4, &[count]);
        assert_eq!(fingerprint.passes, [("terrain and rocks".to_string(), Drawn::counted(4, 1_000))]);
    }
}
