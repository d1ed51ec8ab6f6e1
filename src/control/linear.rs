//! The stabilized DAE (4.1)–(4.3) linearized at rest, the predictor as a linear map, and its
//! δ → 0 limit (section 3): the feedback K_lim, the invariant subspace V* it keeps at −α, and the
//! pair A4 on the quotient, which it has no gain on (its θ and θ̇ columns are zero) — the joint's
//! resonance as the controller leaves it (closed form: [`crate::analysis::resonance`]).
//!
//! Everything here is built from the same plant functions the simulation uses
//! ([`crate::model::Plant`]), linearized at rest (zero velocities, θ = q1, no torque), where the
//! Coriolis terms and ∂M/∂q2 · q̈ vanish. The friction is taken as cancelled by the observer
//! (continuous compensation). The preliminary-feedback design ([`super::feedback`]) and the
//! stability analysis ([`crate::analysis`]) both start from here.

use nalgebra::{Complex, Matrix2, SMatrix};

use crate::control::config::ControllerParameters;
use crate::control::predictive::{FeedbackGain, StateVector};
use crate::error::Error;
use crate::model::params::PlantParameters;
use crate::model::plant::Plant;

pub(crate) type Mat8 = SMatrix<f64, 8, 8>;
pub type Mat10 = SMatrix<f64, 10, 10>;

/// The arm, the integrators w and the stabilized constraint linearized at rest:
/// ẋ = A x + B u, constraint 0 = C x + D u (in deviations from `rest`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearModel {
    pub a: Mat8,
    pub b: SMatrix<f64, 8, 2>,
    pub c: SMatrix<f64, 2, 8>,
    pub d: SMatrix<f64, 2, 2>,
    /// The operating point X at rest.
    pub rest: StateVector,
}

/// Linearizes plant, integrators (4.2) and constraint (4.3) at rest at link angles `q_rest`.
pub fn linearize_at_rest(plant: &PlantParameters, alpha: [f64; 2], q_rest: [f64; 2]) -> LinearModel {
    let model = Plant::new(*plant);
    let q = nalgebra::Vector3::new(q_rest[0], q_rest[1], q_rest[0]);
    let v = nalgebra::Vector3::zeros();
    let (dr_dq, dr_dv) = model.force_jacobians(&q, &v);
    let m_inv = model.mass_matrix(q_rest[1]).try_inverse().expect("validated mass matrix is invertible");
    let acc_q = m_inv * dr_dq;
    let acc_v = m_inv * dr_dv;
    let acc_u = m_inv * Plant::input_matrix();

    let mut a = Mat8::zeros();
    let mut b = SMatrix::<f64, 8, 2>::zeros();
    for i in 0..3 {
        a[(i, 3 + i)] = 1.0;
        for j in 0..3 {
            a[(3 + i, j)] = acc_q[(i, j)];
            a[(3 + i, 3 + j)] = acc_v[(i, j)];
        }
        for j in 0..2 {
            b[(3 + i, j)] = acc_u[(i, j)];
        }
    }
    let mut c = SMatrix::<f64, 2, 8>::zeros();
    let mut d = SMatrix::<f64, 2, 2>::zeros();
    for i in 0..2 {
        let al = alpha[i];
        a[(6 + i, i)] = al * al * al;
        // y_i = q̈_i + 3α q̇_i + 3α² q_i + w_i, with q̈_i from the equations of motion.
        for j in 0..8 {
            c[(i, j)] = a[(3 + i, j)];
        }
        c[(i, 3 + i)] += 3.0 * al;
        c[(i, i)] += 3.0 * al * al;
        c[(i, 6 + i)] += 1.0;
        for j in 0..2 {
            d[(i, j)] = b[(3 + i, j)];
        }
    }
    let rest = StateVector::from_column_slice(&[q_rest[0], q_rest[1], q_rest[0], 0.0, 0.0, 0.0, 0.0, 0.0]);
    LinearModel { a, b, c, d, rest }
}

impl LinearModel {
    /// A + B K: the arm's matrix with the state feedback u = K x folded in. Out of line, so one
    /// copy of the unrolled product serves the pencil, the limit and the sampled loop (the page's
    /// module is smaller).
    #[inline(never)]
    pub fn with_feedback(&self, k: &FeedbackGain) -> Mat8 {
        self.a + self.b * k
    }
}

/// The pencil (E, F) of the linear DAE E ż = F z, z = (x, v), for the plant with the
/// preliminary feedback u = K x + v folded in: F = [[A + BK, B], [C + DK, D]], E = diag(I8, 0).
pub(crate) fn pencil(model: &LinearModel, gain: &FeedbackGain) -> (Mat10, Mat10) {
    let a = model.with_feedback(gain);
    let c = model.c + model.d * gain;
    let mut f = Mat10::zeros();
    f.fixed_view_mut::<8, 8>(0, 0).copy_from(&a);
    f.fixed_view_mut::<8, 2>(0, 8).copy_from(&model.b);
    f.fixed_view_mut::<2, 8>(8, 0).copy_from(&c);
    f.fixed_view_mut::<2, 2>(8, 8).copy_from(&model.d);
    let mut e = Mat10::zeros();
    for i in 0..8 {
        e[(i, i)] = 1.0;
    }
    (e, f)
}

/// One backward-Euler step of the linear DAE as a map z_j ↦ z_{j+1} = (E − εF)⁻¹ E z_j.
pub(crate) fn backward_euler_map(e: &Mat10, f: &Mat10, eps: f64) -> Result<Mat10, Error> {
    let lhs = e - f * eps;
    lhs.lu().solve(e).ok_or(Error::Analysis("the backward-Euler step of the linearized DAE is singular"))
}

/// e^M by scaling and squaring a Taylor series: M is scaled by 2^−s until its ∞-norm is at most
/// 1/8, where ten terms leave a relative error below 1e-18, and the result squared s times.
/// Written for the sampled loop's 10×10 transition matrices: nalgebra's general `exp` (Padé with
/// norm estimation) was 15 kB of the page's module; this is a few hundred bytes, and
/// `tests/analysis.rs` checks it against nalgebra's to 1e-10 of the largest entry.
pub fn expm(m: &Mat10) -> Mat10 {
    let norm = m.row_iter().map(|r| r.iter().map(|v| v.abs()).sum::<f64>()).fold(0.0, f64::max);
    if !norm.is_finite() {
        return Mat10::from_element(f64::NAN);
    }
    let squarings = if norm > 0.125 { (norm / 0.125).log2().ceil() as i32 } else { 0 };
    let a = m * 0.5f64.powi(squarings);
    let mut term = Mat10::identity();
    let mut sum = Mat10::identity();
    for k in 1..=10 {
        term = term * a / k as f64;
        sum += term;
    }
    for _ in 0..squarings {
        sum = sum * sum;
    }
    sum
}

pub(crate) fn matrix_power(m: &Mat10, mut k: usize) -> Mat10 {
    let mut result = Mat10::identity();
    let mut base = *m;
    while k > 0 {
        if k & 1 == 1 {
            result *= base;
        }
        base = base * base;
        k >>= 1;
    }
    result
}

/// The linearized predictor at finite δ: V_k = K_pred x_0 (k steps of ε = δ/m), a 2×8 gain.
pub fn predictor_gain(
    model: &LinearModel,
    gain: &FeedbackGain,
    controller: &ControllerParameters,
) -> Result<SMatrix<f64, 2, 8>, Error> {
    let (e, f) = pencil(model, gain);
    let step = backward_euler_map(&e, &f, controller.integration_step())?;
    let sweep = matrix_power(&step, controller.horizon_steps);
    Ok(sweep.fixed_view::<2, 8>(8, 0).into_owned())
}

/// The fastest rate of the arm with the preliminary feedback u = K x + v acting continuously,
/// 1/s: the largest |λ| of A + BK linearized at rest, over the postures from stretched to folded
/// (the mass matrix depends on cos q2 alone), and at least the arm's own
/// [`PlantParameters::fastest_rate`]. The plant's integrator must follow it, not only the arm's:
/// the paper's K_pr puts a damper of 16.5 N m s/rad on the motor, 8.5 1/s on the paper's motor
/// but 8500 1/s on one a thousand times lighter, where a step sized for the arm alone (h = 0.3/770 s)
/// made RK4 itself unstable and the run "diverged" at t = 0.01 s with ρ = 0.98.
pub fn inner_loop_rate(plant: &PlantParameters, alpha: [f64; 2], gain: &FeedbackGain) -> f64 {
    let mut rate = plant.fastest_rate();
    if gain.iter().all(|k| *k == 0.0) {
        return rate;
    }
    for i in 0..=20 {
        let c: f64 = -1.0 + 0.1 * i as f64;
        let model = linearize_at_rest(plant, alpha, [0.0, c.clamp(-1.0, 1.0).acos()]);
        // Padded into the 10×10 size whose eigen-solver the page's module already has.
        let mut m = Mat10::zeros();
        m.fixed_view_mut::<8, 8>(0, 0).copy_from(&model.with_feedback(gain));
        for l in m.complex_eigenvalues().iter() {
            rate = rate.max(l.norm());
        }
    }
    rate
}

/// The δ → 0 limit of the predictive controller and the pair it has no gain on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LimitPair {
    /// K_lim: the limit of the predictor's V_k as a feedback on x_0.
    pub k_lim: SMatrix<f64, 2, 8>,
    /// Ψ: x ↦ x2, the motor coordinates (θ, θ̇) measured from the invariant subspace V*.
    pub coordinates: SMatrix<f64, 2, 8>,
    /// A4: the closed loop A + B(K + K_lim) on the quotient ℝ⁸/V*, in the coordinates x2.
    pub a4: Matrix2<f64>,
    /// B2 = Ψ B: how (T1, T2) enter x2.
    pub b2: Matrix2<f64>,
    /// The eigenvalues of A4, positive imaginary part first.
    pub eigenvalues: [Complex<f64>; 2],
    /// The largest entry of (I − Π_x) outside the θ and θ̇ rows: ≈ 0 confirms that the limit
    /// controller ignores the motor coordinates.
    pub off_motor_residual: f64,
}

/// Computes the δ → 0 limit of the predictor for the plant with preliminary feedback `gain`.
///
/// Backward Euler on a linear index-3 DAE forgets its inconsistent start after three steps,
/// whatever ε: ((E − εF)⁻¹E)^k = Q diag((I − εJ)^(−k), 0) Q⁻¹ for k ≥ 3 in Weierstrass form. So
/// the k-step map at any moderate ε has exactly the range (finite deflating subspace) and kernel
/// (infinite one) of the limit projector Π. Its nonzero eigenvalues are (1 + εα_i)^(−k), all in
/// (0.6, 1] for εα ≤ 0.1, and the purification X ← X²(3I − 2X) takes them to 1 while keeping the
/// zero ones at 0, giving Π. (The plain Newton step X ← X(2I − X) doubles the rounding noise on
/// the zero eigenvalues at every step and diverged for some α, e.g. α1 = 1, α2 = 3; the
/// purification's fixed points 0 and 1 are both attracting.) Then K_lim x = the v-part of
/// Π (x, 0), V* = range of Π's x-part, and A4 is A + B(K + K_lim) on ℝ⁸/V*.
pub fn limit_pair(model: &LinearModel, gain: &FeedbackGain) -> Result<LimitPair, Error> {
    let (e, f) = pencil(model, gain);
    // The finite spectrum of the pencil is the constrained error dynamics at −α; keep ελ small.
    let alpha_max = model.a[(6, 0)].cbrt().max(model.a[(7, 1)].cbrt()).max(1e-3);
    let eps = 0.1 / alpha_max;
    let step = backward_euler_map(&e, &f, eps)?;
    let proj = limit_projector(matrix_power(&step, 4))?;
    let proj_x: Mat8 = proj.fixed_view::<8, 8>(0, 0).into_owned();
    let k_lim: SMatrix<f64, 2, 8> = proj.fixed_view::<2, 8>(8, 0).into_owned();
    let complement = Mat8::identity() - proj_x;
    let mut coordinates = SMatrix::<f64, 2, 8>::zeros();
    coordinates.set_row(0, &complement.row(2));
    coordinates.set_row(1, &complement.row(5));
    let mut off_motor_residual: f64 = 0.0;
    for r in [0, 1, 3, 4, 6, 7] {
        off_motor_residual = off_motor_residual.max(complement.row(r).amax());
    }
    let closed = model.with_feedback(&(gain + k_lim));
    let projected = coordinates * closed;
    let a4 = Matrix2::new(projected[(0, 2)], projected[(0, 5)], projected[(1, 2)], projected[(1, 5)]);
    let b2 = coordinates * model.b;
    let ev = a4.complex_eigenvalues();
    let eigenvalues = if ev[0].im >= ev[1].im { [ev[0], ev[1]] } else { [ev[1], ev[0]] };
    Ok(LimitPair { k_lim, coordinates, a4, b2, eigenvalues, off_motor_residual })
}

/// The projector Π with the range and kernel of `x`, whose eigenvalues lie near 0 or near 1:
/// the purification X ← X²(3I − 2X) until X² = X to rounding.
fn limit_projector(mut x: Mat10) -> Result<Mat10, Error> {
    for _ in 0..60 {
        let square = x * x;
        let next = square * 3.0 - square * x * 2.0;
        let change = (next - x).amax();
        x = next;
        if change <= 1e-13 * x.amax().max(1.0) {
            break;
        }
    }
    // Accept only an idempotent result: the iteration stalls at rounding, it cannot wander off.
    let residual = (x * x - x).amax();
    // NaN fails the test too.
    if residual.is_nan() || residual > 1e-9 * x.amax().max(1.0) {
        return Err(Error::Analysis("the limit projector did not converge"));
    }
    Ok(x)
}
