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
    /// Slope of ln max(|e1|, |e2|) over the last windows after the first slew, 1/s.
    pub growth_rate: Option<f64>,
    /// max |T_i| applied, N m.
    pub max_torque: [f64; 2],
    pub verdict: Verdict,
}

/// Running statistics of the errors.
#[derive(Clone, Debug, Default)]
pub(crate) struct ErrorStats {
    max_slew: [f64; 2],
    max_after: [f64; 2],
    sum_sq: [f64; 2],
    samples: u64,
    max_torque: [f64; 2],
    /// (window end time, max(|e1|, |e2|) in the window).
    windows: Vec<(f64, f64)>,
    window_start: f64,
    window_max: f64,
    /// The growth rate is fitted only after this time (the last change of configuration), so a
    /// live change shows its own growth, not a mix with the previous setting.
    pub(crate) fit_from: f64,
    /// For a repeating maneuver: its period and the error maximum of each cycle (cycle index, max).
    cycle_period: Option<f64>,
    cycle_max: Vec<(u64, f64)>,
}

impl ErrorStats {
    pub(crate) fn record(
        &mut self,
        t: f64,
        e: &Vector2<f64>,
        torque: &Vector2<f64>,
        moving: bool,
        cycle_period: Option<f64>,
    ) {
        if cycle_period != self.cycle_period {
            self.cycle_period = cycle_period;
            self.cycle_max.clear();
        }
        if let Some(period) = cycle_period {
            let index = (t / period).floor() as u64;
            let m = e[0].abs().max(e[1].abs());
            match self.cycle_max.last_mut() {
                Some((i, max)) if *i == index => *max = max.max(m),
                _ => self.cycle_max.push((index, m)),
            }
        }
        for i in 0..2 {
            let a = e[i].abs();
            let slot = if moving { &mut self.max_slew[i] } else { &mut self.max_after[i] };
            *slot = slot.max(a);
            self.sum_sq[i] += e[i] * e[i];
            self.max_torque[i] = self.max_torque[i].max(torque[i].abs());
        }
        self.samples += 1;
        self.window_max = self.window_max.max(e[0].abs().max(e[1].abs()));
        if t - self.window_start >= GROWTH_WINDOW - 1e-12 {
            self.windows.push((t, self.window_max));
            self.window_start = t;
            self.window_max = 0.0;
        }
    }

    /// The growth rate of the error envelope, 1/s. For a single slew: the least-squares slope of
    /// ln(window max) over the windows after `from` (the end of the slew). For a repeating
    /// maneuver the errors rise with every slew even when the loop is stable, so the envelope is
    /// compared cycle to cycle instead: ln(max of the last full cycle / max of the one before) / period.
    pub(crate) fn growth_rate(&self, from: f64) -> Option<f64> {
        if let Some(period) = self.cycle_period {
            let current = self.cycle_max.last()?.0;
            let mut complete =
                self.cycle_max.iter().filter(|(i, _)| *i < current && *i as f64 * period >= self.fit_from - 1e-9).rev();
            let (_, last) = complete.next()?;
            let (_, previous) = complete.next()?;
            return (*last > 0.0 && *previous > 0.0).then(|| (last / previous).ln() / period);
        }
        let end = self.windows.last()?.0;
        let start = from.max(self.fit_from).max(end - GROWTH_FIT_SPAN);
        let pts: Vec<(f64, f64)> =
            self.windows.iter().filter(|(t, m)| *t > start + 1e-9 && *m > 0.0).map(|(t, m)| (*t, m.ln())).collect();
        if pts.len() < 3 {
            return None;
        }
        let n = pts.len() as f64;
        let (st, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (t, y)| (a + t, b + y));
        let (mt, my) = (st / n, sy / n);
        let (num, den) =
            pts.iter().fold((0.0, 0.0), |(a, b), (t, y)| (a + (t - mt) * (y - my), b + (t - mt) * (t - mt)));
        (den > 0.0).then(|| num / den)
    }
}

impl ErrorStats {
    /// The metrics and verdict at time `time` of a run whose first slew ends at `slew_end`.
    pub(crate) fn metrics(&self, time: f64, slew_end: f64, divergence: Option<(f64, DivergenceReason)>) -> Metrics {
        let n = self.samples.max(1) as f64;
        let growth_rate = self.growth_rate(slew_end);
        let last_window = self.windows.last().map(|w| w.1).unwrap_or(0.0).max(self.window_max);
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
