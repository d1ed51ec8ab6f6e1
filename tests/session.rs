//! The session behind the page: settings and state strings, what a change does to the runs,
//! presets, the comparison, map picks, the analyses and maps it keeps, the stable windows.

use flexarm::analysis::spectral_radius;
use flexarm::session::{MapSide, Session, Settings, Source};
use flexarm::{FrictionCompensation, PreliminaryFeedbackChoice as Pf};

fn session(query: &str) -> Session {
    let (s, notices) = Session::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    s
}

/// Runs the session for `seconds` in page-sized steps.
fn play(s: &mut Session, seconds: f64) {
    let t0 = s.run(0).unwrap().closed_loop().time();
    while s.run(0).unwrap().closed_loop().time() < t0 + seconds - 1e-9 && !s.run(0).unwrap().closed_loop().is_finished()
    {
        s.advance(0.1).unwrap();
    }
}

#[test]
fn the_page_opens_on_the_papers_settings_with_a_repeating_slew() {
    let s = session("");
    let a = s.settings().a;
    assert_eq!((a.delta, a.alpha, a.pf, a.repeat), (0.01, [2.0, 2.0], Pf::Paper, true));
    assert!(s.run(1).is_none());
    let (s, notices) = Session::open("?delta=abc&pf=off");
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].text.contains("delta") && notices[0].text.contains("abc"));
    assert_eq!(s.settings().a.pf, Pf::Off);
}

#[test]
fn a_live_change_keeps_the_run_going_and_a_diverged_run_restarts() {
    let mut s = session("delta=0.01&pf=off&repeat=0");
    play(&mut s, 5.0);
    assert!(s.run(0).unwrap().closed_loop().is_finished(), "Fig. 5.3 diverges after ≈ 4.1 s");
    s.set("pf", "paper").unwrap();
    let run = s.run(0).unwrap().closed_loop();
    assert!(!run.is_finished() && run.time() == 0.0, "restarted from rest");
    assert!(s.note().contains("diverged"), "{}", s.note());
    play(&mut s, 0.5);
    s.set("delta", "0.02").unwrap();
    assert!(s.run(0).unwrap().closed_loop().time() > 0.45, "a live change does not restart");
    assert_eq!(s.note(), "");
    // The slew changing under the arm restarts it.
    s.set("repeat", "1").unwrap();
    assert_eq!(s.run(0).unwrap().closed_loop().time(), 0.0);
    // A bad value changes nothing.
    let before = *s.settings();
    assert!(s.set("eps_ratio", "30").is_err());
    assert!(s.set("delta", "-1").is_err());
    assert_eq!(*s.settings(), before);
}

#[test]
fn presets_apply_restart_and_are_recognised() {
    let mut s = session("");
    play(&mut s, 0.3);
    s.apply_preset("fig5.3").unwrap();
    assert_eq!(s.preset().map(|p| p.id), Some("fig5.3"));
    assert_eq!(s.run(0).unwrap().closed_loop().time(), 0.0);
    assert!(s.note().starts_with("Preset applied"), "{}", s.note());
    s.set("delta", "0.02").unwrap();
    assert!(s.preset().is_none(), "a change the preset did not make leaves it");
    s.set("delta", "0.01").unwrap();
    assert_eq!(s.preset().map(|p| p.id), Some("fig5.3"), "and coming back finds it again");
    assert!(s.apply_preset("fig9.9").is_err());
}

#[test]
fn comparing_starts_run_b_with_the_feedback_switched() {
    let mut s = session("delta=0.01&pf=off");
    play(&mut s, 0.3);
    s.set("compare", "1").unwrap();
    let b = s.run(1).expect("run B").settings();
    assert_eq!((b.pf, b.delta, b.repeat), (Pf::Paper, 0.01, true));
    assert_eq!(s.run(0).unwrap().closed_loop().time(), 0.0, "both restart together");
    s.set("b_delta", "0.04").unwrap();
    s.set("friction", "held").unwrap();
    assert_eq!(s.run(1).unwrap().settings().friction, FrictionCompensation::Held, "B follows A's friction");
    assert_eq!(s.run(1).unwrap().settings().delta, 0.04);
    play(&mut s, 0.2);
    let (ta, tb) = (s.run(0).unwrap().closed_loop().time(), s.run(1).unwrap().closed_loop().time());
    assert!((ta - tb).abs() < 0.05, "one clock: {ta} vs {tb}");
    let q = s.state_string();
    assert!(q.contains("compare=1&b_pf=paper&b_delta=0.04&b_alpha=2"), "{q}");
    s.set("compare", "0").unwrap();
    assert!(s.run(1).is_none() && !s.state_string().contains("compare"));
}

#[test]
fn a_map_pick_sets_delta_alpha_and_the_maps_feedback() {
    let mut s = session("pf=lq&delta=0.01");
    s.set_from_map(MapSide::Off, 0.0512345, 1.98765).unwrap();
    let a = s.settings().a;
    assert_eq!((a.delta, a.alpha, a.pf), (0.0512, [1.99, 1.99], Pf::Off));
    s.set_from_map(MapSide::On, 0.3, 9.0).unwrap();
    let a = s.settings().a;
    assert_eq!((a.delta, a.alpha, a.pf), (0.25, [5.0, 5.0], Pf::Paper), "kept within the controls; the paper's K_pr");
}

#[test]
fn the_analysis_follows_what_changes_rho_only() {
    let mut s = session("delta=0.01&pf=off");
    let rho = s.run(0).unwrap().analysis().report().unwrap().spectral_radius;
    assert!(rho > 1.0);
    let mut cache = s.run(0).unwrap().analysis().clone();
    let mut c = s.settings().a.config();
    c.friction_compensation = FrictionCompensation::Off;
    c.reference.repeat_hold = None;
    assert!(!cache.update(&c), "friction and the slew do not change ρ");
    c.controller.sampling_period = 0.04;
    assert!(cache.update(&c));
    s.set("pf", "paper").unwrap();
    let r = s.run(0).unwrap().analysis().report().unwrap();
    assert!(r.spectral_radius < 1.0);
    assert_eq!(r.spectral_radius, spectral_radius(&s.settings().a.config(), None).unwrap());
}

#[test]
fn the_maps_fill_in_and_are_reused() {
    let mut s = session("delta=0.01&pf=off");
    let mut clock = 0.0;
    let mut tick = || {
        clock += 1.0;
        clock
    };
    let mut calls = 0;
    while s.maps_mut().work(&mut tick, 5.0) {
        calls += 1;
        assert!(calls < 1000);
    }
    let status = s.maps().status();
    assert!(status.done && status.percent == 100, "{status:?}");
    assert!(status.text.starts_with("map: 6000 points in"), "{}", status.text);
    assert_eq!(s.maps().times().len(), 2);
    let off = s.maps().shown(MapSide::Off).unwrap().job();
    assert!(off.values().iter().all(|r| r.is_finite()));
    // ρ on the map is ρ of the settings at that cell.
    let (d, a) = (off.deltas()[40], off.alphas()[45]);
    let mut point = s.settings().a;
    point.delta = d;
    point.alpha = [a, a];
    assert!((s.maps().rho_at(MapSide::Off, d, a) - spectral_radius(&point.config(), None).unwrap()).abs() < 1e-12);
    // δ, α and the paper's feedback do not change which maps are needed.
    s.set("delta", "0.04").unwrap();
    s.set("pf", "paper").unwrap();
    assert!(!s.maps().pending());
    // The LQ design needs its own map on the right.
    s.set("pf", "lq").unwrap();
    assert!(s.maps().pending());
    assert_eq!(s.maps().shown(MapSide::On).unwrap().feedback(), Pf::Lq);
    // Hidden maps do no work.
    s.maps_mut().enabled = false;
    assert!(!s.maps_mut().work(&mut tick, 5.0));
}

#[test]
fn the_stable_windows_without_feedback_are_bracketed_by_rho() {
    let mut s = session("delta=0.01&alpha=2&pf=off");
    let w = s.windows().unwrap().clone();
    // About 0.035–0.101 s, 0.107–0.116 s and 0.163–0.224 s at α = 2 (a fine grid of ρ).
    let expected = [[0.0350, 0.1007], [0.1069, 0.1161], [0.1627, 0.2236]];
    assert_eq!(w.windows.len(), expected.len(), "{w:?}");
    for (got, want) in w.windows.iter().zip(expected) {
        assert!((got[0] - want[0]).abs() < 5e-4 && (got[1] - want[1]).abs() < 5e-4, "{got:?} vs {want:?}");
    }
    let rho = |d: f64| {
        let mut p = s.settings().a;
        p.delta = d;
        spectral_radius(&p.config(), None).unwrap()
    };
    for [lo, hi] in &w.windows {
        let t = w.tolerance;
        assert!(rho(lo - t) > 1.0 && rho(lo + t) < 1.0, "edge at {lo}");
        assert!(rho(hi - t) < 1.0 && rho(hi + t) > 1.0, "edge at {hi}");
    }
    // With the paper's feedback: one window from the smallest δ.
    s.set("pf", "paper").unwrap();
    let w = s.windows().unwrap();
    assert_eq!(w.windows[0][0], 0.002, "{w:?}");
}

#[test]
fn the_state_string_the_command_line_and_the_csv_say_the_same() {
    let mut s = session("delta=0.04&alpha=1.5&pf=off&friction=held");
    play(&mut s, 0.5);
    let q = s.state_string();
    assert!(
        q.starts_with("delta=0.04&alpha=1.5&pf=off&friction=held&inner=continuous&repeat=1&k=12&eps_ratio=8"),
        "{q}"
    );
    let cmd = s.command_line();
    assert!(
        cmd.starts_with("flexarm simulate --delta 0.04 --alpha 1.5 --pf off --friction held --repeat --duration 0.5"),
        "{cmd}"
    );
    let mut back = Settings::default();
    back.read(&q, Source::CommandLine).unwrap();
    assert_eq!(back.a, s.settings().a);
    let csv = s.csv();
    assert!(csv.starts_with(&format!("# flexarm state: {}", s.settings().run_query())), "{}", &csv[..100]);
}
