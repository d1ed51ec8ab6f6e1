//! Physical and controller parameters, the paper's defaults, and validation.
//!
//! Every user-facing number passes through [`SimulationConfig::validate`] before it reaches the
//! physics; an invalid value becomes a [`ConfigError`] naming the parameter and the allowed range.

use core::fmt;
use serde::{Deserialize, Serialize};

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

    fn validate(&self) -> Result<(), ConfigError> {
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
    fn validate(&self) -> Result<(), ConfigError> {
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

/// Settings of the Jankowski–Van Brussel predictive controller, eqs. (2.3)–(2.4) and (4.2)–(4.3).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ControllerParameters {
    /// δ, the sampling period, s.
    pub sampling_period: f64,
    /// α1, α2: the stabilizing polynomial p(s) = (s + α_i)³ of each link's error, 1/s.
    pub alpha: [f64; 2],
    /// k, the number of backward-Euler steps of the prediction horizon τ = kε.
    pub horizon_steps: usize,
    /// m, so that the integration step is ε = δ/m.
    pub eps_ratio: f64,
}

impl Default for ControllerParameters {
    /// The paper's controller table: α1 = α2 = 2, k = 12, ε = δ/8, with δ = 0.01 s.
    fn default() -> Self {
        Self { sampling_period: 0.01, alpha: [2.0, 2.0], horizon_steps: 12, eps_ratio: 8.0 }
    }
}

/// The index of the stabilized DAE (4.1)–(4.3) in (X, U); the horizon must exceed it.
pub const DAE_INDEX: usize = 3;

impl ControllerParameters {
    /// ε = δ/m, the backward-Euler step of the prediction, s.
    pub fn integration_step(&self) -> f64 {
        self.sampling_period / self.eps_ratio
    }

    /// τ = kε, the prediction horizon, s.
    pub fn horizon(&self) -> f64 {
        self.horizon_steps as f64 * self.integration_step()
    }

    /// Checks δ > 0, α > 0, k > index, δ ≤ kε ≤ 2δ and finiteness.
    pub fn validate(&self) -> Result<(), ConfigError> {
        positive("sampling_period (δ)", self.sampling_period)?;
        if self.sampling_period > 10.0 {
            return Err(ConfigError::new("sampling_period (δ)", self.sampling_period, "must be at most 10 s"));
        }
        positive("alpha1 (α1)", self.alpha[0])?;
        positive("alpha2 (α2)", self.alpha[1])?;
        for (name, a) in [("alpha1 (α1)", self.alpha[0]), ("alpha2 (α2)", self.alpha[1])] {
            if a > 1000.0 {
                return Err(ConfigError::new(name, a, "must be at most 1000 1/s"));
            }
        }
        if self.horizon_steps <= DAE_INDEX || self.horizon_steps > 1000 {
            return Err(ConfigError::new(
                "k (horizon steps)",
                self.horizon_steps as f64,
                "must be an integer greater than the DAE index 3 (and at most 1000)",
            ));
        }
        positive("eps_ratio (m = δ/ε)", self.eps_ratio)?;
        let k = self.horizon_steps as f64;
        // δ ≤ kε ≤ 2δ with ε = δ/m  ⇔  m ≤ k ≤ 2m (with a little slack for rounding).
        let ratio = k / self.eps_ratio;
        if !(1.0 - 1e-12..=2.0 + 1e-12).contains(&ratio) {
            return Err(ConfigError::new(
                "eps_ratio (m = δ/ε)",
                self.eps_ratio,
                &format!(
                    "the horizon must satisfy δ ≤ kε ≤ 2δ, i.e. k/2 ≤ m ≤ k; with k = {} that is {} ≤ m ≤ {}",
                    self.horizon_steps,
                    k / 2.0,
                    k
                ),
            ));
        }
        Ok(())
    }
}

/// How the observed Dahl friction x̂f of eq. (4.4) is fed forward (T_i = v_i + x̂f_i).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum FrictionCompensation {
    /// The observer runs with the plant and its output is added continuously (the paper's choice).
    #[default]
    Continuous,
    /// The observer output is sampled at each sampling instant and held over the period.
    Held,
    /// No compensation: the controller's torque meets the friction unaided.
    Off,
}

/// Which preliminary feedback u = K_pr x + v is wrapped around the plant (section 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum PreliminaryFeedbackChoice {
    /// No preliminary feedback: the original Jankowski–Van Brussel controller.
    Off,
    /// The paper's printed gain K_pr.
    #[default]
    Paper,
    /// An LQ gain designed by this library (see [`crate::feedback`]).
    Lq,
}

/// Whether the preliminary feedback acts continuously (analog inner loop) or is sampled at δ.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum InnerLoop {
    /// u = K_pr x(t) + v at every instant (the natural implementation).
    #[default]
    Continuous,
    /// u = K_pr x(t_ρ) + v, held over each sampling period.
    Sampled,
}

/// Everything a closed-loop run needs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SimulationConfig {
    pub plant: PlantParameters,
    pub reference: SlewParameters,
    pub controller: ControllerParameters,
    pub preliminary_feedback: PreliminaryFeedbackChoice,
    pub inner_loop: InnerLoop,
    pub friction_compensation: FrictionCompensation,
    /// Largest step of the plant integrator, s; the actual step divides δ evenly.
    pub plant_step_max: f64,
    /// Spacing of the recorded time series, s (rounded to whole plant steps).
    pub output_interval: f64,
    /// A run counts as diverged once |e_i| exceeds this bound, rad.
    pub divergence_bound: f64,
    /// Operating point q2 at which the LQ preliminary feedback is designed, rad.
    pub lq_design_q2: f64,
}

impl Default for SimulationConfig {
    fn default() -> Self {
        Self {
            plant: PlantParameters::default(),
            reference: SlewParameters::default(),
            controller: ControllerParameters::default(),
            preliminary_feedback: PreliminaryFeedbackChoice::Paper,
            inner_loop: InnerLoop::Continuous,
            friction_compensation: FrictionCompensation::Continuous,
            plant_step_max: DEFAULT_PLANT_STEP_MAX,
            output_interval: 0.002,
            divergence_bound: DEFAULT_DIVERGENCE_BOUND,
            lq_design_q2: 0.0,
        }
    }
}

/// Default largest plant step, s: RK4 resolves the ≈ 30 rad/s flexible mode with ωh ≈ 0.03.
pub const DEFAULT_PLANT_STEP_MAX: f64 = 1e-3;

/// Default divergence bound on |e_i|: π rad, half a turn off the path.
pub const DEFAULT_DIVERGENCE_BOUND: f64 = core::f64::consts::PI;

impl SimulationConfig {
    /// Checks every parameter; the first invalid one is reported.
    pub fn validate(&self) -> Result<(), ConfigError> {
        self.plant.validate()?;
        self.reference.validate()?;
        self.controller.validate()?;
        positive("plant_step_max", self.plant_step_max)?;
        if self.plant_step_max > 0.01 {
            return Err(ConfigError::new("plant_step_max", self.plant_step_max, "must be at most 0.01 s"));
        }
        positive("output_interval", self.output_interval)?;
        positive("divergence_bound", self.divergence_bound)?;
        finite("lq_design_q2", self.lq_design_q2)?;
        Ok(())
    }
}

/// An invalid parameter: which one, its value, and what is allowed.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigError {
    /// The parameter's name, with the paper's symbol.
    pub parameter: &'static str,
    /// The rejected value.
    pub value: f64,
    /// The allowed range, in words.
    pub allowed: String,
}

impl ConfigError {
    pub(crate) fn new(parameter: &'static str, value: f64, allowed: &str) -> Self {
        Self { parameter, value, allowed: allowed.to_string() }
    }
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid {} = {}: {}", self.parameter, self.value, self.allowed)
    }
}

impl std::error::Error for ConfigError {}

fn finite(name: &'static str, v: f64) -> Result<(), ConfigError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(ConfigError::new(name, v, "must be a finite number"))
    }
}

fn positive(name: &'static str, v: f64) -> Result<(), ConfigError> {
    finite(name, v)?;
    if v > 0.0 {
        Ok(())
    } else {
        Err(ConfigError::new(name, v, "must be > 0"))
    }
}

fn non_negative(name: &'static str, v: f64) -> Result<(), ConfigError> {
    finite(name, v)?;
    if v >= 0.0 {
        Ok(())
    } else {
        Err(ConfigError::new(name, v, "must be ≥ 0"))
    }
}
