//! Everything a closed-loop run needs: the controller's settings (δ, α, k, m), which preliminary
//! feedback, friction compensation and inner loop, the plant and the slew, with validation.
//!
//! Every number passes through [`SimulationConfig::validate`] before it reaches the physics; an
//! invalid value becomes a [`ConfigError`] naming the parameter and the allowed range. The
//! user-settable numbers are checked against their [`crate::schema`] entries, so each range is
//! written once.

use serde::{Deserialize, Serialize};

use super::sensing::SensorModel;
use crate::error::{finite, positive, ConfigError};
use crate::model::params::{PlantParameters, SlewParameters};
use crate::schema;

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

/// The index of the stabilized DAE (4.1)–(4.3) in (X, U). The paper asks the horizon k to exceed
/// it; `analysis::structure` finds k equal to it already enough (U_k forgets the inconsistent start
/// from k = 3 on), and the schema lets k go below it, to be tried.
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

    /// Checks δ, α and k against their schema ranges, and δ ≤ kε ≤ 2δ.
    pub fn validate(&self) -> Result<(), ConfigError> {
        schema::DELTA.check(self.sampling_period)?;
        schema::ALPHA1.check(self.alpha[0])?;
        schema::ALPHA2.check(self.alpha[1])?;
        schema::K.check(self.horizon_steps as f64)?;
        schema::EPS_RATIO.check(self.eps_ratio)?;
        let k = self.horizon_steps as f64;
        // δ ≤ kε ≤ 2δ with ε = δ/m  ⇔  m ≤ k ≤ 2m (with a little slack for rounding).
        let ratio = k / self.eps_ratio;
        if !(1.0 - 1e-12..=2.0 + 1e-12).contains(&ratio) {
            return Err(ConfigError::new(
                schema::EPS_RATIO.name,
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
    /// The joint's twist alone on the motor torque, with the gains of [`TwistFeedback`].
    Twist,
}

/// The twist feedback T1 += k_p (q1 − θ) + k_d (q̇1 − θ̇) (`pf = twist`,
/// [`crate::control::feedback::twist_gain`]): a spring and a damper between motor and link 1,
/// applied by the motor.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TwistFeedback {
    /// k_p, N m/rad.
    pub stiffness: f64,
    /// k_d, N m s/rad.
    pub damping: f64,
}

impl Default for TwistFeedback {
    /// The schema's defaults.
    fn default() -> Self {
        let number = |p: &schema::Param| p.number().map_or(0.0, |n| n.default);
        Self { stiffness: number(&schema::TWIST_STIFFNESS), damping: number(&schema::TWIST_DAMPING) }
    }
}

/// The weights of the LQ design of the preliminary feedback (`pf = lq`,
/// [`crate::control::feedback::design_lq`]): Q = diag(`twist`, `twist_rate`) on the motor's gap
/// from the law's motor angle and its rate (the pair A4's coordinates), and R = `torque` ·
/// diag(1, [`LQ_T2_RATIO`]) on (T1, T2). The defaults are the paper's minimum-energy design.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LqWeights {
    /// Q's weight on the gap z = θ − θ*, 1/(N m rad)² scaled: larger pulls the pair further.
    pub twist: f64,
    /// Q's weight on its rate.
    pub twist_rate: f64,
    /// R's weight on T1 (T2's is [`LQ_T2_RATIO`] times it): larger asks for less torque.
    pub torque: f64,
}

/// T2's torque weight over T1's in the LQ design: 6.7 reproduces both printed rows of the paper's
/// K_pr at q2 = 0, α = 2 to within 2.5 % (ERRATA.md says "about 6").
pub const LQ_T2_RATIO: f64 = 6.7;

impl Default for LqWeights {
    /// The schema's defaults: Q = 1e-6 I2 (minimum energy), R = diag(1, 6.7).
    fn default() -> Self {
        let number = |p: &schema::Param| p.number().map_or(1.0, |n| n.default);
        Self {
            twist: number(&schema::LQ_TWIST_WEIGHT),
            twist_rate: number(&schema::LQ_RATE_WEIGHT),
            torque: number(&schema::LQ_TORQUE_WEIGHT),
        }
    }
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

/// The arm the controller's model assumes (section 4 designs the predictor, the friction observer
/// and the preliminary feedback on one model of the arm): the real arm, or the paper's table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum ControllerModel {
    /// The controller knows the arm exactly.
    #[default]
    Arm,
    /// The controller keeps the paper's arm whatever the real one is: a model error.
    Paper,
}

/// The words the enums have in URLs, on the command line and in JSON (the [`crate::schema`]
/// choices), both ways.
macro_rules! named {
    ($t:ty { $($variant:ident => $name:literal),* $(,)? }) => {
        impl $t {
            /// The word for this choice.
            pub fn name(self) -> &'static str {
                match self { $(Self::$variant => $name),* }
            }

            /// The choice named `name`, if any.
            pub fn from_name(name: &str) -> Option<Self> {
                match name { $($name => Some(Self::$variant),)* _ => None }
            }
        }
    };
}

named!(FrictionCompensation { Continuous => "continuous", Held => "held", Off => "off" });
named!(PreliminaryFeedbackChoice { Off => "off", Paper => "paper", Lq => "lq", Twist => "twist" });
named!(InnerLoop { Continuous => "continuous", Sampled => "sampled" });
named!(ControllerModel { Arm => "arm", Paper => "paper" });

/// Everything a closed-loop run needs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SimulationConfig {
    pub plant: PlantParameters,
    pub reference: SlewParameters,
    pub controller: ControllerParameters,
    pub preliminary_feedback: PreliminaryFeedbackChoice,
    /// The twist feedback's gains, used when `preliminary_feedback` is `Twist`.
    pub twist: TwistFeedback,
    /// The LQ design's weights, used when `preliminary_feedback` is `Lq`.
    pub lq: LqWeights,
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
    /// The arm the controller assumes (its predictor, friction observer and LQ design): this
    /// arm, or the paper's while the real one differs.
    pub model: ControllerModel,
    /// What the controller reads and the motors can apply (the paper's perfect robot by default).
    pub sensors: SensorModel,
}

impl Default for SimulationConfig {
    fn default() -> Self {
        Self {
            plant: PlantParameters::default(),
            reference: SlewParameters::default(),
            controller: ControllerParameters::default(),
            preliminary_feedback: PreliminaryFeedbackChoice::Paper,
            twist: TwistFeedback::default(),
            lq: LqWeights::default(),
            inner_loop: InnerLoop::Continuous,
            friction_compensation: FrictionCompensation::Continuous,
            plant_step_max: DEFAULT_PLANT_STEP_MAX,
            output_interval: 0.002,
            divergence_bound: DEFAULT_DIVERGENCE_BOUND,
            lq_design_q2: 0.0,
            model: ControllerModel::Arm,
            sensors: SensorModel::default(),
        }
    }
}

/// Default largest plant step, s: RK4 resolves the ≈ 30 rad/s flexible mode with ωh ≈ 0.03.
pub const DEFAULT_PLANT_STEP_MAX: f64 = 1e-3;

/// Default divergence bound on |e_i|: π rad, half a turn off the path.
pub const DEFAULT_DIVERGENCE_BOUND: f64 = core::f64::consts::PI;

impl SimulationConfig {
    /// The arm the controller assumes: the plant itself, or the paper's (`model = paper`).
    pub fn model_plant(&self) -> PlantParameters {
        match self.model {
            ControllerModel::Arm => self.plant,
            ControllerModel::Paper => PlantParameters::default(),
        }
    }

    /// True if the controller assumes an arm other than the real one.
    pub fn has_model_error(&self) -> bool {
        self.model_plant() != self.plant
    }

    /// Checks every parameter; the first invalid one is reported.
    pub fn validate(&self) -> Result<(), ConfigError> {
        self.plant.validate()?;
        self.reference.validate()?;
        self.controller.validate()?;
        positive("plant_step_max", self.plant_step_max)?;
        if self.plant_step_max > 0.01 {
            return Err(ConfigError::new("plant_step_max", self.plant_step_max, "must be at most 0.01 s"));
        }
        schema::OUTPUT_INTERVAL.check(self.output_interval)?;
        positive("divergence_bound", self.divergence_bound)?;
        finite("lq_design_q2", self.lq_design_q2)?;
        schema::TWIST_STIFFNESS.check(self.twist.stiffness)?;
        schema::TWIST_DAMPING.check(self.twist.damping)?;
        schema::LQ_TWIST_WEIGHT.check(self.lq.twist)?;
        schema::LQ_RATE_WEIGHT.check(self.lq.twist_rate)?;
        schema::LQ_TORQUE_WEIGHT.check(self.lq.torque)?;
        self.sensors.validate()?;
        Ok(())
    }
}
