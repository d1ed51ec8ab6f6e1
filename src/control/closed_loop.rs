//! The sampled-data loop of Fig. 2.1: plant, friction observer, preliminary feedback and the
//! delayed predictive controller, with traces, metrics and a verdict.
//!
//! Timing: at each sampling instant t_ρ = ρδ the controller measures X = x(t_ρ) and computes
//! V^ρ; it is applied, piecewise constant, on [t_{ρ+1}, t_{ρ+2}) (one period of computation
//! delay). Nothing has been computed on [0, δ), so v = 0 there. The applied torque is
//!
//! T(t) = v(t) + K_pr x(t) (or K_pr x(t_ρ) for a sampled inner loop) + friction compensation,
//!
//! where the compensation is the observer output x̂f(t) (continuous), x̂f(t_ρ) (held) or 0.
//! The controller's integrators w are integrated with the plant from the measured error.
//!
//! The same [`ClosedLoop`] value serves batch runs ([`super::batch::simulate`]) and live animation
//! ([`ClosedLoop::advance`]); a new configuration takes effect at the next sampling instant.

use nalgebra::Vector2;

use super::config::{FrictionCompensation, InnerLoop, SimulationConfig};
use super::feedback::{resolve_gain, FeedbackGain};
use super::history::{History, LoopState};
use super::linear::inner_loop_rate;
use super::metrics::{DivergenceReason, ErrorStats, Metrics};
use super::predictive::{controller_vector, Predictor, StateVector, Sweep};
use super::sensing::Measurement;
use super::traces::{Snapshot, Traces};
use crate::error::{ConfigError, Error};
use crate::model::friction::FrictionObserver;
use crate::model::plant::{Plant, PlantState};
use crate::model::reference::Reference;

/// Derived settings that follow from the configuration.
#[derive(Clone, Copy, Debug)]
struct Derived {
    plant: Plant,
    /// The arm the controller assumes (its predictor and friction observer): the plant's own
    /// parameters unless `model = paper`.
    model: crate::model::params::PlantParameters,
    reference: Reference,
    predictor: Predictor,
    gain: FeedbackGain,
    /// Plant step h = δ / steps_per_period, s.
    plant_step: f64,
    steps_per_period: usize,
    output_every: usize,
}

impl Derived {
    fn new(config: &SimulationConfig) -> Result<Self, Error> {
        config.validate()?;
        let delta = config.controller.sampling_period;
        let gain = resolve_gain(config)?;
        let steps_per_period = (delta / plant_step(config, &gain)).ceil().max(1.0) as usize;
        let plant_step = delta / steps_per_period as f64;
        let output_every = (config.output_interval / plant_step).round().max(1.0) as usize;
        Ok(Self {
            plant: Plant::new(config.plant),
            reference: Reference::new(config.reference),
            model: config.model_plant(),
            predictor: Predictor::new(&config.model_plant(), &config.controller),
            gain,
            plant_step,
            steps_per_period,
            output_every,
        })
    }
}

/// The plant integrator's largest step, s, for `config` with its preliminary feedback `gain`:
/// `plant_step_max`, or less where RK4 would not follow the fastest motion at that step
/// (ω h ≤ 0.3) — the arm's (resonance, damping), and with the feedback acting continuously the
/// inner loop's ([`inner_loop_rate`]); a feedback held over δ adds none.
pub fn plant_step(config: &SimulationConfig, gain: &FeedbackGain) -> f64 {
    let rate = match config.inner_loop {
        InnerLoop::Continuous => inner_loop_rate(&config.plant, config.controller.alpha, gain),
        InnerLoop::Sampled => config.plant.fastest_rate(),
    };
    config.plant_step_max.min(0.3 / rate)
}

/// The closed loop of Fig. 2.1 as a value that can be stepped or run to the end.
#[derive(Clone, Debug)]
pub struct ClosedLoop {
    config: SimulationConfig,
    derived: Derived,
    /// A configuration waiting for the next sampling instant.
    pending: Option<(SimulationConfig, Derived)>,

    time: f64,
    /// Time of the last change of δ; sampling instants are origin + n δ (no accumulated rounding).
    period_origin: f64,
    periods_since_origin: u64,
    period_start: f64,
    step_in_period: usize,
    steps_taken: u64,

    plant_state: PlantState,
    /// The controller's integrators w = (w1, w2), eq. (4.2).
    integrators: Vector2<f64>,
    observer: FrictionObserver,

    /// v applied on the current period.
    v_applied: Vector2<f64>,
    /// v computed at the last sampling instant, applied from the next one.
    v_next: Option<Vector2<f64>>,
    /// U_k of the last prediction: the Newton seed of the next one.
    torque_guess: Vector2<f64>,
    held_compensation: Vector2<f64>,
    held_feedback: Vector2<f64>,
    applied_torque: Vector2<f64>,
    /// An extra torque (the "poke") and the time it ends.
    disturbance: Option<(Vector2<f64>, f64)>,
    /// The digital controller's last reading (`config.sensors`; unused while they are off).
    measurement: Measurement,

    traces: Traces,
    stats: ErrorStats,
    divergence: Option<(f64, DivergenceReason)>,
    /// The state at every sampling instant of the last few seconds (none unless asked for).
    history: History,
    /// The newest prediction whole, X_0 … X_k and U_1 … U_k (none unless asked for): Fig. 2.1.
    sweep: Option<Sweep>,
    /// The work of the sampling instant the loop stands on is done (measured, predicted): the
    /// next plant step goes on from it. Only [`ClosedLoop::sample_now`] does it ahead of time.
    sampled: bool,
}

impl ClosedLoop {
    /// A loop at rest on the reference at t = 0.
    pub fn new(config: SimulationConfig) -> Result<Self, Error> {
        let derived = Derived::new(&config)?;
        let r0 = derived.reference.sample(0.0);
        let mut sim = Self {
            config,
            derived,
            pending: None,
            time: 0.0,
            period_origin: 0.0,
            periods_since_origin: 0,
            period_start: 0.0,
            step_in_period: 0,
            steps_taken: 0,
            plant_state: PlantState::at_rest(r0.q[0], r0.q[1]),
            integrators: Vector2::zeros(),
            observer: FrictionObserver::default(),
            v_applied: Vector2::zeros(),
            v_next: None,
            torque_guess: Vector2::zeros(),
            held_compensation: Vector2::zeros(),
            held_feedback: Vector2::zeros(),
            applied_torque: Vector2::zeros(),
            disturbance: None,
            measurement: Measurement::new(config.sensors.seed),
            traces: Traces::default(),
            stats: ErrorStats::default(),
            divergence: None,
            history: History::default(),
            sweep: None,
            sampled: false,
        };
        sim.applied_torque = sim.torque_at(&sim.controller_state());
        sim.record_trace();
        Ok(sim)
    }

    /// Starts over from rest with the current (and any pending) configuration, keeping as much
    /// history as before (none of the old run's).
    pub fn reset(&mut self) -> Result<(), Error> {
        let config = self.pending.take().map(|(c, _)| c).unwrap_or(self.config);
        let seconds = self.history.seconds();
        let sweep = self.sweep.take().map(|mut s| {
            s.states.clear();
            s.torques.clear();
            s
        });
        *self = Self::new(config)?;
        self.keep_history(seconds);
        self.sweep = sweep;
        Ok(())
    }

    /// Keeps the newest prediction whole ([`ClosedLoop::latest_sweep`]), from the next sampling
    /// instant on: what the page shows as Fig. 2.1 without predicting again.
    pub fn keep_sweep(&mut self, keep: bool) {
        self.sweep = if keep { Some(self.sweep.take().unwrap_or_default()) } else { None };
    }

    /// The controller's newest prediction, X_0 … X_k and U_1 … U_k, if kept.
    pub fn latest_sweep(&self) -> Option<&Sweep> {
        self.sweep.as_ref()
    }

    /// Keeps the state at every sampling instant of the last `seconds` (0: none), from now on.
    pub fn keep_history(&mut self, seconds: f64) {
        self.history = History::new(seconds);
    }

    /// The kept states of the recent past.
    pub fn history(&self) -> &History {
        &self.history
    }

    /// The newest state as it was at the kept sampling instant at or before `t`.
    pub fn snapshot_at(&self, t: f64) -> Option<Snapshot> {
        let (state, config) = self.history.at(t)?;
        let reference = Reference::new(config.reference);
        Some(snapshot_of(state, &reference, config.sensors.is_digital()))
    }

    /// Goes back to the kept sampling instant at or before `t` and continues from there: the same
    /// state, configuration and schedule as then, so that without a change it does exactly what
    /// it did (the traces and history after that instant are dropped; the statistics start afresh
    /// there). Returns the instant.
    pub fn branch_at(&mut self, t: f64) -> Result<f64, Error> {
        let Some((state, config)) = self.history.at(t) else {
            return Err(Error::InvalidDuration(t));
        };
        let (state, config) = (*state, *config);
        self.derived = Derived::new(&config)?;
        self.config = config;
        self.pending = None;
        self.time = state.time;
        self.period_origin = state.period_origin;
        self.periods_since_origin = state.periods_since_origin;
        self.period_start = state.time;
        self.step_in_period = 0;
        self.steps_taken = state.steps_taken;
        self.plant_state = state.plant;
        self.integrators = state.integrators;
        self.observer = state.observer;
        self.v_applied = state.v_applied;
        self.v_next = state.v_next;
        self.torque_guess = state.torque_guess;
        self.held_compensation = state.held_compensation;
        self.held_feedback = state.held_feedback;
        self.applied_torque = state.applied_torque;
        self.disturbance = state.disturbance;
        self.measurement = state.measurement;
        self.divergence = None;
        self.sampled = false;
        self.traces.truncate_after(state.time);
        self.history.truncate_from(state.time);
        self.stats.restart(state.time);
        self.stats.continue_phase(self.derived.reference.is_moving(state.time));
        Ok(state.time)
    }

    /// The state carried from this sampling instant to the next.
    fn loop_state(&self) -> LoopState {
        LoopState {
            time: self.time,
            period_origin: self.period_origin,
            periods_since_origin: self.periods_since_origin,
            steps_taken: self.steps_taken,
            plant: self.plant_state,
            integrators: self.integrators,
            observer: self.observer,
            v_applied: self.v_applied,
            v_next: self.v_next,
            torque_guess: self.torque_guess,
            held_compensation: self.held_compensation,
            held_feedback: self.held_feedback,
            applied_torque: self.applied_torque,
            disturbance: self.disturbance,
            measurement: self.measurement,
            config: 0,
        }
    }

    /// The configuration in force.
    pub fn config(&self) -> &SimulationConfig {
        &self.config
    }

    /// Validates `config` and schedules it for the next sampling instant.
    pub fn set_config(&mut self, config: SimulationConfig) -> Result<(), Error> {
        let derived = Derived::new(&config)?;
        if config != self.config {
            // The statistics belong to the new settings from now on: a growth rate measured under
            // the old ones must not stand beside the new prediction, even for one period.
            self.stats.restart(self.time);
        }
        self.pending = Some((config, derived));
        Ok(())
    }

    /// The preliminary feedback gain in force.
    pub fn feedback_gain(&self) -> &FeedbackGain {
        &self.derived.gain
    }

    /// Adds `torque` (T1, T2, N m) to the applied torques for the next `duration` seconds.
    pub fn apply_disturbance(&mut self, torque: [f64; 2], duration: f64) -> Result<(), Error> {
        if !(duration.is_finite() && duration >= 0.0) {
            return Err(Error::InvalidDuration(duration));
        }
        if !torque.iter().all(|v| v.is_finite()) {
            return Err(Error::Config(ConfigError::new("disturbance torque", torque[0] + torque[1], "must be finite")));
        }
        self.disturbance = Some((Vector2::from(torque), self.time + duration));
        Ok(())
    }

    /// The plant's integration step, s (δ divided into whole steps).
    pub fn plant_step(&self) -> f64 {
        self.derived.plant_step
    }

    /// Simulated time, s.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// True once the run has diverged; further `advance` calls do nothing.
    pub fn is_finished(&self) -> bool {
        self.divergence.is_some()
    }

    /// Advances the simulation by `dt` seconds (to the nearest plant step), stopping early if
    /// it diverges.
    pub fn advance(&mut self, dt: f64) -> Result<(), Error> {
        if !(dt.is_finite() && (0.0..=1e6).contains(&dt)) {
            return Err(Error::InvalidDuration(dt));
        }
        let target = self.time + dt;
        while self.divergence.is_none() && self.time + 0.5 * self.derived.plant_step <= target {
            self.step();
        }
        Ok(())
    }

    /// Advances to the next sampling instant (at least one plant step).
    pub fn advance_one_period(&mut self) {
        loop {
            if self.divergence.is_some() {
                return;
            }
            self.step();
            if self.step_in_period == 0 {
                return;
            }
        }
    }

    /// Does the work of the sampling instant the loop stands on now, if it is due (the loop stops
    /// on an instant before its work: Step ▸ does it at once, so that the instant is kept and its
    /// prediction shown). The run goes on exactly as it would have; a change made after it waits
    /// for the next instant.
    pub fn sample_now(&mut self) {
        if self.step_in_period == 0 && !self.sampled && self.divergence.is_none() {
            self.sample();
            // The torque from now on, with the v held from this instant.
            self.applied_torque = self.torque_at(&self.controller_state());
        }
    }

    /// The measured controller state X = (q, q̇, w).
    fn controller_state(&self) -> StateVector {
        controller_vector(&self.plant_state.q, &self.plant_state.qdot, &self.integrators)
    }

    /// The applied torque for controller state `x` at the current instant, within the motors'
    /// limit. A digital controller (sensors on) holds its preliminary feedback over the period.
    fn torque_at(&self, x: &StateVector) -> Vector2<f64> {
        let feedback = match self.config.inner_loop {
            InnerLoop::Continuous if !self.config.sensors.is_digital() => self.derived.gain * x,
            _ => self.held_feedback,
        };
        let compensation = match self.config.friction_compensation {
            FrictionCompensation::Continuous => self.observer.estimate,
            FrictionCompensation::Held => self.held_compensation,
            FrictionCompensation::Off => Vector2::zeros(),
        };
        let poke = match self.disturbance {
            Some((torque, until)) if self.time < until => torque,
            _ => Vector2::zeros(),
        };
        let torque = self.v_applied + feedback + compensation + poke;
        match self.config.sensors.limit() {
            Some(limit) => torque.map(|t| t.clamp(-limit, limit)),
            None => torque,
        }
    }

    /// What the controller knows at this sampling instant: the true X (the paper's perfect
    /// sensors), or X_m = (m, ν, w) read through the sensors.
    fn read_state(&mut self) -> StateVector {
        let sensors = self.config.sensors;
        if !sensors.is_digital() {
            return self.controller_state();
        }
        let reference = self.derived.reference.sample(self.time).q;
        let (q, qdot) = (&self.plant_state.q, &self.plant_state.qdot);
        self.measurement.read(&sensors, self.time, q, qdot, [reference[0], reference[1]]);
        controller_vector(&self.measurement.angles, &self.measurement.velocities, &self.integrators)
    }

    /// The work of a sampling instant: new configuration, new v, new prediction.
    fn sample(&mut self) {
        self.sampled = true;
        if let Some((config, derived)) = self.pending.take() {
            if config.controller.sampling_period != self.config.controller.sampling_period {
                self.period_origin = self.time;
                self.periods_since_origin = 0;
            }
            if config != self.config {
                self.stats.restart(self.time);
            }
            self.config = config;
            self.derived = derived;
        }
        // Kept before this instant's work, so that continuing from here repeats it.
        let state = self.loop_state();
        self.history.record(state, &self.config);
        let x = self.read_state();
        self.v_applied = self.v_next.take().unwrap_or_else(Vector2::zeros);
        self.held_compensation = self.observer.estimate;
        self.held_feedback = self.derived.gain * x;
        let sweep = self.sweep.as_mut();
        match self.derived.predictor.predict_into(&self.derived.reference, self.time, &x, &self.torque_guess, sweep) {
            Ok(p) => {
                self.torque_guess = p.torque;
                let v = p.torque - self.derived.gain * p.state;
                self.v_next = Some(v);
                if let Some(s) = self.sweep.as_mut() {
                    s.held = Some(v);
                }
            }
            Err(_) => self.divergence = Some((self.time, DivergenceReason::NewtonFailure)),
        }
    }

    /// One plant step: the plant's own split step with the integrators w riding along, the
    /// observer advanced in the same two half steps.
    fn step(&mut self) {
        if self.step_in_period == 0 && !self.sampled {
            self.sample();
            if self.divergence.is_some() {
                return;
            }
        }
        let d = self.derived;
        let h = d.plant_step;
        let p = &d.model;
        let t0 = self.time;
        // A digital controller's integrators and observer run on what it read, held (eq. (4.2)
        // and (4.4) with the measured angle and the velocity estimate).
        let digital = self.config.sensors.is_digital().then_some(self.measurement);
        let observed = |qdot: &nalgebra::Vector3<f64>| digital.map_or(*qdot, |m| m.velocities);

        let v = observed(&self.plant_state.qdot);
        self.observer.advance(p, v[2], v[1], 0.5 * h);
        let alpha = self.config.controller.alpha;
        let mut w = self.integrators;
        let this = &*self;
        let mut plant_state = this.plant_state;
        d.plant.step_with(
            &mut plant_state,
            &mut w,
            h,
            |_, q, v, w, _| this.torque_at(&controller_vector(q, v, w)),
            // ẇ_i = α_i³ (q_i − q_di), eq. (4.2).
            |s, q, _| {
                let e = match digital {
                    Some(m) => m.error,
                    None => {
                        let qd = d.reference.sample(t0 + s).q;
                        Vector2::new(q[0] - qd[0], q[1] - qd[1])
                    }
                };
                Vector2::new(alpha[0].powi(3) * e[0], alpha[1].powi(3) * e[1])
            },
        );
        self.plant_state = plant_state;
        self.integrators = w;
        let v = observed(&self.plant_state.qdot);
        self.observer.advance(p, v[2], v[1], 0.5 * h);

        self.step_in_period += 1;
        self.steps_taken += 1;
        self.sampled = false;
        if self.step_in_period == d.steps_per_period {
            self.step_in_period = 0;
            self.periods_since_origin += 1;
            self.period_start =
                self.period_origin + self.periods_since_origin as f64 * self.config.controller.sampling_period;
            self.time = self.period_start;
        } else {
            self.time = self.period_start + self.step_in_period as f64 * h;
        }

        self.applied_torque = self.torque_at(&self.controller_state());
        let r = d.reference.sample(self.time);
        let e = Vector2::new(self.plant_state.q[0] - r.q[0], self.plant_state.q[1] - r.q[1]);
        if !self.plant_state.is_finite() || !self.integrators.iter().all(|v| v.is_finite()) {
            self.divergence = Some((self.time, DivergenceReason::NonFinite));
        } else if e.amax() > self.config.divergence_bound {
            self.divergence = Some((self.time, DivergenceReason::ErrorBound));
        } else {
            self.stats.record(
                self.time,
                &e,
                &self.applied_torque,
                d.reference.is_moving(self.time),
                self.config.sensors.limit(),
            );
        }
        if self.steps_taken.is_multiple_of(d.output_every as u64) || self.divergence.is_some() {
            self.record_trace();
        }
    }

    fn record_trace(&mut self) {
        let s = self.snapshot();
        self.traces.push(&s);
    }

    /// The newest state.
    pub fn snapshot(&self) -> Snapshot {
        snapshot_of(&self.loop_state(), &self.derived.reference, self.config.sensors.is_digital())
    }

    /// The plant's full physical state (including the true friction torques).
    pub fn plant_state(&self) -> &PlantState {
        &self.plant_state
    }

    /// The recorded time series.
    pub fn traces(&self) -> &Traces {
        &self.traces
    }

    /// Mutable access to the traces (e.g. to bound their length in a live view).
    pub fn traces_mut(&mut self) -> &mut Traces {
        &mut self.traces
    }

    /// Metrics and verdict so far.
    pub fn metrics(&self) -> Metrics {
        self.stats.metrics(self.time, self.divergence)
    }
}

/// What is drawn and recorded of a state; `digital`: the controller reads its sensors (what it
/// read is then the held measurement, else the true state).
fn snapshot_of(state: &LoopState, reference: &Reference, digital: bool) -> Snapshot {
    let r = reference.sample(state.time);
    let s = &state.plant;
    let error = [s.q[0] - r.q[0], s.q[1] - r.q[1]];
    let qdot = [s.qdot[0], s.qdot[1], s.qdot[2]];
    let m = &state.measurement;
    let (error_meas, qdot_est) = if digital && m.time.is_some() {
        ([m.error[0], m.error[1]], [m.velocities[0], m.velocities[1], m.velocities[2]])
    } else {
        (error, qdot)
    };
    Snapshot {
        time: state.time,
        q: [s.q[0], s.q[1], s.q[2]],
        qdot,
        qd: [r.q[0], r.q[1]],
        error,
        torque: [state.applied_torque[0], state.applied_torque[1]],
        v: [state.v_applied[0], state.v_applied[1]],
        xf_hat: [state.observer.estimate[0], state.observer.estimate[1]],
        w: [state.integrators[0], state.integrators[1]],
        error_meas,
        qdot_est,
    }
}
