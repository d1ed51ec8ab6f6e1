//! The autoscale of the error and torque plots.
//!
//! The errors span many decades: about 1e-4 rad in a stable run, up to π rad when a run
//! diverges. The plots therefore use a symmetric range ±Y with Y the next "nice" number above the
//! largest visible |value|, and a hysteresis so the scale does not flicker: it grows at once but
//! shrinks only after the data have stayed well below it for a while.

use crate::plot::ticks::nice_ceil;

/// Settings of an [`Autoscale`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AutoscaleSettings {
    /// The smallest half-range Y, in the data's unit (keeps rounding noise from filling a plot).
    pub floor: f64,
    /// Y is at least this factor above the data maximum, so the curve never touches the frame.
    pub headroom: f64,
    /// The scale may shrink once the data maximum is below this fraction of Y ...
    pub shrink_below: f64,
    /// ... continuously for this long (s of simulated time).
    pub shrink_after: f64,
}

impl AutoscaleSettings {
    /// Errors in rad: floor 1e-6 rad.
    pub const ERROR: AutoscaleSettings =
        AutoscaleSettings { floor: 1e-6, headroom: 1.1, shrink_below: 1.0 / 3.0, shrink_after: 1.0 };
    /// Link 1's velocity in rad/s: Y is 1.5 × the true velocity's largest |value| (the estimate,
    /// however noisy, does not set it), at least 0.2 rad/s.
    pub const VELOCITY: AutoscaleSettings =
        AutoscaleSettings { floor: 0.2, headroom: 1.5, shrink_below: 1.0 / 3.0, shrink_after: 1.0 };
    /// Torques in N m: floor 1e-3 N m.
    pub const TORQUE: AutoscaleSettings =
        AutoscaleSettings { floor: 1e-3, headroom: 1.1, shrink_below: 1.0 / 3.0, shrink_after: 1.0 };
}

/// A symmetric range ±Y that follows the data with hysteresis: grows at once, shrinks slowly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Autoscale {
    settings: AutoscaleSettings,
    limit: f64,
    /// Since when the data have been below `shrink_below × limit`.
    low_since: Option<f64>,
}

impl Autoscale {
    pub fn new(settings: AutoscaleSettings) -> Self {
        Self { settings, limit: settings.floor, low_since: None }
    }

    /// Fresh scales for the time plots e1, e2 and the torques (theirs and the zoom's own).
    pub fn time_plots() -> [Autoscale; 3] {
        [Self::new(AutoscaleSettings::ERROR), Self::new(AutoscaleSettings::ERROR), Self::new(AutoscaleSettings::TORQUE)]
    }

    /// The current half-range Y: the plot shows [−Y, Y].
    pub fn limit(&self) -> f64 {
        self.limit
    }

    /// Back to the floor (after a reset of the simulation).
    pub fn reset(&mut self) {
        self.limit = self.settings.floor;
        self.low_since = None;
    }

    /// The Y this data maximum would get without hysteresis.
    pub fn target(&self, data_max: f64) -> f64 {
        let wanted = if data_max.is_finite() { data_max.abs() * self.settings.headroom } else { 0.0 };
        nice_ceil(wanted.max(self.settings.floor))
    }

    /// Takes the largest visible |value| at simulated time `now` and returns the new Y.
    /// A non-finite maximum (a diverged sample) is ignored.
    pub fn update(&mut self, data_max: f64, now: f64) -> f64 {
        if !data_max.is_finite() {
            return self.limit;
        }
        let target = self.target(data_max);
        if target > self.limit {
            self.limit = target;
            self.low_since = None;
        } else if data_max.abs() < self.settings.shrink_below * self.limit {
            let since = match self.low_since {
                Some(s) if s <= now => s,
                _ => now,
            };
            self.low_since = Some(since);
            if now - since >= self.settings.shrink_after {
                self.limit = target;
                self.low_since = None;
            }
        } else {
            self.low_since = None;
        }
        self.limit
    }
}
