//! Every arm the schema accepts gives finite, correct results (issue 34, item 4): `--k1 1e-12` gave
//! ρ = 70571 (an independent model: 1.0267), `--ir1 1e-300` panicked, `--k1 1e-300` never ended.
//!
//! - Over the corners and a log-spaced interior of every arm parameter's range (one at a time
//!   from the paper's arm), and over every all-corner arm that passes `validate`: the analysis is
//!   finite, and ρ at the smallest δ agrees with the δ → 0 limit computed another way. The
//!   reference is the closed form of [`JointResonance`] (the paper's section 3 written in the
//!   arm's parameters: no pencil, no predictor, no matrix exponential, no 10×10 eigen-solver):
//!   as δ → 0 the sampled loop's eigenvalues tend to e^{δ s} for the continuous loop's poles s,
//!   the pair A4 and the six the predictor puts at −α, so ln ρ/δ → max(Re A4, −α).
//! - Eigenvalues are a property of the map, not of its units: a diagonal similarity (a state
//!   measured in other units) leaves them unchanged.
//! - A light motor under the paper's K_pr is simulated with a step its inner loop allows.
//! - A value outside the range is refused on the command line: status 2, one line naming the
//!   setting and its range.

use flexarm::analysis::resonance::{closed_form_a4, JointResonance};
use flexarm::analysis::*;
use flexarm::control::feedback::paper_gain;
use flexarm::*;
use nalgebra::{Complex, Matrix2};
use std::process::Command;

/// The smallest δ the schema accepts, s: there the loop is closest to its δ → 0 limit.
const SMALL_DELTA: f64 = 1e-5;

fn config(plant: PlantParameters, alpha: f64, delta: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { plant, preliminary_feedback: pf, ..SimulationConfig::default() };
    c.controller.alpha = [alpha; 2];
    c.controller.sampling_period = delta;
    c
}

/// The ends of a parameter's range (the smallest positive float for one that only excludes 0) and
/// log-spaced values between them (from a millionth of the top for one that starts at or near 0).
fn range_values(param: &schema::Param) -> Vec<f64> {
    let n = param.number().expect("arm parameters are numbers");
    let low = if n.min_inclusive { n.min } else { f64::from_bits(1) };
    let (from, to) = (low.max(n.max * 1e-6), n.max);
    let mut values = vec![low, n.max];
    values.extend((1..6).map(|i| from * (to / from).powf(i as f64 / 6.0)));
    values
}

/// A4 in closed form with the preliminary feedback's gain (none when off).
fn limit_a4(plant: &PlantParameters, alpha: f64, pf: PreliminaryFeedbackChoice) -> Matrix2<f64> {
    let q2 = SimulationConfig::default().reference.end[1];
    match pf {
        PreliminaryFeedbackChoice::Paper => closed_form_a4(plant, [alpha; 2], q2, &paper_gain()),
        _ => JointResonance::new(plant, [alpha; 2], q2).a4,
    }
}

/// The gaps of one arm from the δ → 0 limit at δ = [`SMALL_DELTA`].
#[derive(Clone, Copy, Debug, Default)]
struct Gaps {
    /// For each eigenvalue s of A4 in closed form, |ln λ/δ − s| for the nearest loop pole λ, as a
    /// fraction of [`pole_tolerance`] (≤ 1 passes).
    pair: f64,
    /// |ρ − max(|e^{δ s}| over A4, e^{−αδ})|.
    rho: f64,
}

/// How far a pole's ln λ/δ at δ = 1e-5 s may be from its limit s, 1/s: the sampling's own effect
/// is O(δ |s|²) (a few 1e-4 1/s at the stiffest corner, |s| δ ≈ 0.01), plus rounding.
fn pole_tolerance(plant: &PlantParameters, s: f64) -> f64 {
    1e-3 * (1.0 + s) + SMALL_DELTA * plant.fastest_rate().powi(2) * 1e-2
}

/// ρ may differ from its limit by the sampling's effect (δ² |s|², under 1e-8 here) and by the
/// rounding of the six poles at −α: two triple eigenvalues, which rounding u ≈ 1e-16 splits by
/// about u^{1/3} ≈ 5e-6 (a defective eigenvalue is that sensitive, whatever the solver).
const RHO_TOLERANCE: f64 = 2e-5;

/// Checks one arm: Err if `validate` refuses it (with a reason, never a panic), else finite
/// results at δ = 0.01 s and at [`SMALL_DELTA`], and there the gaps from the limit (None for an
/// arm too fast for δ = 1e-5 s to be its limit).
fn check(plant: PlantParameters, alpha: f64, pf: PreliminaryFeedbackChoice) -> Result<Option<Gaps>, ConfigError> {
    plant.validate()?;
    let label = format!("{} with α = {alpha}, pf {}", schema::arm_text(&plant.values()), pf.name());
    let report = analyze(&config(plant, alpha, 0.01, pf), None).unwrap_or_else(|e| panic!("{label}: {e}"));
    assert!(report.spectral_radius.is_finite(), "{label}: ρ = {}", report.spectral_radius);
    for p in &report.poles {
        assert!(p.discrete.iter().all(|v| v.is_finite()), "{label}: λ = {:?}", p.discrete);
    }
    for pair in [report.limit_pair, report.limit_pair_open] {
        assert!(pair.iter().flatten().all(|v| v.is_finite()), "{label}: A4 = {pair:?}");
    }
    if let Some(e) = report.swing_energy {
        assert!([e.held_torque, e.preliminary_feedback, e.damping, e.lag].iter().all(|v| v.is_finite()), "{label}");
    }
    let small = analyze(&config(plant, alpha, SMALL_DELTA, pf), None).unwrap_or_else(|e| panic!("{label}: {e}"));
    assert!(small.poles.iter().all(|p| p.discrete.iter().all(|v| v.is_finite())), "{label} at δ = {SMALL_DELTA}");
    // The limit describes a loop whose every motion is slow over δ: an arm with a rate of 7e5 1/s
    // (a motor damped 1400 N m s/rad over 0.0019 kg m²) is not there yet at δ = 1e-5 s.
    if plant.fastest_rate() * SMALL_DELTA > 0.05 {
        return Ok(None);
    }
    let rates: Vec<Complex<f64>> =
        small.poles.iter().map(|p| Complex::new(p.discrete[0], p.discrete[1]).ln() / SMALL_DELTA).collect();
    let mut gaps = Gaps::default();
    let mut rho_limit = (-alpha * SMALL_DELTA).exp();
    for s in limit_a4(&plant, alpha, pf).complex_eigenvalues().iter() {
        rho_limit = rho_limit.max((s.re * SMALL_DELTA).exp());
        let nearest = rates.iter().map(|r| (r - s).norm()).fold(f64::INFINITY, f64::min);
        gaps.pair = gaps.pair.max(nearest / pole_tolerance(&plant, s.norm()));
    }
    gaps.rho = (small.spectral_radius - rho_limit).abs();
    Ok(Some(gaps))
}

#[test]
fn every_arm_parameter_over_its_range_gives_the_delta_to_zero_limit() {
    let paper = PlantParameters::default();
    let (mut checked, mut refused, mut fast) = (0, 0, 0);
    let mut worst = [0.0f64; 2];
    for param in schema::ARM_PARAMS {
        for v in range_values(param) {
            let mut plant = paper;
            plant.set(param.key, v);
            for (alpha, pf) in [
                (2.0, PreliminaryFeedbackChoice::Off),
                (0.2, PreliminaryFeedbackChoice::Off),
                (2.0, PreliminaryFeedbackChoice::Paper),
            ] {
                match check(plant, alpha, pf) {
                    Ok(None) => fast += 1,
                    Ok(Some(gaps)) => {
                        assert!(
                            gaps.pair <= 1.0 && gaps.rho <= RHO_TOLERANCE,
                            "{} = {v}, α = {alpha}, pf {}: {gaps:?}",
                            param.key,
                            pf.name()
                        );
                        worst = [worst[0].max(gaps.pair), worst[1].max(gaps.rho)];
                        checked += 1;
                    }
                    // Only the mass matrix's check may refuse a value inside a single range.
                    Err(e) => {
                        assert!(e.to_string().contains("positive definite"), "{} = {v}: {e}", param.key);
                        refused += 1;
                    }
                }
            }
        }
    }
    println!(
        "{checked} arms checked against the limit, {fast} too fast for it (finite only), {refused} refused by the \
         mass matrix; worst gaps {:.2e} of the pole tolerance, {:.2e} in ρ",
        worst[0], worst[1]
    );
    assert!(checked >= 3 * 9 * 7 && fast == 0, "{checked}, {fast}");
}

#[test]
fn every_all_corner_arm_that_validates_gives_the_delta_to_zero_limit() {
    // The parameters that change ρ (the friction is cancelled in the analysis).
    let keys = ["a1", "a2", "a3", "ir1", "bv1", "bv2", "k1"];
    let (mut checked, mut refused, mut fast) = (0, 0, 0);
    let mut worst = [0.0f64; 2];
    for mask in 0..(1u32 << keys.len()) {
        let mut plant = PlantParameters::default();
        for (i, key) in keys.iter().enumerate() {
            let values = range_values(schema::param(key).unwrap());
            plant.set(key, values[((mask >> i) & 1) as usize]);
        }
        match check(plant, 2.0, PreliminaryFeedbackChoice::Off) {
            Ok(None) => fast += 1,
            Ok(Some(gaps)) => {
                assert!(gaps.pair <= 1.0 && gaps.rho <= RHO_TOLERANCE, "{plant:?}: {gaps:?}");
                worst = [worst[0].max(gaps.pair), worst[1].max(gaps.rho)];
                checked += 1;
            }
            // The mass matrix, or a motion too fast to simulate (PlantParameters::FASTEST_RATE_MAX).
            Err(e) => {
                let e = e.to_string();
                assert!(e.contains("positive definite") || e.contains("too fast for this arm"), "{plant:?}: {e}");
                assert!(e.contains("positive definite") || plant.fastest_rate() > PlantParameters::FASTEST_RATE_MAX);
                refused += 1;
            }
        }
    }
    println!(
        "{checked} all-corner arms checked against the limit, {fast} too fast for it (finite only), {refused} refused \
         (mass matrix, too fast); worst gaps {:.2e} of the pole tolerance, {:.2e} in ρ",
        worst[0], worst[1]
    );
    assert!(checked >= 16, "{checked}");
}

/// Eigenvalues belong to the map, not to the units its states are measured in: D⁻¹ Φ D with D
/// diagonal (powers of 2, so the similarity itself rounds nothing) has Φ's eigenvalues. A soft
/// joint makes the map this badly scaled by itself (at K1 = 1e-12 N m/rad its entries spanned
/// 1e-20 to 1e9, and the unbalanced solver gave ρ = 70571 for 1.0267).
#[test]
fn the_loop_eigenvalues_do_not_depend_on_the_states_units() {
    let c = config(PlantParameters::default(), 2.0, 0.01, PreliminaryFeedbackChoice::Off);
    let settings = LinearSettings::of(&c, None);
    let phi = LoopModel::new(&settings).unwrap().loop_matrix(0.01).unwrap();
    let reference = loop_eigenvalues(&phi);
    // θ and θ̇ in units 2⁴⁰ times smaller, the torques' in 2³⁰ times larger, and the rest mixed.
    let exponents = [0, 3, -40, 0, -5, -40, 10, 2, 30, 30];
    let mut scaled = phi;
    for i in 0..10 {
        for j in 0..10 {
            scaled[(i, j)] *= 2f64.powi(exponents[j] - exponents[i]);
        }
    }
    let ev = loop_eigenvalues(&scaled);
    for (a, b) in reference.iter().zip(&ev) {
        assert!((a - b).norm() < 1e-9, "{a} against {b}: {reference:?} vs {ev:?}");
    }
}

/// The paper's K_pr puts a damper of 16.5 N m s/rad on the motor: 8500 1/s on a motor a thousand
/// times lighter than the paper's, faster than the arm's own motion (770 1/s). The plant's step
/// must follow it: with the step sized for the arm alone RK4 went unstable and the run "diverged"
/// at t = 0.01 s while ρ = 0.98. The reference is the same run at a step 30 times smaller.
#[test]
fn a_light_motor_under_the_papers_feedback_is_simulated_with_a_step_its_inner_loop_allows() {
    let plant = PlantParameters { ir1: 1.939e-3, ..PlantParameters::default() };
    let c = config(plant, 2.0, 0.01, PreliminaryFeedbackChoice::Paper);
    let run = simulate(&c, 1.5).unwrap().metrics;
    let fine = simulate(&SimulationConfig { plant_step_max: 2e-6, ..c }, 1.5).unwrap().metrics;
    let diverged = |m: &Metrics| matches!(m.verdict, Verdict::Diverged { .. });
    assert!(!diverged(&fine), "the reference run: {fine:?}");
    assert!(!diverged(&run), "{run:?}");
    for i in 0..2 {
        let (a, b) = (run.max_error_slew[i], fine.max_error_slew[i]);
        assert!((a - b).abs() <= 0.02 * b, "e{}: {a} against {b}", i + 1);
    }
}

/// Outside the range (or too fast together) the command line refuses the value: status 2, one
/// line naming the setting and its range (before: `--k1 1e-12` printed ρ = 70571 with status 0, `--ir1 1e-300` panicked,
/// `--k1 1e-300` never ended).
#[test]
fn an_arm_outside_the_range_is_one_line_with_status_2() {
    for (flag, value, range) in [
        ("--k1", "1e-12", "1.1526 to 1152600 N m/rad"),
        ("--k1", "1e-300", "1.1526 to 1152600 N m/rad"),
        ("--ir1", "1e-300", "0.001939 to 1939 kg m²"),
        ("--a2", "1e-6", "0.000247 to 247 kg m²"),
        ("--a1", "5000", "0.004984 to 4984 kg m²"),
        // Each within its range, together too fast: the motor's damping over its inertia.
        ("--bv1", "1400", "at most 30000 1/s"),
    ] {
        for command in ["analyze", "simulate"] {
            // A light motor beside each value (one within its range), so that B_v1 = 1400 is too fast.
            let motor: &[&str] = if flag == "--ir1" { &[] } else { &["--ir1", "0.002"] };
            let out = Command::new(env!("CARGO_BIN_EXE_flexarm"))
                .args([command, flag, value, "--pf", "off"])
                .args(motor)
                .output()
                .expect("the flexarm binary runs");
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{command} {flag} {value}: {err}");
            assert_eq!(err.trim_end().lines().count(), 1, "{command} {flag} {value}: {err}");
            assert!(err.starts_with("error: ") && err.contains(&flag[2..]) && err.contains(range), "{err}");
            assert!(out.stdout.is_empty(), "{command} {flag} {value}");
        }
    }
}
