//! Where a student is in the guided lesson ([`crate::lesson`]) and what they did: the step shown,
//! each step's answer, goal and settings as left, the record, the steps where student mode was
//! lifted — and the lesson's checks, the same for the built-in lesson and a teacher's file.

use serde::Serialize;

use super::answers::{self, AnswersStatus, Record};
use crate::error::Error;
use crate::lesson::{self, Lesson, Term};
use crate::schema;
use crate::session::{Settings, Source};

/// Where the student is in the lesson and what they did.
#[derive(Clone, Debug)]
pub struct LessonProgress {
    pub(super) lesson: Lesson,
    /// The step shown (0-based).
    pub(super) step: usize,
    /// The lesson panel is open (false after leaving; the progress stays for coming back).
    pub(super) active: bool,
    /// Each step's chosen answer.
    pub(super) answers: Vec<Option<usize>>,
    /// Each step's goal met (or revealed on request).
    pub(super) done: Vec<bool>,
    /// The settings each step had when the student left it.
    pub(super) left: Vec<Option<Settings>>,
    /// What the student did, to hand in.
    pub(super) record: Record,
    /// Each step where the student showed the answers student mode hid ("Show them").
    pub(super) lifted: Vec<bool>,
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
    /// *Next ▸* waits for this step's answer (the lesson says `next: waits`).
    pub waits: bool,
    /// The answers so far, to hand in (the summary the last step shows).
    pub record: AnswersStatus,
    /// Student mode is on for this lesson: the page keeps it per lesson in the browser, so that
    /// a reload shows nothing the lesson hides.
    pub student_mode: bool,
}

impl LessonProgress {
    pub fn new(lesson: Lesson, text: &str) -> Self {
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
    pub fn answers_revealed_here(&self) -> bool {
        let s = &self.lesson.steps[self.step];
        self.active
            && (s.answers_shown
                || self.lifted[self.step]
                || ((s.question.is_some() || s.goal.is_some()) && self.revealed(self.step)))
    }

    /// The student showed the hidden answers on step `step` ("Show them").
    pub fn lift(&mut self, step: usize) {
        self.lifted[step] = true;
    }

    /// The answer of step `i` may be shown.
    pub fn revealed(&self, i: usize) -> bool {
        let s = &self.lesson.steps[i];
        let answered = s.question.is_none() || self.answers[i].is_some();
        let done = s.goal.is_none() || self.done[i];
        answered && done
    }
}

/// Checks a lesson against the settings it uses: every step's `state:`, `then:` and `show:` reads
/// as a state string, every goal names settings with values they can take. The built-in lesson and
/// a teacher's file pass the same checks; a mistake names its own line.
pub fn validate(lesson: &Lesson) -> Result<(), Error> {
    for (i, step) in lesson.steps.iter().enumerate() {
        // A mistake names the line it is on (the `state:` line, not the step's title): `line`,
        // else the step's heading where the line is not known (0).
        let at = |(what, line): (&str, usize), e: &dyn std::fmt::Display| Error::Lesson {
            line: if line > 0 { line } else { step.line },
            message: format!("step {} ('{}'): {what}: {e}", i + 1, step.title),
        };
        let goal = ("goal", step.lines.goal);
        let mut settings = Settings::page_start();
        settings.read(&step.state, Source::Lesson).map_err(|e| at(("state", step.lines.state), &e))?;
        for (what, text) in [(("then", step.lines.then), &step.then), (("show", step.lines.show), &step.show)] {
            if let Some(text) = text {
                let mut next = settings;
                next.read(text, Source::Lesson).map_err(|e| at(what, &e))?;
            }
        }
        // A goal of time alone is met by waiting: the step must start paused (`paused=1`), so that
        // only the student's Play meets it — a task counts as the student's only if they did it.
        if step.goal.as_ref().is_some_and(|g| g.verdict.is_none() && g.settings.is_empty()) && !settings.start.paused {
            return Err(at(
                goal,
                &"time alone is met by waiting: start the step paused (paused=1 in its state), so that the \
                  student's Play does it",
            ));
        }
        for (key, value) in step.goal.iter().flat_map(|g| g.settings.iter()) {
            let p = schema::param(key).ok_or_else(|| {
                at(
                    goal,
                    &format!("'{key}' is not a setting (a goal takes verdict=, time= and settings such as pf=off)"),
                )
            })?;
            // Within the page's control: what a student can set.
            p.parse(value, true).map_err(|e| at(goal, &format!("{key}={value} can never be met: {e}")))?;
        }
    }
    Ok(())
}

/// A teacher's lesson file read, parsed and checked as the built-in lesson is: its text and the
/// lesson, or the first mistake.
pub fn checked(bytes: &[u8]) -> Result<(String, Lesson), Error> {
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
    /// The teacher's lesson an offline file carries (its file name): the file's links open it.
    Carried(String),
}

impl LessonOrigin {
    /// The lesson file's name or path ("" for the built-in lesson).
    pub fn name(&self) -> &str {
        match self {
            LessonOrigin::BuiltIn => "",
            LessonOrigin::Path(name) | LessonOrigin::File(name) | LessonOrigin::Carried(name) => name,
        }
    }
}
