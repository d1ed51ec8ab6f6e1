//! A link's moment: `t=3&paused=1` in a URL, an embed or a lesson's `state:` line
//! advances the runs to t seconds flat out and holds them there, paused, with the timeline at t.
//! The moment is read once and consumed; "Copy link to this moment" writes it back
//! ([`Classroom::moment_query`]).

use super::room::Classroom;
use crate::error::Error;
use crate::session::Session;

impl Classroom {
    /// Goes to the moment the session's settings name, if any, and forgets it (a later restart
    /// starts from rest as usual). Whether to wait there is kept for the page
    /// ([`Classroom::take_start_paused`]).
    pub(super) fn go_to_start(&mut self, session: &mut Session) -> Result<(), Error> {
        let start = session.take_start();
        self.start_paused |= start.paused;
        if start.time > 0.0 {
            session.run_to(start.time)?;
        }
        Ok(())
    }

    /// True once after a link or a lesson step asked to start paused (`paused=1`): the page pauses.
    pub fn take_start_paused(&mut self) -> bool {
        std::mem::take(&mut self.start_paused)
    }

    /// The state string with this moment: `…&paused=1&t=3.25` (the instant looked back at, or the
    /// newest), for "Copy link to this moment".
    pub fn moment_query(&self, session: &Session) -> String {
        format!("{}&paused=1&t={}", self.state_string(session), moment_text(session))
    }
}

/// The instant a link to this moment names, as the link writes it (6 figures): the instant looked
/// back at, or the newest.
pub fn moment_text(session: &Session) -> String {
    let t = session.viewing().unwrap_or_else(|| session.run(0).map_or(0.0, |a| a.closed_loop().time()));
    crate::plot::format::significant_trimmed(t, 6)
}
