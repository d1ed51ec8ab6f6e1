//! The classroom the page has open — the lesson, the answers to hand in, student mode, a link's
//! moment, embeds — for the page's façade (`www/js/flexarm.js`), which composes it with the
//! physics [`WebSession`]: every method that changes something takes that session, and after it
//! the classroom re-derives what the session hides. Converts and forwards.

use wasm_bindgen::prelude::*;

use super::session::WebSession;
use super::{js_error, to_js};
use crate::classroom::answers::Record;
use crate::classroom::progress::LessonOrigin;
use crate::classroom::{Classroom, LessonFiles};
use crate::session::Notice;

/// The session's status and the classroom's, as the page reads them.
#[derive(serde::Serialize)]
struct PageStatus {
    session: crate::session::Status,
    classroom: crate::classroom::ClassroomStatus,
}

/// What the classroom adds to the page: `new Classroom(session, query, lessonText, teacherPath,
/// teacherBytes)` right after `new Session(query)`.
#[wasm_bindgen(js_name = Classroom)]
pub struct WebClassroom {
    inner: Classroom,
    notices: Vec<Notice>,
}

/// Runs a classroom change on the session, then lets the classroom follow it.
fn change<T>(
    c: &mut WebClassroom,
    s: &mut WebSession,
    f: impl FnOnce(&mut Classroom, &mut crate::session::Session) -> T,
) -> T {
    let out = f(&mut c.inner, s.session_mut());
    c.inner.follow(s.session_mut());
    out
}

#[wasm_bindgen(js_class = Classroom)]
impl WebClassroom {
    /// A class's answer files (`names[i]`, `texts[i]`: the page's CSV each) merged into one table,
    /// with the open lesson's steps where they answer it: `{lesson, counted, refused: [[name, why]],
    /// steps: [{step, title, …}], questions, rows: [[right, wrong, tasks]], student_rows: [[name,
    /// file, score, mark per step…]], summary, csv, students_csv}` — the same as `flexarm answers
    /// merge`.
    #[wasm_bindgen(js_name = mergeAnswers)]
    pub fn merge_answers(&self, names: Vec<String>, texts: Vec<String>) -> Result<JsValue, JsError> {
        use crate::classroom::class::{AnswerFile, ClassTable};
        #[derive(serde::Serialize)]
        struct Merged {
            #[serde(flatten)]
            table: ClassTable,
            rows: Vec<[String; 3]>,
            student_rows: Vec<Vec<String>>,
            summary: String,
            csv: String,
            students_csv: String,
        }
        let files: Vec<AnswerFile> =
            names.into_iter().zip(texts).map(|(name, text)| AnswerFile { name, text }).collect();
        let table = self.inner.merge_answers(&files);
        let rows = table.steps.iter().map(ClassTable::row_words).collect();
        let student_rows = table.students.iter().map(|s| table.student_row(s)).collect();
        let (summary, csv, students_csv) = (table.summary(), table.to_csv(), table.students_csv());
        to_js(&Merged { table, rows, student_rows, summary, csv, students_csv })
    }

    /// The classroom of a URL query (the same the session was opened from): the lesson it names
    /// (`lesson=3`) over the session, and the link's moment (`t=3&paused=1`). `lesson_text`: the
    /// built-in lesson the page fetched (`lessons/paper.md`; without it the lesson cannot open).
    /// A teacher's lesson, used instead of the built-in one if it reads and passes the checks, by
    /// its path (or name) and bytes: the file `lesson_src=PATH` names, which the page fetched, or
    /// (`teacher_carried`) the one an offline file or a homework link carries (`link_fragment`:
    /// the link's fragment, which an embed of its steps carries on). `offline`: the page is an
    /// offline file. Values it could not take are in `notices()`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        session: &mut WebSession,
        query: &str,
        lesson_text: Option<String>,
        teacher_path: Option<String>,
        teacher_bytes: Option<Vec<u8>>,
        teacher_carried: bool,
        offline: bool,
        link_fragment: Option<String>,
    ) -> WebClassroom {
        let teacher = teacher_path.zip(teacher_bytes).map(|(path, bytes)| {
            (if teacher_carried { LessonOrigin::Carried(path) } else { LessonOrigin::Path(path) }, bytes)
        });
        let files = LessonFiles { built_in: lesson_text, teacher, offline, link: link_fragment };
        let (inner, notices) = Classroom::open_on(session.session_mut(), query, files);
        WebClassroom { inner, notices }
    }

    /// `[{key, text}]`: what the query's lesson and moment could not take, and why.
    pub fn notices(&self) -> Result<JsValue, JsError> {
        to_js(&self.notices)
    }

    /// After the session changed by itself (a setting, a reset, time): checks the lesson step's
    /// goal and what student mode hides.
    pub fn follow(&mut self, session: &mut WebSession) {
        self.inner.follow(session.session_mut());
    }

    /// Everything the page says, in one object (one conversion, not two): `{session: {runs: [{run,
    /// verdict, headline, detail, observed, measured, finished, rho, spectral_radius, growth_rate,
    /// announce, readouts, settings}], note, preset, arm, showing, maps, windows, ghost, timeline,
    /// figure, cycle, story}, classroom: {lesson: {lesson_title, source, steps, index, title, text,
    /// terms, task, done, question, answer, can_back, can_next, record} | null, hidden: {text,
    /// controls} | null}}`. Brings the stable windows and the lesson step's goal up to date first
    /// (a few ms after a change of α or the feedback), so call it a few times a second.
    pub fn status(&mut self, session: &mut WebSession) -> Result<JsValue, JsError> {
        let s = session.session_mut();
        s.refresh();
        self.inner.follow(s);
        to_js(&PageStatus { session: s.status(), classroom: self.inner.status(s) })
    }

    /// The state string (the URL query) of everything set, the lesson step among it.
    #[wasm_bindgen(js_name = stateString)]
    pub fn state_string(&self, session: &WebSession) -> String {
        self.inner.state_string(session.session())
    }

    /// Replaces the lesson by a file the user opened or dropped (its name and bytes), checked as
    /// the built-in lesson is, and opens it; throws with the line and the mistake, and the lesson
    /// stays as it was.
    #[wasm_bindgen(js_name = loadLesson)]
    pub fn load_lesson(&mut self, session: &mut WebSession, name: &str, bytes: &[u8]) -> Result<(), JsError> {
        let origin = LessonOrigin::File(name.to_string());
        change(self, session, |c, s| c.load_lesson(s, origin, bytes)).map_err(|e| JsError::new(&format!("{name}: {e}")))
    }

    /// One of the classroom's changes of the session, named (one export for all: the façade gives
    /// each its typed method): "open" the lesson at step `n` (0-based), "next", "back", "answer"
    /// with choice `n` (0-based), "reveal" the step's result without the task, "leave" the lesson,
    /// "clear" the answers, "show" what student mode hides, "keep-student-mode" (a lesson this browser
    /// kept student mode for). Throws with the reason, or for an
    /// unknown action.
    pub fn act(&mut self, session: &mut WebSession, action: &str, n: usize) -> Result<(), JsError> {
        change(self, session, |c, s| match action {
            "open" => c.lesson_open(s, n),
            "next" => c.lesson_next(s),
            "back" => c.lesson_back(s),
            "answer" => c.lesson_answer(s, n),
            "reveal" => c.lesson_reveal(s),
            "leave" => Ok(c.lesson_leave(s)),
            "clear" => c.clear_answers(s),
            "show" => Ok(c.show_answers(s)),
            "keep-student-mode" => Ok(c.keep_student_mode(s)),
            _ => Err(crate::error::Error::NotReady("no such classroom action")),
        })
        .map_err(js_error)
    }

    /// The teacher's lesson just opened from a file (`name`, its text compressed with raw deflate:
    /// `compressed`) moves into the page's address: returns the fragment (without `#`) for the
    /// address bar; throws with the size and the reason when it is too long for an address.
    #[wasm_bindgen(js_name = carryInLink)]
    pub fn carry_in_link(
        &mut self,
        session: &mut WebSession,
        name: &str,
        compressed: &[u8],
    ) -> Result<String, JsError> {
        let fragment = crate::classroom::link::lesson_fragment(name, compressed).map_err(js_error)?;
        change(self, session, |c, s| c.carry_in_link(s, &fragment)).map_err(js_error)?;
        Ok(fragment)
    }

    /// True once after a link or a lesson step asked to start paused (`paused=1`).
    #[wasm_bindgen(js_name = takeStartPaused)]
    pub fn take_start_paused(&mut self) -> bool {
        self.inner.take_start_paused()
    }

    /// The state string with the moment shown (`…&paused=1&t=3.25`): "Copy link to this moment".
    #[wasm_bindgen(js_name = momentQuery)]
    pub fn moment_query(&self, session: &WebSession) -> String {
        self.inner.moment_query(session.session())
    }

    /// The offline file (UTF-8 bytes) of `bundle`'s files, their archive gzip-compressed by the
    /// page (`compressed`), opening where the page is now: its state, the lesson step shown and a
    /// teacher's lesson, and, if `paused`, this moment.
    #[wasm_bindgen(js_name = offlineFile)]
    pub fn offline_file(
        &self,
        session: &WebSession,
        bundle: &super::offline::WebBundle,
        compressed: &[u8],
        paused: bool,
    ) -> Result<Vec<u8>, JsError> {
        let start = crate::offline::OfflineStart::of(&self.inner, session.session(), paused);
        bundle.inner.html(compressed, &start).map(String::into_bytes).map_err(js_error)
    }

    /// An embed of the page at `page_url` as the embed builder's `choices` say (a query:
    /// `views=zplane,rho&width=760&height=480&paused=1&t=3&strip=delta,reset&lesson=4`):
    /// `{html, src, width, height, title}`; throws naming a bad choice.
    pub fn embed(&self, session: &WebSession, page_url: &str, choices: &str) -> Result<JsValue, JsError> {
        to_js(&self.inner.embed(session.session(), page_url, choices).map_err(js_error)?)
    }

    /// The embed builder's choices to start from (what is on screen), as a query.
    #[wasm_bindgen(js_name = embedDefaults)]
    pub fn embed_defaults(&self, session: &WebSession) -> String {
        self.inner.embed_defaults(session.session())
    }

    /// Gives the classroom the wall clock (`Date.now()`), for the answers' times.
    #[wasm_bindgen(js_name = setWallClock)]
    pub fn set_wall_clock(&mut self, ms: f64) {
        self.inner.set_wall_clock(ms);
    }

    /// The record as CSV (empty before the lesson is opened): the page downloads it, reshapes it
    /// into JSON, keeps it in localStorage and gives it back after a reload.
    #[wasm_bindgen(js_name = answersCsv)]
    pub fn answers_csv(&self) -> String {
        self.inner.answers_record().map_or(String::new(), Record::to_csv)
    }

    /// Gives back the record the page kept (the CSV of `answersCsv()`): throws if it is not this
    /// lesson's (its text changed) or does not read, and nothing changes then.
    #[wasm_bindgen(js_name = restoreAnswers)]
    pub fn restore_answers(&mut self, session: &mut WebSession, csv: &str) -> Result<(), JsError> {
        change(self, session, |c, _| c.restore_answers_csv(csv)).map_err(js_error)
    }

    /// Who answers (the name, and the student id if the teacher asks): written into the answers;
    /// throws with the reason for a name too long.
    #[wasm_bindgen(js_name = setStudent)]
    pub fn set_student(&mut self, name: &str) -> Result<(), JsError> {
        self.inner.set_student(name).map_err(js_error)
    }

    /// `{name, text}` of the teacher's lesson loaded now (what a homework link carries), or null
    /// for the built-in lesson.
    #[wasm_bindgen(js_name = teacherLesson)]
    pub fn teacher_lesson(&self) -> Result<JsValue, JsError> {
        #[derive(serde::Serialize)]
        struct Lesson<'a> {
            name: &'a str,
            text: &'a str,
        }
        to_js(&self.inner.teacher_lesson().map(|(name, text)| Lesson { name, text }))
    }
}

/// The homework link for the lesson file `name` whose bytes, compressed with raw deflate, are
/// `compressed`, on the page at `base` (its address without query or fragment); throws with the
/// size and the reason when the lesson is too long for a link.
#[wasm_bindgen(js_name = lessonLink)]
pub fn lesson_link(base: &str, name: &str, compressed: Vec<u8>) -> Result<String, JsError> {
    crate::classroom::link::lesson_link(base, name, &compressed).map_err(js_error)
}

/// `{name, bytes}` (bytes compressed with raw deflate) of the lesson a URL fragment carries, null
/// when it carries none; throws when it carries one the link cut or garbled.
#[wasm_bindgen(js_name = readLessonFragment)]
pub fn read_lesson_fragment(fragment: &str) -> Result<JsValue, JsError> {
    #[derive(serde::Serialize)]
    struct Carried {
        name: String,
        bytes: Vec<u8>,
    }
    let carried = crate::classroom::link::read_lesson_fragment(fragment).map_err(js_error)?;
    to_js(&carried.map(|(name, bytes)| Carried { name, bytes }))
}
