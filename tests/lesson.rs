//! The guided lesson (issue 10), walked natively: every step sets the simulator up as its text
//! says, every question can be answered and shows what the paper and the physics say, "back"
//! restores the previous step as it was left, a link reopens the same step, and the numbers the
//! lesson quotes are the program's.

mod common;
use common::{play, visit as session};

use common::Visit;
use flexarm::analysis::analyze;
use flexarm::lesson::{builtin, LESSON_TEXT};
use flexarm::*;

/// Run A's verdict as the page states it.
fn verdict(s: &Visit) -> &'static str {
    s.status().runs[0].verdict
}

/// The step whose title contains `words` (0-based).
fn step_index(words: &str) -> usize {
    builtin().unwrap().steps.iter().position(|s| s.title.contains(words)).unwrap_or_else(|| panic!("no step {words:?}"))
}

#[test]
fn every_step_asks_to_act_or_to_predict_and_there_are_at_least_six() {
    let lesson = builtin().unwrap();
    assert!(lesson.steps.len() >= 6);
    for s in &lesson.steps {
        assert!(s.question.is_some() || s.goal.is_some(), "step {:?} neither asks nor sets a task", s.title);
    }
}

#[test]
fn the_whole_lesson_can_be_walked_and_back_restores_the_step_as_left() {
    let mut s = session("");
    s.lesson_open(0).unwrap();
    let count = builtin().unwrap().steps.len();
    for i in 0..count {
        let status = s.status().lesson.expect("the lesson is open");
        assert_eq!(status.index, i);
        assert!(s.state_string().ends_with(&format!("lesson={}", i + 1)), "{}", s.state_string());
        assert!(s.settings().view.full, "the lesson shows the full view");
        // Do what the step asks.
        if let Some(q) = &status.question {
            assert!(status.answer.is_empty(), "no answer before the prediction");
            let wrong =
                (0..q.choices.len()).find(|&c| c != builtin().unwrap().steps[i].question.as_ref().unwrap().correct);
            s.lesson_answer(wrong.unwrap()).unwrap();
            let after = s.status().lesson.unwrap();
            let q = after.question.unwrap();
            assert_eq!(q.chosen, wrong, "the prediction is remembered");
            assert!(q.correct.is_some() && q.correct != wrong);
            assert!(!after.answer.is_empty(), "the answer is shown with its reason");
            let settled = *s.settings();
            s.lesson_answer(q.correct.unwrap()).unwrap();
            assert_eq!(s.status().lesson.unwrap().question.unwrap().chosen, wrong, "the first prediction stays");
            assert_eq!(*s.settings(), settled, "and the step is not set up again");
        }
        if status.task.is_some() {
            assert!(!status.done);
            match i {
                0 => play(&mut s, 3.6),
                _ if i == step_index("Find where") => s.set("delta", "0.05").unwrap(),
                _ if i == step_index("Compare") => s.set("compare", "1").unwrap(),
                // The pair dragged left of the axis (the page's handle calls the same).
                _ if i == step_index("Place the pair") => s.place_pair(-3.0, 29.0).unwrap(),
                _ => panic!("a new task: teach this test how to do it"),
            }
            s.refresh();
            let after = s.status().lesson.unwrap();
            assert!(after.done, "step {i}: the goal is recognised");
            assert!(!after.answer.is_empty());
        }
        if i + 1 < count {
            let left = *s.settings();
            s.lesson_next().unwrap();
            s.lesson_back().unwrap();
            assert_eq!(*s.settings(), left, "back restores step {i} as it was left");
            assert_eq!(s.status().lesson.unwrap().index, i);
            s.lesson_next().unwrap();
        } else {
            assert!(s.lesson_next().is_err(), "no step after the last");
        }
    }
    // Leaving keeps the settings to explore from.
    let before = *s.settings();
    s.lesson_leave();
    assert!(s.status().lesson.is_none());
    assert_eq!(*s.settings(), before);
    assert!(!s.state_string().contains("lesson="));
}

#[test]
fn the_predictions_are_answered_by_what_the_simulator_then_shows() {
    let mut s = session("");
    // Sampling 4× as often: stable, errors more than ten times smaller (Figs. 5.1 → 5.2).
    s.lesson_open(step_index("four times")).unwrap();
    assert_eq!(s.settings().a.delta, 0.04);
    play(&mut s, 1.2);
    let before = s.run(0).unwrap().closed_loop().metrics().max_error_slew;
    s.lesson_answer(0).unwrap();
    assert_eq!(s.settings().a.delta, 0.01);
    play(&mut s, 1.2);
    let after = s.run(0).unwrap().closed_loop().metrics().max_error_slew;
    assert_eq!(verdict(&s), "stable");
    assert!(before[0] > 10.0 * after[0] && before[1] > 10.0 * after[1], "{before:?} vs {after:?}");

    // Without K_pr it shakes apart (Fig. 5.3), as ρ said from the first frame.
    s.lesson_open(step_index("helper away")).unwrap();
    assert_eq!(verdict(&s), "stable");
    s.lesson_answer(0).unwrap();
    assert_eq!(verdict(&s), "unstable");
    play(&mut s, 6.0);
    assert_eq!(verdict(&s), "diverged");
    let fast = s.status().runs[0].growth_rate.unwrap();

    // A smaller α: still unstable, slower.
    s.lesson_open(step_index("gentler")).unwrap();
    s.lesson_answer(0).unwrap();
    assert_eq!(s.settings().a.alpha, [0.5, 0.5]);
    assert_eq!(verdict(&s), "unstable");
    assert!(s.status().runs[0].growth_rate.unwrap() < fast / 5.0);

    // The fix: K_pr on, stable.
    s.lesson_open(step_index("The fix")).unwrap();
    assert_eq!(verdict(&s), "unstable");
    s.lesson_answer(1).unwrap();
    assert_eq!(verdict(&s), "stable");
    assert_eq!(s.settings().a.pf, PreliminaryFeedbackChoice::Paper);
}

#[test]
fn the_windows_stay_hidden_until_the_student_finds_one() {
    let mut s = session("");
    s.lesson_open(step_index("Find where")).unwrap();
    s.refresh();
    assert!(s.status().windows.is_none() && s.cached_windows().is_none(), "hidden while guessing");
    s.set("delta", "0.02").unwrap();
    s.refresh();
    assert!(!s.status().lesson.unwrap().done, "δ = 0.02 s is unstable");
    s.set("delta", "0.07").unwrap();
    s.refresh();
    assert!(s.status().lesson.unwrap().done);
    assert_eq!(s.status().windows.clone().unwrap().windows.len(), 3, "revealed: three windows at α = 2");
    // "Show me" reveals them too, and puts δ in a window, so the answer describes what is shown.
    let mut s = session("");
    s.lesson_open(step_index("Find where")).unwrap();
    s.lesson_reveal().unwrap();
    s.refresh();
    assert!(s.status().windows.is_some());
    assert_eq!(verdict(&s), "stable");
    assert_eq!(s.settings().a.pf, PreliminaryFeedbackChoice::Off);
}

/// "Show me" on a task does the task: the answer it reveals describes what is on screen.
#[test]
fn show_me_does_every_task_it_reveals() {
    let lesson = builtin().unwrap();
    for (i, step) in lesson.steps.iter().enumerate().filter(|(_, st)| st.task.is_some()) {
        let mut s = session("");
        s.lesson_open(i).unwrap();
        s.lesson_reveal().unwrap();
        s.refresh();
        let goal = step.goal.as_ref().unwrap();
        if goal.time.is_some() {
            continue; // "play until t" is shown by playing
        }
        assert!(step.show.is_some(), "step {} ({}) reveals an answer without doing its task", i + 1, step.title);
        if let Some(v) = &goal.verdict {
            assert_eq!(verdict(&s), v, "step {}", i + 1);
        }
        for (key, value) in &goal.settings {
            let now = s.settings().get(key).map(|v| v.text());
            assert_eq!(now.as_deref(), Some(value.as_str()), "step {}: {key}", i + 1);
        }
    }
}

#[test]
fn a_link_reopens_the_same_step_with_the_same_settings() {
    let mut s = session("?lesson=5");
    assert_eq!(s.status().lesson.unwrap().index, 4);
    assert!(s.settings().view.z_plane);
    s.set("alpha", "1.5").unwrap();
    let link = s.state_string();
    let again = session(&link);
    assert_eq!(again.status().lesson.unwrap().index, 4);
    assert_eq!(again.settings(), s.settings());
    let (_, notices) = Visit::open("lesson=abc");
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].text.contains("step number"), "{}", notices[0].text);
    // Beyond the last step: the last step, and a notice that says so; the last step itself
    // opens without one.
    let count = builtin().unwrap().steps.len();
    let (last, notices) = Visit::open("lesson=99");
    assert_eq!(last.status().lesson.unwrap().index, count - 1);
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert_eq!(notices[0].key, "lesson");
    assert!(notices[0].text.contains(&format!("has {count} steps")), "{}", notices[0].text);
    assert_eq!(session(&format!("lesson={count}")).status().lesson.unwrap().index, count - 1);
}

#[test]
fn the_numbers_the_lesson_quotes_are_the_programs() {
    let config = |delta: f64, alpha: f64, pf: PreliminaryFeedbackChoice| {
        let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
        c.controller.sampling_period = delta;
        c.controller.alpha = [alpha, alpha];
        c
    };
    let says = |what: &str| assert!(LESSON_TEXT.contains(what), "the lesson should say {what:?}");
    let off = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Off), None).unwrap();
    says(&format!("ρ = {:.4} > 1", off.spectral_radius));
    says(&format!("e-fold every {:.2} s", 1.0 / off.growth_rate));
    let [re, im] = off.limit_pair_open[0];
    says(&format!("A4 ≈ {re:.2} ± {:.2}j", im.abs()));
    // The sampled pair's frequency at δ = 0.01 s.
    let flexible = off.poles.iter().find(|p| p.continuous.is_some_and(|c| c[1] > 20.0)).unwrap();
    let w = flexible.continuous.unwrap()[1];
    says(&format!("swings at {w:.2} rad/s ({:.2} Hz)", w / std::f64::consts::TAU));
    let slow = analyze(&config(0.01, 0.5, PreliminaryFeedbackChoice::Off), None).unwrap();
    says(&format!("grow e-fold every {:.1} s", 1.0 / slow.growth_rate));
    let re_half = slow.limit_pair_open[0][0];
    says(&format!("≈ {re_half:.2} 1/s is still positive"));
    let paper = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Paper), None).unwrap();
    let [pre, pim] = paper.limit_pair[0];
    says(&format!("{} ± {:.2}j", format!("{pre:.2}").replace('-', "−"), pim.abs()));
    let mut s = session("preset=fig5.3");
    let w = s.windows().unwrap().windows.clone();
    let r = |v: f64| format!("{v:.3}").trim_end_matches('0').to_string();
    for [lo, hi] in &w {
        says(&format!("{} s to {} s", r(*lo), r(*hi)));
    }
    s.set("pf", "paper").unwrap();
    let with = s.windows().unwrap().windows.clone();
    says(&format!("up to {:.3} s", with[0][1]));
}
