//! The time plots: the tracking errors e1, e2 and the torques T1, T2 over a scrolling window
//! ([`drawing`], [`series`]), with the previous run faint under them; as log |e| with the slope
//! ln ρ/δ the analysis predicts and the error split into the swing and the rest ([`split`]), by
//! choice or by themselves when two compared runs differ by a decade ([`compare`]); or zoomed on
//! one sampling instant, the paper's Fig. 2.1 ([`zoom`]). With the `measured` switch and digital
//! sensors, link 1's velocity q̇1 beside the controller's estimate of it (differenced, perhaps
//! filtered, held over each period), on a scale the true velocity sets: the estimate is clamped
//! to it.

pub mod compare;
pub mod drawing;
pub mod series;
pub mod split;
pub mod zoom;

use compare::{largest_error, wants_log, AUTO_LOG_KEY, AUTO_LOG_NOTE};
use drawing::{
    draw_background, draw_frame, draw_series, draw_series_clamped, draw_series_within, max_abs, vertex_budget,
    PlotFrame,
};
use series::{
    plot_series, plot_tick_counts, plot_ticks, y_label, CURVE_WIDTH, CURVE_WIDTH_B, DASHED_LINE_BUDGET, LOG_DECADES,
};
use split::{SplitBuffers, SPLIT_SERIES};
use zoom::{Zoom, ZOOM_VERTEX_BUDGET};

use crate::control::sensing::SensorModel;
use crate::control::{Column, Traces};
use crate::model::reference::Reference;
use crate::plot::ticks::Decades;
use crate::plot::{palette, Color};
use crate::schema::PanelKind;
use crate::view::autoscale::{Autoscale, AutoscaleSettings};
use crate::view::layout::Panel;
use crate::view::legend::{item, Glyph, LegendGroup};
use crate::view::painter::Painter;
use crate::view::panel_info::PanelInfo;
use crate::view::panels::contract::{Frame, PanelView, RunState, Runs};
use crate::view::tick_labels::{linear_labels, log_labels};
use crate::view::time_window::TimeWindow;

/// Least distance between log-axis labels along y, CSS px (a label's height).
const LOG_LABEL_SPACING: f64 = 17.0;

/// Width of the measured errors' light staircase under the true errors, CSS px.
const MEASURED_WIDTH: f64 = 3.5;

/// Run A's sensors as of the latest frame (None before it has a configuration).
fn sensors(frame: &Frame) -> Option<SensorModel> {
    frame.runs[0].config.map(|c| c.sensors)
}

/// Run A's torque limit, N m, if its motors have one.
fn torque_limit(frame: &Frame) -> Option<f64> {
    sensors(frame).and_then(|s| s.limit())
}

/// The switch "what the controller reads" is on and run A's controller reads sensors (off, it
/// reads the true state: nothing to compare).
fn measured_shown(frame: &Frame) -> bool {
    frame.options.show_measured && !frame.zoomed() && frame.digital()
}

/// The error as the controller read it, and its colour, if `kind`'s plot draws it.
fn measured_series(frame: &Frame, kind: PanelKind) -> Option<(Column, Color)> {
    if !measured_shown(frame) {
        return None;
    }
    match kind {
        PanelKind::Error1 => Some((Column::E1Meas, palette::MEASURED1)),
        PanelKind::Error2 => Some((Column::E2Meas, palette::MEASURED2)),
        PanelKind::Velocity => Some((Column::Q1DotEst, palette::VELOCITY1_EST)),
        _ => None,
    }
}

/// The key's words for the torque limit ±`limit`.
fn limit_text(limit: f64) -> String {
    format!("limit ±{} N m", crate::plot::format::number(limit))
}

/// The time plots ([`PanelKind::Error1`], [`PanelKind::Error2`], [`PanelKind::Torque`]) and what
/// they keep between frames: their autoscales, the zoom's, the split's buffers and whether the
/// compared runs turned them to log |e|.
#[derive(Clone, Debug)]
pub struct TimePlots {
    /// e1, e2, the torques.
    scales: [Autoscale; 3],
    /// Link 1's velocity (set by the true one).
    velocity: Autoscale,
    /// The latest frame clamped the velocity's estimate to the scale somewhere in the window.
    velocity_clamped: bool,
    zoom: Zoom,
    split: SplitBuffers,
    auto_log: bool,
}

impl Default for TimePlots {
    fn default() -> Self {
        Self {
            scales: Autoscale::time_plots(),
            velocity: Autoscale::new(AutoscaleSettings::VELOCITY),
            velocity_clamped: false,
            zoom: Zoom::default(),
            split: SplitBuffers::default(),
            auto_log: false,
        }
    }
}

/// Which of the scales a time plot uses.
fn scale_index(kind: PanelKind) -> Option<usize> {
    match kind {
        PanelKind::Error1 => Some(0),
        PanelKind::Error2 => Some(1),
        PanelKind::Torque => Some(2),
        _ => None,
    }
}

impl TimePlots {
    /// Forgets every scale (the simulation restarted: the old data are gone, so are their scales).
    pub fn reset_scales(&mut self) {
        for s in &mut self.scales {
            s.reset();
        }
        self.velocity.reset();
        self.zoom.reset();
    }

    /// The half-range a plot shows now (0 for other panels).
    pub fn limit(&self, kind: PanelKind) -> f64 {
        match kind {
            PanelKind::Velocity => self.velocity.limit(),
            _ => scale_index(kind).map_or(0.0, |i| self.scales[i].limit()),
        }
    }

    /// The scale of a plot, if `kind` is a time plot.
    fn scale_mut(&mut self, kind: PanelKind) -> Option<&mut Autoscale> {
        match kind {
            PanelKind::Velocity => Some(&mut self.velocity),
            _ => scale_index(kind).map(|i| &mut self.scales[i]),
        }
    }

    /// True while the error plots are log |e| because the compared runs differ by a decade.
    pub fn auto_log(&self) -> bool {
        self.auto_log
    }

    /// Decides, for this frame, whether the error plots turn to log |e| by themselves: only when
    /// two runs are compared, the user has not chosen log |e| and the plots are not zoomed on one
    /// instant. True if that changed (the frame's ticks and notes differ).
    pub fn update_auto_log(&mut self, frame: &Frame, runs: &Runs<'_>, window: TimeWindow) -> bool {
        let next = match &runs.b {
            Some(b) if !frame.options.log_errors && !frame.zoomed() => {
                wants_log(largest_error(&runs.a, window), largest_error(b, window), self.auto_log)
            }
            _ => false,
        };
        let changed = next != self.auto_log;
        self.auto_log = next;
        changed
    }

    /// What the time plots' description depends on besides the layout: their scales and first
    /// time tick, the window's width, one run or two (or, zoomed, the zoom's scales and whether
    /// the jump to consistency is off the scale). The scene re-describes the frame when it changes.
    pub fn signature(&self, frame: &Frame, window: TimeWindow) -> [f64; 8] {
        let first_tick = frame
            .layout
            .panels
            .iter()
            .find(|p| p.kind.is_time_plot())
            .and_then(|p| plot_ticks(p.rect, window, 1.0).0.next())
            .unwrap_or(f64::NAN);
        // Zoomed, the window moves every period but its ticks stay where they are (t_n − δ …).
        if frame.zoomed() {
            [
                self.zoom.limit(PanelKind::Error1),
                self.zoom.limit(PanelKind::Error2),
                self.zoom.limit(PanelKind::Torque),
                if self.zoom.jump_off_scale(frame) { 1.0 } else { 0.0 },
                window.width(),
                3.0,
                0.0,
                0.0,
            ]
        } else {
            [
                self.scales[0].limit(),
                self.scales[1].limit(),
                self.scales[2].limit(),
                first_tick,
                window.width(),
                if frame.pair { 2.0 } else { 1.0 },
                self.velocity.limit(),
                if self.velocity_clamped { 1.0 } else { 0.0 },
            ]
        }
    }

    /// True if this plot shows log |e|.
    fn log_plot(&self, frame: &Frame, kind: PanelKind) -> bool {
        (frame.options.log_errors || self.auto_log) && matches!(kind, PanelKind::Error1 | PanelKind::Error2)
    }

    /// The value range of a plot with half-range `y`: ±y, or [y·10^−LOG_DECADES, y] for log |e|.
    fn plot_range(&self, frame: &Frame, kind: PanelKind, y: f64) -> [f64; 2] {
        if self.log_plot(frame, kind) {
            [y * 10f64.powi(-LOG_DECADES), y]
        } else {
            [-y, y]
        }
    }

    fn draw_plot(&mut self, frame: &Frame, panel: &Panel, window: TimeWindow, runs: &Runs<'_>, painter: &mut Painter) {
        let mut data_max: f64 = 0.0;
        for (run, state) in runs.each().iter().enumerate() {
            let Some(state) = state else { continue };
            let range = window.indices(state.traces.t());
            for (values, _) in plot_series(panel.kind, state.traces, run).iter().flatten() {
                data_max = data_max.max(values.get(range.clone()).map_or(0.0, max_abs));
            }
        }
        let measured = measured_series(frame, panel.kind);
        let velocity = panel.kind == PanelKind::Velocity;
        // The velocity's scale is the true velocity's: a differenced estimate can be far noisier.
        if let Some((column, _)) = measured.filter(|_| !velocity) {
            let range = window.indices(runs.a.traces.t());
            data_max = data_max.max(runs.a.traces.column(column).get(range).map_or(0.0, max_abs));
        }
        let limit = torque_limit(frame).filter(|_| panel.kind == PanelKind::Torque);
        if let Some(l) = limit {
            // The scale shows the limit, so that a torque at it is seen to be at it.
            data_max = data_max.max(l);
        }
        let log = self.log_plot(frame, panel.kind);
        let Some(scale) = self.scale_mut(panel.kind) else { return };
        let y = scale.update(data_max, frame.time);
        let dpr = frame.layout.device_pixel_ratio;
        let [y_lo, y_hi] = self.plot_range(frame, panel.kind, y);
        let plot = PlotFrame { rect: frame.layout.to_physical(panel.rect), window, y_lo, y_hi, log };
        let (x_ticks, y_ticks) = plot_ticks(panel.rect, window, y);
        let a = &runs.a;
        if log {
            draw_background(painter, &plot, x_ticks, Decades::new(y_lo, y_hi), a.reference, dpr);
        } else {
            draw_background(painter, &plot, x_ticks, y_ticks, a.reference, dpr);
        }
        // The previous run, faint, under everything (it does not drive the scale).
        if let Some(ghost) = a.ghost {
            for (values, _) in plot_series(panel.kind, ghost, 0).iter().flatten() {
                let t = ghost.t();
                let m = t.len().min(values.len());
                draw_series_within(painter, &plot, &t[..m], &values[..m], CURVE_WIDTH * dpr, palette::GHOST_TRACE);
            }
        }
        // What run A's controller read, a light staircase under the true error.
        if let Some((column, color)) = measured {
            let (t, values) = (a.traces.t(), a.traces.column(column));
            let m = t.len().min(values.len());
            if velocity {
                self.velocity_clamped =
                    draw_series_clamped(painter, &plot, &t[..m], &values[..m], MEASURED_WIDTH * dpr, color);
            } else {
                draw_series(painter, &plot, &t[..m], &values[..m], MEASURED_WIDTH * dpr, color);
            }
        }
        for (run, state) in runs.each().iter().enumerate() {
            let Some(state) = state else { continue };
            let traces = state.traces;
            let t = traces.t();
            let width = if run == 0 { CURVE_WIDTH } else { CURVE_WIDTH_B };
            if log && run == 0 {
                // The rest under the error itself, the swing over it.
                self.split.draw_split(painter, &plot, state, panel.kind, dpr);
            }
            for (values, color) in plot_series(panel.kind, traces, run).iter().flatten() {
                let m = t.len().min(values.len());
                draw_series(painter, &plot, &t[..m], &values[..m], width * dpr, *color);
            }
            if log && run == 0 {
                self.split.draw_swing(painter, &plot, dpr);
            }
            if log && !frame.options.hide_prediction {
                draw_predicted_slope(painter, &plot, state, panel.kind, run, dpr);
            }
        }
        if let Some(l) = limit {
            let r = plot.rect;
            for v in [l, -l] {
                let y = plot.y(v);
                painter.dashed_line([r.x, y], [r.right(), y], 1.5 * dpr, 8.0 * dpr, 5.0 * dpr, palette::TORQUE_LIMIT);
            }
        }
        if let Some(c) = frame.cursor.filter(|c| *c >= window.start && *c <= window.end) {
            let x = plot.x(c);
            let r = plot.rect;
            painter.line([x, r.y], [x, r.y + r.h], 2.0 * dpr, palette::CURSOR);
        }
        draw_frame(painter, &plot, dpr);
    }

    /// A time plot as the page reads it (not zoomed).
    fn describe_plot(&self, frame: &Frame, panel: &Panel, window: TimeWindow, info: &mut PanelInfo) {
        let r = panel.rect;
        let y = self.limit(panel.kind);
        let (x_ticks, y_ticks) = plot_ticks(r, window, y);
        info.x_label = "t [s]".into();
        info.y_label = y_label(panel.kind);
        info.x_range = [window.start, window.end];
        info.y_range = self.plot_range(frame, panel.kind, y);
        info.x_ticks = x_ticks.collect();
        if self.log_plot(frame, panel.kind) {
            info.y_label = if panel.kind == PanelKind::Error1 { "|e1| [rad], log" } else { "|e2| [rad], log" };
            info.y_scale = "log";
            info.y_ticks = Decades::new(info.y_range[0], info.y_range[1]).collect();
            info.y_labels = log_labels(&info.y_ticks, info.y_range, r.h, LOG_LABEL_SPACING);
            if panel.kind == PanelKind::Error1 && !frame.options.hide_prediction {
                info.note = "dashed: slope ln ρ/δ; as the analysis predicts".into();
            }
            if self.auto_log {
                // Said where it is seen: the shared axes are logarithmic by the page's choice.
                info.note =
                    if info.note.is_empty() { AUTO_LOG_NOTE.into() } else { format!("{AUTO_LOG_NOTE}; {}", info.note) };
            }
        } else {
            info.y_ticks = y_ticks.collect();
        }
        let note = match panel.kind {
            PanelKind::Torque => torque_limit(frame).map(|l| format!("dashed: {}", limit_text(l))),
            PanelKind::Velocity => Some(if self.velocity_clamped {
                "light: as estimated, held; clipped to the scale".to_string()
            } else {
                "light: as estimated, held over each period".to_string()
            }),
            PanelKind::Error1 if frame.options.show_measured => Some(if measured_shown(frame) {
                "light: as measured, held over each period".to_string()
            } else {
                "sensors off: the controller reads the true errors".to_string()
            }),
            _ => None,
        };
        if let Some(note) = note {
            info.note = if info.note.is_empty() { note } else { format!("{}; {note}", info.note) };
        }
    }
}

/// Over log |e|: the straight line e^{(ln ρ/δ) t} through the newest envelope — where the errors
/// would go if only the dominant mode moved them. The simulation obeys the analysis where the
/// traces run parallel to it.
fn draw_predicted_slope(
    painter: &mut Painter,
    frame: &PlotFrame,
    state: &RunState<'_>,
    kind: PanelKind,
    run: usize,
    dpr: f64,
) {
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
    // Back from now until the line leaves the plot through the top or bottom, the window or the
    // rest it describes.
    let bound = if g > 0.0 { frame.y_lo } else { frame.y_hi };
    let start = (now + (bound / e).ln() / g).max(frame.window.start).max(rest);
    let v_start = e * (g * (start - now)).exp();
    let color = if run == 0 { palette::PREDICTED } else { palette::RUN_B };
    // Kept half a line inside the frame, so that its ends do not stick out of the plot.
    let half = 0.875 * dpr;
    let r = frame.rect;
    // (A plot thinner than the line itself keeps it on its middle.)
    let (top, bottom) = (r.y + half, (r.bottom() - half).max(r.y + half));
    let inside = |p: [f64; 2]| [p[0], p[1].clamp(top, bottom)];
    let (a, b) = (inside([frame.x(start), frame.y(v_start)]), inside([frame.x(now), frame.y(e)]));
    painter.dashed_line(a, b, 1.75 * dpr, 7.0 * dpr, 5.0 * dpr, color);
}

impl PanelView for TimePlots {
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (660.0, 200.0)
    }

    fn vertex_budget(&self, frame: &Frame, panel: &Panel) -> usize {
        let runs = frame.run_count();
        // Each run's curves, the ghost's, and a predicted slope per run.
        let per_run = plot_series(panel.kind, &Traces::default(), 0).iter().flatten().count();
        // … and the measured error under run A's.
        let series = per_run * (runs + 1) + SPLIT_SERIES + usize::from(frame.options.show_measured);
        let (x_ticks, y_ticks) = plot_tick_counts(panel.rect);
        vertex_budget(frame.layout.to_physical(panel.rect).w, series, x_ticks + y_ticks + LOG_DECADES as usize + 4)
            + runs * DASHED_LINE_BUDGET
            + 2 * DASHED_LINE_BUDGET // the torque limit ±L
            + 6 // the cursor
            + if frame.options.show_cycle { ZOOM_VERTEX_BUDGET } else { 0 }
    }

    fn draw(&mut self, frame: &Frame, runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let window = frame.window();
        if frame.zoomed() && panel.kind != PanelKind::Velocity {
            self.zoom.draw(frame, panel, window, &runs.a, painter);
        } else {
            self.draw_plot(frame, panel, window, runs, painter);
        }
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        info.scrolls = true;
        let window = frame.window();
        if frame.zoomed() && panel.kind != PanelKind::Velocity {
            self.zoom.describe(frame, panel, window, &mut info);
        } else {
            self.describe_plot(frame, panel, window, &mut info);
        }
        if info.x_labels.is_empty() {
            info.x_labels = linear_labels(&info.x_ticks);
        }
        if info.y_scale == "linear" {
            info.y_labels = linear_labels(&info.y_ticks);
        }
        info
    }

    fn legend(&self, frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        let mut groups = Vec::new();
        if frame.zoomed() && kinds.contains(&PanelKind::Torque) {
            groups.push(LegendGroup {
                title: "Fig. 2.1: one sampling instant tₙ",
                items: vec![
                    item(Glyph::Ring, palette::PREDICTED, "x(tₙ): the state the controller measures at tₙ"),
                    item(
                        Glyph::Swatch,
                        palette::HORIZON_BAND,
                        "the horizon τ = kε: from x(tₙ) it predicts X₁ … Xₖ and U₁ … Uₖ, k backward-Euler steps of ε \
                         (dashed, a dot per step)",
                    ),
                    item(
                        Glyph::Chevron,
                        palette::ERROR1,
                        "U₁, U₂ off the scale: the first steps put the motor where the links' law needs it, whatever \
                         was measured — from X₂ on the prediction no longer depends on the measured θ, θ̇",
                    ),
                    item(Glyph::Diamond, palette::PREDICTED, "Uₖ, the torque at tₙ + kε: the only one used"),
                    item(
                        Glyph::Swatch,
                        palette::HOLD_BAND,
                        "tₙ + δ to tₙ + 2δ: Uₖ is held there, one period after the measurement (u = v + K_pr x: steps \
                         of v)",
                    ),
                    item(Glyph::Dashed, palette::PREDICTED, "Uₖ still to come: the run is at tₙ"),
                    item(Glyph::Line, palette::PREDICTED_ARM, "on the arm: Xₖ, the arm as predicted for tₙ + kε"),
                ],
                scale: None,
            });
        }
        if (frame.options.log_errors || self.auto_log) && kinds.contains(&PanelKind::Error1) {
            // The panel's note names the line only where there is room; the key always does (and
            // why the axes are logarithmic where the plot's header has no room).
            groups.push(LegendGroup {
                title: if self.auto_log { AUTO_LOG_KEY } else { "log |e|" },
                items: vec![
                    item(Glyph::Dashed, palette::PREDICTED, "the slope ln ρ/δ the linear analysis predicts"),
                    item(
                        Glyph::Line,
                        palette::SWING,
                        "the swing: the flexible pair's amplitude in the error, from the run's state at each sampling \
                         instant while the reference rests (it changes ×|λ| per period)",
                    ),
                    item(Glyph::Line, palette::SPLIT_REST, "the rest of the error, without the swing"),
                ],
                scale: None,
            });
        }
        let velocity = kinds.contains(&PanelKind::Velocity);
        if frame.options.show_measured && !frame.zoomed() && (kinds.contains(&PanelKind::Error1) || velocity) {
            let mut items = if !kinds.contains(&PanelKind::Error1) {
                Vec::new()
            } else if measured_shown(frame) {
                vec![
                    item(
                        Glyph::Line,
                        palette::MEASURED1,
                        "e1 as measured: the encoder's reading of q1 (to the nearest count, plus any noise) minus \
                         the reference, taken at each sampling instant and held over the period — what the \
                         controller sees and integrates",
                    ),
                    item(Glyph::Line, palette::MEASURED2, "e2 as measured, likewise"),
                ]
            } else {
                vec![item(
                    Glyph::Line,
                    palette::ERROR1,
                    "sensors off: the controller reads the true state, so e1, e2 as measured are the errors drawn \
                     (nothing to compare; turn on an encoder, noise or differenced velocities)",
                )]
            };
            if velocity && measured_shown(frame) {
                items.push(item(Glyph::Line, palette::VELOCITY1, "q̇1, link 1's true velocity"));
                items.push(item(
                    Glyph::Line,
                    palette::VELOCITY1_EST,
                    "q̇1 as estimated: what the controller uses for link 1's velocity — the encoder's angle \
                     differenced over one period (filtered if τ_v > 0), held over the period; a count's step over \
                     δ is its noise, clipped to the scale the true velocity sets",
                ));
            }
            groups.push(LegendGroup { title: "What the controller reads", items, scale: None });
        }
        if let Some(l) = torque_limit(frame).filter(|_| kinds.contains(&PanelKind::Torque)) {
            groups.push(LegendGroup {
                title: "Torque limit",
                items: vec![item(
                    Glyph::Dashed,
                    palette::TORQUE_LIMIT,
                    &format!("{}: the motors apply at most this, |T1|, |T2| ≤ L", limit_text(l)),
                )],
                scale: None,
            });
        }
        groups
    }

    fn figure_title(&self, frame: &Frame, kinds: &[PanelKind]) -> String {
        let what = match kinds {
            [PanelKind::Error1, PanelKind::Error2] => "Tracking errors e1, e2",
            [PanelKind::Error1] => "Tracking error e1 (link 1)",
            [PanelKind::Error2] => "Tracking error e2 (link 2)",
            [PanelKind::Velocity] => "Link 1's velocity q̇1, true and as the controller estimated it",
            _ => "Torques T1, T2",
        };
        if kinds == [PanelKind::Velocity] {
            what.to_string()
        } else if frame.options.show_cycle {
            format!("{what}, zoomed on one sampling instant tₙ (Fig. 2.1)")
        } else if frame.options.log_errors {
            format!("{what}, log |e| with the slope ln ρ/δ the analysis predicts")
        } else {
            what.to_string()
        }
    }
}

/// The curves a figure of `kinds` shows and what each is, for its key.
pub fn figure_curves(kinds: &[PanelKind]) -> &'static [(Color, &'static str)] {
    match kinds {
        [PanelKind::Torque] => {
            &[(palette::TORQUE1, "T1, the motor's torque"), (palette::TORQUE2, "T2, joint 2's torque")]
        }
        [PanelKind::Error1] => &[(palette::ERROR1, "e1 = q1 − q_d1, link 1's tracking error")],
        [PanelKind::Error2] => &[(palette::ERROR2, "e2 = q2 − q_d2, link 2's tracking error")],
        // Keyed with the estimate under "What the controller reads".
        [PanelKind::Velocity] => &[],
        _ => &[
            (palette::ERROR1, "e1 = q1 − q_d1, link 1's tracking error"),
            (palette::ERROR2, "e2 = q2 − q_d2, link 2's tracking error"),
        ],
    }
}
