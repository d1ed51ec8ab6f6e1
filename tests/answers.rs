//! Answers to hand in and student mode (issue 21, items 2 and 3). A student's predictions and
//! tasks are recorded with the state they were made in and the time, summarised ("your
//! predictions: r of q right"), written as CSV and JSON, kept across a reload (given back to a new
//! session) and cleared. Student mode (`answers=hidden`, or `answers: hidden` in a lesson) hides
//! every word and figure that gives the verdict away until the step is answered.

mod common;
use common::play;

use common::Visit;
use flexarm::analysis::analyze;
use flexarm::classroom::answers::{check_csv, split_csv as cells, text_hash, Check, Record, CSV_COLUMNS};
use flexarm::classroom::progress::LessonOrigin;
use flexarm::lesson::{parse, LESSON_TEXT};

const HOMEWORK: &str = include_str!("../www/lessons/windows.md");
/// 2026-11-26T05:03:00Z.
const NOW_MS: f64 = 1_795_669_380_000.0;

fn homework(query: &str) -> Visit {
    let q = format!("lesson_src=lessons/windows.md&{query}");
    let (s, notices) =
        Visit::open_with_lessons(&q, None, Some(("lessons/windows.md".into(), HOMEWORK.as_bytes().to_vec())));
    assert!(notices.is_empty(), "{notices:?}");
    s
}

#[test]
fn predictions_and_tasks_are_recorded_with_their_state_and_time_and_summed_up() {
    let lesson = parse(HOMEWORK).unwrap();
    let questions: Vec<usize> = (0..lesson.steps.len()).filter(|&i| lesson.steps[i].question.is_some()).collect();
    let tasks = lesson.steps.iter().filter(|s| s.goal.is_some()).count();
    assert!(questions.len() >= 2 && tasks >= 1, "the homework asks and sets tasks");
    let mut s = homework("lesson=1");
    s.set_wall_clock(NOW_MS);
    let mut right = 0;
    let mut expected_states = Vec::new();
    for (i, step) in lesson.steps.iter().enumerate() {
        if let Some(q) = &step.question {
            // Right on the first question, wrong on the others.
            let choice = if i == questions[0] { q.correct } else { (q.correct + 1) % q.choices.len() };
            right += usize::from(choice == q.correct);
            expected_states.push(s.state_string());
            s.lesson_answer(choice).unwrap();
            // A second answer changes nothing: a prediction is made once.
            s.lesson_answer(q.correct).unwrap();
        }
        if step.goal.is_some() {
            expected_states.push(s.state_string());
            s.lesson_reveal().unwrap();
        }
        if i + 1 < lesson.steps.len() {
            s.lesson_next().unwrap();
        }
    }
    let record = s.answers_record().unwrap().clone();
    assert_eq!(record.lesson, lesson.title);
    assert_eq!(record.lesson_hash, text_hash(HOMEWORK));
    assert_eq!(record.entries.len(), questions.len() + tasks);
    for (e, state) in record.entries.iter().zip(&expected_states) {
        // The state it was made in: before a "then:" changed it; a link back to that step.
        assert_eq!(&e.state, state);
        assert!(e.state.contains(&format!("lesson={}", e.step)), "{}", e.state);
        assert_eq!(e.time, "2026-11-26T05:03:00Z");
        assert_eq!(e.step_title, lesson.steps[e.step - 1].title);
        if e.kind == "prediction" {
            let q = lesson.steps[e.step - 1].question.as_ref().unwrap();
            let c = e.choice.unwrap() - 1;
            assert_eq!(e.choice_text, q.choices[c]);
            assert_eq!(e.result, if c == q.correct { "right" } else { "wrong" });
        } else {
            assert_eq!((e.kind.as_str(), e.result.as_str()), ("task", "shown"));
        }
    }
    let summary = s.status().lesson.unwrap().record;
    assert!(
        summary.headline.starts_with(&format!("Your predictions: {right} of {} right.", questions.len())),
        "{}",
        summary.headline
    );
    assert!(
        summary.headline.contains(&format!("Tasks: 0 of {tasks} done yourself, {tasks} shown")),
        "{}",
        summary.headline
    );
    assert_eq!(summary.rows.len(), record.entries.len());

    // The CSV: a header naming the lesson and its hash, the columns, one row per entry that reads
    // back to the record's values (and back into the record: what the page keeps).
    let csv = record.to_csv();
    assert_eq!(Record::from_csv(&csv, lesson.steps.len()).unwrap(), record);
    let mut lines = csv.lines();
    let comment = lines.next().unwrap();
    assert!(comment.starts_with('#') && comment.contains(&lesson.title) && comment.contains(&record.lesson_hash));
    assert_eq!(lines.next().unwrap(), CSV_COLUMNS.join(","));
    let rows: Vec<Vec<String>> = lines.clone().filter(|l| !l.starts_with('#')).map(cells).collect();
    assert_eq!(rows.len(), record.entries.len());
    // The last line checks the rows: intact as written; a row edited by hand, or a file cut short,
    // is told apart.
    assert!(csv.lines().last().unwrap().starts_with("# check: fnv1a64:"));
    assert_eq!(check_csv(&csv), Check::Intact);
    let edited = csv.replacen(",wrong,", ",right,", 1);
    if edited != csv {
        assert_eq!(check_csv(&edited), Check::Edited);
    }
    assert_eq!(
        check_csv(&csv.replacen("fnv1a64", "fnv1a64", 1).replace(&record.entries[0].time, "2020-01-01T00:00:00Z")),
        Check::Edited
    );
    let cut: String = csv.lines().take(3).map(|l| format!("{l}\n")).collect();
    assert_eq!(check_csv(&cut), Check::Missing);
    for (row, e) in rows.iter().zip(&record.entries) {
        assert_eq!(row.len(), CSV_COLUMNS.len(), "{row:?}");
        assert_eq!(
            row,
            &[
                record.lesson.clone(),
                record.lesson_hash.clone(),
                e.step.to_string(),
                e.step_title.clone(),
                e.kind.clone(),
                e.choice.map_or(String::new(), |c| c.to_string()),
                e.choice_text.clone(),
                e.result.clone(),
                e.state.clone(),
                e.time.clone()
            ]
        );
    }
}

#[test]
fn a_task_done_by_the_student_counts_as_done() {
    let lesson = parse(HOMEWORK).unwrap();
    let (i, step) = lesson.steps.iter().enumerate().find(|(_, s)| s.goal.is_some()).unwrap();
    let mut s = homework(&format!("lesson={}", i + 1));
    s.set_wall_clock(NOW_MS);
    // Doing it: the step's "show" settings typed in by hand, not by "Show me".
    for pair in step.show.as_deref().unwrap().split('&') {
        let (k, v) = pair.split_once('=').unwrap();
        s.set(k, v).unwrap();
    }
    play(&mut s, 1.0);
    s.refresh();
    let e = s.answers_record().unwrap().entries.last().cloned().expect("the goal was met");
    assert_eq!((e.kind.as_str(), e.result.as_str(), e.step), ("task", "done", i + 1));
    assert!(s.status().lesson.unwrap().record.headline.contains("Tasks: 1 of"));
}

#[test]
fn a_kept_record_comes_back_after_a_reload_and_only_for_its_own_text() {
    let lesson = parse(HOMEWORK).unwrap();
    let first = lesson.steps.iter().position(|s| s.question.is_some()).unwrap();
    let q = lesson.steps[first].question.as_ref().unwrap();
    let mut s = homework(&format!("lesson={}", first + 1));
    s.lesson_answer(q.correct).unwrap();
    // What the page keeps in localStorage: the record's CSV.
    let kept = s.answers_record().unwrap().to_csv();

    let mut reloaded = homework(&format!("lesson={}", first + 1));
    assert_eq!(reloaded.status().lesson.unwrap().question.unwrap().chosen, None);
    reloaded.restore_answers_csv(&kept).unwrap();
    let status = reloaded.status().lesson.unwrap();
    assert_eq!(status.question.unwrap().chosen, Some(q.correct));
    assert!(!status.answer.is_empty(), "the answered step shows its answer again");
    assert_eq!(reloaded.answers_record().unwrap(), s.answers_record().unwrap());

    // Another text of the lesson (one character changed): its answers are not these.
    let changed = HOMEWORK.replacen("Homework", "Homework ", 1);
    let mut other = Visit::open_with_lessons("", None, None).0;
    other.load_lesson(LessonOrigin::File("changed.md".into()), changed.as_bytes()).unwrap();
    let before = other.answers_record().unwrap().clone();
    let err = other.restore_answers_csv(&kept).unwrap_err().to_string();
    assert!(err.contains("another text of the lesson"), "{err}");
    assert_eq!(other.answers_record().unwrap(), &before, "a refused record changes nothing");

    // A forged record naming a choice the step does not have is refused too.
    let mut forged = Record::from_csv(&kept, lesson.steps.len()).unwrap();
    forged.entries[0].choice = Some(99);
    assert!(reloaded.restore_answers(forged).is_err());
    // Text that is not a record is refused with a reason.
    let err = reloaded.restore_answers_csv("not, a record").unwrap_err().to_string();
    assert!(err.contains("no header line"), "{err}");

    // Clearing forgets everything, and the step starts over.
    reloaded.clear_answers().unwrap();
    assert!(reloaded.answers_record().unwrap().entries.is_empty());
    assert_eq!(reloaded.status().lesson.unwrap().question.unwrap().chosen, None);
}

#[test]
fn the_builtin_lessons_record_hashes_its_text() {
    let mut s = Visit::open("").0;
    s.lesson_open(0).unwrap();
    assert_eq!(s.answers_record().unwrap().lesson_hash, text_hash(LESSON_TEXT));
    assert_eq!(s.answers_record().unwrap().steps, parse(LESSON_TEXT).unwrap().steps.len());
}

#[test]
fn a_teachers_link_opens_a_given_step_with_a_given_state() {
    let s = homework("lesson=2&delta=0.05&alpha=3");
    assert_eq!(s.status().lesson.unwrap().index, 1);
    assert_eq!(s.settings().a.delta, 0.05);
    assert_eq!(s.settings().a.alpha, [3.0, 3.0]);
}

/// Everything the page says, as text: the status and the figure's description.
fn said(s: &Visit) -> String {
    serde_json::to_string(&s.status()).unwrap()
}

#[test]
fn student_mode_hides_what_gives_the_answer_away_until_the_step_is_answered() {
    // The paper's Fig. 5.3 (ρ = 1.0239): nothing the page says may carry ρ or the verdict.
    let mut s = Visit::open("preset=fig5.3&mode=full&rho=1&map=1&log=1&answers=hidden").0;
    play(&mut s, 2.0);
    s.refresh();
    let rho = analyze(&s.run(0).unwrap().closed_loop().config().clone(), None).unwrap().spectral_radius;
    let status = s.status();
    let text = said(&s);
    assert!(s.answers_hidden());
    for give_away in [format!("{rho:.4}"), format!("{rho:.3}"), "Unstable".into(), "unstable".into()] {
        assert!(!text.contains(&give_away), "'{give_away}' is said in student mode: {text}");
    }
    assert_eq!(status.runs[0].verdict, "hidden");
    assert!(status.runs[0].spectral_radius.is_none() && status.windows.is_none() && status.story.is_none());
    assert!(!status.maps.shown);
    let hidden = status.hidden.expect("the page says what is hidden");
    assert!(hidden.text.contains("hidden") && hidden.text.contains("Show them"), "{}", hidden.text);
    let drawn = s.drawn_view();
    assert!(!drawn.rho && !drawn.map && drawn.answers_hidden);
    assert!(s.cached_windows().is_none());
    // The same settings without student mode say it all (the test above can fail).
    let open = Visit::open("preset=fig5.3&mode=full&rho=1&map=1").0;
    assert!(said(&open).contains(&format!("{rho:.4}")));

    // The downloads that carry ρ are held back too, with the reason.
    assert!(s.figure_data_csv().unwrap_err().to_string().contains("student mode"));
    assert!(flexarm::view::figure::figure_svg(&s, "maps", false).unwrap_err().to_string().contains("student mode"));
    assert!(s.python_script(flexarm::session::python::TEMPLATE).unwrap_err().to_string().contains("student mode"));
    let drawn = s.drawn_view();
    assert!(!drawn.poles && !drawn.log && !drawn.swing, "the analysis' figures are not drawn");
    assert!(open.figure_data_csv().is_ok());

    // The link keeps student mode, and the state string says so.
    assert!(s.state_string().contains("answers=hidden"));

    // The student lifts it: everything is back.
    s.show_answers();
    assert!(!s.answers_hidden());
    assert!(said(&s).contains(&format!("{rho:.4}")));
}

#[test]
fn in_a_lesson_student_mode_lifts_once_the_step_is_answered_and_says_so_in_the_record() {
    let lesson = parse(HOMEWORK).unwrap();
    let first = lesson.steps.iter().position(|s| s.question.is_some()).unwrap();
    let q = lesson.steps[first].question.as_ref().unwrap();
    let mut s = homework(&format!("lesson={}&answers=hidden", first + 1));
    assert!(s.answers_hidden(), "hidden before the answer");
    s.lesson_answer((q.correct + 1) % q.choices.len()).unwrap();
    assert!(!s.answers_hidden(), "shown once answered, right or wrong");
    s.lesson_next().unwrap();
    let step = &lesson.steps[first + 1];
    assert!(!step.answers_shown);
    assert!(s.answers_hidden(), "the next step hides them again");
    s.show_answers();
    assert!(!s.answers_hidden(), "shown on this step");
    let e = s.answers_record().unwrap().entries.last().unwrap().clone();
    assert_eq!((e.kind.as_str(), e.step), ("answers shown", first + 2));
    assert!(s.status().lesson.unwrap().record.headline.contains("You showed the hidden answers"));
    // For this step only: the next one hides them again, and student mode stays in the link.
    if first + 2 < lesson.steps.len() {
        s.lesson_next().unwrap();
        assert!(s.answers_hidden() && s.state_string().contains("answers=hidden"));
    }
}

#[test]
fn a_lessons_header_sets_student_mode_and_a_step_can_show_the_answers() {
    let text = "# Exam\nanswers: hidden\n\n## Predict\nstate: preset=fig5.3\n\nWhat happens?\n\n? Stable?\n+ no\n- yes\n\n= It grows.\n\n## Look\nstate: preset=fig5.3\nanswers: shown\n\nNow look at the verdict.\n";
    let mut s = Visit::open("").0;
    s.load_lesson(LessonOrigin::File("exam.md".into()), text.as_bytes()).unwrap();
    assert!(s.student_mode() && s.answers_hidden());
    s.lesson_next().unwrap();
    assert!(s.student_mode() && !s.answers_hidden(), "the teacher's step shows them");
    assert_eq!(s.status().runs[0].verdict, "unstable");

    let bad = |t: &str| parse(t).unwrap_err().to_string();
    assert!(bad("# T\nanswers: shown\n## S\nstate: x\ntext\n").contains("only 'answers: hidden'"));
    assert!(bad("# T\n## S\nstate: x\nanswers: hidden\ntext\n").contains("only 'answers: shown'"));
}

/// "Show them" on a step that keeps the windows for its answer (`hide: windows`): ρ(δ) comes
/// back empty, and says why (issue 35, item 6).
#[test]
fn rho_of_delta_says_why_it_is_empty_on_a_step_that_hides_the_windows() {
    use flexarm::schema::PanelKind;
    use flexarm::view::options::ViewOptions;
    use flexarm::view::scene::Scene;
    let lesson = parse(HOMEWORK).unwrap();
    let step =
        lesson.steps.iter().position(|s| s.hide_windows && s.question.is_some()).expect("a step hides the windows");
    let q = lesson.steps[step].question.as_ref().unwrap();
    let mut s = homework(&format!("lesson={}&answers=hidden", step + 1));
    s.show_answers();
    assert!(!s.answers_hidden() && s.drawn_view().rho, "the student showed the answers: ρ(δ) is drawn");
    play(&mut s, 0.5);
    s.refresh();
    let note = |s: &Visit| {
        let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
        scene.follow_view(&s.drawn_view());
        scene.draw_session(s);
        let info = scene.panel_info();
        info.iter().find(|p| p.id == PanelKind::RhoCurve.id()).map(|p| p.note.clone()).expect("ρ(δ) is shown")
    };
    assert!(s.cached_windows().is_none());
    let hidden = note(&s);
    assert!(hidden.contains("hidden until you answer this step"), "{hidden}");
    // Answered: the windows are back, and so is the curve's own note.
    s.lesson_answer(q.correct).unwrap();
    s.refresh();
    assert!(s.cached_windows().is_some());
    let shown = note(&s);
    assert!(shown.starts_with("ρ(δ) at α") && !shown.contains("hidden"), "{shown}");
}
