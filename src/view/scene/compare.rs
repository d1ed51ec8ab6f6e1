//! Two runs in the same error axes: when one is more than a decade larger than the other, the
//! smaller looks flat on a shared linear scale (Fig. 5.2 beside Fig. 5.3), so the error plots turn
//! to log |e| by themselves and say so (issue 23 item 5). A `log=1` the user chose stays as it is.

use super::{RunState, Scene};
use crate::view::traces::{max_abs, TimeWindow};

/// The runs' largest errors in view differ by more than this factor: log |e| ...
pub const AUTO_LOG_ON: f64 = 10.0;
/// ... and back to linear only below this one (no flicker about the threshold).
pub const AUTO_LOG_OFF: f64 = 5.0;

/// What the note of an automatically logarithmic error plot says.
pub const AUTO_LOG_NOTE: &str = "log scale: A and B differ by more than 10×";
/// The key's title for the log |e| lines then.
pub const AUTO_LOG_KEY: &str = "log |e|, because runs A and B differ by more than 10×";

/// The largest finite |e1|, |e2| of a run inside the window (0 if none).
fn largest_error(run: &RunState<'_>, window: TimeWindow) -> f64 {
    let range = window.indices(run.traces.t());
    [run.traces.e1(), run.traces.e2()].iter().map(|v| v.get(range.clone()).map_or(0.0, max_abs)).fold(0.0, f64::max)
}

/// Whether two runs whose largest errors are `a` and `b` want log |e|, given the current choice
/// `now` (hysteresis between [`AUTO_LOG_OFF`] and [`AUTO_LOG_ON`]); a run without errors yet
/// (0, or nothing finite) changes nothing.
pub fn wants_log(a: f64, b: f64, now: bool) -> bool {
    if !(a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite()) {
        return now;
    }
    let ratio = (a / b).max(b / a);
    if now {
        ratio > AUTO_LOG_OFF
    } else {
        ratio > AUTO_LOG_ON
    }
}

impl Scene {
    /// Decides, for this frame, whether the error plots turn to log |e| by themselves: only when
    /// two runs are compared, the user has not chosen log |e| and the plots are not zoomed on one
    /// instant. A change re-describes the frame (ticks and notes differ).
    pub(super) fn update_auto_log(&mut self, a: &RunState<'_>, b: Option<&RunState<'_>>, window: TimeWindow) {
        let next = match b {
            Some(b) if !self.options.log_errors && self.cycle_window().is_none() => {
                wants_log(largest_error(a, window), largest_error(b, window), self.auto_log)
            }
            _ => false,
        };
        if next != self.auto_log {
            self.auto_log = next;
            self.info_generation += 1;
        }
    }

    /// True while the error plots are log |e| because the compared runs differ by a decade.
    pub fn auto_log(&self) -> bool {
        self.auto_log
    }
}
