//! The browser binding: one [`Simulation`] handle that JavaScript drives, and the wgpu
//! [`Renderer`](renderer::Renderer) that draws it. This layer converts and forwards; the physics
//! lives in the core modules.
//!
//! Errors from the core become JS exceptions (`Error` objects with a readable message); a Rust
//! panic is reported to the page through `window.flexarmPanic(message)` if the page defines it.

pub mod renderer;

use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::analysis::{analyze, StabilityReport};
use crate::closed_loop::{ClosedLoop, DivergenceReason, Metrics, Verdict};
use crate::params::SimulationConfig;
use crate::presets::{preset, PRESETS};

/// The longest simulated time one `advance` call may cover, s: after a stalled tab the
/// simulation skips ahead instead of freezing the page to catch up.
pub const MAX_ADVANCE_PER_CALL: f64 = 0.25;

/// Seconds of traces kept for drawing and export.
pub const DEFAULT_TRACE_SECONDS: f64 = 60.0;

#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        let message = format!("flexarm crashed: {info}");
        web_sys::console::error_1(&message.clone().into());
        if let Some(window) = web_sys::window() {
            if let Ok(f) = js_sys::Reflect::get(&window, &"flexarmPanic".into()) {
                if let Some(f) = f.dyn_ref::<js_sys::Function>() {
                    let _ = f.call1(&JsValue::NULL, &message.into());
                }
            }
        }
    }));
}

fn to_js<T: Serialize>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("could not convert the result for JavaScript: {e}")))
}

fn config_from_js(config: JsValue) -> Result<SimulationConfig, JsError> {
    if config.is_undefined() || config.is_null() {
        return Ok(SimulationConfig::default());
    }
    let c: SimulationConfig =
        serde_wasm_bindgen::from_value(config).map_err(|e| JsError::new(&format!("invalid configuration: {e}")))?;
    c.validate().map_err(|e| JsError::new(&e.to_string()))?;
    Ok(c)
}

/// Metrics flattened for JavaScript.
#[derive(Serialize)]
struct WebMetrics {
    time: f64,
    verdict: &'static str,
    growth_rate: Option<f64>,
    diverged_at: Option<f64>,
    divergence_reason: Option<DivergenceReason>,
    max_error_slew: [f64; 2],
    max_error_after: [f64; 2],
    rms_error: [f64; 2],
    max_torque: [f64; 2],
}

impl From<Metrics> for WebMetrics {
    fn from(m: Metrics) -> Self {
        let (diverged_at, divergence_reason) = match m.verdict {
            Verdict::Diverged { at, reason } => (Some(at), Some(reason)),
            _ => (None, None),
        };
        Self {
            time: m.time,
            verdict: m.verdict.label(),
            growth_rate: m.growth_rate,
            diverged_at,
            divergence_reason,
            max_error_slew: m.max_error_slew,
            max_error_after: m.max_error_after,
            rms_error: m.rms_error,
            max_torque: m.max_torque,
        }
    }
}

/// The closed loop as JavaScript sees it.
#[wasm_bindgen]
pub struct Simulation {
    inner: ClosedLoop,
    trace_seconds: f64,
    /// The analysis of the configuration in force, computed on demand and cached.
    analysis: Option<(SimulationConfig, StabilityReport)>,
}

impl Simulation {
    /// The core closed loop (for the renderer).
    pub fn closed_loop(&self) -> &ClosedLoop {
        &self.inner
    }

    fn bound_traces(&mut self) {
        let keep = (self.trace_seconds / self.inner.config().output_interval).ceil() as usize + 1;
        let traces = self.inner.traces_mut();
        // Trim in chunks so the cost is amortised rather than paid every frame.
        if traces.len() > keep + keep / 8 {
            traces.truncate_front(keep);
        }
    }
}

#[wasm_bindgen]
impl Simulation {
    /// A simulation at rest on the reference. `config` is a (partial) configuration object with
    /// the fields of `defaultConfig()`; missing fields take the paper's defaults.
    #[wasm_bindgen(constructor)]
    pub fn new(config: JsValue) -> Result<Simulation, JsError> {
        let config = config_from_js(config)?;
        let inner = ClosedLoop::new(config).map_err(|e| JsError::new(&e.to_string()))?;
        Ok(Simulation { inner, trace_seconds: DEFAULT_TRACE_SECONDS, analysis: None })
    }

    /// The paper's default configuration as an object.
    #[wasm_bindgen(js_name = defaultConfig)]
    pub fn default_config() -> Result<JsValue, JsError> {
        to_js(&SimulationConfig::default())
    }

    /// The configuration a preset applies to `base` (or to the defaults).
    #[wasm_bindgen(js_name = presetConfig)]
    pub fn preset_config(id: &str, base: JsValue) -> Result<JsValue, JsError> {
        let base = config_from_js(base)?;
        let p = preset(id).ok_or_else(|| {
            let ids: Vec<&str> = PRESETS.iter().map(|p| p.id).collect();
            JsError::new(&format!("unknown preset '{id}': one of {}", ids.join(", ")))
        })?;
        to_js(&p.apply(&base))
    }

    /// `[{id, title}]` of every preset.
    pub fn presets() -> Result<JsValue, JsError> {
        #[derive(Serialize)]
        struct Entry {
            id: &'static str,
            title: &'static str,
        }
        let list: Vec<Entry> = PRESETS.iter().map(|p| Entry { id: p.id, title: p.title }).collect();
        to_js(&list)
    }

    /// The configuration in force (a pending change shows after the next sampling instant).
    pub fn config(&self) -> Result<JsValue, JsError> {
        to_js(self.inner.config())
    }

    /// Validates `config` and applies it at the next sampling instant; throws if invalid.
    #[wasm_bindgen(js_name = setConfig)]
    pub fn set_config(&mut self, config: JsValue) -> Result<(), JsError> {
        let config = config_from_js(config)?;
        self.inner.set_config(config).map_err(|e| JsError::new(&e.to_string()))
    }

    /// Starts over from rest with the current configuration.
    pub fn reset(&mut self) -> Result<(), JsError> {
        self.inner.reset().map_err(|e| JsError::new(&e.to_string()))
    }

    /// Advances by `wall_seconds × speed` of simulated time (at most 0.25 s per call); returns
    /// the simulated time covered.
    pub fn advance(&mut self, wall_seconds: f64, speed: f64) -> Result<f64, JsError> {
        if !(wall_seconds.is_finite() && wall_seconds >= 0.0 && speed.is_finite() && speed >= 0.0) {
            return Err(JsError::new(&format!(
                "advance needs finite, non-negative wall time and speed, got {wall_seconds} s × {speed}"
            )));
        }
        let dt = (wall_seconds * speed).min(MAX_ADVANCE_PER_CALL);
        let before = self.inner.time();
        self.inner.advance(dt).map_err(|e| JsError::new(&e.to_string()))?;
        self.bound_traces();
        Ok(self.inner.time() - before)
    }

    /// Advances to the next sampling instant.
    #[wasm_bindgen(js_name = stepPeriod)]
    pub fn step_period(&mut self) {
        self.inner.advance_one_period();
        self.bound_traces();
    }

    /// Adds a torque (T1, T2 in N m) for `duration` seconds: a poke.
    pub fn poke(&mut self, torque1: f64, torque2: f64, duration: f64) -> Result<(), JsError> {
        self.inner.apply_disturbance([torque1, torque2], duration).map_err(|e| JsError::new(&e.to_string()))
    }

    /// Simulated time, s.
    pub fn time(&self) -> f64 {
        self.inner.time()
    }

    /// True once the run has diverged (it no longer advances until reset).
    #[wasm_bindgen(js_name = isFinished)]
    pub fn is_finished(&self) -> bool {
        self.inner.is_finished()
    }

    /// The newest state: `{time, q, qdot, qd, error, torque, v, xf_hat, w}`.
    pub fn snapshot(&self) -> Result<JsValue, JsError> {
        to_js(&self.inner.snapshot())
    }

    /// Metrics and verdict so far: `{time, verdict, growth_rate, diverged_at, divergence_reason,
    /// max_error_slew, max_error_after, rms_error, max_torque}`.
    pub fn metrics(&self) -> Result<JsValue, JsError> {
        to_js(&WebMetrics::from(self.inner.metrics()))
    }

    /// One recorded column as a typed array: `t`, `q1`, `q2`, `theta`, `qd1`, `qd2`, `e1`, `e2`,
    /// `torque1`, `torque2`, `v1`, `v2`, `xf1_hat`, `xf2_hat`.
    pub fn trace(&self, name: &str) -> Result<js_sys::Float64Array, JsError> {
        let t = self.inner.traces();
        let column = match name {
            "t" => &t.t,
            "q1" => &t.q1,
            "q2" => &t.q2,
            "theta" => &t.theta,
            "qd1" => &t.qd1,
            "qd2" => &t.qd2,
            "e1" => &t.e1,
            "e2" => &t.e2,
            "torque1" => &t.torque1,
            "torque2" => &t.torque2,
            "v1" => &t.v1,
            "v2" => &t.v2,
            "xf1_hat" => &t.xf1_hat,
            "xf2_hat" => &t.xf2_hat,
            _ => return Err(JsError::new(&format!("unknown trace '{name}'"))),
        };
        Ok(js_sys::Float64Array::from(column.as_slice()))
    }

    /// The recorded traces as CSV with a header row naming units.
    #[wasm_bindgen(js_name = tracesCsv)]
    pub fn traces_csv(&self) -> String {
        self.inner.traces().to_csv()
    }

    /// Seconds of traces kept (older samples are dropped).
    #[wasm_bindgen(js_name = setTraceSeconds)]
    pub fn set_trace_seconds(&mut self, seconds: f64) -> Result<(), JsError> {
        if !(seconds.is_finite() && seconds > 0.0) {
            return Err(JsError::new(&format!("trace length must be > 0 s, got {seconds}")));
        }
        self.trace_seconds = seconds;
        Ok(())
    }

    /// The linear stability analysis of the configuration in force (cached):
    /// `{sampling_period, rest, spectral_radius, growth_rate, poles: [{discrete, continuous}],
    /// limit_pair_open, limit_pair}`.
    pub fn analysis(&mut self) -> Result<JsValue, JsError> {
        let config = *self.inner.config();
        if !matches!(&self.analysis, Some((c, _)) if *c == config) {
            let report = analyze(&config, None).map_err(|e| JsError::new(&e.to_string()))?;
            self.analysis = Some((config, report));
        }
        to_js(&self.analysis.as_ref().map(|(_, r)| r))
    }
}

/// ρ of a configuration without creating a simulation (for sweeps in the page).
#[wasm_bindgen(js_name = spectralRadius)]
pub fn spectral_radius(config: JsValue) -> Result<f64, JsError> {
    let config = config_from_js(config)?;
    crate::analysis::spectral_radius(&config, None).map_err(|e| JsError::new(&e.to_string()))
}

/// ρ over a (δ, α) grid with logarithmic axes, computed a few rows at a time so the page stays
/// responsive (call `step` from successive frames or idle callbacks until `isDone`).
#[wasm_bindgen]
pub struct StabilityMapJob {
    config: SimulationConfig,
    sampling_periods: Vec<f64>,
    alphas: Vec<f64>,
    /// Row-major by α: ρ at `alpha_index * sampling_periods.len() + delta_index`.
    rho: Vec<f64>,
}

impl StabilityMapJob {
    /// (δ values, α values, ρ so far) for the renderer.
    pub fn grid(&self) -> (&[f64], &[f64], &[f64]) {
        (&self.sampling_periods, &self.alphas, &self.rho)
    }

    fn rows_done(&self) -> usize {
        self.rho.len() / self.sampling_periods.len().max(1)
    }
}

#[wasm_bindgen]
impl StabilityMapJob {
    /// A map of `config` (its preliminary feedback, inner loop, k, m, plant) over `n_delta`
    /// sampling periods from `delta_min` to `delta_max` (s) and `n_alpha` values of α1 = α2 from
    /// `alpha_min` to `alpha_max` (1/s), both spaced logarithmically.
    #[wasm_bindgen(constructor)]
    pub fn new(
        config: JsValue,
        delta_min: f64,
        delta_max: f64,
        n_delta: usize,
        alpha_min: f64,
        alpha_max: f64,
        n_alpha: usize,
    ) -> Result<StabilityMapJob, JsError> {
        let config = config_from_js(config)?;
        let positive_range = |lo: f64, hi: f64| lo.is_finite() && hi.is_finite() && lo > 0.0 && hi > lo;
        if !positive_range(delta_min, delta_max) || !positive_range(alpha_min, alpha_max) {
            return Err(JsError::new(&format!(
                "stability map ranges must satisfy 0 < min < max: δ {delta_min}–{delta_max} s, α {alpha_min}–{alpha_max} 1/s"
            )));
        }
        if !(2..=1000).contains(&n_delta) || !(2..=1000).contains(&n_alpha) {
            return Err(JsError::new(&format!(
                "stability map size must be 2–1000 points per axis, got {n_delta} × {n_alpha}"
            )));
        }
        // Check the corners now, so a bad grid fails here rather than halfway through.
        for (d, a) in [(delta_min, alpha_min), (delta_max, alpha_max)] {
            let mut c = config;
            c.controller.sampling_period = d;
            c.controller.alpha = [a, a];
            c.validate().map_err(|e| JsError::new(&e.to_string()))?;
        }
        Ok(StabilityMapJob {
            config,
            sampling_periods: crate::analysis::log_space(delta_min, delta_max, n_delta),
            alphas: crate::analysis::log_space(alpha_min, alpha_max, n_alpha),
            rho: Vec::with_capacity(n_delta * n_alpha),
        })
    }

    /// Computes rows until about `budget_ms` of wall time has passed (at least one row);
    /// returns the fraction done.
    pub fn step(&mut self, budget_ms: f64) -> Result<f64, JsError> {
        let clock = web_sys::window().and_then(|w| w.performance());
        let now = || clock.as_ref().map(|p| p.now()).unwrap_or(0.0);
        let start = now();
        while !self.is_done() {
            let alpha = self.alphas[self.rows_done()];
            crate::analysis::stability_map_row(&self.config, alpha, &self.sampling_periods, &mut self.rho)
                .map_err(|e| JsError::new(&e.to_string()))?;
            if now() - start >= budget_ms {
                break;
            }
        }
        Ok(self.progress())
    }

    /// True when every row is computed.
    #[wasm_bindgen(js_name = isDone)]
    pub fn is_done(&self) -> bool {
        self.rows_done() >= self.alphas.len()
    }

    /// Fraction of rows computed, 0–1.
    pub fn progress(&self) -> f64 {
        self.rows_done() as f64 / self.alphas.len() as f64
    }

    /// ρ row-major by α (index `alpha_index * n_delta + delta_index`), NaN where not computed yet.
    pub fn values(&self) -> js_sys::Float64Array {
        let mut all = self.rho.clone();
        all.resize(self.sampling_periods.len() * self.alphas.len(), f64::NAN);
        js_sys::Float64Array::from(all.as_slice())
    }

    /// The δ values of the columns, s.
    #[wasm_bindgen(js_name = samplingPeriods)]
    pub fn sampling_periods(&self) -> js_sys::Float64Array {
        js_sys::Float64Array::from(self.sampling_periods.as_slice())
    }

    /// The α values of the rows, 1/s.
    pub fn alphas(&self) -> js_sys::Float64Array {
        js_sys::Float64Array::from(self.alphas.as_slice())
    }
}
