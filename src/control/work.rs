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
/// at k = 12 against 3.55 µs measured).
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
        let steps_per_period = (delta / config.plant_step()).ceil().max(1.0);
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

    /// The estimate in words, e.g. "2.0e6 sampling periods, about 9 s".
    pub fn text(&self) -> String {
        let mut parts = Vec::new();
        if self.sampling_periods > 0.0 {
            parts.push(format!("{:.1e} sampling periods", self.sampling_periods));
        }
        parts.push(format!("about {}", duration_text(self.seconds)));
        parts.join(", ")
    }
}

/// Seconds in words: "9 s", "4 min", "3.2 h", "12 days", "10^14 years".
pub fn duration_text(seconds: f64) -> String {
    const MINUTE: f64 = 60.0;
    const HOUR: f64 = 3600.0;
    const DAY: f64 = 86400.0;
    const YEAR: f64 = 365.25 * DAY;
    if !seconds.is_finite() {
        "for ever".into()
    } else if seconds < 1.0 {
        "under a second".into()
    } else if seconds < 2.0 * MINUTE {
        format!("{seconds:.0} s")
    } else if seconds < 2.0 * HOUR {
        format!("{:.0} min", seconds / MINUTE)
    } else if seconds < 2.0 * DAY {
        format!("{:.1} h", seconds / HOUR)
    } else if seconds < YEAR {
        format!("{:.0} days", seconds / DAY)
    } else {
        format!("{:.1e} years", seconds / YEAR)
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

    #[test]
    fn durations_read_in_sensible_units() {
        assert_eq!(duration_text(9.4), "9 s");
        assert_eq!(duration_text(600.0), "10 min");
        assert_eq!(duration_text(f64::INFINITY), "for ever");
        assert!(duration_text(1e12).ends_with("years"));
    }
}
