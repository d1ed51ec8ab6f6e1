//! The renderer JavaScript holds: a [`Scene`] (all geometry, layout and autoscaling, tested
//! natively in `view`) on a [`GpuCanvas`]. It draws a session, describes the frame for the page's
//! labels when that description changes, and answers what lies under the pointer.

use serde::Serialize;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

use super::gpu::GpuCanvas;
use super::session::WebSession;
use super::to_js;
use crate::view::legend::LegendGroup;
use crate::view::{Label, OptionsUpdate, PanelInfo, PoleInfo, Scene, SeriesInfo, ViewOptions};

/// What `Renderer.layout()` returns.
#[derive(Serialize)]
struct LayoutReport {
    /// Changes whenever this report would (compare with `infoGeneration()`).
    generation: u64,
    panels: Vec<PanelInfo>,
    /// "single" or "pair".
    mode: &'static str,
    /// How each shown run is drawn (legend): one entry, or two in pair mode.
    series: Vec<SeriesInfo>,
    /// Every marker of the pole plot, for hover readouts.
    poles: Vec<PoleInfo>,
    spring_magnification: f64,
    backend: &'static str,
    /// Every text over the canvas, placed: `{panel, class, text, x, y, align: [ax, ay], size,
    /// time}` (the anchor in CSS px; `align` says which point of the text sits on it; `time` is
    /// set on time ticks, which move with the scrolling window).
    labels: Vec<Label>,
    /// Page CSS px per layout px: how much larger than normal the figure's text is drawn (the
    /// page scales its HTML tooltips and tabs alike).
    text_scale: f64,
    /// How much larger than Normal the page's own text in presentation mode is (the bar, its
    /// verdict, the key, Fig. 2.1's caption): the size chosen, over the screen's floor.
    page_text: f64,
    /// On a narrow canvas the views it shows one at a time, and which: `[{id, label, selected}]`
    /// (empty when everything is shown at once).
    tabs: Vec<TabInfo>,
    /// The panels asked for that are not in view (on the other tabs), as ids, and a sentence that
    /// says which and where (null when every panel is in view).
    hidden: Vec<&'static str>,
    hidden_note: Option<String>,
    /// The key to the panels shown: `[{title, items: [{glyph, color, text}], scale: {stops:
    /// [[pos, css]], ticks: [[pos, text]]} | null}]`.
    legend: Vec<LegendGroup>,
}

/// One tab of a narrow canvas.
#[derive(Serialize)]
struct TabInfo {
    id: &'static str,
    label: &'static str,
    selected: bool,
}

/// Draws a session on a canvas: the arm on one side, the error (and torque) traces on the other,
/// below them the pole plot and the stability maps without and with preliminary feedback.
/// Create it with `await Renderer.create(canvas)`, call `resize` when the canvas' CSS size or the
/// device-pixel ratio changes, and `render(session)` once per animation frame.
#[wasm_bindgen]
pub struct Renderer {
    gpu: GpuCanvas,
    scene: Scene,
}

#[wasm_bindgen]
impl Renderer {
    /// A renderer on `canvas`: WebGPU when `navigator.gpu` yields an adapter, WebGL2 otherwise.
    /// The choice is logged to the console. Rejects with a readable message if neither works.
    pub async fn create(canvas: HtmlCanvasElement) -> Result<Renderer, JsError> {
        let (css_width, css_height) = initial_css_size(&canvas);
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let scene = Scene::new(ViewOptions::default(), css_width, css_height, dpr);
        let (width, height) = scene.physical_size();
        let gpu = GpuCanvas::open(canvas, width, height).await?;
        Ok(Renderer { gpu, scene })
    }

    /// "WebGPU" or "WebGL2".
    pub fn backend(&self) -> String {
        self.gpu.backend().name().to_string()
    }

    /// Sets the canvas' drawing-buffer size to `css_width × css_height × device_pixel_ratio`
    /// physical pixels and re-lays out the panels. Invalid numbers count as 1; a size beyond the
    /// device's texture limit lowers the effective pixel ratio instead of failing.
    /// `screen_height` is the window's height in CSS px: presentation mode sizes the text for it.
    pub fn resize(&mut self, css_width: f64, css_height: f64, device_pixel_ratio: f64, screen_height: Option<f64>) {
        let sane = |v: f64| if v.is_finite() && v >= 1.0 { v } else { 1.0 };
        let (w, h) = (sane(css_width), sane(css_height));
        let dpr = if device_pixel_ratio.is_finite() && device_pixel_ratio > 0.0 { device_pixel_ratio } else { 1.0 };
        let max = f64::from(self.gpu.max_texture_side());
        let dpr = dpr.min(max / w).min(max / h);
        self.scene.resize(w, h, dpr);
        if let Some(screen) = screen_height.filter(|v| v.is_finite() && *v >= 1.0) {
            self.scene.set_screen_height(screen);
        }
        let (width, height) = self.scene.physical_size();
        self.gpu.resize(width, height);
    }

    /// Draws in the dark colour scheme (every colour's lightness inverted, hues kept) or not.
    #[wasm_bindgen(js_name = setDark)]
    pub fn set_dark(&mut self, dark: bool) {
        self.gpu.set_dark(dark);
    }

    /// Draws the session's newest state: run A, and run B beside it when comparing (two arms,
    /// both runs' errors in the same axes — A solid, B thinner in violet —, both runs' poles and
    /// map markers), and the session's maps as far as they are computed.
    pub fn render(&mut self, session: &WebSession) -> Result<(), JsError> {
        if let Some(performance) = web_sys::window().and_then(|w| w.performance()) {
            self.scene.set_clock(performance.now() / 1000.0);
        }
        self.scene.draw_session(session.session());
        let scene = &self.scene;
        self.gpu.draw(scene.background(), scene.static_vertices(), scene.static_generation(), scene.vertices())
    }

    /// True while the picture moves by itself (the swing's shape, animated): draw every frame even
    /// when the simulation is paused.
    pub fn animating(&self) -> bool {
        self.scene.animating()
    }

    /// Changes whenever `layout()` would describe the frame differently (layout, scales, ticks,
    /// analyses, maps). Between changes only the time window moves (see `windowStart()`, `windowEnd()`).
    #[wasm_bindgen(js_name = infoGeneration)]
    pub fn info_generation(&self) -> f64 {
        self.scene.info_generation() as f64
    }

    /// The start of the time plots' window in the latest frame, s (two numbers, not an array,
    /// so the call allocates nothing every frame).
    #[wasm_bindgen(js_name = windowStart)]
    pub fn window_start(&self) -> f64 {
        self.scene.time_window().start
    }

    /// The end of the time plots' window in the latest frame, s.
    #[wasm_bindgen(js_name = windowEnd)]
    pub fn window_end(&self) -> f64 {
        self.scene.time_window().end
    }

    /// The frame, for HTML labels over the canvas (CSS pixels, origin top-left of the canvas):
    /// `{generation, panels: [{id, x, y, width, height, x_label, y_label, title, note, x_range,
    /// y_range, x_ticks, y_ticks, x_labels: [{value, text}], y_labels, x_scale, y_scale}], mode,
    /// series: [...], poles: [{run, kind, re, im, zeta, omega, unstable, flexible, x, y, in_view, keyboard_stop}],
    /// spring_magnification, backend}`. For plots the rectangle is the data area: x_range spans
    /// its width and y_range its height (lo at the bottom), logarithmically where the scale is
    /// "log".
    pub fn layout(&self) -> Result<JsValue, JsError> {
        let report = LayoutReport {
            generation: self.scene.info_generation(),
            panels: self.scene.page_panel_info(),
            mode: if self.scene.is_pair() { "pair" } else { "single" },
            series: self.scene.series_info(),
            poles: self.scene.page_pole_info(),
            spring_magnification: self.scene.options().spring_magnification,
            backend: self.gpu.backend().name(),
            labels: self.scene.page_labels(),
            text_scale: self.scene.page_scale(),
            page_text: self.scene.page_text_factor(),
            legend: self.scene.legend(),
            hidden: self.scene.hidden_panels().into_iter().map(|k| k.id()).collect(),
            hidden_note: crate::words::panels::hidden_note(&self.scene.hidden_panels()),
            tabs: {
                let layout = self.scene.layout();
                let tabs = layout.tabs.iter();
                tabs.map(|t| TabInfo { id: t.id(), label: t.label(), selected: layout.tab == Some(*t) }).collect()
            },
        };
        to_js(&report)
    }

    /// The simulated time under (x, y) (CSS pixels) on an error or torque plot, or undefined:
    /// dragging there looks back at that instant.
    #[wasm_bindgen(js_name = timeAt)]
    pub fn time_at(&self, x: f64, y: f64) -> Option<f64> {
        self.scene.page_time_at(x, y)
    }

    /// Zooms the z-plane by `factor` (> 1 in, < 1 out) about (x, y) in CSS pixels of the canvas —
    /// the λ under the pointer stays under it — or about the panel's centre when x or y is not a
    /// number (the buttons, the keys), and writes the view into the session's settings (`zsize`,
    /// `zre`, `zim`: the URL carries it). False, and nothing changes, when (x, y) is not on the
    /// z-plane or it is not shown.
    #[wasm_bindgen(js_name = zoomZ)]
    pub fn zoom_z(&mut self, session: &mut WebSession, x: f64, y: f64, factor: f64) -> Result<bool, JsError> {
        let s = self.scene.page_scale();
        let view = if x.is_finite() && y.is_finite() {
            self.scene.zoom_z(x / s, y / s, factor)
        } else {
            self.scene.zoom_z_center(factor)
        };
        self.take_z_view(session, view)
    }

    /// The z-plane's view as drawn now, `[Re λ, Im λ, half-size]`, or undefined when it is not
    /// shown: a figure of it shows the same (`figureSvg`'s `zView`).
    #[wasm_bindgen(js_name = shownZView)]
    pub fn shown_z_view(&self) -> Option<Vec<f64>> {
        self.scene.z_panel()?;
        let v = self.scene.z_view();
        Some(vec![v.center[0], v.center[1], v.half])
    }

    /// True if (x, y) in CSS pixels of the canvas lies on the z-plane (where the wheel, a pinch
    /// and a drag move its view).
    #[wasm_bindgen(js_name = zAt)]
    pub fn z_at(&self, x: f64, y: f64) -> bool {
        let s = self.scene.page_scale();
        self.scene.z_panel().is_some_and(|r| x / s >= r.x && x / s <= r.right() && y / s >= r.y && y / s <= r.bottom())
    }

    /// Moves the z-plane by (dx, dy) CSS pixels (a drag: the plane follows the pointer; the arrow
    /// keys move it by a tenth of the panel), writing the view into the session's settings.
    #[wasm_bindgen(js_name = panZ)]
    pub fn pan_z(&mut self, session: &mut WebSession, dx: f64, dy: f64) -> Result<bool, JsError> {
        let s = self.scene.page_scale();
        let view = self.scene.pan_z(dx / s, dy / s);
        self.take_z_view(session, view)
    }

    /// True when (x, y) (CSS px) is within `reach` of run A's δ → 0 pair with its preliminary
    /// feedback on the pole plot: the handle a drag places.
    #[wasm_bindgen(js_name = pairHandleAt)]
    pub fn pair_handle_at(&self, x: f64, y: f64, reach: f64) -> bool {
        self.scene.page_pair_handle_at(x, y, reach)
    }

    /// Holds the pole plot's scale while the pair is dragged (true at the press, false at the
    /// release), so the plot does not rescale under the pointer.
    #[wasm_bindgen(js_name = holdPolePlot)]
    pub fn hold_pole_plot(&mut self, hold: bool) {
        self.scene.hold_pole_plot(hold);
    }

    /// The s = [Re, Im] under (x, y) (CSS px) on the pole plot, or undefined without one.
    #[wasm_bindgen(js_name = polePlotPoint)]
    pub fn pole_plot_point(&self, x: f64, y: f64) -> Option<Vec<f64>> {
        self.scene.page_pole_plot_point(x, y).map(|s| s.to_vec())
    }

    /// What lies at (x, y) in CSS pixels of the canvas: the nearest pole within `reach` pixels, or
    /// the point of a map: `{kind: "pole"|"map", title, lines: [{text, tone}], x, y, map, delta,
    /// alpha}`, or null.
    pub fn probe(&self, x: f64, y: f64, reach: f64) -> Result<JsValue, JsError> {
        to_js(&self.scene.page_probe(x, y, reach))
    }
}

impl Renderer {
    /// Writes a z-plane view into the session (rounded for a short link); false for none.
    fn take_z_view(
        &mut self,
        session: &mut WebSession,
        view: Option<crate::view::panels::z_plane::view::ZView>,
    ) -> Result<bool, JsError> {
        let Some(v) = view.map(|v| v.rounded()) else { return Ok(false) };
        session.session_mut().set_z_view(v.center, v.half).map_err(|e| JsError::new(&e.to_string()))?;
        self.scene.set_z_view(Some(v));
        Ok(true)
    }
}

/// Not exported to the page, which sets its options through the session's view settings: kept
/// for Rust callers (an export would keep its deserializer in the module).
impl Renderer {
    /// Changes drawing options: `{show_torque?: bool, time_window?: seconds,
    /// spring_magnification?: number, show_poles?: bool, show_map?: bool}`. Missing fields stay
    /// as they are; an invalid or unknown field changes nothing and throws.
    pub fn set_options(&mut self, options: JsValue) -> Result<(), JsError> {
        if options.is_undefined() || options.is_null() {
            return Ok(());
        }
        // serde-wasm-bindgen reads only the fields it knows, so misspelt keys are caught here.
        let Some(object) = options.dyn_ref::<js_sys::Object>() else {
            return Err(JsError::new("invalid renderer options: expected an object"));
        };
        for key in js_sys::Object::keys(object).iter() {
            let name = key.as_string().unwrap_or_default();
            OptionsUpdate::check_field(&name).map_err(|e| JsError::new(&format!("invalid renderer options: {e}")))?;
        }
        let update: OptionsUpdate = serde_wasm_bindgen::from_value(options)
            .map_err(|e| JsError::new(&format!("invalid renderer options: {e}")))?;
        self.scene.set_options(&update).map_err(|e| JsError::new(&format!("invalid renderer options: {e}")))
    }
}

/// The canvas' CSS size, or its attribute size when it is not laid out yet.
fn initial_css_size(canvas: &HtmlCanvasElement) -> (f64, f64) {
    let (w, h) = (canvas.client_width(), canvas.client_height());
    if w > 0 && h > 0 {
        (f64::from(w), f64::from(h))
    } else {
        (f64::from(canvas.width().max(1)), f64::from(canvas.height().max(1)))
    }
}
