//! What a run measures while it goes: the largest errors during and after the slews, their RMS,
//! the growth rate of the error envelope and the verdict (stable, unstable, a bounded oscillation,
//! diverged). Everything is computed online in bounded memory: a run of any length costs the same.

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
/// Errors below this fraction of the largest error of the run are at their floor (a stable run's
/// errors settle near 1e-12 rad, set by rounding and the friction observer): the growth rate is
/// not fitted on them, where it would only measure noise.
pub const FLOOR_FRACTION: f64 = 1e-6;
/// An oscillation is recognised on at least this many regular whole cycles between slews (one
/// ends at every zero crossing, up to up and down to down, so the second ends half a period after
/// the first), those that ended in the last [`GROWTH_FIT_SPAN`] seconds or two periods, whichever
/// is longer…
pub const CYCLES_TO_RECOGNISE: usize = 2;
/// …and it is a bounded oscillation (a limit cycle, e.g. the stick-slip hunting of friction
/// compensation held over δ) when its amplitude neither decays faster than this rate (1/s) nor
/// grows faster than [`UNSTABLE_GROWTH_RATE`] from cycle to cycle. A linear mode whose envelope
/// changes this slowly would need −0.01 < ln ρ/δ < 0.05 1/s.
pub const BOUNDED_ENVELOPE_RATE: f64 = 0.01;
/// Whole cycles kept (bounded memory): 3 s of a 30-rad/s oscillation, two crossings a period.
const CYCLES_KEPT: usize = 64;
/// With a repeating slew, the errors are judged from one there-and-back to the next once this
/// many whole rest phases are in (the last, and the one after the same slew before it): they are
/// unstable if their peaks grow, bounded if they rise between slews but not from one to the next.
pub const PHASES_TO_COMPARE: usize = 3;

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
#[serde(tag = "verdict", rename_all = "snake_case")]
pub enum Verdict {
    /// Errors bounded and not growing (decaying, or at their floor).
    Stable,
    /// Errors growing at the given rate (1/s) but still within the bound.
    Unstable { growth_rate: f64 },
    /// A limit cycle between slews: regular cycles of a period of their own whose amplitude
    /// neither grows nor decays (amplitude = max |e1|, |e2| over the last whole cycle, rad; its
    /// period, s).
    BoundedOscillation { amplitude: [f64; 2], period: f64 },
    /// With a repeating slew: errors that rise between slews but come back no larger after one
    /// slew than after the last — the response to the slews, locked to their period, not an
    /// oscillation of the loop's own (amplitude = max |e1|, |e2| between the last two slews;
    /// period = the time from one rest phase to the next, s). Called stable.
    SlewLocked { amplitude: [f64; 2], period: f64 },
    /// The run ended at `at` (s).
    Diverged { at: f64, reason: DivergenceReason },
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
    /// [`ErrorStats::growth_rate`]); for a bounded oscillation, the rate of its cycles'
    /// amplitude. `None` while too short, or when the errors are at their floor.
    pub growth_rate: Option<f64>,
    /// The errors have settled at their floor (rounding, friction): nothing left to grow or decay.
    pub errors_at_floor: bool,
    /// max |T_i| applied, N m.
    pub max_torque: [f64; 2],
    /// RMS of e_i while the reference rests (the floor the sensors leave), rad; 0 if it never rests.
    pub rms_error_rest: [f64; 2],
    /// RMS of T_i over the whole run, N m.
    pub rms_torque: [f64; 2],
    /// The standard deviation of T_i while the reference rests, N m: how much the torque
    /// fluctuates about its mean (the friction's compensation) once the slew is done — its noise.
    pub torque_fluctuation_rest: [f64; 2],
    /// The share of the time T_i was at the motors' limit (0 without a limit).
    pub saturated: [f64; 2],
    /// The tracking errors e1, e2 at the last sample, rad.
    pub error: [f64; 2],
    pub verdict: Verdict,
}

/// A link's tracking error is large beyond this fraction of its travel in the slew: stable or not,
/// a loop that misses the course by a tenth of the way does not do the job (the paper's stable
/// runs stay below a thousandth).
pub const LARGE_ERROR_FRACTION: f64 = 0.1;

/// A run's largest tracking error where it is large against the slew it follows.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LargeError {
    /// The link, 0 or 1.
    pub link: usize,
    /// max |e_i| over the run, rad.
    pub error: f64,
    /// |q_df − q_d0| of that link, rad.
    pub travel: f64,
}

impl Metrics {
    /// The link whose largest error is the greatest share of its travel, if that share exceeds
    /// [`LARGE_ERROR_FRACTION`] (a link that does not move is not judged by it).
    pub fn large_error(&self, slew: &crate::model::params::SlewParameters) -> Option<LargeError> {
        (0..2)
            .filter_map(|i| {
                let travel = (slew.end[i] - slew.start[i]).abs();
                let error = self.max_error_slew[i].max(self.max_error_after[i]);
                (travel > 0.0 && error.is_finite()).then_some(LargeError { link: i, error, travel })
            })
            .filter(|l| l.error > LARGE_ERROR_FRACTION * l.travel)
            .max_by(|a, b| (a.error / a.travel).total_cmp(&(b.error / b.travel)))
    }
}

/// One window of the error envelope: its end time, max(|e1|, |e2|) in it, and the rest phase it
/// belongs to (windows with motion in them are not kept).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Window {
    end: f64,
    max: f64,
    rest_phase: u64,
}

/// One whole cycle of a link's error: between two upward zero crossings, or two downward ones.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Cycle {
    end: f64,
    period: f64,
    /// max |e1|, |e2| during the cycle.
    amplitude: [f64; 2],
}

/// The cycles of one link's error between slews (a slew starts them afresh). Cycles are taken
/// from every zero crossing, up to up and down to down: they overlap by half a period, so an
/// oscillation is recognised half a period sooner, and each spans both of its halves whatever
/// its offset.
#[derive(Clone, Debug, Default)]
struct Cycles {
    /// The side of zero (beyond ±floor) the error was last on: +1, −1, or 0 before either.
    side: i8,
    /// The last upward and downward crossings, with max |e1|, |e2| since each.
    last: [Option<(f64, [f64; 2])>; 2],
    done: std::collections::VecDeque<Cycle>,
}

impl Cycles {
    fn record(&mut self, t: f64, e: f64, abs: [f64; 2], floor: f64) {
        for (_, max) in self.last.iter_mut().flatten() {
            *max = [max[0].max(abs[0]), max[1].max(abs[1])];
        }
        let side = if e > floor {
            1
        } else if e < -floor {
            -1
        } else {
            return;
        };
        if side != self.side {
            // A crossing (0 up, 1 down) closes the cycle that began at the previous one like it.
            if self.side != 0 {
                let k = usize::from(side < 0);
                if let Some((t0, amplitude)) = self.last[k] {
                    if self.done.len() == CYCLES_KEPT {
                        self.done.pop_front();
                    }
                    self.done.push_back(Cycle { end: t, period: t - t0, amplitude });
                }
                self.last[k] = Some((t, abs));
            }
            self.side = side;
        }
    }

    /// A regular oscillation of link `i`: the cycles that ended in the last [`GROWTH_FIT_SPAN`]
    /// seconds or two periods, at least [`CYCLES_TO_RECOGNISE`] of them, regular (periods within
    /// 1.5×) and above the floor, the oscillation still going at `now`. Returns the amplitude of
    /// the last cycle, the mean period and the rate at which the amplitude changes, 1/s (the
    /// least-squares slope of its logarithm: over many cycles of a fast oscillation, not the
    /// ratio of two).
    fn oscillation(&self, i: usize, now: f64, floor: f64) -> Option<([f64; 2], f64, f64)> {
        let last = *self.done.back()?;
        let span = GROWTH_FIT_SPAN.max(2.0 * last.period);
        // The cycles end in time order: the recent ones are the deque's tail (no allocation).
        let first = self.done.iter().position(|c| c.end >= last.end - span - 1e-9).unwrap_or(0);
        let recent = || self.done.range(first..);
        let n = self.done.len() - first;
        if n < CYCLES_TO_RECOGNISE || recent().any(|c| c.amplitude[i] <= floor) {
            return None;
        }
        let (lo, hi) = recent().fold((f64::INFINITY, 0.0f64), |(a, b), c| (a.min(c.period), b.max(c.period)));
        let period = recent().map(|c| c.period).sum::<f64>() / n as f64;
        // Regular cycles, and the oscillation has not stopped since the last one.
        if hi > 1.5 * lo || now - last.end > period + GROWTH_WINDOW {
            return None;
        }
        let (num, den) = centred_sums(recent().map(|c| (c.end, c.amplitude[i].ln())));
        (den > 0.0).then(|| (last.amplitude, period, num / den))
    }
}

/// Σ(x − x̄)(y − ȳ) and Σ(x − x̄)² over `points`: the numerator and denominator of their
/// least-squares slope.
fn centred_sums(points: impl Iterator<Item = (f64, f64)> + Clone) -> (f64, f64) {
    let n = points.clone().count() as f64;
    let mx = points.clone().map(|p| p.0).sum::<f64>() / n;
    let my = points.clone().map(|p| p.1).sum::<f64>() / n;
    points.fold((0.0, 0.0), |(num, den), (x, y)| (num + (x - mx) * (y - my), den + (x - mx) * (x - mx)))
}

/// Running statistics of the errors: maxima, RMS, torque, and the envelope windows of the last
/// [`GROWTH_FIT_SPAN`] seconds (bounded: the memory does not grow with the run).
#[derive(Clone, Debug, Default)]
pub(crate) struct ErrorStats {
    max_slew: [f64; 2],
    max_after: [f64; 2],
    /// The last error recorded.
    last: [f64; 2],
    sum_sq: [f64; 2],
    samples: u64,
    max_torque: [f64; 2],
    /// Σ e_i², Σ T_i² while the reference rests and the samples in it; Σ T_i² over all samples;
    /// the samples with T_i at the limit.
    rest_sum_sq: [f64; 2],
    rest_torque_sq: [f64; 2],
    rest_torque_sum: [f64; 2],
    rest_samples: u64,
    torque_sq: [f64; 2],
    saturated: [u64; 2],
    windows: std::collections::VecDeque<Window>,
    window_start: f64,
    window_max: f64,
    /// The current window has samples where the reference moves.
    window_moving: bool,
    /// Counts the rest phases (between slews); the reference moved at the last sample.
    rest_phase: u64,
    was_moving: bool,
    /// The largest error since `since`: the floor is a fraction of it.
    peak: f64,
    /// The cycles of e1 and e2 in the current rest phase, and max |e1|, |e2| in it.
    cycles: [Cycles; 2],
    max_since_slew: [f64; 2],
    /// The last whole rest phases (between two slews): when each ended and max |e1|, |e2| in it.
    phases: std::collections::VecDeque<(f64, [f64; 2])>,
    /// The statistics describe the run since this time (the last change of configuration), so a
    /// live change shows its own numbers, not a mix with the previous setting; the rest phase
    /// it fell in (that phase is not whole).
    pub(crate) since: f64,
    since_phase: u64,
}

impl ErrorStats {
    /// Records the errors `e` and the applied `torque` at `t` (every plant step); `limit` is the
    /// motors' torque limit, if any.
    pub(crate) fn record(&mut self, t: f64, e: &Vector2<f64>, torque: &Vector2<f64>, moving: bool, limit: Option<f64>) {
        for i in 0..2 {
            let a = e[i].abs();
            let slot = if moving { &mut self.max_slew[i] } else { &mut self.max_after[i] };
            *slot = slot.max(a);
            self.sum_sq[i] += e[i] * e[i];
            self.max_torque[i] = self.max_torque[i].max(torque[i].abs());
            self.torque_sq[i] += torque[i] * torque[i];
            if !moving {
                self.rest_sum_sq[i] += e[i] * e[i];
                self.rest_torque_sq[i] += torque[i] * torque[i];
                self.rest_torque_sum[i] += torque[i];
            }
            if limit.is_some_and(|l| torque[i].abs() >= l) {
                self.saturated[i] += 1;
            }
        }
        self.rest_samples += u64::from(!moving);
        self.samples += 1;
        self.last = [e[0], e[1]];
        if self.was_moving && !moving {
            self.rest_phase += 1;
        }
        let abs = [e[0].abs(), e[1].abs()];
        self.peak = self.peak.max(abs[0]).max(abs[1]);
        if moving {
            // A rest phase that began after `since` has ended: keep its peaks.
            if !self.was_moving && self.rest_phase > self.since_phase {
                if self.phases.len() == PHASES_TO_COMPARE {
                    self.phases.pop_front();
                }
                self.phases.push_back((t, self.max_since_slew));
            }
            self.cycles = Default::default();
            self.max_since_slew = [0.0; 2];
        } else {
            self.max_since_slew = [self.max_since_slew[0].max(abs[0]), self.max_since_slew[1].max(abs[1])];
            let floor = self.floor();
            for (i, c) in self.cycles.iter_mut().enumerate() {
                c.record(t, e[i], abs, floor);
            }
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

    /// Errors at or below this are at their floor, rad.
    fn floor(&self) -> f64 {
        ERROR_NOISE_FLOOR.max(FLOOR_FRACTION * self.peak)
    }

    /// Starts the statistics afresh at time `t` (a new configuration took effect).
    pub(crate) fn restart(&mut self, t: f64) {
        *self = ErrorStats {
            since: t,
            since_phase: self.rest_phase,
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
    /// 0.75 s of it), not after whole cycles. Windows at the floor are left out. `None` until
    /// three windows above the floor are in.
    pub(crate) fn growth_rate(&self) -> Option<f64> {
        let floor = self.floor();
        let pts: Vec<&Window> = self.windows.iter().filter(|w| w.max > floor).collect();
        if pts.len() < 3 {
            return None;
        }
        let (mut num, mut den) = (0.0, 0.0);
        let mut i = 0;
        while i < pts.len() {
            let phase = pts[i].rest_phase;
            let group = pts[i..].iter().take_while(|w| w.rest_phase == phase);
            i += group.clone().count();
            let (n, d) = centred_sums(group.map(|w| (w.end, w.max.ln())));
            num += n;
            den += d;
        }
        (den > 0.0).then(|| num / den)
    }

    /// With a repeating slew: how the errors' peaks between slews change from one there-and-back
    /// to the next — the last whole rest phase against the one two before it, after the same
    /// slew (the two directions excite the arm differently). Returns the last phase's peaks, the
    /// time from one rest phase to the next and the peaks' rate, 1/s. Each slew excites the
    /// loop anew, and a rest phase of 1.5 s is too short for a slow growth to show through the
    /// decay of the slew's transient: from phase to phase it does.
    fn across_slews(&self) -> Option<([f64; 2], f64, f64)> {
        let n = self.phases.len();
        if n < PHASES_TO_COMPARE {
            return None;
        }
        let (before, last) = (self.phases[n - PHASES_TO_COMPARE], self.phases[n - 1]);
        let peak = |p: [f64; 2]| p[0].max(p[1]);
        let span = last.0 - before.0;
        if span <= 0.0 || peak(before.1) <= 0.0 || peak(last.1) <= 0.0 {
            return None;
        }
        let rate = (peak(last.1) / peak(before.1)).ln() / span;
        Some((last.1, span / (PHASES_TO_COMPARE - 1) as f64, rate))
    }

    /// The metrics and verdict at time `time`.
    pub(crate) fn metrics(&self, time: f64, divergence: Option<(f64, DivergenceReason)>) -> Metrics {
        let n = self.samples.max(1) as f64;
        let floor = self.floor();
        // The link with the larger swing decides whether the errors oscillate steadily: neither
        // decaying nor growing fast enough to be called unstable.
        let dominant = usize::from(self.max_since_slew[1] > self.max_since_slew[0]);
        let steady = self.cycles[dominant]
            .oscillation(dominant, time, floor)
            .filter(|&(_, _, rate)| rate > -BOUNDED_ENVELOPE_RATE && rate <= UNSTABLE_GROWTH_RATE);
        let at_floor = steady.is_none()
            && self.windows.back().is_some_and(|w| w.max <= floor && w.end >= time - 2.0 * GROWTH_WINDOW)
            && self.window_max <= floor;
        let mut growth_rate = match steady {
            Some((_, _, rate)) => Some(rate),
            None if at_floor => None,
            None => self.growth_rate(),
        };
        let verdict = match (divergence, steady) {
            (Some((at, reason)), _) => Verdict::Diverged { at, reason },
            (None, Some((amplitude, period, _))) => Verdict::BoundedOscillation { amplitude, period },
            (None, None) => match (growth_rate, self.across_slews()) {
                // With a repeating slew, growth from one there-and-back to the next decides.
                (_, Some((_, _, rate))) if rate > UNSTABLE_GROWTH_RATE => {
                    growth_rate = Some(rate);
                    Verdict::Unstable { growth_rate: rate }
                }
                // Growth between slews that every slew resets: the response to the slews, at the
                // envelope's rate from one to the next.
                (Some(g), Some((amplitude, period, rate))) if g > UNSTABLE_GROWTH_RATE => {
                    growth_rate = Some(rate);
                    Verdict::SlewLocked { amplitude, period }
                }
                (Some(g), None) if g > UNSTABLE_GROWTH_RATE => Verdict::Unstable { growth_rate: g },
                _ => Verdict::Stable,
            },
        };
        Metrics {
            time,
            max_error_slew: self.max_slew,
            max_error_after: self.max_after,
            rms_error: [(self.sum_sq[0] / n).sqrt(), (self.sum_sq[1] / n).sqrt()],
            growth_rate,
            errors_at_floor: at_floor,
            max_torque: self.max_torque,
            rms_error_rest: rms(self.rest_sum_sq, self.rest_samples),
            rms_torque: rms(self.torque_sq, self.samples),
            torque_fluctuation_rest: deviation(self.rest_torque_sum, self.rest_torque_sq, self.rest_samples),
            saturated: self.saturated.map(|k| k as f64 / n),
            error: self.last,
            verdict,
        }
    }
}

/// √(Σ/n) of each of two sums over `n` samples (0 for none).
fn rms(sum_sq: [f64; 2], n: u64) -> [f64; 2] {
    sum_sq.map(|s| if n == 0 { 0.0 } else { (s / n as f64).sqrt() })
}

/// The standard deviation of each of two series from its sum and sum of squares over `n` samples.
fn deviation(sum: [f64; 2], sum_sq: [f64; 2], n: u64) -> [f64; 2] {
    if n == 0 {
        return [0.0; 2];
    }
    let n = n as f64;
    [0, 1].map(|i| {
        let mean = sum[i] / n;
        (sum_sq[i] / n - mean * mean).max(0.0).sqrt()
    })
}
