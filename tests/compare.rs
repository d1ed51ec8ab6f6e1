//! Comparing two runs reads at a glance (issue 23 item 5): when the runs' errors differ by more
//! than a decade — the paper's Fig. 5.3 (no K_pr, growing) beside Fig. 5.2 (K_pr, settling) — the
//! shared error axes turn logarithmic by themselves and say so; close runs stay linear; a chosen
//! log |e| stays chosen.

mod common;
use common::{drawn_after, session};

use flexarm::view::panels::time_plots::compare::{wants_log, AUTO_LOG_NOTE};
use flexarm::view::{PanelKind, Scene};

fn e1_scale(scene: &Scene) -> (&'static str, String) {
    let e1 = scene.panel_info().into_iter().find(|p| p.id == PanelKind::Error1.id()).expect("e1 shown");
    (e1.y_scale, e1.note)
}

#[test]
fn a_growing_run_beside_a_settling_one_is_shown_on_log_axes() {
    // Fig. 5.3 grows as ρⁿ with ρ = 1.024 per 0.01 s (e^{2.36 t}); Fig. 5.2 settles: by 6 s the
    // slew's errors of A are more than ten times B's.
    let scene = drawn_after("preset=fig5.3&mode=full&compare=1&b_pf=paper", 6.0);
    assert!(scene.auto_log(), "Fig. 5.3 beside Fig. 5.2 at 6 s should turn log");
    let (scale, note) = e1_scale(&scene);
    assert_eq!(scale, "log");
    assert!(note.contains(AUTO_LOG_NOTE), "the axis says why: {note}");
    assert!(scene.legend().iter().any(|g| g.title.contains("differ by more than 10×")), "the key says why");
}

#[test]
fn close_runs_stay_linear_and_a_chosen_log_stays_chosen() {
    // Both stable with K_pr, δ = 0.01 and 0.02 s: errors of the same order.
    let scene = drawn_after("preset=fig5.2&mode=full&compare=1&b_pf=paper&b_delta=0.02", 6.0);
    assert!(!scene.auto_log());
    assert_eq!(e1_scale(&scene).0, "linear");
    // One run alone never turns by itself, however it grows.
    let alone = drawn_after("preset=fig5.3&mode=full", 6.0);
    assert!(!alone.auto_log());
    assert_eq!(e1_scale(&alone).0, "linear");
    // log=1 chosen: log, without the automatic note.
    let chosen = drawn_after("preset=fig5.3&mode=full&compare=1&b_pf=paper&log=1", 6.0);
    assert!(!chosen.auto_log());
    let (scale, note) = e1_scale(&chosen);
    assert_eq!(scale, "log");
    assert!(!note.contains(AUTO_LOG_NOTE), "{note}");
}

#[test]
fn the_switch_has_hysteresis_and_ignores_runs_without_errors() {
    assert!(wants_log(1.0, 0.05, false));
    assert!(!wants_log(1.0, 0.2, false));
    // Between 5× and 10× the current choice stays.
    assert!(wants_log(1.0, 0.15, true));
    assert!(!wants_log(1.0, 0.15, false));
    assert!(!wants_log(1.0, 0.3, true));
    assert!(wants_log(1.0, 0.0, true) && !wants_log(f64::NAN, 1.0, false));
}

#[test]
fn starting_a_comparison_says_so_not_that_the_arm_changed() {
    let mut s = session("preset=fig5.3&mode=full");
    s.set("compare", "1").unwrap();
    let note = s.status().note;
    assert!(note.contains("Comparing two runs"), "{note}");
    assert!(!note.contains("arm changed"), "{note}");
    // Another arm for B while comparing is another arm.
    s.set("b_arm", "softer").unwrap();
    assert!(s.status().note.contains("arm changed"), "{}", s.status().note);
}
