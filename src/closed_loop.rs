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
//! The same [`ClosedLoop`] value serves batch runs ([`simulate`]) and live animation
//! ([`ClosedLoop::advance`]); a new configuration takes effect at the next sampling instant.

use nalgebra::{SVector, Vector2, Vector3};
use serde::{Deserialize, Serialize};

use crate::feedback::{resolve_gain, FeedbackGain};
use crate::friction::FrictionObserver;
use crate::params::{FrictionCompensation, InnerLoop, SimulationConfig};
use crate::plant::{rk4, Plant, PlantState};
use crate::predictive::{Predictor, StateVector};
use crate::reference::Reference;
use crate::Error;

/// Length of the windows over which the error envelope is taken for the growth rate, s.
pub const GROWTH_WINDOW: f64 = 0.25;
/// The growth rate is fitted over at most this much time at the end of the run, s.
pub const GROWTH_FIT_SPAN: f64 = 3.0;
/// A run whose error envelope grows faster than this (1/s) is called unstable.
pub const UNSTABLE_GROWTH_RATE: f64 = 0.05;
/// Errors below this (rad) are rounding noise and cannot make a run unstable.
pub const ERROR_NOISE_FLOOR: f64 = 1e-10;

/// Why a run ended early.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DivergenceReason {
    /// |e_i| exceeded the configured divergence bound.
    ErrorBound,
    /// The state became NaN or infinite.
    NonFinite,
    /// Newton did not converge in the predictor.
    NewtonFailure,
}

/// The outcome of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "verdict", rename_all = "lowercase")]
pub enum Verdict {
    /// Errors bounded and not growing.
    Stable,
    /// Errors growing at the given rate (1/s) but still within the bound.
    Unstable { growth_rate: f64 },
    /// The run ended at `at` (s).
    Diverged { at: f64, reason: DivergenceReason },
}

impl Verdict {
    /// "stable", "unstable" or "diverged".
    pub fn label(&self) -> &'static str {
        match self {
            Verdict::Stable => "stable",
            Verdict::Unstable { .. } => "unstable",
            Verdict::Diverged { .. } => "diverged",
        }
    }
}

/// Summary figures of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Metrics {
    /// Simulated time, s.
    pub time: f64,
    /// max |e_i| while the reference moves, rad.
    pub max_error_slew: [f64; 2],
    /// max |e_i| while the reference rests, rad.
    pub max_error_after: [f64; 2],
    /// RMS of e_i over the whole run, rad.
    pub rms_error: [f64; 2],
    /// Slope of ln max(|e1|, |e2|) over the last windows after the first slew, 1/s.
    pub growth_rate: Option<f64>,
    /// max |T_i| applied, N m.
    pub max_torque: [f64; 2],
    pub verdict: Verdict,
}

/// The recorded time series, one column per quantity (equal lengths).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Traces {
    /// t, s.
    pub t: Vec<f64>,
    /// q1, q2, θ, rad.
    pub q1: Vec<f64>,
    pub q2: Vec<f64>,
    pub theta: Vec<f64>,
    /// q_d1, q_d2, rad.
    pub qd1: Vec<f64>,
    pub qd2: Vec<f64>,
    /// e_i = q_i − q_di, rad.
    pub e1: Vec<f64>,
    pub e2: Vec<f64>,
    /// Applied torques T1, T2, N m.
    pub torque1: Vec<f64>,
    pub torque2: Vec<f64>,
    /// The predictive controller's output v, N m.
    pub v1: Vec<f64>,
    pub v2: Vec<f64>,
    /// Observed friction x̂f, N m.
    pub xf1_hat: Vec<f64>,
    pub xf2_hat: Vec<f64>,
}

impl Traces {
    /// Column names with units, in CSV order.
    pub const HEADER: [&'static str; 14] = [
        "t [s]",
        "q1 [rad]",
        "q2 [rad]",
        "theta [rad]",
        "qd1 [rad]",
        "qd2 [rad]",
        "e1 [rad]",
        "e2 [rad]",
        "T1 [N m]",
        "T2 [N m]",
        "v1 [N m]",
        "v2 [N m]",
        "xf1_hat [N m]",
        "xf2_hat [N m]",
    ];

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    fn columns(&self) -> [&Vec<f64>; 14] {
        [
            &self.t,
            &self.q1,
            &self.q2,
            &self.theta,
            &self.qd1,
            &self.qd2,
            &self.e1,
            &self.e2,
            &self.torque1,
            &self.torque2,
            &self.v1,
            &self.v2,
            &self.xf1_hat,
            &self.xf2_hat,
        ]
    }

    fn columns_mut(&mut self) -> [&mut Vec<f64>; 14] {
        [
            &mut self.t,
            &mut self.q1,
            &mut self.q2,
            &mut self.theta,
            &mut self.qd1,
            &mut self.qd2,
            &mut self.e1,
            &mut self.e2,
            &mut self.torque1,
            &mut self.torque2,
            &mut self.v1,
            &mut self.v2,
            &mut self.xf1_hat,
            &mut self.xf2_hat,
        ]
    }

    fn push(&mut self, row: [f64; 14]) {
        for (col, v) in self.columns_mut().into_iter().zip(row) {
            col.push(v);
        }
    }

    /// Drops the oldest samples so that at most `keep` remain (for bounded live traces).
    pub fn truncate_front(&mut self, keep: usize) {
        let n = self.len();
        if n > keep {
            for col in self.columns_mut() {
                col.drain(..n - keep);
            }
        }
    }

    /// The series as CSV with a header row naming each column and its unit.
    pub fn to_csv(&self) -> String {
        let mut out = String::with_capacity(self.len() * 14 * 14 + 200);
        out.push_str(&Self::HEADER.join(","));
        out.push('\n');
        let cols = self.columns();
        for i in 0..self.len() {
            for (j, col) in cols.iter().enumerate() {
                if j > 0 {
                    out.push(',');
                }
                out.push_str(&format!("{:.10e}", col[i]));
            }
            out.push('\n');
        }
        out
    }
}

/// The newest state, for drawing.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Snapshot {
    /// t, s.
    pub time: f64,
    /// q1, q2, θ, rad.
    pub q: [f64; 3],
    /// q̇1, q̇2, θ̇, rad/s.
    pub qdot: [f64; 3],
    /// q_d1, q_d2, rad.
    pub qd: [f64; 2],
    /// e1, e2, rad.
    pub error: [f64; 2],
    /// Applied T1, T2, N m.
    pub torque: [f64; 2],
    /// Controller output v, N m.
    pub v: [f64; 2],
    /// Observed friction x̂f, N m.
    pub xf_hat: [f64; 2],
    /// Controller integrators w, rad/s².
    pub w: [f64; 2],
}

/// A whole run's result.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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

/// Running statistics of the errors.
#[derive(Clone, Debug, Default)]
struct ErrorStats {
    max_slew: [f64; 2],
    max_after: [f64; 2],
    sum_sq: [f64; 2],
    samples: u64,
    max_torque: [f64; 2],
    /// (window end time, max(|e1|, |e2|) in the window).
    windows: Vec<(f64, f64)>,
    window_start: f64,
    window_max: f64,
    /// The growth rate is fitted only after this time (the last change of configuration), so a
    /// live change shows its own growth, not a mix with the previous setting.
    fit_from: f64,
    /// For a repeating maneuver: its period and the error maximum of each cycle (cycle index, max).
    cycle_period: Option<f64>,
    cycle_max: Vec<(u64, f64)>,
}

impl ErrorStats {
    fn record(&mut self, t: f64, e: &Vector2<f64>, torque: &Vector2<f64>, moving: bool, cycle_period: Option<f64>) {
        if cycle_period != self.cycle_period {
            self.cycle_period = cycle_period;
            self.cycle_max.clear();
        }
        if let Some(period) = cycle_period {
            let index = (t / period).floor() as u64;
            let m = e[0].abs().max(e[1].abs());
            match self.cycle_max.last_mut() {
                Some((i, max)) if *i == index => *max = max.max(m),
                _ => self.cycle_max.push((index, m)),
            }
        }
        for i in 0..2 {
            let a = e[i].abs();
            let slot = if moving { &mut self.max_slew[i] } else { &mut self.max_after[i] };
            *slot = slot.max(a);
            self.sum_sq[i] += e[i] * e[i];
            self.max_torque[i] = self.max_torque[i].max(torque[i].abs());
        }
        self.samples += 1;
        self.window_max = self.window_max.max(e[0].abs().max(e[1].abs()));
        if t - self.window_start >= GROWTH_WINDOW - 1e-12 {
            self.windows.push((t, self.window_max));
            self.window_start = t;
            self.window_max = 0.0;
        }
    }

    /// The growth rate of the error envelope, 1/s. For a single slew: the least-squares slope of
    /// ln(window max) over the windows after `from` (the end of the slew). For a repeating
    /// maneuver the errors rise with every slew even when the loop is stable, so the envelope is
    /// compared cycle to cycle instead: ln(max of the last full cycle / max of the one before) / period.
    fn growth_rate(&self, from: f64) -> Option<f64> {
        if let Some(period) = self.cycle_period {
            let current = self.cycle_max.last()?.0;
            let mut complete =
                self.cycle_max.iter().filter(|(i, _)| *i < current && *i as f64 * period >= self.fit_from - 1e-9).rev();
            let (_, last) = complete.next()?;
            let (_, previous) = complete.next()?;
            return (*last > 0.0 && *previous > 0.0).then(|| (last / previous).ln() / period);
        }
        let end = self.windows.last()?.0;
        let start = from.max(self.fit_from).max(end - GROWTH_FIT_SPAN);
        let pts: Vec<(f64, f64)> =
            self.windows.iter().filter(|(t, m)| *t > start + 1e-9 && *m > 0.0).map(|(t, m)| (*t, m.ln())).collect();
        if pts.len() < 3 {
            return None;
        }
        let n = pts.len() as f64;
        let (st, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (t, y)| (a + t, b + y));
        let (mt, my) = (st / n, sy / n);
        let (num, den) =
            pts.iter().fold((0.0, 0.0), |(a, b), (t, y)| (a + (t - mt) * (y - my), b + (t - mt) * (t - mt)));
        (den > 0.0).then(|| num / den)
    }
}

/// Derived settings that follow from the configuration.
#[derive(Clone, Copy, Debug)]
struct Derived {
    plant: Plant,
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
        let steps_per_period = (delta / config.plant_step_max).ceil().max(1.0) as usize;
        let plant_step = delta / steps_per_period as f64;
        let output_every = (config.output_interval / plant_step).round().max(1.0) as usize;
        Ok(Self {
            plant: Plant::new(config.plant),
            reference: Reference::new(config.reference),
            predictor: Predictor::new(&config.plant, &config.controller),
            gain: resolve_gain(config)?,
            plant_step,
            steps_per_period,
            output_every,
        })
    }
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

    traces: Traces,
    stats: ErrorStats,
    divergence: Option<(f64, DivergenceReason)>,
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
            traces: Traces::default(),
            stats: ErrorStats::default(),
            divergence: None,
        };
        sim.applied_torque = sim.torque_at(&sim.controller_state());
        sim.record_trace();
        Ok(sim)
    }

    /// Starts over from rest with the current (and any pending) configuration.
    pub fn reset(&mut self) -> Result<(), Error> {
        let config = self.pending.take().map(|(c, _)| c).unwrap_or(self.config);
        *self = Self::new(config)?;
        Ok(())
    }

    /// The configuration in force.
    pub fn config(&self) -> &SimulationConfig {
        &self.config
    }

    /// Validates `config` and schedules it for the next sampling instant.
    pub fn set_config(&mut self, config: SimulationConfig) -> Result<(), Error> {
        let derived = Derived::new(&config)?;
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
            return Err(Error::Config(crate::ConfigError::new(
                "disturbance torque",
                torque[0] + torque[1],
                "must be finite",
            )));
        }
        self.disturbance = Some((Vector2::from(torque), self.time + duration));
        Ok(())
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

    /// The measured controller state X = (q, q̇, w).
    fn controller_state(&self) -> StateVector {
        let s = &self.plant_state;
        StateVector::from_column_slice(&[
            s.q[0],
            s.q[1],
            s.q[2],
            s.qdot[0],
            s.qdot[1],
            s.qdot[2],
            self.integrators[0],
            self.integrators[1],
        ])
    }

    /// The applied torque for controller state `x` at the current instant.
    fn torque_at(&self, x: &StateVector) -> Vector2<f64> {
        let feedback = match self.config.inner_loop {
            InnerLoop::Continuous => self.derived.gain * x,
            InnerLoop::Sampled => self.held_feedback,
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
        self.v_applied + feedback + compensation + poke
    }

    /// The work of a sampling instant: new configuration, new v, new prediction.
    fn sample(&mut self) {
        if let Some((config, derived)) = self.pending.take() {
            if config.controller.sampling_period != self.config.controller.sampling_period {
                self.period_origin = self.time;
                self.periods_since_origin = 0;
            }
            if config != self.config {
                self.stats.fit_from = self.time;
            }
            self.config = config;
            self.derived = derived;
        }
        let x = self.controller_state();
        self.v_applied = self.v_next.take().unwrap_or_else(Vector2::zeros);
        self.held_compensation = self.observer.estimate;
        self.held_feedback = self.derived.gain * x;
        match self.derived.predictor.predict(&self.derived.reference, self.time, &x, &self.torque_guess) {
            Ok(p) => {
                self.torque_guess = p.torque;
                self.v_next = Some(p.torque - self.derived.gain * p.state);
            }
            Err(_) => self.divergence = Some((self.time, DivergenceReason::NewtonFailure)),
        }
    }

    /// One plant step: friction half step, RK4 on (q, q̇, w), friction half step.
    fn step(&mut self) {
        if self.step_in_period == 0 {
            self.sample();
            if self.divergence.is_some() {
                return;
            }
        }
        let d = self.derived;
        let h = d.plant_step;
        let p = &d.plant.params;
        let t0 = self.time;

        self.observer.advance(p, self.plant_state.qdot[2], self.plant_state.qdot[1], 0.5 * h);
        d.plant.friction_half_step(&mut self.plant_state, 0.5 * h);

        let friction = self.plant_state.friction;
        let alpha = self.config.controller.alpha;
        let x = self.controller_state();
        let x = rk4(&x, h, |s, x: &SVector<f64, 8>| {
            let q = Vector3::new(x[0], x[1], x[2]);
            let v = Vector3::new(x[3], x[4], x[5]);
            let torque = self.torque_at(x);
            let a = d.plant.acceleration(&q, &v, &friction, &torque);
            let qd = d.reference.sample(t0 + s).q;
            SVector::<f64, 8>::from_column_slice(&[
                v[0],
                v[1],
                v[2],
                a[0],
                a[1],
                a[2],
                alpha[0].powi(3) * (q[0] - qd[0]),
                alpha[1].powi(3) * (q[1] - qd[1]),
            ])
        });
        self.plant_state.q = Vector3::new(x[0], x[1], x[2]);
        self.plant_state.qdot = Vector3::new(x[3], x[4], x[5]);
        self.integrators = Vector2::new(x[6], x[7]);

        d.plant.friction_half_step(&mut self.plant_state, 0.5 * h);
        self.observer.advance(p, self.plant_state.qdot[2], self.plant_state.qdot[1], 0.5 * h);

        self.step_in_period += 1;
        self.steps_taken += 1;
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
            let cycle = self.config.reference.repeat_hold.map(|hold| 2.0 * (self.config.reference.slew_time + hold));
            self.stats.record(self.time, &e, &self.applied_torque, d.reference.is_moving(self.time), cycle);
        }
        if self.steps_taken.is_multiple_of(d.output_every as u64) || self.divergence.is_some() {
            self.record_trace();
        }
    }

    fn record_trace(&mut self) {
        let s = self.snapshot();
        self.traces.push([
            s.time,
            s.q[0],
            s.q[1],
            s.q[2],
            s.qd[0],
            s.qd[1],
            s.error[0],
            s.error[1],
            s.torque[0],
            s.torque[1],
            s.v[0],
            s.v[1],
            s.xf_hat[0],
            s.xf_hat[1],
        ]);
    }

    /// The newest state.
    pub fn snapshot(&self) -> Snapshot {
        let r = self.derived.reference.sample(self.time);
        let s = &self.plant_state;
        Snapshot {
            time: self.time,
            q: [s.q[0], s.q[1], s.q[2]],
            qdot: [s.qdot[0], s.qdot[1], s.qdot[2]],
            qd: [r.q[0], r.q[1]],
            error: [s.q[0] - r.q[0], s.q[1] - r.q[1]],
            torque: [self.applied_torque[0], self.applied_torque[1]],
            v: [self.v_applied[0], self.v_applied[1]],
            xf_hat: [self.observer.estimate[0], self.observer.estimate[1]],
            w: [self.integrators[0], self.integrators[1]],
        }
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
        let s = &self.stats;
        let n = s.samples.max(1) as f64;
        let growth_rate = s.growth_rate(self.config.reference.slew_time);
        let last_window = s.windows.last().map(|w| w.1).unwrap_or(0.0).max(s.window_max);
        let verdict = match self.divergence {
            Some((at, reason)) => Verdict::Diverged { at, reason },
            None => match growth_rate {
                Some(g) if g > UNSTABLE_GROWTH_RATE && last_window > ERROR_NOISE_FLOOR => {
                    Verdict::Unstable { growth_rate: g }
                }
                _ => Verdict::Stable,
            },
        };
        Metrics {
            time: self.time,
            max_error_slew: s.max_slew,
            max_error_after: s.max_after,
            rms_error: [(s.sum_sq[0] / n).sqrt(), (s.sum_sq[1] / n).sqrt()],
            growth_rate,
            max_torque: s.max_torque,
            verdict,
        }
    }
}
