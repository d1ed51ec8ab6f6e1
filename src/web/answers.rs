//! The lesson's answers to hand in and student mode, for the page: the record as CSV (which the
//! page downloads, reshapes into JSON, keeps in localStorage and gives back after a reload), and
//! "Show them".

use wasm_bindgen::prelude::*;

use super::js_error;
use super::session::WebSession;
use crate::session::answers::Record;

#[wasm_bindgen(js_class = Session)]
impl WebSession {
    /// Gives the session the wall clock (`Date.now()`), for the answers' times.
    #[wasm_bindgen(js_name = setWallClock)]
    pub fn set_wall_clock(&mut self, ms: f64) {
        self.session_mut().set_wall_clock(ms);
    }

    /// The record as CSV (empty before the lesson is opened).
    #[wasm_bindgen(js_name = answersCsv)]
    pub fn answers_csv(&self) -> String {
        self.session().answers_record().map_or(String::new(), Record::to_csv)
    }

    /// Gives back the record the page kept (the CSV of `answersCsv()`): throws if it is not this
    /// lesson's (its text changed) or does not read, and nothing changes then.
    #[wasm_bindgen(js_name = restoreAnswers)]
    pub fn restore_answers(&mut self, csv: &str) -> Result<(), JsError> {
        self.session_mut().restore_answers_csv(csv).map_err(js_error)
    }

    /// Forgets the lesson's answers ("Clear my answers").
    #[wasm_bindgen(js_name = clearAnswers)]
    pub fn clear_answers(&mut self) -> Result<(), JsError> {
        self.session_mut().clear_answers().map_err(js_error)
    }

    /// Lifts student mode for this session ("Show them").
    #[wasm_bindgen(js_name = showAnswers)]
    pub fn show_answers(&mut self) {
        self.session_mut().show_answers();
    }
}
