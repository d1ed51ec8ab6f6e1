//! The processor: how long one sampling instant's prediction takes, against δ.
//!
//! The paper, on Fig. 2.1: "At each time t_ρ, the plant is sampled and the vector x(t_ρ) is used
//! as the initial value X_0^ρ for system (2.3). […] Clearly, to be implementable, the numerical
//! integration of the DAE has to be faster than real-time." The loop gives the controller one
//! period for it: V^ρ, computed from x(t_ρ), is applied from t_{ρ+1} on. So the k backward-Euler
//! steps of eq. (2.4), each solved by Newton, must take less than δ on the controller's computer.
//!
//! This module holds that work ([`ControllerWorkload`]: one sampling instant's prediction, made
//! again and again from the same measured state) and its summary ([`ControllerTime`]: seconds per
//! sample against δ). It reads no clock itself (the browser build has no `std::time`): the caller
//! hands [`ControllerWorkload::measure`] its own — `std::time::Instant` on the command line,
//! `performance.now()` in the page.

use nalgebra::{Vector2, Vector3};

use super::config::SimulationConfig;
use super::feedback::resolve_gain;
use super::predictive::{controller_vector, FeedbackGain, Predictor, StateVector};
use crate::error::Error;
use crate::model::reference::Reference;

/// Where in the slew the measured state is taken, as a fraction of t_f: the middle (t = 0.5 s on
/// the paper's 1-s slew), where the reference moves fastest and Newton does real work.
pub const MID_SLEW: f64 = 0.5;

/// One sampling instant of the predictive controller as work to be timed: the predictor of
/// eqs. (2.3)–(2.4) for a configuration, the reference, a measured state X = x(t_ρ) in the middle
/// of the slew and the Newton seed, so that [`ControllerWorkload::predict_once`] does exactly what
/// the loop does at t_ρ (the k backward-Euler steps, then V_k = U_k − K_pr X_k), allocating
/// nothing.
#[derive(Clone, Debug)]
pub struct ControllerWorkload {
    predictor: Predictor,
    reference: Reference,
    gain: FeedbackGain,
    /// t_ρ, s.
    time: f64,
    /// X = x(t_ρ): the reference's angles and rates (θ = q1, θ̇ = q̇1), the integrators w at 0.
    state: StateVector,
    /// U_k of a first prediction from the same state: the loop seeds Newton with the previous U_k.
    torque_guess: Vector2<f64>,
    /// δ, s.
    sampling_period: f64,
    /// k.
    horizon_steps: usize,
    /// Newton iterations of the last prediction, summed over the k steps.
    newton_iterations: usize,
    /// V_k of the last prediction, N m (what the loop would hold over [t_{ρ+1}, t_{ρ+2})).
    held: Vector2<f64>,
    /// K_pr x(t_ρ), N m (what a sampled inner loop holds over the period).
    feedback: Vector2<f64>,
}

impl ControllerWorkload {
    /// The controller of `config` (the predictor on the arm the controller assumes, as the loop
    /// builds it) at t_ρ = [`MID_SLEW`] · t_f, with X from the reference there. Fails if the
    /// configuration is invalid, or if the prediction from that state fails.
    pub fn new(config: &SimulationConfig) -> Result<Self, Error> {
        config.validate()?;
        let predictor = Predictor::new(&config.model_plant(), &config.controller);
        let reference = Reference::new(config.reference);
        let gain = resolve_gain(config)?;
        let time = MID_SLEW * config.reference.slew_time;
        let r = reference.sample(time);
        let q = Vector3::new(r.q[0], r.q[1], r.q[0]);
        let v = Vector3::new(r.qdot[0], r.qdot[1], r.qdot[0]);
        let state = controller_vector(&q, &v, &Vector2::zeros());
        let mut workload = Self {
            predictor,
            reference,
            gain,
            time,
            state,
            torque_guess: Vector2::zeros(),
            sampling_period: config.controller.sampling_period,
            horizon_steps: config.controller.horizon_steps,
            newton_iterations: 0,
            held: Vector2::zeros(),
            feedback: Vector2::zeros(),
        };
        // The first prediction seeds the rest, as the previous U_k seeds the loop's next one.
        let first = workload.predictor.predict(&workload.reference, time, &state, &Vector2::zeros()).map_err(failed)?;
        workload.torque_guess = first.torque;
        workload.predict_once()?;
        Ok(workload)
    }

    /// One sampling instant's prediction: the k backward-Euler steps of eq. (2.4) from X, each a
    /// Newton solve, and V_k = U_k − K_pr X_k with the feedback K_pr x(t_ρ) the loop holds. The
    /// same work every call; nothing allocated.
    pub fn predict_once(&mut self) -> Result<(), Error> {
        let p = self.predictor.predict(&self.reference, self.time, &self.state, &self.torque_guess).map_err(failed)?;
        self.feedback = self.gain * self.state;
        self.held = p.torque - self.gain * p.state;
        self.newton_iterations = p.newton_iterations;
        Ok(())
    }

    /// Times `plan.batches` batches of predictions with `clock` (seconds, any origin; it must not
    /// go back) and returns the median seconds per prediction. A batch has `plan.per_batch`
    /// predictions, fewer where one prediction is so slow that all batches would take over
    /// `plan.budget` seconds (at least one each).
    pub fn measure(&mut self, clock: &mut dyn FnMut() -> f64, plan: TimingPlan) -> Result<ControllerTime, Error> {
        let batches = plan.batches.max(1);
        let start = clock();
        self.predict_once()?;
        let first = clock() - start;
        let affordable = if first > 0.0 { plan.budget / (batches as f64 * first) } else { f64::INFINITY };
        let per_batch = (affordable.floor() as usize).clamp(1, plan.per_batch.max(1));
        let mut samples = Vec::with_capacity(batches);
        for _ in 0..batches {
            let start = clock();
            for _ in 0..per_batch {
                self.predict_once()?;
            }
            samples.push((clock() - start) / per_batch as f64);
        }
        Ok(self.summary(median(&mut samples)))
    }

    /// `seconds_per_sample` (measured by the caller) against this controller's δ and k.
    pub fn summary(&self, seconds_per_sample: f64) -> ControllerTime {
        ControllerTime { seconds_per_sample, sampling_period: self.sampling_period, horizon_steps: self.horizon_steps }
    }

    /// Newton iterations of the last prediction, summed over its k steps.
    pub fn newton_iterations(&self) -> usize {
        self.newton_iterations
    }

    /// V_k of the last prediction, N m.
    pub fn held_torque(&self) -> Vector2<f64> {
        self.held
    }

    /// K_pr x(t_ρ) of the last prediction, N m.
    pub fn held_feedback(&self) -> Vector2<f64> {
        self.feedback
    }

    /// t_ρ, the sampling instant the prediction starts from, s.
    pub fn time(&self) -> f64 {
        self.time
    }
}

/// How a measurement is made: [`TimingPlan::batches`] batches of up to
/// [`TimingPlan::per_batch`] predictions, all within about [`TimingPlan::budget`] seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimingPlan {
    pub batches: usize,
    pub per_batch: usize,
    /// s.
    pub budget: f64,
}

impl Default for TimingPlan {
    /// 7 batches of 200 predictions, at most ≈ 30 ms in all (≈ 5 ms at k = 12 on the
    /// development machine).
    fn default() -> Self {
        Self { batches: 7, per_batch: 200, budget: 0.03 }
    }
}

/// How long one sampling instant's prediction takes against the sampling period δ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ControllerTime {
    /// The prediction's seconds per sampling instant (k backward-Euler steps), s.
    pub seconds_per_sample: f64,
    /// δ, s.
    pub sampling_period: f64,
    /// k, the backward-Euler steps of one prediction.
    pub horizon_steps: usize,
}

impl ControllerTime {
    /// The share of δ the prediction takes: seconds per sample / δ.
    pub fn share(&self) -> f64 {
        self.seconds_per_sample / self.sampling_period
    }

    /// "Faster than real-time": the prediction takes less than δ (share < 1).
    pub fn fits(&self) -> bool {
        self.share() < 1.0
    }

    /// The clock saw the work: a positive, finite time (a page's coarse clock may see none).
    pub fn is_measured(&self) -> bool {
        self.seconds_per_sample > 0.0 && self.seconds_per_sample.is_finite()
    }
}

/// The median of `samples` (sorted in place; the mean of the middle two for an even count; NaN
/// for none).
pub fn median(samples: &mut [f64]) -> f64 {
    crate::sort::sort_by(samples, |a, b| a.total_cmp(b));
    let n = samples.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => samples[n / 2],
        _ => 0.5 * (samples[n / 2 - 1] + samples[n / 2]),
    }
}

fn failed(e: super::predictive::PredictionError) -> Error {
    Error::Refused(format!("the controller's prediction from the middle of the slew failed: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_median_sorts_and_takes_the_middle() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&mut []).is_nan());
    }

    #[test]
    fn the_workload_predicts_mid_slew_with_newton_at_work() {
        let mut w = ControllerWorkload::new(&SimulationConfig::default()).expect("the paper's controller predicts");
        assert_eq!(w.time(), 0.5);
        // k = 12 steps, at least one Newton iteration each.
        assert!(w.newton_iterations() >= 12, "{}", w.newton_iterations());
        let before = w.held_torque();
        w.predict_once().expect("again");
        assert_eq!(w.held_torque(), before, "the same work every call");
        // A clock that advances 1 µs per reading: each batch's mean is 1 µs / per_batch.
        let mut t = 0.0;
        let mut clock = || {
            t += 1e-6;
            t
        };
        let time = w.measure(&mut clock, TimingPlan { batches: 3, per_batch: 4, budget: 1.0 }).expect("timed");
        assert!((time.seconds_per_sample - 0.25e-6).abs() < 1e-12, "{time:?}");
        assert_eq!((time.sampling_period, time.horizon_steps), (0.01, 12));
        assert!(time.fits() && time.is_measured());
    }
}
