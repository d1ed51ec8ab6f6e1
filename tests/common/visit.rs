//! A visit of the page, natively: the physics session and the classroom around it, composed as
//! the page's façade composes them (`www/js/flexarm.js`) — every classroom call takes the
//! session, every change the session makes is followed by the classroom — so that the tests of the
//! lesson, the answers, student mode, moments and embeds read as the page uses them.

use std::ops::{Deref, DerefMut};

use flexarm::classroom::answers::Record;
use flexarm::classroom::embed::Embed;
use flexarm::classroom::progress::{LessonOrigin, LessonProgress, LessonStatus};
use flexarm::classroom::HiddenStatus;
use flexarm::classroom::{Classroom, LessonFiles};
use flexarm::error::Error;
use flexarm::session::{Notice, Session, Status};

pub struct Visit {
    pub session: Session,
    pub classroom: Classroom,
}

/// The session's status with the classroom's (`status.lesson`, `status.hidden`), as the page
/// merges them.
#[derive(serde::Serialize)]
pub struct FullStatus {
    #[serde(flatten)]
    pub status: Status,
    pub lesson: Option<LessonStatus>,
    pub hidden: Option<HiddenStatus>,
}

impl Deref for FullStatus {
    type Target = Status;
    fn deref(&self) -> &Status {
        &self.status
    }
}

impl Deref for Visit {
    type Target = Session;
    fn deref(&self) -> &Session {
        &self.session
    }
}

impl DerefMut for Visit {
    fn deref_mut(&mut self) -> &mut Session {
        &mut self.session
    }
}

impl Visit {
    /// The page for a URL query, the built-in lesson available.
    pub fn open(query: &str) -> (Visit, Vec<Notice>) {
        Self::open_with_lessons(query, None, None)
    }

    /// The page with a lesson text and a teacher's file (`lesson_src=`), as the page fetched them.
    pub fn open_with_lessons(
        query: &str,
        lesson_text: Option<String>,
        teacher: Option<(String, Vec<u8>)>,
    ) -> (Visit, Vec<Notice>) {
        let files = LessonFiles {
            built_in: lesson_text,
            teacher: teacher.map(|(path, bytes)| (LessonOrigin::Path(path), bytes)),
            offline: false,
            link: None,
        };
        let (session, classroom, notices) = Classroom::open(query, files);
        (Visit { session, classroom }, notices)
    }

    fn follow<T>(&mut self, out: T) -> T {
        self.classroom.follow(&mut self.session);
        out
    }

    pub fn status(&self) -> FullStatus {
        let c = self.classroom.status(&self.session);
        FullStatus { status: self.session.status(), lesson: c.lesson, hidden: c.hidden }
    }

    pub fn state_string(&self) -> String {
        self.classroom.state_string(&self.session)
    }

    pub fn refresh(&mut self) {
        self.session.refresh();
        self.follow(())
    }

    pub fn set(&mut self, key: &str, text: &str) -> Result<(), Error> {
        let r = self.session.set(key, text);
        self.follow(r)
    }

    pub fn read_state(&mut self, state: &str) -> Result<Vec<Notice>, Error> {
        let r = self.session.read_state(state);
        self.follow(r)
    }

    pub fn advance(&mut self, wall_seconds: f64) -> Result<f64, Error> {
        let r = self.session.advance(wall_seconds);
        self.follow(r)
    }

    pub fn lesson(&self) -> Option<&LessonProgress> {
        self.classroom.lesson()
    }

    pub fn lesson_open(&mut self, step: usize) -> Result<(), Error> {
        self.classroom.lesson_open(&mut self.session, step)
    }

    pub fn lesson_next(&mut self) -> Result<(), Error> {
        self.classroom.lesson_next(&mut self.session)
    }

    pub fn lesson_back(&mut self) -> Result<(), Error> {
        self.classroom.lesson_back(&mut self.session)
    }

    pub fn lesson_answer(&mut self, choice: usize) -> Result<(), Error> {
        self.classroom.lesson_answer(&mut self.session, choice)
    }

    pub fn lesson_reveal(&mut self) -> Result<(), Error> {
        self.classroom.lesson_reveal(&mut self.session)
    }

    pub fn lesson_leave(&mut self) {
        self.classroom.lesson_leave(&mut self.session)
    }

    pub fn lesson_status(&self) -> Option<LessonStatus> {
        self.classroom.lesson_status(&self.session)
    }

    pub fn load_lesson(&mut self, origin: LessonOrigin, bytes: &[u8]) -> Result<(), Error> {
        self.classroom.load_lesson(&mut self.session, origin, bytes)
    }

    pub fn student_mode(&self) -> bool {
        self.classroom.student_mode(&self.session)
    }

    pub fn show_answers(&mut self) {
        self.classroom.show_answers(&mut self.session)
    }

    pub fn set_wall_clock(&mut self, ms: f64) {
        self.classroom.set_wall_clock(ms)
    }

    pub fn answers_record(&self) -> Option<&Record> {
        self.classroom.answers_record()
    }

    pub fn restore_answers(&mut self, record: Record) -> Result<(), Error> {
        let r = self.classroom.restore_answers(record);
        self.follow(r)
    }

    pub fn restore_answers_csv(&mut self, csv: &str) -> Result<(), Error> {
        let r = self.classroom.restore_answers_csv(csv);
        self.follow(r)
    }

    pub fn clear_answers(&mut self) -> Result<(), Error> {
        self.classroom.clear_answers(&mut self.session)
    }

    pub fn take_start_paused(&mut self) -> bool {
        self.classroom.take_start_paused()
    }

    pub fn moment_query(&self) -> String {
        self.classroom.moment_query(&self.session)
    }

    pub fn embed(&self, page_url: &str, choices: &str) -> Result<Embed, Error> {
        self.classroom.embed(&self.session, page_url, choices)
    }

    pub fn embed_defaults(&self) -> String {
        self.classroom.embed_defaults(&self.session)
    }
}
