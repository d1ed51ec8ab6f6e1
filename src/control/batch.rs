//! Whole runs of the closed loop at once: [`simulate`] keeps the traces, [`simulate_in_chunks`]
//! hands them on chunk by chunk so that a long run's memory does not grow with its duration.

use super::closed_loop::ClosedLoop;
use super::config::SimulationConfig;
use super::metrics::Metrics;
use super::traces::Traces;
use crate::error::Error;

/// A whole run's result.
#[derive(Clone, Debug, PartialEq)]
pub struct RunReport {
    pub config: SimulationConfig,
    pub metrics: Metrics,
    pub traces: Traces,
}

/// Runs `config` from rest on the reference for `duration` seconds (or until it diverges).
pub fn simulate(config: &SimulationConfig, duration: f64) -> Result<RunReport, Error> {
    let mut sim = ClosedLoop::new(*config)?;
    sim.advance(duration)?;
    Ok(RunReport { config: *config, metrics: sim.metrics(), traces: sim.traces().clone() })
}

/// Runs `config` from rest for `duration` seconds (or until it diverges) in chunks of at most
/// `chunk` simulated seconds, handing each chunk's traces and the fraction done to `on_chunk`
/// and then dropping them: the memory does not grow with the duration (the metrics are online).
pub fn simulate_in_chunks<E: From<Error>>(
    config: &SimulationConfig,
    duration: f64,
    chunk: f64,
    mut on_chunk: impl FnMut(&Traces, f64) -> Result<(), E>,
) -> Result<Metrics, E> {
    let mut sim = ClosedLoop::new(*config)?;
    if !(duration.is_finite() && duration >= 0.0) {
        return Err(Error::InvalidDuration(duration).into());
    }
    let chunk = if chunk > 0.0 { chunk } else { duration.max(1.0) };
    loop {
        // The last chunk ends on the duration itself (advance rounds to whole plant steps).
        let left = duration - sim.time();
        sim.advance(left.clamp(0.0, chunk))?;
        on_chunk(sim.traces(), (sim.time() / duration).min(1.0))?;
        sim.traces_mut().clear();
        if left <= chunk || sim.is_finished() {
            return Ok(sim.metrics());
        }
    }
}
