//! The time interval the time plots show: the newest W seconds, or a window around an instant
//! looked back at, or three sampling periods around one instant (the zoom). Shared by the scene,
//! which decides it each frame, and every panel that draws or reads time.

use core::ops::Range;

/// Default width W of the time window, s.
pub const DEFAULT_TIME_WINDOW: f64 = 10.0;

/// The time interval a plot shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeWindow {
    pub start: f64,
    pub end: f64,
}

impl TimeWindow {
    /// [t − W, t], or [0, W] while t < W, so the first seconds fill the plot from the left.
    pub fn ending_at(t: f64, width: f64) -> TimeWindow {
        let t = if t.is_finite() { t } else { 0.0 };
        if t < width {
            TimeWindow { start: 0.0, end: width }
        } else {
            TimeWindow { start: t - width, end: t }
        }
    }

    pub fn width(&self) -> f64 {
        self.end - self.start
    }

    /// The indices of the sorted times `t` that fall inside the window (binary search).
    pub fn indices(&self, t: &[f64]) -> Range<usize> {
        let first = t.partition_point(|&s| s < self.start);
        let last = t.partition_point(|&s| s <= self.end);
        first..last.max(first)
    }
}
