//! Student mode for homework and exams (`answers=hidden` in a link, or `answers: hidden` under a
//! lesson's title): what gives the answer away — the verdict and ρ, the stable windows of δ, ρ(δ),
//! the stability maps and the predicted slope — stays hidden until the student has committed an
//! answer to the lesson step's question (and met its goal), or the teacher's step shows them
//! (`answers: shown`). The page says what is hidden and how to show it; the student may lift it
//! ("Show them"), and the answers' record says so.

use super::answers::Entry;
use super::room::{Classroom, HiddenStatus};
use crate::session::Session;

/// The page's controls that show nothing while the answers are hidden (the figures' switches and
/// the downloads that carry ρ): the page disables them.
pub const HIDDEN_CONTROLS: [&str; 9] =
    ["poles", "rho", "map", "log", "swing", "export-python", "export-data-json", "export-data-csv", "export-svg-maps"];

impl Classroom {
    /// Student mode is on: set by the link (the session's `answers=hidden`) or the lesson, not
    /// lifted by the student.
    pub fn student_mode(&self, session: &Session) -> bool {
        let by_lesson = self.lesson.as_ref().is_some_and(|l| l.lesson().answers_hidden);
        (session.settings().view.answers_hidden || by_lesson) && !self.answers_shown
    }

    /// What gives the answer away is hidden now: student mode, and the lesson step shown has not
    /// been answered (outside the lesson, always). The session is told ([`Classroom::follow`]).
    pub fn answers_hidden(&self, session: &Session) -> bool {
        self.student_mode(session) && !self.lesson.as_ref().is_some_and(|l| l.answers_revealed_here())
    }

    /// Student mode comes back for a lesson this browser kept it for (the page keeps it per
    /// lesson text): a reload, or `answers=hidden` deleted from the address, shows nothing the
    /// lesson hides. What the student already answered stays shown.
    pub fn keep_student_mode(&mut self, session: &mut Session) {
        if self.student_mode(session) {
            return;
        }
        self.answers_shown = false;
        session.keep_student_mode();
        self.sync(session);
    }

    /// What the page says while the answers are hidden.
    pub fn hidden_status(&self) -> HiddenStatus {
        let hidden =
            "the verdict, ρ, the stable windows of δ, the pole plot, ρ(δ), the stability maps, log |e|, the swing's \
                      shape, the explanation and the data downloads";
        let lesson = self.lesson.as_ref().and_then(|l| l.open_step().map(|i| &l.lesson().steps[i]));
        let until = match lesson {
            Some(s) if s.question.is_some() => "until you answer this step's question",
            Some(s) if s.goal.is_some() => "until you have done this step's task",
            Some(_) => "on this step (a step with a question shows them once you answer)",
            None => "(open the lesson and answer a step's question to see them)",
        };
        let show = if lesson.is_some() {
            "“Show them” shows them on this step (your answers' record will say so)"
        } else {
            "“Show them” shows them for the rest of this visit"
        };
        HiddenStatus {
            text: format!("Student mode: {hidden} are hidden {until}. {show}."),
            controls: HIDDEN_CONTROLS.to_vec(),
        }
    }

    /// The student shows what is hidden ("Show them"): on a lesson step, for that step only (the
    /// next step hides them again), and the lesson's record says so; outside the lesson, for the
    /// rest of the session.
    pub fn show_answers(&mut self, session: &mut Session) {
        if !self.answers_hidden(session) {
            return;
        }
        let Some(step) = self.lesson.as_ref().and_then(|l| l.open_step()) else {
            self.answers_shown = true;
            session.lift_student_mode();
            self.sync(session);
            return;
        };
        let l = self.lesson.as_mut().expect("open");
        l.lift(step);
        let title = l.lesson().steps[step].title.clone();
        self.record(
            session,
            Entry {
                step: step + 1,
                step_title: title,
                kind: "answers shown".into(),
                choice: None,
                choice_text: String::new(),
                result: "shown".into(),
                state: String::new(),
                time: String::new(),
            },
        );
        self.sync(session);
    }
}
