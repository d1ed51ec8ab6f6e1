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

    pub fn validate(&self) -> Result<(), ConfigError> {
        positive("plant.a1 (A1)", self.a1)?;
        positive("plant.a2 (A2)", self.a2)?;
        finite("plant.a3 (A3)", self.a3)?;
        // M2 = [[A1 + 2 A3 c, A2 + A3 c], [A2 + A3 c, A2]] has determinant A1 A2 − A2² − A3² c²,
        // which must stay positive for every q2.
        let det_min = self.a1 * self.a2 - self.a2 * self.a2 - self.a3 * self.a3;
        if det_min <= 0.0 {
            return Err(ConfigError::new(
                "plant.a3 (A3)",
                self.a3,
                "the mass matrix must be positive definite for every q2: A1·A2 − A2² − A3² > 0",
            ));
        }
        positive("plant.ir1 (Ir1)", self.ir1)?;
        non_negative("plant.bv1 (Bv1)", self.bv1)?;
        non_negative("plant.bv2 (Bv2)", self.bv2)?;
        non_negative("plant.fc1 (Fc1)", self.fc1)?;
        non_negative("plant.fc2 (Fc2)", self.fc2)?;
        positive("plant.eps1 (ε1)", self.eps1)?;
        positive("plant.eps2 (ε2)", self.eps2)?;
        positive("plant.k1 (K1)", self.k1)?;
        Ok(())
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
