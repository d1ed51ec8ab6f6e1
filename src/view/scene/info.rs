//! The frame as the page reads it: each panel's rectangle, axis ranges, ticks and their labels
//! (formatted here, so the page only places text), the pole plot's markers, how each run is drawn
//! (the legend) and the time under the pointer; what lies under it for a tooltip is `probe.rs`.

use serde::Serialize;

use super::{
    plot_series, plot_ticks, pole_ticks, run_pole_style, y_label, Scene, CURVE_WIDTH, CURVE_WIDTH_B, RUN_NAMES,
};
use crate::plot::color::Measure;
use crate::plot::format;
use crate::plot::ticks::Decades;
use crate::plot::Color;
use crate::session::maps::MapSide;
use crate::view::arm::ArmFrame;
use crate::view::autoscale::Autoscale;
use crate::view::labels::{place_labels, Label};
use crate::view::panel_info::{Mark, PanelInfo, TickLabel};
use crate::view::text_metrics::{bold_width, font, text_width, LINE_HEIGHT};
use crate::view::tick_labels::{linear_labels, log_labels, offset_labels};
use crate::view::layout::margins;
use crate::view::layout::{Panel, PanelKind};
use crate::view::map::{map_ticks, side_of};
use crate::view::poles::{describe_poles, flexible_aliased, nyquist, PoleInfo, PoleView, RE_RANGE};
use crate::view::rho_curve::rho_ticks;
use crate::view::traces::TimeWindow;
use crate::view::zplane::{gap_text, label_fits, z_ticks, WHOLE_HALF};

/// Least distance between log-axis labels, CSS px (x: a label's width, y: its height).
const LOG_LABEL_SPACING: [f64; 2] = [38.0, 17.0];

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
        let window = self.window();
        self.layout.panels.iter().map(|panel| self.describe(panel, window)).collect()
    }

    /// The key to the panels shown (see [`crate::view::legend`]).
    pub fn legend(&self) -> Vec<crate::view::legend::LegendGroup> {
        let kinds: Vec<PanelKind> = self.layout.panels.iter().map(|p| p.kind).collect();
        let zoom = self.cycle_window().is_some();
        let mut groups = crate::view::legend::legend(
            &kinds,
            self.pair,
            self.options.measure,
            self.options.log_errors || self.auto_log,
            zoom,
        );
        if self.auto_log {
            // The key says why the axes are logarithmic where the plot's header has no room.
            if let Some(g) = groups.iter_mut().find(|g| g.title == "log |e|") {
                g.title = super::compare::AUTO_LOG_KEY;
            }
        }
        groups.extend(self.swing_legend());
        groups
    }

    /// Every text over the canvas, placed (see [`crate::view::labels`]).
    pub fn labels(&self) -> Vec<Label> {
        let kinds = self.layout.panels.iter().map(|p| p.kind);
        place_labels(&kinds.zip(self.panel_info()).collect::<Vec<_>>())
    }

    fn describe(&self, panel: &Panel, window: TimeWindow) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo {
            id: panel.kind.id(),
            x: r.x,
            y: r.y,
            width: r.w,
            height: r.h,
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
            scrolls: panel.kind.is_time_plot(),
            marks: Vec::new(),
            x2_label: String::new(),
            x2_labels: Vec::new(),
        };
        match panel.kind {
            PanelKind::Arm | PanelKind::ArmB => {
                let rect_px = self.layout.to_physical(r);
                let (x_range, y_range) = ArmFrame::fit(rect_px, self.layout.device_pixel_ratio).world_range(rect_px);
                info.x_range = x_range;
                info.y_range = y_range;
                let zoom = self.cycle_window().is_some();
                info.title = match (panel.kind, self.pair) {
                    (PanelKind::Arm, _) if zoom => "arm at tₙ".into(),
                    (PanelKind::Arm, false) => "arm, top view".into(),
                    (PanelKind::Arm, true) => "A: arm, top view".into(),
                    _ => "B: arm, top view".into(),
                };
                if panel.kind == PanelKind::Arm {
                    if zoom {
                        info.title += "; violet: as predicted for tₙ + kε";
                    }
                    if self.options.show_swing && self.swing_shape().is_some() {
                        info.title += &format!("; amber: the swing's shape, {}× slower", super::SWING_SLOWDOWN);
                    }
                }
            }
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque if self.cycle_window().is_some() => {
                self.describe_cycle_plot(panel, window, &mut info);
            }
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => {
                let y = self.scale(panel.kind).map_or(0.0, Autoscale::limit);
                let (x_ticks, y_ticks) = plot_ticks(r, window, y);
                info.x_label = "t [s]".into();
                info.y_label = y_label(panel.kind);
                info.x_range = [window.start, window.end];
                info.y_range = self.plot_range(panel.kind, y);
                info.x_ticks = x_ticks.collect();
                if self.log_plot(panel.kind) {
                    info.y_label = if panel.kind == PanelKind::Error1 { "|e1| [rad], log" } else { "|e2| [rad], log" };
                    info.y_scale = "log";
                    info.y_ticks = Decades::new(info.y_range[0], info.y_range[1]).collect();
                    info.y_labels = log_labels(&info.y_ticks, info.y_range, r.h, LOG_LABEL_SPACING[1]);
                    if panel.kind == PanelKind::Error1 && !self.options.hide_prediction {
                        info.note = "dashed: slope ln ρ/δ; as the analysis predicts".into();
                    }
                    if self.auto_log {
                        // Said where it is seen: the shared axes are logarithmic by the page's choice.
                        info.note = if info.note.is_empty() {
                            super::compare::AUTO_LOG_NOTE.into()
                        } else {
                            format!("{}; {}", super::compare::AUTO_LOG_NOTE, info.note)
                        };
                    }
                } else {
                    info.y_ticks = y_ticks.collect();
                }
            }
            PanelKind::Poles => {
                let im = self.pole_frame(r).im;
                let (x_ticks, y_ticks) = pole_ticks(r, im);
                info.x_label = "Re s [1/s]".into();
                info.y_label = "Im s [rad/s]";
                info.x_range = RE_RANGE;
                info.y_range = im;
                info.x_ticks = x_ticks.collect();
                info.y_ticks = y_ticks.collect();
                info.note = "poles s = ln λ/δ".into();
                if let Some(report) = &self.runs[0].report {
                    let w = nyquist(report.sampling_period);
                    if w < im[1] {
                        // The warning first: a narrow panel keeps it and drops the line's name
                        // (the key names it).
                        if flexible_aliased(report) {
                            info.note += "; aliased: the flexible mode is faster than π/δ";
                        }
                        info.note += &format!("; dashed: π/δ = {} rad/s", format::sig(w, 3));
                    }
                }
                info.marks = self.flexible_mark();
            }
            PanelKind::ZPlane => {
                let frame = self.z_frame(r);
                let (x_range, y_range) = frame.ranges();
                let (x_ticks, y_ticks) = z_ticks(r, frame.view);
                info.x_label = "Re λ".into();
                info.y_label = "Im λ";
                info.x_range = x_range;
                info.y_range = y_range;
                info.x_ticks = x_ticks.collect();
                info.y_ticks = y_ticks.collect();
                info.note = "eigenvalues λ; outside |λ| = 1: grows".into();
                let zoom = WHOLE_HALF / frame.view.half;
                if zoom > 1.05 {
                    info.note += &format!("; zoomed ×{}", crate::plot::format::sig_trim(zoom, 2));
                }
                info.marks = self.flexible_mark();
                // Only labels within the panel's sides (the grid lines stay).
                let fits_x = |t: &TickLabel| {
                    label_fits(t.value, x_range, r.w, text_width(&t.text, font::TICK))
                };
                let fits_y = |t: &TickLabel| label_fits(t.value, y_range, r.h, font::TICK * LINE_HEIGHT);
                info.x_labels = linear_labels(&info.x_ticks).into_iter().filter(fits_x).collect();
                let y_labels = linear_labels(&info.y_ticks);
                // Labels wider than the gutter (0.70705 at the closest zoom) count steps from a
                // tick in the middle instead, which the title names.
                let room = margins::ANALYSIS_LEFT - 4.0;
                let wide = y_labels.iter().any(|t| text_width(&t.text, font::TICK) > room);
                let title_room = r.w + margins::ANALYSIS_LEFT;
                info.y_labels = match (wide, offset_labels(&info.y_ticks, title_room)) {
                    (true, Some((labels, base))) => {
                        info.note = format!("{base}; {}", info.note);
                        labels
                    }
                    (true, None) => Vec::new(),
                    _ => y_labels,
                };
                info.y_labels.retain(fits_y);
            }
            PanelKind::RhoCurve => {
                let frame = self.rho_frame(panel, false);
                let (x_ticks, y_ticks) = rho_ticks(r, &frame);
                let rate = self.options.measure == Measure::Rate;
                info.x_label = "δ [s]".into();
                info.y_label = if rate { "ln ρ/δ [1/s]" } else { "ρ" };
                info.x_range = frame.x_range;
                info.y_range = frame.y_range;
                info.x_labels = log_labels(&x_ticks, info.x_range, r.w, LOG_LABEL_SPACING[0]);
                info.x_ticks = x_ticks;
                info.y_ticks = y_ticks;
                info.x_scale = "log";
                // Both α when they differ: the curve is the loop's with α1 and α2 as set.
                let [a1, a2] = self.runs[0].config.map_or([f64::NAN; 2], |c| c.controller.alpha);
                let alpha = if a1 == a2 {
                    format!("α = {}", format::sig_trim(a1, 3))
                } else {
                    format!("α1 = {}, α2 = {}", format::sig_trim(a1, 3), format::sig_trim(a2, 3))
                };
                if let Some(omega) = crate::view::rho_curve::turn_omega(self.runs[0].report.as_ref()) {
                    info.x2_label = format!("ωδ [rad/period]; ω = {omega:.1} rad/s; 2π = one swing");
                    info.x2_labels = crate::view::rho_curve::turn_ticks(omega, frame.x_range)
                        .map(|(value, text)| TickLabel { value, text: text.into() })
                        .collect();
                }
                info.note = if rate {
                    format!("rate at {alpha} 1/s; shaded: < 0")
                } else {
                    format!("ρ(δ) at {alpha} 1/s; shaded: ρ < 1")
                };
            }
            PanelKind::MapOff | PanelKind::MapOn => {
                let side = side_of(panel.kind).unwrap_or(MapSide::Off);
                let grid = &self.maps[side.index()];
                let (x_ticks, y_ticks) = map_ticks(r, grid);
                info.x_label = "δ [s]".into();
                info.y_label = "α [1/s]";
                info.x_range = grid.delta_range();
                info.y_range = grid.alpha_range();
                info.x_labels = log_labels(&x_ticks, info.x_range, r.w, LOG_LABEL_SPACING[0]);
                info.y_labels = log_labels(&y_ticks, info.y_range, r.h, LOG_LABEL_SPACING[1]);
                info.x_ticks = x_ticks;
                info.y_ticks = y_ticks;
                info.x_scale = "log";
                info.y_scale = "log";
                let pf = self.runs[0].config.map(|c| c.preliminary_feedback).unwrap_or_default();
                info.note = side.caption(pf, self.options.measure);
            }
        }
        if info.x_scale == "linear" && info.x_labels.is_empty() {
            info.x_labels = linear_labels(&info.x_ticks);
        }
        if info.y_scale == "linear" && panel.kind != PanelKind::ZPlane {
            info.y_labels = linear_labels(&info.y_ticks);
        }
        info
    }

    /// Every marker of the pole plot (both runs in pair mode) with its position in CSS pixels
    /// in the plot shown (s- or z-plane), for hover readouts. Positions are null when the pole
    /// plot is hidden.
    pub fn pole_info(&self) -> Vec<PoleInfo> {
        let s_frame = self.layout.panel(PanelKind::Poles).map(|p| self.pole_frame(p.rect));
        let z_frame = self.layout.panel(PanelKind::ZPlane).map(|p| self.z_frame(p.rect));
        let view = match (&s_frame, &z_frame) {
            (Some(f), _) => PoleView::S(f),
            (None, Some(f)) => PoleView::Z(f),
            _ => PoleView::Hidden,
        };
        let mut out = Vec::new();
        for (memory, name) in self.runs.iter().zip(RUN_NAMES).take(self.run_count()) {
            if let Some(report) = &memory.report {
                describe_poles(report, name, view, &mut out);
            }
        }
        out
    }

    /// "flexible pair" beside run A's upper flexible loop pole, if the pole plot shows it.
    fn flexible_mark(&self) -> Vec<Mark> {
        let poles = self.pole_info();
        let Some(p) = poles.iter().find(|p| p.run == "A" && p.flexible && p.im > 0.0 && p.in_view) else {
            return Vec::new();
        };
        let (Some(x), Some(y)) = (p.x, p.y) else { return Vec::new() };
        // A narrow pole plot gets the short form rather than a cut one ("flexible pair, alia…").
        let room = self.layout.panels.iter().find(|q| q.kind.is_pole_plot()).map_or(0.0, |q| q.rect.w - 8.0);
        let fits = |t: &str| bold_width(t, font::NOTE) <= room;
        let forms: &[&str] =
            if p.aliased { &["flexible pair, aliased", "aliased pair", "aliased"] } else { &["flexible pair", "pair"] };
        // The z-plane says how far outside (or inside) the unit circle the pair is.
        if self.layout.panel(PanelKind::ZPlane).is_some() {
            let gap = gap_text(p.lambda);
            let long = format!("{}: {gap}", forms[0]);
            let text = [long.as_str(), gap.as_str()].into_iter().find(|t| fits(t)).unwrap_or(forms[forms.len() - 1]);
            return vec![Mark { x, y, text: text.into() }];
        }
        let text = forms.iter().copied().find(|t| fits(t)).unwrap_or(forms[forms.len() - 1]);
        vec![Mark { x, y, text: text.into() }]
    }

    /// How each shown run is drawn (one entry, or two in pair mode), for the page's legend.
    pub fn series_info(&self) -> Vec<SeriesInfo> {
        use crate::control::Traces;
        (0..self.run_count())
            .map(|run| {
                let style = run_pole_style(run);
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
        if self.cycle_window().is_some() {
            return None;
        }
        let panel = self.layout.panels.iter().find(|p| p.kind.is_time_plot() && contains(p, x, y))?;
        let w = self.window();
        let f = ((x - panel.rect.x) / panel.rect.w).clamp(0.0, 1.0);
        Some(w.start + f * w.width())
    }
}

pub(super) fn contains(p: &Panel, x: f64, y: f64) -> bool {
    x >= p.rect.x && x <= p.rect.right() && y >= p.rect.y && y <= p.rect.bottom()
}
