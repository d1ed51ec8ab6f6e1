//! Property tests over random valid configurations (proptest): no panic, no NaN or infinity in
//! any output, the same result twice, the CLI's JSON always parseable, and — the paper's claim
//! in its linear form — ρ < 1 ⇔ a small poke at rest dies out, ρ > 1 ⇔ it grows.
//!
//! The case counts are printed by the README's test command (`cargo test` shows them per test
//! name); each property states its count in `ProptestConfig::with_cases`.

use std::process::Command;

use flexarm::analysis::spectral_radius;
use flexarm::control::Traces;
use flexarm::*;
use proptest::prelude::*;
use proptest::test_runner::{Config as ProptestConfig, RngSeed};

/// `cases` cases from a fixed seed: the suite checks the same configurations on every run (a
/// failure reproduces), and writes no regression files into the checkout. Change the seed to
/// explore others.
fn cases(cases: u32) -> ProptestConfig {
    ProptestConfig { cases, rng_seed: RngSeed::Fixed(1994), failure_persistence: None, ..ProptestConfig::default() }
}

/// A random valid configuration: every choice, δ and α over the page's controls (log-uniform),
/// k and m anywhere the controller allows (k/2 ≤ m ≤ k).
fn configs() -> impl Strategy<Value = SimulationConfig> {
    ((-3.0f64..-0.6, -1.0f64..0.7, 0usize..3, 0usize..3, 0usize..2, any::<bool>()), (4usize..=24, 0.0f64..=1.0))
        .prop_map(|((log_delta, log_alpha, pf, friction, inner, repeat), (k, m))| {
            let mut c = SimulationConfig::default();
            c.controller.sampling_period = 10f64.powf(log_delta);
            c.controller.alpha = [10f64.powf(log_alpha); 2];
            c.controller.horizon_steps = k;
            c.controller.eps_ratio = k as f64 * (0.5 + 0.5 * m);
            c.preliminary_feedback =
                [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper, PreliminaryFeedbackChoice::Lq][pf];
            c.friction_compensation =
                [FrictionCompensation::Continuous, FrictionCompensation::Held, FrictionCompensation::Off][friction];
            c.inner_loop = [InnerLoop::Continuous, InnerLoop::Sampled][inner];
            if repeat {
                c.reference.repeat_hold = Some(1.5);
            }
            c
        })
}

fn metrics_finite(m: &Metrics) -> bool {
    let pairs = [m.max_error_slew, m.max_error_after, m.rms_error, m.max_torque];
    m.time.is_finite() && pairs.iter().flatten().all(|v| v.is_finite()) && m.growth_rate.is_none_or(f64::is_finite)
}

/// Every recorded value is finite, except the last row of a run whose state became non-finite
/// (that row records the moment it ended).
fn traces_finite(t: &Traces, verdict: Verdict) -> bool {
    let rows = match verdict {
        Verdict::Diverged { reason: control::DivergenceReason::NonFinite, .. } => t.len().saturating_sub(1),
        _ => t.len(),
    };
    control::Column::ALL.iter().all(|c| t.column(*c)[..rows].iter().all(|v| v.is_finite()))
}

proptest! {
    #![proptest_config(cases(1000))]

    /// 1000 random configurations run 2.5 s (past the slew): no panic, finite metrics and
    /// traces, finite ρ, and the same run twice to the last bit.
    #[test]
    fn any_valid_configuration_runs_finite_and_deterministic(c in configs()) {
        let a = simulate(&c, 2.5).expect("a valid configuration runs");
        prop_assert!(metrics_finite(&a.metrics), "{:?}", a.metrics);
        prop_assert!(traces_finite(&a.traces, a.metrics.verdict));
        let rho = spectral_radius(&c, None).expect("ρ of a valid configuration");
        prop_assert!(rho.is_finite() && rho >= 0.0, "ρ = {rho}");
        let b = simulate(&c, 2.5).unwrap();
        prop_assert_eq!(&a, &b);
        prop_assert_eq!(rho.to_bits(), spectral_radius(&c, None).unwrap().to_bits());
    }
}

/// Errors above this (rad, ≈ 30°) from a poke of 0.01 N m have left the linear regime: they grew
/// (a stable loop at δ = 0.25 s answers the poke with at most ≈ 0.07 rad).
const LINEAR_REGIME: f64 = 0.5;

/// The loop at rest at the analysis point (the end of the slew), poked by a small torque.
fn poked_at_rest(c: &SimulationConfig, duration: f64) -> Result<(ClosedLoop, [f64; 2]), Error> {
    let mut c = *c;
    c.reference.start = c.reference.end;
    c.reference.repeat_hold = None;
    let mut sim = ClosedLoop::new(c)?;
    sim.apply_disturbance([1e-2, 1e-2], 0.05)?;
    // The largest error in the second and the last quarter of the run (the first lets the
    // faster modes die out).
    let mut max = [0.0f64; 2];
    let quarter = duration / 4.0;
    for i in 0..4 {
        sim.traces_mut().clear();
        sim.advance(quarter)?;
        let e = sim.traces();
        let quarter_max = e.e1().iter().chain(e.e2()).fold(0.0f64, |m, v| m.max(v.abs()));
        if sim.is_finished() || quarter_max > LINEAR_REGIME {
            // It grew out of the linear regime (and maybe diverged): growth without doubt.
            max[1] = f64::INFINITY;
            break;
        }
        if i % 2 == 1 {
            max[i / 2] = quarter_max;
        }
    }
    Ok((sim, max))
}

proptest! {
    #![proptest_config(cases(300))]

    /// The linear claim, 300 cases (those with |ρ − 1| > 0.02 and a run ≤ 60 s): with the friction cancelled
    /// (continuous compensation), a poke of 0.01 N m for 50 ms at rest dies out when ρ < 1 and
    /// grows when ρ > 1. The run lasts 12/|ln ρ/δ|, at most 60 s: the slowest mode changes by
    /// e⁶ between its second and last quarters, enough to outgrow modes that start larger and
    /// decay nearly as slowly (e.g. λ = −1.04 beside four at 0.96).
    #[test]
    fn rho_below_one_iff_a_small_poke_dies_out(c in configs()) {
        let mut c = c;
        c.friction_compensation = FrictionCompensation::Continuous;
        let delta = c.controller.sampling_period;
        let rho = spectral_radius(&c, None).unwrap();
        prop_assume!((rho - 1.0).abs() > 0.02);
        let rate = rho.ln() / delta;
        let duration = (12.0 / rate.abs()).max(20.0 * delta).max(0.5);
        prop_assume!(duration <= 60.0);
        let (_, [first, second]) = poked_at_rest(&c, duration).unwrap();
        if rho < 1.0 {
            prop_assert!(second < first, "ρ = {rho}: max |e| {first:e} then {second:e} over {duration} s");
        } else {
            prop_assert!(second > first, "ρ = {rho}: max |e| {first:e} then {second:e} over {duration} s");
        }
    }
}

fn query(c: &SimulationConfig) -> String {
    let pf = c.preliminary_feedback.name();
    let friction = c.friction_compensation.name();
    let inner = c.inner_loop.name();
    let k = &c.controller;
    format!(
        "delta={}&alpha={}&pf={pf}&friction={friction}&inner={inner}&repeat={}&k={}&eps_ratio={}",
        k.sampling_period,
        k.alpha[0],
        u8::from(c.reference.repeat_hold.is_some()),
        k.horizon_steps,
        k.eps_ratio
    )
}

proptest! {
    #![proptest_config(cases(150))]

    /// 150 random configurations through the command line: `simulate --json` always prints one
    /// JSON object with finite numbers (or null where a value does not exist), the verdict one
    /// of the four names.
    #[test]
    fn the_clis_json_is_always_parseable(c in configs()) {
        let state = query(&c);
        let out = Command::new(env!("CARGO_BIN_EXE_flexarm"))
            .args(["simulate", "--state", &state, "--duration", "2", "--json"])
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        prop_assert!(out.status.success(), "{state}: {}", String::from_utf8_lossy(&out.stderr));
        let v: serde_json::Value = serde_json::from_str(&stdout).map_err(|e| TestCaseError::fail(format!("{e}: {stdout}")))?;
        let verdict = v["verdict"].as_str().unwrap_or("");
        prop_assert!(
            ["stable", "unstable", "borderline", "bounded", "bounded oscillation", "diverged", "too early to tell"].contains(&verdict),
            "{verdict}"
        );
        prop_assert!(v["spectral_radius"].as_f64().is_some_and(f64::is_finite), "{stdout}");
        prop_assert!(v["growth"].is_string());
    }
}

proptest! {
    #![proptest_config(cases(2000))]

    /// 2000 random grids (2–40 nodes a side, a cone with a random apex, a level through a random
    /// node — the degenerate case — and random unknown cells): the contour's segments chain into
    /// polylines that use every segment exactly once, join only at shared endpoints, and the
    /// chaining ends. `chain_segments` marks one segment used per step, so it cannot loop; this
    /// checks the bookkeeping that argument rests on (the cone test in tests/view.rs once failed
    /// and then hung under parallel builds: the hang was the build, not this code).
    #[test]
    fn contours_chain_every_segment_once(
        nx in 2usize..40, ny in 2usize..40, apex in (-1.0f64..1.0, -1.0f64..1.0),
        node in (0usize..40, 0usize..40), holes in proptest::collection::vec(0usize..1600, 0..6),
    ) {
        use flexarm::plot::contour::{chain_segments, marching_squares};
        let xs: Vec<f64> = (0..nx).map(|i| -2.0 + 4.0 * i as f64 / (nx - 1) as f64).collect();
        let ys: Vec<f64> = (0..ny).map(|i| -2.0 + 4.0 * i as f64 / (ny - 1) as f64).collect();
        let mut values: Vec<f64> =
            ys.iter().flat_map(|&y| xs.iter().map(move |&x| (x - apex.0).hypot(y - apex.1))).collect();
        let level = values[(node.1 % ny) * nx + node.0 % nx];
        for h in holes {
            if h < values.len() {
                values[h] = f64::NAN;
            }
        }
        let segments = marching_squares(&xs, &ys, &values, level);
        let lines = chain_segments(&segments);
        let used: usize = lines.iter().map(|l| l.len() - 1).sum();
        prop_assert_eq!(used, segments.len());
        for line in &lines {
            for w in line.windows(2) {
                let joins = segments.iter().any(|s| (s[0] == w[0] && s[1] == w[1]) || (s[0] == w[1] && s[1] == w[0]));
                prop_assert!(joins, "{:?} is not a segment", w);
            }
        }
    }
}
