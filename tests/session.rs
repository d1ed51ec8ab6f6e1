//! The session behind the page: settings and state strings, what a change does to the runs,
//! presets, the comparison, map picks, the analyses and maps it keeps, the stable windows.

mod common;
use common::{play, session};

use flexarm::analysis::spectral_radius;
use flexarm::session::{MapSide, Session, Settings, Source};
use flexarm::{plot::format::escape, view::figure::figure_svg, FrictionCompensation, PreliminaryFeedbackChoice as Pf};

/// Runs the session for `seconds` in page-sized steps.

#[test]
fn the_page_opens_on_fig_5_3_named_in_the_intro_with_a_repeating_slew() {
    // Issue 10: the cold open is the case the page is about, and says which figure it is.
    let s = session("");
    let a = s.settings().a;
    assert_eq!((a.delta, a.alpha, a.pf, a.repeat), (0.01, [2.0, 2.0], Pf::Off, true));
    assert_eq!(s.status().preset, "fig5.3");
    assert!(!s.settings().view.full, "beginners first");
    assert!(s.run(1).is_none());
    let (s, notices) = Session::open("?delta=abc&pf=paper");
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].text.contains("delta") && notices[0].text.contains("abc"));
    assert_eq!(s.settings().a.pf, Pf::Paper);
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
    assert!(!cache.update(&c, 0.0), "friction and the slew do not change ρ");
    c.controller.sampling_period = 0.04;
    assert!(cache.update(&c, 0.0));
    s.set("pf", "paper").unwrap();
    let r = s.run(0).unwrap().analysis().report().unwrap();
    assert!(r.spectral_radius < 1.0);
    assert_eq!(r.spectral_radius, spectral_radius(&s.settings().a.config(), None).unwrap());
}

#[test]
fn the_maps_fill_in_and_are_reused() {
    let mut s = session("delta=0.01&pf=off&mode=full");
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
    // Hidden maps do no work: the intro view hides them.
    s.set("mode", "intro").unwrap();
    assert!(!s.maps().pending());
    s.set("mode", "full").unwrap();
    s.set("map", "0").unwrap();
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

// ------------------------------------------------------------ issue 9: an honest verdict

/// The words of a status, for checking what a student reads.
fn words(s: &flexarm::session::RunStatus) -> String {
    format!("{} {} {} {}", s.headline, s.detail, s.observed, s.rho)
}

fn has_word(text: &str, word: &str) -> bool {
    text.split(|c: char| !c.is_alphanumeric()).any(|w| w.eq_ignore_ascii_case(word))
}

#[test]
fn fig_5_3_is_called_unstable_from_the_first_frame_and_the_simulation_confirms_it_within_2_s() {
    let mut s = session("preset=fig5.3");
    assert!(s.settings().a.repeat, "the page's repeating slew");
    let first = s.status().runs[0].clone();
    assert_eq!((first.verdict, first.headline), ("unstable", "Unstable"));
    assert!(
        first.detail.starts_with("ρ = 1.0239 > 1 — in the long run the errors grow e-fold every 0.42 s"),
        "{}",
        first.detail
    );
    let mut confirmed_at = None;
    while s.run(0).unwrap().closed_loop().time() < 6.0 && !s.run(0).unwrap().closed_loop().is_finished() {
        s.advance(0.05).unwrap();
        let st = &s.status().runs[0];
        assert!(!has_word(&words(st), "stable"), "t = {}: {}", st.readouts.time, words(st));
        assert!(matches!(st.verdict, "unstable" | "diverged"));
        if confirmed_at.is_none() && st.measured {
            confirmed_at = Some(s.run(0).unwrap().closed_loop().time());
            assert!(st.observed.contains("matches ln ρ/δ = 2.36 1/s"), "{}", st.observed);
        }
    }
    let t = confirmed_at.expect("the observation came");
    assert!(t <= 2.0, "observed growth shown at t = {t} s, before the divergence (≈ 4 s)");
}

#[test]
fn every_presets_verdict_agrees_with_rho_from_the_first_frame() {
    for p in flexarm::session::PRESETS {
        let s = session(&format!("preset={}", p.id));
        let st = &s.status().runs[0];
        let rho = st.spectral_radius.unwrap();
        let want = if rho < 1.0 { "stable" } else { "unstable" };
        assert_eq!(st.verdict, want, "{}: ρ = {rho}", p.id);
        assert!(has_word(st.headline, want), "{}: {}", p.id, st.headline);
        assert!(p.title.to_lowercase().contains("unstable") == (want == "unstable") || p.id != "fig5.3");
    }
}

#[test]
fn a_stable_run_is_confirmed_and_a_borderline_one_is_called_so() {
    let mut s = session("delta=0.01&pf=paper");
    while !s.status().runs[0].measured {
        s.advance(0.05).unwrap();
    }
    let st = &s.status().runs[0];
    assert_eq!(st.verdict, "stable");
    assert!(st.detail.contains("shrink e-fold every"), "{}", st.detail);
    assert!(st.observed.contains("1/s —") && !st.observed.contains("but"), "{}", st.observed);
    // ρ within a hair of 1: neither word. (At α = 2 without K_pr, near the window's edge.)
    let mut s = session("delta=0.03501&pf=off&alpha=2");
    let st = &s.status().runs[0];
    assert_eq!(st.verdict, "borderline", "{}", st.detail);
    assert!(st.detail.contains("≈ 1"), "{}", st.detail);
    s.set("delta", "0.05").unwrap();
    assert_eq!(s.status().runs[0].verdict, "stable");
}

#[test]
fn a_change_after_divergence_restarts_and_keeps_the_old_run_as_a_ghost() {
    let mut s = session("preset=fig5.3");
    play(&mut s, 6.0);
    assert_eq!(s.status().runs[0].verdict, "diverged");
    assert!(s.status().runs[0].observed.contains("as ρ > 1 predicted"), "{}", s.status().runs[0].observed);
    s.set("pf", "paper").unwrap();
    let st = s.status();
    assert_eq!(st.runs[0].verdict, "stable", "the verdict belongs to the settings on screen");
    assert_eq!(s.run(0).unwrap().closed_loop().time(), 0.0);
    let ghost = s.ghost().expect("the diverged run stays as a ghost");
    assert!(ghost.settings.starts_with("no K_pr, δ = 0.01 s"), "{}", ghost.settings);
    assert!(ghost.traces.t().last().unwrap() > &4.0 && ghost.traces.e2().len() == ghost.traces.t().len());
    assert!(st.ghost.contains("previous run"), "{}", st.ghost);
    // A preset no longer erases the previous run either.
    play(&mut s, 1.0);
    s.apply_preset("fig5.1").unwrap();
    assert!(s.ghost().unwrap().settings.starts_with("paper K_pr, δ = 0.01 s"));
}

#[test]
fn a_live_change_starts_the_numbers_afresh() {
    let mut s = session("delta=0.04&pf=paper&repeat=0");
    play(&mut s, 1.5);
    let slew = s.run(0).unwrap().closed_loop().metrics().max_error_slew;
    assert!(slew[0] > 1e-3, "the slew's errors at δ = 0.04 s: {slew:?}");
    s.set("delta", "0.01").unwrap();
    play(&mut s, 0.2);
    let m = s.run(0).unwrap().closed_loop().metrics();
    assert_eq!(m.max_error_slew, [0.0, 0.0], "no slew since the change: the old maxima are not shown as the new");
    assert!(m.max_error_after[0] < slew[0]);
}

#[test]
fn the_windows_status_says_them_in_words_and_as_slider_bands() {
    let mut s = session("delta=0.01&alpha=2&pf=off");
    assert!(s.status().windows.is_none(), "computed on demand");
    s.refresh();
    let w = s.status().windows.unwrap();
    assert!(
        w.text.starts_with(
            "Without preliminary feedback (α = 2 1/s) the loop is stable only for 0.0350 s < δ < 0.1007 s, 0.1068 s < δ < 0.1161 s and 0.1627 s < δ < 0.2236 s"
        ),
        "{}",
        w.text
    );
    assert_eq!(w.bands.len(), 3);
    for ([lo, hi], [p0, p1]) in w.windows.iter().zip(&w.bands) {
        let spec = flexarm::schema::DELTA.number().unwrap();
        assert!((spec.position(*lo) - p0).abs() < 1e-12 && (spec.position(*hi) - p1).abs() < 1e-12 && p0 < p1);
    }
    s.set("pf", "paper").unwrap();
    assert!(s.status().windows.is_none(), "stale after a change that matters");
    s.refresh();
    assert!(s
        .status()
        .windows
        .unwrap()
        .text
        .starts_with("With paper K_pr (α = 2 1/s) the loop is stable only for δ < 0.2240 s"));
    // δ does not matter to the windows.
    s.set("delta", "0.02").unwrap();
    assert!(s.status().windows.is_some());
}

#[test]
fn the_page_exports_the_clis_figures_and_an_embed_snippet() {
    let mut s = session("preset=fig5.3&mode=full");
    play(&mut s, 1.0);
    let svg = figure_svg(&s, "errors", false).unwrap().svg;
    assert!(svg.starts_with("<svg") && svg.contains("Tracking errors") && svg.contains("(unstable)"), "{}", &svg[..99]);
    assert!(svg.contains(&escape(&s.settings().run_query())), "the state string in the figure");
    let e = figure_svg(&s, "maps", false).unwrap_err().to_string();
    assert!(e.starts_with("the stability maps are still being computed"), "{e}");
    let mut tick = 0.0;
    let mut clock = || {
        tick += 1.0;
        tick
    };
    while s.maps_mut().work(&mut clock, 50.0) {}
    let maps = figure_svg(&s, "maps", false).unwrap().svg;
    assert!(maps.contains("no Kₚᵣ") && maps.contains("paper Kₚᵣ"), "both maps, captioned");
    let snippet = flexarm::classroom::Classroom::default()
        .embed(&s, "https://example.org/flexarm/index.html?x=1#top", "")
        .unwrap()
        .html;
    assert!(snippet.starts_with("<iframe src=\"https://example.org/flexarm/index.html?delta=0.01"), "{snippet}");
    assert!(snippet.contains("embed=1") && snippet.contains("width=\"640\" height=\"400\""), "{snippet}");
    assert!(snippet.contains("&amp;"), "the query is escaped in the attribute: {snippet}");
    let (embedded, notices) = Session::open("preset=fig5.3&embed=1&views=arm,traces,zplane");
    assert!(notices.is_empty(), "{notices:?}");
    let v = embedded.settings().view.shown();
    assert!(v.embed && v.poles && v.z_plane && !v.map && !v.rho && !v.torque, "{v:?}");
    let (_, notices) = Session::open("views=arm,everything");
    assert!(notices[0].text.contains("a list of arm, traces"), "{notices:?}");
}

#[test]
fn the_keyboard_moves_the_point_on_a_map_through_round_values() {
    let mut s = session("preset=fig5.2&mode=full");
    s.step_on_map(MapSide::Off, 1, 0).unwrap();
    let a = s.settings().a;
    assert_eq!((a.delta, a.alpha, a.pf), (0.012, [2.0, 2.0], Pf::Off), "one step right on the map without K_pr");
    s.step_on_map(MapSide::On, 0, -1).unwrap();
    let a = s.settings().a;
    assert_eq!((a.delta, a.alpha[0], a.pf), (0.012, 1.5, Pf::Paper), "one step down on the map with K_pr");
}

#[test]
fn a_lesson_link_reads_each_url_value_once() {
    // Issue 12: the settings after `lesson=N` were decoded, joined and decoded again, so an
    // encoded `&` inside a value smuggled in a second setting.
    let (plain, _) = Session::open("lesson=2");
    let (s, notices) = Session::open("lesson=2&pf=off%26delta%3D0.2");
    assert_eq!(s.settings().a.delta, plain.settings().a.delta, "no δ = 0.2 from inside pf's value");
    assert_eq!(s.settings().a.pf, plain.settings().a.pf);
    assert!(notices.iter().any(|n| n.key == "pf" && n.text.contains("'off&delta=0.2'")), "{notices:?}");
    // "0.0%25350" is the text "0.0%350" (not a number), not "0.050" decoded twice.
    let (s, notices) = Session::open("lesson=2&delta=0.0%25350");
    assert_ne!(plain.settings().a.delta, 0.05);
    assert_eq!(s.settings().a.delta, plain.settings().a.delta, "{notices:?}");
}

/// The page names a limit cycle as the CLI and the JSON do — "bounded oscillation" — with its
/// amplitude and period, says why ρ < 1 could not show it, and never calls the held-friction
/// hunting unstable once the cycle is recognised; a settled stable run says its growth is "none
/// (errors at their floor)".
#[test]
fn the_page_names_a_limit_cycle_and_a_settled_run_as_the_cli_does() {
    let mut s = common::session("delta=0.04&alpha=2&pf=paper&friction=held&repeat=0");
    common::play(&mut s, 45.0);
    let st = &s.status().runs[0];
    let m = s.run(0).unwrap().closed_loop().metrics();
    assert!(matches!(m.verdict, flexarm::Verdict::BoundedOscillation { .. }), "{:?}", m.verdict);
    assert_eq!(st.verdict, "bounded oscillation");
    assert_eq!(st.headline, "Bounded oscillation");
    assert!(st.observed.contains("limit cycle") && st.observed.contains("held over δ"), "{}", st.observed);
    // ρ takes the friction as cancelled: with held compensation it does not describe the run, and
    // the line under the headline says so instead of offering ρ as a second verdict.
    assert!(st.detail.starts_with("the simulation decides"), "{}", st.detail);
    assert!(st.rho.contains("not this run's friction") && !st.rho.contains("⇒"), "{}", st.rho);
    // Held friction is not the paper's Fig. 5.1 and is named, and the preset puts the paper's
    // model back.
    assert!(!s.status().showing.contains("Fig. 5.1"), "{}", s.status().showing);
    assert!(s.status().showing.ends_with("friction compensation held"), "{}", s.status().showing);
    s.apply_preset("fig5.1").unwrap();
    assert!(s.status().showing.starts_with("Fig. 5.1"), "{}", s.status().showing);
    assert!(s.state_string().contains("friction=continuous"), "{}", s.state_string());

    let mut s = common::session("delta=0.01&alpha=2&pf=paper&friction=continuous&repeat=0");
    common::play(&mut s, 30.0);
    let st = &s.status().runs[0];
    assert_eq!(st.verdict, "stable");
    assert_eq!(st.readouts.growth, "none (errors at their floor)");
    assert!(st.observed.contains("settled at their floor"), "{}", st.observed);
}

/// ρ is computed with the friction cancelled (issue 22): where the run's friction is not — the
/// compensation off or held — ρ does not decide the headline and is never cited as the cause of
/// what the simulation shows; with the compensation continuous it is.
#[test]
fn where_rho_does_not_describe_the_run_it_is_not_cited() {
    let cites_rho =
        |text: &str| text.contains("ρ predict") || text.contains("ρ > 1 predicted") || text.contains("matches");
    let mut s = common::session("delta=0.01&alpha=2&pf=off&friction=off&repeat=0");
    let st = &s.status().runs[0];
    assert_eq!((st.verdict, st.headline), ("too early to tell", "Too early to tell"), "not ρ's 'Unstable'");
    assert!(
        st.rho.contains("friction cancelled, not this run's friction") && st.rho.contains("q2 = 0 rad"),
        "{}",
        st.rho
    );
    common::play(&mut s, 4.0);
    let st = &s.status().runs[0];
    assert!(!cites_rho(&st.observed) && !cites_rho(&st.detail), "{} / {}", st.observed, st.detail);
    assert!(st.observed.contains("F_c1/ε1 = 48\u{202f}200 N m/rad"), "the presliding spring is named: {}", st.observed);
    // Uncompensated, the friction holds the arm far off the path: the errors after the slew stay
    // hundreds of times larger than Fig. 5.3's before it diverges.
    let m = s.run(0).unwrap().closed_loop().metrics();
    assert!(m.max_error_after[1] > 0.1, "{:?}", m.max_error_after);

    let mut s = common::session("delta=0.01&alpha=2&pf=off&friction=off&repeat=1");
    common::play(&mut s, 10.0);
    let st = &s.status().runs[0];
    assert_eq!(st.verdict, "diverged");
    // ρ, with the friction cancelled, points the same way, and says it is not the verdict.
    assert!(st.observed.contains("points the same way") && !cites_rho(&st.observed), "{}", st.observed);

    // With the friction cancelled, ρ decides from the first frame and explains the divergence.
    let mut s = common::session("preset=fig5.3&repeat=0");
    assert_eq!(s.status().runs[0].headline, "Unstable");
    assert!(s.status().runs[0]
        .rho
        .starts_with("linear analysis (at rest at q2 = 0 rad, friction cancelled): ρ = 1.0239 > 1"));
    common::play(&mut s, 6.0);
    assert!(s.status().runs[0].observed.contains("as ρ > 1 predicted"), "{}", s.status().runs[0].observed);
}

/// `rest=arm`: the analysis follows the arm between the repeating slew's two rest points (q2 = 0
/// and 3π/2 rad), and says where it is linearized; `rest=end` (the default, left out of links)
/// stays at the slew's end.
#[test]
fn the_analysis_can_follow_the_arm_between_its_rest_points() {
    let mut s = common::session("preset=fig5.2&repeat=1&rest=arm");
    assert!(s.state_string().contains("rest=arm"), "{}", s.state_string());
    let at_end = s.run(0).unwrap().analysis().report().unwrap().clone();
    assert_eq!(at_end.rest[1], 0.0);
    common::play(&mut s, 3.0);
    let back = s.run(0).unwrap().analysis().report().unwrap().clone();
    assert!((back.rest[1] - 1.5 * std::f64::consts::PI).abs() < 1e-12, "{:?}", back.rest);
    assert!(back.spectral_radius != at_end.spectral_radius, "cos q2 changes the linearization");
    assert!(s.status().runs[0].rho.contains("q2 = 4.71 rad"), "{}", s.status().runs[0].rho);
    common::play(&mut s, 2.5);
    assert_eq!(s.run(0).unwrap().analysis().report().unwrap().rest[1], 0.0, "and back again");

    let mut s = common::session("preset=fig5.3&repeat=1");
    assert!(!s.state_string().contains("rest="), "{}", s.state_string());
    common::play(&mut s, 3.0);
    assert_eq!(s.run(0).unwrap().analysis().report().unwrap().rest[1], 0.0);
}

/// The reasons the verdict gives are the physics' (issue 22's cold trial): a stable loop whose
/// slowest mode outlasts the time between slews is the response to the slews, not a nonlinear
/// oscillation; a rate too slow to show is "too early", not "far from rest"; a decay slower
/// than ln ρ/δ is not blamed on "the slowest mode, which takes over later".
#[test]
fn the_verdicts_reasons_are_the_physics() {
    let nonlinear = |t: &str| t.contains("nonlinear");
    // α = 0.2 without K_pr: ρ < 1 with a 12-s e-folding, re-excited every 2.5 s.
    let mut s = common::session("delta=0.01&alpha=0.2&pf=off&repeat=1");
    let mut seen_locked = false;
    for _ in 0..24 {
        common::play(&mut s, 1.0);
        let st = &s.status().runs[0];
        assert_eq!(st.headline, "Stable", "t = {}: {}", s.run(0).unwrap().closed_loop().time(), st.observed);
        assert!(!nonlinear(&st.observed), "{}", st.observed);
        if st.observed.contains("come back about as large after every slew") {
            seen_locked = true;
            assert!(st.observed.contains("dies out by e only every 12 s"), "{}", st.observed);
        }
    }
    assert!(seen_locked);
    let m = s.run(0).unwrap().closed_loop().metrics();
    assert!(matches!(m.verdict, flexarm::Verdict::SlewLocked { .. }), "{:?}", m.verdict);
    // The same loop after one slew: near rest, a slow rate is too early to see.
    let mut s = common::session("delta=0.01&alpha=0.2&pf=off&repeat=0");
    for _ in 0..20 {
        common::play(&mut s, 1.0);
        let st = &s.status().runs[0];
        assert!(!nonlinear(&st.observed), "{}", st.observed);
    }
    // Decaying slower than ln ρ/δ is never put down to the slowest mode taking over later.
    for preset in ["fig5.1", "fig5.2", "large-delta"] {
        let mut s = common::session(&format!("preset={preset}&repeat=1"));
        for _ in 0..12 {
            common::play(&mut s, 1.0);
            let st = &s.status().runs[0];
            let (g, p) = (s.run(0).unwrap().closed_loop().metrics().growth_rate, st.growth_rate.unwrap());
            if g.is_some_and(|g| g > p) {
                assert!(!st.observed.contains("takes over later"), "{preset}: {}", st.observed);
            }
        }
    }
}

/// A steady envelope near rest is not a limit cycle where ρ describes the run: α = 0.5 without
/// K_pr grows slowly (ρ > 1) while the slew's transient dies out, and the page says it is too
/// early to tell — never that a nonlinearity bounds it.
#[test]
fn a_flat_envelope_near_rest_is_too_early_not_a_limit_cycle() {
    let mut s = common::session("delta=0.01&alpha=0.5&pf=off&repeat=0");
    let mut early = false;
    for _ in 0..8 {
        common::play(&mut s, 0.5);
        let st = &s.status().runs[0];
        assert_eq!(st.headline, "Unstable", "{}", st.observed);
        assert!(!st.observed.contains("nonlinearity bounds it"), "{}", st.observed);
        assert!(!st.observed.contains("limit cycle"), "{}", st.observed);
        early |= st.observed.contains("too early to tell");
    }
    assert!(early, "the flat stretch is called too early to tell");
}

/// The second cold trial's cases: a nearly undamped pair near a window's edge is what ρ ≈ 1 says,
/// not a nonlinear effect; with the friction held the hunting is "too early to tell" until the
/// cycle is recognised, never "unstable" and "stable" in turn; with it off, no green "Stable"
/// while the errors are far from rest.
#[test]
fn the_headline_never_flips_on_one_behaviour() {
    let mut s = common::session("delta=0.035&pf=off&repeat=1");
    for _ in 0..30 {
        common::play(&mut s, 1.0);
        let st = &s.status().runs[0];
        assert_eq!(st.headline, "Borderline", "{}", st.observed);
        assert!(!st.observed.contains("nonlinear"), "{}", st.observed);
        assert!(!st.observed.contains("dies out by e only"), "ρ > 1 by a hair here: {}", st.observed);
    }
    let mut s = common::session("preset=fig5.2&friction=held&repeat=0");
    let mut headlines = Vec::new();
    for _ in 0..60 {
        common::play(&mut s, 1.0);
        let h = s.status().runs[0].headline;
        if headlines.last() != Some(&h) {
            headlines.push(h);
        }
    }
    // It only ever becomes more definite: too early, bounded (near rest), then the cycle named.
    let order = ["Too early to tell", "Bounded", "Bounded oscillation"];
    let ranks: Vec<usize> =
        headlines.iter().map(|h| order.iter().position(|o| o == h).expect("no other word")).collect();
    assert!(ranks.windows(2).all(|w| w[0] < w[1]), "one behaviour, one judgement at a time: {headlines:?}");
    let mut s = common::session("delta=0.01&alpha=2&pf=off&friction=off&repeat=1");
    for _ in 0..40 {
        common::play(&mut s, 0.25);
        let st = &s.status().runs[0];
        let e = s.run(0).unwrap().closed_loop().snapshot().error;
        if e[0].abs().max(e[1].abs()) > 0.05 {
            assert_ne!(st.headline, "Stable", "errors {e:?}: {}", st.observed);
        }
    }
}

/// A δ typed beyond the slider's span, but within the limits, is taken — and said (issue 20).
#[test]
fn a_value_typed_beyond_the_slider_is_taken_and_said() {
    let mut s = common::session("delta=0.01&pf=paper");
    s.set("delta", "0.5").unwrap();
    assert_eq!(s.settings().a.delta, 0.5);
    let note = s.status().note;
    assert!(note.contains("δ = 0.5 s is outside the slider's 0.002–0.25 s"), "{note}");
    s.set("delta", "0.02").unwrap();
    assert!(!s.status().note.contains("outside the slider"), "{}", s.status().note);
}

/// Readouts that would mean nothing say so: no "max after the slew" before the reference has
/// rested, no growth rate of a diverged run; with the friction off, near rest, the simulation
/// calls the run bounded, not stable (issue 22's third trial).
#[test]
fn readouts_and_words_say_nothing_they_cannot() {
    let mut s = common::session("preset=fig5.3&repeat=0");
    common::play(&mut s, 0.5);
    assert!(s.status().runs[0].readouts.max_after.starts_with('—'), "{}", s.status().runs[0].readouts.max_after);
    common::play(&mut s, 6.0);
    let st = &s.status().runs[0];
    assert_eq!(st.verdict, "diverged");
    assert_eq!(st.readouts.growth, "— (diverged)");
    let mut s = common::session("delta=0.01&alpha=2&pf=off&friction=off&repeat=0");
    common::play(&mut s, 20.0);
    assert_eq!(s.status().runs[0].headline, "Bounded", "{}", s.status().runs[0].observed);
}
