//! Links that start where you want (issue 23, item 1): `t=3&paused=1` in a link or a lesson step
//! advances the runs to t flat out and holds them there; the moment is read once (a restart starts
//! from rest), never written into the page's state string, and "Copy link to this moment" writes
//! a link that comes back to the same instant.

mod common;
use common::play;

use common::Visit;

fn open(query: &str) -> Visit {
    let (s, notices) = Visit::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    s
}

#[test]
fn a_link_to_a_moment_opens_there_paused_and_is_the_run_played_to_it() {
    let mut s = open("preset=fig5.3&t=3&paused=1");
    let t = s.run(0).unwrap().closed_loop().time();
    assert!((3.0..3.0 + 0.01).contains(&t), "t = {t}");
    assert!(s.take_start_paused(), "the page is told to pause");
    assert!(!s.take_start_paused(), "once");
    // The same run, played by frames as the page does, reaches the same state at that time
    // (the loop is deterministic however its time is cut into calls).
    let mut played = open("preset=fig5.3");
    play(&mut played, t);
    let (a, b) = (s.run(0).unwrap().closed_loop().snapshot(), played.run(0).unwrap().closed_loop().snapshot());
    assert!((a.time - b.time).abs() < 1e-9, "{} vs {}", a.time, b.time);
    assert!((a.error[0] - b.error[0]).abs() <= 1e-12 * b.error[0].abs().max(1e-9), "{a:?} vs {b:?}");
    // The page's own state string does not carry the moment: its URL would jump on reload.
    let state = s.state_string();
    assert!(!state.split('&').any(|p| p.starts_with("t=") || p.starts_with("paused=")), "{state}");
    // A restart starts from rest.
    s.reset().unwrap();
    assert_eq!(s.run(0).unwrap().closed_loop().time(), 0.0);
}

#[test]
fn the_link_to_this_moment_comes_back_to_the_same_instant() {
    let mut s = open("preset=fig5.2&speed=2");
    play(&mut s, 1.37);
    let link = s.moment_query();
    assert!(link.contains("&paused=1&t="), "{link}");
    let mut again = open(&link);
    assert!(again.take_start_paused());
    let (t0, t1) = (s.run(0).unwrap().closed_loop().time(), again.run(0).unwrap().closed_loop().time());
    assert!((t0 - t1).abs() < 1e-6, "{t0} vs {t1}");
    assert_eq!(again.settings().a, s.settings().a);
    // Looking back: the moment is the instant looked at.
    s.view_at(0.5);
    let back = s.moment_query();
    let t = back.rsplit("t=").next().unwrap().parse::<f64>().unwrap();
    assert!((t - s.viewing().unwrap()).abs() < 1e-6, "{back}");
}

#[test]
fn a_moment_past_divergence_stops_there_and_bad_values_are_refused_with_a_notice() {
    // Fig. 5.3 diverges after about 4 s: a moment at 100 s stops where the run did.
    let s = open("preset=fig5.3&t=100");
    let run = s.run(0).unwrap().closed_loop();
    assert!(run.is_finished() && run.time() < 100.0, "t = {}", run.time());
    for bad in ["t=-1", "t=1e9", "t=abc", "paused=maybe"] {
        let (s, notices) = Visit::open(&format!("preset=fig5.3&{bad}"));
        assert_eq!(notices.len(), 1, "{bad}: {notices:?}");
        assert_eq!(s.run(0).unwrap().closed_loop().time(), 0.0);
    }
}

#[test]
fn a_lesson_step_can_start_at_a_moment() {
    let text = "# L\n\n## At three seconds\nstate: preset=fig5.3&t=3&paused=1\n\nLook at the errors now.\n";
    let mut s = Visit::open("").0;
    s.load_lesson(flexarm::classroom::progress::LessonOrigin::File("l.md".into()), text.as_bytes()).unwrap();
    assert!(s.run(0).unwrap().closed_loop().time() >= 3.0 - 1e-9);
    assert!(s.take_start_paused());
}
