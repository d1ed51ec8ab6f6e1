//! The physical story the page tells, checked (issue 22): the pair A4 in closed form against the
//! numerical δ → 0 limit over α, q2 and α1 ≠ α2, with and without preliminary feedback; the arm's
//! own pair with the controller off; the unstable eigenvector's shape; α*; what K_pr does to the
//! pair and where the paper's gains stop working; the limit and the LQ design over the whole range
//! of α.

use flexarm::analysis::resonance::*;
use flexarm::analysis::*;
use flexarm::control::feedback::*;
use flexarm::*;
use std::f64::consts::PI;

fn numerical(plant: &PlantParameters, alpha: [f64; 2], q2: f64, gain: &FeedbackGain) -> LimitPair {
    limit_pair(&linearize_at_rest(plant, alpha, [0.5 * PI, q2]), gain).unwrap()
}

/// Other arms than the paper's, to show the closed form is not a fit to one arm.
fn arms() -> Vec<PlantParameters> {
    let paper = PlantParameters::default();
    vec![
        paper,
        PlantParameters { k1: paper.k1 * 4.0, ..paper },
        PlantParameters { k1: paper.k1 / 4.0, ir1: paper.ir1 * 3.0, ..paper },
        PlantParameters { ir1: paper.ir1 / 4.0, bv1: 5.0, a3: 0.1, ..paper },
    ]
}

#[test]
fn a4_in_closed_form_is_the_numerical_limit_over_alpha_q2_and_unequal_alphas() {
    let alphas = [[2.0, 2.0], [0.3, 0.3], [5.0, 5.0], [0.5, 2.0], [2.0, 0.5], [1.0, 3.0], [4.0, 0.2]];
    let mut checked = 0;
    for plant in arms() {
        for alpha in alphas {
            for q2 in [0.0, 0.7, 0.5 * PI, 2.0, PI, -1.2] {
                let n = numerical(&plant, alpha, q2, &FeedbackGain::zeros());
                let r = JointResonance::new(&plant, alpha, q2);
                // The same matrix, not only the same eigenvalues: (z, y) are the coordinates the
                // numerical limit measures from V*.
                let scale = n.a4.amax();
                assert!((n.a4 - r.a4).amax() < 1e-7 * scale, "{plant:?} α = {alpha:?} q2 = {q2}: {} vs {}", n.a4, r.a4);
                // Re A4 = 3β/2 − Bv1/(2 Ir1), β = α1 + μ (α1 − α2).
                let mu = (plant.a2 + plant.a3 * q2.cos()).powi(2) / (plant.a2 * r.j_eff);
                let re = 1.5 * (alpha[0] + mu * (alpha[0] - alpha[1])) - plant.bv1 / (2.0 * plant.ir1);
                assert!(
                    (n.eigenvalues[0].re - re).abs() < 1e-6 * (1.0 + re.abs()),
                    "Re A4 {} vs {re}",
                    n.eigenvalues[0]
                );
                assert!((r.real_part() - re).abs() < 1e-12);
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 4 * 7 * 6);
}

#[test]
fn a4_in_closed_form_with_preliminary_feedback_is_the_numerical_limit() {
    let plant = PlantParameters::default();
    for alpha in [[2.0, 2.0], [0.5, 2.0], [3.0, 1.0], [0.2, 0.2]] {
        for q2 in [0.0, 1.0, PI] {
            let lq = design_lq(&plant, alpha, [0.5 * PI, q2], &LqWeights::default()).unwrap().gain;
            for gain in [paper_gain(), lq, paper_gain() * 0.3] {
                let n = numerical(&plant, alpha, q2, &gain);
                let c = closed_form_a4(&plant, alpha, q2, &gain);
                assert!((n.a4 - c).amax() < 1e-7 * n.a4.amax(), "α = {alpha:?} q2 = {q2}: {} vs {c}", n.a4);
            }
        }
    }
}

/// The paper: "a change of the control parameters α_i to smaller values does help". Below
/// α* = Bv1/(3 Ir1) ≈ 0.24 1/s the pair is stable without any K_pr, and at α = 0.2 every δ of the
/// slider is; just above α* the smallest δ fail again.
#[test]
fn below_alpha_star_no_preliminary_feedback_is_needed() {
    let plant = PlantParameters::default();
    let star = alpha_star(&plant);
    assert!((star - 0.2407).abs() < 1e-4, "{star}");
    for plant in arms() {
        let star = alpha_star(&plant);
        for (alpha, stable) in [(0.9 * star, true), (1.1 * star, false)] {
            let n = numerical(&plant, [alpha, alpha], 0.0, &FeedbackGain::zeros());
            assert_eq!(n.eigenvalues[0].re < 0.0, stable, "{plant:?} α = {alpha}: {}", n.eigenvalues[0]);
        }
    }
    let settings = |alpha: f64| {
        let mut c = SimulationConfig { preliminary_feedback: PreliminaryFeedbackChoice::Off, ..Default::default() };
        c.controller.alpha = [alpha, alpha];
        LinearSettings::of(&c, None)
    };
    let w = stable_windows(&settings(0.2), [0.002, 0.25]).unwrap();
    assert_eq!(w.windows, vec![[0.002, 0.25]], "{}", flexarm::words::settings::windows(&w));
    let w = stable_windows(&settings(0.3), [0.002, 0.25]).unwrap();
    assert!(
        w.windows[0][0] > 0.002,
        "just above α* the smallest δ are unstable: {}",
        flexarm::words::settings::windows(&w)
    );
    // Unequal α: α1 = 0.5, α2 = 2 is stable at δ = 0.01 s (β < α*), though α1 = α2 = 0.5 is not.
    let mut c = SimulationConfig { preliminary_feedback: PreliminaryFeedbackChoice::Off, ..Default::default() };
    c.controller.alpha = [0.5, 2.0];
    let r = analyze(&c, None).unwrap();
    assert!(r.spectral_radius < 1.0 && r.limit_pair_open[0][0] < 0.0, "{r:?}");
}

/// With the controller off (no torque, the friction cancelled) the arm's pair is lightly damped;
/// the controller moves it to the right half-plane by nearly its feed 3α/2.
#[test]
fn the_arms_own_pair_is_damped_and_the_controller_feeds_it() {
    let plant = PlantParameters::default();
    let own = arm_pair(&plant, 0.0)[0];
    assert!(own.re < 0.0 && own.re > -plant.bv1 / plant.ir1, "{own}");
    let r = JointResonance::new(&plant, [2.0, 2.0], 0.0);
    // The two-inertia resonance, motor against link 1, is the frequency of both.
    for s in [own, r.eigenvalues[0]] {
        assert!((s.im - r.omega_joint).abs() < 0.01 * r.omega_joint, "{s} vs ω = {}", r.omega_joint);
    }
    assert!(r.omega_clamped < 0.85 * r.omega_joint, "a clamped link would swing much slower");
    let moved = r.eigenvalues[0].re - own.re;
    assert!(
        (moved - r.controller_feed).abs() < 0.1 * r.controller_feed,
        "moved by {moved}, feed {}",
        r.controller_feed
    );
}

/// The unstable pair of Fig. 5.3 (δ = 0.01 s, no K_pr) is the joint's resonance: the motor turns
/// against link 1 (θ ≈ −2 q1) and link 2 is flung the other way with the largest amplitude.
#[test]
fn the_unstable_mode_is_motor_against_link_with_link_two_flung_along() {
    let mut c = SimulationConfig { preliminary_feedback: PreliminaryFeedbackChoice::Off, ..Default::default() };
    c.controller.sampling_period = 0.01;
    let model = LoopModel::new(&LinearSettings::of(&c, None)).unwrap();
    let [_, q2, theta] = model.mode_shape(0.01).unwrap().unwrap();
    assert!((theta.norm() - 2.0).abs() < 0.15 && theta.re < -1.8, "θ/q1 = {theta}");
    assert!((q2.norm() - 2.3).abs() < 0.15 && q2.re < -2.0, "q2/q1 = {q2}");
    // Link 2 moves most; the motor and link 1 turn in opposite directions.
    assert!(q2.norm() > theta.norm() && theta.norm() > 1.0);
}

/// K_pr acts on the pair through its gains on θ̇: a shift of Re A4 independent of α (α1 = α2),
/// ≈ −5.1 1/s at q2 = 0, while the controller adds 3α/2 — so the paper's gains fail above
/// α ≈ 3.65, where the δ → 0 pair with K_pr crosses into the right half-plane.
#[test]
fn the_papers_gains_shift_the_pair_by_a_fixed_amount_and_fail_at_large_alpha() {
    let plant = PlantParameters::default();
    let shift = feedback_shift(&plant, [2.0, 2.0], 0.0, &paper_gain());
    assert!((shift + 5.12).abs() < 0.01, "{shift}");
    for alpha in [0.3, 1.0, 2.0, 3.0, 5.0] {
        let with = numerical(&plant, [alpha, alpha], 0.0, &paper_gain()).eigenvalues[0].re;
        let without = numerical(&plant, [alpha, alpha], 0.0, &FeedbackGain::zeros()).eigenvalues[0].re;
        assert!((with - without - shift).abs() < 1e-6, "α = {alpha}: {with} − {without} vs {shift}");
    }
    let limit = alpha_limit(&plant, shift);
    assert!((limit - 3.65).abs() < 0.01, "{limit}");
    for (alpha, stable) in [(limit - 0.02, true), (limit + 0.02, false)] {
        assert_eq!(numerical(&plant, [alpha, alpha], 0.0, &paper_gain()).eigenvalues[0].re < 0.0, stable);
    }
    // At α = 5 only a window of δ is left (the paper's "every small δ" is lost).
    let mut c = SimulationConfig::default();
    c.controller.alpha = [5.0, 5.0];
    let w = stable_windows(&LinearSettings::of(&c, None), [0.002, 0.25]).unwrap();
    assert_eq!(w.windows.len(), 1, "{}", flexarm::words::settings::windows(&w));
    let [lo, hi] = w.windows[0];
    assert!((lo - 0.018).abs() < 0.002 && (hi - 0.090).abs() < 0.002, "{}", flexarm::words::settings::windows(&w));
    // The minimum-energy LQ design mirrors the pair instead: −Re A4 at every α.
    for alpha in [1.0, 3.7, 5.0] {
        let d = design_lq(&plant, [alpha, alpha], [0.5 * PI, 0.0], &LqWeights::default()).unwrap();
        assert!((d.closed_pair[0].re + d.open_pair[0].re).abs() < 1e-3 * d.open_pair[0].re.abs(), "{d:?}");
    }
}

/// The δ → 0 limit and the LQ design work for every α the schema allows (the limit projector
/// used to diverge for some, e.g. `flexarm analyze --pf lq --alpha 3.7`).
#[test]
fn the_limit_and_the_lq_design_work_over_the_whole_range_of_alpha() {
    let plant = PlantParameters::default();
    let spec = flexarm::schema::ALPHA_SPEC;
    let (lo, hi) = (1e-3_f64.max(spec.min), spec.max);
    let alphas: Vec<f64> = (0..80).map(|i| lo * (hi / lo).powf(i as f64 / 79.0)).collect();
    let dense: Vec<f64> = (0..200).map(|i| 3.6 + 0.3 * i as f64 / 199.0).collect();
    for &a1 in alphas.iter().chain(&dense) {
        for a2 in [a1, 0.1, 2.0, 5.0] {
            for q2 in [0.0, 2.2] {
                let d = design_lq(&plant, [a1, a2], [0.5 * PI, q2], &LqWeights::default());
                let d = d.unwrap_or_else(|e| panic!("LQ at α = ({a1}, {a2}), q2 = {q2}: {e}"));
                for pf in
                    [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper, PreliminaryFeedbackChoice::Lq]
                {
                    let mut c = SimulationConfig { preliminary_feedback: pf, lq_design_q2: q2, ..Default::default() };
                    c.controller.alpha = [a1, a2];
                    analyze(&c, Some(q2)).unwrap_or_else(|e| panic!("{pf:?} α = ({a1}, {a2}), q2 = {q2}: {e}"));
                }
                assert!(d.closed_pair[0].re <= 1e-9, "{d:?}");
            }
        }
    }
}

/// The predictor reads only the links: its linearized gain has exactly zero columns for θ and θ̇
/// at every ε, not only in the limit (with or without a preliminary feedback folded in, which
/// the predictor sees through the links too).
#[test]
fn the_predictor_never_reads_the_motor_at_any_delta() {
    let plant = PlantParameters::default();
    for alpha in [[2.0, 2.0], [0.5, 3.0]] {
        let model = linearize_at_rest(&plant, alpha, [0.5 * PI, 0.4]);
        for delta in [0.002, 0.01, 0.05, 0.2] {
            let c = flexarm::ControllerParameters { sampling_period: delta, alpha, ..Default::default() };
            let k = predictor_gain(&model, &FeedbackGain::zeros(), &c).unwrap();
            let scale = k.amax();
            assert!(scale > 1.0, "{k}");
            for row in 0..2 {
                assert!(k[(row, 2)].abs() < 1e-9 * scale && k[(row, 5)].abs() < 1e-9 * scale, "δ = {delta}: {k}");
            }
        }
    }
}
