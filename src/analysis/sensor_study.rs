//! What bounds δ from below with these sensors (issue 36), as facts: for each δ of a list, the
//! simulated slew with the settings' sensors and with perfect ones ([`crate::control::sensor_sweep`]),
//! the linear prediction of the noise ([`super::noise`]); the δ where the tracking error during
//! the slew is smallest, and what the numbers on either side of it show. Values, never English.

use super::noise::{noise_floor, NoiseFloor};
use super::sampled::{LinearSettings, LoopModel};
use crate::control::config::SimulationConfig;
use crate::control::sensor_sweep::{SensorSweep, SweepPoint};

/// The sampling periods studied, s: the slider's lower end to past the paper's largest working δ
/// with K_pr (0.08 s at α = 2), roughly evenly on a log scale.
pub const STUDY_DELTAS: [f64; 11] = [0.002, 0.003, 0.005, 0.007, 0.01, 0.015, 0.02, 0.03, 0.05, 0.07, 0.1];

/// One δ of the study.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct StudyRow {
    pub sampling_period: f64,
    /// The run with the settings' sensors (None until simulated).
    pub real: Option<SweepPoint>,
    /// The run with perfect sensors and no torque limit.
    pub ideal: Option<SweepPoint>,
    /// The linear prediction of the noise (None where the digital loop is unstable or the
    /// sensors read exactly).
    pub predicted: Option<NoiseFloor>,
    /// ρ of the settings' loop at this δ (the digital loop's with sensors on), None if the
    /// analysis failed. ρ ≥ 1: the errors grow in the long run, even where a short run has not
    /// diverged yet — such a row is never the best.
    pub spectral_radius: Option<f64>,
    /// ρ of the paper's loop at this δ — the same settings with exact readings, what the
    /// controller computes applied continuously — None if that analysis failed: what the
    /// perfect-sensors column runs.
    pub ideal_spectral_radius: Option<f64>,
}

impl StudyRow {
    /// True where ρ says the loop is unstable (ρ ≥ 1).
    pub fn unstable(&self) -> bool {
        self.spectral_radius.is_some_and(|r| r >= 1.0)
    }

    /// True where the run with the settings' sensors diverged.
    pub fn diverged(&self) -> bool {
        self.real.is_some_and(|p| p.diverged)
    }

    /// The study's quantities at this δ, each None until its run is in or where that run
    /// diverged (its figures stop there and describe no slew and no rest): what the table
    /// prints and the panels draw, from one place.
    /// max |e1|, |e2| during the slew with the settings' sensors, rad.
    pub fn slew_error(&self) -> Option<f64> {
        simulated(self.real, tracking_error)
    }

    /// The same with perfect sensors and no torque limit, rad.
    pub fn ideal_slew_error(&self) -> Option<f64> {
        simulated(self.ideal, tracking_error)
    }

    /// RMS e at rest (the larger link's), rad.
    pub fn rest_error(&self) -> Option<f64> {
        simulated(self.real, |p| p.rms_error_rest[0].max(p.rms_error_rest[1]))
    }

    /// T1's RMS about its mean at rest, N m.
    pub fn torque_noise(&self) -> Option<f64> {
        simulated(self.real, |p| p.torque_fluctuation_rest[0])
    }

    /// The same with perfect sensors, N m.
    pub fn ideal_torque_noise(&self) -> Option<f64> {
        simulated(self.ideal, |p| p.torque_fluctuation_rest[0])
    }

    /// max |T1|, N m.
    pub fn peak_torque(&self) -> Option<f64> {
        simulated(self.real, |p| p.max_torque[0])
    }

    /// The share of the time either motor sat at its limit, 0 … 1.
    pub fn saturated(&self) -> Option<f64> {
        simulated(self.real, |p| p.saturated[0].max(p.saturated[1]))
    }

    /// The linear prediction's RMS error (the larger link's), rad.
    pub fn predicted_error(&self) -> Option<f64> {
        self.predicted.map(|f| f.rms_error[0].max(f.rms_error[1]))
    }

    /// The linear prediction's RMS of T1, N m.
    pub fn predicted_torque(&self) -> Option<f64> {
        self.predicted.map(|f| f.rms_torque[0])
    }
}

/// A run's figure, None until the run is in or where it diverged.
fn simulated(p: Option<SweepPoint>, f: fn(&SweepPoint) -> f64) -> Option<f64> {
    p.filter(|p| !p.diverged).map(|p| f(&p)).filter(|v| v.is_finite())
}

/// What the linear analysis says at one δ of the study: computed once per study.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LinearRow {
    pub spectral_radius: Option<f64>,
    pub predicted: Option<NoiseFloor>,
    /// The paper's loop (perfect sensors).
    pub ideal_spectral_radius: Option<f64>,
}

/// Where the tracking error is smallest, once every run is in.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Best {
    /// Runs are still to come.
    Pending,
    /// A best δ exists: the smallest δ of the list tracks markedly worse (by over
    /// [`MARKEDLY_WORSE`]) than the δ at `index`, and so do the larger ones.
    Inside { index: usize },
    /// The least error is at `index`, and down to the smallest δ of the list the error stays
    /// within [`MARKEDLY_WORSE`] of it: no best δ inside the list.
    Smallest { index: usize },
    /// The largest δ tracks best (the sensors' error outweighs the sampling everywhere).
    Largest,
    /// No δ studied tracks: at every one ρ ≥ 1 or the run diverges.
    Nowhere,
}

/// The smallest δ tracks "markedly worse" than the best when its error exceeds the least by this
/// factor: below it the differences are of the order of how the errors vary from one δ to the
/// next (the friction's stick and slip, where a joint stops), not a trend.
pub const MARKEDLY_WORSE: f64 = 1.25;

/// The whole study.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SensorStudy {
    pub rows: Vec<StudyRow>,
    pub best: Best,
    /// The smallest δ's tracking error over the least of all (≥ 1; None until done or where
    /// the smallest δ diverged, which makes a best δ above it): what sampling as fast as the list
    /// goes costs.
    pub smallest_excess: Option<f64>,
    /// The share of the runs done, 0 … 1.
    pub progress: f64,
}

impl SensorStudy {
    /// ρ and the linear prediction for `config`'s sensors at each δ of `deltas` (the prediction
    /// None where there is none: sensors off, or an unstable loop). Computed once per study, not
    /// per look at it.
    pub fn linear(config: &SimulationConfig, deltas: &[f64]) -> Vec<LinearRow> {
        let Ok(model) = LoopModel::new(&LinearSettings::of(config, None)) else {
            return vec![LinearRow::default(); deltas.len()];
        };
        let digital = config.sensors.is_digital();
        let ideal = SimulationConfig { sensors: Default::default(), ..*config };
        let paper = if digital { LoopModel::new(&LinearSettings::of(&ideal, None)).ok() } else { None };
        deltas
            .iter()
            .map(|&d| {
                let spectral_radius = model.spectral_radius(d).ok();
                LinearRow {
                    spectral_radius,
                    predicted: digital.then(|| noise_floor(&model, d, &config.sensors).ok()).flatten(),
                    ideal_spectral_radius: paper.as_ref().map_or(spectral_radius, |m| m.spectral_radius(d).ok()),
                }
            })
            .collect()
    }

    /// The facts of `sweep` so far, with `linear` ([`Self::linear`]) at each of its δ.
    pub fn of(sweep: &SensorSweep, linear: &[LinearRow]) -> Self {
        let rows: Vec<StudyRow> = sweep
            .deltas()
            .iter()
            .enumerate()
            .map(|(i, &d)| StudyRow {
                sampling_period: d,
                real: sweep.real.get(i).copied(),
                ideal: sweep.ideal.get(i).copied(),
                predicted: linear.get(i).and_then(|l| l.predicted),
                spectral_radius: linear.get(i).and_then(|l| l.spectral_radius),
                ideal_spectral_radius: linear.get(i).and_then(|l| l.ideal_spectral_radius),
            })
            .collect();
        let (best, smallest_excess) = match sweep.is_done() {
            false => (Best::Pending, None),
            true => best_of(&rows),
        };
        Self { rows, best, smallest_excess, progress: sweep.progress() }
    }

    /// The row of the best δ, if one exists inside the list.
    pub fn best_row(&self) -> Option<&StudyRow> {
        match self.best {
            Best::Inside { index } => self.rows.get(index),
            _ => None,
        }
    }
}

/// The error a row is judged by: its run's [`tracking_error`], ∞ where ρ ≥ 1 (unstable in the
/// long run whatever the short run showed) or not yet simulated.
pub fn judged_error(r: &StudyRow) -> f64 {
    match r.real {
        Some(p) if !r.unstable() => tracking_error(&p),
        _ => f64::INFINITY,
    }
}

/// The tracking error during the slew that the study minimizes: max |e1|, |e2| while the
/// reference moves (∞ for a run that diverged), rad.
pub fn tracking_error(p: &SweepPoint) -> f64 {
    if p.diverged {
        f64::INFINITY
    } else {
        p.max_error_slew[0].max(p.max_error_slew[1])
    }
}

fn best_of(rows: &[StudyRow]) -> (Best, Option<f64>) {
    let errors: Vec<f64> = rows.iter().map(judged_error).collect();
    let Some((index, &least)) = errors.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)) else {
        return (Best::Pending, None);
    };
    if !least.is_finite() {
        // Every row unstable or diverged: nothing tracks.
        return (Best::Nowhere, None);
    }
    let excess = (errors[0].is_finite() && least > 0.0).then(|| errors[0] / least);
    // A smallest δ that diverges is as markedly worse as can be.
    let worse = excess.is_some_and(|x| x > MARKEDLY_WORSE) || (index > 0 && errors[0].is_infinite());
    let best = if index + 1 == rows.len() && index > 0 {
        Best::Largest
    } else if worse {
        Best::Inside { index }
    } else {
        Best::Smallest { index }
    };
    (best, excess)
}
