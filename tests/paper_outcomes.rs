//! The paper's outcomes (section 5, Figs. 5.1–5.3), checked by simulation and by the linear
//! analysis of the sampled loop.

use flexarm::analysis::spectral_radius;
use flexarm::control::DivergenceReason;
use flexarm::*;

const RUN: f64 = 8.0;

fn config(delta: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
    c.controller.sampling_period = delta;
    c
}

fn is_unstable(v: &Verdict) -> bool {
    matches!(v, Verdict::Unstable { .. } | Verdict::Diverged { .. })
}

/// Figs. 5.1–5.2: with preliminary feedback every small δ works.
#[test]
fn with_papers_feedback_every_small_delta_is_stable() {
    for delta in [0.005, 0.01, 0.02, 0.04, 0.08] {
        let c = config(delta, PreliminaryFeedbackChoice::Paper);
        let report = simulate(&c, RUN).unwrap();
        assert_eq!(report.metrics.verdict, Verdict::Stable, "δ = {delta}: {:?}", report.metrics);
        let rho = spectral_radius(&c, None).unwrap();
        assert!(rho < 1.0, "δ = {delta}: ρ = {rho}");
    }
}

/// Fig. 5.3 and section 4: without it the loop is unstable for small δ, stable for larger δ,
/// and ρ > 1 exactly in the unstable cases.
#[test]
fn without_feedback_small_delta_is_unstable_and_larger_delta_is_stable() {
    for (delta, unstable) in [(0.005, true), (0.01, true), (0.02, true), (0.04, false), (0.06, false)] {
        let c = config(delta, PreliminaryFeedbackChoice::Off);
        let report = simulate(&c, RUN).unwrap();
        let rho = spectral_radius(&c, None).unwrap();
        assert_eq!(is_unstable(&report.metrics.verdict), unstable, "δ = {delta}: {:?}", report.metrics.verdict);
        assert_eq!(rho > 1.0, unstable, "δ = {delta}: ρ = {rho}");
    }
}

/// "Stable for large, but not too large, δ": without feedback ρ exceeds 1 again at large δ.
#[test]
fn without_feedback_too_large_delta_is_unstable_again() {
    let rho = spectral_radius(&config(0.15, PreliminaryFeedbackChoice::Off), None).unwrap();
    assert!(rho > 1.0, "ρ(0.15 s) = {rho}");
    let report = simulate(&config(0.15, PreliminaryFeedbackChoice::Off), 10.0).unwrap();
    assert!(is_unstable(&report.metrics.verdict), "{:?}", report.metrics.verdict);
}

/// ERRATA: at δ = 0.01 s without feedback the errors grow like e^{2.4 t}, visible within 2–3 s
/// and diverging after ~4 s; the simulated growth agrees with ln ρ / δ.
#[test]
fn unstable_run_grows_like_the_flexible_pair_and_diverges_after_about_four_seconds() {
    let c = config(0.01, PreliminaryFeedbackChoice::Off);
    let mut sim = ClosedLoop::new(c).unwrap();
    sim.advance(3.5).unwrap();
    let m = sim.metrics();
    let growth = m.growth_rate.unwrap();
    let predicted = spectral_radius(&c, None).unwrap().ln() / 0.01;
    assert!((1.8..=3.0).contains(&growth), "growth {growth} 1/s");
    assert!((growth - predicted).abs() < 0.15 * predicted, "simulated {growth} vs ln ρ/δ = {predicted}");
    sim.advance(RUN).unwrap();
    match sim.metrics().verdict {
        Verdict::Diverged { at, reason: DivergenceReason::ErrorBound } => {
            assert!((3.0..=6.0).contains(&at), "diverged at {at}")
        }
        v => panic!("expected divergence, got {v:?}"),
    }
    assert!(sim.is_finished());
}

/// Fig. 5.3's caption: smaller α slows the growth.
#[test]
fn smaller_alpha_slows_the_growth() {
    let growth = |alpha: f64| {
        let mut c = config(0.01, PreliminaryFeedbackChoice::Off);
        c.controller.alpha = [alpha, alpha];
        spectral_radius(&c, None).unwrap().ln() / 0.01
    };
    let rates: Vec<f64> = [0.5, 1.0, 2.0].iter().map(|a| growth(*a)).collect();
    assert!(rates[0] < rates[1] && rates[1] < rates[2], "{rates:?}");
    let mut c = config(0.01, PreliminaryFeedbackChoice::Off);
    c.controller.alpha = [0.5, 0.5];
    let slow = simulate(&c, RUN).unwrap().metrics;
    let fast = simulate(&config(0.01, PreliminaryFeedbackChoice::Off), 3.5).unwrap().metrics;
    assert!(slow.growth_rate.unwrap() < 0.5 * fast.growth_rate.unwrap());
}

/// Figs. 5.1–5.2: errors are satisfactory at δ = 0.04 s and decrease as δ becomes small.
#[test]
fn errors_shrink_with_delta_and_are_small_at_forty_milliseconds() {
    let coarse = simulate(&config(0.04, PreliminaryFeedbackChoice::Paper), RUN).unwrap().metrics;
    let fine = simulate(&config(0.01, PreliminaryFeedbackChoice::Paper), RUN).unwrap().metrics;
    assert!(coarse.max_error_slew[0] < 1e-2 && coarse.max_error_slew[1] < 2e-2, "{:?}", coarse.max_error_slew);
    for i in 0..2 {
        assert!(
            fine.max_error_slew[i] * 5.0 <= coarse.max_error_slew[i],
            "link {}: {:?} vs {:?}",
            i + 1,
            fine.max_error_slew,
            coarse.max_error_slew
        );
    }
    // After the slew the errors die out.
    assert!(fine.max_error_after[0] < fine.max_error_slew[0] && fine.max_error_after[1] < fine.max_error_slew[1]);
}

/// The LQ gain designed by the library works like the paper's.
#[test]
fn lq_feedback_is_stable_at_small_delta() {
    for delta in [0.005, 0.01] {
        let c = config(delta, PreliminaryFeedbackChoice::Lq);
        assert_eq!(simulate(&c, RUN).unwrap().metrics.verdict, Verdict::Stable);
        assert!(spectral_radius(&c, None).unwrap() < 1.0);
    }
}

/// Eq. (4.4): the observer run continuously cancels the Dahl friction, so the loop behaves as
/// with a friction-free plant; without compensation the errors are far larger.
#[test]
fn continuous_friction_compensation_equals_the_friction_free_plant() {
    let compensated = simulate(&config(0.01, PreliminaryFeedbackChoice::Paper), 4.0).unwrap();
    let mut free = config(0.01, PreliminaryFeedbackChoice::Paper);
    free.plant.fc1 = 0.0;
    free.plant.fc2 = 0.0;
    let free = simulate(&free, 4.0).unwrap();
    let diff = compensated
        .traces
        .e1()
        .iter()
        .zip(free.traces.e1())
        .chain(compensated.traces.e2().iter().zip(free.traces.e2()))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(diff < 1e-6, "compensated vs friction-free: {diff:e} rad");
    // The friction was really there: the observer saw the Coulomb levels.
    let xf_max = compensated.traces.xf1_hat().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(xf_max > 0.9 * PlantParameters::default().fc1);

    let mut off = config(0.01, PreliminaryFeedbackChoice::Paper);
    off.friction_compensation = FrictionCompensation::Off;
    let off = simulate(&off, 4.0).unwrap().metrics;
    let on = compensated.metrics;
    for i in 0..2 {
        assert!(
            off.max_error_slew[i] >= 10.0 * on.max_error_slew[i],
            "link {}: {:?} vs {:?}",
            i + 1,
            off.max_error_slew,
            on.max_error_slew
        );
    }
}

/// ERRATA: compensation held over each period is not equivalent: errors grow 2–5×.
#[test]
fn held_friction_compensation_is_worse_than_continuous() {
    let on = simulate(&config(0.01, PreliminaryFeedbackChoice::Paper), 4.0).unwrap().metrics;
    let mut held = config(0.01, PreliminaryFeedbackChoice::Paper);
    held.friction_compensation = FrictionCompensation::Held;
    let held = simulate(&held, 4.0).unwrap().metrics;
    for i in 0..2 {
        let ratio = held.max_error_slew[i] / on.max_error_slew[i];
        assert!((1.5..=10.0).contains(&ratio), "link {}: ratio {ratio}", i + 1);
    }
}

/// ERRATA: sampling the inner loop at δ lowers the largest stable δ to ≈ 0.08 s
/// (the paper: satisfactory "as long as δ < 0.1 s").
#[test]
fn sampled_inner_loop_limits_the_largest_stable_delta() {
    let rho = |delta: f64| {
        let mut c = config(delta, PreliminaryFeedbackChoice::Paper);
        c.inner_loop = InnerLoop::Sampled;
        spectral_radius(&c, None).unwrap()
    };
    assert!(rho(0.06) < 1.0 && rho(0.1) > 1.0, "ρ(0.06) = {}, ρ(0.1) = {}", rho(0.06), rho(0.1));
    let mut c = config(0.1, PreliminaryFeedbackChoice::Paper);
    c.inner_loop = InnerLoop::Sampled;
    assert!(is_unstable(&simulate(&c, RUN).unwrap().metrics.verdict));
}
