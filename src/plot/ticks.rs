//! Axis ticks on the 1-2-5 × 10^k ladder, linear ([`Ticks`]) and logarithmic ([`log_ticks`]),
//! and the choice of which log ticks get a label when they crowd ([`label_log_ticks`]). The
//! canvas's plots, their HTML labels and the SVG figures all take their ticks from here.

/// The smallest number of the form {1, 2, 5} × 10^k that is ≥ `v`, for `v > 0`.
///
/// Returns `v` unchanged if it is not a positive finite number.
pub fn nice_ceil(v: f64) -> f64 {
    match nice_ceil_parts(v) {
        Some((m, k)) => power_of_ten_times(m as f64, k),
        None => v,
    }
}

/// [`nice_ceil`] as (mantissa 1, 2 or 5, exponent k).
fn nice_ceil_parts(v: f64) -> Option<(i64, i32)> {
    if !(v > 0.0 && v.is_finite()) {
        return None;
    }
    let mut k = v.log10().floor() as i32;
    // log10 may land one decade off for exact powers of ten; correct it.
    if v / power_of_ten_times(1.0, k) >= 10.0 {
        k += 1;
    } else if v / power_of_ten_times(1.0, k) < 1.0 {
        k -= 1;
    }
    const RELATIVE_SLACK: f64 = 1e-9;
    let m = v / power_of_ten_times(1.0, k);
    Some(match [1, 2, 5].into_iter().find(|&c| m <= c as f64 * (1.0 + RELATIVE_SLACK)) {
        Some(c) => (c, k),
        None => (1, k + 1),
    })
}

/// Evenly spaced "nice" tick values inside [lo, hi]: an iterator, so drawing allocates nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ticks {
    /// Spacing between ticks.
    pub step: f64,
    /// step = mantissa × 10^exponent, kept apart so that every tick is an exact decimal.
    mantissa: i64,
    exponent: i32,
    next: i64,
    last: i64,
}

impl Ticks {
    /// At most `max_count + 1` ticks in [lo, hi] with a step of 1, 2 or 5 × 10^k, including 0 when it
    /// lies in the range. Empty for an empty or non-finite range.
    pub fn new(lo: f64, hi: f64, max_count: usize) -> Ticks {
        let empty = Ticks { step: 0.0, mantissa: 0, exponent: 0, next: 1, last: 0 };
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return empty;
        }
        let Some((mantissa, exponent)) = nice_ceil_parts((hi - lo) / max_count.max(1) as f64) else {
            return empty;
        };
        let step = power_of_ten_times(mantissa as f64, exponent);
        if !(step > 0.0 && step.is_finite()) {
            return empty;
        }
        // Tolerance so that ticks at the ends of [lo, hi] survive rounding.
        const EDGE: f64 = 1e-9;
        let first = (lo / step - EDGE).ceil();
        let last = (hi / step + EDGE).floor();
        if !(first.abs() < 1e14 && last.abs() < 1e14) {
            return empty;
        }
        Ticks { step, mantissa, exponent, next: first as i64, last: last as i64 }
    }
}

impl Ticks {
    /// [`Ticks::new`] with at least `least` ticks where up to four more intervals give them: a
    /// short axis (a projector's large text) keeps three labels rather than one or two.
    pub fn at_least(lo: f64, hi: f64, max_count: usize, least: usize) -> Ticks {
        Ticks::first_with(lo, hi, max_count, 4, |t| t.len() >= least).unwrap_or(Ticks::new(lo, hi, max_count))
    }

    /// The first of [`Ticks::new`] for `count`, `count + 1`, … `count + extra` intervals that is
    /// `enough` (more ticks, smaller steps, until the axis has what it needs), or None.
    pub fn first_with(lo: f64, hi: f64, count: usize, extra: usize, enough: impl Fn(Ticks) -> bool) -> Option<Ticks> {
        (count..=count + extra).map(|n| Ticks::new(lo, hi, n)).find(|t| enough(*t))
    }
}

impl ExactSizeIterator for Ticks {}

impl Iterator for Ticks {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        if self.next > self.last {
            return None;
        }
        let k = self.next;
        self.next += 1;
        // (k × mantissa) × 10^exponent from exact integers: no accumulated rounding, 0.6 not
        // 0.6000000000000001, and 0 stays 0.
        Some(power_of_ten_times((k * self.mantissa) as f64, self.exponent))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = (self.last - self.next + 1).max(0) as usize;
        (n, Some(n))
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
pub fn power_of_ten_times(m: f64, k: i32) -> f64 {
    if k >= 0 {
        m * 10f64.powi(k)
    } else {
        m / 10f64.powi(-k)
    }
}

/// The minor ticks of a log axis: 1…9 × 10^k in [lo, hi] that are not in `major`.
pub fn log_minor_ticks(lo: f64, hi: f64, major: &[f64]) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Vec::new();
    }
    let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    if k1 - k0 > 30 {
        return Vec::new();
    }
    let mut out = Vec::new();
    for k in k0..=k1 {
        for m in 1..=9 {
            let v = power_of_ten_times(m as f64, k);
            let inside = v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
            if inside && !major.iter().any(|t| (t / v - 1.0).abs() < 1e-9) {
                out.push(v);
            }
        }
    }
    out
}

/// Which values of a log axis get a label when the axis is `length` pixels long and labels need
/// `min_spacing` pixels: the grid ticks `ticks` first, then the other 1-2-5 values (decades, then
/// 5s, then 2s), each kept only if it is at least `min_spacing` from every label kept so far.
/// Returned in increasing order.
pub fn label_log_ticks(ticks: &[f64], lo: f64, hi: f64, length: f64, min_spacing: f64) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && hi.is_finite() && length > 0.0) {
        return Vec::new();
    }
    let pos = |v: f64| (v / lo).ln() / (hi / lo).ln() * length;
    let rank = |v: f64| {
        let m = (v / power_of_ten_times(1.0, (v.log10() + 1e-9).floor() as i32)).round() as i64;
        match m {
            1 => 0,
            5 => 1,
            2 => 2,
            _ => 3,
        }
    };
    let near = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-6;
    let extra = log_ticks(lo, hi, usize::MAX / 2);
    let mut candidates: Vec<(bool, f64)> = ticks.iter().filter(|v| **v > 0.0).map(|&v| (true, v)).collect();
    for v in extra {
        if !candidates.iter().any(|(_, c)| near(*c, v)) {
            candidates.push((false, v));
        }
    }
    crate::sort::sort_by(&mut candidates, |a, b| {
        b.0.cmp(&a.0).then(rank(a.1).cmp(&rank(b.1))).then(a.1.total_cmp(&b.1))
    });
    let mut kept: Vec<(f64, f64)> = Vec::new();
    for (_, v) in candidates {
        let q = pos(v);
        if kept.iter().all(|(_, k)| (k - q).abs() >= min_spacing) {
            kept.push((v, q));
        }
    }
    crate::sort::sort_by(&mut kept, |a, b| a.0.total_cmp(&b.0));
    kept.into_iter().map(|(v, _)| v).collect()
}

/// The powers of ten in [lo, hi] (lo > 0), without allocating: the grid of a log |e| plot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decades {
    next: i32,
    last: i32,
}

impl Decades {
    pub fn new(lo: f64, hi: f64) -> Decades {
        if !(lo > 0.0 && hi > lo && hi.is_finite()) {
            return Decades { next: 1, last: 0 };
        }
        Decades { next: (lo.log10() - 1e-9).ceil() as i32, last: (hi.log10() + 1e-9).floor() as i32 }
    }
}

impl Iterator for Decades {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        if self.next > self.last {
            return None;
        }
        self.next += 1;
        Some(power_of_ten_times(1.0, self.next - 1))
    }
}
