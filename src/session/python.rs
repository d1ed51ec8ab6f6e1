//! The model as a Python script: `www/export/model_template.py` filled with a configuration's
//! numbers — the arm (and the arm the controller assumes), α, δ, k, m, the preliminary feedback's
//! gains written out, the inner loop, the rest point, the slew and the sensors — so that a student
//! can rebuild the linearized loop in NumPy/SciPy, read how it is made, and compare its ρ and A4
//! with flexarm's (`tests/export_python.rs` runs it). With the sensors on it builds the digital
//! controller's loop ([`crate::analysis::digital`]) and predicts its noise floor
//! ([`crate::analysis::noise`]). The page's "Export as Python" and `flexarm export-python` write
//! the same text.

use super::Session;
use crate::control::config::{InnerLoop, SimulationConfig};
use crate::control::feedback::resolve_gain;
use crate::control::sensing::SensorModel;
use crate::error::Error;
use crate::model::params::PlantParameters;
use crate::schema::ARM_PARAMS;

/// The script's template: a file beside the page, which the page fetches when asked for the
/// script (it is not compiled into the wasm: 4.5 kB gzip less), and which the native build reads
/// at compile time.
#[cfg(not(target_arch = "wasm32"))]
pub const TEMPLATE: &str = include_str!("../../www/export/model_template.py");

/// Where the page finds the template, relative to the page.
pub const TEMPLATE_PATH: &str = "export/model_template.py";

/// A number as Python reads it back exactly (Rust's shortest round-trip form).
fn num(v: f64) -> String {
    let s = format!("{v:?}");
    if s.contains('.') || s.contains('e') || s.contains("inf") || s.contains("NaN") {
        s
    } else {
        format!("{s}.0")
    }
}

/// `{"a1": 4.984, …}`: an arm under its schema keys.
fn arm(p: &PlantParameters) -> String {
    let pairs: Vec<String> =
        ARM_PARAMS.iter().zip(p.values()).map(|(k, v)| format!("\"{}\": {}", k.key, num(v))).collect();
    format!("{{{}}}", pairs.join(", "))
}

/// `{"encoder": 1024.0, "noise": 0.0, "velocity": "difference", "velocity_filter": 0.0,
/// "torque_limit": 0.0}`: the
/// sensors as the script reads them (the seed is left out: the script has no noise to draw).
fn sensors(s: &SensorModel) -> String {
    format!(
        "{{\"encoder\": {}, \"noise\": {}, \"velocity\": \"{}\", \"velocity_filter\": {}, \"torque_limit\": {}}}",
        num(s.encoder_counts),
        num(s.noise),
        s.velocity.name(),
        num(s.velocity_filter),
        num(s.torque_limit)
    )
}

/// The script for `config`, linearized at rest at `rest` (q1, q2), headed by `state`, from
/// `template` ([`TEMPLATE`]).
pub fn python_script(config: &SimulationConfig, rest: [f64; 2], state: &str, template: &str) -> Result<String, Error> {
    if !template.contains("{{ARM}}") {
        return Err(Error::NotReady("the script's template did not load (export/model_template.py, beside the page)"));
    }
    config.validate()?;
    let gain = resolve_gain(config)?;
    let row = |r: usize| format!("[{}]", (0..8).map(|c| num(gain[(r, c)])).collect::<Vec<_>>().join(", "));
    let c = &config.controller;
    let s = &config.reference;
    // A state string is plain text here: no quote or backslash can end the script's strings.
    let state: String = state.chars().filter(|ch| !matches!(ch, '"' | '\\' | '\n' | '\r')).collect();
    let fills: [(&str, String); 12] = [
        ("{{STATE}}", state),
        ("{{ARM}}", arm(&config.plant)),
        ("{{MODEL}}", if config.has_model_error() { arm(&config.model_plant()) } else { "ARM".into() }),
        ("{{ALPHA}}", format!("({}, {})", num(c.alpha[0]), num(c.alpha[1]))),
        ("{{DELTA}}", num(c.sampling_period)),
        ("{{K}}", c.horizon_steps.to_string()),
        ("{{M}}", num(c.eps_ratio)),
        ("{{GAIN}}", format!("[{}, {}]", row(0), row(1))),
        (
            "{{INNER}}",
            match config.inner_loop {
                InnerLoop::Continuous => "continuous".into(),
                InnerLoop::Sampled => "sampled".into(),
            },
        ),
        ("{{REST}}", format!("({}, {})", num(rest[0]), num(rest[1]))),
        (
            "{{SLEW}}",
            format!(
                "(({}, {}), ({}, {}), {})",
                num(s.start[0]),
                num(s.start[1]),
                num(s.end[0]),
                num(s.end[1]),
                num(s.slew_time)
            ),
        ),
        ("{{SENSORS}}", sensors(&config.sensors)),
    ];
    let mut out = template.to_string();
    for (key, value) in &fills {
        out = out.replace(key, value);
    }
    Ok(out)
}

impl Session {
    /// Run A's settings as a Python script, linearized where the analysis is, from `template`.
    pub fn python_script(&self, template: &str) -> Result<String, Error> {
        if self.answers_hidden() {
            // The script prints ρ and the verdict: an answer student mode keeps back.
            return Err(Error::NotReady("student mode holds the Python script back until you answer (it prints ρ)"));
        }
        let rest = self.linear_settings().rest;
        python_script(&self.settings.a.config(), rest, &self.settings.run_query(), template)
    }
}
