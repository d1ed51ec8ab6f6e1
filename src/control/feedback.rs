//! Preliminary feedback u = K_pr x + v (sections 3–4): the paper's gain, and an LQ gain designed
//! the way the paper did.
//!
//! # The LQ design
//! In the limit δ → 0 the predictive controller acts as a linear feedback K_lim that keeps a
//! 6-dimensional subspace V* (the consistent states of the stabilized DAE) invariant with all six
//! eigenvalues at −α, and never looks at the motor coordinates x2 = (θ, θ̇): it has no gain on the
//! quotient ℝ⁸/V*, whose 2×2 matrix A4 it cannot move (see [`super::linear::limit_pair`]). That
//! does not make A4 the arm's own motion: the way the predictor drives the links through the
//! spring is part of it, and feeds the joint's resonance (Re A4 = 3α/2 − Bv1/(2 Ir1), see
//! [`crate::analysis::resonance`]). The preliminary feedback is designed on that part alone,
//! u = K2 x2, with x2 = Ψ x the motor coordinates measured from V*, and mapped back to the full
//! state, K_pr = K2 Ψ.
//!
//! K2 is the LQ gain for ẋ2 = A4 x2 + B2 u (B2 = Ψ B), by default ([`LqWeights`], settings
//! `lq_q_twist`, `lq_q_rate`, `lq_r`) with a tiny state weight Q = 1e-6 · I2 and R = diag(1, 6.7): a minimum-energy design that reflects the unstable pair
//! into the left half-plane (2.639 ± 29.58j → −2.639 ± 29.58j) with the least torque, weighting
//! T2 about 6.7 times more than T1 (ERRATA.md says "about 6"; 6.7 reproduces both printed rows of
//! K_pr at q2 = 0, α = 2 to within 2.5 %, while 6 leaves the T2 row 11 % high).

use nalgebra::{Complex, Matrix2, Matrix4, SMatrix};
use serde::Serialize;

pub use crate::control::config::{LqWeights, LQ_T2_RATIO};
use crate::control::config::{PreliminaryFeedbackChoice, SimulationConfig};
use crate::control::linear::{limit_pair, linearize_at_rest};
use crate::error::Error;
use crate::model::params::PlantParameters;

pub use crate::control::predictive::FeedbackGain;

/// The α the paper designed its K_pr for (on its own arm), 1/s.
pub const PAPER_GAIN_ALPHA: f64 = 2.0;

/// The paper's K_pr (section 4), acting on the absolute state.
pub fn paper_gain() -> FeedbackGain {
    FeedbackGain::from_row_slice(&[
        102.3, -0.07, -103.0, 15.97, -0.10, -17.0, 0.0, 0.0, //
        16.17, -0.01, -16.3, 2.55, -0.02, -2.71, 0.0, 0.0,
    ])
}

/// A feedback of the joint's twist alone on the motor torque, T1 += k_p (q1 − θ) + k_d (q̇1 − θ̇):
/// a spring (`stiffness` k_p, N m/rad) and a damper (`damping` k_d, N m s/rad) between motor and
/// link 1, applied by the motor. It acts on the pair A4 through its θ and θ̇ columns only
/// ([`crate::analysis::resonance`]): Re A4 = 3β/2 − (Bv1 + k_d)/(2 Ir1).
pub fn twist_gain(stiffness: f64, damping: f64) -> FeedbackGain {
    let mut k = FeedbackGain::zeros();
    // The state is (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2); row 0 is T1.
    k[(0, 0)] = stiffness;
    k[(0, 2)] = -stiffness;
    k[(0, 3)] = damping;
    k[(0, 5)] = -damping;
    k
}

/// A gain split into its twist part — a spring k_p (q1 − θ) and a damper k_d (q̇1 − θ̇) on each
/// torque — and the rest.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TwistParts {
    /// [k_p, k_d] of the T1 row and of the T2 row.
    pub t1: [f64; 2],
    pub t2: [f64; 2],
    /// The largest |entry| of the gain minus its twist parts.
    pub rest: f64,
}

/// The twist parts of a gain: on each row, the spring is the mean of the q1 and −θ entries and the
/// damper that of the q̇1 and −θ̇ entries (for the paper's K_pr: T1 ≈ 102.7 (q1 − θ) + 16.5 (q̇1 − θ̇)).
pub fn twist_parts(gain: &FeedbackGain) -> TwistParts {
    let row = |r: usize| [0.5 * (gain[(r, 0)] - gain[(r, 2)]), 0.5 * (gain[(r, 3)] - gain[(r, 5)])];
    let (t1, t2) = (row(0), row(1));
    let mut rest = *gain;
    for (r, [kp, kd]) in [(0, t1), (1, t2)] {
        rest[(r, 0)] -= kp;
        rest[(r, 2)] += kp;
        rest[(r, 3)] -= kd;
        rest[(r, 5)] += kd;
    }
    TwistParts { t1, t2, rest: rest.amax() }
}

/// The outcome of the LQ design.
#[derive(Clone, Debug, PartialEq)]
pub struct LqDesign {
    /// K_pr = K2 Ψ on the full state.
    pub gain: FeedbackGain,
    /// K2, the gain on the motor coordinates x2 = Ψ x.
    pub k2: Matrix2<f64>,
    /// A4 and its eigenvalues without preliminary feedback.
    pub open_pair: [Complex<f64>; 2],
    /// Eigenvalues of A4 + B2 K2.
    pub closed_pair: [Complex<f64>; 2],
}

/// Designs the LQ preliminary feedback at rest at (q1, q2) for the stabilizing constants α.
pub fn design_lq(
    plant: &PlantParameters,
    alpha: [f64; 2],
    q_rest: [f64; 2],
    weights: &LqWeights,
) -> Result<LqDesign, Error> {
    let model = linearize_at_rest(plant, alpha, q_rest);
    let open = limit_pair(&model, &FeedbackGain::zeros())?;
    let q = Matrix2::new(weights.twist, 0.0, 0.0, weights.twist_rate);
    let (r1, r2) = (weights.torque, weights.torque * LQ_T2_RATIO);
    let r = Matrix2::new(r1, 0.0, 0.0, r2);
    let p = solve_care(&open.a4, &open.b2, &q, &r)?;
    // u = K2 x2 with K2 = −R⁻¹ B2ᵀ P.
    let r_inv = Matrix2::new(1.0 / r1, 0.0, 0.0, 1.0 / r2);
    let k2 = -(r_inv * open.b2.transpose() * p);
    let gain = k2 * open.coordinates;
    let closed = (open.a4 + open.b2 * k2).complex_eigenvalues();
    Ok(LqDesign { gain, k2, open_pair: open.eigenvalues, closed_pair: [closed[0], closed[1]] })
}

/// The gain selected by a configuration (zero when the preliminary feedback is off).
pub fn resolve_gain(config: &SimulationConfig) -> Result<FeedbackGain, Error> {
    match config.preliminary_feedback {
        PreliminaryFeedbackChoice::Off => Ok(FeedbackGain::zeros()),
        PreliminaryFeedbackChoice::Paper => Ok(paper_gain()),
        PreliminaryFeedbackChoice::Lq => {
            let q_rest = [config.reference.end[0], config.lq_design_q2];
            Ok(design_lq(&config.model_plant(), config.controller.alpha, q_rest, &config.lq)?.gain)
        }
        PreliminaryFeedbackChoice::Twist => Ok(twist_gain(config.twist.stiffness, config.twist.damping)),
    }
}

/// Solves the continuous algebraic Riccati equation AᵀP + PA − PBR⁻¹BᵀP + Q = 0 for the
/// stabilizing P of a system with two states and `M` inputs (the preliminary feedback's design
/// on A4), by the matrix sign function of the Hamiltonian H = [[A, −BR⁻¹Bᵀ], [−Q, −Aᵀ]]: the
/// stable invariant subspace is ker(sign H + I). Fixed sizes throughout: no allocation, and a
/// fraction of the generic solver's code in the page.
pub fn solve_care<const M: usize>(
    a: &Matrix2<f64>,
    b: &SMatrix<f64, 2, M>,
    q: &Matrix2<f64>,
    r: &SMatrix<f64, M, M>,
) -> Result<Matrix2<f64>, Error> {
    let r_inv = r.try_inverse().ok_or(Error::Analysis("Riccati: R is singular"))?;
    let g = b * r_inv * b.transpose();
    let mut h = Matrix4::zeros();
    h.fixed_view_mut::<2, 2>(0, 0).copy_from(a);
    h.fixed_view_mut::<2, 2>(0, 2).copy_from(&(-g));
    h.fixed_view_mut::<2, 2>(2, 0).copy_from(&(-q));
    h.fixed_view_mut::<2, 2>(2, 2).copy_from(&(-a.transpose()));

    // Newton iteration for the sign function with determinant scaling (|det|^(1/4) for 4×4).
    let mut z = h;
    let mut converged = false;
    for _ in 0..100 {
        let inv =
            z.try_inverse().ok_or(Error::Analysis("Riccati: Hamiltonian has eigenvalues on the imaginary axis"))?;
        let det = z.determinant().abs();
        let c = if det.is_finite() && det > 0.0 { det.powf(0.25) } else { 1.0 };
        let next = (z / c + inv * c) * 0.5;
        let change = (next - z).norm() / next.norm().max(1.0);
        z = next;
        if change < 1e-13 {
            converged = true;
            break;
        }
    }
    if !converged {
        return Err(Error::Analysis("Riccati: sign iteration did not converge"));
    }
    // [W12; W22 + I] P = −[W11 + I; W21], in the least-squares sense (QR).
    let id = Matrix2::<f64>::identity();
    let mut lhs = SMatrix::<f64, 4, 2>::zeros();
    lhs.fixed_view_mut::<2, 2>(0, 0).copy_from(&z.fixed_view::<2, 2>(0, 2));
    lhs.fixed_view_mut::<2, 2>(2, 0).copy_from(&(z.fixed_view::<2, 2>(2, 2) + id));
    let mut rhs = SMatrix::<f64, 4, 2>::zeros();
    rhs.fixed_view_mut::<2, 2>(0, 0).copy_from(&(-(z.fixed_view::<2, 2>(0, 0) + id)));
    rhs.fixed_view_mut::<2, 2>(2, 0).copy_from(&(-z.fixed_view::<2, 2>(2, 0)));
    let qr = lhs.qr();
    let p = qr
        .r()
        .solve_upper_triangular(&(qr.q().transpose() * rhs))
        .ok_or(Error::Analysis("Riccati: least-squares solve failed"))?;
    let p = (p + p.transpose()) * 0.5;
    if !p.iter().all(|v| v.is_finite()) {
        return Err(Error::Analysis("Riccati: no finite solution"));
    }
    Ok(p)
}
