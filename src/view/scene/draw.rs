//! Drawing one frame's panels into the per-frame layer: the arms, the time plots (linear or
//! log |e| with the slope ρ predicts, and the ghost of the previous run), the pole plot in the s- or
//! z-plane, the markers on ρ(δ) and on the maps. Nothing here allocates once the painter is warm.

use super::plots::{plot_series, plot_ticks, pole_ticks};
use super::{run_pole_style, RunState, Scene, CURVE_WIDTH, CURVE_WIDTH_B, LOG_DECADES};
use crate::control::Snapshot;
use crate::model::reference::Reference;
use crate::plot::ticks::Decades;
use crate::plot::{palette, Color};
use crate::session::MapSide;
use crate::view::arm::{draw_arm_outline, draw_arm_panel, ArmPose};
use crate::view::layout::{Panel, PanelKind};
use crate::view::map::{draw_map_marker, side_of, LogFrame};
use crate::view::poles::{draw_a4, draw_flexible_halo, draw_nyquist, draw_pole_background, draw_poles};
use crate::view::rho_curve::draw_rho_marker;
use crate::view::traces::{
    draw_background, draw_frame, draw_series, draw_series_within, max_abs, PlotFrame, TimeWindow,
};
use crate::view::zplane::{draw_radial_tick, draw_zplane_background, draw_zplane_run, upper_flexible, z_ticks};

impl Scene {
    pub(super) fn draw_arm(&mut self, panel: Panel, snapshot: &Snapshot) {
        let [q1, q2, theta] = snapshot.q;
        let actual = ArmPose { q1, q2, theta };
        let [qd1, qd2] = snapshot.qd;
        let reference = ArmPose { q1: qd1, q2: qd2, theta: qd1 };
        let rect = self.layout.to_physical(panel.rect);
        let dpr = self.layout.device_pixel_ratio;
        let magnification = self.options.spring_magnification;
        draw_arm_panel(&mut self.painter, rect, dpr, &actual, &reference, magnification);
        // The flexible pair's shape, turning (slowed down) about the rest point of the analysis.
        if panel.kind == PanelKind::Arm {
            if let Some(pose) = self.swing_pose() {
                draw_arm_outline(&mut self.painter, rect, dpr, &pose, 1.0, palette::SWING);
            }
        }
        // Zoomed on t_n: where the controller predicts the arm at t_n + kε (X_k).
        if panel.kind == PanelKind::Arm && self.cycle_window().is_some() && self.cycle.sweep.complete {
            if let Some(x) = self.cycle.sweep.states.last() {
                let predicted = ArmPose { q1: x[0], q2: x[1], theta: x[2] };
                draw_arm_outline(&mut self.painter, rect, dpr, &predicted, magnification, palette::PREDICTED_ARM);
            }
        }
    }

    /// True if this plot shows log |e|.
    pub(super) fn log_plot(&self, kind: PanelKind) -> bool {
        (self.options.log_errors || self.auto_log) && matches!(kind, PanelKind::Error1 | PanelKind::Error2)
    }

    /// The value range of a plot with half-range `y`: ±y, or [y·10^−LOG_DECADES, y] for log |e|.
    pub(super) fn plot_range(&self, kind: PanelKind, y: f64) -> [f64; 2] {
        if self.log_plot(kind) {
            [y * 10f64.powi(-LOG_DECADES), y]
        } else {
            [-y, y]
        }
    }

    pub(super) fn draw_plot(&mut self, panel: Panel, window: TimeWindow, a: &RunState<'_>, b: Option<&RunState<'_>>) {
        let runs = [Some(a), b];
        let mut data_max: f64 = 0.0;
        for (run, state) in runs.iter().enumerate() {
            let Some(state) = state else { continue };
            let range = window.indices(state.traces.t());
            for (values, _) in plot_series(panel.kind, state.traces, run).iter().flatten() {
                data_max = data_max.max(values.get(range.clone()).map_or(0.0, max_abs));
            }
        }
        let time = self.time;
        let log = self.log_plot(panel.kind);
        let Some(scale) = self.scale_mut(panel.kind) else { return };
        let y = scale.update(data_max, time);
        let dpr = self.layout.device_pixel_ratio;
        let [y_lo, y_hi] = self.plot_range(panel.kind, y);
        let frame = PlotFrame { rect: self.layout.to_physical(panel.rect), window, y_lo, y_hi, log };
        let (x_ticks, y_ticks) = plot_ticks(panel.rect, window, y);
        if log {
            draw_background(&mut self.painter, &frame, x_ticks, Decades::new(y_lo, y_hi), a.reference, dpr);
        } else {
            draw_background(&mut self.painter, &frame, x_ticks, y_ticks, a.reference, dpr);
        }
        // The previous run, faint, under everything (it does not drive the scale).
        if let Some(ghost) = a.ghost {
            for (values, _) in plot_series(panel.kind, ghost, 0).iter().flatten() {
                let t = ghost.t();
                let m = t.len().min(values.len());
                draw_series_within(
                    &mut self.painter,
                    &frame,
                    &t[..m],
                    &values[..m],
                    CURVE_WIDTH * dpr,
                    palette::GHOST_TRACE,
                );
            }
        }
        for (run, state) in runs.iter().enumerate() {
            let Some(state) = state else { continue };
            let traces = state.traces;
            let t = traces.t();
            let width = if run == 0 { CURVE_WIDTH } else { CURVE_WIDTH_B };
            if log && run == 0 {
                // The rest under the error itself, the swing over it.
                self.draw_split(&frame, state, panel.kind);
            }
            for (values, color) in plot_series(panel.kind, traces, run).iter().flatten() {
                let m = t.len().min(values.len());
                draw_series(&mut self.painter, &frame, &t[..m], &values[..m], width * dpr, *color);
            }
            if log && run == 0 {
                self.draw_swing(&frame);
            }
            if log && !self.options.hide_prediction {
                self.draw_predicted_slope(&frame, state, panel.kind, run);
            }
        }
        if let Some(c) = self.cursor.filter(|c| *c >= window.start && *c <= window.end) {
            let x = frame.x(c);
            let r = frame.rect;
            self.painter.line([x, r.y], [x, r.y + r.h], 2.0 * dpr, palette::CURSOR);
        }
        draw_frame(&mut self.painter, &frame, dpr);
    }

    /// Over log |e|: the straight line e^{(ln ρ/δ) t} through the newest envelope — where the
    /// errors would go if only the dominant mode moved them. The simulation obeys the analysis
    /// where the traces run parallel to it.
    fn draw_predicted_slope(&mut self, frame: &PlotFrame, state: &RunState<'_>, kind: PanelKind, run: usize) {
        let Some(report) = state.analysis else { return };
        let g = report.growth_rate;
        let t = state.traces.t();
        let Some(&now) = t.last() else { return };
        let [Some((values, _)), _] = plot_series(kind, state.traces, run) else { return };
        // The free motion about rest: not while the reference moves, nor back into the last slew.
        let reference = state.reference.copied().or_else(|| state.config.map(|c| Reference::new(c.reference)));
        let rest = match reference {
            Some(r) => match r.rest_since(now) {
                Some(since) if now - since >= 0.1 => since,
                _ => return,
            },
            None => f64::NEG_INFINITY,
        };
        let recent = TimeWindow { start: (now - 0.5).max(rest), end: now }.indices(t);
        let e = values.get(recent).map_or(0.0, max_abs);
        if !(g.is_finite() && g != 0.0 && e > 0.0 && now > frame.window.start) {
            return;
        }
        // Back from now until the line leaves the plot through the top or bottom, the window or
        // the rest it describes.
        let bound = if g > 0.0 { frame.y_lo } else { frame.y_hi };
        let start = (now + (bound / e).ln() / g).max(frame.window.start).max(rest);
        let v_start = e * (g * (start - now)).exp();
        let dpr = self.layout.device_pixel_ratio;
        let color = if run == 0 { palette::PREDICTED } else { palette::RUN_B };
        // Kept half a line inside the frame, so that its ends do not stick out of the plot.
        let half = 0.875 * dpr;
        let r = frame.rect;
        // (A plot thinner than the line itself keeps it on its middle.)
        let (top, bottom) = (r.y + half, (r.bottom() - half).max(r.y + half));
        let inside = |p: [f64; 2]| [p[0], p[1].clamp(top, bottom)];
        let (a, b) = (inside([frame.x(start), frame.y(v_start)]), inside([frame.x(now), frame.y(e)]));
        self.painter.dashed_line(a, b, 1.75 * dpr, 7.0 * dpr, 5.0 * dpr, color);
    }

    pub(super) fn draw_pole_plot(&mut self, panel: Panel) {
        let dpr = self.layout.device_pixel_ratio;
        let frame = self.pole_frame(self.layout.to_physical(panel.rect));
        let (x_ticks, y_ticks) = pole_ticks(panel.rect, frame.im);
        draw_pole_background(&mut self.painter, &frame, x_ticks, y_ticks, dpr);
        if let Some(config) = &self.runs[0].config {
            draw_nyquist(&mut self.painter, &frame, config.controller.sampling_period, dpr);
        }
        let runs = self.run_count();
        for memory in &self.runs[..runs] {
            if let Some(report) = &memory.report {
                draw_flexible_halo(&mut self.painter, &frame, report, dpr);
            }
        }
        // B first, so run A's markers stay on top.
        for run in (0..runs).rev() {
            if let Some(report) = &self.runs[run].report {
                draw_a4(&mut self.painter, &frame, report, &run_pole_style(run), dpr);
            }
        }
        for run in (0..runs).rev() {
            if let Some(report) = &self.runs[run].report {
                draw_poles(&mut self.painter, &frame, report, &run_pole_style(run), dpr);
            }
        }
        self.painter.rect_outline(frame.rect, dpr.max(1.0), palette::FRAME);
    }

    pub(super) fn draw_zplane(&mut self, panel: Panel) {
        let dpr = self.layout.device_pixel_ratio;
        let frame = self.z_frame(self.layout.to_physical(panel.rect));
        let ticks = z_ticks(panel.rect, frame.view);
        draw_zplane_background(&mut self.painter, &frame, ticks, dpr);
        // How far run A's flexible pair is from the circle: the mark names it, this shows it.
        if let Some(z) = self.runs[0].report.as_ref().and_then(upper_flexible) {
            draw_radial_tick(&mut self.painter, &frame, z, dpr);
        }
        for run in (0..self.run_count()).rev() {
            if let Some(report) = &self.runs[run].report {
                draw_zplane_run(&mut self.painter, &frame, report, &run_pole_style(run), dpr);
            }
        }
        self.painter.rect_outline(frame.rect, dpr.max(1.0), palette::FRAME);
    }

    /// The runs' current δ on ρ(δ) or ln ρ/δ (the curve itself is in the static layer).
    pub(super) fn draw_rho_markers(&mut self, panel: Panel) {
        let dpr = self.layout.device_pixel_ratio;
        let frame = self.rho_frame(&panel, true);
        for run in (0..self.run_count()).rev() {
            let memory = &self.runs[run];
            let (Some(config), Some(report)) = (&memory.config, &memory.report) else { continue };
            let color = if run == 0 { palette::MAP_MARKER } else { palette::RUN_B };
            let delta = config.controller.sampling_period;
            let value = self.options.measure.value(report.spectral_radius, delta);
            draw_rho_marker(&mut self.painter, &frame, delta, value, color, dpr);
        }
        self.painter.rect_outline(frame.rect, dpr.max(1.0), palette::FRAME);
    }

    pub(super) fn draw_map_overlay(&mut self, panel: Panel) {
        let Some(side) = side_of(panel.kind) else { return };
        let dpr = self.layout.device_pixel_ratio;
        let grid = &self.maps[side.index()];
        let frame = LogFrame {
            rect: self.layout.to_physical(panel.rect),
            x_range: grid.delta_range(),
            y_range: grid.alpha_range(),
        };
        // Run A's stable windows of δ at its α, on the map of its feedback.
        if let (Some(config), Some(windows)) = (&self.runs[0].config, &self.windows) {
            if MapSide::for_feedback(config.preliminary_feedback) == side {
                let y = frame.y_log(config.controller.alpha[0].ln());
                if y >= frame.rect.y && y <= frame.rect.bottom() {
                    for [lo, hi] in &windows.windows {
                        let (x0, x1) = (frame.x_log(lo.ln()), frame.x_log(hi.ln()));
                        let (x0, x1) = (x0.max(frame.rect.x), x1.min(frame.rect.right()));
                        if x1 > x0 {
                            self.painter.line([x0, y], [x1, y], 7.0 * dpr, palette::MARKER_HALO);
                            self.painter.line([x0, y], [x1, y], 3.5 * dpr, palette::WINDOW_MARK);
                        }
                    }
                }
            }
        }
        for run in (0..self.run_count()).rev() {
            let Some(config) = &self.runs[run].config else { continue };
            let filled = MapSide::for_feedback(config.preliminary_feedback) == side;
            let color: Color = if run == 0 { palette::MAP_MARKER } else { palette::RUN_B };
            let (delta, alpha) = (config.controller.sampling_period, config.controller.alpha[0]);
            draw_map_marker(&mut self.painter, &frame, delta, alpha, filled, color, dpr);
        }
        self.painter.rect_outline(frame.rect, dpr.max(1.0), palette::FRAME);
    }
}
