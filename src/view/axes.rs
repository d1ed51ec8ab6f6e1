//! Axis ticks on the 1-2-5 × 10^k ladder and the autoscale of the error and torque plots.
//!
//! The errors span many decades: about 1e-4 rad in a stable run, up to π rad when a run
//! diverges. The plots therefore use a symmetric range ±Y with Y the next "nice" number above the
//! largest visible |value|, and a hysteresis so the scale does not flicker: it grows at once but
//! shrinks only after the data have stayed well below it for a while.

/// The smallest number of the form {1, 2, 5} × 10^k that is ≥ `v`, for `v > 0`.
///
/// Returns `v` unchanged if it is not a positive finite number.
pub fn nice_ceil(v: f64) -> f64 {
    if !(v > 0.0 && v.is_finite()) {
        return v;
    }
    let mut decade = 10f64.powi(v.log10().floor() as i32);
    // log10 may land one decade off for exact powers of ten; correct it.
    if v / decade >= 10.0 {
        decade *= 10.0;
    } else if v / decade < 1.0 {
        decade /= 10.0;
    }
    const RELATIVE_SLACK: f64 = 1e-9;
    let m = v / decade;
    let mantissa = [1.0, 2.0, 5.0, 10.0].into_iter().find(|&c| m <= c * (1.0 + RELATIVE_SLACK)).unwrap_or(10.0);
    mantissa * decade
}

/// Evenly spaced "nice" tick values inside [lo, hi]: an iterator, so drawing allocates nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ticks {
    /// Spacing between ticks.
    pub step: f64,
    next: i64,
    last: i64,
}

impl Ticks {
    /// At most `max_count + 1` ticks in [lo, hi] with a step of 1, 2 or 5 × 10^k, including 0 when it
    /// lies in the range. Empty for an empty or non-finite range.
    pub fn new(lo: f64, hi: f64, max_count: usize) -> Ticks {
        let empty = Ticks { step: 0.0, next: 1, last: 0 };
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return empty;
        }
        let step = nice_ceil((hi - lo) / max_count.max(1) as f64);
        if !(step > 0.0 && step.is_finite()) {
            return empty;
        }
        // Tolerance so that ticks at the ends of [lo, hi] survive rounding.
        const EDGE: f64 = 1e-9;
        let first = (lo / step - EDGE).ceil();
        let last = (hi / step + EDGE).floor();
        if !(first.abs() < 1e15 && last.abs() < 1e15) {
            return empty;
        }
        Ticks { step, next: first as i64, last: last as i64 }
    }
}

impl Iterator for Ticks {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        if self.next > self.last {
            return None;
        }
        let k = self.next;
        self.next += 1;
        // k × step (not a running sum), so ticks carry no accumulated rounding; 0 stays 0.
        Some(k as f64 * self.step)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = (self.last - self.next + 1).max(0) as usize;
        (n, Some(n))
    }
}

/// Settings of an [`Autoscale`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AutoscaleSettings {
    /// The smallest half-range Y, in the data's unit (keeps rounding noise from filling a plot).
    pub floor: f64,
    /// Y is at least this factor above the data maximum, so the curve never touches the frame.
    pub headroom: f64,
    /// The scale may shrink once the data maximum is below this fraction of Y ...
    pub shrink_below: f64,
    /// ... continuously for this long (s of simulated time).
    pub shrink_after: f64,
}

impl AutoscaleSettings {
    /// Errors in rad: floor 1e-6 rad.
    pub const ERROR: AutoscaleSettings =
        AutoscaleSettings { floor: 1e-6, headroom: 1.1, shrink_below: 1.0 / 3.0, shrink_after: 1.0 };
    /// Torques in N m: floor 1e-3 N m.
    pub const TORQUE: AutoscaleSettings =
        AutoscaleSettings { floor: 1e-3, headroom: 1.1, shrink_below: 1.0 / 3.0, shrink_after: 1.0 };
}

/// A symmetric range ±Y that follows the data with hysteresis: grows at once, shrinks slowly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Autoscale {
    settings: AutoscaleSettings,
    limit: f64,
    /// Since when the data have been below `shrink_below × limit`.
    low_since: Option<f64>,
}

impl Autoscale {
    pub fn new(settings: AutoscaleSettings) -> Self {
        Self { settings, limit: settings.floor, low_since: None }
    }

    /// The current half-range Y: the plot shows [−Y, Y].
    pub fn limit(&self) -> f64 {
        self.limit
    }

    /// Back to the floor (after a reset of the simulation).
    pub fn reset(&mut self) {
        self.limit = self.settings.floor;
        self.low_since = None;
    }

    /// The Y this data maximum would get without hysteresis.
    pub fn target(&self, data_max: f64) -> f64 {
        let wanted = if data_max.is_finite() { data_max.abs() * self.settings.headroom } else { 0.0 };
        nice_ceil(wanted.max(self.settings.floor))
    }

    /// Takes the largest visible |value| at simulated time `now` and returns the new Y.
    /// A non-finite maximum (a diverged sample) is ignored.
    pub fn update(&mut self, data_max: f64, now: f64) -> f64 {
        if !data_max.is_finite() {
            return self.limit;
        }
        let target = self.target(data_max);
        if target > self.limit {
            self.limit = target;
            self.low_since = None;
        } else if data_max.abs() < self.settings.shrink_below * self.limit {
            let since = match self.low_since {
                Some(s) if s <= now => s,
                _ => now,
            };
            self.low_since = Some(since);
            if now - since >= self.settings.shrink_after {
                self.limit = target;
                self.low_since = None;
            }
        } else {
            self.low_since = None;
        }
        self.limit
    }
}

/// Tick values for a logarithmic axis over [lo, hi] (both > 0): 1, 2, 5 × 10^k when at most
/// `max_count + 1` of them fit, else 1 and 5 × 10^k, else only the powers of ten (every decade,
/// or every 2nd, 3rd, ... decade on very long ranges). A range too short to hold two such ticks gets 1, 2, ..., 9 × 10^k.
/// Empty for an empty, non-positive or non-finite range.
///
/// Values are built as m × 10^k or m / 10^−k from exact integers, so 0.002 is the double
/// nearest to 0.002 (labels print cleanly).
pub fn log_ticks(lo: f64, hi: f64, max_count: usize) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Vec::new();
    }
    let max_count = max_count.max(1);
    let first = lo.log10().floor() as i32 - 1;
    let last = hi.log10().ceil() as i32 + 1;
    if last - first > 600 {
        return Vec::new();
    }
    let collect = |mantissas: &[f64], decade_step: i32| -> Vec<f64> {
        let mut out = Vec::new();
        let mut k = first;
        // Align the decades to multiples of the step so that 10^0 stays a tick.
        k -= k.rem_euclid(decade_step);
        while k <= last {
            for &m in mantissas {
                let v = power_of_ten_times(m, k);
                if v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9) {
                    out.push(v);
                }
            }
            k += decade_step;
        }
        out
    };
    let fine = collect(&[1.0, 2.0, 5.0], 1);
    if fine.len() < 2 {
        return collect(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0], 1);
    }
    if fine.len() <= max_count + 1 {
        return fine;
    }
    let medium = collect(&[1.0, 5.0], 1);
    if medium.len() <= max_count + 1 && medium.len() >= 2 {
        return medium;
    }
    let mut step = 1;
    loop {
        let coarse = collect(&[1.0], step);
        if coarse.len() <= max_count + 1 || step > 600 {
            return coarse;
        }
        step += 1;
    }
}

/// m × 10^k computed from exact integers (for |k| ≤ 22 the power is exact).
fn power_of_ten_times(m: f64, k: i32) -> f64 {
    if k >= 0 {
        m * 10f64.powi(k)
    } else {
        m / 10f64.powi(-k)
    }
}
