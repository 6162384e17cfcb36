//! Counting what a frame draws: draw calls and triangles, per pass, taken
//! from the arguments of the draws as they are recorded (never estimated
//! from a formula elsewhere). The overlay shows the counts, `--bench`
//! prints them, and the book's bench tables carry them, so that a level of
//! detail shows in numbers, not only in milliseconds.

use std::cell::RefCell;
use std::ops::{Add, AddAssign, Range};

/// What some draw calls drew: how many calls, and how many triangles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Drawn {
    pub draws: u32,
    pub triangles: u64,
    /// Of `triangles`, those known only from the GPU's own count, read
    /// back a frame or more late (draws the GPU wrote itself): they are
    /// an earlier frame's, so a frame's fingerprint leaves them out.
    pub read_back: u64,
}

impl Drawn {
    /// No draw at all.
    pub const NOTHING: Self = Self { draws: 0, triangles: 0, read_back: 0 };

    /// One full-screen triangle (`common::fullscreen`): one draw of three
    /// vertices, one instance.
    pub const FULL_SCREEN: Self = Self { draws: 1, triangles: 1, read_back: 0 };

    /// One draw of a triangle list, given the draw's own arguments:
    /// `vertices` (or indices, for `draw_indexed`) and `instances`, as
    /// passed to `RenderPass::draw`. Every three vertices are a triangle,
    /// drawn once per instance.
    pub fn triangle_list(vertices: Range<u32>, instances: Range<u32>) -> Self {
        let per_instance = u64::from(vertices.end.saturating_sub(vertices.start) / 3);
        let instances = u64::from(instances.end.saturating_sub(instances.start));
        Self { draws: 1, triangles: per_instance * instances, read_back: 0 }
    }

    /// One draw of points or lines: a draw, no triangles.
    pub const POINTS_OR_LINES: Self = Self { draws: 1, triangles: 0, read_back: 0 };

    /// Draws whose triangles were counted some other way: an indirect
    /// draw's arguments read back from the GPU, or a piece that adds up
    /// its own draws.
    pub const fn counted(draws: u32, triangles: u64) -> Self {
        Self { draws, triangles, read_back: 0 }
    }

    /// These draws and `triangles` more, known only from the GPU's count
    /// read back late ([`Drawn::read_back`]).
    pub const fn and_read_back(self, triangles: u64) -> Self {
        Self { triangles: self.triangles + triangles, read_back: self.read_back + triangles, ..self }
    }

    /// The triangles known when the frame was recorded: the frame's own.
    pub const fn recorded_triangles(&self) -> u64 {
        self.triangles - self.read_back
    }
}

impl Add for Drawn {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        Self {
            draws: self.draws + other.draws,
            triangles: self.triangles + other.triangles,
            read_back: self.read_back + other.read_back,
        }
    }
}

impl AddAssign for Drawn {
    fn add_assign(&mut self, other: Self) {
        *self = *self + other;
    }
}

impl std::iter::Sum for Drawn {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::NOTHING, Add::add)
    }
}

/// What one pass of a frame drew. `pass` is the pass's name as it is
/// timed (`PassTimer::pass`), so counts and times line up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PassCount {
    pub pass: &'static str,
    pub drawn: Drawn,
}

/// The frame's tally, filled by the chapter while it records
/// (`frame.drawn.add("scene", drawn)`); the runner makes a fresh one for
/// every frame and reads it afterwards. Whoever begins a pass names it, so
/// a piece that draws into a pass it is given returns a [`Drawn`], and one
/// that begins passes of its own returns [`PassCount`]s. It takes `&self`, like
/// [`crate::PassTimer`], so that a pass borrowed from the frame does not
/// keep a chapter from counting into it.
#[derive(Debug, Default)]
pub struct DrawCounts {
    passes: RefCell<Vec<PassCount>>,
}

impl DrawCounts {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds `drawn` to pass `pass`: a pass counted twice (a chain of small
    /// passes reported as one) adds up; passes keep the order they first
    /// came in.
    pub fn add(&self, pass: &'static str, drawn: Drawn) {
        let mut passes = self.passes.borrow_mut();
        match passes.iter_mut().find(|p| p.pass == pass) {
            Some(count) => count.drawn += drawn,
            None => passes.push(PassCount { pass, drawn }),
        }
    }

    /// Adds what pieces that begin their own passes report: each names
    /// its pass (a shadow map's, a bloom chain's) and says what it drew.
    pub fn extend(&self, counts: impl IntoIterator<Item = PassCount>) {
        for count in counts {
            self.add(count.pass, count.drawn);
        }
    }

    /// The passes counted so far, in order.
    pub fn passes(&self) -> Vec<PassCount> {
        self.passes.borrow().clone()
    }

    /// The passes counted, and forgets them.
    pub fn take(&self) -> Vec<PassCount> {
        std::mem::take(&mut *self.passes.borrow_mut())
    }
}

/// The whole frame: every pass's draws added up.
pub fn total(passes: &[PassCount]) -> Drawn {
    passes.iter().map(|p| p.drawn).sum()
}

/// `n` with a comma between thousands, as the book writes counts: 1,234,567.
pub fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut text = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, digit) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            text.push(',');
        }
        text.push(digit);
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_draw_counts_its_triangles_once_per_instance() {
        assert_eq!(Drawn::triangle_list(0..3, 0..1), Drawn { draws: 1, triangles: 1, read_back: 0 });
        // 12 indices from the 6th on, instances 10 to 14: 4 triangles, 5 times.
        assert_eq!(Drawn::triangle_list(6..18, 10..15), Drawn { draws: 1, triangles: 20, read_back: 0 });
        assert_eq!(Drawn::triangle_list(0..36, 3..3), Drawn { draws: 1, triangles: 0, read_back: 0 }, "no instances");
        assert_eq!(Drawn::triangle_list(0..3, 0..1), Drawn::FULL_SCREEN);
    }

    #[test]
    fn passes_add_up_in_the_order_they_came() {
        let counts = DrawCounts::new();
        counts.add("scene", Drawn::triangle_list(0..300, 0..2));
        counts.add("bloom", Drawn::FULL_SCREEN);
        counts.add("scene", Drawn::triangle_list(0..30, 0..1));
        counts.add("bloom", Drawn::FULL_SCREEN);
        let passes = counts.take();
        assert_eq!(
            passes,
            [
                PassCount { pass: "scene", drawn: Drawn { draws: 2, triangles: 210, read_back: 0 } },
                PassCount { pass: "bloom", drawn: Drawn { draws: 2, triangles: 2, read_back: 0 } },
            ]
        );
        assert_eq!(total(&passes), Drawn { draws: 4, triangles: 212, read_back: 0 });
        assert!(counts.passes().is_empty(), "take forgets");
    }

    #[test]
    fn thousands_are_separated() {
        let cases = [(0, "0"), (7, "7"), (999, "999"), (1000, "1,000"), (1234567, "1,234,567"), (100000, "100,000")];
        for (n, text) in cases {
            assert_eq!(thousands(n), text);
        }
    }
}
