//! A figure per panel for the page's "Figure" row: the SVG Rust writes
//! ([`crate::view::figure`]) and the list of panels shown. The page rasterizes the SVG for a PNG.
//! Converts and forwards.

use wasm_bindgen::prelude::*;

use super::session::WebSession;
use super::{js_error, to_js};
use crate::view::figure::{caption_head, figure_choices, figure_svg_with, FigureOptions};

#[wasm_bindgen(js_class = Session)]
impl WebSession {
    /// The panel `panel` ("arm", "errors", "e1", "poles", "zplane", "rho", "map-off", "maps", …) as
    /// a standalone SVG figure captioned with `state` (the whole state string, the classroom's),
    /// made as `options` ask (`dark=1&background=white&text=large&caption=settings&shape=wide&
    /// zview=RE,IM,HALF`, every key optional: [`FigureOptions::parse`]). Throws for an unknown
    /// panel or option, maps still being computed, or (student mode) a figure that gives the
    /// answer away.
    #[wasm_bindgen(js_name = figureSvg)]
    pub fn figure_svg(&self, panel: &str, state: &str, options: &str) -> Result<String, JsError> {
        let options = FigureOptions::parse(options).map_err(js_error)?;
        figure_svg_with(self.session(), state, panel, &options).map(|f| f.svg).map_err(js_error)
    }

    /// The caption under the page's picture: what it shows at which time, and the state string
    /// `state` (the classroom's): "flexarm at t = 4.138 s — Fig. 5.3: … — state: delta=0.01&…".
    #[wasm_bindgen(js_name = pictureCaption)]
    pub fn picture_caption(&self, state: &str) -> String {
        format!("{} — state: {state}", caption_head(self.session()))
    }

    /// The figures of the panels shown now: `[{id, label}]`.
    #[wasm_bindgen(js_name = figurePanels)]
    pub fn figure_panels(&self) -> Result<JsValue, JsError> {
        to_js(&figure_choices(self.session()))
    }
}
