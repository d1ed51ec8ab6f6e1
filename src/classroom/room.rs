//! The classroom itself: what a visit keeps (the lesson's progress and text, the clock, student
//! mode lifted, a moment to wait at), opening from a URL, following the session and telling it
//! what to hide, the status and the state string it adds.

use serde::Serialize;

use super::answers::{self, Entry};
use super::class::{merge, AnswerFile, ClassTable};
use super::progress::{checked, LessonOrigin, LessonProgress, LessonStatus};
use crate::error::Error;
use crate::session::query::split_query;
use crate::session::{Hidden, Notice, Session, Settings, Source};

/// What student mode hides at this moment, as the page says it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct HiddenStatus {
    /// "Student mode: the verdict, ρ, … are hidden until you answer this step's question."
    pub text: String,
    /// The figures' switches that show nothing while hidden (the page disables them).
    pub controls: Vec<&'static str>,
}

/// What the classroom adds to the page's status: the lesson's step and what student mode hides.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ClassroomStatus {
    /// The lesson's step, while the lesson is open.
    pub lesson: Option<LessonStatus>,
    /// Student mode: what is hidden now and how to show it (null when nothing is hidden).
    pub hidden: Option<HiddenStatus>,
}

/// The lessons a page opens with: the built-in one's text and, perhaps, a teacher's.
#[derive(Clone, Debug, Default)]
pub struct LessonFiles {
    /// The built-in lesson's text (the page fetches it; None: the native build's).
    pub built_in: Option<String>,
    /// A teacher's lesson and its bytes: the file `lesson_src=PATH` names, which the page fetched
    /// ([`LessonOrigin::Path`]), or the one an offline file carries ([`LessonOrigin::Carried`]).
    pub teacher: Option<(LessonOrigin, Vec<u8>)>,
    /// The page is an offline file: it can load no lesson by path but the ones it carries.
    pub offline: bool,
    /// The address's fragment the teacher's lesson came in (a homework link,
    /// [`super::link`]; with [`LessonOrigin::Carried`]): an embed of its steps carries it on.
    pub link: Option<String>,
}

impl LessonFiles {
    /// What a refused `lesson_src=` falls back to.
    fn instead(&self) -> &'static str {
        match self.teacher {
            Some((LessonOrigin::Carried(_), _)) => "the lesson this file carries is used instead",
            _ => "the built-in lesson is used instead",
        }
    }
}

/// The lesson, the answers, student mode and the link's moment of one visit.
#[derive(Clone, Debug, Default)]
pub struct Classroom {
    /// The guided lesson, once opened.
    pub(super) lesson: Option<LessonProgress>,
    /// The lesson's text (the page fetches it; the native build has it built in).
    pub(super) lesson_text: Option<String>,
    /// Where that text comes from.
    pub(super) lesson_origin: LessonOrigin,
    /// The wall clock the page last gave, ms since 1970 (None: none): the answers' times.
    pub(super) wall_clock_ms: Option<f64>,
    /// The student lifted student mode for this visit ("Show them").
    pub(super) answers_shown: bool,
    /// A link or a lesson step asked to start paused; the page takes it once.
    pub(super) start_paused: bool,
    /// The homework link's fragment the teacher's lesson came in (without `#`), if it did.
    pub(super) link_fragment: Option<String>,
}

impl Classroom {
    /// The page's session and classroom for a URL query: the session's settings from it, then
    /// the lesson it names (`lesson=3`; a teacher's lesson from `files`) with the URL's other
    /// settings over the step's, then the link's moment (`t=3&paused=1`). Bad values become
    /// notices.
    pub fn open(query: &str, files: LessonFiles) -> (Session, Classroom, Vec<Notice>) {
        let (mut session, mut notices) = Session::open(query);
        let (classroom, more) = Classroom::open_on(&mut session, query, files);
        notices.extend(more);
        (session, classroom, notices)
    }

    /// [`Classroom::open`] on a session already opened from the same query (the web handle
    /// builds the two apart): what the query says of the lesson and the moment, and its notices.
    pub fn open_on(session: &mut Session, query: &str, files: LessonFiles) -> (Classroom, Vec<Notice>) {
        let mut notices = Vec::new();
        let mut classroom = Classroom { lesson_text: files.built_in.clone(), ..Classroom::default() };
        // `lesson_src=PATH`: a teacher's lesson, which the page fetched if the path is on its site
        // (or, in an offline file, among the files it carries).
        let source = split_query(query).into_iter().rev().find(|(k, _)| k == "lesson_src").map(|(_, v)| v);
        let fetched = matches!(files.teacher, Some((LessonOrigin::Path(_), _)));
        if let Some(value) = source {
            match crate::lesson::source_path(&value) {
                Err(e) => notices.push(Notice {
                    key: "lesson_src".into(),
                    text: format!("{e} — {}", files.instead()),
                }),
                Ok(path) if !fetched => notices.push(Notice {
                    key: "lesson_src".into(),
                    text: if files.offline {
                        format!(
                            "lesson_src={path}: an offline file cannot load a lesson from a path, only the lessons it carries — drop the file on the page instead; {}",
                            files.instead()
                        )
                    } else {
                        format!(
                            "lesson_src={path}: the file could not be loaded from this site (is it beside the page?) — {}",
                            files.instead()
                        )
                    },
                }),
                Ok(_) => {}
            }
        }
        if let Some((origin, bytes)) = files.teacher {
            let name = origin.name().to_string();
            match checked(&bytes) {
                Ok((text, _)) => {
                    classroom.lesson_text = Some(text);
                    if matches!(origin, LessonOrigin::Carried(_)) {
                        classroom.link_fragment = files.link.map(|f| f.trim_start_matches('#').to_string());
                    }
                    classroom.lesson_origin = origin;
                }
                Err(e) => notices.push(Notice {
                    key: "lesson_src".into(),
                    text: format!("{name}: {e} — the built-in lesson is used instead"),
                }),
            }
        }
        // `lesson=3` opens the lesson at that step, with the URL's settings over the step's.
        match classroom.open_lesson_from(session, query) {
            Ok(notice) => notices.extend(notice),
            Err(e) => notices.push(Notice { key: "lesson".into(), text: e.to_string() }),
        }
        // `t=3&paused=1`: the link's moment.
        if let Err(e) = classroom.go_to_start(session) {
            notices.push(Notice { key: "t".into(), text: e.to_string() });
        }
        classroom.follow(session);
        (classroom, notices)
    }

    /// After a change the session made itself (a setting, a reset, time passing): checks the
    /// lesson step's goal and tells the session what is hidden now (student mode may have been
    /// switched by `answers=`).
    #[inline(never)] // one copy for every change the page makes, not one inlined into each
    pub fn follow(&mut self, session: &mut Session) {
        self.check_lesson_goal(session);
        self.sync(session);
    }

    /// Tells the session what student mode and the lesson step hide now.
    #[inline(never)]
    pub(super) fn sync(&self, session: &mut Session) {
        let hidden = Hidden { answers: self.answers_hidden(session), windows: self.lesson_hides_windows() };
        session.set_hidden(hidden);
    }

    /// A class's answer files merged into one table ([`merge`]), with every step of the open
    /// lesson that has a question or a task where the files answer this lesson's text.
    pub fn merge_answers(&self, files: &[AnswerFile]) -> ClassTable {
        merge(files, self.lesson.as_ref().map(|l| (&l.lesson, l.record.lesson_hash.as_str())))
    }

    /// The lesson's step and what student mode hides, for the page.
    pub fn status(&self, session: &Session) -> ClassroomStatus {
        ClassroomStatus {
            lesson: self.lesson_status(session),
            hidden: self.answers_hidden(session).then(|| self.hidden_status()),
        }
    }

    /// The state string: the session's, and the lesson step shown (`lesson=3`, with its
    /// `lesson_src=` for a teacher's file) — the page's URL.
    pub fn state_string(&self, session: &Session) -> String {
        match self.lesson_query() {
            Some(lesson) => format!("{}&{lesson}", session.state_string()),
            None => session.state_string(),
        }
    }

    /// The settings a step starts from: the page's start in the full view, at the session's speed,
    /// with student mode as the teacher's link set it.
    pub(super) fn step_start(session: &Session) -> Settings {
        let mut next = Settings::page_start();
        next.view.full = true;
        next.speed = session.settings().speed;
        // Student mode set by the teacher's link stays on through the steps.
        next.view.answers_hidden = session.settings().view.answers_hidden;
        next
    }

    /// Adds an entry to the record, stamped with the state string and the clock.
    #[inline(never)]
    pub(super) fn record(&mut self, session: &Session, mut entry: Entry) {
        entry.state = self.state_string(session);
        entry.time = answers::iso_time(self.wall_clock_ms.unwrap_or(f64::NAN));
        if let Some(l) = self.lesson.as_mut() {
            l.record.entries.push(entry);
        }
    }

    /// Reads `state` (a step's `then:` or `show:`) over the session's settings.
    pub(super) fn read_over(session: &Session, state: &str) -> Result<Settings, Error> {
        let mut next = *session.settings();
        next.read(state, Source::Lesson)?;
        Ok(next)
    }
}
