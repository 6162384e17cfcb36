//! Long work a chapter does before its first frame, cut into steps, whose
//! result [`crate::Chapter::new`] receives. On the desktop the steps simply
//! run in one go. A browser page has one thread, and while Rust runs on it
//! nothing repaints and no input is handled: the page runs one step, shows
//! how far it has got, and gives the browser its thread back before the
//! next (`common::web::prepare`).

use crate::Gpu;

// ANCHOR: preparation
/// Work that makes a `T`, in steps.
pub struct Preparation<T> {
    /// What is being made, for the page's message: "generating the terrain".
    pub what: &'static str,
    work: Work<T>,
}

/// What one step of a [`Preparation`] got to.
pub enum Step<T> {
    /// Not finished: the fraction of the whole done so far (0 to 1).
    Progress(f32),
    /// Finished: what was made.
    Done(T),
}

/// The next step, each time it is called.
type NextStep<T> = Box<dyn FnMut(&Gpu) -> Step<T>>;

enum Work<T> {
    /// Nothing (left) to do.
    Ready(Option<T>),
    Steps(NextStep<T>),
}

impl<T> Preparation<T> {
    /// Nothing to do: `value` is already made (or there is nothing to make,
    /// `Preparation::ready(())`).
    pub fn ready(value: T) -> Self {
        Self { what: "", work: Work::Ready(Some(value)) }
    }

    /// `step` does the next slice of the work each time it is called, and
    /// returns [`Step::Done`] with the result after the last.
    pub fn in_steps(what: &'static str, step: impl FnMut(&Gpu) -> Step<T> + 'static) -> Self {
        Self { what, work: Work::Steps(Box::new(step)) }
    }

    /// Does one step. Call it until it returns [`Step::Done`], and not after.
    pub fn step(&mut self, gpu: &Gpu) -> Step<T> {
        match &mut self.work {
            Work::Ready(value) => Step::Done(value.take().expect("a preparation is finished only once")),
            Work::Steps(step) => step(gpu),
        }
    }

    /// Does every step in one go (the desktop's way).
    pub fn finish(mut self, gpu: &Gpu) -> T {
        loop {
            if let Step::Done(value) = self.step(gpu) {
                return value;
            }
        }
    }
}
// ANCHOR_END: preparation

impl<T: 'static> Preparation<T> {
    /// The same work, its result passed through `f`: how a runner that
    /// takes any chapter ([`crate::chapter::About`]) gets every chapter's
    /// result as one type.
    pub fn map<U>(self, f: impl Fn(T) -> U + 'static) -> Preparation<U> {
        let work = match self.work {
            Work::Ready(value) => Work::Ready(value.map(f)),
            Work::Steps(mut step) => Work::Steps(Box::new(move |gpu| match step(gpu) {
                Step::Progress(done) => Step::Progress(done),
                Step::Done(value) => Step::Done(f(value)),
            })),
        };
        Preparation { what: self.what, work }
    }
}
