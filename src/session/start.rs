//! A link's moment (issue 23): `t=3&paused=1` in a URL, an embed or a lesson's `state:` line
//! advances the runs to t seconds flat out and holds them there, paused, with the timeline at t.
//! The moment is read once and consumed; "Copy link to this moment" writes it back
//! ([`Session::moment_query`]).

use super::{Session, MAX_ADVANCE_PER_CALL};
use crate::error::Error;

impl Session {
    /// Goes to the moment the settings name, if any, and forgets it (a later restart starts from
    /// rest as usual). Whether to wait there is kept for the page ([`Session::take_start_paused`]).
    pub(super) fn go_to_start(&mut self) -> Result<(), Error> {
        let start = std::mem::take(&mut self.settings.start);
        self.start_paused |= start.paused;
        if start.time > 0.0 {
            self.run_to(start.time)?;
        }
        Ok(())
    }

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

    /// True once after a link or a lesson step asked to start paused (`paused=1`): the page pauses.
    pub fn take_start_paused(&mut self) -> bool {
        std::mem::take(&mut self.start_paused)
    }

    /// The state string with this moment: `…&paused=1&t=3.25` (the instant looked back at, or the
    /// newest), for "Copy link to this moment".
    pub fn moment_query(&self) -> String {
        let t = self.viewing.unwrap_or_else(|| self.a.closed_loop().time());
        format!("{}&paused=1&t={}", self.state_string(), crate::plot::format::sig_trim(t, 6))
    }
}
