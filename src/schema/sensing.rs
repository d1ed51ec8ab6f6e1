//! The sensors and the actuators' limit ([`crate::control::sensing`]) as settings like δ: all off
//! by default (the paper's perfect robot), so that every link and number written before them
//! reads the same.

use super::{Choice, Kind, NumberSpec, Param, Scale, Scope};

/// A number from 0 (off) to `max`, the page's control over `control` on `scale`.
const fn from_zero(max: f64, control: [f64; 2], scale: Scale, integer: bool, allowed: &'static str) -> NumberSpec {
    NumberSpec {
        min: 0.0,
        min_inclusive: true,
        max,
        allowed: Some(allowed),
        control,
        scale,
        digits: 3,
        integer,
        default: 0.0,
    }
}

/// Encoder counts per revolution on q1, q2 and θ.
pub const ENCODER: Param = Param {
    key: "encoder",
    label: "Encoder counts per revolution",
    symbol: "N",
    unit: "",
    name: "encoder counts (encoder)",
    kind: Kind::Number(from_zero(
        1073741824.0,
        [256.0, 1048576.0],
        Scale::Log,
        true,
        "must be a whole number of counts from 0 (exact angles) to 2³⁰ (a count of 6e-9 rad, below any encoder \
         and near the simulation's own rounding)",
    )),
    scope: Scope::Run,
    help: "The controller reads q1, q2 and θ to the nearest count Δ = 2π/N (0: exact, the paper's assumption). \
           Any sensor setting makes the controller digital: everything it computes is held over δ.",
};

/// Measurement noise on each angle.
pub const NOISE: Param = Param {
    key: "noise",
    label: "Angle noise σ",
    symbol: "σ",
    unit: "rad",
    name: "measurement noise (noise)",
    kind: Kind::Number(from_zero(
        0.1,
        [1e-6, 1e-2],
        Scale::Log,
        false,
        "must be from 0 (none) to 0.1 rad (beyond, the noise is larger than the errors the controller corrects)",
    )),
    scope: Scope::Run,
    help: "White Gaussian noise of standard deviation σ on each measured angle, drawn from the seed: the same \
           seed gives the same run, bit for bit.",
};

/// The noise's seed.
pub const SEED: Param = Param {
    key: "seed",
    label: "Noise seed",
    symbol: "",
    unit: "",
    name: "noise seed (seed)",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: true,
        max: 4294967295.0,
        allowed: Some("must be a whole number from 0 to 4294967295"),
        control: [1.0, 1000.0],
        scale: Scale::Linear,
        digits: 10,
        integer: true,
        default: 1.0,
    }),
    scope: Scope::Run,
    help: "Which noise: another seed draws other numbers of the same size.",
};

/// How the controller gets the velocities.
pub const VELOCITY: Param = Param {
    key: "velocity",
    label: "Velocities from",
    symbol: "",
    unit: "",
    name: "velocity source (velocity)",
    kind: Kind::Choice {
        options: &[
            Choice { value: "exact", label: "exact (the paper's assumption)" },
            Choice { value: "difference", label: "differences of readings over δ" },
        ],
        default: "exact",
    },
    scope: Scope::Run,
    help: "The paper's controller reads the velocities exactly. An encoder gives only angles: the velocity \
           (m_n − m_{n−1})/δ carries the angles' error divided by δ, and so grows as δ shrinks.",
};

/// The low-pass filter on the velocity estimate.
pub const VELOCITY_FILTER: Param = Param {
    key: "velocity_filter",
    label: "Velocity filter time constant τ_v",
    symbol: "τ_v",
    unit: "s",
    name: "velocity filter (velocity_filter)",
    kind: Kind::Number(from_zero(
        1.0,
        [1e-4, 0.1],
        Scale::Log,
        false,
        "must be from 0 (no filter) to 1 s (beyond, the estimate lags the arm's every motion)",
    )),
    scope: Scope::Run,
    help: "A first-order low-pass filter on the velocity estimate, ν_n = β ν_{n−1} + (1 − β) ν_raw with \
           β = e^(−δ/τ_v) (0: none). On differenced velocities it bounds their noise at about σ/τ_v whatever \
           δ, instead of √2 σ/δ, but delays the estimate by about τ_v.",
};

/// The motor torque limit.
pub const TORQUE_LIMIT: Param = Param {
    key: "torque_limit",
    label: "Torque limit |T1|, |T2|",
    symbol: "T_max",
    unit: "N m",
    name: "torque limit (torque_limit)",
    kind: Kind::Number(from_zero(1e6, [10.0, 1000.0], Scale::Log, false, "must be from 0 (no limit) to 1e6 N m")),
    scope: Scope::Run,
    help: "The motors deliver at most this torque; beyond it they saturate (0: unlimited, the paper's \
           assumption). On the paper's arm the slew itself needs about 97 N m on T1; another arm needs its own.",
};

/// The sensor settings, in the order the page and `--help` list them.
pub const SENSOR_PARAMS: [&Param; 6] = [&ENCODER, &NOISE, &SEED, &VELOCITY, &VELOCITY_FILTER, &TORQUE_LIMIT];

/// True for a key of the sensor model.
pub fn is_sensor(key: &str) -> bool {
    SENSOR_PARAMS.iter().any(|p| p.key == key)
}

/// What 0 means for a sensor setting, as its control shows it ("0 N m" would read as no torque).
pub fn off_text(key: &str) -> Option<&'static str> {
    match key {
        "encoder" => Some("0: exact angles"),
        "noise" | "velocity_filter" => Some("0: none"),
        "torque_limit" => Some("0: unlimited"),
        _ => None,
    }
}
