//! Looking back: every run keeps its state at each sampling instant of the last
//! [`HISTORY_SECONDS`]; the session can show any of those instants (the arm, the traces' cursor,
//! the readouts as they were), replay from there, step back and forth one sampling period, and
//! continue from there — exactly, or with a setting changed from that moment on.

use serde::Serialize;

use super::run::HISTORY_SECONDS;
use super::MAX_ADVANCE_PER_CALL;
use super::{CompareSettings, Session};
use crate::control::{ClosedLoop, Snapshot};
use crate::error::Error;
use crate::plot::format::scientific;

/// Where the session looks, for the page's scrubber.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TimelineStatus {
    /// Showing the newest state (not looking back).
    pub live: bool,
    /// The instant shown, s.
    pub time: f64,
    /// The oldest instant that can be shown, s.
    pub start: f64,
    /// The newest (the run's time), s.
    pub end: f64,
    /// What the scrubber shows, in words.
    pub text: String,
}

impl Session {
    /// Advances both runs to A's time `t` (s), flat out, whatever the playback speed; a run that
    /// diverges on the way stops there.
    pub fn run_to(&mut self, t: f64) -> Result<(), Error> {
        if !(t.is_finite() && t >= 0.0) {
            return Err(Error::InvalidDuration(t));
        }
        self.viewing = None;
        let keep = self.trace_seconds;
        loop {
            let now = self.a.closed_loop().time();
            if now >= t - 1e-9 || self.a.closed_loop().is_finished() {
                break;
            }
            let dt = (t - now).min(MAX_ADVANCE_PER_CALL);
            for run in self.runs_mut() {
                run.advance(dt, keep)?;
            }
            if self.a.closed_loop().time() <= now {
                break;
            }
        }
        self.maps.show(&self.linear_settings());
        Ok(())
    }

    /// The run whose clock the timeline follows: the one furthest in time (B goes on alone when
    /// A has diverged in a comparison).
    fn clock(&self) -> &ClosedLoop {
        self.runs().map(|r| r.closed_loop()).max_by(|a, b| a.time().total_cmp(&b.time())).expect("run A")
    }

    /// The instant looked at, or None when showing the newest state.
    pub fn viewing(&self) -> Option<f64> {
        self.viewing
    }

    /// Looks at run A's kept sampling instant at or before `t` (clamped to what is kept); at or
    /// past the newest state, shows that again.
    pub fn view_at(&mut self, t: f64) {
        let history = self.clock().history();
        let now = self.clock().time();
        self.viewing = match history.span() {
            Some([first, _]) if t.is_finite() && t < now - 1e-9 => {
                history.at(t.max(first)).map(|(state, _)| state.time)
            }
            _ => None,
        };
    }

    /// One sampling period back (from the newest state: the instant before it).
    pub fn step_back(&mut self) {
        let history = self.clock().history();
        let from = self.viewing.unwrap_or_else(|| self.clock().time());
        if let Some(t) = history.before(from) {
            self.viewing = Some(t);
        }
    }

    /// While looking back, one sampling period forward; true if it moved the cursor (false: live).
    pub(super) fn step_forward_in_history(&mut self) -> bool {
        let Some(t) = self.viewing else { return false };
        let clock = self.clock();
        self.viewing = clock.history().after(t).filter(|&next| next < clock.time() - 1e-9);
        true
    }

    /// While looking back, plays the kept history forward by `dt` (until it reaches the newest
    /// state); returns the simulated time covered, or None when live.
    pub(super) fn replay(&mut self, dt: f64) -> Option<f64> {
        let t = self.viewing?;
        let now = self.clock().time();
        if t + dt >= now - 1e-9 {
            self.viewing = None;
            return Some(now - t);
        }
        // The newest instant not after t + dt (at least the next one, so that slow play moves).
        let history = self.clock().history();
        let next = history.at(t + dt).map(|(s, _)| s.time).filter(|&s| s > t).or_else(|| history.after(t));
        self.viewing = next;
        Some(next.map_or(now, |n| n) - t)
    }

    /// Continues both runs from the instant looked at: what followed is dropped (kept faint as the
    /// ghost), the settings become those in force then. Does nothing when live.
    pub fn continue_from_here(&mut self) -> Result<(), Error> {
        let Some(t) = self.viewing.take() else { return Ok(()) };
        self.keep_ghost();
        // A run that had already stopped before t (diverged) stays as it was.
        if self.a.closed_loop().time() > t {
            self.a.branch_at(t)?;
            self.settings.a = *self.a.settings();
        }
        if let Some(b) = self.b.as_mut().filter(|b| b.closed_loop().time() > t) {
            b.branch_at(t)?;
            let s = *b.settings();
            // B keeps its arm (the arm is not changed by looking back).
            let arm = self.settings.b.and_then(|b| b.arm);
            self.settings.b = Some(CompareSettings { pf: s.pf, delta: s.delta, alpha: s.alpha, arm });
        }
        let what = if self.b.is_some() { "both runs continue" } else { "the run continues" };
        self.note = format!("Continued from t = {t:.2} s: {what} from there; what followed is the faint grey ghost.");
        Ok(())
    }

    /// Run `index`'s state as shown: at the instant looked at, or the newest.
    pub fn shown_snapshot(&self, index: usize) -> Option<Snapshot> {
        let sim = self.run(index)?.closed_loop();
        // A run that stopped before the instant looked at is shown as it stopped.
        let past = self.viewing.filter(|&t| t < sim.time()).and_then(|t| sim.snapshot_at(t));
        Some(past.unwrap_or_else(|| sim.snapshot()))
    }

    /// The scrubber's state.
    pub fn timeline(&self) -> TimelineStatus {
        let sim = self.clock();
        let now = sim.time();
        let start = sim.history().span().map_or(now, |[first, _]| first);
        let time = self.viewing.unwrap_or(now);
        let text = match self.viewing {
            // Zoomed on one instant the plots follow it: only the scrubber and ◂ move it.
            None if self.settings().view.shown().predict => format!(
                "t = {now:.2} s — the last {:.0} s can be looked at: drag here, or press ◂ to step back one period",
                HISTORY_SECONDS
            ),
            None => format!(
                "t = {now:.2} s — the last {:.0} s can be looked at: drag here or on the error plots, or press ◂",
                HISTORY_SECONDS
            ),
            Some(t) => {
                let e = self.shown_snapshot(0).map_or([f64::NAN; 2], |s| s.error);
                format!(
                    "looking back at t = {t:.2} s (e1 = {}, e2 = {} rad; the run is at {now:.2} s) — Play replays from here; Continue from here, or any change, runs on from here",
                    scientific(e[0], 3),
                    scientific(e[1], 3)
                )
            }
        };
        TimelineStatus { live: self.viewing.is_none(), time, start, end: now, text }
    }
}
