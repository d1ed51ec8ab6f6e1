//! Helpers shared by the tests: the session-level ones, and the lag law's arms ([`lag`]).
#![allow(dead_code)]

pub mod lag;
pub mod visit;

use flexarm::session::Session;
pub use visit::Visit;

/// The page's session for `query`, which must read without notices.
pub fn session(query: &str) -> Session {
    let (s, notices) = Session::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    s
}

/// The page (session and classroom) for `query`, which must read without notices.
pub fn visit(query: &str) -> Visit {
    let (v, notices) = Visit::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    v
}

/// Plays run A for `seconds` of simulated time (or until it diverges), as the page's frames do.
pub fn play(s: &mut Session, seconds: f64) {
    let t0 = s.run(0).unwrap().closed_loop().time();
    while s.run(0).unwrap().closed_loop().time() < t0 + seconds - 1e-9 && !s.run(0).unwrap().closed_loop().is_finished()
    {
        s.advance(0.05).unwrap();
    }
}
