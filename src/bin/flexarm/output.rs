//! Words and numbers the commands share: the configuration line, the settings in JSON.

use flexarm::control::timing::{ControllerTime, ControllerWorkload, TimingPlan};
use flexarm::schema::{self, Scope, Value as Setting};
use flexarm::session::RunSettings;
use flexarm::SimulationConfig;
use serde_json::{json, Map, Value};
use std::time::Instant;

/// A run's settings as every command's JSON writes them: each under its schema key, once, in the
/// schema's order — α as `alpha1` and `alpha2` (the key `alpha` sets both and would repeat them),
/// the arm's parameters in an object `arm` — with `keep` choosing which (a map, for one, varies δ
/// and α itself).
pub fn settings_json(s: &RunSettings, keep: impl Fn(&str) -> bool) -> Map<String, Value> {
    let mut out = Map::new();
    let mut arm = Map::new();
    for p in schema::PARAMS.iter().filter(|p| p.scope == Scope::Run && p.key != schema::ALPHA.key && keep(p.key)) {
        let Some(v) = s.get(p.key) else { continue };
        let v = match v {
            Setting::Number(x) if p.number().is_some_and(|n| n.integer) => json!(x as i64),
            Setting::Number(x) => json!(x),
            Setting::Choice(c) => json!(c),
            Setting::Switch(b) => json!(b),
        };
        if schema::is_arm(p.key) {
            arm.insert(p.key.to_string(), v);
        } else {
            out.insert(p.key.to_string(), v);
        }
    }
    if !arm.is_empty() {
        out.insert("arm".into(), Value::Object(arm));
    }
    out
}

/// The configuration lines shared by the text outputs.
pub fn describe_config(c: &SimulationConfig) -> String {
    let k = &c.controller;
    format!(
        "  δ = {} s, α1 = {} 1/s, α2 = {} 1/s, k = {}, m = {} (ε = {:.3e} s, τ = kε = {:.3e} s)\n  \
         preliminary feedback {}, inner loop {}, friction compensation {}\n  arm: {}\n",
        k.sampling_period,
        k.alpha[0],
        k.alpha[1],
        k.horizon_steps,
        k.eps_ratio,
        k.integration_step(),
        k.horizon(),
        c.preliminary_feedback.name(),
        c.inner_loop.name(),
        c.friction_compensation.name(),
        flexarm::schema::arm_text(&c.plant.values())
    ) + if c.has_model_error() {
        "  the controller assumes the paper's arm (model = paper): a model error\n"
    } else {
        ""
    } + &sensors_line(c)
}

/// "  sensors: a 1024-count encoder, …" while any sensor or the torque limit is on (else nothing).
fn sensors_line(c: &SimulationConfig) -> String {
    if c.sensors == flexarm::control::sensing::SensorModel::default() {
        return String::new();
    }
    let digital = if c.sensors.is_digital() { " (a digital controller: what it computes is held over δ)" } else { "" };
    format!("  sensors: {}{digital}\n", flexarm::words::sensors::sensors_text(&c.sensors))
}

/// The linear noise floor of `c`'s digital loop at its δ, if its sensors make it digital (Err:
/// why there is none, e.g. an unstable loop).
pub fn noise_floor(c: &SimulationConfig) -> Option<Result<flexarm::analysis::NoiseFloor, flexarm::Error>> {
    flexarm::analysis::noise::noise_floor_of(c)
}

/// "δ = 0.01 s, α = 2 1/s" (or α1, α2 when they differ).
pub fn delta_alpha_text(c: &SimulationConfig) -> String {
    let k = &c.controller;
    if k.alpha[0] == k.alpha[1] {
        format!("δ = {} s, α = {} 1/s", k.sampling_period, k.alpha[0])
    } else {
        format!("δ = {} s, α1 = {} 1/s, α2 = {} 1/s", k.sampling_period, k.alpha[0], k.alpha[1])
    }
}

/// The controller's prediction timed on this computer (issue 36, "the processor"): the median
/// seconds per sampling instant over 7 batches of up to 200 predictions from the middle of the
/// slew, a few milliseconds in all. The paper: "to be implementable, the numerical integration of
/// the DAE has to be faster than real-time".
pub fn processor(config: &SimulationConfig) -> Result<ControllerTime, flexarm::Error> {
    let mut workload = ControllerWorkload::new(config)?;
    let start = Instant::now();
    workload.measure(&mut || start.elapsed().as_secs_f64(), TimingPlan::default())
}

/// The processor's line: the timing in words, or why there is none.
pub fn processor_text(time: &Result<ControllerTime, flexarm::Error>) -> String {
    match time {
        Ok(t) => flexarm::words::processor::processor(t),
        Err(e) => format!("the controller's prediction was not timed: {e}"),
    }
}

/// The JSON field `controller_seconds_per_sample`: the median seconds, or null.
pub fn processor_json(time: &Result<ControllerTime, flexarm::Error>) -> Value {
    match time {
        Ok(t) if t.is_measured() => json!(t.seconds_per_sample),
        _ => Value::Null,
    }
}
