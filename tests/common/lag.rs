//! The lag law against the exact sampled loop on one arm (`tests/lag.rs`, `tests/lag_bias.rs`):
//! the paper's arm scaled, no preliminary feedback, at rest with q2 = 0.

use flexarm::analysis::lag::LagLaw;
use flexarm::analysis::{stable_windows, LinearSettings, LoopModel, StableWindows};
use flexarm::*;

/// The paper's arm with K1, I_r1 and B_v1 scaled by these factors, α1 = α2 = `alpha`, no
/// preliminary feedback.
pub fn config(k1: f64, ir1: f64, bv1: f64, alpha: f64) -> SimulationConfig {
    let mut c = SimulationConfig::default();
    c.plant.k1 *= k1;
    c.plant.ir1 *= ir1;
    c.plant.bv1 *= bv1;
    c.controller.alpha = [alpha; 2];
    c.preliminary_feedback = PreliminaryFeedbackChoice::Off;
    c
}

/// What ends the loop's first window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    /// The flexible pair: it sets ρ just past the edge.
    Swing,
    /// Another (slow) mode sets ρ just past the edge: the window runs on past the swing's end.
    Slow,
    /// The window reaches the end of the searched range.
    Range,
}

/// The law and the loop's window it describes on one arm.
#[derive(Clone, Debug)]
pub struct Measured {
    pub law: LagLaw,
    /// The law's window [lower turn/ω, π/ω], s.
    pub law_window: [f64; 2],
    /// The loop's first stable window, s: its lower edge (set by the flexible pair, asserted) and
    /// upper edge, each located to a relative 1e-6 on ρ = 1.
    pub window: [f64; 2],
    pub end: End,
    /// All the loop's windows in the range (as `stable_windows` locates them).
    pub windows: StableWindows,
}

impl Measured {
    /// The true lower edge over the law's.
    pub fn lower_ratio(&self) -> f64 {
        self.window[0] / self.law_window[0]
    }
}

/// Whether the flexible pair sets ρ at δ (either eigenvalue of the pair, which splits into two
/// real ones at the Nyquist frequency).
pub fn swing_sets_rho(model: &LoopModel, delta: f64) -> bool {
    let r = model.report_at(delta).unwrap();
    r.flexible_pair().iter().flatten().any(|&i| {
        let [re, im] = r.poles[i].discrete;
        (re.hypot(im) - r.spectral_radius).abs() < 1e-9
    })
}

/// The crossing of ρ = 1 between a and b (stable at exactly one of them), to a relative 1e-6.
fn crossing(model: &LoopModel, mut a: f64, mut b: f64) -> f64 {
    let stable = |d: f64| model.spectral_radius(d).unwrap() < 1.0;
    let sa = stable(a);
    assert_ne!(sa, stable(b), "no crossing of ρ = 1 between {a} and {b} s");
    while b - a > 1e-6 * b {
        let m = 0.5 * (a + b);
        if stable(m) == sa {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// The law of `c` and the loop's first stable window in `range` (the window the law describes:
/// at the smallest δ the swing grows, and the first window is where it stops). `None` where the
/// law has no window — the motor damps the swing at every small δ —, after checking that the
/// loop is then stable from the range's start.
pub fn measure(c: &SimulationConfig, range: [f64; 2]) -> Option<Measured> {
    let settings = LinearSettings::of(c, Some(0.0));
    let model = LoopModel::new(&settings).unwrap();
    let law = LagLaw::of(&model.report().unwrap());
    let windows = stable_windows(&settings, range).unwrap();
    let Some(law_window) = law.window() else {
        assert!(windows.windows.first().is_some_and(|w| w[0] <= range[0]), "{:?}: {:?}", c.plant, windows.windows);
        return None;
    };
    let case =
        format!("K1 = {}, I_r1 = {}, B_v1 = {}, α = {:?}", c.plant.k1, c.plant.ir1, c.plant.bv1, c.controller.alpha);
    let w = *windows.windows.first().unwrap_or_else(|| panic!("{case}: no window in {range:?}"));
    assert!(w[0] > range[0] && w[1] > law_window[0], "{case}: first window {w:?}, the law's {law_window:?}");
    let tol = windows.tolerance;
    let lower = crossing(&model, (w[0] - tol).max(range[0]), w[0] + tol);
    assert!(swing_sets_rho(&model, lower * (1.0 - 1e-3)), "{case}: the swing does not set ρ below {lower} s");
    let (upper, end) = if w[1] >= range[1] {
        (w[1], End::Range)
    } else {
        let upper = crossing(&model, w[1] - tol, w[1] + tol);
        (upper, if swing_sets_rho(&model, upper * (1.0 + 1e-3)) { End::Swing } else { End::Slow })
    };
    Some(Measured { law, law_window, window: [lower, upper], end, windows })
}
