//! Two runs in the same error axes: when one is more than a decade larger than the other, the
//! smaller looks flat on a shared linear scale (Fig. 5.2 beside Fig. 5.3), so the error plots turn
//! to log |e| by themselves and say so. A `log=1` the user chose stays as it is.

use super::drawing::max_abs;
use crate::view::panels::contract::RunState;
use crate::view::time_window::TimeWindow;

/// The runs' largest errors in view differ by more than this factor: log |e| ...
pub const AUTO_LOG_ON: f64 = 10.0;
/// ... and back to linear only below this one (no flicker about the threshold).
pub const AUTO_LOG_OFF: f64 = 5.0;

/// What the note of an automatically logarithmic error plot says.
pub const AUTO_LOG_NOTE: &str = "log scale: A and B differ by more than 10×";
/// The key's title for the log |e| lines then.
pub const AUTO_LOG_KEY: &str = "log |e|, because runs A and B differ by more than 10×";

/// The largest finite |e1|, |e2| of a run inside the window (0 if none).
pub fn largest_error(run: &RunState<'_>, window: TimeWindow) -> f64 {
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
