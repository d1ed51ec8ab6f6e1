//! The Jankowski–Van Brussel predictive controller, eqs. (2.3)–(2.4) with the stabilized
//! constraint (4.2)–(4.3).
//!
//! At each sampling instant t_ρ the controller integrates the DAE in (X, U)
//!
//! Ẋ = f(X) + G(X) U,  0 = ĥ(X) + Ĵ(X) U − ξ̂(t),  X(t_ρ) = x(t_ρ),
//!
//! with k backward-Euler steps of ε = δ/m, eq. (2.4), and returns U_k. Here
//! X = (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2), U = (T1, T2) drives the friction-free arm (the friction
//! observer cancels the friction), and for i = 1, 2 the constraint is
//!
//! (q̈_i − q̈_di) + 3α_i (q̇_i − q̇_di) + 3α_i² (q_i − q_di) + w_i = 0,  ẇ_i = α_i³ (q_i − q_di),
//!
//! p*(s) = (s + α)³/s applied to the error, eq. (4.3) with the second derivative (ERRATA.md).
//! The DAE has index 3: the first steps of every sweep carry impulsive torques while the
//! discretisation jumps to consistency; they are not clipped, only U_k is used.
//!
//! # One backward-Euler step
//! The rows q⁺ = q + ε q̇⁺ and w⁺ = w + ε α³ (q⁺ − q_d) are linear and eliminated, and the
//! acceleration of the step is (q̇⁺ − q̇)/ε, so the unknowns are z = (q̇⁺, U⁺) ∈ ℝ⁵ with residual
//!
//! R_dyn = M(q2⁺) (q̇⁺ − q̇)/ε − r(q⁺, q̇⁺) − B U⁺                  (3 rows, eq. 4.1)
//! R_con = (q̇⁺ − q̇)/ε − q̈_d + 3α (q̇⁺ − q̇_d) + 3α² (q⁺ − q_d) + w⁺   (2 rows, eq. 4.3)
//!
//! evaluated with the reference at t_ρ + (j+1)ε (consistent backward Euler; the printed t_ρ + jε
//! lags by one step, see ERRATA.md). Newton with the analytic Jacobian solves it; the system is
//! nearly linear, so two or three iterations reach machine precision. Each Newton system is solved
//! by back-substitution along the Jacobian's sparsity ([`solve_structured`]) instead of a dense LU.
//!
//! # Small ε
//! U⁺ is found from the spring's stretch θ⁺ − q1⁺ through two divisions by ε (the index 3), so the
//! Jacobian's condition grows like 1/(ω ε)², ω = √(K1/Ir1): a rounding of the residual's rows by
//! u·|terms| moves T1 by ≈ u·|terms| Ir1/(K1 ε²). Two things keep Newton converging down to the
//! smallest δ the schema accepts:
//! - it iterates on the step's change y = (Δq̇, U⁺), Δq̇ = q̇⁺ − q̇, and forms the acceleration
//!   Δq̇/ε, the stretch (θ − q1) + ε (θ̇⁺ − q̇1⁺) and the error (q − q_d) + ε q̇⁺ from the small
//!   changes: from q⁺ and q̇⁺ rounded to their ulp the residual is a staircase in z with steps of
//!   ulp(q)/ε, which Newton cannot descend (so every δ below ≈ 1.5e-4 s stopped, issue 34);
//! - it accepts a stalled update within a few times the rounding floor of the step (the change of
//!   z the residual's rounding makes through J⁻¹, [`Predictor::solve_step`]), not only below the
//!   fixed relative [`NEWTON_STALL_TOLERANCE`], which the floor passes near δ = 1e-5 s.
//!
//! # Preliminary feedback
//! With u = K_pr X + V the paper integrates f(X) + G(X)(K_pr X + V) and designs V. The
//! backward-Euler equations in (X, V) are those in (X, U) under the affine change U = K_pr X + V,
//! and Newton is affine invariant, so the controller solves for U and returns V_k = U_k − K_pr X_k.

use nalgebra::{SMatrix, SVector, Vector2, Vector3};

use crate::control::config::ControllerParameters;
use crate::model::params::PlantParameters;
use crate::model::plant::Plant;
use crate::model::reference::{Reference, ReferenceSample};

/// The controller's state X = (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2).
pub type StateVector = SVector<f64, 8>;
/// X = (q, q̇, w) from its parts: the state the controller measures.
#[inline]
pub fn controller_vector(q: &Vector3<f64>, v: &Vector3<f64>, w: &Vector2<f64>) -> StateVector {
    StateVector::from_column_slice(&[q[0], q[1], q[2], v[0], v[1], v[2], w[0], w[1]])
}

/// A feedback gain from X = (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2) to U = (T1, T2).
pub type FeedbackGain = SMatrix<f64, 2, 8>;
/// Newton unknowns of one step, z = (q̇1⁺, q̇2⁺, θ̇⁺, T1⁺, T2⁺).
pub type StepUnknowns = SVector<f64, 5>;
/// Jacobian ∂R/∂z of one step.
pub type StepJacobian = SMatrix<f64, 5, 5>;

/// Newton gives up after this many iterations in one step.
pub const NEWTON_MAX_ITERATIONS: usize = 30;
/// Newton stops when every update is below this, relative to 1 + |z_i|. The update estimates the
/// error of the previous iterate and convergence is quadratic, so the accepted iterate is accurate
/// to rounding; a tighter bound would chase rounding noise (the Jacobian's condition number is
/// ≈ 1e7 at ε = 1.25 ms).
pub const NEWTON_TOLERANCE: f64 = 1e-9;
/// An update that stops shrinking quadratically below this relative size is at the rounding
/// floor (torques are resolved to ≈ Ir1 · 1e-13/ε N m) and is accepted.
pub const NEWTON_STALL_TOLERANCE: f64 = 1e-6;
/// A stalled update is also accepted within this many times the step's rounding floor (see
/// "Small ε" in the module docs): below it the residual's rounding, not the iterate, decides.
pub const NEWTON_FLOOR_MARGIN: f64 = 4.0;

/// Why a prediction failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PredictionError {
    /// Newton did not converge in backward-Euler step `step` (1-based).
    NewtonFailure { step: usize },
    /// The initial state or the reference is not finite.
    NonFinite,
}

impl core::fmt::Display for PredictionError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::NewtonFailure { step } => write!(f, "Newton did not converge in backward-Euler step {step}"),
            Self::NonFinite => write!(f, "the state is not finite"),
        }
    }
}

/// The result of one sweep of k backward-Euler steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prediction {
    /// U_k = (T1, T2), the friction-free torque at the end of the horizon, N m.
    pub torque: Vector2<f64>,
    /// X_k, the predicted state at t_ρ + kε.
    pub state: StateVector,
    /// Newton iterations summed over the k steps.
    pub newton_iterations: usize,
}

/// One whole prediction, the picture of Fig. 2.1: from the measured X_0 = x(t_n) the k
/// backward-Euler steps X_1 … X_k of ε and the torques U_1 … U_k that keep the constraint.
/// U_1, U_2 are impulsive (the index-3 DAE jumps to consistency: the motor's measured angle and
/// speed are replaced by those the links' law needs); only U_k is used.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sweep {
    /// t_n, the sampling instant the sweep starts from, s.
    pub start: f64,
    /// ε, s.
    pub step: f64,
    /// X_0 … X_k (fewer if a step failed).
    pub states: Vec<StateVector>,
    /// U_1 … U_k, N m: `torques[j − 1]` is U_j, the torque at t_n + jε.
    pub torques: Vec<Vector2<f64>>,
    /// All k steps converged.
    pub complete: bool,
    /// V_k = U_k − K_pr X_k, what the loop holds on [t_n + δ, t_n + 2δ), N m (None if the sweep
    /// failed or nobody said).
    pub held: Option<Vector2<f64>>,
}

impl Sweep {
    fn start(&mut self, t0: f64, eps: f64, x0: &StateVector) {
        self.start = t0;
        self.step = eps;
        self.states.clear();
        self.torques.clear();
        self.held = None;
        self.complete = false;
        self.states.push(*x0);
    }

    /// The time of X_j, s.
    pub fn time(&self, j: usize) -> f64 {
        self.start + j as f64 * self.step
    }
}

/// The predictive controller for one set of plant and controller parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Predictor {
    plant: Plant,
    /// α_i, 1/s.
    alpha: [f64; 2],
    /// ε, s.
    eps: f64,
    /// k.
    steps: usize,
}

impl Predictor {
    /// Uses the friction-free model of `plant` (the observer cancels the friction).
    pub fn new(plant: &PlantParameters, controller: &ControllerParameters) -> Self {
        Self {
            plant: Plant::new(*plant),
            alpha: controller.alpha,
            eps: controller.integration_step(),
            steps: controller.horizon_steps,
        }
    }

    /// ε, s.
    pub fn integration_step(&self) -> f64 {
        self.eps
    }

    /// Integrates eq. (2.4) from X_0 = `x0` at `t0` over k steps and returns U_k and X_k.
    /// `torque_guess` seeds Newton in the first step (the previous U_k is a good choice).
    pub fn predict(
        &self,
        reference: &Reference,
        t0: f64,
        x0: &StateVector,
        torque_guess: &Vector2<f64>,
    ) -> Result<Prediction, PredictionError> {
        self.predict_into(reference, t0, x0, torque_guess, None)
    }

    /// [`Predictor::predict`], keeping the whole sweep X_0 … X_k, U_1 … U_k in `sweep` (Fig. 2.1;
    /// its buffers are reused, so a sweep of the same k allocates nothing). On failure the sweep
    /// holds the steps that converged.
    pub fn predict_into(
        &self,
        reference: &Reference,
        t0: f64,
        x0: &StateVector,
        torque_guess: &Vector2<f64>,
        mut sweep: Option<&mut Sweep>,
    ) -> Result<Prediction, PredictionError> {
        if let Some(s) = sweep.as_deref_mut() {
            s.start(t0, self.eps, x0);
        }
        if !x0.iter().all(|v| v.is_finite()) {
            return Err(PredictionError::NonFinite);
        }
        let mut x = *x0;
        let mut z = StepUnknowns::new(x0[3], x0[4], x0[5], torque_guess[0], torque_guess[1]);
        let mut iterations = 0;
        for j in 0..self.steps {
            let r = reference.sample(t0 + (j + 1) as f64 * self.eps);
            let (z_next, n) = self.solve_step(&x, &r, &z).ok_or(PredictionError::NewtonFailure { step: j + 1 })?;
            iterations += n;
            z = z_next;
            x = self.advance_state(&x, &r, &z);
            if let Some(s) = sweep.as_deref_mut() {
                s.states.push(x);
                s.torques.push(Vector2::new(z[3], z[4]));
            }
        }
        if let Some(s) = sweep {
            s.complete = true;
        }
        Ok(Prediction { torque: Vector2::new(z[3], z[4]), state: x, newton_iterations: iterations })
    }

    /// Solves one backward-Euler step for z = (q̇⁺, U⁺) by Newton from `guess`; returns z and the
    /// number of iterations, or `None` if Newton fails (a vanishing pivot, a non-finite iterate,
    /// or no convergence in [`NEWTON_MAX_ITERATIONS`]). Newton runs in y = (Δq̇, U⁺) (the same
    /// iterates: an affine change of unknowns) and stops when every update is below
    /// [`NEWTON_TOLERANCE`] relative to 1 + |z_i|, or when it has stopped shrinking quadratically
    /// and each update is below [`NEWTON_STALL_TOLERANCE`] (relative) or [`NEWTON_FLOOR_MARGIN`]
    /// times the step's rounding floor.
    pub fn solve_step(
        &self,
        x: &StateVector,
        r: &ReferenceSample,
        guess: &StepUnknowns,
    ) -> Option<(StepUnknowns, usize)> {
        let mut y = *guess;
        for i in 0..3 {
            y[i] -= x[3 + i];
        }
        let mut previous = f64::INFINITY;
        for iteration in 1..=NEWTON_MAX_ITERATIONS {
            let (residual, jacobian) = self.step_equations(x, r, &y);
            let dy = solve_structured(&jacobian, &residual)?;
            y -= dy;
            if !y.iter().all(|v| v.is_finite()) {
                return None;
            }
            let z = self.step_unknowns(x, &y);
            let update = dy.iter().zip(z.iter()).map(|(d, v)| d.abs() / (1.0 + v.abs())).fold(0.0, f64::max);
            if update <= NEWTON_TOLERANCE {
                return Some((z, iteration));
            }
            // Stalled (no more quadratic decrease) at the rounding floor: more iterations only
            // chase the residual's rounding.
            if iteration > 1 && update > 0.25 * previous {
                let floor = rounding_floor(&jacobian, &self.row_rounding(x, r, &y));
                let at_floor = (0..5).all(|i| {
                    dy[i].abs() <= NEWTON_STALL_TOLERANCE * (1.0 + z[i].abs())
                        || dy[i].abs() <= NEWTON_FLOOR_MARGIN * floor[i]
                });
                if at_floor {
                    return Some((z, iteration));
                }
            }
            previous = update;
        }
        None
    }

    /// z = (q̇⁺, U⁺) from y = (Δq̇, U⁺).
    fn step_unknowns(&self, x: &StateVector, y: &StepUnknowns) -> StepUnknowns {
        StepUnknowns::new(x[3] + y[0], x[4] + y[1], x[5] + y[2], y[3], y[4])
    }

    /// X⁺ from X and the step's solution z: q⁺ = q + ε q̇⁺, w⁺ = w + ε α³ (q⁺ − q_d), the w⁺ the
    /// step's constraint row solved with.
    pub fn advance_state(&self, x: &StateVector, r: &ReferenceSample, z: &StepUnknowns) -> StateVector {
        let e = self.eps;
        let mut next = StateVector::zeros();
        for i in 0..3 {
            next[i] = x[i] + e * z[i];
            next[3 + i] = z[i];
        }
        for i in 0..2 {
            let a = self.alpha[i];
            // q⁺ − q_d as the residual forms it (see `step_point`).
            let error = ((x[i] - r.q[i]) + e * x[3 + i]) + e * (z[i] - x[3 + i]);
            next[6 + i] = x[6 + i] + e * a * a * a * error;
        }
        next
    }

    /// The residual R(z) of one step (see the module docs).
    pub fn residual(&self, x: &StateVector, r: &ReferenceSample, z: &StepUnknowns) -> StepUnknowns {
        self.residual_and_jacobian(x, r, z).0
    }

    /// The residual and its analytic Jacobian ∂R/∂z.
    pub fn residual_and_jacobian(
        &self,
        x: &StateVector,
        r: &ReferenceSample,
        z: &StepUnknowns,
    ) -> (StepUnknowns, StepJacobian) {
        let y = StepUnknowns::new(z[0] - x[3], z[1] - x[4], z[2] - x[5], z[3], z[4]);
        self.step_equations(x, r, &y)
    }

    /// The quantities of one step at y = (Δq̇, U⁺). Every one that is small in a step (the
    /// acceleration, the stretch, the errors) is formed from the small changes, never as the
    /// difference of two rounded large ones (see "Small ε").
    fn step_point(&self, x: &StateVector, r: &ReferenceSample, y: &StepUnknowns) -> StepPoint {
        let e = self.eps;
        let v = Vector3::new(x[3], x[4], x[5]);
        let dv = Vector3::new(y[0], y[1], y[2]);
        let v_next = v + dv;
        let mut error = Vector2::zeros();
        let mut rate_error = Vector2::zeros();
        let mut w_next = Vector2::zeros();
        for i in 0..2 {
            // q⁺ − q_d and q̇⁺ − q̇_d from the step's change.
            error[i] = ((x[i] - r.q[i]) + e * v[i]) + e * dv[i];
            rate_error[i] = (v[i] - r.qdot[i]) + dv[i];
            w_next[i] = x[6 + i] + e * self.alpha[i] * self.alpha[i] * self.alpha[i] * error[i];
        }
        StepPoint {
            q_next: Vector3::new(x[0], x[1], x[2]) + v_next * e,
            v_next,
            acc: dv / e,
            // θ⁺ − q1⁺ = (θ − q1) + ε ((θ̇ − q̇1) + (Δθ̇ − Δq̇1)).
            stretch: (x[2] - x[0]) + e * ((v[2] - v[0]) + (dv[2] - dv[0])),
            torque: Vector2::new(y[3], y[4]),
            error,
            rate_error,
            w_next,
        }
    }

    /// The residual and its Jacobian ∂R/∂y (= ∂R/∂z) at y = (Δq̇, U⁺).
    fn step_equations(&self, x: &StateVector, r: &ReferenceSample, y: &StepUnknowns) -> (StepUnknowns, StepJacobian) {
        let e = self.eps;
        let p = self.step_point(x, r, y);
        let m = self.plant.mass_matrix(p.q_next[1]);
        let dyn_res =
            m * p.acc - self.plant.forces_stretched(p.q_next[1], p.stretch, &p.v_next, &Vector2::zeros(), &p.torque);

        let mut res = StepUnknowns::zeros();
        let mut jac = StepJacobian::zeros();
        res.fixed_rows_mut::<3>(0).copy_from(&dyn_res);

        // ∂R_dyn/∂q̇⁺ = M/ε + ε (∂M/∂q2 · acc) e2ᵀ − ε ∂r/∂q − ∂r/∂q̇.
        let (dr_dq, dr_dv) = self.plant.force_jacobians(&p.q_next, &p.v_next);
        let mut d_dyn = m / e - dr_dq * e - dr_dv;
        let dm_acc = self.plant.mass_matrix_dq2(p.q_next[1]) * p.acc;
        for row in 0..3 {
            d_dyn[(row, 1)] += e * dm_acc[row];
        }
        jac.fixed_view_mut::<3, 3>(0, 0).copy_from(&d_dyn);
        jac.fixed_view_mut::<3, 2>(0, 3).copy_from(&(-Plant::input_matrix()));

        for i in 0..2 {
            let a = self.alpha[i];
            res[3 + i] = (p.acc[i] - r.qddot[i]) + 3.0 * a * p.rate_error[i] + 3.0 * a * a * p.error[i] + p.w_next[i];
            jac[(3 + i, i)] = 1.0 / e + 3.0 * a + 3.0 * a * a * e + a * a * a * e * e;
        }
        (res, jac)
    }

    /// The rounding of each row of the residual at y: the unit roundoff times the sum of its
    /// terms' magnitudes (computed only when Newton stalls).
    fn row_rounding(&self, x: &StateVector, r: &ReferenceSample, y: &StepUnknowns) -> StepUnknowns {
        let p = self.step_point(x, r, y);
        let m = self.plant.mass_matrix(p.q_next[1]);
        let size = m.abs() * p.acc.abs() + self.plant.force_magnitudes(p.q_next[1], p.stretch, &p.v_next, &p.torque);
        let mut rounding = StepUnknowns::zeros();
        rounding.fixed_rows_mut::<3>(0).copy_from(&(size * f64::EPSILON));
        for i in 0..2 {
            let a = self.alpha[i];
            let size = p.acc[i].abs()
                + r.qddot[i].abs()
                + 3.0 * a * (x[3 + i].abs() + r.qdot[i].abs() + y[i].abs())
                + 3.0 * a * a * (x[i].abs() + r.q[i].abs() + self.eps * p.v_next[i].abs())
                + p.w_next[i].abs();
            rounding[3 + i] = size * f64::EPSILON;
        }
        rounding
    }
}

/// One backward-Euler step's quantities at an iterate (see [`Predictor::step_point`]).
struct StepPoint {
    q_next: Vector3<f64>,
    v_next: Vector3<f64>,
    /// (q̇⁺ − q̇)/ε.
    acc: Vector3<f64>,
    /// θ⁺ − q1⁺.
    stretch: f64,
    torque: Vector2<f64>,
    /// q⁺ − q_d.
    error: Vector2<f64>,
    /// q̇⁺ − q̇_d.
    rate_error: Vector2<f64>,
    w_next: Vector2<f64>,
}

/// The rounding floor of one step's unknowns: how far the rows' `rounding` can move z
/// through J⁻¹, bounded by the structured back-substitution of [`solve_structured`] in magnitudes
/// (no cancellation assumed). The pivots are nonzero where this is called.
fn rounding_floor(j: &StepJacobian, rounding: &StepUnknowns) -> StepUnknowns {
    let dv1 = rounding[3] / j[(3, 0)].abs();
    let dv2 = rounding[4] / j[(4, 1)].abs();
    let dtheta = (rounding[0] + j[(0, 0)].abs() * dv1 + j[(0, 1)].abs() * dv2) / j[(0, 2)].abs();
    let dt2 = j[(1, 0)].abs() * dv1 + j[(1, 1)].abs() * dv2 + j[(1, 2)].abs() * dtheta + rounding[1];
    let dt1 = j[(2, 0)].abs() * dv1 + j[(2, 1)].abs() * dv2 + j[(2, 2)].abs() * dtheta + rounding[2];
    StepUnknowns::new(dv1, dv2, dtheta, dt1, dt2)
}

/// Solves J dz = R for the Jacobian of one step by back-substitution along its sparsity:
/// the constraint rows involve only q̇1⁺ and q̇2⁺ (diagonally), the first dynamics row involves θ̇⁺
/// only through the spring (∂/∂θ̇⁺ = −ε K1 ≠ 0) and no torque, and T2, T1 enter the second and
/// third dynamics rows alone with coefficient −1. Returns `None` if a pivot vanishes.
#[inline]
pub fn solve_structured(j: &StepJacobian, r: &StepUnknowns) -> Option<StepUnknowns> {
    let (c1, c2, pivot) = (j[(3, 0)], j[(4, 1)], j[(0, 2)]);
    if c1 == 0.0 || c2 == 0.0 || pivot == 0.0 {
        return None;
    }
    let dv1 = r[3] / c1;
    let dv2 = r[4] / c2;
    let dtheta = (r[0] - j[(0, 0)] * dv1 - j[(0, 1)] * dv2) / pivot;
    // Row 1: j10 dv1 + j11 dv2 + j12 dθ̇ − dT2 = r1; row 2 likewise with −dT1.
    let dt2 = j[(1, 0)] * dv1 + j[(1, 1)] * dv2 + j[(1, 2)] * dtheta - r[1];
    let dt1 = j[(2, 0)] * dv1 + j[(2, 1)] * dv2 + j[(2, 2)] * dtheta - r[2];
    Some(StepUnknowns::new(dv1, dv2, dtheta, dt1, dt2))
}
