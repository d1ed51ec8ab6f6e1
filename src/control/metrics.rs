//! What a run measures while it goes: the largest errors during and after the slews, their RMS,
//! the growth rate of the error envelope and the verdict (stable, unstable, diverged).

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

/// Length of the windows over which the error envelope is taken for the growth rate, s.
pub const GROWTH_WINDOW: f64 = 0.25;
/// The growth rate is fitted over at most this much time at the end of the run, s.
pub const GROWTH_FIT_SPAN: f64 = 3.0;
/// A run whose error envelope grows faster than this (1/s) is called unstable.
pub const UNSTABLE_GROWTH_RATE: f64 = 0.05;
/// Errors below this (rad) are rounding noise and cannot make a run unstable.
pub const ERROR_NOISE_FLOOR: f64 = 1e-10;

/// Why a run ended early.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DivergenceReason {
    /// |e_i| exceeded the configured divergence bound.
    ErrorBound,
    /// The state became NaN or infinite.
    NonFinite,
    /// Newton did not converge in the predictor.
    NewtonFailure,
}

/// The outcome of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "verdict", rename_all = "lowercase")]
pub enum Verdict {
    /// Errors bounded and not growing.
    Stable,
    /// Errors growing at the given rate (1/s) but still within the bound.
    Unstable { growth_rate: f64 },
    /// The run ended at `at` (s).
    Diverged { at: f64, reason: DivergenceReason },
}

impl Verdict {
    /// "stable", "unstable" or "diverged".
    pub fn label(&self) -> &'static str {
        match self {
            Verdict::Stable => "stable",
            Verdict::Unstable { .. } => "unstable",
            Verdict::Diverged { .. } => "diverged",
        }
    }
}

/// Summary figures of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Metrics {
    /// Simulated time, s.
    pub time: f64,
    /// max |e_i| while the reference moves, rad.
    pub max_error_slew: [f64; 2],
    /// max |e_i| while the reference rests, rad.
    pub max_error_after: [f64; 2],
    /// RMS of e_i over the whole run, rad.
    pub rms_error: [f64; 2],
    /// Slope of ln max(|e1|, |e2|) over the last windows between slews, 1/s (see
    /// [`ErrorStats::growth_rate`]).
    pub growth_rate: Option<f64>,
    /// max |T_i| applied, N m.
    pub max_torque: [f64; 2],
    pub verdict: Verdict,
}

/// One window of the error envelope: its end time, max(|e1|, |e2|) in it, and the rest phase it
/// belongs to (windows with motion in them are not kept).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Window {
    end: f64,
    max: f64,
    rest_phase: u64,
}

/// Running statistics of the errors: maxima, RMS, torque, and the envelope windows of the last
/// [`GROWTH_FIT_SPAN`] seconds (bounded: the memory does not grow with the run).
#[derive(Clone, Debug, Default)]
pub(crate) struct ErrorStats {
    max_slew: [f64; 2],
    max_after: [f64; 2],
    sum_sq: [f64; 2],
    samples: u64,
    max_torque: [f64; 2],
    windows: std::collections::VecDeque<Window>,
    window_start: f64,
    window_max: f64,
    /// The current window has samples where the reference moves.
    window_moving: bool,
    /// Counts the rest phases (between slews); the reference moved at the last sample.
    rest_phase: u64,
    was_moving: bool,
    /// The statistics describe the run since this time (the last change of configuration), so a
    /// live change shows its own numbers, not a mix with the previous setting.
    pub(crate) since: f64,
}

impl ErrorStats {
    pub(crate) fn record(&mut self, t: f64, e: &Vector2<f64>, torque: &Vector2<f64>, moving: bool) {
        for i in 0..2 {
            let a = e[i].abs();
            let slot = if moving { &mut self.max_slew[i] } else { &mut self.max_after[i] };
            *slot = slot.max(a);
            self.sum_sq[i] += e[i] * e[i];
            self.max_torque[i] = self.max_torque[i].max(torque[i].abs());
        }
        self.samples += 1;
        if self.was_moving && !moving {
            self.rest_phase += 1;
        }
        self.was_moving = moving;
        self.window_moving |= moving;
        self.window_max = self.window_max.max(e[0].abs().max(e[1].abs()));
        if t - self.window_start >= GROWTH_WINDOW - 1e-12 {
            if !self.window_moving && self.window_start >= self.since - 1e-9 {
                self.windows.push_back(Window { end: t, max: self.window_max, rest_phase: self.rest_phase });
            }
            while self.windows.front().is_some_and(|w| w.end < t - GROWTH_FIT_SPAN - 1e-9) {
                self.windows.pop_front();
            }
            self.window_start = t;
            self.window_max = 0.0;
            self.window_moving = false;
        }
    }

    /// Starts the statistics afresh at time `t` (a new configuration took effect).
    pub(crate) fn restart(&mut self, t: f64) {
        *self = ErrorStats {
            since: t,
            window_start: t,
            rest_phase: self.rest_phase,
            was_moving: self.was_moving,
            ..Default::default()
        };
    }

    /// After a jump back in time: whether the reference moved at the instant continued from.
    pub(crate) fn continue_phase(&mut self, moving: bool) {
        self.was_moving = moving;
    }

    /// The growth rate of the error envelope, 1/s: the least-squares slope of ln(window max)
    /// against time over the windows of the last [`GROWTH_FIT_SPAN`] seconds in which the
    /// reference rests, each rest phase with its own level (a pooled, within-phase slope). Every
    /// slew excites the loop anew, so only the phases between slews show how its free motion
    /// grows or decays; with a repeating slew that is known after the first rest phase (about
    /// 0.75 s of it), not after whole cycles. `None` until three windows are in.
    pub(crate) fn growth_rate(&self) -> Option<f64> {
        let pts: Vec<&Window> = self.windows.iter().filter(|w| w.max > 0.0).collect();
        if pts.len() < 3 {
            return None;
        }
        let (mut num, mut den) = (0.0, 0.0);
        let mut i = 0;
        while i < pts.len() {
            let phase = pts[i].rest_phase;
            let group: Vec<&&Window> = pts[i..].iter().take_while(|w| w.rest_phase == phase).collect();
            i += group.len();
            let n = group.len() as f64;
            let mt = group.iter().map(|w| w.end).sum::<f64>() / n;
            let my = group.iter().map(|w| w.max.ln()).sum::<f64>() / n;
            for w in group {
                num += (w.end - mt) * (w.max.ln() - my);
                den += (w.end - mt) * (w.end - mt);
            }
        }
        (den > 0.0).then(|| num / den)
    }

    /// The metrics and verdict at time `time`.
    pub(crate) fn metrics(&self, time: f64, divergence: Option<(f64, DivergenceReason)>) -> Metrics {
        let n = self.samples.max(1) as f64;
        let growth_rate = self.growth_rate();
        let last_window = self.windows.back().map(|w| w.max).unwrap_or(0.0).max(self.window_max);
        let verdict = match divergence {
            Some((at, reason)) => Verdict::Diverged { at, reason },
            None => match growth_rate {
                Some(g) if g > UNSTABLE_GROWTH_RATE && last_window > ERROR_NOISE_FLOOR => {
                    Verdict::Unstable { growth_rate: g }
                }
                _ => Verdict::Stable,
            },
        };
        Metrics {
            time,
            max_error_slew: self.max_slew,
            max_error_after: self.max_after,
            rms_error: [(self.sum_sq[0] / n).sqrt(), (self.sum_sq[1] / n).sqrt()],
            growth_rate,
            max_torque: self.max_torque,
            verdict,
        }
    }
}
