//! One frame of the page's picture, built from the closed loop: the layout, the autoscales that
//! persist between frames, and the painter that collects the triangles.
//!
//! [`Scene`] is everything the renderer needs except the GPU: the wgpu layer only uploads
//! [`Scene::vertices`] and forwards [`Scene::panel_info`] to the page for its HTML labels.

use serde::{Deserialize, Serialize};

use super::arm::{draw_arm_panel, ArmFrame, ArmPose, DEFAULT_SPRING_MAGNIFICATION, VERTEX_BUDGET as ARM_VERTEX_BUDGET};
use super::axes::{Autoscale, AutoscaleSettings, Ticks};
use super::layout::{Layout, LayoutOptions, Panel, PanelKind, Rect};
use super::painter::{Color, Painter, Vertex};
use super::palette;
use super::traces::{
    draw_background, draw_frame, draw_series, max_abs, vertex_budget, PlotFrame, TimeWindow, DEFAULT_TIME_WINDOW,
};
use crate::closed_loop::{ClosedLoop, Snapshot, Traces};
use crate::reference::Reference;

/// Longest time window accepted, s.
pub const MAX_TIME_WINDOW: f64 = 3600.0;
/// Largest spring magnification accepted.
pub const MAX_SPRING_MAGNIFICATION: f64 = 1000.0;

/// What the page can change about the picture.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ViewOptions {
    /// Show the torque panel (T1, T2) below the error panels.
    pub show_torque: bool,
    /// Width W of the scrolling time window, s.
    pub time_window: f64,
    /// Magnification M of the spring twist θ − q1 in the arm picture.
    pub spring_magnification: f64,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            show_torque: false,
            time_window: DEFAULT_TIME_WINDOW,
            spring_magnification: DEFAULT_SPRING_MAGNIFICATION,
        }
    }
}

/// A partial update of [`ViewOptions`] as the page sends it; missing fields stay unchanged.
/// Unknown fields are rejected so that a misspelt option does not silently do nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OptionsUpdate {
    pub show_torque: Option<bool>,
    pub time_window: Option<f64>,
    pub spring_magnification: Option<f64>,
}

impl OptionsUpdate {
    /// The accepted field names (for checking objects whose deserializer ignores unknown keys).
    pub const FIELDS: [&'static str; 3] = ["show_torque", "time_window", "spring_magnification"];

    /// An error message if `name` is not one of [`OptionsUpdate::FIELDS`].
    pub fn check_field(name: &str) -> Result<(), String> {
        if Self::FIELDS.contains(&name) {
            Ok(())
        } else {
            Err(format!("unknown option '{name}' (known: {})", Self::FIELDS.join(", ")))
        }
    }
}

impl ViewOptions {
    /// Applies `update` if every given field is valid; otherwise changes nothing and explains.
    pub fn apply(&mut self, update: &OptionsUpdate) -> Result<(), String> {
        let mut next = *self;
        if let Some(v) = update.show_torque {
            next.show_torque = v;
        }
        if let Some(w) = update.time_window {
            if !(w.is_finite() && w > 0.0 && w <= MAX_TIME_WINDOW) {
                return Err(format!("time_window = {w}: must be a number of seconds in (0, {MAX_TIME_WINDOW}]"));
            }
            next.time_window = w;
        }
        if let Some(m) = update.spring_magnification {
            if !(m.is_finite() && m > 0.0 && m <= MAX_SPRING_MAGNIFICATION) {
                return Err(format!("spring_magnification = {m}: must be a number in (0, {MAX_SPRING_MAGNIFICATION}]"));
            }
            next.spring_magnification = m;
        }
        *self = next;
        Ok(())
    }

    fn layout_options(&self) -> LayoutOptions {
        LayoutOptions { show_torque: self.show_torque }
    }
}

/// A panel as the page sees it, for placing HTML labels over the canvas (CSS pixels, origin at
/// the canvas' top-left). For plots the rectangle is the data area: `x_range` maps onto
/// [x, x + width] and `y_range` onto [y + height, y]. For the arm the ranges are the shown region
/// in picture units (link 1 is 1 long) and there are no labels or ticks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PanelInfo {
    pub id: &'static str,
    pub x: f64,
    pub y: f64,
    pub width: f64,
    pub height: f64,
    pub x_label: &'static str,
    pub y_label: &'static str,
    pub x_range: [f64; 2],
    pub y_range: [f64; 2],
    pub x_ticks: Vec<f64>,
    pub y_ticks: Vec<f64>,
}

/// Plot curve widths, CSS pixels.
const CURVE_WIDTH: f64 = 1.75;
/// About one time tick per this many CSS pixels of plot width.
const X_TICK_SPACING: f64 = 80.0;
/// About one value tick per this many CSS pixels of plot height (±Y gets an even split).
const Y_TICK_SPACING: f64 = 32.0;

/// The picture: layout, persistent autoscales and the triangle list of the latest frame.
#[derive(Clone, Debug)]
pub struct Scene {
    options: ViewOptions,
    layout: Layout,
    painter: Painter,
    scale_e1: Autoscale,
    scale_e2: Autoscale,
    scale_torque: Autoscale,
    /// Simulated time of the latest frame, s.
    time: f64,
}

impl Scene {
    /// A scene for a canvas of the given CSS size and device-pixel ratio.
    pub fn new(options: ViewOptions, css_width: f64, css_height: f64, device_pixel_ratio: f64) -> Self {
        let mut scene = Self {
            layout: Layout::compute(css_width, css_height, device_pixel_ratio, &options.layout_options()),
            options,
            painter: Painter::new(),
            scale_e1: Autoscale::new(AutoscaleSettings::ERROR),
            scale_e2: Autoscale::new(AutoscaleSettings::ERROR),
            scale_torque: Autoscale::new(AutoscaleSettings::TORQUE),
            time: 0.0,
        };
        scene.relayout(css_width, css_height, device_pixel_ratio);
        scene
    }

    pub fn options(&self) -> &ViewOptions {
        &self.options
    }

    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// Validates and applies a partial options update (re-laying out if panels change).
    pub fn set_options(&mut self, update: &OptionsUpdate) -> Result<(), String> {
        self.options.apply(update)?;
        self.relayout(self.layout.css_width, self.layout.css_height, self.layout.device_pixel_ratio);
        Ok(())
    }

    /// Lays the panels out for a new canvas size.
    pub fn resize(&mut self, css_width: f64, css_height: f64, device_pixel_ratio: f64) {
        self.relayout(css_width, css_height, device_pixel_ratio);
    }

    /// Lays out again and reserves room for the largest frame this layout can produce, so that
    /// drawing never reallocates.
    fn relayout(&mut self, css_width: f64, css_height: f64, device_pixel_ratio: f64) {
        self.layout = Layout::compute(css_width, css_height, device_pixel_ratio, &self.options.layout_options());
        let budget: usize = self.layout.panels.iter().map(|panel| self.vertex_budget(panel)).sum();
        self.painter.reserve_total(budget);
    }

    /// An upper bound on the vertices one panel writes.
    fn vertex_budget(&self, panel: &Panel) -> usize {
        match panel.kind {
            PanelKind::Arm => ARM_VERTEX_BUDGET,
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => {
                let series = plot_series(panel.kind, &Traces::default()).iter().flatten().count();
                let (x_ticks, y_ticks) = plot_tick_counts(panel.rect);
                vertex_budget(self.layout.to_physical(panel.rect).w, series, x_ticks + y_ticks + 2)
            }
        }
    }

    /// Canvas size in physical pixels.
    pub fn physical_size(&self) -> (u32, u32) {
        self.layout.physical_size()
    }

    /// The latest frame's triangle list.
    pub fn vertices(&self) -> &[Vertex] {
        self.painter.vertices()
    }

    /// The painter (for its byte view and capacity).
    pub fn painter(&self) -> &Painter {
        &self.painter
    }

    /// The background colour the renderer clears to.
    pub fn background(&self) -> Color {
        palette::BACKGROUND
    }

    /// Builds the frame for the closed loop's newest state.
    pub fn draw(&mut self, closed_loop: &ClosedLoop) -> &[Vertex] {
        let reference = Reference::new(closed_loop.config().reference);
        self.draw_state(&closed_loop.snapshot(), closed_loop.traces(), Some(&reference))
    }

    /// Builds the frame from a snapshot and traces; `reference` (if given) shades the slews.
    /// Allocates nothing once the painter has grown to the scene's size.
    pub fn draw_state(&mut self, snapshot: &Snapshot, traces: &Traces, reference: Option<&Reference>) -> &[Vertex] {
        if snapshot.time < self.time || !snapshot.time.is_finite() {
            // The simulation restarted: the old data are gone, so are their scales.
            self.scale_e1.reset();
            self.scale_e2.reset();
            self.scale_torque.reset();
        }
        self.time = if snapshot.time.is_finite() { snapshot.time } else { 0.0 };
        self.painter.clear();
        let window = self.window();
        for i in 0..self.layout.panels.len() {
            let panel = self.layout.panels[i];
            match panel.kind {
                PanelKind::Arm => self.draw_arm(panel, snapshot),
                PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => {
                    self.draw_plot(panel, window, traces, reference)
                }
            }
        }
        self.painter.vertices()
    }

    fn window(&self) -> TimeWindow {
        TimeWindow::ending_at(self.time, self.options.time_window)
    }

    fn draw_arm(&mut self, panel: Panel, snapshot: &Snapshot) {
        let [q1, q2, theta] = snapshot.q;
        let actual = ArmPose { q1, q2, theta };
        let [qd1, qd2] = snapshot.qd;
        let reference = ArmPose { q1: qd1, q2: qd2, theta: qd1 };
        let rect = self.layout.to_physical(panel.rect);
        let dpr = self.layout.device_pixel_ratio;
        draw_arm_panel(&mut self.painter, rect, dpr, &actual, &reference, self.options.spring_magnification);
    }

    fn draw_plot(&mut self, panel: Panel, window: TimeWindow, traces: &Traces, reference: Option<&Reference>) {
        let n = traces.t.len();
        let range = window.indices(&traces.t);
        let series = plot_series(panel.kind, traces);
        let data_max = series
            .iter()
            .flatten()
            .map(|(values, _)| values.get(range.clone()).map_or(0.0, max_abs))
            .fold(0.0, f64::max);
        let time = self.time;
        let Some(scale) = self.scale_mut(panel.kind) else { return };
        let y = scale.update(data_max, time);
        let dpr = self.layout.device_pixel_ratio;
        let frame = PlotFrame { rect: self.layout.to_physical(panel.rect), window, y_lo: -y, y_hi: y };
        let (x_ticks, y_ticks) = plot_ticks(panel.rect, window, y);
        draw_background(&mut self.painter, &frame, x_ticks, y_ticks, reference, dpr);
        for (values, color) in series.iter().flatten() {
            let m = n.min(values.len());
            draw_series(&mut self.painter, &frame, &traces.t[..m], &values[..m], CURVE_WIDTH * dpr, *color);
        }
        draw_frame(&mut self.painter, &frame, dpr);
    }

    fn scale_mut(&mut self, kind: PanelKind) -> Option<&mut Autoscale> {
        match kind {
            PanelKind::Error1 => Some(&mut self.scale_e1),
            PanelKind::Error2 => Some(&mut self.scale_e2),
            PanelKind::Torque => Some(&mut self.scale_torque),
            PanelKind::Arm => None,
        }
    }

    fn scale(&self, kind: PanelKind) -> Option<&Autoscale> {
        match kind {
            PanelKind::Error1 => Some(&self.scale_e1),
            PanelKind::Error2 => Some(&self.scale_e2),
            PanelKind::Torque => Some(&self.scale_torque),
            PanelKind::Arm => None,
        }
    }

    /// The panels with their axis ranges, ticks and labels as of the latest frame.
    pub fn panel_info(&self) -> Vec<PanelInfo> {
        let window = self.window();
        self.layout.panels.iter().map(|panel| self.describe(panel, window)).collect()
    }

    fn describe(&self, panel: &Panel, window: TimeWindow) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo {
            id: panel.kind.id(),
            x: r.x,
            y: r.y,
            width: r.w,
            height: r.h,
            x_label: "",
            y_label: "",
            x_range: [0.0, 0.0],
            y_range: [0.0, 0.0],
            x_ticks: Vec::new(),
            y_ticks: Vec::new(),
        };
        match self.scale(panel.kind) {
            None => {
                let rect_px = self.layout.to_physical(r);
                let (x_range, y_range) = ArmFrame::fit(rect_px, self.layout.device_pixel_ratio).world_range(rect_px);
                info.x_range = x_range;
                info.y_range = y_range;
            }
            Some(scale) => {
                let y = scale.limit();
                let (x_ticks, y_ticks) = plot_ticks(r, window, y);
                info.x_label = "t [s]";
                info.y_label = y_label(panel.kind);
                info.x_range = [window.start, window.end];
                info.y_range = [-y, y];
                info.x_ticks = x_ticks.collect();
                info.y_ticks = y_ticks.collect();
            }
        }
        info
    }
}

/// The y-axis label of a plot, with its unit.
fn y_label(kind: PanelKind) -> &'static str {
    match kind {
        PanelKind::Error1 => "e1 [rad]",
        PanelKind::Error2 => "e2 [rad]",
        PanelKind::Torque => "T1, T2 [N m]",
        PanelKind::Arm => "",
    }
}

/// The curves of a plot and their colours (at most two per plot).
fn plot_series(kind: PanelKind, traces: &Traces) -> [Option<(&[f64], Color)>; 2] {
    match kind {
        PanelKind::Error1 => [Some((traces.e1.as_slice(), palette::ERROR1)), None],
        PanelKind::Error2 => [Some((traces.e2.as_slice(), palette::ERROR2)), None],
        PanelKind::Torque => {
            [Some((traces.torque1.as_slice(), palette::TORQUE1)), Some((traces.torque2.as_slice(), palette::TORQUE2))]
        }
        PanelKind::Arm => [None, None],
    }
}

/// How many time and value intervals a plot whose data area is `rect_css` (CSS pixels) gets at
/// most; an even value count keeps 0 and ±Y/2 as ticks of the symmetric range.
fn plot_tick_counts(rect_css: Rect) -> (usize, usize) {
    let x_count = (rect_css.w / X_TICK_SPACING).floor().clamp(2.0, 12.0) as usize;
    let y_count = ((rect_css.h / Y_TICK_SPACING / 2.0).floor() * 2.0).clamp(2.0, 8.0) as usize;
    (x_count, y_count)
}

/// Time and value ticks for a plot whose data area is `rect_css` (CSS pixels).
fn plot_ticks(rect_css: Rect, window: TimeWindow, y: f64) -> (Ticks, Ticks) {
    let (x_count, y_count) = plot_tick_counts(rect_css);
    (Ticks::new(window.start, window.end, x_count), Ticks::new(-y, y, y_count))
}
