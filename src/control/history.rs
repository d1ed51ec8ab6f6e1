//! The recent past of a closed loop: its complete state at every sampling instant of the last
//! few seconds, so that a run can be looked at as it was and continued from any of those instants
//! exactly (the loop is deterministic, so continuing reproduces what followed, unless something
//! is changed).
//!
//! A bounded ring: once warm, recording allocates nothing; the oldest instants fall out.

use std::collections::VecDeque;

use nalgebra::Vector2;

use super::config::SimulationConfig;
use super::predictive::StateVector;
use super::sensing::Measurement;
use crate::model::friction::FrictionObserver;
use crate::model::plant::PlantState;

/// Everything [`super::ClosedLoop`] carries from one sampling instant to the next, besides its
/// configuration, its traces and its statistics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoopState {
    /// The sampling instant, s.
    pub time: f64,
    pub period_origin: f64,
    pub periods_since_origin: u64,
    pub steps_taken: u64,
    pub plant: PlantState,
    /// The controller's integrators w, eq. (4.2).
    pub integrators: Vector2<f64>,
    pub observer: FrictionObserver,
    pub v_applied: Vector2<f64>,
    pub v_next: Option<Vector2<f64>>,
    pub torque_guess: Vector2<f64>,
    pub held_compensation: Vector2<f64>,
    pub held_feedback: Vector2<f64>,
    pub applied_torque: Vector2<f64>,
    pub disturbance: Option<(Vector2<f64>, f64)>,
    /// The digital controller's last reading (unused while the sensors are off).
    pub measurement: Measurement,
    /// Which configuration was in force (a serial number in the history's list of them).
    pub(super) config: u32,
}

impl LoopState {
    /// What the controller measures at this instant: X = (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2).
    pub fn measured(&self) -> StateVector {
        super::predictive::controller_vector(&self.plant.q, &self.plant.qdot, &self.integrators)
    }

    /// The sampled loop's state ζ = (x − x_rest, v) of the linear analysis
    /// ([`crate::analysis::sampled_loop_matrix`]) while the reference rests at link angles `rest`:
    /// the errors, the motor's angle from link 1's reference, the velocities, the integrators w,
    /// and the torque v that will be held over the coming period.
    pub fn deviation(&self, rest: [f64; 2]) -> [f64; 10] {
        let (q, qd, w) = (&self.plant.q, &self.plant.qdot, &self.integrators);
        let v = self.v_next.unwrap_or_else(Vector2::zeros);
        [q[0] - rest[0], q[1] - rest[1], q[2] - rest[0], qd[0], qd[1], qd[2], w[0], w[1], v[0], v[1]]
    }
}

/// The loop's states at the sampling instants of the last `seconds`.
#[derive(Clone, Debug, Default)]
pub struct History {
    seconds: f64,
    states: VecDeque<LoopState>,
    /// The configurations in force, each with its serial number (what [`LoopState`] refers to).
    configs: VecDeque<(u32, SimulationConfig)>,
    next_serial: u32,
}

impl History {
    /// A history of the last `seconds` (0 keeps nothing).
    pub fn new(seconds: f64) -> Self {
        Self { seconds: seconds.max(0.0), ..Self::default() }
    }

    /// Seconds kept.
    pub fn seconds(&self) -> f64 {
        self.seconds
    }

    pub fn is_empty(&self) -> bool {
        self.states.is_empty()
    }

    pub fn len(&self) -> usize {
        self.states.len()
    }

    /// States the ring holds without growing.
    pub fn capacity(&self) -> usize {
        self.states.capacity()
    }

    /// The oldest and newest instants kept, s.
    pub fn span(&self) -> Option<[f64; 2]> {
        Some([self.states.front()?.time, self.states.back()?.time])
    }

    /// Records the state at a sampling instant under `config`. Allocates only when the
    /// configuration changes or the ring must grow (a smaller δ).
    pub(crate) fn record(&mut self, mut state: LoopState, config: &SimulationConfig) {
        if self.seconds <= 0.0 {
            return;
        }
        if self.configs.back().map(|(_, c)| c) != Some(config) {
            self.configs.push_back((self.next_serial, *config));
            self.next_serial += 1;
            // Room for the whole span at this δ, reserved once rather than grown step by step.
            let needed = (self.seconds / config.controller.sampling_period).ceil() as usize + 2;
            self.states.reserve(needed.saturating_sub(self.states.len()));
        }
        state.config = self.configs.back().map_or(0, |(serial, _)| *serial);
        while self.states.front().is_some_and(|s| s.time < state.time - self.seconds) {
            self.states.pop_front();
        }
        // A configuration no kept state refers to any more goes too.
        while self.configs.len() > 1 && self.states.front().is_some_and(|s| s.config >= self.configs[1].0) {
            self.configs.pop_front();
        }
        self.states.push_back(state);
    }

    /// The newest state at or before `t` (within a nanosecond), with its configuration.
    pub fn at(&self, t: f64) -> Option<(&LoopState, &SimulationConfig)> {
        let i = self.index_at(t)?;
        let s = &self.states[i];
        Some((s, self.config_of(s)))
    }

    /// The states from `start` to `end` (s), oldest first.
    pub fn between(&self, start: f64, end: f64) -> impl Iterator<Item = &LoopState> {
        let first = self.states.partition_point(|s| s.time < start);
        let last = self.states.partition_point(|s| s.time <= end).max(first);
        self.states.range(first..last)
    }

    /// The instant before the newest one at or before `t` (for stepping back), if kept.
    pub fn before(&self, t: f64) -> Option<f64> {
        let i = self.index_at(t)?;
        let i = if self.states[i].time < t - 1e-9 { i } else { i.checked_sub(1)? };
        Some(self.states[i].time)
    }

    /// The first instant after `t`, if kept.
    pub fn after(&self, t: f64) -> Option<f64> {
        let i = self.states.partition_point(|s| s.time <= t + 1e-9);
        self.states.get(i).map(|s| s.time)
    }

    /// Forgets every instant from `t` on (the run goes on from `t` differently).
    pub(crate) fn truncate_from(&mut self, t: f64) {
        let i = self.states.partition_point(|s| s.time < t - 1e-9);
        self.states.truncate(i);
        let last = self.states.back().map_or(0, |s| s.config);
        while self.configs.len() > 1 && self.configs.back().is_some_and(|(serial, _)| *serial > last) {
            self.configs.pop_back();
        }
    }

    fn index_at(&self, t: f64) -> Option<usize> {
        self.states.partition_point(|s| s.time <= t + 1e-9).checked_sub(1)
    }

    fn config_of(&self, s: &LoopState) -> &SimulationConfig {
        let i = self.configs.partition_point(|(serial, _)| *serial < s.config);
        &self.configs[i.min(self.configs.len() - 1)].1
    }
}
