//! The data behind every figure for the page's "Download the data": the session's long table as
//! CSV ([`crate::session::data`]); the page reshapes it into the JSON `flexarm data --json`
//! prints (`www/js/export.js`), so the module carries no serialisation code for it. Converts and
//! forwards.

use wasm_bindgen::prelude::*;

use super::js_error;
use super::session::WebSession;

#[wasm_bindgen(js_class = Session)]
impl WebSession {
    /// The model, A, B, C, D, the one-period map Φ, its eigenvalues, ρ, A4, the ρ(δ) curve and
    /// the maps as far as computed — one number a row, `quantity,i,j,row,column,value,unit`,
    /// headed by `# ` lines with the state string and the units: `flexarm data --csv`.
    #[wasm_bindgen(js_name = dataCsv)]
    pub fn data_csv(&self) -> Result<String, JsError> {
        self.session().figure_data_csv().map_err(js_error)
    }
}
