//! The plant of eq. (4.1): energy conservation, and the integrator's accuracy.

use flexarm::model::plant::{Plant, PlantState};
use flexarm::*;
use nalgebra::{Vector2, Vector3};

fn swinging_state() -> PlantState {
    PlantState { q: Vector3::new(0.3, 1.0, 0.35), qdot: Vector3::new(1.0, -2.0, 0.5), friction: Vector2::zeros() }
}

/// ERRATA.md: with torques, damping and friction zero, E = ½ q̇ᵀ M q̇ + ½ K1 (θ − q1)² stays
/// constant with the corrected mass matrix (the OCR's variant drifts by ~19 % in 5 s).
#[test]
fn unforced_undamped_plant_conserves_energy() {
    let plant = Plant::new(PlantParameters::undamped_frictionless());
    let mut s = swinging_state();
    let e0 = plant.energy(&s.q, &s.qdot);
    let h = flexarm::control::config::DEFAULT_PLANT_STEP_MAX;
    let mut worst: f64 = 0.0;
    for _ in 0..(5.0 / h).round() as usize {
        plant.step(&mut s, h, |_, _, _| Vector2::zeros());
        worst = worst.max(((plant.energy(&s.q, &s.qdot) - e0) / e0).abs());
    }
    eprintln!("relative energy drift over 5 s: {worst:.2e}");
    assert!(worst < 1e-6, "relative energy drift {worst:e} over 5 s");
    // The motion is not trivial: the joints actually swing.
    assert!((s.q[1] - 1.0).abs() > 0.1);
}

/// The printed OCR variant (2 A3 off the diagonal) does not conserve energy: the test above can fail.
#[test]
fn energy_test_detects_the_ocr_mass_matrix() {
    let p = PlantParameters::undamped_frictionless();
    let plant = Plant::new(p);
    // M with A2 + 2 A3 c2 off the diagonal, integrated with the same RK4 on the same forces.
    let ocr_mass = |q2: f64| {
        let c2 = q2.cos();
        nalgebra::Matrix3::new(
            p.a1 + 2.0 * p.a3 * c2,
            p.a2 + 2.0 * p.a3 * c2,
            0.0,
            p.a2 + 2.0 * p.a3 * c2,
            p.a2,
            0.0,
            0.0,
            0.0,
            p.ir1,
        )
    };
    let energy =
        |q: &Vector3<f64>, v: &Vector3<f64>| 0.5 * v.dot(&(ocr_mass(q[1]) * v)) + 0.5 * p.k1 * (q[2] - q[0]).powi(2);
    let s = swinging_state();
    let (mut q, mut v) = (s.q, s.qdot);
    let e0 = energy(&q, &v);
    let h = 1e-3;
    let acc = |q: &Vector3<f64>, v: &Vector3<f64>| {
        let r = plant.forces(q, v, &Vector2::zeros(), &Vector2::zeros());
        ocr_mass(q[1]).try_inverse().unwrap() * r
    };
    for _ in 0..5000 {
        let k1 = (v, acc(&q, &v));
        let (q2, v2) = (q + k1.0 * (h / 2.0), v + k1.1 * (h / 2.0));
        let k2 = (v2, acc(&q2, &v2));
        let (q3, v3) = (q + k2.0 * (h / 2.0), v + k2.1 * (h / 2.0));
        let k3 = (v3, acc(&q3, &v3));
        let (q4, v4) = (q + k3.0 * h, v + k3.1 * h);
        let k4 = (v4, acc(&q4, &v4));
        q += (k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) * (h / 6.0);
        v += (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) * (h / 6.0);
    }
    let drift = ((energy(&q, &v) - e0) / e0).abs();
    assert!(drift > 1e-3, "the OCR variant should drift, got {drift:e}");
}

/// Runs the paper's slew and returns e1, e2 sampled every 10 ms.
fn errors_with_step(friction: FrictionCompensation, plant_step_max: f64) -> (Vec<f64>, Vec<f64>) {
    let config = SimulationConfig {
        friction_compensation: friction,
        plant_step_max,
        output_interval: 0.01,
        ..SimulationConfig::default()
    };
    let report = simulate(&config, 3.0).unwrap();
    assert!(matches!(report.metrics.verdict, flexarm::Verdict::Stable), "{:?}", report.metrics.verdict);
    (report.traces.e1().to_vec(), report.traces.e2().to_vec())
}

fn worst_difference(a: &(Vec<f64>, Vec<f64>), b: &(Vec<f64>, Vec<f64>)) -> (f64, f64) {
    assert_eq!(a.0.len(), b.0.len());
    let diff = a.0.iter().zip(&b.0).chain(a.1.iter().zip(&b.1)).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    let size = a.0.iter().chain(&a.1).map(|x| x.abs()).fold(0.0, f64::max);
    (diff, size)
}

/// The default step (1 ms) against a step 16 times finer, with the stiff friction compensated
/// and with it left to act on the arm (stick–slip at the end of the slew).
#[test]
fn default_step_matches_a_sixteen_times_finer_step() {
    for friction in [FrictionCompensation::Continuous, FrictionCompensation::Off] {
        let coarse = errors_with_step(friction, 1e-3);
        let fine = errors_with_step(friction, 1e-3 / 16.0);
        let (diff, size) = worst_difference(&coarse, &fine);
        eprintln!("{friction:?}: step error {diff:.2e} rad, errors up to {size:.2e} rad");
        assert!(diff < 1e-3 * size, "{friction:?}: step error {diff:e} rad against errors of {size:e} rad");
    }
}
