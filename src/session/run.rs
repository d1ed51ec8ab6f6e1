//! One run of the page (A or B): the closed loop, its settings, and the linear analysis of those
//! settings, computed once per change that matters.

use crate::analysis::noise::unit_noise_floor;
use crate::analysis::{analyze, LinearSettings, LoopModel, NoiseFloor, StabilityReport};
use crate::control::config::SimulationConfig;
use crate::control::ClosedLoop;
use crate::error::Error;

use super::settings::RunSettings;

/// The analysis of one configuration, recomputed only when its [`LinearSettings`] change.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AnalysisCache {
    key: Option<LinearSettings>,
    result: Option<Result<StabilityReport, String>>,
    /// Section 3's structure of the same settings, computed on first use after a change (a few ms:
    /// a drag of δ pays for it at most once per status, not once per move).
    structure: std::cell::OnceCell<Option<crate::analysis::structure::Structure>>,
    /// The digital loop's noise floor for an angle error of 1 rad RMS (None: sensors off or no
    /// floor), on first use after a change: the encoder and the noise only scale it.
    unit_floor: std::cell::OnceCell<Option<NoiseFloor>>,
}

impl AnalysisCache {
    /// Makes the cache describe `config` linearized at rest at link-2 angle `q2`; returns true if
    /// it had to recompute.
    pub fn update(&mut self, config: &SimulationConfig, q2: f64) -> bool {
        let key = LinearSettings::of(config, Some(q2));
        if self.key == Some(key) {
            return false;
        }
        self.key = Some(key);
        self.result = Some(analyze(config, Some(q2)).map_err(|e| e.to_string()));
        self.structure = std::cell::OnceCell::new();
        self.unit_floor = std::cell::OnceCell::new();
        true
    }

    /// The noise floor of the digital loop at the analysed δ for an angle error of 1 rad RMS
    /// (None with the sensors off, before the first update, or where the loop is unstable).
    pub fn unit_floor(&self) -> Option<&NoiseFloor> {
        let key = self.key.as_ref()?;
        self.unit_floor
            .get_or_init(|| {
                let velocity = key.sensing?;
                let model = LoopModel::new(key).ok()?;
                unit_noise_floor(&model, key.controller.sampling_period, velocity).ok()
            })
            .as_ref()
    }

    /// Section 3's structure of these settings (None before the first update, or where the
    /// linearized DAE has none).
    pub fn structure(&self) -> Option<&crate::analysis::structure::Structure> {
        let key = self.key.as_ref()?;
        self.structure.get_or_init(|| crate::analysis::structure::Structure::new(key).ok()).as_ref()
    }

    /// What the analysis was computed for (None before the first update).
    pub fn settings(&self) -> Option<&LinearSettings> {
        self.key.as_ref()
    }

    /// The analysis, if it succeeded.
    pub fn report(&self) -> Option<&StabilityReport> {
        self.result.as_ref().and_then(|r| r.as_ref().ok())
    }

    /// Why the analysis failed, if it did.
    pub fn error(&self) -> Option<&str> {
        self.result.as_ref().and_then(|r| r.as_ref().err()).map(String::as_str)
    }
}

/// Seconds of traces a page run keeps for drawing and export.
pub const DEFAULT_TRACE_SECONDS: f64 = 60.0;

/// Seconds of the past a page run can be looked at and continued from (every sampling instant).
pub const HISTORY_SECONDS: f64 = 30.0;

/// A run: the loop, the settings it runs with, their analysis.
#[derive(Clone, Debug)]
pub struct Run {
    sim: ClosedLoop,
    settings: RunSettings,
    analysis: AnalysisCache,
}

impl Run {
    /// A run at rest on the reference.
    pub fn new(settings: RunSettings) -> Result<Self, Error> {
        let mut sim = ClosedLoop::new(settings.config())?;
        sim.keep_history(HISTORY_SECONDS);
        // Fig. 2.1 on the page shows the controller's own newest prediction.
        sim.keep_sweep(true);
        let mut run = Self { sim, settings, analysis: AnalysisCache::default() };
        run.follow_rest(&settings.config());
        Ok(run)
    }

    /// Brings the analysis to `config` at the rest point the settings choose at the run's present
    /// time; true if it changed.
    fn follow_rest(&mut self, config: &SimulationConfig) -> bool {
        let q2 = self.settings.rest.angles(config, self.sim.time())[1];
        self.analysis.update(config, q2)
    }

    pub fn closed_loop(&self) -> &ClosedLoop {
        &self.sim
    }

    pub fn settings(&self) -> &RunSettings {
        &self.settings
    }

    /// The linear analysis of the settings (those on screen: a change is analysed at once,
    /// though the loop takes it at its next sampling instant), at the rest point they choose.
    pub fn analysis(&self) -> &AnalysisCache {
        &self.analysis
    }

    /// Takes new settings: live at the next sampling instant, or from rest when `restart` (or
    /// when the run has diverged and cannot go on). Returns true if the run restarted.
    pub fn change(&mut self, settings: RunSettings, restart: bool) -> Result<bool, Error> {
        let config = settings.config();
        self.sim.set_config(config)?;
        self.settings = settings;
        let restarted = restart || self.sim.is_finished();
        if restarted {
            self.sim.reset()?;
        }
        self.follow_rest(&config);
        Ok(restarted)
    }

    /// Continues from the kept sampling instant at or before `t`, with the settings in force
    /// then; returns the instant.
    pub fn branch_at(&mut self, t: f64) -> Result<f64, Error> {
        let at = self.sim.branch_at(t)?;
        // The rest point of the analysis is not part of the loop's state: it stays as chosen.
        self.settings = RunSettings { rest: self.settings.rest, ..RunSettings::of_config(self.sim.config()) };
        let config = *self.sim.config();
        self.follow_rest(&config);
        Ok(at)
    }

    /// Back to rest with the current settings.
    pub fn reset(&mut self) -> Result<(), Error> {
        self.sim.reset()?;
        self.follow_rest(&self.settings.config());
        Ok(())
    }

    /// Advances by `dt` simulated seconds, keeping `trace_seconds` of traces. True if the
    /// analysis moved to another rest point (the arm began a slew to the other end).
    pub fn advance(&mut self, dt: f64, trace_seconds: f64) -> Result<bool, Error> {
        self.sim.advance(dt)?;
        self.bound_traces(trace_seconds);
        Ok(self.follow_rest(&self.settings.config()))
    }

    /// Advances to the next sampling instant; true if the analysis moved to another rest point.
    pub fn step_period(&mut self, trace_seconds: f64) -> bool {
        self.sim.advance_one_period();
        // The instant reached is kept and predicted at once (Fig. 2.1 shows it).
        self.sim.sample_now();
        self.bound_traces(trace_seconds);
        self.follow_rest(&self.settings.config())
    }

    /// Adds a torque (T1, T2 in N m) for `duration` seconds.
    pub fn poke(&mut self, torque: [f64; 2], duration: f64) -> Result<(), Error> {
        self.sim.apply_disturbance(torque, duration)
    }

    fn bound_traces(&mut self, seconds: f64) {
        let keep = (seconds / self.sim.config().output_interval).ceil() as usize + 1;
        let traces = self.sim.traces_mut();
        // Trim in chunks so the cost is amortised rather than paid every frame.
        if traces.len() > keep + keep / 8 {
            traces.truncate_front(keep);
        }
    }
}
