//! What a short horizon k does: the predictor's gains on the motor's inconsistent start, and ρ.

use serde::{Deserialize, Serialize};

use crate::analysis::sampled::{loop_eigenvalues, sampled_loop_matrix, LoopModel};
use crate::control::linear::{backward_euler_map, matrix_power, pencil, Mat10};
use crate::error::Error;

/// What the predictor with a short horizon k does at the settings' δ.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct HorizonProbe {
    /// k, the backward-Euler steps.
    pub k: usize,
    /// m (ε = δ/m): kε/δ as in the settings, kept within δ ≤ kε ≤ 2δ and ε ≤ δ.
    pub eps_ratio: f64,
    /// The largest |gain| from θ(tₙ) to the predictor's torque U_k (either row; with a preliminary
    /// feedback the V_k on top of K x), N m/rad.
    pub theta_gain: f64,
    /// The same from θ̇(tₙ), N m s/rad.
    pub theta_rate_gain: f64,
    /// p in theta_gain ∝ ε^(−p), measured between ε and ε/10: how it grows as δ → 0 (None where
    /// V_k has forgotten θ and θ̇).
    pub theta_gain_order: Option<f64>,
    /// The largest |gain| from θ(tₙ) or θ̇(tₙ) to the predicted state X_k (any entry).
    pub state_gain: f64,
    /// The predictor's largest gain on the other states (the links and w), for scale, N m/rad or
    /// N m s/rad.
    pub other_gain: f64,
    /// Whether V_k has forgotten θ and θ̇: their gains below 1e-9 of the largest entry of one
    /// step's map or of the sweep (rounding of what cancels).
    pub torque_forgets: bool,
    /// Whether X_k has (the same test on the state's gains).
    pub state_forgets: bool,
    /// ρ of the sampled loop at δ with this k and m; None if the loop could not be computed.
    pub rho: Option<f64>,
}

/// The predictor with horizon `k` at the settings' δ, m = k/`ratio` kept in [max(1, k/2), k].
pub(super) fn probe(loop_model: &LoopModel, k: usize, ratio: f64) -> Result<HorizonProbe, Error> {
    let settings = loop_model.settings();
    let mut controller = settings.controller;
    controller.horizon_steps = k;
    let kf = k as f64;
    controller.eps_ratio = (kf / ratio).clamp((kf / 2.0).max(1.0), kf);
    let model = loop_model.predictor();
    let (e, f) = pencil(model, loop_model.gain());
    let sweep_at = |eps: f64| -> Result<(Mat10, f64), Error> {
        let step = backward_euler_map(&e, &f, eps)?;
        Ok((matrix_power(&step, k), step.amax()))
    };
    let eps = controller.integration_step();
    let (sweep, step_size) = sweep_at(eps)?;
    let motor_gains = |sweep: &Mat10| {
        let (mut theta, mut rate, mut other, mut state, mut state_other) = (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for row in 0..10 {
            for col in 0..8 {
                let g = sweep[(row, col)].abs();
                match (row >= 8, col) {
                    (true, 2) => theta = theta.max(g),
                    (true, 5) => rate = rate.max(g),
                    (true, _) => other = other.max(g),
                    (false, 2 | 5) => state = state.max(g),
                    (false, _) => state_other = state_other.max(g),
                }
            }
        }
        (theta, rate, other, state, state_other)
    };
    let (theta_gain, theta_rate_gain, other_gain, state_gain, state_other) = motor_gains(&sweep);
    // Zero to rounding: below 1e-9 of the largest entry of one step's map or of the sweep — what
    // cancels when the sweep forgets is of the step's size (the 1/ε² of the inconsistent start),
    // and its rounding is ≈ 1e-16 of it per step.
    let zero = 1e-9 * step_size.max(sweep.amax()).max(state_other);
    let torque_forgets = theta_gain.max(theta_rate_gain) <= zero;
    let theta_gain_order = if torque_forgets || theta_gain == 0.0 {
        None
    } else {
        let (finer, _) = sweep_at(eps / 10.0)?;
        Some((motor_gains(&finer).0 / theta_gain).log10())
    };
    let rho = sampled_loop_matrix(loop_model.arm(), model, loop_model.gain(), &controller, settings.inner_loop)
        .ok()
        .and_then(|m| loop_eigenvalues(&m).first().map(|l| l.norm()))
        .filter(|r| r.is_finite());
    Ok(HorizonProbe {
        k,
        eps_ratio: controller.eps_ratio,
        theta_gain,
        theta_rate_gain,
        theta_gain_order,
        state_gain,
        other_gain,
        torque_forgets,
        state_forgets: state_gain <= zero,
        rho,
    })
}
