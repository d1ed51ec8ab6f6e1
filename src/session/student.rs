//! Student mode for homework and exams (`answers=hidden` in a link, or `answers: hidden` under a
//! lesson's title): what gives the answer away — the verdict and ρ, the stable windows of δ, ρ(δ),
//! the stability maps and the predicted slope — stays hidden until the student has committed an
//! answer to the lesson step's question (and met its goal), or the teacher's step shows them
//! (`answers: shown`). The page says what is hidden and how to show it; the student may lift it
//! ("Show them"), and the answers' record says so.

use super::answers::Entry;
use super::{HiddenStatus, RunStatus, Session, ViewSettings};

/// The page's controls that show nothing while the answers are hidden (the figures' switches and
/// the downloads that carry ρ): the page disables them.
pub const HIDDEN_CONTROLS: [&str; 9] =
    ["poles", "rho", "map", "log", "swing", "export-python", "export-data-json", "export-data-csv", "export-svg-maps"];

impl Session {
    /// Student mode is on: set by the link or the lesson, not lifted by the student.
    pub fn student_mode(&self) -> bool {
        let by_lesson = self.lesson.as_ref().is_some_and(|l| l.lesson().answers_hidden);
        (self.settings.view.answers_hidden || by_lesson) && !self.answers_shown
    }

    /// What gives the answer away is hidden now: student mode, and the lesson step shown has not
    /// been answered (outside the lesson, always).
    pub fn answers_hidden(&self) -> bool {
        self.student_mode() && !self.lesson.as_ref().is_some_and(|l| l.answers_revealed_here())
    }

    /// The figures drawn: while the answers are hidden, only those that show the run itself (the
    /// arm, the errors, the torques, the zoom on one instant) — not the analysis' (the pole plot,
    /// ρ(δ), the maps, log |e| with its slope and the swing's split, the swing's shape).
    pub fn drawn_view(&self) -> ViewSettings {
        let v = self.settings.view.shown();
        if self.answers_hidden() {
            ViewSettings { poles: false, rho: false, map: false, log: false, swing: false, answers_hidden: true, ..v }
        } else {
            ViewSettings { answers_hidden: false, ..v }
        }
    }

    /// What the page says while the answers are hidden.
    pub(super) fn hidden_status(&self) -> HiddenStatus {
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
    pub fn show_answers(&mut self) {
        if !self.answers_hidden() {
            return;
        }
        let Some(step) = self.lesson.as_ref().and_then(|l| l.open_step()) else {
            self.answers_shown = true;
            self.settings.view.answers_hidden = false;
            return;
        };
        let l = self.lesson.as_mut().expect("open");
        l.lift(step);
        let title = l.lesson().steps[step].title.clone();
        self.record(Entry {
            step: step + 1,
            step_title: title,
            kind: "answers shown".into(),
            choice: None,
            choice_text: String::new(),
            result: "shown".into(),
            state: String::new(),
            time: String::new(),
        });
    }
}

/// What a student in student mode (`answers=hidden`) may not see yet: the verdict and ρ, the
/// observation (it says whether the simulation agrees with ρ), the growth rates and A4. What the
/// figure shows (the errors, the torques, the time) stays; the words say what is hidden, for the
/// eye and the screen reader alike.
pub fn hide_answers(r: &mut RunStatus) {
    const HIDDEN: &str = "hidden until you answer";
    r.verdict = "hidden";
    r.headline = "Verdict hidden";
    r.detail = "student mode: the verdict and ρ wait for your answer".into();
    r.observed = if r.finished {
        // What the run did is on screen: say why it stopped, not what ρ says.
        "The run stopped: the errors passed π rad. Restart to watch it again.".into()
    } else {
        "Watch the errors: do they grow or die out?".into()
    };
    r.measured = false;
    r.rho = format!("linear analysis: {HIDDEN}");
    r.spectral_radius = None;
    r.growth_rate = None;
    r.announce = format!("Run {}: the verdict is hidden until you answer.", r.run);
    r.readouts.growth = HIDDEN.into();
    r.readouts.a4 = HIDDEN.into();
}
