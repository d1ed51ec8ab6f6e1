//! The paper's Fig. 2.1 at one sampling instant t_n of a run: the state measured there, the
//! prediction X_0 … X_k, U_1 … U_k the controller integrated from it over τ = kε, the torque U_k
//! it chose, and the torques the loop applied on the periods around t_n — the one chosen at t_n
//! held from t_n + δ to t_n + 2δ.
//!
//! Nothing here is stored for the purpose: at the newest instant the sweep is the controller's own
//! ([`super::ClosedLoop::latest_sweep`]); at an earlier one it is computed again from the kept state
//! ([`super::History`]), which gives the same numbers (the loop is deterministic; `tests/cycle.rs`
//! checks it to the bit). The buffers are reused: filling a cycle allocates nothing once warm.

use nalgebra::Vector2;

use super::config::SimulationConfig;
use super::feedback::resolve_gain;
use super::history::{History, LoopState};
use super::predictive::{Predictor, Sweep};
use super::traces::Traces;
use crate::model::reference::Reference;

/// Periods before and after t_n whose applied torque a cycle describes: [t_{n−2}, t_{n+3}).
const PERIODS: usize = 5;
/// Index of the period [t_n, t_{n+1}) among them.
const THIS: usize = 2;

/// One sampling period and the torque v the predictive controller held over it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldPeriod {
    /// [start, end), s.
    pub start: f64,
    pub end: f64,
    /// v, N m: computed at the instant before `start` (zero on the first period of a run).
    pub v: Vector2<f64>,
}

/// Fig. 2.1 at one sampling instant.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Cycle {
    /// t_n, s (NaN while empty).
    pub instant: f64,
    /// δ in force at t_n, s.
    pub period: f64,
    /// k and τ = kε, s.
    pub horizon_steps: usize,
    pub horizon: f64,
    /// The prediction from x(t_n).
    pub sweep: Sweep,
    /// For X_0 … X_k: the predicted errors e1, e2 against the reference at t_n + jε, rad.
    pub predicted: Vec<[f64; 2]>,
    /// The periods from t_{n−2} to t_{n+3} that the run went through (or, for [t_{n+1}, t_{n+2}),
    /// will go through: then `applied` stops at the run's present), with the v held on each.
    pub held: Vec<HeldPeriod>,
    /// The torques the controller applied, u = v + K_pr x (+ a poke; the friction compensation
    /// x̂f left out), as a polyline over `held`'s periods — times (s), u1 and u2 (N m): flat steps
    /// of v plus the preliminary feedback's continuous part, read off the traces.
    pub applied: [Vec<f64>; 3],
}

impl Cycle {
    /// An empty cycle.
    pub fn new() -> Self {
        Self { instant: f64::NAN, ..Self::default() }
    }

    /// True if there is a prediction to show.
    pub fn is_empty(&self) -> bool {
        !self.instant.is_finite()
    }

    /// Describes the kept sampling instant at or before `t` of a run with this `history` and
    /// these `traces`; `latest` is the controller's newest sweep (used when it is of that instant,
    /// else the sweep is computed again from the kept state). Empties the cycle if no instant is
    /// kept there.
    pub fn fill(&mut self, history: &History, latest: Option<&Sweep>, traces: &Traces, t: f64) {
        let Some((state, config)) = history.at(t) else {
            self.instant = f64::NAN;
            return;
        };
        let tn = state.time;
        self.instant = tn;
        self.period = config.controller.sampling_period;
        self.horizon_steps = config.controller.horizon_steps;
        self.horizon = config.controller.horizon();
        match latest {
            Some(s) if s.start == tn && !s.states.is_empty() => copy_sweep(&mut self.sweep, s),
            _ => {
                recompute(state, config, &mut self.sweep);
                // The torque it chose is what the loop held from the next instant on (the next
                // kept state says it; at the newest instant, V_k = U_k − K_pr X_k).
                let next = history.after(tn).and_then(|t| history.at(t)).and_then(|(s, _)| s.v_next);
                self.sweep.held = next.or_else(|| {
                    let (u, x) = (self.sweep.torques.last()?, self.sweep.states.last()?);
                    let gain = resolve_gain(config).ok()?;
                    Some(u - gain * x).filter(|_| self.sweep.complete)
                });
            }
        }
        let reference = Reference::new(config.reference);
        self.predicted.clear();
        for (j, x) in self.sweep.states.iter().enumerate() {
            let r = reference.sample(self.sweep.time(j));
            self.predicted.push([x[0] - r.q[0], x[1] - r.q[1]]);
        }
        self.fill_held(history, state);
        self.fill_applied(traces);
    }

    /// The periods [t_{n−2}, t_{n+3}) as far as the run knows them, each with its v: kept states
    /// say what was held; after the newest one only the torque chosen at t_n is known, for the
    /// period after the present one.
    fn fill_held(&mut self, history: &History, state: &LoopState) {
        let v_of = |t: f64| history.at(t).map(|(s, _)| s.v_next.unwrap_or_else(Vector2::zeros));
        let mut instants = [f64::NAN; PERIODS + 1];
        let mut v = [None; PERIODS];
        instants[THIS] = state.time;
        v[THIS] = Some(state.v_next.unwrap_or_else(Vector2::zeros));
        for i in (0..THIS).rev() {
            let Some(t) = history.before(instants[i + 1]) else { break };
            instants[i] = t;
            v[i] = v_of(t);
        }
        for i in THIS + 1..=PERIODS {
            let kept = history.after(instants[i - 1]);
            instants[i] = kept.unwrap_or(instants[i - 1] + self.period);
            if i < PERIODS {
                v[i] = match kept {
                    Some(t) => v_of(t),
                    None if i == THIS + 1 => self.sweep.held,
                    None => None,
                };
            }
        }
        self.held.clear();
        for i in 0..PERIODS {
            if let Some(v) = v[i].filter(|_| instants[i].is_finite() && instants[i + 1].is_finite()) {
                self.held.push(HeldPeriod { start: instants[i], end: instants[i + 1], v });
            }
        }
    }

    /// u(t) over the held periods, from the traces: on each period its v plus the rest of the
    /// recorded torque, T − v − x̂f (the preliminary feedback and any poke), which is continuous
    /// and so read between recorded rows by linear interpolation.
    fn fill_applied(&mut self, traces: &Traces) {
        for column in &mut self.applied {
            column.clear();
        }
        let t = traces.t();
        let (t1, t2, v1, v2) = (traces.torque1(), traces.torque2(), traces.v1(), traces.v2());
        let (x1, x2) = (traces.xf1_hat(), traces.xf2_hat());
        let n = [t.len(), t1.len(), t2.len(), v1.len(), v2.len(), x1.len(), x2.len()].into_iter().min().unwrap_or(0);
        if n == 0 {
            return;
        }
        let t = &t[..n];
        let rest = |i: usize| [t1[i] - v1[i] - x1[i], t2[i] - v2[i] - x2[i]];
        let rest_at = |s: f64| {
            let i = t.partition_point(|&x| x < s);
            if i == 0 || i >= n {
                return rest(i.min(n - 1));
            }
            let f = if t[i] > t[i - 1] { (s - t[i - 1]) / (t[i] - t[i - 1]) } else { 1.0 };
            let (a, b) = (rest(i - 1), rest(i));
            [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
        };
        let last = t[n - 1];
        for p in &self.held {
            // A period not run yet (or not recorded) has no applied torque.
            let end = p.end.min(last);
            if end <= p.start || p.start < t[0] {
                continue;
            }
            let [at, u1, u2] = &mut self.applied;
            let mut push = |s: f64, r: [f64; 2]| {
                at.push(s);
                u1.push(p.v[0] + r[0]);
                u2.push(p.v[1] + r[1]);
            };
            push(p.start, rest_at(p.start));
            let inside = t.partition_point(|&x| x <= p.start)..t.partition_point(|&x| x < end);
            for i in inside {
                push(t[i], rest(i));
            }
            push(end, rest_at(end));
        }
    }

    /// The period [t_{n+1}, t_{n+2}) on which the torque chosen at t_n is held, if known.
    pub fn hold(&self) -> Option<&HeldPeriod> {
        self.held.iter().find(|p| p.start > self.instant + 1e-12)
    }

    /// U_k, the torque the prediction ends on, N m.
    pub fn chosen_torque(&self) -> Option<Vector2<f64>> {
        if self.sweep.complete {
            self.sweep.torques.last().copied()
        } else {
            None
        }
    }
}

/// Copies a sweep into `out`, reusing its buffers.
fn copy_sweep(out: &mut Sweep, from: &Sweep) {
    out.start = from.start;
    out.step = from.step;
    out.complete = from.complete;
    out.held = from.held;
    out.states.clone_from(&from.states);
    out.torques.clone_from(&from.torques);
}

/// The controller's sweep at a kept instant, computed again from the state kept there: the same
/// predictor, reference, measured state and Newton seed as then.
fn recompute(state: &LoopState, config: &SimulationConfig, out: &mut Sweep) {
    let predictor = Predictor::new(&config.model_plant(), &config.controller);
    let reference = Reference::new(config.reference);
    // A failed sweep keeps the steps that converged; `complete` says so.
    let _ = predictor.predict_into(&reference, state.time, &state.measured(), &state.torque_guess, Some(out));
}
