//! One run's settings: δ, α, the preliminary feedback, the friction compensation, the inner loop,
//! the slew, the predictor's horizon, the analysis's rest point and the arm — keyed by the
//! schema's run parameters, and the configuration they make. Run B of a comparison has its own
//! δ, α and feedback over A's.

use crate::control::config::{
    ControllerModel, FrictionCompensation, InnerLoop, LqWeights, PreliminaryFeedbackChoice, SimulationConfig,
    TwistFeedback,
};
use crate::control::sensing::{SensorModel, VelocitySource};
use crate::model::PlantParameters;
use crate::schema::{self, Param, Value};

/// Hold time of the repeating slew at each end, s.
pub const REPEAT_HOLD: f64 = 1.5;

/// Where the linear analysis linearizes a run's loop (at rest, the friction cancelled).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum RestPoint {
    /// Where the slew ends (q2 = 0 rad): the paper's point, fixed for the whole run.
    #[default]
    SlewEnd,
    /// The end of the slew under way: under the repeating slew the analysis follows the arm
    /// between its two rest points (the paper's remark that the operating point of a
    /// linearization be "updated if necessary").
    Arm,
}

impl RestPoint {
    /// The word in URLs and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            RestPoint::SlewEnd => "end",
            RestPoint::Arm => "arm",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "end" => Some(RestPoint::SlewEnd),
            "arm" => Some(RestPoint::Arm),
            _ => None,
        }
    }

    /// The link angles (q1, q2) the analysis of `config` linearizes at, at simulated time `t`.
    pub fn angles(self, config: &SimulationConfig, t: f64) -> [f64; 2] {
        match self {
            RestPoint::SlewEnd => config.reference.end,
            RestPoint::Arm => crate::model::Reference::new(config.reference).target(t),
        }
    }
}

/// Run settings left out of the state string while at their defaults (the rest point, the
/// arm's parameters, the controller's model of it and the twist feedback's gains), so that links,
/// CSV and SVG headers written before they existed still read the same.
pub(super) fn quiet_at_default(key: &str) -> bool {
    key == "rest"
        || key == "model"
        || key == schema::TWIST_STIFFNESS.key
        || key == schema::TWIST_DAMPING.key
        || is_lq_weight(key)
        || schema::is_arm(key)
        || schema::is_sensor(key)
}

/// A weight of the LQ design (`pf = lq`).
pub(super) fn is_lq_weight(key: &str) -> bool {
    [schema::LQ_TWIST_WEIGHT.key, schema::LQ_RATE_WEIGHT.key, schema::LQ_TORQUE_WEIGHT.key].contains(&key)
}

/// The settings of one run, keyed by the schema's run parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunSettings {
    /// δ, s.
    pub delta: f64,
    /// α1, α2, 1/s.
    pub alpha: [f64; 2],
    pub pf: PreliminaryFeedbackChoice,
    /// k_p, k_d of `pf = twist`.
    pub twist: TwistFeedback,
    /// The LQ design's weights (`pf = lq`).
    pub lq: LqWeights,
    pub friction: FrictionCompensation,
    pub inner: InnerLoop,
    /// The slew repeats there and back (holding [`REPEAT_HOLD`] s) instead of the paper's one slew.
    pub repeat: bool,
    /// k, the horizon steps.
    pub k: usize,
    /// m = δ/ε.
    pub eps_ratio: f64,
    /// Where the analysis linearizes the loop.
    pub rest: RestPoint,
    /// The arm (the paper's table by default).
    pub plant: PlantParameters,
    /// The arm the controller assumes.
    pub model: ControllerModel,
    /// The sensors and the torque limit (the paper's perfect robot by default).
    pub sensors: SensorModel,
}

impl Default for RunSettings {
    /// The schema's defaults: the paper's controller with its K_pr at δ = 0.01 s, one slew.
    fn default() -> Self {
        let number = |p: &Param| p.number().map_or(f64::NAN, |n| n.default);
        let choice = |p: &Param| p.default_value().choice().unwrap_or("");
        Self {
            delta: number(&schema::DELTA),
            alpha: [number(&schema::ALPHA1), number(&schema::ALPHA2)],
            pf: PreliminaryFeedbackChoice::from_name(choice(&schema::PF)).unwrap_or_default(),
            twist: TwistFeedback::default(),
            lq: LqWeights::default(),
            friction: FrictionCompensation::from_name(choice(&schema::FRICTION)).unwrap_or_default(),
            inner: InnerLoop::from_name(choice(&schema::INNER)).unwrap_or_default(),
            repeat: schema::REPEAT.default_value().switch().unwrap_or(false),
            k: number(&schema::K) as usize,
            eps_ratio: number(&schema::EPS_RATIO),
            rest: RestPoint::from_name(choice(&schema::REST)).unwrap_or_default(),
            plant: PlantParameters::default(),
            model: ControllerModel::from_name(choice(&schema::MODEL)).unwrap_or_default(),
            sensors: SensorModel::default(),
        }
    }
}

impl RunSettings {
    /// The configuration of a run with these settings (the paper's slew).
    pub fn config(&self) -> SimulationConfig {
        let mut c = SimulationConfig::default();
        c.plant = self.plant;
        c.controller.sampling_period = self.delta;
        c.controller.alpha = self.alpha;
        c.controller.horizon_steps = self.k;
        c.controller.eps_ratio = self.eps_ratio;
        c.preliminary_feedback = self.pf;
        c.twist = self.twist;
        c.lq = self.lq;
        c.friction_compensation = self.friction;
        c.inner_loop = self.inner;
        c.reference.repeat_hold = self.repeat.then_some(REPEAT_HOLD);
        c.model = self.model;
        c.sensors = self.sensors;
        c
    }

    /// The settings that make `config` (the inverse of [`RunSettings::config`]; the analysis's
    /// rest point is not part of a configuration and is the default).
    pub fn of_config(c: &SimulationConfig) -> Self {
        Self {
            delta: c.controller.sampling_period,
            alpha: c.controller.alpha,
            pf: c.preliminary_feedback,
            twist: c.twist,
            lq: c.lq,
            friction: c.friction_compensation,
            inner: c.inner_loop,
            repeat: c.reference.repeat_hold.is_some(),
            k: c.controller.horizon_steps,
            eps_ratio: c.controller.eps_ratio,
            rest: RestPoint::default(),
            plant: c.plant,
            model: c.model,
            sensors: c.sensors,
        }
    }

    /// The value of a run parameter (`alpha` reads α1).
    pub fn get(&self, key: &str) -> Option<Value> {
        Some(match key {
            "delta" => Value::Number(self.delta),
            "alpha" | "alpha1" => Value::Number(self.alpha[0]),
            "alpha2" => Value::Number(self.alpha[1]),
            "pf" => Value::Choice(self.pf.name()),
            "twist_stiffness" => Value::Number(self.twist.stiffness),
            "twist_damping" => Value::Number(self.twist.damping),
            "lq_q_twist" => Value::Number(self.lq.twist),
            "lq_q_rate" => Value::Number(self.lq.twist_rate),
            "lq_r" => Value::Number(self.lq.torque),
            "friction" => Value::Choice(self.friction.name()),
            "inner" => Value::Choice(self.inner.name()),
            "repeat" => Value::Switch(self.repeat),
            "k" => Value::Number(self.k as f64),
            "eps_ratio" => Value::Number(self.eps_ratio),
            "rest" => Value::Choice(self.rest.name()),
            "model" => Value::Choice(self.model.name()),
            "encoder" => Value::Number(self.sensors.encoder_counts),
            "noise" => Value::Number(self.sensors.noise),
            "seed" => Value::Number(self.sensors.seed as f64),
            "velocity" => Value::Choice(self.sensors.velocity.name()),
            "velocity_filter" => Value::Number(self.sensors.velocity_filter),
            "torque_limit" => Value::Number(self.sensors.torque_limit),
            _ => return self.plant.get(key).map(Value::Number),
        })
    }

    /// Sets a run parameter from a value of the right kind (checked by the schema already);
    /// `alpha` sets α1 and α2. False if `key` is not a run parameter.
    pub(super) fn set(&mut self, key: &str, v: Value) -> bool {
        match (key, v) {
            ("delta", Value::Number(x)) => self.delta = x,
            ("alpha", Value::Number(x)) => self.alpha = [x, x],
            ("alpha1", Value::Number(x)) => self.alpha[0] = x,
            ("alpha2", Value::Number(x)) => self.alpha[1] = x,
            ("pf", Value::Choice(s)) => self.pf = PreliminaryFeedbackChoice::from_name(s).unwrap_or(self.pf),
            ("twist_stiffness", Value::Number(x)) => self.twist.stiffness = x,
            ("twist_damping", Value::Number(x)) => self.twist.damping = x,
            ("lq_q_twist", Value::Number(x)) => self.lq.twist = x,
            ("lq_q_rate", Value::Number(x)) => self.lq.twist_rate = x,
            ("lq_r", Value::Number(x)) => self.lq.torque = x,
            ("friction", Value::Choice(s)) => {
                self.friction = FrictionCompensation::from_name(s).unwrap_or(self.friction)
            }
            ("inner", Value::Choice(s)) => self.inner = InnerLoop::from_name(s).unwrap_or(self.inner),
            ("repeat", Value::Switch(b)) => self.repeat = b,
            ("k", Value::Number(x)) => self.k = x as usize,
            ("eps_ratio", Value::Number(x)) => self.eps_ratio = x,
            ("rest", Value::Choice(s)) => self.rest = RestPoint::from_name(s).unwrap_or(self.rest),
            ("model", Value::Choice(s)) => self.model = ControllerModel::from_name(s).unwrap_or(self.model),
            ("encoder", Value::Number(x)) => self.sensors.encoder_counts = x,
            ("noise", Value::Number(x)) => self.sensors.noise = x,
            ("seed", Value::Number(x)) => self.sensors.seed = x as u64,
            ("velocity", Value::Choice(s)) => {
                self.sensors.velocity = VelocitySource::from_name(s).unwrap_or(self.sensors.velocity)
            }
            ("velocity_filter", Value::Number(x)) => self.sensors.velocity_filter = x,
            ("torque_limit", Value::Number(x)) => self.sensors.torque_limit = x,
            (_, Value::Number(x)) => return self.plant.set(key, x),
            _ => return false,
        }
        true
    }
}

/// Run B of a comparison: its own preliminary feedback, δ and α; the rest follows run A.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompareSettings {
    pub pf: PreliminaryFeedbackChoice,
    pub delta: f64,
    pub alpha: [f64; 2],
    /// B's own arm: an arm preset's id, or `None` for A's arm.
    pub arm: Option<&'static str>,
}

impl CompareSettings {
    /// B's default: A with the preliminary feedback switched (off → the paper's, otherwise off).
    pub fn switched(a: &RunSettings) -> Self {
        let pf = match a.pf {
            PreliminaryFeedbackChoice::Off => PreliminaryFeedbackChoice::Paper,
            _ => PreliminaryFeedbackChoice::Off,
        };
        Self { pf, delta: a.delta, alpha: a.alpha, arm: None }
    }

    /// Run B's settings: A's with B's own preliminary feedback, δ, α and arm.
    pub fn run(&self, a: &RunSettings) -> RunSettings {
        let plant = self.arm.and_then(super::presets::arm).map_or(a.plant, |p| p.plant());
        RunSettings { pf: self.pf, delta: self.delta, alpha: self.alpha, plant, ..*a }
    }
}
