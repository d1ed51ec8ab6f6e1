//! An embed you control (issue 23, item 7): `views=` names exactly the panels shown, the arm and
//! the errors included; a panel that cannot fit is announced, never dropped silently; the strip's
//! controls are a checked list; the builder's snippet carries its choices, checked, and a lesson
//! step can be embedded.

mod common;
use common::visit as session;

use flexarm::error::Error;
use flexarm::session::view::Strip;
use flexarm::session::{Session, ViewSettings};
use flexarm::view::layout::Arrangement;
use flexarm::view::{Layout, LayoutOptions, PanelKind, Scene, Tab, ViewOptions};
use flexarm::words::panels::hidden_note;

use PanelKind::*;

/// The panels a scene of `query` lays out on a canvas of `w × h`.
fn panels(query: &str, w: f64, h: f64) -> Vec<PanelKind> {
    let s = session(query);
    let mut scene = Scene::new(ViewOptions::default(), w, h, 1.0);
    scene.draw_session(&s);
    scene.layout().panels.iter().map(|p| p.kind).collect()
}

#[test]
fn views_names_exactly_the_panels_shown_the_arm_and_the_errors_included() {
    // The lists, and the panels each must show — nothing more (a large canvas: all fit).
    let cases: [(&str, &[PanelKind]); 7] = [
        ("zplane,rho", &[ZPlane, RhoCurve]),
        ("arm", &[Arm]),
        ("traces", &[Error1, Error2]),
        ("traces,torque", &[Error1, Error2, Torque]),
        ("arm,traces", &[Arm, Error1, Error2]),
        ("map", &[MapOff, MapOn]),
        ("arm,poles,map", &[Arm, Poles, MapOff, MapOn]),
    ];
    for (list, want) in cases {
        for (w, h) in [(1280.0, 800.0), (1920.0, 1080.0), (760.0, 1000.0)] {
            assert_eq!(panels(&format!("preset=fig5.3&embed=1&views={list}"), w, h), want, "views={list} at {w}×{h}");
        }
    }
    // Two runs: both arms, or neither.
    assert_eq!(panels("preset=fig5.3&embed=1&compare=1&views=arm,rho", 1280.0, 800.0), [Arm, ArmB, RhoCurve]);
    assert_eq!(panels("preset=fig5.3&embed=1&compare=1&views=traces", 1280.0, 800.0), [Error1, Error2]);
    // The zoom on one sampling instant adds the torques on the page, not in an embed that did
    // not ask for them.
    assert_eq!(panels("preset=fig5.3&embed=1&views=arm,traces&predict=1", 1280.0, 800.0), [Arm, Error1, Error2]);
    assert_eq!(
        panels("preset=fig5.3&mode=full&poles=0&rho=0&map=0&predict=1", 1280.0, 800.0),
        [Arm, Error1, Error2, Torque]
    );
    // The page's intro and full view draw the arm and its errors whatever the switches say (the
    // full page an embed's "Open flexarm ↗" opens has them back).
    assert_eq!(panels("preset=fig5.3&picture=0&errors=0", 1280.0, 800.0), [Arm, Error1, Error2]);
    assert_eq!(panels("preset=fig5.3&views=zplane", 1280.0, 800.0), [Arm, Error1, Error2, ZPlane]);
}

#[test]
fn a_views_list_that_names_no_panel_is_a_typed_error() {
    for list in ["", ",", " , "] {
        let mut v = ViewSettings::default();
        match v.read_views(list) {
            Err(Error::Parse(e)) => {
                assert_eq!(e.key, "views");
                assert!(e.expected.contains("at least one figure"), "{}", e.expected);
            }
            other => panic!("views={list:?}: {other:?}"),
        }
        assert_eq!(v, ViewSettings::default(), "a bad list changes nothing");
    }
    let (s, notices) = Session::open("embed=1&views=");
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert_eq!(notices[0].key, "views");
    assert!(s.settings().view.picture && s.settings().view.errors, "the view stays as it was");
}

#[test]
fn the_strip_is_a_checked_list_written_back_in_the_state_string() {
    let s = session("preset=fig5.3&embed=1&strip=delta,reset");
    let strip = s.settings().view.strip;
    for (name, on) in [("play", false), ("reset", true), ("delta", true), ("alpha", false), ("pf", false)] {
        assert_eq!(strip.has(name), on, "{name}");
    }
    // Written back (in the strip's own order), so a reload or "Open flexarm" keeps it …
    let q = s.state_string();
    assert!(q.contains("strip=reset%2Cdelta"), "{q}");
    assert_eq!(session(&q).settings().view.strip, strip);
    // … and left out at the default (Play and K_pr, as the strip always had).
    assert_eq!(Strip::read("play,pf").unwrap(), Strip::DEFAULT);
    assert!(!session("preset=fig5.3&embed=1").state_string().contains("strip="));
    // An empty list: the verdict and the link alone.
    assert_eq!(Strip::read("").unwrap().text(), "");
    let (s, notices) = Session::open("embed=1&strip=play,volume");
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert_eq!(notices[0].key, "strip");
    assert!(notices[0].text.contains("a list of play, reset, delta, alpha, pf"), "{}", notices[0].text);
    assert_eq!(s.settings().view.strip, Strip::DEFAULT, "a bad list changes nothing");
}

#[test]
fn a_panel_that_cannot_fit_is_announced_with_the_tab_it_is_on() {
    let all = LayoutOptions::default();
    // An embed 640 × 400 with every panel: its canvas (about 630 × 340 px) cannot show them all
    // readably; the analysis panels go to their tabs, and the notice says so.
    let small = Layout::compute(632.0, 340.0, 1.0, &all);
    assert_eq!(small.arrangement, Arrangement::Tabbed);
    assert_eq!(small.hidden(&all), [Poles, RhoCurve, MapOff, MapOn]);
    let note = hidden_note(&small.hidden(&all)).expect("a notice");
    assert!(note.starts_with("The pole plot, ρ(δ) and the stability maps do not fit"), "{note}");
    assert!(note.contains("“Poles and ρ(δ)” and “Stability maps”"), "{note}");
    // On the maps' tab, the run and the poles are the ones away.
    let maps = Layout::compute(632.0, 340.0, 1.0, &LayoutOptions { tab: Tab::Maps, ..all });
    assert_eq!(maps.hidden(&all), [Arm, Error1, Error2, Poles, RhoCurve]);
    let note = hidden_note(&maps.hidden(&all)).unwrap();
    assert!(note.starts_with("The arm, the errors, the pole plot and ρ(δ) do not fit"), "{note}");
    // A large canvas shows them all: nothing to say.
    let large = Layout::compute(1264.0, 740.0, 1.0, &all);
    assert!(large.hidden(&all).is_empty() && hidden_note(&[]).is_none());
    // One panel: "does".
    assert_eq!(
        hidden_note(&[ZPlane]).unwrap(),
        "The z-plane does not fit beside the rest at this size: see the tab “Poles and ρ(δ)” (or open flexarm ↗)"
    );
    // Panels on a single tab are never tabbed, however small: nothing is away.
    let rho_only = LayoutOptions { show_arm: false, show_errors: false, show_map: false, ..all };
    let l = Layout::compute(300.0, 200.0, 1.0, &rho_only);
    assert!(l.tabs.is_empty() && l.hidden(&rho_only).is_empty(), "{:?}", l.tabs);
}

#[test]
fn the_builders_snippet_carries_its_choices_and_opens_as_chosen() {
    let s = session("preset=fig5.3&mode=full");
    let e = s
        .embed(
            "https://example.org/flexarm/index.html?delta=1#x",
            "views=zplane,rho&width=760&height=480&paused=1&t=3&strip=delta,reset",
        )
        .unwrap();
    assert_eq!((e.width, e.height), (760, 480));
    assert!(e.html.starts_with("<iframe src=\"https://example.org/flexarm/index.html?delta=0.01&amp;"), "{}", e.html);
    assert!(e.html.contains("width=\"760\" height=\"480\""), "{}", e.html);
    let query = e.src.split_once('?').unwrap().1;
    for part in ["embed=1", "picture=0", "errors=0", "plane=z", "map=0", "strip=reset%2Cdelta", "paused=1", "t=3"] {
        assert!(query.split('&').any(|p| p == part), "{part} in {query}");
    }
    // Opened, it shows exactly those panels, at t = 3 s, paused, with that strip.
    let mut opened = session(query);
    assert!((opened.run(0).unwrap().closed_loop().time() - 3.0).abs() < 0.01);
    assert!(opened.take_start_paused());
    assert!(opened.settings().view.strip.has("delta") && !opened.settings().view.strip.has("play"));
    let mut scene = Scene::new(ViewOptions::default(), 1200.0, 700.0, 1.0);
    scene.draw_session(&opened.session);
    let kinds: Vec<PanelKind> = scene.layout().panels.iter().map(|p| p.kind).collect();
    assert_eq!(kinds, [ZPlane, RhoCurve]);
    // Without choices: what is on screen, 640 × 400, playing.
    let plain = s.embed("https://example.org/flexarm/", "").unwrap();
    assert_eq!((plain.width, plain.height), (640, 400));
    assert!(!plain.src.contains("paused=") && !plain.src.contains("&t="), "{}", plain.src);
    let defaults = s.embed_defaults();
    assert!(defaults.starts_with("views=arm,traces,poles,rho,map&width=640&height=400&strip=play,pf&"), "{defaults}");
    // The form's limits are the ones the session holds to: the smallest size is taken, one pixel
    // less is refused.
    let limit = |k: &str| defaults.split('&').find_map(|kv| kv.strip_prefix(&format!("{k}="))).unwrap().to_string();
    let (w0, h0) = (limit("min_width"), limit("min_height"));
    assert!(s.embed("https://example.org/", &format!("width={w0}&height={h0}")).is_ok());
    let below: u32 = w0.parse::<u32>().unwrap() - 1;
    assert!(s.embed("https://example.org/", &format!("width={below}&height={h0}")).is_err());
    // From the intro: its arm and errors, not the analysis its switches hold for the full view.
    let intro = session("preset=fig5.3").embed("https://example.org/", "").unwrap();
    let q = intro.src.split_once('?').unwrap().1;
    assert_eq!(panels(q, 1280.0, 800.0), [Arm, Error1, Error2], "{q}");
}

#[test]
fn every_bad_choice_is_an_error_naming_it() {
    let s = session("preset=fig5.3&mode=full");
    for (choices, key) in [
        ("width=100", "width"),
        ("height=5000", "height"),
        ("width=7.5", "width"),
        ("views=nothing", "views"),
        ("views=", "views"),
        ("strip=volume", "strip"),
        ("t=-1", "t"),
        ("t=1e9", "t"),
        ("paused=maybe", "paused"),
        ("lesson=0.5", "lesson"),
        ("lesson=99", "lesson"),
        ("colour=red", "colour"),
    ] {
        match s.embed("https://example.org/", choices) {
            Err(Error::Parse(e)) => assert_eq!(e.key, key, "{choices}: {e}"),
            other => panic!("{choices}: {other:?}"),
        }
    }
}

#[test]
fn a_lesson_step_embeds_with_its_own_settings() {
    let s = session("preset=fig5.2&delta=0.04&mode=full");
    let e = s.embed("https://example.org/flexarm/index.html", "lesson=4&views=arm,traces&strip=play,reset").unwrap();
    let query = e.src.split_once('?').unwrap().1;
    assert!(e.title.starts_with("flexarm: lesson step 4, Inside one period"), "{}", e.title);
    assert!(query.starts_with("lesson=4&embed=1&views=arm%2Ctraces&strip=play%2Creset"), "{query}");
    assert!(!query.contains("delta="), "the step sets the run, not the page's settings: {query}");
    let opened = session(query);
    let step = opened.lesson_status().expect("the lesson is open");
    assert_eq!(step.index, 3);
    let v = opened.settings().view;
    assert!(v.embed && v.picture && v.errors && !v.poles && !v.rho && !v.map, "{v:?}");
    // The step's run (Fig. 5.3's settings), not the page's δ = 0.04 s.
    assert_eq!(opened.settings().a, session("lesson=4").settings().a);
    assert_eq!(opened.settings().a.delta, 0.01);
}

/// A panel left out leaves no empty room: the panels shown, with their label gutters, reach
/// across the canvas and from its top to its bottom (the arm alone fills it, the plots alone
/// start at the top).
#[test]
fn the_panels_shown_fill_the_canvas() {
    use flexarm::view::layout::gutters;
    let lists = ["arm", "traces", "traces,torque", "zplane,rho", "map", "traces,map", "arm,rho", "arm,traces,zplane"];
    for list in lists {
        for (w, h) in [(760.0, 420.0), (1280.0, 800.0), (390.0, 700.0), (640.0, 340.0), (600.0, 900.0)] {
            let s = session(&format!("preset=fig5.3&embed=1&views={list}"));
            let mut scene = Scene::new(ViewOptions::default(), w, h, 1.0);
            scene.draw_session(&s);
            let (mut left, mut top, mut right, mut bottom) = (f64::MAX, f64::MAX, 0.0f64, 0.0f64);
            for p in &scene.layout().panels {
                let [l, t, r, b] = gutters(p.kind);
                left = left.min(p.rect.x - l);
                top = top.min(p.rect.y - t);
                right = right.max(p.rect.right() + r);
                bottom = bottom.max(p.rect.bottom() + b);
            }
            assert!(left <= 10.0 && top <= 10.0, "views={list} at {w}×{h}: starts at ({left}, {top})");
            assert!(right >= w - 10.0 && bottom >= h - 10.0, "views={list} at {w}×{h}: ends at ({right}, {bottom})");
        }
    }
}

/// The embed's strip says the verdict in its short form (issue 35, item 5): the headline and the
/// detail's first clause, from the same words as the page's verdict — short enough for a 760-px
/// strip (about 40 characters beside its buttons) for every preset, stable or not.
#[test]
fn the_short_verdict_is_the_headline_and_the_details_first_clause() {
    for preset in flexarm::session::presets::PRESETS {
        let mut s = common::session(&format!("preset={}", preset.id));
        common::play(&mut s, 2.0);
        s.refresh();
        let r = &s.status().runs[0];
        assert!(r.short.starts_with(&format!("{}: ", r.headline)), "{}: {}", preset.id, r.short);
        let clause = &r.short[r.headline.len() + 2..];
        assert!(r.detail.starts_with(clause), "{}: '{}' is not the start of '{}'", preset.id, clause, r.detail);
        assert!(r.short.chars().count() <= 40, "{}: {} characters: {}", preset.id, r.short.chars().count(), r.short);
        // Presentation mode's verdict on a short screen: the same clause after the headline.
        assert_eq!(r.detail_short, clause, "{}", preset.id);
    }
}

/// The figure's description for screen readers names only what is drawn (issue 35, item 5): an
/// embed of ρ(δ) alone says nothing of the arm or the errors.
#[test]
fn the_description_covers_only_what_is_shown() {
    let all = session("preset=fig5.3&embed=1&views=arm,traces,rho").figure_text();
    assert!(all.contains("the arm") && all.contains("the errors are") && all.contains("ρ along δ"), "{all}");
    let rho = session("preset=fig5.3&embed=1&views=rho").figure_text();
    assert!(rho.contains("ρ along δ"), "{rho}");
    assert!(!rho.contains("arm") && !rho.contains("the errors are") && !rho.contains("e1, e2"), "{rho}");
}
