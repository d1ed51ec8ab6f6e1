//! The guided lesson: its steps, texts, questions and goals are data, written for teachers in
//! `www/lessons/paper.md` (a small Markdown format that file explains), read here into [`Lesson`]. What a
//! step does to the simulator is a state string, the same text as the page's URL; the session
//! ([`crate::session`]) walks the steps.
//!
//! Architecture invariant: this module knows the format, not the session; whether a step's state
//! string is valid is checked by the session's tests.

use serde::Serialize;

use crate::error::Error;

/// The lesson as the page ships it: `www/lessons/paper.md`, which the page fetches beside the
/// module and hands to the session (the text is not compiled into the wasm: 5 kB gzip less), and
/// which the native build reads at compile time.
#[cfg(not(target_arch = "wasm32"))]
pub const LESSON_TEXT: &str = include_str!("../../www/lessons/paper.md");

/// Where the page finds the built-in lesson, relative to the page.
pub const LESSON_PATH: &str = "lessons/paper.md";

/// A lesson: a title and its steps.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Lesson {
    pub title: String,
    /// Student mode for the whole lesson (`answers: hidden` under the title): the verdict, ρ and
    /// the stable windows wait for each step's answer, as `answers=hidden` in a link does.
    pub answers_hidden: bool,
    /// *Next ▸* waits for each step's answer and task (`next: waits` under the title); else it
    /// goes on and the answers' record says the step was skipped (`next: skips`, the default).
    pub next_waits: bool,
    pub steps: Vec<Step>,
}

/// One step: what it sets up, says, asks and expects.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Step {
    pub title: String,
    /// The line of its '## title' (for messages about it).
    #[serde(skip)]
    pub line: usize,
    /// The lines of its `state:`, `then:`, `show:` and `goal:` (a mistake in one names its own line).
    #[serde(skip)]
    pub lines: KeyLines,
    /// The settings the step starts from, as a state string (over the page's defaults).
    pub state: String,
    /// Settings applied once the question is answered (the prediction, then the result).
    pub then: Option<String>,
    /// What the student should do.
    pub task: Option<String>,
    /// When the task is done.
    pub goal: Option<Goal>,
    /// Settings that do the task for the student ("Show me"), over the current ones.
    pub show: Option<String>,
    /// The stable windows of δ stay hidden until the question is answered or the goal is met.
    pub hide_windows: bool,
    /// In student mode, this step shows the answers from its start (`answers: shown`): the
    /// teacher's lesson reveals them.
    pub answers_shown: bool,
    /// Paragraphs.
    pub text: Vec<String>,
    pub terms: Vec<Term>,
    pub question: Option<Question>,
    /// Paragraphs shown once the student has answered or met the goal.
    pub answer: Vec<String>,
}

/// Where a step's settings lines are in the file (0: the step has none).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct KeyLines {
    pub state: usize,
    pub then: usize,
    pub show: usize,
    pub goal: usize,
}

/// A term and its definition, shown beside the text that uses it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Term {
    pub term: String,
    pub definition: String,
}

/// A question with one right choice.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Question {
    pub prompt: String,
    pub choices: Vec<String>,
    /// The index of the right choice.
    pub correct: usize,
}

/// When a task is done: every condition holds.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Goal {
    /// Run A's verdict: "stable", "unstable", "borderline" or "diverged".
    pub verdict: Option<String>,
    /// Run A has run at least this long, s.
    pub time: Option<f64>,
    /// Settings that must hold, as (key, value) in state-string form.
    pub settings: Vec<(String, String)>,
}

/// The verdicts a goal may ask for.
pub const GOAL_VERDICTS: [&str; 5] = ["stable", "unstable", "borderline", "diverged", "bounded oscillation"];

/// The built-in lesson ([`LESSON_TEXT`]).
#[cfg(not(target_arch = "wasm32"))]
pub fn builtin() -> Result<Lesson, Error> {
    parse(LESSON_TEXT)
}

/// The largest lesson file read, bytes.
pub const MAX_LESSON_BYTES: usize = 200 * 1024;

/// A lesson file's text: at most [`MAX_LESSON_BYTES`], UTF-8.
pub fn read_file(bytes: &[u8]) -> Result<String, Error> {
    if bytes.len() > MAX_LESSON_BYTES {
        return Err(error(
            0,
            format!(
                "the file has {} kB; a lesson may have at most {} kB",
                bytes.len().div_ceil(1024),
                MAX_LESSON_BYTES / 1024
            ),
        ));
    }
    String::from_utf8(bytes.to_vec()).map_err(|e| {
        let line = bytes[..e.utf8_error().valid_up_to()].iter().filter(|b| **b == b'\n').count() + 1;
        error(line, "the file is not UTF-8 text (save it as UTF-8, as a plain-text editor does)")
    })
}

/// Where a teacher's lesson may be fetched from (`lesson_src=`): a path on this site, beside the
/// page or under it (`lessons/homework.md`, `/course/lesson.md`) — never another site.
pub fn source_path(value: &str) -> Result<String, Error> {
    let v = value.trim();
    let refuse = |why: &str| Err(error(0, format!("lesson_src={v}: {why}")));
    if v.is_empty() {
        return refuse("names no file; give a path beside the page, like lessons/windows.md");
    }
    if v.len() > 300 || v.chars().any(char::is_control) {
        return refuse("is not a path (at most 300 characters, no control characters)");
    }
    // A scheme ("https:", "data:", "javascript:") or a host ("//example.org") is another site.
    let before_path = v.split(['/', '?', '#']).next().unwrap_or("");
    if before_path.contains(':') || v.starts_with("//") || v.contains('\\') {
        return refuse(
            "points to another site; the page loads lessons from its own site only (put the file beside the page)",
        );
    }
    Ok(v.to_string())
}

fn error(line: usize, message: impl Into<String>) -> Error {
    Error::Lesson { line, message: message.into() }
}

/// What the last lines were building, so that the next line can continue it.
#[derive(Clone, Copy, PartialEq)]
enum Open {
    Nothing,
    Text,
    Answer,
    Question,
}

/// Reads a lesson in the format `lesson.md` describes.
pub fn parse(text: &str) -> Result<Lesson, Error> {
    let mut title = String::new();
    let mut answers_hidden = false;
    let mut next_waits = false;
    let mut steps: Vec<Step> = Vec::new();
    let mut open = Open::Nothing;
    let mut in_comment = false;
    for (i, raw) in text.lines().enumerate() {
        let n = i + 1;
        let line = raw.trim();
        if in_comment {
            in_comment = !line.contains("-->");
            continue;
        }
        if line.starts_with("<!--") {
            in_comment = !line.contains("-->");
            continue;
        }
        if line.is_empty() {
            if open != Open::Question {
                open = Open::Nothing;
            }
            continue;
        }
        if let Some(t) = line.strip_prefix("## ") {
            steps.push(Step { title: t.trim().to_string(), line: n, ..Step::default() });
            open = Open::Nothing;
            continue;
        }
        if let Some(t) = line.strip_prefix("# ") {
            if !steps.is_empty() || !title.is_empty() {
                return Err(error(n, "only one '# title', before the first step"));
            }
            title = t.trim().to_string();
            continue;
        }
        let Some(step) = steps.last_mut() else {
            // The lesson's own settings, between its title and its first step.
            match setting_line(line) {
                Some(("answers", v)) if v.trim() == "hidden" => {
                    answers_hidden = true;
                    continue;
                }
                Some(("answers", v)) => {
                    return Err(error(
                        n,
                        format!(
                            "'answers: {}' under the title: only 'answers: hidden' (student mode) is known",
                            v.trim()
                        ),
                    ))
                }
                Some(("next", v)) => {
                    next_waits = match v.trim() {
                        "waits" => true,
                        "skips" => false,
                        other => {
                            return Err(error(
                                n,
                                format!(
                                    "'next: {other}': 'next: waits' (Next waits for each answer) or 'next: skips' \
                                     (Next goes on and the record says the step was skipped)"
                                ),
                            ))
                        }
                    };
                    continue;
                }
                _ => return Err(error(n, "text before the first step ('## title')")),
            }
        };
        if let Some((key, value)) = setting_line(line) {
            let value = value.trim().to_string();
            match key {
                "state" => (step.state, step.lines.state) = (value, n),
                "then" => (step.then, step.lines.then) = (Some(value), n),
                "task" => step.task = Some(value),
                "goal" => (step.goal, step.lines.goal) = (Some(parse_goal(&value).map_err(|m| error(n, m))?), n),
                "show" => (step.show, step.lines.show) = (Some(value), n),
                "hide" if value == "windows" => step.hide_windows = true,
                "hide" => return Err(error(n, format!("'hide: {value}': only 'hide: windows' is known"))),
                "answers" if value == "shown" => step.answers_shown = true,
                "answers" => {
                    return Err(error(
                        n,
                        format!(
                            "'answers: {value}' in a step: only 'answers: shown' (reveal them at this step) is known"
                        ),
                    ))
                }
                "term" => {
                    let (term, definition) =
                        value.split_once(" — ").ok_or_else(|| error(n, "a term reads 'term: symbol — definition'"))?;
                    step.terms.push(Term { term: term.trim().into(), definition: definition.trim().into() });
                }
                "next" => return Err(error(n, "'next:' goes under the lesson's title, before the first step")),
                _ => unreachable!("setting_line knows its keys"),
            }
            open = Open::Nothing;
            continue;
        }
        if let Some(prompt) = line.strip_prefix("? ") {
            if step.question.is_some() {
                return Err(error(n, "one question per step"));
            }
            step.question = Some(Question { prompt: prompt.trim().into(), choices: Vec::new(), correct: usize::MAX });
            open = Open::Question;
            continue;
        }
        if let Some((right, choice)) =
            line.strip_prefix("+ ").map(|c| (true, c)).or(line.strip_prefix("- ").map(|c| (false, c)))
        {
            let Some(q) = step.question.as_mut().filter(|_| open == Open::Question) else {
                return Err(error(n, "a choice ('- ' or '+ ') belongs right under its question ('? ')"));
            };
            if right {
                if q.correct != usize::MAX {
                    return Err(error(n, "a second right choice: mark exactly one with '+ '"));
                }
                q.correct = q.choices.len();
            }
            q.choices.push(choice.trim().into());
            continue;
        }
        if let Some(answer) = line.strip_prefix("= ") {
            step.answer.push(answer.trim().into());
            open = Open::Answer;
            continue;
        }
        // A paragraph, or the continuation of the one above.
        match open {
            Open::Text => append(step.text.last_mut(), line),
            Open::Answer => append(step.answer.last_mut(), line),
            Open::Question => return Err(error(n, "after a question come its choices ('- ', '+ ') and a blank line")),
            Open::Nothing => {
                step.text.push(line.to_string());
                open = Open::Text;
            }
        }
    }
    if in_comment {
        return Err(error(text.lines().count(), "an unclosed comment ('<!--' without '-->')"));
    }
    check(&title, &steps)?;
    Ok(Lesson { title, answers_hidden, next_waits, steps })
}

/// `key: value` for the keys a step knows.
fn setting_line(line: &str) -> Option<(&'static str, &str)> {
    const KEYS: [&str; 9] = ["state", "then", "task", "goal", "show", "hide", "term", "answers", "next"];
    let (key, value) = line.split_once(':')?;
    KEYS.iter().find(|k| **k == key.trim()).map(|k| (*k, value))
}

fn append(paragraph: Option<&mut String>, line: &str) {
    if let Some(p) = paragraph {
        p.push(' ');
        p.push_str(line);
    }
}

/// `verdict=stable&pf=off&time=3.5`.
fn parse_goal(text: &str) -> Result<Goal, String> {
    let mut goal = Goal::default();
    for part in text.split('&').map(str::trim).filter(|p| !p.is_empty()) {
        let (key, value) = part.split_once('=').ok_or_else(|| format!("goal condition '{part}' is not key=value"))?;
        match key {
            "verdict" if GOAL_VERDICTS.contains(&value) => goal.verdict = Some(value.into()),
            "verdict" => return Err(format!("goal verdict '{value}': one of {}", GOAL_VERDICTS.join(", "))),
            "time" => {
                let t: f64 = value
                    .parse()
                    .ok()
                    .filter(|t: &f64| t.is_finite() && *t >= 0.0)
                    .ok_or_else(|| format!("goal time '{value}': a number of seconds ≥ 0"))?;
                goal.time = Some(t);
            }
            _ => goal.settings.push((key.into(), value.into())),
        }
    }
    if goal == Goal::default() {
        return Err("a goal needs at least one condition".into());
    }
    Ok(goal)
}

/// What every lesson must have.
fn check(title: &str, steps: &[Step]) -> Result<(), Error> {
    if title.is_empty() {
        return Err(error(1, "the lesson starts with '# title'"));
    }
    if steps.is_empty() {
        return Err(error(1, "no steps ('## title')"));
    }
    for (i, s) in steps.iter().enumerate() {
        let at = |m: &str| error(s.line, format!("step {} ('{}'): {m}", i + 1, s.title));
        if s.state.is_empty() {
            return Err(at("no 'state:' line"));
        }
        if s.text.is_empty() {
            return Err(at(
                "no text: a step needs at least one paragraph of prose (a plain line, not a 'key:' line, '? ', '- ', '+ ' or '= ')",
            ));
        }
        if let Some(q) = &s.question {
            if q.choices.len() < 2 {
                return Err(at("a question needs at least two choices"));
            }
            if q.correct == usize::MAX {
                return Err(at("no right choice: mark it with '+ '"));
            }
            if s.answer.is_empty() {
                return Err(at("a question needs its answer ('= ')"));
            }
        } else if s.then.is_some() {
            return Err(at("'then:' applies after a question, and there is none"));
        }
        if s.task.is_some() != s.goal.is_some() {
            return Err(at("'task:' and 'goal:' go together"));
        }
        if s.show.is_some() && s.task.is_none() {
            return Err(at("'show:' does a task for the student, and there is none"));
        }
        if s.hide_windows && s.question.is_none() && s.goal.is_none() {
            return Err(at("'hide: windows' needs a question or a goal to reveal them"));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_builtin_lesson_reads() {
        let l = builtin().unwrap();
        assert!(l.steps.len() >= 6);
        assert!(l.title.contains("flexible arm"));
    }

    #[test]
    fn the_format_is_read_and_mistakes_name_their_line() {
        let text = "# T\n\n## One\nstate: preset=fig5.1\n\nSome text\ngoes on.\n\nterm: δ — the period.\n\n? Which?\n- a\n+ b\n\n= Because\nof this.\nthen: delta=0.02\n";
        let l = parse(text).unwrap();
        let s = &l.steps[0];
        assert_eq!(s.text, ["Some text goes on."]);
        assert_eq!(s.answer, ["Because of this."]);
        assert_eq!(s.terms[0], Term { term: "δ".into(), definition: "the period.".into() });
        let q = s.question.as_ref().unwrap();
        assert_eq!((q.choices.len(), q.correct), (2, 1));
        assert_eq!(s.then.as_deref(), Some("delta=0.02"));

        let bad = |t: &str| parse(t).unwrap_err().to_string();
        assert_eq!(
            bad("# T\n## S\nstate: x\ntext\n? Q\n- a\n- b\n= A\n"),
            "lesson, line 2: step 1 ('S'): no right choice: mark it with '+ '"
        );
        assert_eq!(
            bad("# T\n## S\nstate: x\n- a\n"),
            "lesson, line 4: a choice ('- ' or '+ ') belongs right under its question ('? ')"
        );
        assert_eq!(
            bad("# T\n## S\nstate: x\ngoal: verdict=fine\n"),
            "lesson, line 4: goal verdict 'fine': one of stable, unstable, borderline, diverged, bounded oscillation"
        );
        assert!(bad("# T\n## S\ntext\n").contains("no 'state:' line"));
        assert!(bad("# T\n<!-- open\n").contains("unclosed comment"));
        assert!(bad("# T\n## S\nstate: x\ntext\nthen: y\n").contains("'then:' applies after a question"));
    }
}
