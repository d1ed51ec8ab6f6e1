//! Helpers shared by the session-level tests.
#![allow(dead_code)]

use flexarm::session::Session;

/// The page's session for `query`, which must read without notices.
pub fn session(query: &str) -> Session {
    let (s, notices) = Session::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    s
}

/// Plays run A for `seconds` of simulated time (or until it diverges), as the page's frames do.
pub fn play(s: &mut Session, seconds: f64) {
    let t0 = s.run(0).unwrap().closed_loop().time();
    while s.run(0).unwrap().closed_loop().time() < t0 + seconds - 1e-9 && !s.run(0).unwrap().closed_loop().is_finished()
    {
        s.advance(0.05).unwrap();
    }
}
