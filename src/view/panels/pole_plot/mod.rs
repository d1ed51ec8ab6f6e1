//! The pole plot: the sampled loop's eigenvalues as s = ln λ / δ against the imaginary axis, the
//! δ → 0 pair A4 without and with the preliminary feedback, and the Nyquist frequency π/δ — the
//! picture of why small δ goes unstable ([`drawing`]; what it shares with the z-plane is
//! [`crate::view::loop_poles`]).

pub mod drawing;

use drawing::{
    draw_a4, draw_flexible_halo, draw_nyquist, draw_pole_background, draw_poles, PoleFrame, RUN_VERTEX_BUDGET,
};

use crate::plot::{format, palette, Ticks};
use crate::schema::PanelKind;
use crate::view::layout::Panel;
use crate::view::legend::LegendGroup;
use crate::view::loop_poles::readout::flexible_mark;
use crate::view::loop_poles::{flexible_aliased, legend_group, nyquist, size, PoleInfo, PoleStyle, RE_RANGE};
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe, Region};
use crate::view::panels::contract::{Frame, PanelView, Runs};
use crate::view::rect::Rect;
use crate::view::tick_labels::linear_labels;

/// About one Re s tick per this many CSS pixels of the plot's width ...
const X_TICK_SPACING: f64 = 30.0;
/// ... and one Im s tick per this many of its height.
const Y_TICK_SPACING: f64 = 32.0;
/// Vertices of one dashed Nyquist line at most (512 dashes).
const DASHED_LINE_BUDGET: usize = 512 * 6;

/// How many Re s and Im s intervals the pole plot gets at most.
fn tick_counts(rect_css: Rect) -> (usize, usize) {
    let x_count = (rect_css.w / X_TICK_SPACING).floor().clamp(2.0, 14.0) as usize;
    let y_count = (rect_css.h / Y_TICK_SPACING).floor().clamp(2.0, 16.0) as usize;
    (x_count, y_count)
}

/// Re s and Im s ticks of the pole plot whose data area is `rect_css` (CSS pixels) and whose Im s
/// range is `im`.
fn ticks(rect_css: Rect, im: [f64; 2]) -> (Ticks, Ticks) {
    let (x_count, y_count) = tick_counts(rect_css);
    (Ticks::at_least(RE_RANGE[0], RE_RANGE[1], x_count, 3), Ticks::at_least(im[0], im[1], y_count, 3))
}

/// The pole plot ([`PanelKind::Poles`]).
#[derive(Clone, Debug, Default)]
pub struct PolePlot;

impl PolePlot {
    /// Its frame on `rect` (physical or CSS pixels): the Im s range fits the shown runs' flexible
    /// pairs.
    pub fn frame(frame: &Frame, rect: Rect) -> PoleFrame {
        match frame.pole_im_held {
            Some(im) => PoleFrame { im, ..PoleFrame::fitting(rect, frame.reports()) },
            None => PoleFrame::fitting(rect, frame.reports()),
        }
    }
}

impl PanelView for PolePlot {
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (540.0, 380.0)
    }

    fn vertex_budget(&self, frame: &Frame, panel: &Panel) -> usize {
        let (x_ticks, y_ticks) = tick_counts(panel.rect);
        // Up to four more intervals each way where the axis is short (`Ticks::at_least`).
        let background = 6 * (x_ticks + y_ticks + 18) + 2 * 6 + 24 + 2 * DASHED_LINE_BUDGET;
        background + frame.run_count() * RUN_VERTEX_BUDGET
    }

    fn draw(&mut self, frame: &Frame, _runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let dpr = frame.layout.device_pixel_ratio;
        let plot = Self::frame(frame, frame.layout.to_physical(panel.rect));
        let (x_ticks, y_ticks) = ticks(panel.rect, plot.im);
        draw_pole_background(painter, &plot, x_ticks, y_ticks, dpr);
        if let Some(config) = &frame.runs[0].config {
            draw_nyquist(painter, &plot, config.controller.sampling_period, dpr);
        }
        let runs = frame.run_count();
        for memory in &frame.runs[..runs] {
            if let Some(report) = &memory.report {
                draw_flexible_halo(painter, &plot, report, dpr);
            }
        }
        // B first, so run A's markers stay on top.
        for run in (0..runs).rev() {
            if let Some(report) = &frame.runs[run].report {
                draw_a4(painter, &plot, report, &PoleStyle::of_run(run), dpr);
            }
        }
        for run in (0..runs).rev() {
            if let Some(report) = &frame.runs[run].report {
                draw_poles(painter, &plot, report, &PoleStyle::of_run(run), dpr);
            }
        }
        painter.rect_outline(plot.rect, dpr.max(1.0), palette::FRAME);
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        let im = Self::frame(frame, r).im;
        let (x_ticks, y_ticks) = ticks(r, im);
        info.x_label = "Re s [1/s]".into();
        info.y_label = "Im s [rad/s]";
        info.x_range = RE_RANGE;
        info.y_range = im;
        info.x_ticks = x_ticks.collect();
        info.y_ticks = y_ticks.collect();
        info.note = "poles s = ln λ/δ".into();
        if let Some(report) = &frame.runs[0].report {
            let w = nyquist(report.sampling_period);
            if w < im[1] {
                // The warning first: a narrow panel keeps it and drops the line's name (the key
                // names it).
                if flexible_aliased(report) {
                    info.note += "; aliased: the flexible mode is faster than π/δ";
                }
                info.note += &format!("; dashed: π/δ = {} rad/s", format::significant(w, 3));
            }
        }
        let poles = self.pole_markers(frame, panel).unwrap_or_default();
        info.marks = flexible_mark(&poles, r.w, None);
        info.x_labels = linear_labels(&info.x_ticks);
        info.y_labels = linear_labels(&info.y_ticks);
        info.region = Some(Region {
            label: "Pole plot. Arrow keys step from pole to pole and read each one.",
            keys: "poles",
            map: None,
        });
        info
    }

    fn pole_markers(&self, frame: &Frame, panel: &Panel) -> Option<Vec<PoleInfo>> {
        let plot = Self::frame(frame, panel.rect);
        let place = |s: [f64; 2], _: [f64; 2]| {
            let (p, off) = plot.marker(s, size::EDGE);
            (Some(p), off.is_none())
        };
        Some(frame.pole_markers(&place))
    }

    fn probe(&self, frame: &Frame, panel: &Panel, x: f64, y: f64, reach: f64) -> Option<Probe> {
        let poles = self.pole_markers(frame, panel)?;
        frame.probe_poles(&poles, panel, false, x, y, reach)
    }

    fn legend(&self, frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        if kinds.contains(&PanelKind::Poles) {
            vec![legend_group(false, frame.pair)]
        } else {
            Vec::new()
        }
    }

    fn figure_title(&self, _frame: &Frame, _kinds: &[PanelKind]) -> String {
        "Poles of the sampled loop, s = ln λ/δ".into()
    }
}
