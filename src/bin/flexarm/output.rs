//! Words and numbers the commands share: the configuration line, the verdicts.

use flexarm::control::Verdict;
use flexarm::SimulationConfig;

/// The verdict in words, e.g. "unstable (errors grow at 2.273 1/s)".
pub fn verdict_text(verdict: Verdict, bound: f64) -> String {
    flexarm::words::verdict::verdict(&verdict, bound)
}

/// "stable" for ρ < 1, else "unstable".
pub fn linear_verdict(rho: f64) -> &'static str {
    if rho < 1.0 {
        "stable"
    } else {
        "unstable"
    }
}

/// The configuration lines shared by the text outputs.
pub fn describe_config(c: &SimulationConfig) -> String {
    let k = &c.controller;
    format!(
        "  δ = {} s, α1 = {} 1/s, α2 = {} 1/s, k = {}, m = {} (ε = {:.3e} s, τ = kε = {:.3e} s)\n  \
         preliminary feedback {}, inner loop {}, friction compensation {}\n  arm: {}\n",
        k.sampling_period,
        k.alpha[0],
        k.alpha[1],
        k.horizon_steps,
        k.eps_ratio,
        k.integration_step(),
        k.horizon(),
        c.preliminary_feedback.name(),
        c.inner_loop.name(),
        c.friction_compensation.name(),
        flexarm::schema::arm_text(&c.plant.values())
    ) + if c.has_model_error() {
        "  the controller assumes the paper's arm (model = paper): a model error\n"
    } else {
        ""
    }
}

/// "δ = 0.01 s, α = 2 1/s" (or α1, α2 when they differ).
pub fn delta_alpha_text(c: &SimulationConfig) -> String {
    let k = &c.controller;
    if k.alpha[0] == k.alpha[1] {
        format!("δ = {} s, α = {} 1/s", k.sampling_period, k.alpha[0])
    } else {
        format!("δ = {} s, α1 = {} 1/s, α2 = {} 1/s", k.sampling_period, k.alpha[0], k.alpha[1])
    }
}
