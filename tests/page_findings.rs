//! What a student found on the page (issue 34, items 15–18): each frequency the explanation quotes
//! named as the one it is and computed for the arm shown, a model error named where the settings
//! are, phases said consistently, no dangling phrase, a task counted as the student's only when
//! the student did it, the previous run's ghost of another arm dropped, the ρ(δ) note short
//! enough, the maps' top α labelled.

mod common;

use flexarm::analysis::resonance::JointResonance;
use flexarm::view::{Scene, ViewOptions};
use std::f64::consts::PI;

const PAGE: &str = include_str!("../www/index.html");

/// The page's "In short" paragraph, as written.
fn in_short() -> &'static str {
    let start = PAGE.find("<strong>In short.</strong>").expect("the explanation's short form");
    &PAGE[start..start + PAGE[start..].find("</p>").unwrap()]
}

fn story(query: &str) -> flexarm::words::story::Story {
    common::session(query).status().story.expect("a story")
}

#[test]
fn in_short_the_ringing_is_the_arms_own_frequency_and_a4_is_named_where_it_is_quoted() {
    // The arm alone rings at ω = √(K1 (1/I_r1 + 1/J_eff)); A4's pair as δ → 0 turns at |Im A4|,
    // another number (29.58 against 29.4 rad/s on the paper's arm). The short form speaks of the
    // arm's ringing: it quotes the arm's frequency, not A4's.
    let short = in_short();
    assert!(!short.contains("data-live=\"omega_a4\""), "In short quotes A4's frequency as the arm's: {short}");
    assert!(short.contains("data-live=\"omega_arm\""), "{short}");
    for arm in ["", "&arm=stiffer", "&arm=softer"] {
        let s = common::session(&format!("pf=off{arm}"));
        let plant = s.run(0).unwrap().settings().config().plant;
        let r = JointResonance::new(&plant, [2.0, 2.0], 0.0);
        let st = s.status().story.unwrap();
        // One format for every frequency, each named.
        let hz = |w: f64| format!("{w:.2} rad/s ({:.2} Hz", w / (2.0 * PI));
        // The arm alone rings at its damped pair's frequency (README: −0.29 ± 29.36j on the paper's arm).
        let own = flexarm::analysis::resonance::arm_pair(&plant, 0.0)[0].im.abs();
        assert!(st.omega_arm.starts_with(&hz(own)), "{arm}: {} vs ω = {own}", st.omega_arm);
        assert!(st.omega_arm.contains("the arm alone"), "{}", st.omega_arm);
        assert!(st.omega_joint.starts_with(&hz(r.omega_joint)), "{}", st.omega_joint);
        let a4 = s.run(0).unwrap().analysis().report().unwrap().limit_pair_open[0][1].abs();
        assert!(st.omega_a4.starts_with(&hz(a4)), "{}", st.omega_a4);
        // The loop's own pair at this δ: s with |Im s| of the flexible pair.
        let report = s.run(0).unwrap().analysis().report().unwrap().clone();
        let i = report.flexible_pair()[0].unwrap();
        let w = report.poles[i].continuous.unwrap()[1].abs();
        assert!(st.loop_pair.contains(&format!("{w:.2}j")), "{} vs {w}", st.loop_pair);
    }
    // Where the lag section names the loop's pair at this δ, it quotes it.
    let flat = PAGE.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("the loop's own pair at this δ, in the pole plot, is <span data-live=\"loop_pair\">"));
}

#[test]
fn the_showing_line_names_a_model_error_and_the_a4_row_says_what_its_value_is() {
    let s = common::session("arm=stiffer&model=paper&pf=off&delta=0.01");
    let st = s.status();
    assert!(st.showing.contains("the controller assumes the paper's arm"), "{}", st.showing);
    let a4 = &st.runs[0].readouts.a4;
    assert!(a4.contains("not A4"), "under a model error the δ → 0 limit is not A4: {a4}");
    // Without a model error the value is A4 (with the run's K_pr).
    let known = common::session("arm=stiffer&pf=off&delta=0.01").status();
    assert!(!known.showing.contains("assumes"), "{}", known.showing);
    assert!(known.runs[0].readouts.a4.ends_with("(A4)"), "{}", known.runs[0].readouts.a4);
    let with = common::session("pf=paper&delta=0.01").status();
    assert!(with.runs[0].readouts.a4.ends_with("(A4 with Kₚᵣ)"), "{}", with.runs[0].readouts.a4);
    // The row's label claims nothing the value contradicts.
    assert!(!PAGE.contains("A4 when the controller knows the arm)</th>"), "the row's label");
}

#[test]
fn a_phase_is_said_one_way_and_never_as_zero_degrees_ahead_or_behind() {
    use flexarm::words::story::phase_words;
    for tenth in -1799..=1800 {
        let degrees = tenth as f64 / 10.0;
        let text = phase_words(degrees);
        if degrees.abs() < 0.5 {
            assert_eq!(text, "is in phase with the motor's velocity", "{degrees}°");
        }
        assert!(!text.contains(" 0°"), "{degrees}°: {text}");
        assert!(!text.contains("−") && !text.contains('-'), "{degrees}°: {text}");
    }
    // The computed lag and the law's estimate are named as two things.
    let st = story("pf=off&delta=0.01");
    assert!(st.energy.contains("the lag law estimates"), "{}", st.energy);
}

#[test]
fn the_paper_kpr_sentence_reads_whole_where_kpr_does_not_work() {
    // "The predictor then does its job on the links as before, and <kpr_works>."
    let st = story("pf=paper&alpha=5&delta=0.01");
    let sentence = format!("as before, and {}.", st.kpr_works);
    assert!(!sentence.contains("and not here:"), "{sentence}");
    assert!(PAGE.contains("as before, and <span data-live=\"kpr_works\">"), "the page's sentence around it");
}

#[test]
fn waiting_alone_does_not_complete_a_task() {
    // The first step's task is to play the slew: it opens paused, so only the student's Play
    // makes the time go by.
    let mut v = common::visit("");
    v.lesson_open(0).unwrap();
    assert!(v.classroom.take_start_paused(), "step 1 waits for the student's Play");
    // And a lesson whose task waiting alone meets (a time goal, the step not paused) is refused.
    let text = "# T\n## S\nstate: preset=fig5.1\ntask: Watch.\ngoal: time=1\n\nText.\n";
    let lesson = flexarm::lesson::parse(text).unwrap();
    let e = flexarm::classroom::progress::validate(&lesson).unwrap_err().to_string();
    assert!(e.contains("paused=1"), "{e}");
    let paused = text.replace("preset=fig5.1", "preset=fig5.1&paused=1");
    flexarm::classroom::progress::validate(&flexarm::lesson::parse(&paused).unwrap()).unwrap();
}

#[test]
fn the_ghost_of_a_run_on_another_arm_is_dropped() {
    let mut s = common::session("preset=fig5.3");
    common::play(&mut s, 2.0);
    s.set("delta", "0.05").unwrap();
    s.reset().unwrap();
    assert!(s.ghost().is_some(), "the same arm: the previous run stays, faint");
    common::play(&mut s, 2.0);
    s.read_state("arm=stiffer").unwrap();
    assert!(s.ghost().is_none(), "another arm's errors are on another scale");
    assert_eq!(s.status().ghost, "");
}

#[test]
fn the_rho_curves_note_says_both_alphas_briefly_and_the_maps_top_alpha_is_labelled() {
    let s = common::session("mode=full&alpha1=5&alpha2=2&pf=off&rho=1&map=1");
    let mut seen = 0;
    for (w, h) in [(1280.0, 800.0), (1920.0, 1080.0), (390.0, 844.0)] {
        let mut scene = Scene::new(ViewOptions::default(), w, h, 1.0);
        scene.draw_session(&s);
        let panels = scene.panel_info();
        if let Some(rho) = panels.iter().find(|p| p.id == "rho-curve") {
            assert!(rho.note.contains("α = 5, 2 1/s"), "{}", rho.note);
        }
        // The top of the α axis gets a label, and the page shows it (no other text hides it).
        let labels = scene.labels();
        // The ρ(δ) panel's title names both α whole, never cut to "α1 = 5, α2 = 2…".
        for l in labels.iter().filter(|l| l.panel == "rho-curve" && l.text.starts_with("ρ(δ)")) {
            assert!(l.text.contains("α = 5, 2 1/s") && !l.text.contains('…'), "{w}×{h}: {:?}", l.text);
        }
        for id in ["map-off", "map-on"] {
            let Some(map) = panels.iter().find(|p| p.id == id) else { continue };
            let top = map.y_range[1];
            let last = map.y_labels.last().expect("labels");
            assert!((last.value / top - 1.0).abs() < 1e-9, "{w}×{h} {id}: the top α {top} unlabelled");
            let shown = labels.iter().any(|l| l.panel == id && l.text == last.text && l.x < map.x);
            assert!(shown, "{w}×{h} {id}: the top α's label {:?} is left out", last.text);
            seen += 1;
        }
    }
    assert!(seen > 0, "the maps were drawn");
}

/// `present=1&predict=1` shows Fig. 2.1's zoom without `mode=full` (issue 35, item 3); outside
/// presentation mode the intro still shows the arm and the errors only.
#[test]
fn predict_works_in_presentation_mode_without_the_full_view() {
    let present = common::session("preset=fig5.3&present=1&predict=1");
    assert!(present.drawn_view().predict && !present.settings().view.full);
    let intro = common::session("preset=fig5.3&predict=1");
    assert!(!intro.drawn_view().predict, "the intro keeps to the arm and the errors");
}

/// A download's name says what it shows (issue 35, item 4): the preset, else the key settings.
#[test]
fn a_downloads_name_carries_the_preset_or_the_key_settings() {
    assert_eq!(common::session("preset=fig5.3").file_label(), "fig5.3");
    assert_eq!(common::session("delta=0.02&alpha=5&pf=off").file_label(), "delta0.02-alpha5-pf-off");
    assert_eq!(
        common::session("delta=0.02&alpha1=5&alpha2=2&pf=paper").file_label(),
        "delta0.02-alpha1-5-alpha2-2-pf-paper"
    );
}
