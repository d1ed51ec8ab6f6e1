//! ρ(δ) at the current α: the spectral radius (or the rate ln ρ/δ) along the sampling period with
//! the stable windows shaded, the law's window of the lag without preliminary feedback, a second
//! axis in ωδ, and the runs' δ marked ([`drawing`]). The curve is the static layer; the markers
//! move every frame. Clicking or dragging on it picks δ.

pub mod drawing;

use drawing::{
    curve_range, draw_rho_marker, draw_rho_static, lag_band, rho_ticks, turn_omega, turn_ticks, RhoFrame,
    MARKER_VERTEX_BUDGET,
};

use crate::plot::color::Measure;
use crate::plot::{format, palette};
use crate::schema::PanelKind;
use crate::view::layout::Panel;
use crate::view::legend::{item, Glyph, LegendGroup};
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe, Region, TickLabel, TipLine};
use crate::view::panels::contract::{Frame, PanelView, Runs};
use crate::view::rho_readout::stability_lines;
use crate::view::tick_labels::{linear_labels, log_labels};

/// Least distance between labels along the log δ axis, CSS px (a label's width).
const LOG_LABEL_SPACING: f64 = 38.0;

/// ρ(δ) ([`PanelKind::RhoCurve`]).
#[derive(Clone, Debug, Default)]
pub struct RhoCurve;

impl RhoCurve {
    /// Its frame (ρ or ln ρ/δ, as the view's measure says), in physical pixels or (for
    /// descriptions) CSS pixels.
    fn frame(frame: &Frame, panel: &Panel, physical: bool) -> RhoFrame {
        let rect = if physical { frame.layout.to_physical(panel.rect) } else { panel.rect };
        let x_range = frame.windows.as_ref().map_or(crate::schema::DELTA_SPEC.control, |w| w.range);
        RhoFrame { rect, x_range, y_range: curve_range(frame.windows.as_ref(), frame.options.measure) }
    }
}

impl PanelView for RhoCurve {
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (600.0, 300.0)
    }

    fn vertex_budget(&self, frame: &Frame, _panel: &Panel) -> usize {
        24 + frame.run_count() * MARKER_VERTEX_BUDGET
    }

    fn draw_static(&self, frame: &Frame, panel: &Panel, painter: &mut Painter) {
        let curve = Self::frame(frame, panel, true);
        let (x_ticks, y_ticks) = rho_ticks(panel.rect, &curve);
        let ticks = (&x_ticks[..], &y_ticks[..]);
        let lag = lag_band(frame.runs[0].config.as_ref(), frame.runs[0].report.as_ref());
        let omega = turn_omega(frame.runs[0].report.as_ref());
        let dpr = frame.layout.device_pixel_ratio;
        draw_rho_static(painter, &curve, frame.windows.as_ref(), lag, omega, ticks, frame.options.measure, dpr);
    }

    /// The runs' current δ on ρ(δ) or ln ρ/δ (the curve itself is in the static layer).
    fn draw(&mut self, frame: &Frame, _runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let dpr = frame.layout.device_pixel_ratio;
        let curve = Self::frame(frame, panel, true);
        for run in (0..frame.run_count()).rev() {
            let memory = &frame.runs[run];
            let (Some(config), Some(report)) = (&memory.config, &memory.report) else { continue };
            let color = if run == 0 { palette::MAP_MARKER } else { palette::RUN_B };
            let delta = config.controller.sampling_period;
            let value = frame.options.measure.value(report.spectral_radius, delta);
            draw_rho_marker(painter, &curve, delta, value, color, dpr);
        }
        painter.rect_outline(curve.rect, dpr.max(1.0), palette::FRAME);
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        let curve = Self::frame(frame, panel, false);
        let (x_ticks, y_ticks) = rho_ticks(r, &curve);
        let rate = frame.options.measure == Measure::Rate;
        info.x_label = "δ [s]".into();
        info.y_label = if rate { "ln ρ/δ [1/s]" } else { "ρ" };
        info.x_range = curve.x_range;
        info.y_range = curve.y_range;
        info.x_labels = log_labels(&x_ticks, info.x_range, r.w, LOG_LABEL_SPACING);
        info.x_ticks = x_ticks;
        info.y_ticks = y_ticks;
        info.x_scale = "log";
        // Both α when they differ (α1, α2): the curve is the loop's with α1 and α2 as set.
        let [a1, a2] = frame.runs[0].config.map_or([f64::NAN; 2], |c| c.controller.alpha);
        let alpha = if a1 == a2 {
            format!("α = {}", format::significant_trimmed(a1, 3))
        } else {
            // As the settings write them ("α = 5, 2 1/s"): "α1 = 5, α2 = 2" did not fit a small panel.
            format!("α = {}, {}", format::significant_trimmed(a1, 3), format::significant_trimmed(a2, 3))
        };
        if let Some(omega) = turn_omega(frame.runs[0].report.as_ref()) {
            info.x2_label = format!("ωδ [rad/period]; ω = {omega:.1} rad/s; 2π = one swing");
            info.x2_labels =
                turn_ticks(omega, curve.x_range).map(|(value, text)| TickLabel { value, text: text.into() }).collect();
        }
        info.note = if frame.windows_hidden {
            // Empty on purpose: the lesson's step keeps the windows for its answer.
            "ρ(δ) is hidden until you answer this step (the lesson keeps the windows of δ back)".into()
        } else if rate {
            format!("rate at {alpha} 1/s; shaded: < 0")
        } else {
            format!("ρ(δ) at {alpha} 1/s; shaded: ρ < 1")
        };
        info.y_labels = linear_labels(&info.y_ticks);
        info.region =
            Some(Region { label: "ρ along δ. Left and right arrow keys change δ.", keys: "delta", map: None });
        info
    }

    /// The δ under (x, y) on ρ(δ), with ρ and ln ρ/δ there.
    fn probe(&self, frame: &Frame, panel: &Panel, x: f64, y: f64, _reach: f64) -> Option<Probe> {
        if !panel.contains(x, y) {
            return None;
        }
        let curve = Self::frame(frame, panel, false);
        let delta = curve.delta_at(x);
        let [scan_delta, rho] = frame
            .windows
            .as_ref()
            .and_then(|w| {
                w.scan.iter().min_by(|a, b| (a[0] / delta).ln().abs().total_cmp(&(b[0] / delta).ln().abs())).copied()
            })
            .unwrap_or([delta, f64::NAN]);
        let mut lines = vec![TipLine::plain(format!("δ = {} s", format::significant(delta, 3)))];
        stability_lines(rho, scan_delta, &mut lines);
        // The second reading of δ: how far the joint's swing turns in a period, and how late the
        // torque acts on it (the lag law, analysis::lag).
        if let Some(law) = frame.runs[0].report.as_ref().map(crate::analysis::lag::LagLaw::of) {
            lines.push(TipLine::plain(format!(
                "the swing turns ωδ = {:.2} rad per period ({:.2} of a turn); the torque acts 1.5 ωδ = {:.0}° later",
                law.turn(delta),
                law.turn(delta) / core::f64::consts::TAU,
                law.lag(delta).to_degrees()
            )));
        }
        lines.push(TipLine::plain("click or drag to run at this δ"));
        let title = if frame.options.measure == Measure::Rate { "ln ρ/δ at this α" } else { "ρ(δ) at this α" };
        Some(Probe { kind: "rho", title: title.into(), lines, x, y, map: None, delta: Some(delta), alpha: None })
    }

    fn legend(&self, frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        if !kinds.contains(&PanelKind::RhoCurve) {
            return Vec::new();
        }
        let rate = frame.options.measure == Measure::Rate;
        let [curve, band, border] = if rate {
            [
                "ln ρ/δ (1/s) along δ at this α",
                "ln ρ/δ < 0: the stable windows of δ",
                "ln ρ/δ = 0, and the δ running now",
            ]
        } else {
            ["ρ along δ at this α", "ρ < 1: the stable windows of δ", "ρ = 1, and the δ running now"]
        };
        vec![LegendGroup {
            title: if rate { "ln ρ/δ along δ" } else { "ρ(δ)" },
            items: vec![
                item(Glyph::Line, palette::ERROR1, curve),
                item(Glyph::Swatch, palette::WINDOW_BAND, band),
                item(Glyph::Line, palette::POLE_STABLE, border),
                // Drawn only without preliminary feedback: the law explains the controller alone.
                item(
                    Glyph::Line,
                    palette::LAG_BAND,
                    "no Kₚᵣ: the window the lag law gives, ωδ up to π (see “Why some larger δ work”)",
                ),
                item(
                    Glyph::Line,
                    palette::AXIS,
                    "top axis ωδ: how far the swing turns in one period (ω = |Im A4|; π = half a swing, 2π = one)",
                ),
            ],
            scale: None,
        }]
    }

    fn figure_title(&self, frame: &Frame, _kinds: &[PanelKind]) -> String {
        format!("{} along δ", frame.options.measure.quantity())
    }
}
