//! Helpers shared by the tests: the session-level ones, and the lag law's arms ([`lag`]).
#![allow(dead_code)]

pub mod lag;
pub mod visit;

use flexarm::session::Session;
use flexarm::view::{Scene, ViewOptions};
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

/// The page's scene at 1280 × 800 after playing `query` for `seconds`, drawn twice as the page
/// draws its frames (some decisions, the scales' and the log switch's, are the frame's).
pub fn drawn_after(query: &str, seconds: f64) -> Scene {
    let mut s = session(query);
    play(&mut s, seconds);
    s.refresh();
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    scene.draw_session(&s);
    scene.draw_session(&s);
    scene
}
