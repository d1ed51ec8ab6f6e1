//! Dahl friction (the last two rows of eq. (4.1)) and its observer, eq. (4.4).
//!
//! ε_i ẋf_i = −|v_i| xf_i + Fc_i v_i, with v_1 = θ̇ (motor) and v_2 = q̇2 (joint 2).
//! The time constant ε/|v| is about 1e-4 s at slew speeds, far below any sensible explicit step,
//! so the friction states are advanced with the exact solution for a velocity held over the step
//! (an exponential update, unconditionally stable) and split from the mechanical states
//! (see [`crate::model::plant`]).

use nalgebra::Vector2;

use crate::model::params::PlantParameters;

/// Exact solution of ε ẋ = −|v| x + Fc v over `dt` for a constant velocity `v`.
///
/// The friction torque relaxes towards the Coulomb level Fc·sign(v) at rate |v|/ε.
#[inline]
pub fn dahl_update(xf: f64, velocity: f64, dt: f64, coulomb: f64, length: f64) -> f64 {
    if velocity == 0.0 {
        return xf;
    }
    let target = coulomb * velocity.signum();
    target + (xf - target) * (-velocity.abs() * dt / length).exp()
}

/// Advances both friction states (xf1 on θ̇, xf2 on q̇2) over `dt` at the given velocities.
#[inline]
pub fn advance_friction(
    p: &PlantParameters,
    xf: &mut Vector2<f64>,
    motor_velocity: f64,
    joint2_velocity: f64,
    dt: f64,
) {
    xf[0] = dahl_update(xf[0], motor_velocity, dt, p.fc1, p.eps1);
    xf[1] = dahl_update(xf[1], joint2_velocity, dt, p.fc2, p.eps2);
}

/// The friction observer of eq. (4.4): a copy of the Dahl model driven by the measured
/// velocities (θ̇ for i = 1, q̇2 for i = 2). Its output x̂f is fed forward, T_i = v_i + x̂f_i.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrictionObserver {
    /// x̂f = (x̂f1, x̂f2), N m.
    pub estimate: Vector2<f64>,
}

impl FrictionObserver {
    /// Advances the estimate over `dt` with the measured velocities held.
    #[inline]
    pub fn advance(&mut self, p: &PlantParameters, motor_velocity: f64, joint2_velocity: f64, dt: f64) {
        advance_friction(p, &mut self.estimate, motor_velocity, joint2_velocity, dt);
    }
}
