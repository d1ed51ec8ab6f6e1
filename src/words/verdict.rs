//! The simulation's own verdict in words ([`Verdict`] is a value: stable, unstable, a limit
//! cycle, errors locked to the slews, diverged), its growth rate, and why a run diverged. The
//! judgement a run is given — ρ's, unless the simulation saw more — is
//! [`crate::words::judgement`]'s; this is what the simulation alone measured.

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

/// The simulation's own verdict in a table cell (a benchmark's line): "unstable (2.27 1/s)",
/// "bounded oscillation (7.80 s)", "diverged at 1.23 s".
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
