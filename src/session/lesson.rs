//! Walking the guided lesson ([`crate::lesson`]): entering a step sets the simulator up from its
//! state string, an answer is remembered and may change the settings ("then"), a goal is checked
//! against the session, "back" restores the previous step as the student left it, and leaving
//! keeps everything as it is for exploring.

use serde::Serialize;

use super::answers::{self, AnswersStatus, Entry, Record};
use super::query::split_query;
use super::settings::{Notice, Settings, Source};
use super::Session;
use crate::error::Error;
use crate::lesson::{self, Goal, Lesson, Term};
use crate::schema;

/// Where the student is in the lesson and what they did.
#[derive(Clone, Debug)]
pub struct LessonProgress {
    lesson: Lesson,
    /// The step shown (0-based).
    step: usize,
    /// The lesson panel is open (false after leaving; the progress stays for coming back).
    active: bool,
    /// Each step's chosen answer.
    answers: Vec<Option<usize>>,
    /// Each step's goal met (or revealed on request).
    done: Vec<bool>,
    /// The settings each step had when the student left it.
    left: Vec<Option<Settings>>,
    /// What the student did, to hand in.
    record: Record,
    /// Each step where the student showed the answers student mode hid ("Show them").
    lifted: Vec<bool>,
}

/// The question of the step shown, as the page shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QuestionStatus {
    pub prompt: String,
    pub choices: Vec<String>,
    /// The student's answer, remembered.
    pub chosen: Option<usize>,
    /// The right answer, once the student has chosen.
    pub correct: Option<usize>,
}

/// The step shown, as the page shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LessonStatus {
    pub lesson_title: String,
    /// Where the lesson comes from ("" for the built-in one, else the teacher's file).
    pub source: String,
    /// Every step's title (for the list of steps).
    pub steps: Vec<String>,
    /// 0-based.
    pub index: usize,
    pub title: String,
    pub text: Vec<String>,
    pub terms: Vec<Term>,
    pub task: Option<String>,
    /// The task is done.
    pub done: bool,
    pub question: Option<QuestionStatus>,
    /// The answer and why: shown once answered or done (at once for a step with neither).
    pub answer: Vec<String>,
    pub can_back: bool,
    pub can_next: bool,
    /// The answers so far, to hand in (the summary the last step shows).
    pub record: AnswersStatus,
}

impl LessonProgress {
    fn new(lesson: Lesson, text: &str) -> Self {
        let n = lesson.steps.len();
        let record = Record::new(&lesson, answers::text_hash(text));
        Self {
            lesson,
            step: 0,
            active: false,
            answers: vec![None; n],
            done: vec![false; n],
            left: vec![None; n],
            record,
            lifted: vec![false; n],
        }
    }

    /// The lesson.
    pub fn lesson(&self) -> &Lesson {
        &self.lesson
    }

    /// The step shown (0-based) while the lesson is open.
    pub fn open_step(&self) -> Option<usize> {
        self.active.then_some(self.step)
    }

    /// In student mode, the step shown lets the answers be seen: its teacher says so
    /// (`answers: shown`), or it asks something and the student has answered it (and met its goal).
    pub(super) fn answers_revealed_here(&self) -> bool {
        let s = &self.lesson.steps[self.step];
        self.active
            && (s.answers_shown
                || self.lifted[self.step]
                || ((s.question.is_some() || s.goal.is_some()) && self.revealed(self.step)))
    }

    /// The student showed the hidden answers on step `step` ("Show them").
    pub(super) fn lift(&mut self, step: usize) {
        self.lifted[step] = true;
    }

    /// The answer of step `i` may be shown.
    fn revealed(&self, i: usize) -> bool {
        let s = &self.lesson.steps[i];
        let answered = s.question.is_none() || self.answers[i].is_some();
        let done = s.goal.is_none() || self.done[i];
        answered && done
    }
}

impl Session {
    /// The lesson's progress (None until the lesson is first opened).
    pub fn lesson(&self) -> Option<&LessonProgress> {
        self.lesson.as_ref()
    }

    /// True while the lesson panel is open.
    pub fn lesson_active(&self) -> bool {
        self.lesson.as_ref().is_some_and(|l| l.active)
    }

    /// Opens the lesson at `step` (0-based; the last step if beyond): the step's settings, run from rest.
    pub fn lesson_open(&mut self, step: usize) -> Result<(), Error> {
        if self.lesson.is_none() {
            let text: &str = match &self.lesson_text {
                Some(text) => text,
                #[cfg(not(target_arch = "wasm32"))]
                None => lesson::LESSON_TEXT,
                #[cfg(target_arch = "wasm32")]
                None => {
                    return Err(Error::NotReady("the lesson's text did not load (lessons/paper.md, beside the page)"))
                }
            };
            self.lesson = Some(LessonProgress::new(lesson::parse(text)?, text));
        }
        let progress = self.lesson.as_mut().expect("just made");
        progress.active = true;
        let step = step.min(progress.lesson.steps.len() - 1);
        self.enter(step)?;
        self.note = "The lesson uses the full view; leave it any time to explore from where it is.".into();
        Ok(())
    }

    /// Goes on to the next step, remembering how this one was left.
    pub fn lesson_next(&mut self) -> Result<(), Error> {
        let (step, count) = self.lesson_position()?;
        if step + 1 >= count {
            return Err(lesson_error("this is the last step"));
        }
        self.remember_step(step);
        self.enter(step + 1)
    }

    /// Goes back to the previous step exactly as the student left it.
    pub fn lesson_back(&mut self) -> Result<(), Error> {
        let (step, _) = self.lesson_position()?;
        if step == 0 {
            return Err(lesson_error("this is the first step"));
        }
        self.remember_step(step);
        self.enter(step - 1)
    }

    /// Answers the step's question with choice `choice` (0-based): the first answer is remembered
    /// (later ones change nothing) and the step's "then" settings, if any, are applied (from rest).
    pub fn lesson_answer(&mut self, choice: usize) -> Result<(), Error> {
        let (step, _) = self.lesson_position()?;
        let progress = self.lesson.as_mut().expect("positioned");
        let s = &progress.lesson.steps[step];
        let q = s.question.as_ref().ok_or_else(|| lesson_error("this step asks no question"))?;
        if choice >= q.choices.len() {
            return Err(lesson_error(&format!("choice {choice} of {}", q.choices.len())));
        }
        if progress.answers[step].is_some() {
            // A prediction is made once: the first answer is the one remembered.
            return Ok(());
        }
        let entry = Entry {
            step: step + 1,
            step_title: s.title.clone(),
            kind: "prediction".into(),
            choice: Some(choice + 1),
            choice_text: q.choices[choice].clone(),
            result: if choice == q.correct { "right" } else { "wrong" }.into(),
            state: String::new(),
            time: String::new(),
        };
        let then = s.then.clone();
        progress.answers[step] = Some(choice);
        self.record(entry);
        match then {
            Some(state) => self.apply_lesson_state(&state),
            None => Ok(()),
        }
    }

    /// Shows a task's result without the student having done it ("show me"): the step's "show"
    /// settings, if any, are applied over the current ones, so the result the answer describes is
    /// on screen.
    pub fn lesson_reveal(&mut self) -> Result<(), Error> {
        let (step, _) = self.lesson_position()?;
        let progress = self.lesson.as_mut().expect("positioned");
        if !progress.done[step] && progress.lesson.steps[step].goal.is_some() {
            let entry = task_entry(&progress.lesson, step, "shown");
            self.record(entry);
        }
        let progress = self.lesson.as_mut().expect("positioned");
        progress.done[step] = true;
        if let Some(show) = progress.lesson.steps[step].show.clone() {
            let mut next = self.settings;
            next.read(&show, Source::Lesson)?;
            self.apply(next, false, "")?;
        }
        Ok(())
    }

    /// Closes the lesson panel; the settings stay as they are, to explore from.
    pub fn lesson_leave(&mut self) {
        if let Some(l) = self.lesson.as_mut() {
            l.active = false;
        }
    }

    /// Marks the step's goal met if it is (called with the other periodic work).
    pub(super) fn check_lesson_goal(&mut self) {
        let Some(l) = self.lesson.as_ref().filter(|l| l.active) else { return };
        let step = l.step;
        if l.done[step] {
            return;
        }
        let met = l.lesson.steps[step].goal.as_ref().is_some_and(|g| self.goal_met(g));
        if met {
            let l = self.lesson.as_mut().expect("active");
            l.done[step] = true;
            let entry = task_entry(&l.lesson, step, "done");
            self.record(entry);
        }
    }

    /// The stable windows are hidden by the step until its answer is revealed.
    pub(super) fn lesson_hides_windows(&self) -> bool {
        self.lesson.as_ref().is_some_and(|l| l.active && l.lesson.steps[l.step].hide_windows && !l.revealed(l.step))
    }

    /// The step shown, for the page (None when the lesson is not open).
    pub fn lesson_status(&self) -> Option<LessonStatus> {
        let l = self.lesson.as_ref().filter(|l| l.active)?;
        let i = l.step;
        let s = &l.lesson.steps[i];
        let revealed = l.revealed(i);
        Some(LessonStatus {
            lesson_title: l.lesson.title.clone(),
            source: match &self.lesson_origin {
                LessonOrigin::BuiltIn => String::new(),
                LessonOrigin::Path(name) | LessonOrigin::File(name) => name.clone(),
            },
            steps: l.lesson.steps.iter().map(|s| s.title.clone()).collect(),
            index: i,
            title: s.title.clone(),
            text: s.text.clone(),
            terms: s.terms.clone(),
            task: s.task.clone(),
            done: l.done[i],
            question: s.question.as_ref().map(|q| QuestionStatus {
                prompt: q.prompt.clone(),
                choices: q.choices.clone(),
                chosen: l.answers[i],
                correct: l.answers[i].map(|_| q.correct),
            }),
            answer: if revealed { s.answer.clone() } else { Vec::new() },
            can_back: i > 0,
            can_next: i + 1 < l.lesson.steps.len(),
            record: l.record.status(&l.lesson),
        })
    }

    /// "lesson=3" while the lesson is open (1-based), for the URL.
    pub(super) fn lesson_query(&self) -> Option<String> {
        let l = self.lesson.as_ref().filter(|l| l.active)?;
        match &self.lesson_origin {
            LessonOrigin::BuiltIn => Some(format!("lesson={}", l.step + 1)),
            LessonOrigin::Path(path) => {
                Some(format!("lesson_src={}&lesson={}", super::query::encode(path), l.step + 1))
            }
            // A file from the user's disk: a link cannot bring it back.
            LessonOrigin::File(_) => None,
        }
    }

    /// Opens the lesson a URL names (`lesson=3`), then reads the URL's other settings over the
    /// step's: a link written while in the lesson comes back as it was. A step past the last
    /// opens the last, with a notice.
    pub(super) fn open_lesson_from(&mut self, query: &str) -> Result<Option<Notice>, Error> {
        let pairs = split_query(query);
        let named = pairs.iter().rev().find(|(k, _)| k == "lesson").map(|(_, n)| n.clone());
        // A teacher's lesson named by the link opens at once, at its first step unless it says.
        let n = match (named, &self.lesson_origin) {
            (Some(n), _) => n,
            (None, LessonOrigin::Path(_)) => "1".to_string(),
            (None, _) => return Ok(None),
        };
        let n = &n;
        let step: usize = n.trim().parse().ok().filter(|&s| s >= 1).ok_or_else(|| {
            Error::Parse(crate::error::ParseError {
                key: "lesson".into(),
                text: n.clone(),
                expected: "a step number from 1".into(),
            })
        })?;
        self.lesson_open(step - 1)?;
        let (opened, count) = self.lesson_position()?;
        let notice = (opened + 1 < step).then(|| Notice {
            key: "lesson".into(),
            text: format!("lesson={}: the lesson has {count} steps; opened step {count}", n.trim()),
        });
        // Encoded again: a decoded `&`, `=`, `%` or `+` in a value must not be read a second time
        // as another setting (`pf=off%26delta%3D0.2` is one bad value of pf, not delta=0.2).
        let rest: Vec<String> = pairs
            .iter()
            .filter(|(k, _)| k != "lesson" && k != "lesson_src")
            .map(|(k, v)| format!("{}={}", super::query::encode(k), super::query::encode(v)))
            .collect();
        if !rest.is_empty() {
            let mut next = self.settings;
            next.read(&rest.join("&"), Source::Page)?;
            self.apply(next, true, "")?;
        }
        Ok(notice)
    }

    fn lesson_position(&self) -> Result<(usize, usize), Error> {
        let l = self.lesson.as_ref().filter(|l| l.active).ok_or_else(|| lesson_error("the lesson is not open"))?;
        Ok((l.step, l.lesson.steps.len()))
    }

    fn remember_step(&mut self, step: usize) {
        let settings = self.settings;
        if let Some(l) = self.lesson.as_mut() {
            l.left[step] = Some(settings);
        }
    }

    /// Shows step `step`: as the student left it, or from its state string.
    fn enter(&mut self, step: usize) -> Result<(), Error> {
        let l = self.lesson.as_mut().expect("the lesson is open");
        l.step = step;
        let left = l.left[step];
        let state = l.lesson.steps[step].state.clone();
        match left {
            Some(settings) => self.apply(settings, true, "")?,
            None => self.apply_lesson_state(&state)?,
        }
        // A new step starts clean: the faint ghost compares within a step (before and after its
        // answer), not with whatever ran before.
        self.ghost = None;
        Ok(())
    }

    /// A step's state string over the page's start, in the full view, run from rest.
    fn apply_lesson_state(&mut self, state: &str) -> Result<(), Error> {
        let mut next = Settings::page_start();
        next.view.full = true;
        next.speed = self.settings.speed;
        // Student mode set by the teacher's link stays on through the steps.
        next.view.answers_hidden = self.settings.view.answers_hidden;
        next.read(state, Source::Lesson)?;
        next.view.tab = super::named::step_tab(state, &next.view, self.settings.view.tab);
        self.apply(next, true, "")?;
        // A step may start at a moment (`t=2&paused=1`).
        self.go_to_start()
    }

    fn goal_met(&self, goal: &Goal) -> bool {
        let a = self.run(0).expect("run A");
        if goal.time.is_some_and(|t| a.closed_loop().time() < t - 1e-9) {
            return false;
        }
        if let Some(v) = &goal.verdict {
            if super::run_status("A", a).verdict != v {
                return false;
            }
        }
        goal.settings.iter().all(|(key, text)| {
            let Some(p) = schema::param(key) else { return false };
            p.parse(text, false).ok().is_some_and(|v| self.settings.get(key) == Some(v))
        })
    }
}

/// Checks a lesson against the settings it uses: every step's `state:`, `then:` and `show:` reads
/// as a state string, every goal names settings with values they can take. The built-in lesson and
/// a teacher's file pass the same checks; a mistake names its step's line.
pub fn validate(lesson: &Lesson) -> Result<(), Error> {
    for (i, step) in lesson.steps.iter().enumerate() {
        let at = |what: &str, e: &dyn std::fmt::Display| Error::Lesson {
            line: step.line,
            message: format!("step {} ('{}'): {what}: {e}", i + 1, step.title),
        };
        let mut settings = Settings::page_start();
        settings.read(&step.state, Source::Lesson).map_err(|e| at("state", &e))?;
        for (what, text) in [("then", &step.then), ("show", &step.show)] {
            if let Some(text) = text {
                let mut next = settings;
                next.read(text, Source::Lesson).map_err(|e| at(what, &e))?;
            }
        }
        for (key, value) in step.goal.iter().flat_map(|g| g.settings.iter()) {
            let p = schema::param(key).ok_or_else(|| {
                at(
                    "goal",
                    &format!("'{key}' is not a setting (a goal takes verdict=, time= and settings such as pf=off)"),
                )
            })?;
            // Within the page's control: what a student can set.
            p.parse(value, true).map_err(|e| at("goal", &format!("{key}={value} can never be met: {e}")))?;
        }
    }
    Ok(())
}

/// A teacher's lesson file read, parsed and checked as the built-in lesson is: its text and the
/// lesson, or the first mistake.
pub(super) fn checked(bytes: &[u8]) -> Result<(String, Lesson), Error> {
    let text = lesson::read_file(bytes)?;
    let parsed = lesson::parse(&text)?;
    validate(&parsed)?;
    Ok((text, parsed))
}

/// Where the lesson shown comes from.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum LessonOrigin {
    /// `lessons/paper.md`, beside the page (or built into the native build).
    #[default]
    BuiltIn,
    /// A teacher's file at this path of the page's site (`lesson_src=`): a link can name it.
    Path(String),
    /// A file the user opened or dropped on the page: no link can name it.
    File(String),
}

impl Session {
    /// Replaces the lesson by a teacher's: its file's bytes, read, parsed and checked as the
    /// built-in lesson is, then opened at its first step. A mistake leaves the lesson as it was and
    /// says which line and what is wrong.
    pub fn load_lesson(&mut self, origin: LessonOrigin, bytes: &[u8]) -> Result<(), Error> {
        let (text, parsed) = checked(bytes)?;
        self.lesson_origin = origin;
        self.lesson = Some(LessonProgress::new(parsed, &text));
        self.lesson_text = Some(text);
        self.lesson_open(0)
    }
}

impl Session {
    /// Gives the session the wall clock (ms since 1970), for the answers' times.
    pub fn set_wall_clock(&mut self, ms: f64) {
        self.wall_clock_ms = ms;
    }

    /// What the student did in the lesson, to hand in (None before the lesson is opened).
    pub fn answers_record(&self) -> Option<&Record> {
        self.lesson.as_ref().map(|l| &l.record)
    }

    /// Gives back a record kept earlier (after a reload): the answers and tasks it holds count as
    /// given, with their times and states. A record of another lesson or text is refused and
    /// changes nothing.
    pub fn restore_answers(&mut self, record: Record) -> Result<(), Error> {
        let l = self.lesson.as_mut().ok_or_else(|| lesson_error("the lesson is not open"))?;
        if record.entries.is_empty() {
            return Ok(());
        }
        record.check(&l.lesson, &l.record.lesson_hash)?;
        for e in &record.entries {
            let i = e.step - 1;
            match (e.kind.as_str(), e.choice) {
                ("prediction", Some(c)) => l.answers[i] = l.answers[i].or(Some(c - 1)),
                ("task", _) => l.done[i] = true,
                ("answers shown", _) => l.lifted[i] = true,
                _ => {}
            }
        }
        l.record.entries = record.entries;
        Ok(())
    }

    /// [`Session::restore_answers`] from the CSV the page kept ([`Record::to_csv`]).
    pub fn restore_answers_csv(&mut self, csv: &str) -> Result<(), Error> {
        let steps = self.lesson.as_ref().map_or(0, |l| l.lesson.steps.len());
        self.restore_answers(Record::from_csv(csv, steps)?)
    }

    /// Forgets every answer and task of the lesson (the page's "Clear my answers"); the step shown
    /// stays, from its start.
    pub fn clear_answers(&mut self) -> Result<(), Error> {
        let l = self.lesson.as_mut().ok_or_else(|| lesson_error("the lesson is not open"))?;
        let n = l.lesson.steps.len();
        l.answers = vec![None; n];
        l.done = vec![false; n];
        l.left = vec![None; n];
        l.lifted = vec![false; n];
        l.record.entries.clear();
        let (step, active) = (l.step, l.active);
        if active {
            self.enter(step)?;
        }
        Ok(())
    }

    /// Adds an entry to the record, stamped with the state string and the clock.
    pub(super) fn record(&mut self, mut entry: Entry) {
        entry.state = self.state_string();
        entry.time = answers::iso_time(self.wall_clock_ms);
        if let Some(l) = self.lesson.as_mut() {
            l.record.entries.push(entry);
        }
    }
}

/// A task's entry: done by the student, or shown by "Show me".
fn task_entry(lesson: &Lesson, step: usize, result: &str) -> Entry {
    Entry {
        step: step + 1,
        step_title: lesson.steps[step].title.clone(),
        kind: "task".into(),
        choice: None,
        choice_text: String::new(),
        result: result.into(),
        state: String::new(),
        time: String::new(),
    }
}

fn lesson_error(message: &str) -> Error {
    Error::Lesson { line: 0, message: message.into() }
}
