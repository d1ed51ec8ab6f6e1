//! What the page reads about a panel to put text over the canvas: its rectangle, axis ranges and
//! scales, ticks and their labels, title, note and marks at points. Plain data, written by each
//! panel's `describe` and read by [`super::labels`], the page and the figures; a leaf: it knows no
//! panel and no layout.

use serde::Serialize;

use crate::session::MapSide;

/// A tick that gets a label, and the label.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TickLabel {
    pub value: f64,
    pub text: String,
}

/// A panel as the page sees it, for placing HTML labels over the canvas (CSS pixels, origin at
/// the canvas' top-left). For plots the rectangle is the data area: `x_range` maps onto
/// [x, x + width] and `y_range` onto [y + height, y] — linearly, or logarithmically where
/// `x_scale`/`y_scale` is "log" (then a fraction f of the width is x = lo·(hi/lo)^f). For the arms
/// the ranges are the shown region in picture units (link 1 is 1 long) and there are no ticks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PanelInfo {
    pub id: &'static str,
    pub x: f64,
    pub y: f64,
    pub width: f64,
    pub height: f64,
    pub x_label: String,
    pub y_label: &'static str,
    /// A caption for panels without axis titles ("arm, top view").
    pub title: String,
    /// A note inside the panel ("ρ, no Kₚᵣ").
    pub note: String,
    pub x_range: [f64; 2],
    pub y_range: [f64; 2],
    /// Where the grid lines are.
    pub x_ticks: Vec<f64>,
    pub y_ticks: Vec<f64>,
    /// Which ticks get a label, and the label text.
    pub x_labels: Vec<TickLabel>,
    pub y_labels: Vec<TickLabel>,
    /// "linear" or "log".
    pub x_scale: &'static str,
    pub y_scale: &'static str,
    /// The x axis is the scrolling time window: between descriptions its range moves with
    /// `Renderer.windowStart()` and `windowEnd()`.
    pub scrolls: bool,
    /// Text placed at points of the panel (CSS pixels of the canvas), e.g. the flexible pair.
    pub marks: Vec<Mark>,
    /// A second x axis along the top (ρ(δ): ωδ, how far the swing turns per period): its
    /// title and its labelled ticks, at values of the x axis.
    pub x2_label: String,
    pub x2_labels: Vec<TickLabel>,
    /// The panel as a keyboard region over the canvas (null: none): what a screen reader hears
    /// there and what the keys do.
    pub region: Option<Region>,
}

/// A panel the keyboard can work: focused, it is announced with `label`, and the arrow keys act
/// as `keys` says.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Region {
    pub label: &'static str,
    /// "map": the arrows move the running (δ, α) on the map of `map`, Enter runs there; "delta":
    /// left and right step δ; "poles": the arrows step from pole to pole and read each one;
    /// "zplane": the same, and + − 0 P and Shift with the arrows zoom and pan.
    pub keys: &'static str,
    pub map: Option<MapSide>,
}

impl PanelInfo {
    /// A panel at (x, y), `width × height` CSS px, with linear axes and nothing on them yet.
    #[inline(never)]
    pub fn new(id: &'static str, x: f64, y: f64, width: f64, height: f64) -> PanelInfo {
        PanelInfo {
            id,
            x,
            y,
            width,
            height,
            x_label: String::new(),
            y_label: "",
            title: String::new(),
            note: String::new(),
            x_range: [0.0, 0.0],
            y_range: [0.0, 0.0],
            x_ticks: Vec::new(),
            y_ticks: Vec::new(),
            x_labels: Vec::new(),
            y_labels: Vec::new(),
            x_scale: "linear",
            y_scale: "linear",
            scrolls: false,
            marks: Vec::new(),
            x2_label: String::new(),
            x2_labels: Vec::new(),
            region: None,
        }
    }
}

/// A short text at a point of a panel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Mark {
    pub x: f64,
    pub y: f64,
    pub text: String,
}

/// One line of a tooltip, with its tone ("good", "bad" or "").
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TipLine {
    pub text: String,
    pub tone: &'static str,
}

impl TipLine {
    pub fn plain(text: impl Into<String>) -> Self {
        Self { text: text.into(), tone: "" }
    }

    pub fn toned(text: impl Into<String>, good: bool) -> Self {
        Self { text: text.into(), tone: if good { "good" } else { "bad" } }
    }
}

/// What lies under the pointer: a pole or a point of a map, described for a tooltip.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Probe {
    /// "pole" or "map".
    pub kind: &'static str,
    pub title: String,
    pub lines: Vec<TipLine>,
    /// Where the tooltip points, CSS pixels in the canvas.
    pub x: f64,
    pub y: f64,
    /// For a map: which one ("off" or "on") and the (δ, α) under the pointer.
    pub map: Option<MapSide>,
    pub delta: Option<f64>,
    pub alpha: Option<f64>,
}
