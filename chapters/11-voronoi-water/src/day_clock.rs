//! The day's clock: the sun's phase follows scene time (a day every
//! [`DAY_SECONDS`]) from where the view starts it, unless Space freezes it;
//! Q and E run it backwards or forwards. The colours of the sunset are
//! looked up by the sun's height at that phase (`atmosphere`).

use crate::atmosphere::DAY_SECONDS;
use crate::views::Settings;

// ANCHOR: clock
/// The day's clock: the phase follows scene time unless frozen (Space);
/// holding Q or E runs it backwards or forwards.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DayClock {
    /// Phase added by Q and E.
    pub shift: f32,
    /// The phase it was frozen at.
    pub frozen: Option<f32>,
}

impl DayClock {
    /// The phase of the day, 0..1, at scene time `time`.
    pub fn phase(&self, settings: &Settings, time: f32) -> f32 {
        let running = if settings.day_runs { time.rem_euclid(DAY_SECONDS) / DAY_SECONDS } else { 0.0 };
        self.frozen.unwrap_or(settings.day_start + self.shift + running).rem_euclid(1.0)
    }
}
// ANCHOR_END: clock
