//! Long work a chapter does before its first frame, cut into steps. On the
//! desktop a chapter simply does it in one go. A browser page has one
//! thread, and while Rust runs on it nothing repaints and no input is
//! handled: the page runs one step, shows how far it has got, and gives the
//! browser its thread back before the next (`common::web::prepare`).

use crate::Gpu;

// ANCHOR: preparation
/// Work made of steps, each returning the fraction done so far.
pub struct Preparation {
    /// What is being made, for the page's message: "generating the terrain".
    pub what: &'static str,
    step: Box<dyn FnMut(&Gpu) -> f32>,
}

impl Preparation {
    /// `step` does the next slice of the work and returns the fraction of
    /// the whole done so far; 1.0 or more means finished.
    pub fn new(what: &'static str, step: impl FnMut(&Gpu) -> f32 + 'static) -> Self {
        Self { what, step: Box::new(step) }
    }

    /// Does one step; returns the fraction done so far.
    pub fn step(&mut self, gpu: &Gpu) -> f32 {
        (self.step)(gpu)
    }
}
// ANCHOR_END: preparation
