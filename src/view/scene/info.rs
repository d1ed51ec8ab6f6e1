//! The frame as the page reads it: each panel's description (rectangle, axes, ticks and their
//! labels, title, note, marks: written by the panel), every text placed over the canvas, the key,
//! the pole plot's markers, how each run is drawn, and the time under the pointer.

use serde::Serialize;

use super::Scene;
use crate::plot::Color;
use crate::schema::PanelKind;
use crate::view::labels::{place_labels, Label};
use crate::view::legend::LegendGroup;
use crate::view::loop_poles::{describe_poles, unplaced, PoleInfo, PoleStyle};
use crate::view::panel_info::PanelInfo;
use crate::view::panels::contract::RUN_NAMES;
use crate::view::panels::time_plots::series::{plot_series, CURVE_WIDTH, CURVE_WIDTH_B};

/// How one run is drawn, for the page's legend (colours as CSS strings).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SeriesInfo {
    /// "A" or "B".
    pub run: &'static str,
    /// The run's main colour (legend swatch): e1's colour for A, the single hue of B.
    pub color: String,
    /// Curve colours in the e1, e2 and torque panels.
    pub e1: String,
    pub e2: String,
    pub torque1: String,
    pub torque2: String,
    /// Curve width, CSS pixels.
    pub line_width: f64,
    /// "solid" (A) or "thin" (B: a thinner line in its own hue, drawn over A's).
    pub style: &'static str,
    /// Loop-pole marker in the pole plot: "cross" (×, A) or "plus" (+, B); unstable poles red.
    pub pole_marker: &'static str,
    /// Colour of stable loop poles and of the map marker.
    pub pole_color: String,
    /// Colour of unstable loop poles.
    pub unstable_color: String,
    /// Colours of the A4 markers: rings without preliminary feedback, diamonds with it.
    pub a4_open_color: String,
    pub a4_color: String,
}

impl Scene {
    /// The panels with their axis ranges, ticks and labels as of the latest frame.
    pub fn panel_info(&self) -> Vec<PanelInfo> {
        let frame = &self.frame;
        frame.layout.panels.iter().map(|panel| self.panels.describe(frame, panel)).collect()
    }

    /// The key to the panels shown: each panel type's groups, then the keys carrying this
    /// frame's numbers.
    pub fn legend(&self) -> Vec<LegendGroup> {
        let kinds: Vec<PanelKind> = self.frame.layout.panels.iter().map(|p| p.kind).collect();
        self.panels.legend(&self.frame, &kinds)
    }

    /// A figure's title for the panels `kinds` (of one panel type), as the view shows them now.
    pub fn figure_title(&self, kinds: &[PanelKind]) -> String {
        self.panels.figure_title(&self.frame, kinds)
    }

    /// The data area of a `kind` panel in a figure (w, h), px.
    pub fn figure_size(&self, kind: PanelKind) -> (f64, f64) {
        self.panels.figure_size(kind)
    }

    /// Every text over the canvas, placed (see [`crate::view::labels`]).
    pub fn labels(&self) -> Vec<Label> {
        let kinds = self.frame.layout.panels.iter().map(|p| p.kind);
        place_labels(&kinds.zip(self.panel_info()).collect::<Vec<_>>())
    }

    /// Every marker of the pole plot (both runs in pair mode) with its position in CSS pixels
    /// in the plot shown (s- or z-plane), for hover readouts. Positions are null when the pole
    /// plot is hidden.
    pub fn pole_info(&self) -> Vec<PoleInfo> {
        let frame = &self.frame;
        let shown = frame.layout.panels.iter().find_map(|p| self.panels.pole_markers(frame, p));
        shown.unwrap_or_else(|| {
            let mut out = Vec::new();
            for (memory, name) in frame.runs.iter().zip(RUN_NAMES).take(frame.run_count()) {
                if let Some(report) = &memory.report {
                    describe_poles(report, name, &unplaced, &mut out);
                }
            }
            out
        })
    }

    /// How each shown run is drawn (one entry, or two in pair mode), for the page's legend.
    pub fn series_info(&self) -> Vec<SeriesInfo> {
        use crate::control::Traces;
        (0..self.frame.run_count())
            .map(|run| {
                let style = PoleStyle::of_run(run);
                let empty = Traces::default();
                let [t1, t2] = plot_series(PanelKind::Torque, &empty, run).map(|s| s.map(|(_, c)| c));
                let e1 = plot_series(PanelKind::Error1, &empty, run)[0].map(|(_, c)| c);
                let e2 = plot_series(PanelKind::Error2, &empty, run)[0].map(|(_, c)| c);
                let css = |c: Option<Color>| c.map(Color::css).unwrap_or_default();
                SeriesInfo {
                    run: RUN_NAMES[run],
                    color: css(e1),
                    e1: css(e1),
                    e2: css(e2),
                    torque1: css(t1),
                    torque2: css(t2),
                    line_width: if run == 0 { CURVE_WIDTH } else { CURVE_WIDTH_B },
                    style: if run == 0 { "solid" } else { "thin" },
                    pole_marker: if style.plus { "plus" } else { "cross" },
                    pole_color: style.stable.css(),
                    unstable_color: style.unstable.css(),
                    a4_open_color: style.a4_open.css(),
                    a4_color: style.a4.css(),
                }
            })
            .collect()
    }

    /// The simulated time under (x, y) (CSS pixels) on a time plot, within its window; None
    /// elsewhere. Dragging there looks back at that instant.
    pub fn time_at(&self, x: f64, y: f64) -> Option<f64> {
        // Zoomed on t_n the window follows the instant shown: dragging would chase itself (the
        // timeline and Step ◂ ▸ move t_n instead).
        if self.frame.zoomed() {
            return None;
        }
        let panel = self.frame.layout.panels.iter().find(|p| p.kind.is_time_plot() && p.contains(x, y))?;
        let w = self.frame.window();
        let f = ((x - panel.rect.x) / panel.rect.w).clamp(0.0, 1.0);
        Some(w.start + f * w.width())
    }
}
