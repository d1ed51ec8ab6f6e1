//! What a preliminary feedback costs in motor torque: the closed loop run through one slew, then
//! poked at rest, with the peak and RMS torque the controller applies in each phase. A stiffer
//! damper between motor and link 1 takes more torque to answer the same poke; the slew's torque is
//! mostly the reference's own (the links' inertia), which no feedback changes much.

use nalgebra::Vector2;
use serde::Serialize;

use super::closed_loop::ClosedLoop;
use super::config::SimulationConfig;
use crate::error::Error;

/// The poke: (T1, T2) in N m for this many seconds — the page's Poke button and the price's.
pub const POKE: ([f64; 2], f64) = ([40.0, 5.0], 0.05);
/// Rest after the slew before the poke, s: the slew's transient has died down by then.
pub const SETTLE: f64 = 1.0;
/// The swing after the poke is measured for this long from the poke's start, s.
pub const SWING: f64 = 2.0;

/// Peak and RMS of the torques (T1, T2) the controller applied over a phase, N m.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct TorqueFigures {
    pub peak: [f64; 2],
    pub rms: [f64; 2],
}

/// Accumulates [`TorqueFigures`] one plant step at a time (bounded memory).
#[derive(Clone, Copy, Debug, Default)]
struct TorqueStats {
    peak: [f64; 2],
    sum_sq: [f64; 2],
    samples: usize,
}

impl TorqueStats {
    fn record(&mut self, torque: Vector2<f64>) {
        for i in 0..2 {
            self.peak[i] = self.peak[i].max(torque[i].abs());
            self.sum_sq[i] += torque[i] * torque[i];
        }
        self.samples += 1;
    }

    fn figures(&self) -> TorqueFigures {
        let n = self.samples.max(1) as f64;
        TorqueFigures { peak: self.peak, rms: self.sum_sq.map(|s| (s / n).sqrt()) }
    }
}

/// The torque a configuration's loop applies: during its slew, and in the swing after a poke at
/// rest ([`POKE`] applied [`SETTLE`] s after the slew ends, measured for [`SWING`] s with the
/// poke's own torque taken out: what the controller and its preliminary feedback answer with).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TorquePrice {
    pub slew: TorqueFigures,
    pub poke: TorqueFigures,
    /// The run diverged before the end (the figures are those up to then).
    pub diverged: bool,
}

/// Runs `config` from rest through one slew (a repeating slew is run once) and a poke; see
/// [`TorquePrice`]. About 4 s of simulated time: a few ms natively at δ = 0.01 s.
pub fn torque_price(config: &SimulationConfig) -> Result<TorquePrice, Error> {
    let mut config = *config;
    config.reference.repeat_hold = None;
    let slew_end = config.reference.slew_time;
    let poke_at = slew_end + SETTLE;
    let end = poke_at + SWING;
    let mut sim = ClosedLoop::new(config)?;
    let h = sim.plant_step();
    let (poke, poke_duration) = POKE;
    let mut slew = TorqueStats::default();
    let mut swing = TorqueStats::default();
    let mut poked = false;
    while sim.time() + 0.5 * h < end && !sim.is_finished() {
        if !poked && sim.time() + 0.5 * h >= poke_at {
            sim.apply_disturbance(poke, poke_duration)?;
            poked = true;
        }
        sim.advance(h)?;
        let t = sim.time();
        let torque = Vector2::from(sim.snapshot().torque);
        if t <= slew_end + 0.5 * h {
            slew.record(torque);
        } else if poked {
            // The controller's own answer: the poke's torque is the disturbance, not the price.
            let applied = if t < poke_at + poke_duration - 0.5 * h { Vector2::from(poke) } else { Vector2::zeros() };
            swing.record(torque - applied);
        }
    }
    Ok(TorquePrice { slew: slew.figures(), poke: swing.figures(), diverged: sim.is_finished() })
}
