//! What a user has open: the settings (one [`Settings`] value, read from and written to the state
//! string), run A and, when comparing, run B with their analyses, the two stability maps, and the
//! stable windows of δ. The page and the CLI meet here: the wasm binding wraps a [`Session`] and
//! converts; it decides nothing.
//!
//! Architecture invariant: no web types; every decision about which change restarts a run, which
//! settings change ρ or which map is needed is made here, not in the page.

mod changes;
pub mod controls;
pub mod data;
mod design;
mod design_cache;
mod figure_text;
pub mod file_name;
pub mod map_cache;
pub mod named;
pub mod presets;
pub mod python;
pub mod query;
pub mod run;
mod run_settings;
mod sensor_study;
mod sensor_study_job;
pub mod settings;
pub mod status;
pub mod timeline;
pub mod view;
mod zoom_caption;

use serde::Serialize;

use crate::analysis::{stable_windows, LinearSettings, StableWindows};
use crate::control::config::PreliminaryFeedbackChoice;
use crate::error::{Error, ParseError};
use crate::schema::{self, Kind, Scope, Value};

pub use controls::{display, ControlValue};
pub use map_cache::{MapSide, Maps};
pub use presets::{arm, preset, ArmPreset, Preset, ARMS, PRESETS};
pub use run::{AnalysisCache, Run, DEFAULT_TRACE_SECONDS, HISTORY_SECONDS};
pub use sensor_study_job::SensorStudyView;
pub use settings::{CompareSettings, Notice, RunSettings, Settings, Source, ViewSettings};
pub use status::{run_status, RunStatus};
pub use timeline::TimelineStatus;

/// The longest simulated time one `advance` call may cover, s: after a stalled tab the
/// simulation skips ahead instead of freezing the page to catch up.
pub const MAX_ADVANCE_PER_CALL: f64 = 0.25;

pub use crate::control::price::POKE;

/// Everything the page shows about the session, in words.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Status {
    /// Run A, then run B when comparing.
    pub runs: Vec<RunStatus>,
    /// Why the run restarted, or what a change waits for ("" if nothing to say).
    pub note: String,
    /// The preset the settings match ("" if none).
    pub preset: String,
    /// The arm preset the arm is ("" for an arm of its own).
    pub arm: String,
    /// What the page shows, in words: the preset's title, or run A's settings.
    pub showing: String,
    pub maps: map_cache::MapStatus,
    /// Run A's stable windows of δ (null until computed: `Session::refresh`).
    pub windows: Option<WindowsStatus>,
    /// What the faint ghost traces are ("" if there are none).
    pub ghost: String,
    /// The instant shown and the span that can be looked back at.
    pub timeline: TimelineStatus,
    /// The figure in words (the canvas' text alternative).
    pub figure: String,
    /// The zoom on one sampling instant in words (Fig. 2.1; "" when it is not shown).
    pub cycle: String,
    /// Run A's preliminary feedback as a design: its pair, its price (null without one).
    pub design: Option<crate::words::design::DesignStatus>,
    /// The explanation's live numbers for run A (null while its analysis is missing, or hidden
    /// in student mode).
    pub story: Option<crate::words::story::Story>,
}

/// What the classroom hides from the session's status and figures now
/// ([`crate::classroom::Classroom::follow`] decides; the session only obeys).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Hidden {
    /// Student mode: the verdict, ρ, the windows, the analysis' figures and the downloads that
    /// carry ρ wait for the student's answer.
    pub answers: bool,
    /// The lesson step hides the stable windows of δ until its answer.
    pub windows: bool,
}

/// The stable windows of δ for run A's settings, as the page shows them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WindowsStatus {
    /// "Without preliminary feedback (α = 2 1/s) the loop is stable only for …".
    pub text: String,
    /// The windows, s.
    pub windows: Vec<[f64; 2]>,
    /// The same as positions [from, to] along the δ slider (0–1).
    pub bands: Vec<[f64; 2]>,
}

/// The previous run of A, kept faint for comparison after a restart.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ghost {
    /// Its t, e1, e2 (the other columns empty).
    pub traces: crate::control::Traces,
    /// Which settings it had.
    pub settings: String,
}

/// The stable windows of δ for one set of linear settings (δ itself ignored), cached.
#[derive(Clone, Debug, Default)]
struct WindowsCache {
    key: Option<LinearSettings>,
    result: Option<Result<StableWindows, String>>,
}

/// A user's session: settings, runs, analyses, maps.
#[derive(Clone, Debug)]
pub struct Session {
    settings: Settings,
    a: Run,
    b: Option<Run>,
    maps: Maps,
    windows: WindowsCache,
    design: design_cache::DesignCache,
    ghost: Option<Ghost>,
    note: String,
    trace_seconds: f64,
    /// The kept instant looked at (None: the newest state).
    viewing: Option<f64>,
    /// What the classroom hides now.
    hidden: Hidden,
    /// The study of what bounds δ with run A's sensors, run a little at a time.
    sensor_study: sensor_study_job::StudyJob,
}

impl Session {
    /// A session with `settings`, both runs at rest.
    pub fn new(settings: Settings) -> Result<Self, Error> {
        let a = Run::new(settings.a)?;
        let b = settings.b.map(|b| Run::new(b.run(&settings.a))).transpose()?;
        let mut session = Self {
            settings,
            a,
            b,
            maps: Maps::default(),
            windows: WindowsCache::default(),
            design: design_cache::DesignCache::default(),
            ghost: None,
            note: String::new(),
            trace_seconds: DEFAULT_TRACE_SECONDS,
            viewing: None,
            hidden: Hidden::default(),
            sensor_study: sensor_study_job::StudyJob::default(),
        };
        session.maps.show(&session.linear_settings());
        session.maps.enabled = settings.view.shown().map;
        Ok(session)
    }

    /// The page's session for a URL query: the page's start settings with the query read over
    /// them (the tab a panel it names is on). Bad values become notices; settings that cannot run
    /// together fall back to the start. The lesson, a teacher's file and the link's moment it may
    /// name are the classroom's ([`crate::classroom::Classroom::open`]).
    pub fn open(query: &str) -> (Self, Vec<Notice>) {
        let mut settings = Settings::page_start();
        let mut notices = settings.read(query, Source::Page).unwrap_or_default();
        if let Some(tab) = named::tab_named_in(query, &settings.view) {
            settings.view.tab = tab;
        }
        let session = match Self::new(settings) {
            Ok(s) => s,
            Err(e) => {
                notices.push(Notice { key: "state".into(), text: format!("{e}; using the defaults") });
                Self::new(Settings::page_start()).unwrap_or_else(|e| panic!("the page's start settings are valid: {e}"))
            }
        };
        (session, notices)
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Run A (0) or run B (1, when comparing).
    pub fn run(&self, index: usize) -> Option<&Run> {
        match index {
            0 => Some(&self.a),
            1 => self.b.as_ref(),
            _ => None,
        }
    }

    /// The runs shown: A, then B when comparing.
    pub fn runs(&self) -> impl Iterator<Item = &Run> {
        std::iter::once(&self.a).chain(self.b.as_ref())
    }

    fn runs_mut(&mut self) -> impl Iterator<Item = &mut Run> {
        std::iter::once(&mut self.a).chain(self.b.as_mut())
    }

    /// What a downloaded file's name says of what it shows: the preset ("fig5.3"), else run A's
    /// key settings ("delta0.02-alpha5-pf-off"): a teacher's figures no longer share one name.
    pub fn file_label(&self) -> String {
        match self.preset() {
            Some(p) => file_name::file_slug(p.id),
            None => self.settings.file_label(),
        }
    }

    /// The preset the settings match, if any.
    pub fn preset(&self) -> Option<&'static Preset> {
        PRESETS.iter().find(|p| self.settings.matches(p))
    }

    /// What the last change did to the runs ("" if nothing to say).
    pub fn note(&self) -> &str {
        &self.note
    }

    /// Run A's settings as the linear analysis sees them, at the rest point it linearizes at now.
    fn linear_settings(&self) -> LinearSettings {
        let config = self.settings.a.config();
        let q2 = self.settings.a.rest.angles(&config, self.a.closed_loop().time())[1];
        LinearSettings::of(&config, Some(q2))
    }

    // ----------------------------------------------------------------------------------- time

    /// Advances both runs by `wall_seconds × speed` of simulated time (at most
    /// [`MAX_ADVANCE_PER_CALL`]); returns the simulated time run A covered.
    pub fn advance(&mut self, wall_seconds: f64) -> Result<f64, Error> {
        if !(wall_seconds.is_finite() && wall_seconds >= 0.0) {
            return Err(Error::InvalidDuration(wall_seconds));
        }
        let dt = (wall_seconds * self.settings.speed).min(MAX_ADVANCE_PER_CALL);
        if let Some(covered) = self.replay(dt) {
            return Ok(covered);
        }
        let before = self.a.closed_loop().time();
        let keep = self.trace_seconds;
        let mut moved = false;
        for run in self.runs_mut() {
            moved |= run.advance(dt, keep)?;
        }
        if moved {
            // The analysis follows the arm to its other rest point: so do the maps.
            self.maps.show(&self.linear_settings());
        }
        Ok(self.a.closed_loop().time() - before)
    }

    /// Advances to A's next sampling instant; B follows A's clock (or its own period if A stopped).
    pub fn step_period(&mut self) {
        if self.step_forward_in_history() {
            return;
        }
        let keep = self.trace_seconds;
        let mut moved = self.a.step_period(keep);
        let t = self.a.closed_loop().time();
        let a_finished = self.a.closed_loop().is_finished();
        if let Some(b) = self.b.as_mut() {
            let dt = t - b.closed_loop().time();
            if dt > 1e-12 {
                moved |= b.advance(dt, keep).unwrap_or(false);
            } else if a_finished {
                moved |= b.step_period(keep);
            }
        }
        if moved {
            self.maps.show(&self.linear_settings());
        }
        if self.note.starts_with("Paused") {
            self.note.clear();
        }
    }

    /// Keeps run A's traces (t, e1, e2) as the ghost, if it has run for a while.
    fn keep_ghost(&mut self) {
        use crate::control::{Column, Traces};
        let sim = self.a.closed_loop();
        if sim.time() < 0.5 {
            return;
        }
        let t = sim.traces();
        let traces = Traces::from_columns([Column::T, Column::E1, Column::E2].map(|c| (c, t.column(c).to_vec())));
        self.ghost = Some(Ghost { traces, settings: crate::words::settings::run(&self.a.settings().config()) });
    }

    /// The previous run of A, drawn faint (None until a run restarted).
    pub fn ghost(&self) -> Option<&Ghost> {
        self.ghost.as_ref()
    }

    /// Both runs back to rest.
    pub fn reset(&mut self) -> Result<(), Error> {
        self.viewing = None;
        self.keep_ghost();
        for run in self.runs_mut() {
            run.reset()?;
        }
        self.maps.show(&self.linear_settings());
        self.note.clear();
        Ok(())
    }

    /// A short torque kick on both runs ([`POKE`]).
    pub fn poke(&mut self) -> Result<(), Error> {
        self.continue_from_here()?;
        let (torque, duration) = POKE;
        for run in self.runs_mut() {
            run.poke(torque, duration)?;
        }
        Ok(())
    }

    /// Seconds of traces kept per run.
    pub fn set_trace_seconds(&mut self, seconds: f64) -> Result<(), Error> {
        if !(seconds.is_finite() && seconds > 0.0 && seconds <= 3600.0) {
            return Err(Error::InvalidDuration(seconds));
        }
        self.trace_seconds = seconds;
        Ok(())
    }

    /// Sets the note shown under the verdict (e.g. while paused).
    pub fn set_note(&mut self, note: &str) {
        self.note = note.to_string();
    }

    // ---------------------------------------------------------------------------- analysis

    /// The stability maps.
    pub fn maps(&self) -> &Maps {
        &self.maps
    }

    pub fn maps_mut(&mut self) -> &mut Maps {
        &mut self.maps
    }

    /// The stable windows of δ over the δ control's span for run A's settings (everything but δ),
    /// computed on first use after a change that matters.
    pub fn windows(&mut self) -> Result<&StableWindows, Error> {
        let key = self.linear_settings().at(0.0, self.settings.a.alpha);
        if self.windows.key != Some(key) {
            let range = schema::DELTA.number().expect("δ is a number").control;
            let result = stable_windows(&self.linear_settings(), range).map_err(|e| e.to_string());
            self.windows = WindowsCache { key: Some(key), result: Some(result) };
        }
        match self.windows.result.as_ref().expect("just computed") {
            Ok(w) => Ok(w),
            Err(e) => Err(Error::Parse(ParseError { key: "windows".into(), text: String::new(), expected: e.clone() })),
        }
    }

    /// Brings what is computed on demand up to date: the stable windows of δ (about 240 ρ, a few
    /// milliseconds; call it a few times a second, not per slider event).
    pub fn refresh(&mut self) {
        let _ = self.windows();
        self.refresh_design();
    }

    /// The stable windows as last computed for the current settings (None if stale or failed,
    /// or while the classroom hides them until an answer).
    pub fn cached_windows(&self) -> Option<&StableWindows> {
        if self.hidden.windows || self.hidden.answers {
            return None;
        }
        let key = self.linear_settings().at(0.0, self.settings.a.alpha);
        match (&self.windows.key, &self.windows.result) {
            (Some(k), Some(Ok(w))) if *k == key => Some(w),
            _ => None,
        }
    }

    fn windows_status(&self) -> Option<WindowsStatus> {
        let w = self.cached_windows()?;
        let a = self.settings.a;
        let spec = schema::DELTA.number().expect("δ is a number");
        Some(WindowsStatus {
            text: crate::words::settings::windows_sentence(a.pf, a.alpha, w),
            windows: w.windows.clone(),
            bands: w.windows.iter().map(|[lo, hi]| [spec.position(*lo), spec.position(*hi)]).collect(),
        })
    }

    /// The status of both runs, in words.
    pub fn status(&self) -> Status {
        // Looking back, the caption computes the sweep again: once for both texts.
        let cycle = self.cycle_caption();
        let mut runs = vec![run_status("A", &self.a)];
        if let Some(b) = &self.b {
            runs.push(run_status("B", b));
        }
        let hidden = self.answers_hidden();
        if hidden {
            runs.iter_mut().for_each(status::hide_answers);
        }
        if self.viewing.is_some() {
            // The readouts of the moment looked at; the verdict and the maxima are the run's.
            for (i, r) in runs.iter_mut().enumerate() {
                if let Some(s) = self.shown_snapshot(i) {
                    r.readouts.time = format!("{:.2} s (looking back)", s.time);
                    r.readouts.error = crate::words::settings::errors(s.error);
                }
            }
        }
        Status {
            runs,
            note: self.note.clone(),
            preset: self.preset().map_or(String::new(), |p| p.id.to_string()),
            arm: self.settings.arm_preset().map_or(String::new(), |p| p.id.to_string()),
            showing: self.preset().map_or_else(
                || format!("your settings — {}", crate::words::settings::run(&self.a.settings().config())),
                // A preset names the paper's figure; the paper slews once.
                |p| {
                    let repeating =
                        if self.settings.a.repeat { " — the slew repeating (the paper's slews once)" } else { "" };
                    // Student mode: the figure's settings, not what it shows.
                    format!("{}{repeating}", if hidden { p.settings_title } else { p.title })
                },
            ),
            maps: map_cache::MapStatus {
                // Hidden in student mode: the maps say where ρ < 1.
                shown: self.maps.status().shown && !hidden,
                title: {
                    let design = self.settings.a.pf == PreliminaryFeedbackChoice::Twist;
                    match (self.settings.view.measure, design) {
                        (crate::plot::color::Measure::Rho, false) => "Stability maps ρ(δ, α)".into(),
                        (crate::plot::color::Measure::Rate, false) => "Stability maps: ln ρ/δ over (δ, α), 1/s".into(),
                        (crate::plot::color::Measure::Rho, true) => {
                            "Stability maps ρ(δ, α) without Kₚᵣ, and the design map ρ(δ, k_d) of your damper".into()
                        }
                        (crate::plot::color::Measure::Rate, true) => {
                            "Stability maps: ln ρ/δ (1/s) over (δ, α) without Kₚᵣ, and over (δ, k_d) for your damper"
                                .into()
                        }
                    }
                },
                ..self.maps.status()
            },
            windows: self.windows_status(),
            ghost: self
                .ghost
                .as_ref()
                .map_or(String::new(), |g| format!("faint grey: the previous run ({})", g.settings)),
            timeline: self.timeline(),
            figure: match cycle.as_str() {
                "" => self.figure_text(),
                c => format!("{} The time plots are zoomed on one sampling instant. {c}", self.figure_text()),
            },
            cycle,
            design: self.design_status(),
            story: if hidden {
                None
            } else {
                // The settings' configuration, as the analysis: a change reaches the loop only at its
                // next sampling instant.
                let config = self.a.settings().config();
                let analysis = self.a.analysis();
                analysis.report().map(|report| {
                    let words = analysis
                        .structure()
                        .map(|s| crate::words::structure::structure(s, config.preliminary_feedback));
                    crate::words::story::story(&config, report).with_structure(words)
                })
            },
        }
    }

    // ------------------------------------------------------------------------------ export

    /// The state string of the settings (the page's URL query, but for the lesson step the
    /// classroom adds).
    pub fn state_string(&self) -> String {
        self.settings.to_query()
    }

    // ------------------------------------------------------------------------ the classroom's

    /// What the classroom hides now (student mode, a lesson step hiding the windows).
    pub fn set_hidden(&mut self, hidden: Hidden) {
        self.hidden = hidden;
    }

    /// A lesson step hides the stable windows until its answer (`hide: windows`).
    pub fn windows_hidden(&self) -> bool {
        self.hidden.windows
    }

    /// The answers are hidden now (student mode): the verdict, ρ, the analysis' figures.
    pub fn answers_hidden(&self) -> bool {
        self.hidden.answers
    }

    /// The figures drawn: while the answers are hidden, only those that show the run itself (the
    /// arm, the errors, the torques, the zoom on one instant) — not the analysis' (the pole plot,
    /// ρ(δ), the maps, log |e| with its slope and the swing's split, the swing's shape).
    pub fn drawn_view(&self) -> ViewSettings {
        let v = self.settings.view.shown();
        if self.hidden.answers {
            ViewSettings { poles: false, rho: false, map: false, log: false, swing: false, answers_hidden: true, ..v }
        } else {
            ViewSettings { answers_hidden: false, ..v }
        }
    }

    /// Makes `next` the settings (see the changes' rules): a lesson step's, applied whole;
    /// `restart` runs from rest; `why` is the note.
    pub fn apply_settings(&mut self, next: Settings, restart: bool, why: &str) -> Result<(), Error> {
        self.apply(next, restart, why)
    }

    /// Forgets the faint previous run (a lesson step starts clean).
    pub fn forget_ghost(&mut self) {
        self.ghost = None;
    }

    /// The moment a link named (`t=3&paused=1`), taken once.
    pub fn take_start(&mut self) -> settings::Start {
        std::mem::take(&mut self.settings.start)
    }

    /// The student lifted student mode outside a lesson ("Show them"): the link's `answers=hidden`
    /// no longer holds.
    pub fn lift_student_mode(&mut self) {
        self.settings.view.answers_hidden = false;
    }

    /// Student mode back on, as the link's `answers=hidden` sets it: for a lesson this browser
    /// kept it for ([`crate::classroom::Classroom::keep_student_mode`]).
    pub fn keep_student_mode(&mut self) {
        self.settings.view.answers_hidden = true;
    }

    /// `flexarm simulate …` reproducing run A up to its current time.
    pub fn command_line(&self) -> String {
        self.settings.command_line(Some(self.a.closed_loop().time()))
    }

    /// Run A's traces as CSV, headed by its state string.
    pub fn csv(&self) -> String {
        let comment = format!("flexarm state: {} | {}", self.settings.run_query(), self.settings.command_line(None));
        self.a.closed_loop().traces().to_csv(Some(&comment))
    }
}

fn not_a_setting(key: &str) -> Error {
    Error::Parse(ParseError { key: key.into(), text: String::new(), expected: "a setting of the page".into() })
}
