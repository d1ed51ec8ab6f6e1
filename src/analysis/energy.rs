//! The mechanism behind the windows of δ: the swing's energy over one sampling period — what the
//! held torque puts into the flexible pair, what the preliminary feedback and the arm's damping
//! take out — and the phase by which the held torque lags the swing (beyond the paper, which
//! calls the windows "not clear"; `tests/energy.rs` checks it against ρ over arms and α).
//!
//! Take the flexible pair's eigenvector ζ = (x, v) of the one-period map Φ (eigenvalue λ) as the
//! loop's state at t_n: the held torque v acts over [t_n, t_n + δ) while the arm moves from x to
//! λx. Along that motion the arm's energy E = ½ q̇ᴴ M q̇ + ½ K1 |θ − q1|² obeys
//!
//! dE/dt = Re(q̇ᴴ B_u u) − Re(q̇ᴴ D q̇),   D = diag(0, B_v2, B_v1),
//!
//! with u = v + K x the torques (the preliminary feedback K continuous or held). Integrated over
//! the period and divided by E(t_n) this is an exact balance,
//!
//! |λ|² − 1 = (work of v) + (work of K x) − (loss to damping),
//!
//! so the pair grows (|λ| > 1) exactly when the held torque puts in more energy than the rest
//! takes out. Without preliminary feedback and with a motor without damping, the sign of the held
//! torque's work alone decides: it pushes while it is less than a quarter turn behind the motor's
//! velocity and brakes beyond — the lag law of [`super::lag`], here computed, not estimated.

use nalgebra::{Complex, SMatrix, Vector3};
use serde::{Deserialize, Serialize};

use super::sampled::LoopModel;
use crate::control::config::InnerLoop;
use crate::control::linear::{expm, Mat10};
use crate::error::Error;
use crate::model::plant::Plant;

/// Substeps of the period for the energy integrals (Simpson's rule): at least this many, and at
/// least [`SUBSTEPS_PER_RADIAN`] per radian the arm's fastest motion turns.
const MIN_SUBSTEPS: usize = 48;
const SUBSTEPS_PER_RADIAN: f64 = 16.0;

type CVec10 = SMatrix<Complex<f64>, 10, 1>;
type CVec3 = Vector3<Complex<f64>>;

/// The flexible pair's energy over one sampling period, each as a fraction of its energy at t_n.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SwingEnergy {
    /// Work of the held (predicted) torque v: > 0 feeds the swing, < 0 brakes it.
    pub held_torque: f64,
    /// Work of the preliminary feedback's torque K x (0 without it).
    pub preliminary_feedback: f64,
    /// Energy the arm's viscous damping takes out (≥ 0).
    pub damping: f64,
    /// How far the held motor torque T1 lags the motor's mean velocity over the period, rad in
    /// [0, 2π): below π/2 or above 3π/2 it pushes, in between it brakes.
    pub lag: f64,
}

impl SwingEnergy {
    /// The net change of the swing's energy per period, |λ|² − 1 (up to the integration error).
    pub fn net(&self) -> f64 {
        self.held_torque + self.preliminary_feedback - self.damping
    }
}

/// The swing's energy over one period at sampling period `delta` for the pair with eigenvalue
/// `lambda` (from [`super::StabilityReport::flexible_pair`] at the same δ).
pub fn swing_energy(loop_model: &LoopModel, delta: f64, lambda: Complex<f64>) -> Result<SwingEnergy, Error> {
    let phi = loop_model.loop_matrix(delta)?;
    let zeta = eigenvector(&phi, lambda).ok_or(Error::Analysis("the flexible pair has no eigenvector"))?;
    let arm = loop_model.arm();
    let gain = loop_model.gain();
    let held_feedback = loop_model.settings().inner_loop == InnerLoop::Sampled;
    let params = loop_model.settings().plant;
    let plant = Plant::new(params);
    let mass = plant.mass_matrix(loop_model.settings().rest[1]).map(|m| Complex::new(m, 0.0));
    let input = Plant::input_matrix().map(|m| Complex::new(m, 0.0));
    let damping = Vector3::new(0.0, params.bv2, params.bv1);

    // The motion over the period: (x, u_held) with ẋ = A' x + B u_held, u_held constant, where
    // A' = A + BK for a continuous preliminary feedback, and u_held = v + K x(t_n) when it is held.
    let mut aug = Mat10::zeros();
    let a = if held_feedback { arm.a } else { arm.with_feedback(gain) };
    // √‖A‖ bounds the fastest frequency of a mass–spring system (‖A‖ ≥ K/m).
    let fastest = a.amax().sqrt();
    let substeps = MIN_SUBSTEPS.max(2 * (SUBSTEPS_PER_RADIAN * fastest * delta / 2.0).ceil() as usize).min(4096);
    let h = delta / substeps as f64;
    aug.fixed_view_mut::<8, 8>(0, 0).copy_from(&(a * h));
    aug.fixed_view_mut::<8, 2>(0, 8).copy_from(&(arm.b * h));
    let step = expm(&aug).map(|m| Complex::new(m, 0.0));
    let k = gain.map(|m| Complex::new(m, 0.0));
    let x0 = zeta.fixed_rows::<8>(0).into_owned();
    let v = zeta.fixed_rows::<2>(8).into_owned();
    let mut state = zeta;
    if held_feedback {
        let u0 = v + k * x0;
        state.fixed_rows_mut::<2>(8).copy_from(&u0);
    }

    let q = |s: &CVec10| -> (CVec3, CVec3) {
        (Vector3::new(s[0], s[1], s[2]), Vector3::new(s[3], s[4], s[5]))
    };
    let energy = |s: &CVec10| {
        let (q, qd) = q(s);
        let stretch = q[2] - q[0];
        0.5 * (qd.dotc(&(mass * qd)).re + params.k1 * stretch.norm_sqr())
    };
    let e0 = energy(&zeta);
    if !(e0 > 0.0 && e0.is_finite()) {
        return Err(Error::Analysis("the flexible pair carries no energy"));
    }
    let (mut held, mut pf, mut loss) = (0.0, 0.0, 0.0);
    let mut mean_motor_velocity = Complex::new(0.0, 0.0);
    for i in 0..=substeps {
        let weight = if i == 0 || i == substeps { 1.0 } else if i % 2 == 1 { 4.0 } else { 2.0 };
        let x = state.fixed_rows::<8>(0).into_owned();
        let (_, qd) = q(&state);
        let feedback = if held_feedback { k * x0 } else { k * x };
        let power = |u: &SMatrix<Complex<f64>, 2, 1>| qd.dotc(&(input * u)).re;
        held += weight * power(&v);
        pf += weight * power(&feedback);
        loss += weight * (0..3).map(|j| damping[j] * qd[j].norm_sqr()).sum::<f64>();
        mean_motor_velocity += qd[2] * weight;
        state = step * state;
    }
    let scale = h / 3.0 / e0;
    // Phasors e^{st}: a torque lagging the velocity by φ is the velocity's phase minus φ.
    let lag = (mean_motor_velocity / v[0]).arg().rem_euclid(core::f64::consts::TAU);
    Ok(SwingEnergy {
        held_torque: held * scale,
        preliminary_feedback: pf * scale,
        damping: loss * scale,
        lag,
    })
}

/// The eigenvector of `phi` for the eigenvalue `lambda`, by two steps of inverse iteration.
fn eigenvector(phi: &Mat10, lambda: Complex<f64>) -> Option<CVec10> {
    let shift = lambda + Complex::new(1e-10, 1e-10) * lambda.norm().max(1e-12);
    let m: SMatrix<Complex<f64>, 10, 10> = phi.map(|v| Complex::new(v, 0.0)) - SMatrix::identity() * shift;
    let lu = m.lu();
    let mut v = CVec10::from_element(Complex::new(1.0, 0.3));
    for _ in 0..2 {
        v = lu.solve(&v)?;
        let n = v.norm();
        if !(n > 0.0 && n.is_finite()) {
            return None;
        }
        v /= Complex::new(n, 0.0);
    }
    Some(v)
}
