//! The timeline (issue 10): a run keeps its state at every sampling instant of the recent past,
//! can be looked at as it was, and continued from any of those instants exactly — the loop is
//! deterministic, so continuing without a change repeats what happened, to the last bit.

mod common;
use common::{play, session};

use flexarm::control::{ClosedLoop, PreliminaryFeedbackChoice, SimulationConfig};

fn config(delta: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
    c.controller.sampling_period = delta;
    c
}

fn with_history(c: SimulationConfig, seconds: f64) -> ClosedLoop {
    let mut sim = ClosedLoop::new(c).unwrap();
    sim.keep_history(seconds);
    sim
}

#[test]
fn continuing_from_a_past_instant_repeats_the_run_exactly() {
    // Fig. 5.3: the unstable case, where any difference would grow.
    let mut sim = with_history(config(0.01, PreliminaryFeedbackChoice::Off), 30.0);
    sim.advance(3.0).unwrap();
    let original_end = sim.snapshot();
    let original_traces = sim.traces().clone();
    let then = sim.snapshot_at(1.5).expect("1.5 s is kept");
    assert!((then.time - 1.5).abs() < 1e-9, "1.5 s is a sampling instant: {}", then.time);
    // The state looked at is the state the run had: the traces recorded it then.
    let i = original_traces.t().iter().position(|&t| (t - then.time).abs() < 1e-9).unwrap();
    assert_eq!(then.error, [original_traces.e1()[i], original_traces.e2()[i]]);

    let at = sim.branch_at(1.5).unwrap();
    assert_eq!(at, then.time);
    assert_eq!(sim.snapshot(), then, "continuing starts from exactly the state looked at");
    assert!(sim.traces().t().last().unwrap() <= &(at + 1e-9), "the later traces are gone");
    sim.advance(3.0 - at).unwrap();
    assert_eq!(sim.snapshot(), original_end, "the same run, to the last bit");
    assert_eq!(sim.traces(), &original_traces);
}

#[test]
fn a_branch_can_take_another_setting_from_that_instant() {
    let mut sim = with_history(config(0.01, PreliminaryFeedbackChoice::Off), 30.0);
    sim.advance(3.5).unwrap();
    let e_unstable = sim.snapshot().error[1].abs();
    sim.branch_at(2.0).unwrap();
    sim.set_config(config(0.01, PreliminaryFeedbackChoice::Paper)).unwrap();
    sim.advance(1.5).unwrap();
    assert!(sim.snapshot().error[1].abs() < 0.1 * e_unstable, "the feedback switched on at 2 s calms the arm");
    // Back before the switch, the old configuration is in force again.
    sim.branch_at(1.0).unwrap();
    assert_eq!(sim.config().preliminary_feedback, PreliminaryFeedbackChoice::Off);
}

#[test]
fn stepping_through_the_instants_and_the_span_is_bounded() {
    let mut sim = with_history(config(0.002, PreliminaryFeedbackChoice::Paper), 5.0);
    sim.advance(2.0).unwrap();
    let capacity = sim.history().capacity();
    sim.advance(10.0).unwrap();
    let h = sim.history();
    let [first, last] = h.span().unwrap();
    assert!(last - first <= 5.0 + 1e-9 && last - first > 5.0 - 0.003, "{first}..{last}");
    assert!(h.len() <= (5.0 / 0.002) as usize + 2, "{}", h.len());
    assert_eq!(h.capacity(), capacity, "no allocation once warm");
    let before = h.before(last).unwrap();
    assert!((last - before - 0.002).abs() < 1e-9);
    assert_eq!(h.after(before), Some(last));
    assert_eq!(h.after(last), None);
    assert!(h.at(first - 1.0).is_none(), "older than kept");
    assert!(sim.snapshot_at(first - 1.0).is_none());
}

#[test]
fn a_diverged_run_can_be_continued_from_before_it_diverged() {
    let mut sim = with_history(config(0.01, PreliminaryFeedbackChoice::Off), 30.0);
    sim.advance(8.0).unwrap();
    assert!(sim.is_finished());
    sim.branch_at(3.0).unwrap();
    assert!(!sim.is_finished());
    sim.set_config(config(0.01, PreliminaryFeedbackChoice::Paper)).unwrap();
    sim.advance(5.0).unwrap();
    assert!(!sim.is_finished(), "rescued at 3 s");
}

#[test]
fn without_history_nothing_is_kept() {
    let mut sim = ClosedLoop::new(config(0.01, PreliminaryFeedbackChoice::Paper)).unwrap();
    sim.advance(1.0).unwrap();
    assert!(sim.history().is_empty());
    assert!(sim.branch_at(0.5).is_err());
}

// ------------------------------------------------------------------ the session's timeline

use flexarm::view::{Scene, ViewOptions};

#[test]
fn the_page_looks_back_steps_and_replays_without_changing_the_run() {
    let mut s = session("preset=fig5.3");
    play(&mut s, 3.0);
    let now = s.run(0).unwrap().closed_loop().time();
    let live = s.run(0).unwrap().closed_loop().snapshot();
    assert!(s.timeline().live);
    s.view_at(1.234);
    let t = s.viewing().unwrap();
    assert!(t <= 1.234 && t > 1.234 - 0.01, "the sampling instant at or before: {t}");
    let status = s.status();
    assert!(!status.timeline.live && status.timeline.time == t && status.timeline.end == now);
    assert!(status.runs[0].readouts.time.contains("looking back"), "{}", status.runs[0].readouts.time);
    assert!(status.timeline.text.contains(&format!("{t:.2}")), "{}", status.timeline.text);
    // Step back and forth by one sampling period.
    s.step_back();
    assert!((s.viewing().unwrap() - (t - 0.01)).abs() < 1e-9);
    s.step_period();
    assert!((s.viewing().unwrap() - t).abs() < 1e-9);
    // Playing replays the kept past, then the run goes on from where it was.
    s.advance(0.1).unwrap();
    assert!(s.viewing().unwrap() > t);
    assert_eq!(s.run(0).unwrap().closed_loop().snapshot(), live, "replaying does not run the loop");
    s.view_at(now + 1.0);
    assert!(s.viewing().is_none(), "past the newest state: live again");
}

#[test]
fn continuing_from_a_past_instant_in_the_page_is_exact_and_a_change_there_branches() {
    let mut s = session("preset=fig5.3");
    play(&mut s, 2.5);
    s.view_at(1.5);
    let then = s.shown_snapshot(0).unwrap();
    s.continue_from_here().unwrap();
    assert_eq!(s.run(0).unwrap().closed_loop().snapshot(), then, "the same numbers as the instant looked at");
    assert!(s.ghost().is_some(), "what followed stays as the ghost");
    assert!(s.note().contains("1.50"), "{}", s.note());
    // Looking back to 2 s and switching the feedback on there continues with it from 2 s.
    play(&mut s, 1.0);
    s.view_at(2.0);
    s.set("pf", "paper").unwrap();
    assert!(s.viewing().is_none());
    let sim = s.run(0).unwrap().closed_loop();
    assert!((sim.time() - 2.0).abs() < 1e-9, "continued from 2 s: {}", sim.time());
    assert!(s.state_string().contains("pf=paper"));
    play(&mut s, 4.0);
    assert!(!s.run(0).unwrap().closed_loop().is_finished(), "rescued before it diverged");
}

#[test]
fn a_view_change_while_looking_back_keeps_looking() {
    let mut s = session("preset=fig5.3&mode=full");
    play(&mut s, 2.0);
    s.view_at(1.0);
    s.set("plane", "z").unwrap();
    assert!(s.viewing().is_some());
}

#[test]
fn the_scene_draws_the_instant_looked_at_with_a_cursor_and_maps_pointer_to_time() {
    let mut s = session("preset=fig5.2");
    play(&mut s, 14.0);
    let mut scene = Scene::new(ViewOptions::default(), 1200.0, 700.0, 1.0);
    scene.draw_session(&s);
    let live_window = scene.time_window();
    s.view_at(3.0);
    scene.draw_session(&s);
    let w = scene.time_window();
    assert_eq!(scene.cursor(), s.viewing());
    assert!(w.start <= 3.0 && 3.0 <= w.end && w.start < live_window.start, "{w:?} vs {live_window:?}");
    let panels = scene.panel_info();
    let e1 = panels.iter().find(|p| p.id == "e1").unwrap();
    let x = e1.x + (3.0 - w.start) / w.width() * e1.width;
    let t = scene.time_at(x, e1.y + e1.height / 2.0).unwrap();
    assert!((t - 3.0).abs() < 1e-9, "{t}");
    assert!(scene.time_at(e1.x - 50.0, e1.y - 50.0).is_none());
}

#[test]
fn comparing_the_timeline_follows_the_run_that_goes_on() {
    // A (no K_pr) diverges after about 4 s; B (K_pr) goes on alone.
    let mut s = session("preset=fig5.3&compare=1");
    play_both(&mut s, 7.0);
    let (a, b) = (s.run(0).unwrap().closed_loop().time(), s.run(1).unwrap().closed_loop().time());
    assert!(s.run(0).unwrap().closed_loop().is_finished() && b > a + 2.0, "A at {a}, B at {b}");
    let t = s.timeline();
    assert_eq!(t.end, b, "the timeline ends where B is, not where A stopped");
    s.view_at(b - 1.0);
    assert!(s.viewing().is_some());
    assert_eq!(s.shown_snapshot(0).unwrap().time, s.run(0).unwrap().closed_loop().snapshot().time, "A as it stopped");
    s.continue_from_here().unwrap();
    assert!(s.run(0).unwrap().closed_loop().is_finished(), "A had stopped before that instant and stays stopped");
    assert!((s.run(1).unwrap().closed_loop().time() - (b - 1.0)).abs() < 0.011);
}

/// Plays until run B has run `seconds` (A may stop first).
fn play_both(s: &mut flexarm::session::Session, seconds: f64) {
    while s.run(1).unwrap().closed_loop().time() < seconds {
        s.advance(0.05).unwrap();
    }
}
