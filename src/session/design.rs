//! Run A's preliminary feedback as a design: placing its δ → 0 pair by hand (the handle on the
//! pole plot, the arrow keys) writes the twist gains into the settings — the one source of truth —
//! and the design's price is computed on demand: the windows of δ with run A's own inner loop are
//! the session's (with the status); those with the other inner loop and the torque (a simulated
//! slew and poke) once the settings have rested for a status refresh, which a drag would
//! otherwise pay for at every move.

use nalgebra::Complex;

use super::*;
use crate::analysis::design::place_twist;
use crate::control::config::InnerLoop;

use crate::control::config::TwistFeedback;
use crate::control::feedback::{resolve_gain, twist_parts};
use crate::control::price::torque_price;
use crate::words::design::DesignStatus;

/// Significant digits of the gains a placement writes.
pub const GAIN_DIGITS: u32 = 4;

/// How far one arrow-key step moves the pair's target: Re s by this (1/s), Im s by twice it (rad/s).
pub const TARGET_STEP: f64 = 0.5;

impl Session {
    /// The linear settings of run A with the other inner loop, δ normalized away: what the other
    /// line of the price depends on.
    fn other_loop(&self) -> LinearSettings {
        let mut key = self.linear_settings().at(0.0, self.settings.a.alpha);
        key.inner_loop = match key.inner_loop {
            InnerLoop::Continuous => InnerLoop::Sampled,
            InnerLoop::Sampled => InnerLoop::Continuous,
        };
        key
    }

    /// Brings the design's price up to date (with the status; see the module's note): run A's own
    /// windows are the session's; the other inner loop's and the torque follow once the settings
    /// have stayed the same for one refresh, so that a drag pays for one scan of δ per move.
    pub(super) fn refresh_design(&mut self) {
        if self.settings.a.pf == PreliminaryFeedbackChoice::Off {
            return;
        }
        let config = self.settings.a.config();
        if self.design.seen == Some(config) {
            let key = self.other_loop();
            if self.design.other_key != Some(key) {
                let range = schema::DELTA.number().expect("δ is a number").control;
                let mut settings = self.linear_settings();
                settings.inner_loop = key.inner_loop;
                self.design.other = Some(stable_windows(&settings, range).map_err(|e| e.to_string()));
                self.design.other_key = Some(key);
            }
            if self.design.torque_key != Some(config) {
                self.design.torque = Some(torque_price(&config).map_err(|e| e.to_string()));
                self.design.torque_key = Some(config);
            }
        }
        self.design.seen = Some(config);
    }

    /// The design as the page shows it (None without preliminary feedback, while the answers or
    /// the windows are hidden, or before run A's windows are computed).
    pub fn design_status(&self) -> Option<DesignStatus> {
        if self.settings.a.pf == PreliminaryFeedbackChoice::Off {
            return None;
        }
        let own = self.cached_windows()?;
        let other = match (&self.design.other_key, &self.design.other) {
            (Some(k), Some(Ok(w))) if *k == self.other_loop() => Some(w),
            _ => None,
        };
        let config = self.settings.a.config();
        let digital = config.sensors.is_digital();
        let (analog, sampled) = match config.inner_loop {
            // With the sensors on there is one loop, the digital controller's.
            _ if digital => (Some(own), None),
            InnerLoop::Continuous => (Some(own), other),
            InnerLoop::Sampled => (other, Some(own)),
        };
        let torque = match (&self.design.torque_key, &self.design.torque) {
            (Some(k), Some(Ok(t))) if *k == config => Some(t),
            _ => None,
        };
        let report = self.a.analysis().report()?;
        let gain = resolve_gain(&config).ok()?;
        Some(crate::words::design::status(
            config.preliminary_feedback,
            config.inner_loop,
            digital,
            report.limit_pair,
            [analog, sampled],
            torque,
            &twist_parts(&gain),
        ))
    }

    /// Places run A's δ → 0 pair at `re ± j im` (1/s) with the twist feedback: the gains that put
    /// it there (on the arm the controller assumes, as the LQ design) become run A's, with
    /// `pf = twist`, rounded to [`GAIN_DIGITS`] figures. A target no twist feedback in the gains' ranges reaches is refused with the
    /// reason, and nothing changes.
    pub fn place_pair(&mut self, re: f64, im: f64) -> Result<(), Error> {
        let config = self.settings.a.config();
        let q2 = self.linear_settings().rest[1];
        let [stiffness, damping] =
            place_twist(&config.model_plant(), config.controller.alpha, q2, Complex::new(re, im)).map_err(|u| {
                Error::Refused(format!("The pair cannot go there: {}.", crate::words::design::unplaceable(&u)))
            })?;
        self.continue_from_here()?;
        let mut next = self.settings;
        next.a.pf = PreliminaryFeedbackChoice::Twist;
        // Four figures, as a link and the controls show them (the pair moves by < 0.1 %).
        let round = |v: f64| schema::round_significant(v, GAIN_DIGITS);
        next.a.twist = TwistFeedback { stiffness: round(stiffness), damping: round(damping) };
        self.apply(next, false, "")
    }

    /// Moves the pair's target by arrow-key steps: `re_steps` of [`TARGET_STEP`] along Re s,
    /// `im_steps` of twice that along Im s (the keyboard's drag).
    pub fn nudge_pair(&mut self, re_steps: i32, im_steps: i32) -> Result<(), Error> {
        let [re, im] = self.a.analysis().report().ok_or(Error::NotReady("the analysis is not ready"))?.limit_pair[0];
        let step = TARGET_STEP;
        self.place_pair(re + f64::from(re_steps) * step, im.abs() + f64::from(im_steps) * 2.0 * step)
    }
}
