//! The noise floor of the digital loop: how far the encoders' quantization and the measurement
//! noise keep the arm from rest, and how much torque they cost, predicted from the linear loop
//! ([`super::digital`]) by the discrete Lyapunov equation P = F P Fᵀ + G R Gᵀ.
//!
//! What it predicts: the stationary covariance P of ζ at the sampling instants when each measured
//! angle carries a white error η_n of covariance R = (Δ²/12 + σ²) I3 — hence the rms link errors
//! e = (q1, q2) at the instants, the rms held torque u_n = H ζ_n + J η_n, and the rms error of the
//! velocity estimate ν_n − q̇_n. Every rms scales as √(Δ²/12 + σ²): one solve with R = I serves
//! every encoder and noise level.
//!
//! The assumption: the quantizer's error is white, uniform over one count, independent of the
//! state. That holds where the arm moves over many counts between samples (a slew, or noise σ of
//! a count or more). It does not describe the quantizer at rest — there the error is a constant
//! offset of up to half a count, or a limit cycle of a count or two, which only the simulation
//! shows — nor a torque held at its limit (the loop is then no longer linear).

use nalgebra::{Complex, SMatrix};
use serde::{Deserialize, Serialize};

use super::digital::{digital_eigenvalues, digital_spectral_radius, MatDigital, DIGITAL_STATES};
use super::sampled::{LinearSettings, LoopModel};
use crate::control::config::SimulationConfig;
use crate::control::sensing::{SensorModel, VelocityEstimator};
use crate::error::Error;

/// The digital loop's noise floor at one δ ([`noise_floor`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct NoiseFloor {
    /// ρ of the noise-free digital loop.
    pub spectral_radius: f64,
    /// rms of the link errors e1, e2 at the sampling instants, rad.
    pub rms_error: [f64; 2],
    /// rms of the held torques T1, T2 (the controller's u_n, deviation from rest), N m.
    pub rms_torque: [f64; 2],
    /// rms of the velocity estimate's error ν − q̇ on q̇1, q̇2, θ̇, rad/s (0 for exact velocities).
    pub rms_velocity_estimate: [f64; 3],
}

/// The noise-free digital loop at sampling period `delta` with velocities estimated by `velocity`: its
/// spectral radius ρ and eigenvalues, largest |λ| first.
pub fn digital_spectrum(
    model: &LoopModel,
    delta: f64,
    velocity: VelocityEstimator,
) -> Result<(f64, Vec<Complex<f64>>), Error> {
    let ev = digital_eigenvalues(&model.digital_loop(delta, velocity)?.f);
    Ok((ev.first().map(|c| c.norm()).unwrap_or(0.0), ev))
}

/// Solves P = F P Fᵀ + Q by Smith's doubling: P ← P + A P Aᵀ, A ← A² from P = Q, A = F, which
/// after k steps has summed the first 2ᵏ terms of Σ Fⁱ Q Fⁱᵀ. Stops when the last step changed
/// no diagonal entry by more than 1e-15 of itself (the step is positive semidefinite, so the
/// off-diagonal entries' change is bounded by the diagonal's). Err if ρ(F) ≥ 1: an unstable
/// loop has no stationary covariance.
pub fn discrete_lyapunov(f: &MatDigital, q: &MatDigital) -> Result<MatDigital, Error> {
    let rho = digital_spectral_radius(f);
    if rho.is_nan() || rho >= 1.0 {
        return Err(Error::Analysis("the digital loop is unstable (ρ ≥ 1): it has no noise floor"));
    }
    let mut p = (q + q.transpose()) * 0.5;
    let mut a = *f;
    // 2⁶⁰ terms: enough for any ρ that is not 1 to rounding.
    for _ in 0..60 {
        let step = a * p * a.transpose();
        let step = (step + step.transpose()) * 0.5;
        p += step;
        let settled = (0..DIGITAL_STATES).all(|i| step[(i, i)].abs() <= 1e-15 * p[(i, i)].abs());
        if !p.iter().all(|v| v.is_finite()) {
            break;
        }
        if settled {
            return Ok(p);
        }
        a = a * a;
    }
    Err(Error::Analysis("the discrete Lyapunov equation did not converge"))
}

/// The noise floor of `model`'s digital loop at sampling period `delta` with `sensors`: the
/// stationary rms errors, torques and velocity-estimate errors their white angle error causes
/// (see the module's note on when that describes a run). Err if the loop is unstable.
pub fn noise_floor(model: &LoopModel, delta: f64, sensors: &SensorModel) -> Result<NoiseFloor, Error> {
    sensors.validate()?;
    Ok(unit_noise_floor(model, delta, sensors.estimator())?.scaled(sensors.angle_variance().sqrt()))
}

/// The noise floor of `config` at its own δ, if its sensors make the controller digital (Err: why
/// there is none, e.g. an unstable loop).
pub fn noise_floor_of(config: &SimulationConfig) -> Option<Result<NoiseFloor, Error>> {
    config.sensors.is_digital().then(|| {
        LoopModel::new(&LinearSettings::of(config, None))
            .and_then(|m| noise_floor(&m, config.controller.sampling_period, &config.sensors))
    })
}

impl NoiseFloor {
    /// The floor for an angle error of standard deviation `sd` from the floor for 1 (every rms
    /// scales with it; ρ does not).
    pub fn scaled(self, sd: f64) -> Self {
        let s = |v: [f64; 2]| v.map(|x| x * sd);
        Self {
            spectral_radius: self.spectral_radius,
            rms_error: s(self.rms_error),
            rms_torque: s(self.rms_torque),
            rms_velocity_estimate: self.rms_velocity_estimate.map(|x| x * sd),
        }
    }
}

/// The noise floor for an angle error of standard deviation 1 (rad): what every encoder and noise
/// level scales ([`NoiseFloor::scaled`]), so that one solve serves them all.
pub fn unit_noise_floor(model: &LoopModel, delta: f64, velocity: VelocityEstimator) -> Result<NoiseFloor, Error> {
    let dl = model.digital_loop(delta, velocity)?;
    let spectral_radius = digital_spectral_radius(&dl.f);
    let p = discrete_lyapunov(&dl.f, &(dl.g * dl.g.transpose()))?;
    let sd = 1.0;
    let torque = dl.h * p * dl.h.transpose() + dl.j * dl.j.transpose();
    // ν − q̇ = (S_ν − E_q̇) ζ + T_ν η: zero for exact velocities.
    let mut c: SMatrix<f64, 3, DIGITAL_STATES> = dl.s.fixed_view::<3, DIGITAL_STATES>(3, 0).into_owned();
    for i in 0..3 {
        c[(i, 3 + i)] -= 1.0;
    }
    let d: SMatrix<f64, 3, 3> = dl.t.fixed_view::<3, 3>(3, 0).into_owned();
    let velocity = c * p * c.transpose() + d * d.transpose();
    let rms = |v: f64| sd * v.max(0.0).sqrt();
    Ok(NoiseFloor {
        spectral_radius,
        rms_error: [rms(p[(0, 0)]), rms(p[(1, 1)])],
        rms_torque: [rms(torque[(0, 0)]), rms(torque[(1, 1)])],
        rms_velocity_estimate: [rms(velocity[(0, 0)]), rms(velocity[(1, 1)]), rms(velocity[(2, 2)])],
    })
}
