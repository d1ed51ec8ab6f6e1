//! The simulated side of "what bounds δ from below on a real arm" (issue 36): the slew run at a
//! series of sampling periods, each twice — with the sensors and torque limit of the settings,
//! and with the paper's perfect robot —, one run per call so that a page can show the curve
//! growing. The linear prediction of the same noise is `analysis::noise`; this module only
//! simulates (the analysis never runs the nonlinear simulation).

use super::batch::simulate;
use super::config::SimulationConfig;
use super::metrics::Metrics;
use super::sensing::SensorModel;
use crate::error::Error;

/// Seconds simulated per point: the 1-s slew and 2 s of rest after it, where the error floor
/// and the torque's noise are measured.
pub const SWEEP_SECONDS: f64 = 3.0;

/// What one run says about a sampling period.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct SweepPoint {
    /// δ, s.
    pub sampling_period: f64,
    /// max |e1|, |e2| while the reference moves, rad.
    pub max_error_slew: [f64; 2],
    /// RMS e1, e2 at rest after the slew, rad.
    pub rms_error_rest: [f64; 2],
    /// The standard deviation of T1, T2 at rest after the slew, N m.
    pub torque_fluctuation_rest: [f64; 2],
    /// max |T1|, |T2|, N m.
    pub max_torque: [f64; 2],
    /// The share of the time T1, T2 sat at the limit.
    pub saturated: [f64; 2],
    /// The run diverged (its figures are up to then).
    pub diverged: bool,
}

impl SweepPoint {
    fn of(delta: f64, m: &Metrics) -> Self {
        Self {
            sampling_period: delta,
            max_error_slew: m.max_error_slew,
            rms_error_rest: m.rms_error_rest,
            torque_fluctuation_rest: m.torque_fluctuation_rest,
            max_torque: m.max_torque,
            saturated: m.saturated,
            diverged: matches!(m.verdict, super::metrics::Verdict::Diverged { .. }),
        }
    }
}

/// The slew at each δ of a list, with the settings' sensors and with perfect ones.
#[derive(Clone, Debug)]
pub struct SensorSweep {
    config: SimulationConfig,
    deltas: Vec<f64>,
    /// Runs with the settings' sensors, in the order of `deltas`.
    pub real: Vec<SweepPoint>,
    /// Runs with the paper's perfect robot.
    pub ideal: Vec<SweepPoint>,
}

impl SensorSweep {
    /// A sweep of `config` over `deltas` (s), nothing run yet. Each point is the paper's single
    /// slew and the rest after it, whether or not `config` repeats the slew.
    pub fn new(mut config: SimulationConfig, deltas: &[f64]) -> Result<Self, Error> {
        config.reference.repeat_hold = None;
        for &d in deltas {
            let mut c = config;
            c.controller.sampling_period = d;
            c.validate()?;
        }
        Ok(Self { config, deltas: deltas.to_vec(), real: Vec::new(), ideal: Vec::new() })
    }

    /// The sampling periods, s.
    pub fn deltas(&self) -> &[f64] {
        &self.deltas
    }

    /// True once every δ has both runs.
    pub fn is_done(&self) -> bool {
        self.real.len() == self.deltas.len() && self.ideal.len() == self.deltas.len()
    }

    /// The share done, 0 … 1.
    pub fn progress(&self) -> f64 {
        (self.real.len() + self.ideal.len()) as f64 / (2 * self.deltas.len()).max(1) as f64
    }

    /// Runs the next run (the real sensors' first at each δ, then the ideal's). False when done.
    pub fn step(&mut self) -> Result<bool, Error> {
        let (i, sensors) = if self.real.len() <= self.ideal.len() && self.real.len() < self.deltas.len() {
            (self.real.len(), self.config.sensors)
        } else if self.ideal.len() < self.deltas.len() {
            (self.ideal.len(), SensorModel::default())
        } else {
            return Ok(false);
        };
        let mut c = self.config;
        c.controller.sampling_period = self.deltas[i];
        c.sensors = sensors;
        let point = SweepPoint::of(self.deltas[i], &simulate(&c, SWEEP_SECONDS)?.metrics);
        if sensors == self.config.sensors && self.real.len() == i {
            self.real.push(point);
            // The perfect robot's run is the same run where the settings have no sensors.
            if sensors == SensorModel::default() {
                self.ideal.push(point);
            }
        } else {
            self.ideal.push(point);
        }
        Ok(true)
    }

    /// Runs everything left.
    pub fn finish(&mut self) -> Result<(), Error> {
        while self.step()? {}
        Ok(())
    }
}
