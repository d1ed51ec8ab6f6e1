//! What the page says about a run, in words: the verdict, the observed growth, the linear
//! analysis, the readouts. Written here so that every number shown for one setting comes from
//! one place and cannot contradict another.

use serde::Serialize;

use super::maps::feedback_short;
use super::run::Run;
use crate::control::metrics::{DivergenceReason, Verdict};
use crate::plot::format::{sci, sig};

/// The readouts under the canvas.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Readouts {
    pub time: String,
    pub error: String,
    pub max_slew: String,
    pub max_after: String,
    pub torque: String,
    /// The δ → 0 pair A4 with the run's preliminary feedback.
    pub a4: String,
}

/// One run's status, in words and flags.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RunStatus {
    /// "A" or "B".
    pub run: &'static str,
    /// "stable", "unstable" or "diverged".
    pub verdict: &'static str,
    /// True while "stable" only means that nothing has grown yet (no growth rate fitted).
    pub observing: bool,
    /// The run has diverged and does not advance until a reset or a change.
    pub finished: bool,
    pub detail: String,
    /// "observed growth rate: 2.27 1/s".
    pub growth: String,
    /// "linear analysis: ρ = 1.0239 ≥ 1 ⇒ unstable (ln ρ/δ = 2.37 1/s)".
    pub rho: String,
    /// The spectral radius (null if the analysis failed).
    pub spectral_radius: Option<f64>,
    pub readouts: Readouts,
    /// "no K_pr, δ = 0.01 s, α = 2 1/s": which settings this run has.
    pub settings: String,
}

/// The status of `run`, named `name`.
pub fn run_status(name: &'static str, run: &Run) -> RunStatus {
    let sim = run.closed_loop();
    let m = sim.metrics();
    let s = sim.snapshot();
    let report = run.analysis().report();
    let rho = report.map(|r| r.spectral_radius);
    let detail = match m.verdict {
        Verdict::Diverged { at, reason } => {
            let why = match reason {
                DivergenceReason::ErrorBound => "an error exceeded the bound",
                DivergenceReason::NonFinite => "the state became non-finite",
                DivergenceReason::NewtonFailure => "the predictor's Newton iteration failed",
            };
            format!("diverged at t = {at:.2} s ({why}) — change a parameter or press reset")
        }
        // With a repeating slew the growth is measured cycle to cycle (two full cycles are
        // needed), so say what the linear analysis expects meanwhile.
        _ if m.growth_rate.is_none() => match rho {
            Some(r) if r >= 1.0 => "so far — no growth measured yet, but ρ ≥ 1 predicts the errors will grow".into(),
            _ => "so far — no growth measured yet".into(),
        },
        Verdict::Unstable { .. } => "the errors grow exponentially".into(),
        Verdict::Stable => "the errors stay bounded".into(),
    };
    let growth = match m.growth_rate {
        None => "observed growth rate: observing…".into(),
        Some(g) => format!("observed growth rate: {} 1/s", sig_fixed(g, 2)),
    };
    let rho_line = match report {
        None => "linear analysis: ρ = —".into(),
        Some(r) => {
            let verdict = if r.spectral_radius < 1.0 { "< 1 ⇒ stable" } else { "≥ 1 ⇒ unstable" };
            let growth = if r.growth_rate.is_finite() {
                format!(" (ln ρ/δ = {} 1/s)", sig_fixed(r.growth_rate, 2))
            } else {
                String::new()
            };
            format!("linear analysis: ρ = {:.4} {verdict}{growth}", r.spectral_radius)
        }
    };
    let pair = |v: [f64; 2], unit: &str| format!("{}, {} {unit}", sci(v[0], 3), sci(v[1], 3));
    let readouts = Readouts {
        time: format!("{:.2} s", m.time),
        error: pair(s.error, "rad"),
        max_slew: pair(m.max_error_slew, "rad"),
        max_after: pair(m.max_error_after, "rad"),
        torque: format!("{}, {} N m", sig(m.max_torque[0], 3), sig(m.max_torque[1], 3)),
        a4: report.map_or("—".into(), |r| {
            let [re, im] = r.limit_pair[0];
            format!("{} ± {}j 1/s", sig(re, 3), sig(im.abs(), 4))
        }),
    };
    RunStatus {
        run: name,
        verdict: m.verdict.label(),
        observing: matches!(m.verdict, Verdict::Stable) && m.growth_rate.is_none(),
        finished: sim.is_finished(),
        detail,
        growth,
        rho: rho_line,
        spectral_radius: rho,
        readouts,
        settings: describe(run),
    }
}

/// "no K_pr, δ = 0.01 s, α = 2 1/s".
pub fn describe(run: &Run) -> String {
    let s = run.settings();
    let alpha = if s.alpha[0] == s.alpha[1] {
        format!("α = {}", crate::plot::format::sig_trim(s.alpha[0], 3))
    } else {
        format!(
            "α = {}, {}",
            crate::plot::format::sig_trim(s.alpha[0], 3),
            crate::plot::format::sig_trim(s.alpha[1], 3)
        )
    };
    format!("{}, δ = {} s, {alpha} 1/s", feedback_short(s.pf), crate::plot::format::sig_trim(s.delta, 3))
}

/// Two decimals with a real minus sign ("2.27", "−0.35").
fn sig_fixed(v: f64, decimals: usize) -> String {
    crate::plot::format::minus(&format!("{v:.decimals$}"))
}
