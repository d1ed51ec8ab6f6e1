//! Walking the guided lesson: entering a step sets the session up from its state string, an
//! answer is remembered and may change the settings ("then"), a goal is checked against the
//! session, "back" restores the previous step as the student left it, and leaving keeps
//! everything as it is for exploring; a teacher's lesson replaces the built-in one; the answers'
//! record is given back after a reload or cleared.

use super::answers::{Entry, Record, SKIPPED};
use super::progress::{checked, LessonOrigin, LessonProgress, LessonStatus, QuestionStatus};
use super::room::Classroom;
use crate::error::Error;
use crate::lesson::{self, Goal, Lesson};
use crate::schema;
use crate::session::query::{encode, split_query};
use crate::session::{Notice, Session, Source};

impl Classroom {
    /// The lesson's progress (None until the lesson is first opened).
    pub fn lesson(&self) -> Option<&LessonProgress> {
        self.lesson.as_ref()
    }

    /// True while the lesson panel is open.
    pub fn lesson_active(&self) -> bool {
        self.lesson.as_ref().is_some_and(|l| l.active)
    }

    /// Opens the lesson at `step` (0-based; the last step if beyond): the step's settings, run from rest.
    pub fn lesson_open(&mut self, session: &mut Session, step: usize) -> Result<(), Error> {
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
        self.enter(session, step)?;
        session.set_note("The lesson uses the full view; leave it any time to explore from where it is.");
        self.sync(session);
        Ok(())
    }

    /// Goes on to the next step, remembering how this one was left.
    pub fn lesson_next(&mut self, session: &mut Session) -> Result<(), Error> {
        let (step, count) = self.lesson_position()?;
        if step + 1 >= count {
            return Err(lesson_error("this is the last step"));
        }
        let l = self.lesson.as_ref().expect("positioned");
        if !l.revealed(step) {
            if l.lesson.next_waits {
                return Err(lesson_error(WAIT));
            }
            // Gone on without the answer or the task: the record says so, once per step.
            let skipped = l.record.entries.iter().any(|e| e.step == step + 1 && e.kind == SKIPPED);
            if !skipped {
                let entry = Entry { kind: SKIPPED.into(), result: SKIPPED.into(), ..task_entry(&l.lesson, step, "") };
                self.record(session, entry);
            }
        }
        self.remember_step(session, step);
        self.enter(session, step + 1)?;
        self.sync(session);
        Ok(())
    }

    /// Goes back to the previous step exactly as the student left it.
    pub fn lesson_back(&mut self, session: &mut Session) -> Result<(), Error> {
        let (step, _) = self.lesson_position()?;
        if step == 0 {
            return Err(lesson_error("this is the first step"));
        }
        self.remember_step(session, step);
        self.enter(session, step - 1)?;
        self.sync(session);
        Ok(())
    }

    /// Answers the step's question with choice `choice` (0-based): the first answer is remembered
    /// (later ones change nothing) and the step's "then" settings, if any, are applied (from rest).
    pub fn lesson_answer(&mut self, session: &mut Session, choice: usize) -> Result<(), Error> {
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
        self.record(session, entry);
        if let Some(state) = then {
            self.apply_lesson_state(session, &state)?;
        }
        self.sync(session);
        Ok(())
    }

    /// Shows a task's result without the student having done it ("show me"): the step's "show"
    /// settings, if any, are applied over the current ones, so the result the answer describes is
    /// on screen.
    pub fn lesson_reveal(&mut self, session: &mut Session) -> Result<(), Error> {
        let (step, _) = self.lesson_position()?;
        let progress = self.lesson.as_mut().expect("positioned");
        if !progress.done[step] && progress.lesson.steps[step].goal.is_some() {
            let entry = task_entry(&progress.lesson, step, "shown");
            self.record(session, entry);
        }
        let progress = self.lesson.as_mut().expect("positioned");
        progress.done[step] = true;
        if let Some(show) = progress.lesson.steps[step].show.clone() {
            let next = Self::read_over(session, &show)?;
            session.apply_settings(next, false, "")?;
        }
        self.sync(session);
        Ok(())
    }

    /// Closes the lesson panel; the settings stay as they are, to explore from.
    pub fn lesson_leave(&mut self, session: &mut Session) {
        if let Some(l) = self.lesson.as_mut() {
            l.active = false;
        }
        self.sync(session);
    }

    /// Marks the step's goal met if it is (called with the other periodic work).
    pub(super) fn check_lesson_goal(&mut self, session: &Session) {
        let Some(l) = self.lesson.as_ref().filter(|l| l.active) else { return };
        let step = l.step;
        if l.done[step] {
            return;
        }
        let met = l.lesson.steps[step].goal.as_ref().is_some_and(|g| goal_met(session, g));
        if met {
            let l = self.lesson.as_mut().expect("active");
            l.done[step] = true;
            let entry = task_entry(&l.lesson, step, "done");
            self.record(session, entry);
        }
    }

    /// The stable windows are hidden by the step until its answer is revealed.
    pub(super) fn lesson_hides_windows(&self) -> bool {
        self.lesson.as_ref().is_some_and(|l| l.active && l.lesson.steps[l.step].hide_windows && !l.revealed(l.step))
    }

    /// The lesson's step shown (0-based; None when the lesson is not open).
    pub fn lesson_step_shown(&self) -> Option<usize> {
        self.lesson.as_ref().filter(|l| l.active).map(|l| l.step)
    }

    /// A teacher's lesson, if one replaced the built-in lesson: its file's name (or path) and text.
    pub fn teacher_lesson(&self) -> Option<(&str, &str)> {
        match (&self.lesson_origin, &self.lesson_text) {
            (LessonOrigin::BuiltIn, _) | (_, None) => None,
            (origin, Some(text)) => Some((origin.name(), text)),
        }
    }

    /// The step shown, for the page (None when the lesson is not open), in the session's
    /// student mode or not.
    pub fn lesson_status(&self, session: &Session) -> Option<LessonStatus> {
        let l = self.lesson.as_ref().filter(|l| l.active)?;
        let i = l.step;
        let s = &l.lesson.steps[i];
        let revealed = l.revealed(i);
        Some(LessonStatus {
            lesson_title: l.lesson.title.clone(),
            source: self.lesson_origin.name().to_string(),
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
            can_next: i + 1 < l.lesson.steps.len() && !(l.lesson.next_waits && !revealed),
            waits: l.lesson.next_waits && !revealed && i + 1 < l.lesson.steps.len(),
            record: l.record.status(&l.lesson),
            student_mode: self.student_mode(session),
        })
    }

    /// "lesson=3" while the lesson is open (1-based), for the URL.
    pub(super) fn lesson_query(&self) -> Option<String> {
        let l = self.lesson.as_ref().filter(|l| l.active)?;
        match &self.lesson_origin {
            // The built-in lesson, and the one an offline file carries: the page has it.
            LessonOrigin::BuiltIn | LessonOrigin::Carried(_) => Some(format!("lesson={}", l.step + 1)),
            LessonOrigin::Path(path) => Some(format!("lesson_src={}&lesson={}", encode(path), l.step + 1)),
            // A file from the user's disk: a link cannot bring it back.
            LessonOrigin::File(_) => None,
        }
    }

    /// Opens the lesson a URL names (`lesson=3`), then reads the URL's other settings over the
    /// step's: a link written while in the lesson comes back as it was. A step past the last
    /// opens the last, with a notice.
    pub(super) fn open_lesson_from(&mut self, session: &mut Session, query: &str) -> Result<Option<Notice>, Error> {
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
        self.lesson_open(session, step - 1)?;
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
            .map(|(k, v)| format!("{}={}", encode(k), encode(v)))
            .collect();
        if !rest.is_empty() {
            let mut next = *session.settings();
            next.read(&rest.join("&"), Source::Page)?;
            session.apply_settings(next, true, "")?;
        }
        Ok(notice)
    }

    fn lesson_position(&self) -> Result<(usize, usize), Error> {
        let l = self.lesson.as_ref().filter(|l| l.active).ok_or_else(|| lesson_error("the lesson is not open"))?;
        Ok((l.step, l.lesson.steps.len()))
    }

    fn remember_step(&mut self, session: &Session, step: usize) {
        let settings = *session.settings();
        if let Some(l) = self.lesson.as_mut() {
            l.left[step] = Some(settings);
        }
    }

    /// Shows step `step`: as the student left it, or from its state string.
    fn enter(&mut self, session: &mut Session, step: usize) -> Result<(), Error> {
        let l = self.lesson.as_mut().expect("the lesson is open");
        l.step = step;
        let left = l.left[step];
        let state = l.lesson.steps[step].state.clone();
        match left {
            Some(settings) => session.apply_settings(settings, true, "")?,
            None => self.apply_lesson_state(session, &state)?,
        }
        // A new step starts clean: the faint ghost compares within a step (before and after its
        // answer), not with whatever ran before.
        session.forget_ghost();
        Ok(())
    }

    /// A step's state string over the page's start, in the full view, run from rest.
    fn apply_lesson_state(&mut self, session: &mut Session, state: &str) -> Result<(), Error> {
        let mut next = Self::step_start(session);
        next.read(state, Source::Lesson)?;
        next.view.tab = crate::session::named::step_tab(state, &next.view, session.settings().view.tab);
        session.apply_settings(next, true, "")?;
        // A step may start at a moment (`t=2&paused=1`).
        self.go_to_start(session)
    }
}

/// The step's goal is met by the session's run A and settings.
fn goal_met(session: &Session, goal: &Goal) -> bool {
    let a = session.run(0).expect("run A");
    if goal.time.is_some_and(|t| a.closed_loop().time() < t - 1e-9) {
        return false;
    }
    if let Some(v) = &goal.verdict {
        if crate::session::run_status("A", a).verdict != v {
            return false;
        }
    }
    goal.settings.iter().all(|(key, text)| {
        let Some(p) = schema::param(key) else { return false };
        p.parse(text, false).ok().is_some_and(|v| session.settings().get(key) == Some(v))
    })
}

impl Classroom {
    /// Replaces the lesson by a teacher's: its file's bytes, read, parsed and checked as the
    /// built-in lesson is, then opened at its first step. A mistake leaves the lesson as it was and
    /// says which line and what is wrong.
    pub fn load_lesson(&mut self, session: &mut Session, origin: LessonOrigin, bytes: &[u8]) -> Result<(), Error> {
        let (text, parsed) = checked(bytes)?;
        self.lesson_origin = origin;
        // A homework link's lesson, if one was open, is not this one.
        self.link_fragment = None;
        self.lesson = Some(LessonProgress::new(parsed, &text));
        self.lesson_text = Some(text);
        self.lesson_open(session, 0)
    }

    /// The teacher's lesson opened from a file travels on in the page's address, as a homework
    /// link carries it (`fragment`, `lesson=…&name=…`, made by [`super::link::lesson_fragment`]
    /// from this lesson's text): a reload brings it back at the step the address names, and the
    /// embed builder's steps carry it.
    pub fn carry_in_link(&mut self, session: &mut Session, fragment: &str) -> Result<(), Error> {
        let LessonOrigin::File(name) = &self.lesson_origin else {
            return Err(lesson_error("only a lesson opened from a file moves into the address"));
        };
        self.lesson_origin = LessonOrigin::Carried(name.clone());
        self.link_fragment = Some(fragment.trim_start_matches('#').to_string());
        self.sync(session);
        Ok(())
    }

    /// Gives the classroom the wall clock (ms since 1970), for the answers' times.
    pub fn set_wall_clock(&mut self, ms: f64) {
        self.wall_clock_ms = Some(ms);
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

    /// [`Classroom::restore_answers`] from the CSV the page kept ([`Record::to_csv`]).
    pub fn restore_answers_csv(&mut self, csv: &str) -> Result<(), Error> {
        let steps = self.lesson.as_ref().map_or(0, |l| l.lesson.steps.len());
        self.restore_answers(Record::from_csv(csv, steps)?)
    }

    /// Who answers: the name (and student id) the student gives once, written into the answers
    /// they hand in ([`Record::student`]).
    pub fn set_student(&mut self, name: &str) -> Result<(), Error> {
        let name = crate::classroom::answers::student_name(name)?;
        if let Some(l) = self.lesson.as_mut() {
            l.record.student = name;
        }
        Ok(())
    }

    /// Forgets every answer and task of the lesson (the page's "Clear my answers"); the step shown
    /// stays, from its start.
    pub fn clear_answers(&mut self, session: &mut Session) -> Result<(), Error> {
        let l = self.lesson.as_mut().ok_or_else(|| lesson_error("the lesson is not open"))?;
        let n = l.lesson.steps.len();
        l.answers = vec![None; n];
        l.done = vec![false; n];
        l.left = vec![None; n];
        l.lifted = vec![false; n];
        l.record.entries.clear();
        let (step, active) = (l.step, l.active);
        if active {
            self.enter(session, step)?;
        }
        self.sync(session);
        Ok(())
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

/// Why *Next ▸* waits, in a lesson that says `next: waits`.
const WAIT: &str = "this lesson waits for each answer: answer this step's question (and do its task) to go on";

fn lesson_error(message: &str) -> Error {
    Error::Lesson { line: 0, message: message.into() }
}
