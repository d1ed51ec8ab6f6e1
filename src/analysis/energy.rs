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

use nalgebra::{Complex, SVector, Vector3};
use serde::{Deserialize, Serialize};

use super::swing::SwingMode;
use crate::control::config::InnerLoop;
use crate::control::feedback::FeedbackGain;
use crate::control::linear::{expm, LinearModel, Mat10};
use crate::error::Error;
use crate::model::plant::Plant;
use crate::model::PlantParameters;

/// Substeps of the period for the energy integrals (Simpson's rule): at least this many, and at
/// least [`SUBSTEPS_PER_RADIAN`] per radian the arm's fastest motion turns.
const MIN_SUBSTEPS: usize = 48;
const SUBSTEPS_PER_RADIAN: f64 = 16.0;
/// At most this many (an even number, as Simpson's rule needs).
const MAX_SUBSTEPS: usize = 4096;

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

/// The arm a swing's energy is taken on: linearized at rest, with its preliminary feedback.
#[derive(Clone, Copy, Debug)]
pub struct EnergyModel<'a> {
    /// The arm linearized (what the sampled plant is).
    pub arm: &'a LinearModel,
    /// The preliminary feedback's gain K and whether it acts continuously or held over δ.
    pub gain: &'a FeedbackGain,
    pub inner_loop: InnerLoop,
    /// The arm's parameters and the rest angle q2 (its mass matrix there).
    pub plant: PlantParameters,
    pub rest_q2: f64,
}

/// The swing's energy over one period at sampling period `delta` for the pair's `mode` (its
/// eigenvector of the one-period map at the same δ); `LoopModel::swing_energy` gives the model.
pub fn swing_energy(model: &EnergyModel<'_>, delta: f64, mode: &SwingMode) -> Result<SwingEnergy, Error> {
    let [re, im] = mode.shape_vectors();
    let arm = model.arm;
    let gain = model.gain;
    let held_feedback = model.inner_loop == InnerLoop::Sampled;
    let params = model.plant;
    let mass = Plant::new(params).mass_matrix(model.rest_q2);
    let input = Plant::input_matrix();
    let damping = [0.0, params.bv2, params.bv1];

    // The motion over the period, real and imaginary parts apart (the map is real): (x, u_held)
    // with ẋ = A' x + B u_held, u_held constant, where A' = A + BK for a continuous preliminary
    // feedback, and u_held = v + K x(t_n) when it is held.
    let mut aug = Mat10::zeros();
    let a = if held_feedback { arm.a } else { arm.with_feedback(gain) };
    // √‖A‖ bounds the fastest frequency of a mass–spring system (‖A‖ ≥ K/m).
    let fastest = a.amax().sqrt();
    // Capped in floating point before the cast: an arm's rate times δ can exceed any integer.
    let half = (SUBSTEPS_PER_RADIAN * fastest * delta / 2.0).ceil().min((MAX_SUBSTEPS / 2) as f64);
    let substeps = MIN_SUBSTEPS.max(2 * half as usize);
    let h = delta / substeps as f64;
    aug.fixed_view_mut::<8, 8>(0, 0).copy_from(&(a * h));
    aug.fixed_view_mut::<8, 2>(0, 8).copy_from(&(arm.b * h));
    let step = expm(&aug);
    let parts = [re, im];
    let x0 = parts.map(|p| p.fixed_rows::<8>(0).into_owned());
    let v = parts.map(|p| p.fixed_rows::<2>(8).into_owned());
    let mut state = parts;
    if held_feedback {
        for (s, (v, x)) in state.iter_mut().zip(v.iter().zip(&x0)) {
            s.fixed_rows_mut::<2>(8).copy_from(&(v + gain * x));
        }
    }

    // Real quadratic forms of the complex vector: Re(aᴴ M b) = aᵣᵀ M bᵣ + aᵢᵀ M bᵢ.
    let velocity = |s: &SVector<f64, 10>| Vector3::new(s[3], s[4], s[5]);
    let e0 = parts
        .iter()
        .map(|p| {
            let qd = velocity(p);
            0.5 * (qd.dot(&(mass * qd)) + params.k1 * (p[2] - p[0]).powi(2))
        })
        .sum::<f64>();
    if !(e0 > 0.0 && e0.is_finite()) {
        return Err(Error::Analysis("the flexible pair carries no energy"));
    }
    let (mut held, mut pf, mut loss) = (0.0, 0.0, 0.0);
    let mut mean_motor_velocity = [0.0; 2];
    for i in 0..=substeps {
        let weight = if i == 0 || i == substeps {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        for part in 0..2 {
            let qd = velocity(&state[part]);
            let x = state[part].fixed_rows::<8>(0).into_owned();
            let feedback = if held_feedback { gain * x0[part] } else { gain * x };
            held += weight * qd.dot(&(input * v[part]));
            pf += weight * qd.dot(&(input * feedback));
            loss += weight * (0..3).map(|j| damping[j] * qd[j] * qd[j]).sum::<f64>();
            mean_motor_velocity[part] += weight * qd[2];
            state[part] = step * state[part];
        }
    }
    let scale = h / 3.0 / e0;
    // Phasors e^{st}: a torque lagging the velocity by φ is the velocity's phase minus φ.
    let [vr, vi] = [mean_motor_velocity[0], mean_motor_velocity[1]];
    let lag = (Complex::new(vr, vi) / Complex::new(v[0][0], v[1][0])).arg().rem_euclid(core::f64::consts::TAU);
    Ok(SwingEnergy { held_torque: held * scale, preliminary_feedback: pf * scale, damping: loss * scale, lag })
}
