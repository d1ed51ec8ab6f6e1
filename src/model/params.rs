//! The arm's parameters (the paper's table) and the prescribed slew (section 5), with validation.

use serde::{Deserialize, Serialize};

use crate::error::{finite, non_negative, positive, ConfigError};

/// Parameters of the two-link arm with one flexible joint, eq. (4.1) and the paper's table.
///
/// Units: inertias kg m², viscous damping N m s/rad, Coulomb levels N m, Dahl lengths rad,
/// stiffness N m/rad.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PlantParameters {
    /// A1, kg m².
    pub a1: f64,
    /// A2, kg m².
    pub a2: f64,
    /// A3, kg m² (the coupling term; the mass matrix uses A2 + A3 cos q2 off the diagonal, see ERRATA).
    pub a3: f64,
    /// Ir1, motor inertia of joint 1, kg m².
    pub ir1: f64,
    /// Bv1, viscous damping of the motor, N m s/rad.
    pub bv1: f64,
    /// Bv2, viscous damping of joint 2, N m s/rad.
    pub bv2: f64,
    /// Fc1, Coulomb level of the motor friction, N m.
    pub fc1: f64,
    /// Fc2, Coulomb level of joint-2 friction, N m.
    pub fc2: f64,
    /// ε1, Dahl presliding length of the motor friction, rad.
    pub eps1: f64,
    /// ε2, Dahl presliding length of joint-2 friction, rad.
    pub eps2: f64,
    /// K1, stiffness of the flexible joint between motor and link 1, N m/rad.
    pub k1: f64,
}

impl Default for PlantParameters {
    /// The paper's table of model parameters.
    fn default() -> Self {
        Self {
            a1: 4.984,
            a2: 0.247,
            a3: 0.328,
            ir1: 1.939,
            bv1: 1.40,
            bv2: 0.20,
            fc1: 4.82,
            fc2: 1.15,
            eps1: 1e-4,
            eps2: 1e-4,
            k1: 1152.6,
        }
    }
}

impl PlantParameters {
    /// The same arm without friction or damping: the energy-conserving plant used in tests.
    pub fn undamped_frictionless() -> Self {
        Self { bv1: 0.0, bv2: 0.0, fc1: 0.0, fc2: 0.0, ..Self::default() }
    }

    /// The values in the order of [`crate::schema::ARM_PARAMS`].
    pub fn values(&self) -> [f64; 11] {
        [self.a1, self.a2, self.a3, self.ir1, self.bv1, self.bv2, self.fc1, self.fc2, self.eps1, self.eps2, self.k1]
    }

    /// The value of an arm parameter by its schema key (`k1`).
    pub fn get(&self, key: &str) -> Option<f64> {
        let i = crate::schema::ARM_PARAMS.iter().position(|p| p.key == key)?;
        Some(self.values()[i])
    }

    /// Sets an arm parameter by its schema key; false if `key` is not one.
    pub fn set(&mut self, key: &str, v: f64) -> bool {
        let slot = match key {
            "a1" => &mut self.a1,
            "a2" => &mut self.a2,
            "a3" => &mut self.a3,
            "ir1" => &mut self.ir1,
            "bv1" => &mut self.bv1,
            "bv2" => &mut self.bv2,
            "fc1" => &mut self.fc1,
            "fc2" => &mut self.fc2,
            "eps1" => &mut self.eps1,
            "eps2" => &mut self.eps2,
            "k1" => &mut self.k1,
            _ => return false,
        };
        *slot = v;
        true
    }

    /// Each value within its schema limits, then the conditions across them: the mass matrix
    /// M2 = [[A1 + 2 A3 c, A2 + A3 c], [A2 + A3 c, A2]] (c = cos q2) has determinant
    /// A1 A2 − A2² − A3² c², which must stay positive for every q2; and the arm's fastest motion
    /// at most [`Self::FASTEST_RATE_MAX`].
    pub fn validate(&self) -> Result<(), ConfigError> {
        for (p, v) in crate::schema::ARM_PARAMS.iter().zip(self.values()) {
            p.check(v)?;
        }
        self.check_mass_matrix(&crate::schema::A3)
    }

    /// The check across A1, A2 and A3 (the mass matrix positive definite for every q2), its
    /// failure reported as a mistake in `p`, one of the three: the one the user changed, so that
    /// a bad A1 is not blamed on A3. The reason names all three.
    pub fn check_mass_matrix(&self, p: &crate::schema::Param) -> Result<(), ConfigError> {
        let room = self.a1 * self.a2 - self.a2 * self.a2;
        if self.a3 * self.a3 >= room {
            let g = |v: f64| crate::plot::format::significant(v, 3);
            let reason = format!(
                "must keep the mass matrix positive definite for every q2, which needs A3² < A1·A2 − A2²; with A1 = {}, \
                 A2 = {} and A3 = {} kg m² it is {} ≥ {}",
                crate::schema::format_number(self.a1),
                crate::schema::format_number(self.a2),
                crate::schema::format_number(self.a3),
                g(self.a3 * self.a3),
                g(room)
            );
            let value = self.get(p.key).unwrap_or(self.a3);
            return Err(ConfigError::new(p.name, value, &reason));
        }
        self.check_fastest_rate()
    }

    /// The largest rate of the arm's mechanics, 1/s: the joint's resonance
    /// √(K1 (1/I_r1 + 1/J_eff)) at its stiffest posture, the motor's damping B_v1/I_r1 and
    /// joint 2's B_v2 (M⁻¹)₂₂, whichever is largest (the simulation's step follows it).
    pub fn fastest_rate(&self) -> f64 {
        self.rates().into_iter().fold(0.0, f64::max)
    }

    /// The three rates of [`Self::fastest_rate`], 1/s: [resonance, motor damping, joint-2 damping].
    fn rates(&self) -> [f64; 3] {
        let mut rates = [0.0, self.bv1 / self.ir1, 0.0];
        for i in 0..=20 {
            let c = -1.0 + 0.1 * i as f64;
            let det = self.a1 * self.a2 - self.a2 * self.a2 - self.a3 * self.a3 * c * c;
            // The links as one body seen from the spring: J_eff = det / A2 (link 2 free to follow).
            let j_eff = det / self.a2;
            let m22_inv = (self.a1 + 2.0 * self.a3 * c) / det;
            rates[0] = f64::max(rates[0], (self.k1 * (1.0 / self.ir1 + 1.0 / j_eff)).sqrt());
            rates[2] = f64::max(rates[2], self.bv2 * m22_inv);
        }
        rates
    }

    /// The fastest motion an arm may have, 1/s: the
    /// simulation's step follows it ([`Self::fastest_rate`]), so beyond this an arm's run of a
    /// few seconds takes millions of steps (the torque price's 4 s took 10 s at 7e5 1/s, a motor
    /// damped 1400 N m s/rad over 0.0019 kg m²). Every arm with one setting at an end of its range
    /// is below it (the fastest, the lightest motor on the stiffest joint: 2.4e4 1/s).
    pub const FASTEST_RATE_MAX: f64 = 3e4;

    /// The check across parameters after the mass matrix's: the arm's fastest motion at most
    /// [`Self::FASTEST_RATE_MAX`], refused naming the setting whose rate it is.
    fn check_fastest_rate(&self) -> Result<(), ConfigError> {
        let rates = self.rates();
        let (i, rate) = rates.iter().enumerate().fold((0, 0.0), |(j, r), (i, &x)| if x > r { (i, x) } else { (j, r) });
        if rate <= Self::FASTEST_RATE_MAX {
            return Ok(());
        }
        let (param, what) = [
            (&crate::schema::K1, "the joint's resonance √(K1 (1/I_r1 + 1/J_eff))"),
            (&crate::schema::BV1, "the motor's damping B_v1/I_r1"),
            (&crate::schema::BV2, "joint 2's damping B_v2 (M⁻¹)₂₂"),
        ][i];
        let reason = format!(
            "too fast for this arm: {what} is {} 1/s, at most {} 1/s (the simulation's step follows the arm's fastest \
             motion; a faster arm takes millions of steps per simulated second)",
            crate::plot::format::significant(rate, 3),
            crate::plot::format::significant(Self::FASTEST_RATE_MAX, 3)
        );
        Err(ConfigError::new(param.name, self.get(param.key).unwrap_or(f64::NAN), &reason))
    }
}

/// The prescribed slew of section 5: both links move from `start` to `end` in `slew_time`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SlewParameters {
    /// q_d0 for links 1 and 2, rad.
    pub start: [f64; 2],
    /// q_df for links 1 and 2, rad.
    pub end: [f64; 2],
    /// t_f, s.
    pub slew_time: f64,
    /// If set, the slew repeats there and back: after each slew the arm holds for this many
    /// seconds, then returns. `None` (the paper) slews once and holds forever.
    pub repeat_hold: Option<f64>,
}

impl Default for SlewParameters {
    /// The paper's reference: q1 0 → π/2, q2 3π/2 → 0, t_f = 1 s.
    fn default() -> Self {
        use core::f64::consts::PI;
        Self { start: [0.0, 1.5 * PI], end: [0.5 * PI, 0.0], slew_time: 1.0, repeat_hold: None }
    }
}

impl SlewParameters {
    pub fn validate(&self) -> Result<(), ConfigError> {
        for (i, v) in self.start.iter().enumerate() {
            finite(["reference.start[0] (q_d1,0)", "reference.start[1] (q_d2,0)"][i], *v)?;
        }
        for (i, v) in self.end.iter().enumerate() {
            finite(["reference.end[0] (q_d1,f)", "reference.end[1] (q_d2,f)"][i], *v)?;
        }
        positive("reference.slew_time (t_f)", self.slew_time)?;
        if let Some(h) = self.repeat_hold {
            non_negative("reference.repeat_hold", h)?;
        }
        Ok(())
    }
}
