//! A teacher's own lesson (issue 21): a Markdown file in the built-in lesson's format, named by
//! `lesson_src=PATH` (a path on the page's own site) or opened from disk, read and checked by the
//! same parser and the same checks as the built-in lesson. Mistakes name their line, what is
//! wrong and what is allowed; the built-in lesson stays when a file is refused. The second lesson
//! shipped with the page, `www/lessons/windows.md` (a homework on the windows of δ), is walked
//! here and the numbers it quotes are the program's.

mod common;
use common::{play, visit as session};

use common::Visit;
use flexarm::analysis::{analyze, stable_windows, LinearSettings};
use flexarm::classroom::progress::{validate, LessonOrigin};
use flexarm::lesson::{parse, read_file, source_path, MAX_LESSON_BYTES};
use flexarm::*;

const HOMEWORK: &str = include_str!("../www/lessons/windows.md");
const TEACHING: &str = include_str!("../docs/teaching.md");

fn open_homework(query: &str) -> (Visit, Vec<flexarm::session::Notice>) {
    let q = format!("lesson_src=lessons/windows.md&{query}");
    Visit::open_with_lessons(&q, None, Some(("lessons/windows.md".into(), HOMEWORK.as_bytes().to_vec())))
}

#[test]
fn the_homework_lesson_reads_passes_the_checks_and_opens_from_its_link() {
    let lesson = parse(HOMEWORK).unwrap();
    validate(&lesson).unwrap();
    assert!(lesson.steps.len() >= 5);
    let (s, notices) = open_homework("lesson=2");
    assert!(notices.is_empty(), "{notices:?}");
    let status = s.status().lesson.expect("open at step 2");
    assert_eq!(status.index, 1);
    assert_eq!(status.lesson_title, "Homework: the windows of δ");
    assert_eq!(status.source, "lessons/windows.md");
    // The link the page writes names the file and the step, and reads back.
    let link = s.state_string();
    assert!(link.contains("lesson_src=lessons%2Fwindows.md&lesson=2"), "{link}");
    let (again, notices) =
        Visit::open_with_lessons(&link, None, Some(("lessons/windows.md".into(), HOMEWORK.as_bytes().to_vec())));
    assert!(notices.is_empty(), "{notices:?}");
    assert_eq!(again.status().lesson.unwrap().index, 1);
    assert_eq!(again.settings(), s.settings());
}

#[test]
fn the_homework_can_be_walked_and_its_tasks_met() {
    let (mut s, _) = open_homework("lesson=1");
    let lesson = parse(HOMEWORK).unwrap();
    for (i, step) in lesson.steps.iter().enumerate() {
        let status = s.status().lesson.unwrap();
        assert_eq!(status.index, i);
        if let Some(q) = &step.question {
            s.lesson_answer(q.correct).unwrap();
            assert!(!s.status().lesson.unwrap().answer.is_empty());
        }
        if let Some(goal) = &step.goal {
            // "Show me" does the task, and then the goal holds.
            s.lesson_reveal().unwrap();
            play(&mut s, 0.5);
            s.refresh();
            if let Some(v) = &goal.verdict {
                assert_eq!(s.status().runs[0].verdict, v, "step {}", i + 1);
            }
        }
        if i + 1 < lesson.steps.len() {
            s.lesson_next().unwrap();
        }
    }
}

/// The numbers the homework quotes are what the analysis says.
#[test]
fn the_homework_quotes_the_programs_numbers() {
    let window = |k1: f64| {
        let mut c = SimulationConfig::default();
        c.plant.k1 *= k1;
        c.preliminary_feedback = PreliminaryFeedbackChoice::Off;
        let w = stable_windows(&LinearSettings::of(&c, None), [0.002, 0.25]).unwrap();
        w.windows[0]
    };
    let text = HOMEWORK.split_whitespace().collect::<Vec<_>>().join(" ");
    let [lo, hi] = window(1.0);
    assert!(text.contains(&format!("first runs from {lo:.4} s to {hi:.4} s")), "paper: {lo} {hi}");
    let [lo, hi] = window(4.0);
    assert!(text.contains(&format!("first window runs from {lo:.4} s to {hi:.4} s")), "stiffer: {lo} {hi}");
    let [lo, hi] = window(0.25);
    assert!(text.contains(&format!("first window runs from {lo:.4} s to {hi:.4} s")), "softer: {lo} {hi}");
    let mut c = SimulationConfig::default();
    c.preliminary_feedback = PreliminaryFeedbackChoice::Off;
    c.controller.sampling_period = 0.05;
    let r = analyze(&c, None).unwrap();
    assert!(text.contains(&format!("ρ = {:.4}", r.spectral_radius)));
    assert!(text.contains(&format!("{:.2} rad/s on the paper's arm", r.limit_pair[0][1].abs())));
}

/// What a teacher's mistakes say: the line, what is wrong, what is allowed.
#[test]
fn a_broken_lesson_names_its_line_and_the_mistake() {
    let load = |text: &str| {
        let mut s = session("");
        let e = s.load_lesson(LessonOrigin::File("mine.md".into()), text.as_bytes()).unwrap_err().to_string();
        // The lesson stays as it was: the built-in one opens.
        s.lesson_open(0).unwrap();
        assert_eq!(s.status().lesson.unwrap().source, "");
        e
    };
    let head = "# Mine\n\n## One\nstate: preset=fig5.3\n\nText.\n\n";
    // An unknown key in a state line: that line (not the step's title, line 8), the key, the keys there are.
    let e = load(&format!("{head}## Two\nstate: delta=0.02&wobble=3\n\nText.\n"));
    assert!(e.starts_with("lesson, line 9: step 2 ('Two'): state:"), "{e}");
    assert!(e.contains("wobble") && e.contains("delta"), "{e}");
    // A value out of its range.
    let e = load(&format!("{head}## Two\nstate: delta=7\n\nText.\n"));
    assert!(e.contains("line 9") && e.contains("delta = '7'") && e.contains("0.002–0.25 s"), "{e}");
    // A question with no right answer.
    let e = load(&format!("{head}## Two\nstate: pf=off\n\nText.\n\n? Which?\n- a\n- b\n\n= Because.\n"));
    assert_eq!(e, "lesson, line 8: step 2 ('Two'): no right choice: mark it with '+ '");
    // A goal that can never be met.
    let e = load(&format!("{head}## Two\nstate: pf=off\ntask: Do it.\ngoal: delta=5\n\nText.\n"));
    assert!(e.contains("line 11") && e.contains("delta=5 can never be met"), "{e}");
    // A 'then:' or 'show:' that does not read: its own line.
    let e = load(&format!("{head}## Two\nstate: pf=off\ntask: Do it.\ngoal: pf=paper\nshow: pf=maybe\n\nText.\n"));
    assert!(e.starts_with("lesson, line 12: step 2 ('Two'): show:"), "{e}");
    let e = load(&format!("{head}## Two\nstate: pf=off\ntask: Do it.\ngoal: colour=red\n\nText.\n"));
    assert!(e.contains("'colour' is not a setting"), "{e}");
    let e = load(&format!("{head}## Two\nstate: pf=off\ntask: Do it.\ngoal: verdict=fine\n\nText.\n"));
    assert!(e.starts_with("lesson, line 11: goal verdict 'fine': one of stable"), "{e}");
    // Not a lesson at all, too large, not UTF-8.
    assert!(load("just some words\n").contains("line 1"));
    assert!(load("").contains("'# title'"));
    let big = format!("# Big\n\n## S\nstate: pf=off\n\n{}\n", "x".repeat(MAX_LESSON_BYTES));
    assert!(load(&big).contains("at most 200 kB"));
    let mut s = session("");
    let e =
        s.load_lesson(LessonOrigin::File("latin1.md".into()), b"# T\n\n## S\nstate: pf=off\n\nCaf\xe9\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "lesson, line 6: the file is not UTF-8 text (save it as UTF-8, as a plain-text editor does)"
    );
    assert!(read_file(&[0xff; 4]).is_err());
}

/// Hostile text is text: the session hands it to the page as strings (the page sets textContent).
#[test]
fn markup_in_a_lesson_stays_text() {
    let mut s = session("");
    let text = "# <script>alert(1)</script>\n\n## <img src=x onerror=alert(1)>\nstate: pf=off\n\nHello <b>there</b>.\n";
    s.load_lesson(LessonOrigin::File("evil.md".into()), text.as_bytes()).unwrap();
    let l = s.status().lesson.unwrap();
    assert_eq!(l.lesson_title, "<script>alert(1)</script>");
    assert_eq!(l.text, ["Hello <b>there</b>."]);
}

#[test]
fn a_lesson_comes_only_from_the_pages_own_site() {
    for ok in ["lessons/windows.md", "/course/week3.md", "../shared/l.md", "l.md?v=2"] {
        assert_eq!(source_path(ok).unwrap(), ok);
    }
    for bad in [
        "https://example.org/l.md",
        "http://127.0.0.1:8080/lessons/paper.md",
        "//example.org/l.md",
        "javascript:alert(1)",
        "data:text/markdown,# T",
        "\\\\server\\l.md",
        "",
    ] {
        let e = source_path(bad).unwrap_err().to_string();
        assert!(e.contains("another site") || e.contains("names no file"), "{bad}: {e}");
    }
    // In a link: refused with the reason, the built-in lesson stays; a path whose file did not
    // load says so.
    let (s, notices) = Visit::open_with_lessons("lesson_src=https://example.org/l.md&lesson=1", None, None);
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].text.contains("another site") && notices[0].text.contains("built-in lesson is used"));
    assert_eq!(s.status().lesson.unwrap().source, "");
    let (_, notices) = Visit::open_with_lessons("lesson_src=lessons/missing.md", None, None);
    assert!(notices[0].text.contains("could not be loaded"), "{notices:?}");
    // A broken file named by a link: its mistake, and the built-in lesson.
    let (s, notices) =
        Visit::open_with_lessons("lesson_src=l.md&lesson=1", None, Some(("l.md".into(), b"# T\n\n## S\n".to_vec())));
    assert!(notices[0].text.starts_with("l.md: lesson, line 3: step 1 ('S'): no 'state:' line"), "{notices:?}");
    assert_eq!(s.status().lesson.unwrap().source, "");
}

/// The teacher's guide describes the format the parser reads: every key it lists is one the
/// parser knows, and its complete example lesson reads and passes the checks.
#[test]
fn the_teachers_guide_example_is_a_valid_lesson() {
    let example =
        TEACHING.split("```markdown\n").nth(1).and_then(|rest| rest.split("\n```").next()).expect("an example");
    let lesson = parse(example).unwrap();
    validate(&lesson).unwrap();
    for key in ["state:", "then:", "task:", "goal:", "show:", "hide: windows", "term:", "lesson_src="] {
        assert!(TEACHING.contains(key), "the guide explains {key}");
    }
    assert!(TEACHING.contains("www/lessons/windows.md"));
}

#[test]
fn the_built_in_lesson_passes_the_same_checks() {
    validate(&flexarm::lesson::builtin().unwrap()).unwrap();
}

#[test]
fn a_teachers_link_opens_the_lesson_at_once() {
    let (s, notices) = open_homework("");
    assert!(notices.is_empty(), "{notices:?}");
    let l = s.status().lesson.expect("open");
    assert_eq!((l.index, l.source.as_str()), (0, "lessons/windows.md"));
}

/// The example lesson the page's help shows (www/help.html) is a lesson the page accepts: a
/// teacher who copies it gets a working file (a cold trial found it refused for having no text).
#[test]
fn the_help_pages_example_lesson_reads_and_passes_the_checks() {
    let help = include_str!("../www/help.html");
    let start = help.find("<pre><code># ").expect("the help shows an example lesson") + "<pre><code>".len();
    let end = start + help[start..].find("</code></pre>").unwrap();
    let text = help[start..end].replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">");
    let lesson = parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    validate(&lesson).unwrap();
    assert!(lesson.steps[0].question.is_some());
}
