//! Where the loop is stable along δ: the intervals of the sampling period with ρ < 1 for fixed
//! α, preliminary feedback and inner loop. Without preliminary feedback there are several such
//! windows (at α = 2 about 0.035–0.101 s, 0.107–0.116 s and 0.163–0.224 s): ρ is not monotone in δ.

use serde::Serialize;

use super::sampled::{LinearSettings, LoopModel};
use crate::error::Error;

/// Grid points of the scan that brackets the edges (logarithmic; ≈ 2 % apart over 2 ms – 0.25 s).
pub const SCAN_POINTS: usize = 240;
/// The edges are located to within this, s.
pub const EDGE_TOLERANCE: f64 = 1e-4;

/// The stable intervals of δ within a range.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StableWindows {
    /// The δ range searched, s.
    pub range: [f64; 2],
    /// The intervals [from, to] where ρ < 1, in increasing order, s. An interval that reaches an
    /// end of the range ends there (the loop may stay stable beyond it).
    pub windows: Vec<[f64; 2]>,
    /// Each edge inside the range lies within this of the true crossing of ρ = 1, s.
    pub tolerance: f64,
    /// The scan the edges were bracketed on: (δ, ρ), logarithmic in δ; ρ is NaN where the
    /// analysis failed. The ρ(δ) curve of the page.
    pub scan: Vec<[f64; 2]>,
}

impl StableWindows {
    /// True if δ lies in one of the windows.
    pub fn contains(&self, delta: f64) -> bool {
        self.windows.iter().any(|w| delta >= w[0] && delta <= w[1])
    }
}

/// The intervals of δ in `range` where ρ < 1 for `settings` (its δ is ignored): ρ on a
/// logarithmic scan of [`SCAN_POINTS`] points; then every local extremum of ρ near 1 that the
/// scan's points straddle is searched for (golden section), so that a narrow window — or a
/// narrow gap between two, as at α = 0.5 without K_pr near δ = 0.105 s, where the flexible pair
/// meets the Nyquist frequency — is not stepped over; then each change of sign of ρ − 1 is
/// bisected to [`EDGE_TOLERANCE`].
pub fn stable_windows(settings: &LinearSettings, range: [f64; 2]) -> Result<StableWindows, Error> {
    let model = LoopModel::new(settings)?;
    let deltas = super::stability_map::log_space(range[0], range[1], SCAN_POINTS);
    // A cell whose linear algebra fails counts as not stable.
    let rho_at = |d: f64| -> Result<f64, Error> {
        match model.spectral_radius(d) {
            Ok(r) => Ok(r),
            Err(Error::Analysis(_)) => Ok(f64::NAN),
            Err(e) => Err(e),
        }
    };
    let stable = |d: f64| model.spectral_radius(d).map(|r| r < 1.0);
    let mut scan = Vec::with_capacity(deltas.len());
    for &d in &deltas {
        scan.push([d, rho_at(d)?]);
    }
    // Between scan points the curve can dip across 1 and back: look inside every bracket whose
    // middle point is an extremum close to 1 on the same side as its neighbours.
    let mut samples = scan.clone();
    for i in 1..scan.len().saturating_sub(1) {
        let (l, m, r) = (scan[i - 1][1], scan[i][1], scan[i + 1][1]);
        if !(l.is_finite() && m.is_finite() && r.is_finite()) || (l < 1.0) != (m < 1.0) || (m < 1.0) != (r < 1.0) {
            continue;
        }
        let peak = m >= l && m >= r && m < 1.0 && m > 1.0 - NEAR;
        let dip = m <= l && m <= r && m >= 1.0 && m < 1.0 + NEAR;
        if !(peak || dip) {
            continue;
        }
        let sign = if peak { 1.0 } else { -1.0 };
        let (d, value) = golden_extremum(|d| rho_at(d).map(|v| sign * v), scan[i - 1][0], scan[i + 1][0])?;
        if (sign * value < 1.0) != (m < 1.0) {
            samples.push([d, sign * value]);
        }
    }
    crate::sort::sort_by(&mut samples, |a, b| a[0].total_cmp(&b[0]));
    let flags: Vec<bool> = samples.iter().map(|p| p[1] < 1.0).collect();
    // The crossing between a (stability `sa`) and b, by bisection.
    let edge = |mut a: f64, mut b: f64, sa: bool| -> f64 {
        while b - a > EDGE_TOLERANCE {
            let m = 0.5 * (a + b);
            if stable(m).unwrap_or(false) == sa {
                a = m;
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    };
    let at = |i: usize| samples[i][0];
    let mut windows = Vec::new();
    let mut start: Option<f64> = None;
    for i in 0..samples.len() {
        match (flags[i], start) {
            (true, None) => start = Some(if i == 0 { at(0) } else { edge(at(i - 1), at(i), false) }),
            (false, Some(s)) => {
                windows.push([s, edge(at(i - 1), at(i), true)]);
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        windows.push([s, at(samples.len() - 1)]);
    }
    Ok(StableWindows { range, windows, tolerance: EDGE_TOLERANCE, scan })
}

/// An extremum of ρ within this of 1 between scan points is searched for a crossing.
const NEAR: f64 = 0.05;

/// The maximum of `f` on [a, b] (assumed unimodal there) by golden section in log δ, to a
/// relative width of 1e-4: its δ and value.
fn golden_extremum(f: impl Fn(f64) -> Result<f64, Error>, a: f64, b: f64) -> Result<(f64, f64), Error> {
    const G: f64 = 0.618_033_988_749_894_8;
    let (mut lo, mut hi) = (a.ln(), b.ln());
    let mut x1 = hi - G * (hi - lo);
    let mut x2 = lo + G * (hi - lo);
    let (mut f1, mut f2) = (f(x1.exp())?, f(x2.exp())?);
    while hi - lo > 1e-4 {
        if f1 >= f2 {
            hi = x2;
            (x2, f2) = (x1, f1);
            x1 = hi - G * (hi - lo);
            f1 = f(x1.exp())?;
        } else {
            lo = x1;
            (x1, f1) = (x2, f2);
            x2 = lo + G * (hi - lo);
            f2 = f(x2.exp())?;
        }
    }
    Ok(if f1 >= f2 { (x1.exp(), f1) } else { (x2.exp(), f2) })
}

/// The δ intervals of one grid row where ρ < 1: runs of stable cells whose ends are moved to the
/// crossing of ρ = 1, interpolated linearly in log δ (a run that reaches the end of the grid, or
/// a NaN cell, ends at that grid point). A map's summary; [`stable_windows`] is the precise search.
pub fn stable_intervals(deltas: &[f64], rho: &[f64]) -> Vec<[f64; 2]> {
    let crossing = |a: usize, b: usize| {
        let (ra, rb) = (rho[a], rho[b]);
        if !(ra.is_finite() && rb.is_finite()) || ra == rb {
            return None;
        }
        let t = (1.0 - ra) / (rb - ra);
        Some((deltas[a].ln() + t * (deltas[b].ln() - deltas[a].ln())).exp())
    };
    let n = deltas.len().min(rho.len());
    let mut out = Vec::new();
    let mut j = 0;
    while j < n {
        if rho[j] < 1.0 {
            let start = j;
            while j + 1 < n && rho[j + 1] < 1.0 {
                j += 1;
            }
            let lo = if start > 0 { crossing(start - 1, start).unwrap_or(deltas[start]) } else { deltas[start] };
            let hi = if j + 1 < n { crossing(j, j + 1).unwrap_or(deltas[j]) } else { deltas[j] };
            out.push([lo, hi]);
        }
        j += 1;
    }
    out
}
