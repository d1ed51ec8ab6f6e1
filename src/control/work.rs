//! What a run will cost, known before it starts: the number of sampling periods and plant steps,
//! and the seconds they take on a machine like the one this program is developed on (2 cores,
//! 2026; `cargo bench --bench core` measures the same things). The command line refuses work over
//! [`WORK_LIMIT_SECONDS`] unless told to insist, and shows progress for work over
//! [`PROGRESS_SECONDS`].

use super::config::SimulationConfig;

/// Work estimated above this many seconds is refused unless the user insists (`--force`).
pub const WORK_LIMIT_SECONDS: f64 = 60.0;
/// Work estimated above this many seconds reports its progress.
pub const PROGRESS_SECONDS: f64 = 3.0;

/// Seconds per backward-Euler step of the predictor (k of them per sampling period, each a
/// Newton solve of eq. (2.3)); measured 0.25 µs, rounded up (with the next, 3.9 µs a period
/// at k = 12 against 3.55 µs measured). The processor's own measurement (`control::timing`,
/// `cargo bench --bench core`, issue 36) finds one prediction from mid-slew at 1.9–3.4 µs at
/// k = 12 (34–36 Newton iterations; δ = 0.01 and 0.002 s) and 0.6–1.0 µs at k = 4, within this
/// price.
const SECONDS_PER_PREDICTION_STEP: f64 = 0.28e-6;
/// Seconds per sampling period besides the prediction (measurement, observer, feedback).
const SECONDS_PER_PERIOD: f64 = 0.5e-6;
/// Seconds per step of the plant integrator (4.1); measured 0.05 µs, rounded up.
const SECONDS_PER_PLANT_STEP: f64 = 0.1e-6;

/// The estimated cost of some work.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Work {
    /// Sampling periods (controller predictions) to compute.
    pub sampling_periods: f64,
    /// Plant integration steps to take.
    pub plant_steps: f64,
    /// Other units of work (e.g. ρ of map cells), already priced in `seconds`.
    pub other: f64,
    /// Estimated seconds.
    pub seconds: f64,
}

impl Work {
    /// Nothing to do.
    pub const NONE: Work = Work { sampling_periods: 0.0, plant_steps: 0.0, other: 0.0, seconds: 0.0 };

    /// A run of `config` for `duration` seconds (the whole duration: a run that diverges stops
    /// earlier).
    pub fn of_run(config: &SimulationConfig, duration: f64) -> Work {
        let delta = config.controller.sampling_period;
        let periods = (duration / delta).ceil().max(0.0);
        // The step the run will take (a gain that cannot be designed fails the run itself).
        let gain = super::feedback::resolve_gain(config).unwrap_or_default();
        let steps_per_period = (delta / super::closed_loop::plant_step(config, &gain)).ceil().max(1.0);
        let plant_steps = periods * steps_per_period;
        let per_period = SECONDS_PER_PERIOD + config.controller.horizon_steps as f64 * SECONDS_PER_PREDICTION_STEP;
        Work {
            sampling_periods: periods,
            plant_steps,
            other: 0.0,
            seconds: periods * per_period + plant_steps * SECONDS_PER_PLANT_STEP,
        }
    }

    /// `count` units of other work at `seconds_each`.
    pub fn of_units(count: f64, seconds_each: f64) -> Work {
        Work { other: count, seconds: count * seconds_each, ..Work::NONE }
    }

    /// Both pieces of work.
    pub fn plus(self, other: Work) -> Work {
        Work {
            sampling_periods: self.sampling_periods + other.sampling_periods,
            plant_steps: self.plant_steps + other.plant_steps,
            other: self.other + other.other,
            seconds: self.seconds + other.seconds,
        }
    }

    /// The same work `n` times.
    pub fn times(self, n: f64) -> Work {
        Work {
            sampling_periods: self.sampling_periods * n,
            plant_steps: self.plant_steps * n,
            other: self.other * n,
            seconds: self.seconds * n,
        }
    }

    /// Over [`WORK_LIMIT_SECONDS`] (or not even finite).
    pub fn is_over_limit(&self) -> bool {
        self.is_over(WORK_LIMIT_SECONDS)
    }

    /// Over `limit` seconds (or not even finite).
    pub fn is_over(&self, limit: f64) -> bool {
        !(self.seconds <= limit)
    }

    /// Long enough to report progress.
    pub fn wants_progress(&self) -> bool {
        self.seconds > PROGRESS_SECONDS
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn work_grows_with_duration_and_shrinking_period() {
        let mut c = SimulationConfig::default();
        let a = Work::of_run(&c, 10.0);
        c.controller.sampling_period = 0.001;
        let b = Work::of_run(&c, 10.0);
        assert_eq!(a.sampling_periods, 1000.0);
        assert_eq!(b.sampling_periods, 10_000.0);
        assert!(b.seconds > 2.0 * a.seconds);
        assert!(!a.is_over_limit());
        assert!(Work::of_run(&c, 1e6).is_over_limit());
    }
}
