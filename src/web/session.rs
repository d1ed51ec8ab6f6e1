//! The session as JavaScript sees it: a thin wrapper over [`crate::session::Session`] that
//! converts arguments and results. Every decision (what a change does, which map is needed, what
//! the verdict says) is the session's.

use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::{js_error, now_ms, to_js};
use crate::control::{Column, Verdict};
use crate::schema::{Kind, Param, Scale, Scope, PARAMS};
use crate::session::{MapSide, Session, Settings, Source, PRESETS};

/// A parameter of the schema, flattened for the page's controls.
#[derive(Serialize)]
struct ParamView {
    key: &'static str,
    label: &'static str,
    symbol: &'static str,
    unit: &'static str,
    help: &'static str,
    scope: Scope,
    /// "number", "choice" or "switch".
    kind: &'static str,
    scale: Option<Scale>,
    /// The control's span and its hard limits.
    control: Option<[f64; 2]>,
    limits: Option<[f64; 2]>,
    integer: bool,
    /// Choices: value and label.
    options: Vec<[&'static str; 2]>,
    /// The default as the state string writes it.
    default: String,
    /// The allowed values in words.
    allowed: String,
}

impl ParamView {
    fn of(p: &'static Param) -> Self {
        let (kind, scale, control, limits, integer, options) = match &p.kind {
            Kind::Number(n) => ("number", Some(n.scale), Some(n.control), Some([n.min, n.max]), n.integer, vec![]),
            Kind::Choice { options, .. } => {
                ("choice", None, None, None, false, options.iter().map(|o| [o.value, o.label]).collect())
            }
            Kind::Switch { .. } => ("switch", None, None, None, false, vec![]),
        };
        Self {
            key: p.key,
            label: p.label,
            symbol: p.symbol,
            unit: p.unit,
            help: p.help,
            scope: p.scope,
            kind,
            scale,
            control,
            limits,
            integer,
            options,
            default: p.default_value().text(),
            allowed: p.allowed(true),
        }
    }
}

/// Every user-settable parameter: key, label, unit, kind, ranges, default, help.
#[wasm_bindgen]
pub fn schema() -> Result<JsValue, JsError> {
    to_js(&PARAMS.iter().map(|p| ParamView::of(p)).collect::<Vec<_>>())
}

/// The path a `lesson_src=` value names on this site; throws with the reason for anything else
/// (another site, a script URL, no path).
#[wasm_bindgen(js_name = lessonSourcePath)]
pub fn lesson_source_path(value: &str) -> Result<String, JsError> {
    crate::lesson::source_path(value).map_err(js_error)
}

/// `[{id, title, state}]` of every preset.
#[wasm_bindgen]
pub fn presets() -> Result<JsValue, JsError> {
    to_js(&PRESETS)
}

/// `[{id, title, state}]` of every arm preset (`arm=ID` in a state string).
#[wasm_bindgen]
pub fn arms() -> Result<JsValue, JsError> {
    to_js(&crate::session::ARMS)
}

/// ρ of the settings in a state string (over the CLI's defaults), without a session (for the
/// wasm-bindgen tests; not exported to the page, which has its session's).
pub fn spectral_radius(state: &str) -> Result<f64, JsError> {
    let mut settings = Settings::default();
    settings.read(state, Source::CommandLine).map_err(js_error)?;
    crate::analysis::spectral_radius(&settings.a.config(), None).map_err(js_error)
}

/// A run's metrics, flattened.
#[derive(Serialize)]
struct MetricsView {
    time: f64,
    /// The run's judgement, the status's word ("stable", "borderline", "diverged", …).
    verdict: &'static str,
    growth_rate: Option<f64>,
    diverged_at: Option<f64>,
    max_error_slew: [f64; 2],
    max_error_after: [f64; 2],
    rms_error: [f64; 2],
    max_torque: [f64; 2],
}

/// The controller's prediction timed in the page (issue 36): `controllerTime()`.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ControllerTimeView {
    /// The median seconds one sampling instant's prediction takes here, s.
    seconds_per_sample: f64,
    /// δ, s.
    sampling_period: f64,
    /// seconds per sample / δ (below 1: faster than real time).
    share: f64,
    /// The same in words.
    text: String,
}

/// The physics session the page has open — runs, analyses, maps — for the page's façade
/// (`www/js/flexarm.js`), which composes it with the [`super::classroom::WebClassroom`]: create it
/// from the URL's query with `new Session(q)`.
#[wasm_bindgen(js_name = Session)]
pub struct WebSession {
    inner: Session,
    notices: Vec<crate::session::Notice>,
}

impl WebSession {
    /// The core session (for the renderer).
    pub fn session(&self) -> &Session {
        &self.inner
    }

    /// The core session, to change (for the binding's other files).
    pub(super) fn session_mut(&mut self) -> &mut Session {
        &mut self.inner
    }

    fn run(&self, index: usize) -> Result<&crate::session::Run, JsError> {
        self.inner.run(index).ok_or_else(|| JsError::new(&format!("no run {index}: 0 is A, 1 is B when comparing")))
    }
}

#[wasm_bindgen(js_class = Session)]
impl WebSession {
    /// The page's session for a URL query (`?delta=0.01&pf=off`, or ""): the page's start with the
    /// query over it. Values it could not take are in `notices()`; the lesson and the moment the
    /// query may name are the classroom's (`new Classroom(session, q, …)`).
    #[wasm_bindgen(constructor)]
    pub fn new(query: &str) -> WebSession {
        let (inner, notices) = Session::open(query);
        WebSession { inner, notices }
    }

    /// `[{key, text}]`: the values the last query read could not take, and why.
    pub fn notices(&self) -> Result<JsValue, JsError> {
        to_js(&self.notices)
    }

    /// Sets a parameter from its text (a selector's value, a number typed): throws with a
    /// readable message if invalid, and nothing changes then.
    pub fn set(&mut self, key: &str, text: &str) -> Result<(), JsError> {
        self.inner.set(key, text).map_err(js_error)
    }

    /// Sets a numeric parameter from its slider's position in [0, 1].
    #[wasm_bindgen(js_name = setPosition)]
    pub fn set_position(&mut self, key: &str, position: f64) -> Result<(), JsError> {
        self.inner.set_position(key, position).map_err(js_error)
    }

    /// Moves a numeric parameter by `steps` arrow-key steps (round values on a log control).
    #[wasm_bindgen(js_name = stepValue)]
    pub fn step_value(&mut self, key: &str, steps: i32) -> Result<(), JsError> {
        self.inner.step_value(key, steps).map_err(js_error)
    }

    /// Applies a preset and restarts from rest.
    #[wasm_bindgen(js_name = applyPreset)]
    pub fn apply_preset(&mut self, id: &str) -> Result<(), JsError> {
        self.inner.apply_preset(id).map_err(js_error)
    }

    /// Reads a state string over the current settings (restarting); returns the notices.
    #[wasm_bindgen(js_name = readState)]
    pub fn read_state(&mut self, state: &str) -> Result<JsValue, JsError> {
        let notices = self.inner.read_state(state).map_err(js_error)?;
        to_js(&notices)
    }

    /// Runs A at a point picked on a map ("off" or "on").
    #[wasm_bindgen(js_name = setFromMap)]
    pub fn set_from_map(&mut self, side: &str, delta: f64, alpha: f64) -> Result<(), JsError> {
        let side = MapSide::parse(side).map_err(|e| JsError::new(&e))?;
        self.inner.set_from_map(side, delta, alpha).map_err(js_error)
    }

    /// Moves run A's point on a map ("off" or "on") by arrow-key steps of δ and α.
    #[wasm_bindgen(js_name = stepOnMap)]
    pub fn step_on_map(&mut self, side: &str, delta_steps: i32, alpha_steps: i32) -> Result<(), JsError> {
        let side = MapSide::parse(side).map_err(|e| JsError::new(&e))?;
        self.inner.step_on_map(side, delta_steps, alpha_steps).map_err(js_error)
    }

    /// `[{key, value, position, text}]`: what each control shows.
    pub fn controls(&self) -> Result<JsValue, JsError> {
        to_js(&self.inner.controls())
    }

    /// Advances by `wall_seconds × speed` of simulated time (at most 0.25 s per call); returns
    /// the simulated time run A covered.
    pub fn advance(&mut self, wall_seconds: f64) -> Result<f64, JsError> {
        self.inner.advance(wall_seconds).map_err(js_error)
    }

    /// Advances to the next sampling instant.
    #[wasm_bindgen(js_name = stepPeriod)]
    pub fn step_period(&mut self) {
        self.inner.step_period();
    }

    /// Both runs back to rest.
    pub fn reset(&mut self) -> Result<(), JsError> {
        self.inner.reset().map_err(js_error)
    }

    /// A short torque kick on both runs.
    pub fn poke(&mut self) -> Result<(), JsError> {
        self.inner.poke().map_err(js_error)
    }

    /// Sets the note under the verdict.
    #[wasm_bindgen(js_name = setNote)]
    pub fn set_note(&mut self, note: &str) {
        self.inner.set_note(note);
    }

    /// Simulated time of run A, s.
    pub fn time(&self) -> f64 {
        self.inner.run(0).map_or(0.0, |r| r.closed_loop().time())
    }

    /// True once run A has diverged (it no longer advances until a reset or a change).
    #[wasm_bindgen(js_name = isFinished)]
    pub fn is_finished(&self) -> bool {
        self.inner.run(0).is_some_and(|r| r.closed_loop().is_finished())
    }

    // ------------------------------------------------------------------------ the timeline

    /// Looks at the kept sampling instant at or before `t` (s); at or past the newest state,
    /// shows that again. Advancing then replays the kept past; a change continues from there.
    #[wasm_bindgen(js_name = viewAt)]
    pub fn view_at(&mut self, t: f64) {
        self.inner.view_at(t);
    }

    /// Run `run`'s state as shown (at the instant looked at, or the newest): `{time, q, qdot, qd,
    /// error, torque, v, xf_hat, w}`.
    pub fn snapshot(&self, run: usize) -> Result<JsValue, JsError> {
        let s = self.inner.shown_snapshot(run).ok_or_else(|| JsError::new(&format!("no run {run}")))?;
        to_js(&s)
    }

    /// One sampling period back in the kept past.
    #[wasm_bindgen(js_name = stepBack)]
    pub fn step_back(&mut self) {
        self.inner.step_back();
    }

    /// Continues from the instant looked at (what followed becomes the ghost).
    #[wasm_bindgen(js_name = continueFromHere)]
    pub fn continue_from_here(&mut self) -> Result<(), JsError> {
        self.inner.continue_from_here().map_err(js_error)
    }

    /// Places run A's δ → 0 pair at re ± j im (1/s) with the twist feedback (its gains become the
    /// settings); throws the reason where no twist feedback in range reaches it.
    #[wasm_bindgen(js_name = placePair)]
    pub fn place_pair(&mut self, re: f64, im: f64) -> Result<(), JsError> {
        self.inner.place_pair(re, im).map_err(js_error)
    }

    /// Moves the pair's target by arrow-key steps (Re s across, Im s up).
    #[wasm_bindgen(js_name = nudgePair)]
    pub fn nudge_pair(&mut self, re_steps: i32, im_steps: i32) -> Result<(), JsError> {
        self.inner.nudge_pair(re_steps, im_steps).map_err(js_error)
    }

    /// Runs A at a sampling period picked on ρ(δ).
    #[wasm_bindgen(js_name = pickDelta)]
    pub fn pick_delta(&mut self, delta: f64) -> Result<(), JsError> {
        self.inner.pick_delta(delta).map_err(js_error)
    }

    /// Run A's traces as CSV, headed by the state string.
    pub fn csv(&self) -> String {
        self.inner.csv()
    }

    /// Run A's settings as a Python script (NumPy, SciPy) that rebuilds the linearized loop and
    /// prints ρ, its eigenvalues and A4 — what `flexarm export-python` writes — from the
    /// template the page fetched (`export/model_template.py`).
    #[wasm_bindgen(js_name = pythonScript)]
    pub fn python_script(&self, template: &str) -> Result<String, JsError> {
        self.inner.python_script(template).map_err(js_error)
    }

    /// The z-plane's view: "whole" (the whole unit circle) or "pair" (the default, around the
    /// flexible pair); zooming and panning are the renderer's (`zoomZ`, `panZ`).
    #[wasm_bindgen(js_name = zView)]
    pub fn z_view(&mut self, which: &str) -> Result<(), JsError> {
        let half = match which {
            "whole" => crate::view::panels::z_plane::view::WHOLE_HALF,
            "pair" => 0.0,
            _ => return Err(JsError::new(&format!("invalid z-plane view '{which}': expected whole or pair"))),
        };
        self.inner.set_z_view([0.0, 0.0], half).map_err(js_error)
    }

    /// What a downloaded file's name says of what it shows: "fig5.3", or "delta0.02-alpha5-pf-off".
    #[wasm_bindgen(js_name = fileLabel)]
    pub fn file_label(&self) -> String {
        self.inner.file_label()
    }

    /// The settings' state string (the classroom's `stateString` adds the lesson step).
    #[wasm_bindgen(js_name = stateString)]
    pub fn state_string(&self) -> String {
        self.inner.state_string()
    }

    /// `flexarm simulate …` reproducing run A up to now.
    #[wasm_bindgen(js_name = commandLine)]
    pub fn command_line(&self) -> String {
        self.inner.command_line()
    }

    /// Computes map rows for about `budget_ms` (at least one row); returns true if work remains.
    #[wasm_bindgen(js_name = workMaps)]
    pub fn work_maps(&mut self, budget_ms: f64) -> bool {
        let mut clock = now_ms;
        self.inner.maps_mut().work(&mut clock, budget_ms)
    }

    /// `{secondsPerSample, samplingPeriod, share, text}`: run A's controller timed on this
    /// computer — one sampling instant's prediction (k backward-Euler steps of the stabilized DAE,
    /// Newton in each) from the middle of the slew, the median of 7 batches of up to 400 by the
    /// page's clock (coarse in some browsers: a batch is long enough for it), ≈ 30 ms at most.
    /// The paper: "to be implementable, the numerical integration of the DAE has to be faster
    /// than real-time".
    #[wasm_bindgen(js_name = controllerTime)]
    pub fn controller_time(&self) -> Result<JsValue, JsError> {
        use crate::control::timing::{ControllerWorkload, TimingPlan};
        let mut workload = ControllerWorkload::new(&self.inner.settings().a.config()).map_err(js_error)?;
        let plan = TimingPlan { per_batch: 400, ..TimingPlan::default() };
        let t = workload.measure(&mut || now_ms() * 1e-3, plan).map_err(js_error)?;
        to_js(&ControllerTimeView {
            seconds_per_sample: t.seconds_per_sample,
            sampling_period: t.sampling_period,
            share: t.share(),
            text: crate::words::processor::processor(&t),
        })
    }

    /// `[{pf, ms, compute_ms}]`: how long each finished map took.
    #[wasm_bindgen(js_name = mapTimes)]
    pub fn map_times(&self) -> Result<JsValue, JsError> {
        to_js(self.inner.maps().times())
    }
}

/// Read-outs for the wasm-bindgen tests (`wasm-tests/`, which call them from Rust), not exported
/// to the page: the page needs none of them, and each export would keep in the module the
/// serialization it carries (the whole analysis report, the metrics).
impl WebSession {
    /// The session's status (the page asks the classroom's `status`, which carries it).
    pub fn status(&mut self) -> Result<JsValue, JsError> {
        self.inner.refresh();
        to_js(&self.inner.status())
    }

    /// A run's metrics: `{time, verdict, growth_rate, diverged_at, max_error_slew,
    /// max_error_after, rms_error, max_torque}`.
    pub fn metrics(&self, run: usize) -> Result<JsValue, JsError> {
        let r = self.run(run)?;
        let m = r.closed_loop().metrics();
        let diverged_at = match m.verdict {
            Verdict::Diverged { at, .. } => Some(at),
            _ => None,
        };
        to_js(&MetricsView {
            time: m.time,
            // The run's judgement, as its status says it (not the simulation's verdict alone).
            verdict: crate::session::run_status(if run == 0 { "A" } else { "B" }, r).verdict,
            growth_rate: m.growth_rate,
            diverged_at,
            max_error_slew: m.max_error_slew,
            max_error_after: m.max_error_after,
            rms_error: m.rms_error,
            max_torque: m.max_torque,
        })
    }

    /// The linear analysis of a run's settings: `{sampling_period, rest, spectral_radius,
    /// growth_rate, poles: [{discrete, continuous}], limit_pair_open, limit_pair}` (null if it
    /// failed).
    pub fn analysis(&self, run: usize) -> Result<JsValue, JsError> {
        to_js(&self.run(run)?.analysis().report())
    }

    /// One recorded column of a run as a typed array (`t`, `e1`, `torque2`, …).
    pub fn trace(&self, run: usize, key: &str) -> Result<js_sys::Float64Array, JsError> {
        let column = Column::from_key(key).ok_or_else(|| {
            let keys: Vec<&str> = Column::ALL.iter().map(|c| c.key()).collect();
            JsError::new(&format!("unknown trace '{key}': one of {}", keys.join(", ")))
        })?;
        Ok(js_sys::Float64Array::from(self.run(run)?.closed_loop().traces().column(column)))
    }

    /// ρ of a side's map so far, row-major by α (rows not computed yet are missing).
    pub fn map_values(&self, side: &str) -> Result<js_sys::Float64Array, JsError> {
        let side = MapSide::parse(side).map_err(|e| JsError::new(&e))?;
        let values = self.inner.maps().shown(side).map_or(&[][..], |e| e.job().values());
        Ok(js_sys::Float64Array::from(values))
    }

    /// The maps' δ values (columns), s.
    pub fn map_deltas(&self) -> js_sys::Float64Array {
        js_sys::Float64Array::from(self.inner.maps().grid().deltas().as_slice())
    }

    /// The maps' α values (rows), 1/s.
    pub fn map_alphas(&self) -> js_sys::Float64Array {
        js_sys::Float64Array::from(self.inner.maps().grid().alphas().as_slice())
    }

    /// The stable windows of δ for run A's settings: `{range, windows: [[from, to]], tolerance}`.
    pub fn windows(&mut self) -> Result<JsValue, JsError> {
        let w = self.inner.windows().map_err(js_error)?.clone();
        to_js(&w)
    }

    /// True while a shown map is unfinished (and the maps are enabled).
    pub fn maps_pending(&self) -> bool {
        self.inner.maps().pending()
    }
}
