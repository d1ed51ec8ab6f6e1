//! The study of what bounds δ with run A's sensors, for the page: one simulated slew per call, so
//! the table fills while the page stays live (the session decides what to run and says it).

use wasm_bindgen::prelude::*;

use super::session::WebSession;
use super::{js_error, to_js};

#[wasm_bindgen(js_class = Session)]
impl WebSession {
    /// Runs up to `runs` more slews of the sensor study (0: none) and returns where it stands:
    /// `{sensors, table, best_row, current_row, summary, prediction, done, progress}`.
    #[wasm_bindgen(js_name = sensorStudy)]
    pub fn sensor_study(&mut self, runs: u32) -> Result<JsValue, JsError> {
        let view = self.session_mut().sensor_study_step(runs as usize).map_err(js_error)?;
        to_js(&view)
    }

    /// True if the figure draws the study (the `study` switch with digital sensors): the page then
    /// runs it whether or not its section is open.
    #[wasm_bindgen(js_name = studyDrawn)]
    pub fn study_drawn(&self) -> bool {
        self.session().study_drawn()
    }
}
