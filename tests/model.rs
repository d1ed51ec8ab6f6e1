//! The controller's model of the arm (issue 18, `model = paper`): the predictor, the friction
//! observer and the LQ design assume the paper's arm while the real arm differs. What physics
//! says, checked — not values copied from our output:
//!
//! - A controller that assumes the paper's arm *on* the paper's arm is the same controller: every
//!   analysis and every run is identical to `model = arm`.
//! - With a model error the sampled loop still tends to a continuous loop as δ → 0: the
//!   predictor's limit feedback K_lim (from its model) closing the real arm. Its resonance pair is
//!   where the sampled loop's s = ln λ/δ go at δ = 1e-4 s, and its sign decides ρ there.
//! - The simulation (nonlinear, with friction) agrees with the linear verdict under a model error.
//! - Beyond the paper: the preliminary feedback keeps every small δ stable on the stiffer, softer,
//!   lighter and heavier arms even when the controller assumes the paper's arm, while without it
//!   the damped motor — stable when the controller knows it — is unstable at small δ when the
//!   controller assumes the paper's lightly damped motor.

use flexarm::analysis::{analyze, spectral_radius, stable_windows, LinearSettings};
use flexarm::control::config::ControllerModel;
use flexarm::session::{Settings, Source};
use flexarm::*;

const PFS: [PreliminaryFeedbackChoice; 3] =
    [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper, PreliminaryFeedbackChoice::Lq];

/// The configuration of a state string (the same reading the page and the CLI do).
fn config(state: &str) -> SimulationConfig {
    let mut s = Settings::default();
    s.read(state, Source::CommandLine).unwrap_or_else(|e| panic!("{state}: {e}"));
    s.a.config()
}

#[test]
fn assuming_the_papers_arm_on_the_papers_arm_changes_nothing() {
    for pf in PFS {
        for delta in [0.005, 0.01, 0.05] {
            let state = format!("delta={delta}&pf={}", pf.name());
            let exact = config(&state);
            let assumed = config(&format!("{state}&model=paper"));
            assert_eq!(assumed.model, ControllerModel::Paper);
            assert!(!assumed.has_model_error());
            assert_eq!(analyze(&exact, None).unwrap(), analyze(&assumed, None).unwrap(), "{state}");
            let run = |c: &SimulationConfig| simulate(c, 2.0).unwrap();
            let (a, b) = (run(&exact), run(&assumed));
            assert_eq!(a.metrics, b.metrics, "{state}");
            assert!(a.traces == b.traces, "{state}: the traces differ");
        }
        let settings = |c: &SimulationConfig| LinearSettings::of(c, None);
        let state = format!("pf={}", pf.name());
        let w = |c: &SimulationConfig| stable_windows(&settings(c), [0.002, 0.25]).unwrap().windows;
        assert_eq!(w(&config(&state)), w(&config(&format!("{state}&model=paper"))));
    }
}

#[test]
fn with_a_model_error_the_loop_tends_to_the_real_arm_under_the_models_limit_feedback() {
    let delta = 1e-4;
    for arm in ["stiffer", "softer", "lighter", "heavier", "damped"] {
        for pf in PFS {
            for alpha in [1.0, 2.0, 3.0] {
                let state = format!("arm={arm}&model=paper&pf={}&alpha={alpha}&delta={delta}", pf.name());
                let c = config(&state);
                assert!(c.has_model_error());
                let r = analyze(&c, None).unwrap();
                let [re, im] = r.limit_pair[0];
                // An eigenvalue of the sampled loop sits at the predicted pair (s = ln λ/δ)…
                let nearest = r
                    .poles
                    .iter()
                    .filter_map(|p| p.continuous)
                    .map(|[sr, si]| (sr - re).hypot(si - im.abs()))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    nearest <= 0.01 * re.hypot(im) + 0.05,
                    "{state}: pair {re} ± {im}j, nearest pole {nearest} away"
                );
                // …and where the pair grows it sets ρ: ρ ≈ e^{Re δ}.
                if re > 0.0 {
                    let predicted = (re * delta).exp();
                    assert!(
                        (r.spectral_radius - predicted).abs() <= 0.01 * re * delta,
                        "{state}: ρ {} against e^(Re δ) {predicted}",
                        r.spectral_radius
                    );
                } else {
                    assert!(
                        r.spectral_radius < 1.0,
                        "{state}: pair {re} ± {im}j in the left half-plane, ρ {}",
                        r.spectral_radius
                    );
                }
            }
        }
    }
}

#[test]
fn the_simulation_agrees_with_the_linear_verdict_under_a_model_error() {
    // A stiffer spring the controller does not know: without K_pr the swing grows at δ = 0.01 s
    // (as on the paper's arm); the paper's fixed K_pr still damps it. The damped motor: stable
    // when the controller knows its damping, growing slowly when it assumes the paper's motor.
    for (state, stable) in [
        ("arm=stiffer&model=paper&pf=off&delta=0.01", false),
        ("arm=stiffer&model=paper&pf=paper&delta=0.01", true),
        ("arm=damped&model=paper&pf=off&delta=0.005", false),
        ("arm=damped&pf=off&delta=0.005", true),
    ] {
        let c = config(state);
        let rho = spectral_radius(&c, None).unwrap();
        assert_eq!(rho < 1.0, stable, "{state}: ρ = {rho}");
        let m = simulate(&c, 12.0).unwrap().metrics;
        // Where it grows without diverging, at the rate the linear analysis gives.
        if let Verdict::Unstable { growth_rate } = m.verdict {
            let predicted = rho.ln() / c.controller.sampling_period;
            assert!(
                (growth_rate / predicted - 1.0).abs() <= 0.2,
                "{state}: grows at {growth_rate} against {predicted} 1/s"
            );
        }
        let grows = match m.verdict {
            Verdict::Stable | Verdict::SlewLocked { .. } => false,
            Verdict::Unstable { .. } | Verdict::Diverged { .. } => true,
            ref other => panic!("{state}: verdict {other:?}"),
        };
        assert_eq!(!grows, stable, "{state}: verdict {:?} against ρ = {rho}", m.verdict);
    }
}

#[test]
fn the_preliminary_feedback_is_robust_to_the_arm_the_controller_assumes() {
    // The stiffness from a quarter to four times the paper's, the motor inertia likewise: the
    // controller keeps assuming the paper's arm; with the paper's K_pr or the LQ design (made on
    // the paper's arm) every small δ is stable.
    for key in ["k1", "ir1"] {
        for factor in [0.25, 0.5, 2.0, 4.0] {
            let paper = schema::param(key).unwrap().number().unwrap().default;
            for pf in [PreliminaryFeedbackChoice::Paper, PreliminaryFeedbackChoice::Lq] {
                for delta in [0.002, 0.005, 0.01, 0.02] {
                    let state = format!("{key}={}&model=paper&pf={}&delta={delta}", paper * factor, pf.name());
                    let rho = spectral_radius(&config(&state), None).unwrap();
                    assert!(rho < 1.0, "{state}: ρ = {rho}");
                }
            }
        }
    }
    // The damped motor's own damping is not enough when the controller assumes the paper's
    // motor: the predictor asks for the torque that would move a lightly damped motor.
    let state = "arm=damped&model=paper&pf=off&delta=0.005";
    assert!(spectral_radius(&config(state), None).unwrap() > 1.0, "{state}");
}

#[test]
fn the_model_is_a_setting_like_delta() {
    let mut s = Settings::default();
    s.read("k1=2000&model=paper", Source::Page).unwrap();
    assert!(s.to_query().contains("model=paper"), "{}", s.to_query());
    // At its default it stays out of the state string (today's links read the same).
    s.read("model=arm", Source::Page).unwrap();
    assert!(!s.to_query().contains("model"), "{}", s.to_query());
    assert!(s.read("model=wrong", Source::CommandLine).is_err());
}
