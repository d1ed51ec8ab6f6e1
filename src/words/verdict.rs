//! The simulation's own verdict in words ([`Verdict`] is a value: stable, unstable, a limit
//! cycle, errors locked to the slews, diverged), its growth rate, and why a run diverged — one
//! wording, for the CLI's summary and table and the page's observation alike.

use crate::control::metrics::{DivergenceReason, Verdict};

/// Why a run diverged: "a tracking error passed π rad" (`bound`, rad, the error bound), "the state
/// became non-finite (NaN or infinite)", "the predictor's Newton iteration failed".
pub fn divergence_reason(reason: DivergenceReason, bound: f64) -> String {
    match reason {
        DivergenceReason::ErrorBound if bound == core::f64::consts::PI => "a tracking error passed π rad".into(),
        DivergenceReason::ErrorBound => format!("a tracking error passed {bound:.4} rad"),
        DivergenceReason::NonFinite => "the state became non-finite (NaN or infinite)".into(),
        DivergenceReason::NewtonFailure => solver_failure().into(),
    }
}

/// A run the predictor's Newton iteration stopped, in words: what failed, and that it is a
/// numerical failure, not the arm's.
pub fn solver_failure() -> &'static str {
    "the predictor's Newton iteration did not converge — a numerical failure of the solver, not the arm's dynamics"
}

/// The verdict in a sentence, e.g. "unstable (errors grow at 2.273 1/s)"; `bound` is the
/// divergence bound, rad.
pub fn verdict(v: &Verdict, bound: f64) -> String {
    match *v {
        Verdict::Stable => "stable".into(),
        Verdict::Unstable { growth_rate } => format!("unstable (errors grow at {growth_rate:.3} 1/s)"),
        Verdict::BoundedOscillation { amplitude, period } => format!(
            "bounded oscillation (a limit cycle: amplitude {:.2e}, {:.2e} rad, period {period:.2} s)",
            amplitude[0], amplitude[1]
        ),
        Verdict::SlewLocked { amplitude, period } => format!(
            "stable (the errors come back with every slew, no larger: up to {:.2e}, {:.2e} rad, every {period:.2} s)",
            amplitude[0], amplitude[1]
        ),
        Verdict::Diverged { at, reason: DivergenceReason::NewtonFailure } => {
            format!("stopped at t = {at:.3} s ({})", solver_failure())
        }
        Verdict::Diverged { at, reason } => format!("diverged at t = {at:.3} s ({})", divergence_reason(reason, bound)),
    }
}

/// The verdict in a table cell: "unstable (2.27 1/s)", "limit cycle (7.8 s)", "diverged at 1.23 s".
pub fn verdict_short(v: &Verdict) -> String {
    match *v {
        Verdict::Stable => "stable".into(),
        Verdict::Unstable { growth_rate } => format!("unstable ({growth_rate:.2} 1/s)"),
        Verdict::BoundedOscillation { period, .. } => format!("bounded oscillation ({period:.2} s)"),
        Verdict::SlewLocked { period, .. } => format!("stable (repeats every {period:.2} s)"),
        Verdict::Diverged { at, reason: DivergenceReason::NewtonFailure } => format!("solver failed at {at:.2} s"),
        Verdict::Diverged { at, .. } => format!("diverged at {at:.2} s"),
    }
}

/// The errors' observed growth rate: "2.27 1/s" (never "−0.00"), "none (errors at their floor)",
/// or "n/a (run too short)".
pub fn growth(growth_rate: Option<f64>, at_floor: bool) -> String {
    match (growth_rate, at_floor) {
        (Some(g), _) => format!("{:.2} 1/s", if g.abs() < 0.005 { 0.0 } else { g }),
        (None, true) => "none (errors at their floor)".into(),
        (None, false) => "n/a (run too short)".into(),
    }
}
