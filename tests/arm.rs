//! The arm is a setting (issue 18): what the physics says of every arm, not values copied from
//! our output.
//!
//! - Re A4 = 3α/2 − B_v1/(2 I_r1) for every arm (α1 = α2): the controller's negative damping 3α/2
//!   against the motor's own, whatever the inertias and the spring; and the loop is stable for a
//!   small δ exactly when that is negative.
//! - Scaling every inertia, damping, friction level and the stiffness by the same c gives the same
//!   motion for c times the torque: ρ, the windows of δ and the errors do not change (without a
//!   preliminary feedback or with the LQ design, which is redesigned for the arm; the paper's
//!   fixed K_pr is not scaled and would change).
//! - An impossible arm is refused with a reason, never a NaN or a panic.

use flexarm::analysis::{analyze, spectral_radius, stable_windows, LinearSettings};
use flexarm::session::{Settings, Source};
use flexarm::*;
use proptest::prelude::*;
use proptest::test_runner::{Config as ProptestConfig, RngSeed};

fn cases(cases: u32) -> ProptestConfig {
    ProptestConfig { cases, rng_seed: RngSeed::Fixed(2026), failure_persistence: None, ..ProptestConfig::default() }
}

/// A random arm over the page's sliders (log-uniform where the slider is logarithmic), kept only
/// if its mass matrix is positive definite.
fn arms() -> impl Strategy<Value = PlantParameters> {
    proptest::collection::vec(0.0f64..=1.0, 11).prop_filter_map("mass matrix not positive definite", |f| {
        let mut p = PlantParameters::default();
        for (param, u) in schema::ARM_PARAMS.iter().zip(&f) {
            let n = param.number().expect("arm parameters are numbers");
            p.set(param.key, n.value_at(*u));
        }
        p.validate().is_ok().then_some(p)
    })
}

fn config(plant: PlantParameters, alpha: f64, delta: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig::default();
    c.plant = plant;
    c.controller.alpha = [alpha; 2];
    c.controller.sampling_period = delta;
    c.preliminary_feedback = pf;
    c
}

proptest! {
    #![proptest_config(cases(48))]

    /// The δ → 0 pair A4 of the linearized loop (computed from the predictor's gain, not from the
    /// closed form) has the mean of its two eigenvalues, trace/2, at 3α/2 − B_v1/(2 I_r1) for every
    /// arm: Re A4 when the pair swings. Stability needs more than that sign: a motor damped so much
    /// that the pair no longer swings (two real eigenvalues) turns unstable again once
    /// det A4 < 0, i.e. B_v1 > I_r1 (K1/I_r1 + K1/J_eff + 6α²)/(3α) — a slow real mode grows. At
    /// a small δ the loop grows (ρ > 1) exactly when A4's larger eigenvalue is positive.
    #[test]
    fn re_a4_is_the_controllers_negative_damping_against_the_motors(plant in arms(), log_alpha in -1.0f64..0.7) {
        let alpha = 10f64.powf(log_alpha);
        let c = config(plant, alpha, 0.002, PreliminaryFeedbackChoice::Off);
        let report = analyze(&c, None).unwrap();
        let [first, second] = report.limit_pair_open;
        let mean = 0.5 * (first[0] + second[0]);
        let law = 1.5 * alpha - plant.bv1 / (2.0 * plant.ir1);
        prop_assert!((mean - law).abs() <= 1e-6 * (1.0 + law.abs()), "trace/2 of A4 {mean} against {law} for {plant:?}");
        if first[1].abs() > 1e-9 {
            prop_assert!((first[0] - law).abs() <= 1e-6 * (1.0 + law.abs()), "Re A4 {} against {law}", first[0]);
        }
        // det A4 from its eigenvalues, against the closed form's stiffness term.
        let r = &report.resonance;
        let stiffness = plant.k1 / plant.ir1 + plant.k1 / r.j_eff + 6.0 * alpha * alpha;
        let det = first[0] * second[0] + first[1] * second[1].abs();
        let det_law = stiffness - 3.0 * alpha * plant.bv1 / plant.ir1;
        prop_assert!((det - det_law).abs() <= 1e-6 * (1.0 + det_law.abs()), "det A4 {det} against {det_law} for {plant:?}");
        prop_assert!(report.spectral_radius.is_finite() && report.poles.iter().all(|p| p.discrete.iter().all(|v| v.is_finite())));
        // The sampled loop at δ = 2 ms follows its limit where the limit is clear of the axis
        // (the sampling's own effect on the pair is a fraction of 1/s here).
        let largest = first[0].max(second[0]);
        if largest.abs() > 1.0 {
            prop_assert_eq!(report.spectral_radius > 1.0, largest > 0.0, "ρ = {} with A4's largest {} for {:?}", report.spectral_radius, largest, plant);
        }
    }
}

/// The paper's arm scaled by `c`: every inertia, damping, friction level and the stiffness.
fn scaled(c: f64) -> PlantParameters {
    let p = PlantParameters::default();
    PlantParameters {
        a1: c * p.a1,
        a2: c * p.a2,
        a3: c * p.a3,
        ir1: c * p.ir1,
        bv1: c * p.bv1,
        bv2: c * p.bv2,
        fc1: c * p.fc1,
        fc2: c * p.fc2,
        k1: c * p.k1,
        ..p
    }
}

#[test]
fn an_arm_scaled_as_a_whole_moves_the_same_for_proportional_torques() {
    for pf in [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Lq] {
        // The LQ design's weights are absolute (R on the torques): its gain scales with the arm
        // to the accuracy of its near-minimum-energy limit, not exactly.
        let tol = if pf == PreliminaryFeedbackChoice::Off { 1e-9 } else { 1e-5 };
        for delta in [0.01, 0.04] {
            let base = config(scaled(1.0), 2.0, delta, pf);
            let rho = spectral_radius(&base, None).unwrap();
            let run = simulate(&base, 3.0).unwrap();
            for c in [0.25, 3.0] {
                let other = config(scaled(c), 2.0, delta, pf);
                let rho_c = spectral_radius(&other, None).unwrap();
                assert!((rho_c - rho).abs() <= tol, "{pf:?} δ = {delta}, c = {c}: ρ {rho_c} against {rho}");
                let run_c = simulate(&other, 3.0).unwrap();
                for i in 0..2 {
                    let (a, b) = (run.metrics.max_error_slew[i], run_c.metrics.max_error_slew[i]);
                    assert!(
                        (a - b).abs() <= 1e3 * tol * a.abs().max(1e-6),
                        "{pf:?} δ = {delta}, c = {c}: e{} {a} against {b}",
                        i + 1
                    );
                    let (ta, tb) = (run.metrics.max_torque[i], run_c.metrics.max_torque[i]);
                    assert!((tb / (c * ta) - 1.0).abs() <= 1e3 * tol, "{pf:?}: torque {tb} is not {c} × {ta}");
                }
            }
        }
    }
    // The windows of δ without K_pr are the arm's too, not its size's.
    let range = [0.002, 0.25];
    let w = |c: f64| {
        stable_windows(&LinearSettings::of(&config(scaled(c), 2.0, 0.01, PreliminaryFeedbackChoice::Off), None), range)
            .unwrap()
    };
    let (one, three) = (w(1.0), w(3.0));
    assert_eq!(one.windows.len(), three.windows.len());
    for (a, b) in one.windows.iter().zip(&three.windows) {
        assert!((a[0] - b[0]).abs() <= one.tolerance && (a[1] - b[1]).abs() <= one.tolerance, "{a:?} against {b:?}");
    }
}

/// The damped motor: enough motor damping (B_v1 > 3 α I_r1) makes the loop stable at δ = 0.01 s
/// with no preliminary feedback — the paper's Fig. 5.3 on another arm.
#[test]
fn a_damped_motor_needs_no_preliminary_feedback() {
    let mut s = Settings::default();
    s.read("arm=damped&delta=0.01&pf=off", Source::CommandLine).unwrap();
    let p = s.a.plant;
    assert!(p.bv1 > 3.0 * 2.0 * p.ir1, "the preset damps enough: {}", p.bv1);
    assert!(spectral_radius(&s.a.config(), None).unwrap() < 1.0);
    // …and the paper's arm with the same settings is the unstable Fig. 5.3.
    s.read("arm=paper", Source::CommandLine).unwrap();
    assert!(spectral_radius(&s.a.config(), None).unwrap() > 1.0);
}

#[test]
fn the_arm_is_in_the_state_string_only_where_it_differs_from_the_papers() {
    let mut s = Settings::page_start();
    let before = s.to_query();
    assert!(!before.contains("k1=") && !before.contains("bv1="), "{before}");
    s.read("k1=2000", Source::Page).unwrap();
    let q = s.to_query();
    assert!(q.contains("k1=2000") && !q.contains("ir1="), "{q}");
    let mut back = Settings::default();
    assert!(back.read(&q, Source::Page).unwrap().is_empty());
    assert_eq!(back.a.plant.k1, 2000.0);
    assert!(s.command_line(None).contains("--k1 2000"), "{}", s.command_line(None));
    // A figure preset is the paper's arm again.
    s.read("preset=fig5.3", Source::Page).unwrap();
    assert_eq!(s.a.plant, PlantParameters::default());
    // Every arm preset changes one part and is recognised as itself.
    for a in flexarm::session::ARMS {
        let mut t = Settings::default();
        t.set_arm(a.id).unwrap();
        assert_eq!(t.arm_preset().map(|p| p.id), Some(a.id));
        let changed =
            schema::ARM_PARAMS.iter().filter(|p| t.a.plant.get(p.key) != Some(p.number().unwrap().default)).count();
        assert_eq!(changed, usize::from(a.id != "paper"), "{}", a.id);
    }
}

#[test]
fn an_impossible_arm_is_refused_with_a_reason() {
    let mut s = Settings::default();
    // A3 too large for A1 and A2: the mass matrix is singular at some q2.
    s.read("a3=2", Source::CommandLine).unwrap();
    let e = s.a.config().validate().unwrap_err().to_string();
    assert!(e.contains("A3") && e.contains("positive definite"), "{e}");
    assert!(!e.contains('\n'), "one line: {e}");
    for bad in ["k1=0", "ir1=-1", "bv1=-0.1", "eps1=0", "k1=1e9", "a1=NaN"] {
        let e = Settings::default().read(bad, Source::CommandLine).unwrap_err().to_string();
        assert!(e.contains("must be"), "{bad}: {e}");
    }
    // The page skips such values with a notice instead.
    let notices = Settings::page_start().read("k1=1e9&arm=rubber", Source::Page).unwrap();
    assert_eq!(notices.len(), 2, "{notices:?}");
}

/// The README's numbers about the arm come from the physics: the damping that kills the swing
/// at α = 2 on the paper's arm, and the damped preset's two terms of Re A4.
#[test]
fn the_readme_quotes_the_arms_numbers() {
    let readme = include_str!("../README.md").replace('\n', " ").replace("  ", " ");
    let p = PlantParameters::default();
    let needed = format!("B_v1 > 3α I_r1 ({:.1} N m s/rad on the paper's arm at α = 2)", 3.0 * 2.0 * p.ir1);
    assert!(readme.contains(&needed), "README should say {needed:?}");
    let damped = flexarm::session::arm("damped").unwrap().plant();
    let terms = format!("Re A4 = {} − {:.2} < 0", 1.5 * 2.0, damped.bv1 / (2.0 * damped.ir1));
    assert!(readme.contains(&terms), "README should say {terms:?}");
    let j_eff = analyze(&config(p, 2.0, 0.01, PreliminaryFeedbackChoice::Off), None).unwrap().resonance.j_eff;
    let high = (p.k1 / p.ir1 + p.k1 / j_eff + 6.0 * 4.0) * p.ir1 / 6.0;
    let bound = format!("below {high:.0} N m s/rad");
    assert!(readme.contains(&bound), "README should say {bound:?}");
}

/// Run B may have another arm (`b_arm`): the paper's Fig. 5.3 beside the same controller on the
/// damped motor — one grows, the other does not; the link keeps B's arm.
#[test]
fn run_b_may_have_another_arm() {
    let (s, notices) = flexarm::session::Session::open("preset=fig5.3&compare=1&b_pf=off&b_delta=0.01&b_arm=damped");
    assert!(notices.is_empty(), "{notices:?}");
    let rho = |i: usize| spectral_radius(s.run(i).unwrap().closed_loop().config(), None).unwrap();
    assert!(rho(0) > 1.0 && rho(1) < 1.0, "A {} B {}", rho(0), rho(1));
    assert_eq!(s.run(1).unwrap().closed_loop().config().plant.bv1, 15.0);
    assert_eq!(s.run(0).unwrap().closed_loop().config().plant, PlantParameters::default());
    assert!(s.settings().to_query().contains("b_arm=damped"));
    let (plain, _) = flexarm::session::Session::open("preset=fig5.3&compare=1");
    assert!(!plain.settings().to_query().contains("b_arm"), "B on A's arm writes no b_arm");
}

/// The lesson's steps on other arms quote the physics: ρ at δ = 0.05 s on the softer spring, its
/// A4 and windows, where the stiffer spring's first window starts, and the damped motor's Re A4
/// with the damping it needs (checked against the analysis, not copied from it).
#[test]
fn the_lesson_quotes_the_arms_numbers() {
    let lesson = flexarm::lesson::LESSON_TEXT;
    let says = |what: String| assert!(lesson.contains(&what), "the lesson should say {what:?}");
    let on = |id: &str, delta: f64| {
        config(flexarm::session::arm(id).unwrap().plant(), 2.0, delta, PreliminaryFeedbackChoice::Off)
    };
    let range = [0.002, 0.25];
    let soft = analyze(&on("softer", 0.05), None).unwrap();
    assert!(soft.spectral_radius > 1.0);
    says(format!("ρ = {:.3} at δ = 0.05 s", soft.spectral_radius));
    let pair = |r: &flexarm::analysis::StabilityReport| {
        format!("{:.2} ± {:.2}j", r.limit_pair_open[0][0], r.limit_pair_open[0][1].abs())
    };
    let paper = analyze(&on("paper", 0.05), None).unwrap();
    assert!(paper.spectral_radius < 1.0, "δ = 0.05 s works on the paper's arm");
    says(format!("A4 at {} 1/s instead of {}", pair(&soft), pair(&paper)));
    let w = stable_windows(&LinearSettings::of(&on("softer", 0.05), None), range).unwrap().windows;
    assert_eq!(w.len(), 2, "{w:?}");
    says(format!("now from {:.3} s to {:.3} s and from {:.3} s to {:.3} s", w[0][0], w[0][1], w[1][0], w[1][1]));
    let stiff = stable_windows(&LinearSettings::of(&on("stiffer", 0.05), None), range).unwrap().windows;
    says(format!("starting at {:.3} s", stiff[0][0]));
    // The damped motor: Re A4's two terms from the analysis's A4, the damping needed from the law.
    let damped = flexarm::session::arm("damped").unwrap().plant();
    let d = analyze(&on("damped", 0.01), None).unwrap();
    let feed = 1.5 * 2.0;
    let take = damped.bv1 / (2.0 * damped.ir1);
    assert!((d.limit_pair_open[0][0] - (feed - take)).abs() < 1e-6);
    says(format!("= {} − {:.2} = {} 1/s", feed, take, format!("{:.2}", feed - take).replace('-', "−")));
    says(format!("B_v1 > 3α I_r1 = {:.1} N m s/rad", 3.0 * 2.0 * PlantParameters::default().ir1));
    let w = stable_windows(&LinearSettings::of(&on("damped", 0.01), None), range).unwrap();
    assert_eq!(w.windows, vec![range], "stable at every δ of the slider");
}

/// Damping has a window too: the story's bounds on B_v1 are where A4's trace and determinant
/// change sign, and the sampled loop at a small δ (1e-4 s) agrees on both sides of each.
#[test]
fn the_motor_damping_that_kills_the_swing_has_two_bounds() {
    let s = common_session("arm=damped&pf=off&mode=full");
    let text = s.status().story.unwrap().damping_needed;
    let p = PlantParameters::default();
    let j_eff = analyze(&config(p, 2.0, 0.01, PreliminaryFeedbackChoice::Off), None).unwrap().resonance.j_eff;
    let low = 3.0 * 2.0 * p.ir1;
    let high = (p.k1 / p.ir1 + p.k1 / j_eff + 6.0 * 4.0) * p.ir1 / (3.0 * 2.0);
    assert!(text.starts_with(&format!("B_v1 > 3α I_r1 = {low:.1} N m s/rad as δ → 0;")), "{text}");
    assert!(text.contains(&format!("one of them grows only beyond {high:.0} N m s/rad")), "{text}");
    assert!(text.ends_with("(this arm: 15 N m s/rad)"), "{text}");
    let rho = |bv1: f64| {
        spectral_radius(&config(PlantParameters { bv1, ..p }, 2.0, 1e-4, PreliminaryFeedbackChoice::Off), None).unwrap()
    };
    assert!(rho(0.9 * low) > 1.0 && rho(1.1 * low) < 1.0, "the lower bound");
    assert!(rho(0.9 * high) < 1.0 && rho(1.1 * high) > 1.0, "the upper bound: {} {}", rho(0.9 * high), rho(1.1 * high));
}

fn common_session(query: &str) -> flexarm::session::Session {
    let (s, notices) = flexarm::session::Session::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    s
}

/// Run B's arm choices are the arm presets, in their order (the schema cannot read the session's
/// list at compile time, so the two are held together here).
#[test]
fn run_bs_arm_choices_are_the_arm_presets() {
    let schema::Kind::Choice { options, .. } = schema::B_ARM.kind else { panic!("b_arm is a choice") };
    assert_eq!(options[0].value, "same");
    let ids: Vec<&str> = options[1..].iter().map(|c| c.value).collect();
    let presets: Vec<&str> = flexarm::session::ARMS.iter().map(|a| a.id).collect();
    assert_eq!(ids, presets);
    for (choice, preset) in options[1..].iter().zip(flexarm::session::ARMS.iter()) {
        assert_eq!(choice.label.to_lowercase(), preset.title.to_lowercase(), "{}", preset.id);
    }
}
