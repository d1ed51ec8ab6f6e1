//! The predictive controller, eqs. (2.3)–(2.4): the analytic Newton Jacobian, convergence, and
//! agreement with the independent linear (pencil) form used by the analysis.

use flexarm::analysis::{linearize_at_rest, predictor_gain};
use flexarm::control::feedback::{paper_gain, FeedbackGain};
use flexarm::control::predictive::{Predictor, StateVector, StepUnknowns};
use flexarm::model::reference::Reference;
use flexarm::*;
use nalgebra::Vector2;

fn moving_state() -> StateVector {
    StateVector::from_column_slice(&[0.4, 2.1, 0.41, 1.3, -2.2, 1.1, 0.02, -0.03])
}

#[test]
fn analytic_jacobian_matches_finite_differences() {
    let plant = PlantParameters::default();
    let reference = Reference::new(SlewParameters::default());
    for delta in [0.002, 0.01, 0.1] {
        let controller = ControllerParameters { sampling_period: delta, alpha: [2.0, 1.3], ..Default::default() };
        let predictor = Predictor::new(&plant, &controller);
        let x = moving_state();
        let r = reference.sample(0.37);
        let z = StepUnknowns::new(1.35, -2.1, 1.4, 12.0, -3.0);
        let (_, jac) = predictor.residual_and_jacobian(&x, &r, &z);
        for j in 0..5 {
            let h = 1e-6 * (1.0 + z[j].abs());
            let mut zp = z;
            let mut zm = z;
            zp[j] += h;
            zm[j] -= h;
            let fd = (predictor.residual(&x, &r, &zp) - predictor.residual(&x, &r, &zm)) / (2.0 * h);
            for i in 0..5 {
                let scale = 1.0 + jac[(i, j)].abs();
                assert!(
                    (fd[i] - jac[(i, j)]).abs() < 1e-6 * scale,
                    "δ = {delta}: ∂R{i}/∂z{j}: analytic {} vs FD {}",
                    jac[(i, j)],
                    fd[i]
                );
            }
        }
    }
}

#[test]
fn newton_solves_each_step_to_rounding_in_a_few_iterations() {
    let plant = PlantParameters::default();
    let controller = ControllerParameters::default();
    let predictor = Predictor::new(&plant, &controller);
    let reference = Reference::new(SlewParameters::default());
    let x = moving_state();
    let r = reference.sample(0.5);
    let guess = StepUnknowns::new(x[3], x[4], x[5], 0.0, 0.0);
    let (z, iterations) = predictor.solve_step(&x, &r, &guess).unwrap();
    assert!(iterations <= 5, "{iterations} iterations");
    let res = predictor.residual(&x, &r, &z);
    // Residual rows are torques (N m) and accelerations (rad/s²) of size up to M/ε · |Δq̇| ≈ 1e3.
    assert!(res.amax() < 1e-8, "residual {:e}", res.amax());
}

/// A consistent state at rest on a resting reference needs no torque: U_k = 0 and X_k = X_0.
#[test]
fn at_rest_on_the_reference_the_prediction_is_zero() {
    let plant = PlantParameters::default();
    let controller = ControllerParameters::default();
    let predictor = Predictor::new(&plant, &controller);
    let reference = Reference::new(SlewParameters::default());
    let end = SlewParameters::default().end;
    let x0 = StateVector::from_column_slice(&[end[0], end[1], end[0], 0.0, 0.0, 0.0, 0.0, 0.0]);
    let p = predictor.predict(&reference, 3.0, &x0, &Vector2::zeros()).unwrap();
    assert!(p.torque.amax() < 1e-9, "U_k = {:?}", p.torque);
    assert!((p.state - x0).amax() < 1e-12);
}

/// The nonlinear predictor linearized by finite differences equals the linear backward-Euler
/// sweep on the DAE pencil that the stability analysis uses (two independent formulations).
#[test]
fn linearized_predictor_equals_the_pencil_sweep() {
    let plant = PlantParameters::default();
    let slew = SlewParameters::default();
    let reference = Reference::new(slew);
    for (gain, delta) in [(FeedbackGain::zeros(), 0.01), (paper_gain(), 0.04), (FeedbackGain::zeros(), 0.003)] {
        let controller = ControllerParameters { sampling_period: delta, ..Default::default() };
        let predictor = Predictor::new(&plant, &controller);
        let model = linearize_at_rest(&plant, controller.alpha, slew.end);
        let linear = predictor_gain(&model, &gain, &controller).unwrap();
        let x_rest = model.rest;
        let v_of = |x: &StateVector| {
            let p = predictor.predict(&reference, 5.0, x, &Vector2::zeros()).unwrap();
            p.torque - gain * p.state
        };
        for j in 0..8 {
            let h = 1e-5;
            let mut xp = x_rest;
            let mut xm = x_rest;
            xp[j] += h;
            xm[j] -= h;
            let column = (v_of(&xp) - v_of(&xm)) / (2.0 * h);
            for i in 0..2 {
                let scale = 1.0 + linear.row(i).amax();
                assert!(
                    (column[i] - linear[(i, j)]).abs() < 1e-5 * scale,
                    "δ = {delta}, ∂V{i}/∂x{j}: finite differences {} vs pencil {}",
                    column[i],
                    linear[(i, j)]
                );
            }
        }
    }
}

/// The structured back-substitution solves the same Newton system as a dense LU.
#[test]
fn structured_newton_solve_equals_dense_lu() {
    let plant = PlantParameters::default();
    let reference = Reference::new(SlewParameters::default());
    for delta in [0.002, 0.01, 0.15] {
        let controller = ControllerParameters { sampling_period: delta, alpha: [0.7, 3.0], ..Default::default() };
        let predictor = Predictor::new(&plant, &controller);
        let z = StepUnknowns::new(1.1, -2.5, 0.9, 40.0, -7.0);
        let (res, jac) = predictor.residual_and_jacobian(&moving_state(), &reference.sample(0.6), &z);
        let structured = flexarm::control::predictive::solve_structured(&jac, &res).unwrap();
        let dense = jac.lu().solve(&res).unwrap();
        assert!((structured - dense).amax() < 1e-9 * (1.0 + dense.amax()), "{structured} vs {dense}");
    }
}
