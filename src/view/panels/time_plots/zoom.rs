//! The time plots zoomed on one sampling instant t_n: the paper's Fig. 2.1 drawn from run A's
//! [`Cycle`] (measure at t_n, predict over τ = kε, hold U_k from t_n + δ to t_n + 2δ).
//!
//! Three sampling periods and a quarter on each side: [t_n − 1.25 δ, t_n + 2.25 δ]. The errors'
//! panels show the errors as they were and the predicted errors of X_0 … X_k (a dashed line with a
//! dot per step; X_0 = x(t_n), the state measured, larger); the torque panel shows the torque the
//! controller applied, u = v + K_pr x — steps of the held v —, the predicted U_j (U_1 and U_2, the
//! index-3 DAE's jump to consistency, off the scale at its edge), and U_k, which lands on the
//! torque held one period later. The horizon τ and that hold are shaded across all three panels.

use super::drawing::{draw_background, draw_frame, draw_series, max_abs, PlotFrame};
use super::series::{plot_tick_counts, y_label, CURVE_WIDTH};
use crate::plot::palette;
use crate::schema::PanelKind;
use crate::view::autoscale::Autoscale;
use crate::view::layout::Panel;
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, TickLabel};
use crate::view::panels::contract::{Frame, RunState};
use crate::view::time_window::TimeWindow;

/// Predictions of more steps than this get a line but no dot per step.
pub const MAX_DOTS: usize = 48;
/// The first U_j drawn on the scale: U_1, U_2 are the jump to consistency (hundreds of
/// thousands of N m at small ε).
const FIRST_ON_SCALE: usize = 3;

/// Vertices the zoom adds to one time plot at most: bands, the predicted lines and dots of two
/// series (k ≤ 1000 steps), U_k, the planned hold, chevrons and the tick lines.
pub const ZOOM_VERTEX_BUDGET: usize = 2 * (1001 * 12 + MAX_DOTS * 3 * 32) + 64 * 6 + 12 * 6;

/// The sampling instants in the zoom's window, t_{n−1} … t_{n+2} (the grid and the ticks).
pub fn cycle_ticks(frame: &Frame) -> impl Iterator<Item = f64> + '_ {
    let window = frame.cycle_window();
    let held = &frame.cycle.held;
    held.iter()
        .map(|p| p.start)
        .chain(held.last().map(|p| p.end))
        .filter(move |t| window.is_some_and(|w| *t >= w.start && *t <= w.end))
}

/// The zoom's ticks, at most eight, NaN past the last.
fn cycle_ticks_array(frame: &Frame) -> [f64; 8] {
    let mut out = [f64::NAN; 8];
    for (slot, t) in out.iter_mut().zip(cycle_ticks(frame)) {
        *slot = t;
    }
    out
}

/// The zoom's own scales (e1, e2, the torques), kept between frames.
#[derive(Clone, Debug)]
pub struct Zoom {
    scales: [Autoscale; 3],
}

impl Default for Zoom {
    fn default() -> Self {
        Self { scales: Autoscale::time_plots() }
    }
}

impl Zoom {
    /// Forgets the scales (the simulation restarted).
    pub fn reset(&mut self) {
        for s in &mut self.scales {
            s.reset();
        }
    }

    /// The zoom's half-range for a plot.
    pub fn limit(&self, kind: PanelKind) -> f64 {
        self.scales[zoom_index(kind)].limit()
    }

    /// One time plot of the zoom.
    pub fn draw(&mut self, frame: &Frame, panel: &Panel, window: TimeWindow, a: &RunState<'_>, painter: &mut Painter) {
        let dpr = frame.layout.device_pixel_ratio;
        let rect = frame.layout.to_physical(panel.rect);
        let cycle = &frame.cycle;
        let torque = panel.kind == PanelKind::Torque;
        let series: &[usize] = if torque {
            &[0, 1]
        } else if panel.kind == PanelKind::Error1 {
            &[0]
        } else {
            &[1]
        };
        // The scale: what was and what was predicted, but not the jump to consistency.
        let mut data_max: f64 = 0.0;
        if torque {
            let range = window.indices(&cycle.applied[0]);
            for &i in series {
                data_max = data_max.max(cycle.applied[1 + i].get(range.clone()).map_or(0.0, max_abs));
                for u in cycle.sweep.torques.iter().skip(FIRST_ON_SCALE - 1) {
                    data_max = data_max.max(u[i].abs());
                }
            }
        } else {
            let i = series[0];
            let values = if i == 0 { a.traces.e1() } else { a.traces.e2() };
            data_max = values.get(window.indices(a.traces.t())).map_or(0.0, max_abs);
            for e in &cycle.predicted {
                data_max = data_max.max(e[i].abs());
            }
        }
        let y = self.scales[zoom_index(panel.kind)].update(data_max, frame.time);
        let ticks = cycle_ticks_array(frame);
        let frame = PlotFrame { rect, window, y_lo: -y, y_hi: y, log: false };
        let y_ticks = crate::plot::Ticks::new(-y, y, plot_tick_counts(panel.rect).1);
        draw_background(painter, &frame, ticks.into_iter().filter(|t| t.is_finite()), y_ticks, None, dpr);
        // The horizon τ = kε from t_n and the period U_k is held on, across the panel (translucent:
        // the grid shows through).
        let mut band = |t0: f64, t1: f64, color| {
            let (x0, x1) = (frame.x(t0.max(window.start)), frame.x(t1.min(window.end)));
            if x1 > x0 {
                painter.rect(crate::view::rect::Rect::new(x0, rect.y, x1 - x0, rect.h), color);
            }
        };
        // The errors are what is predicted, the torque what is held: one band each.
        if torque {
            if let Some(hold) = cycle.hold() {
                band(hold.start, hold.end, palette::HOLD_BAND);
            }
        } else {
            band(cycle.instant, cycle.instant + cycle.horizon, palette::HORIZON_BAND);
        }
        // t_n itself, darker.
        let xn = frame.x(cycle.instant);
        painter.line([xn, rect.y], [xn, rect.bottom()], 1.5 * dpr, palette::AXIS);
        let colors = [palette::ERROR1, palette::ERROR2];
        let width = CURVE_WIDTH * dpr;
        let dot = 2.25 * dpr;
        for &i in series {
            let color = colors[i];
            if torque {
                let [t, u1, u2] = &cycle.applied;
                draw_series(painter, &frame, t, if i == 0 { u1 } else { u2 }, width, color);
                // U_j at t_n + jε; the first ones (off the scale) as a chevron at the edge.
                let sweep = &cycle.sweep;
                let mut previous = None;
                for (j, u) in sweep.torques.iter().enumerate() {
                    let p = [frame.x(sweep.time(j + 1)), frame.y(u[i])];
                    if !frame.contains(u[i]) {
                        let up = u[i] > 0.0;
                        let edge = if up { rect.y + 6.0 * dpr } else { rect.bottom() - 6.0 * dpr };
                        painter.chevron([p[0], edge], [0.0, if up { -1.0 } else { 1.0 }], 5.0 * dpr, 1.5 * dpr, color);
                        previous = None;
                        continue;
                    }
                    if let Some(q) = previous {
                        painter.dashed_line(q, p, 1.5 * dpr, 4.0 * dpr, 3.0 * dpr, color);
                    }
                    if sweep.torques.len() <= MAX_DOTS {
                        painter.circle(p, dot, color);
                    }
                    previous = Some(p);
                }
                // U_k: the torque chosen, at t_n + kε — in the middle of the period it is held on.
                if let Some(u) = cycle.chosen_torque() {
                    let p = [frame.x(sweep.time(sweep.torques.len())), frame.y(u[i])];
                    painter.diamond(p, 6.0 * dpr, 2.0 * dpr, palette::PREDICTED);
                    // Not held yet (the run is at t_n): the plan, dashed.
                    if let Some(hold) = cycle.hold().filter(|h| h.start > t.last().copied().unwrap_or(f64::NAN) - 1e-12)
                    {
                        let (a0, a1) = ([frame.x(hold.start), p[1]], [frame.x(hold.end.min(window.end)), p[1]]);
                        painter.dashed_line(a0, a1, 2.0 * dpr, 6.0 * dpr, 4.0 * dpr, palette::PREDICTED);
                    }
                }
            } else {
                let values = if i == 0 { a.traces.e1() } else { a.traces.e2() };
                let t = a.traces.t();
                let m = t.len().min(values.len());
                draw_series(painter, &frame, &t[..m], &values[..m], width, color);
                let sweep = &cycle.sweep;
                let points = cycle.predicted.iter().enumerate().map(|(j, e)| [frame.x(sweep.time(j)), frame.y(e[i])]);
                let mut previous: Option<[f64; 2]> = None;
                for p in points {
                    if let Some(q) = previous {
                        painter.dashed_line(q, p, 1.5 * dpr, 4.0 * dpr, 3.0 * dpr, color);
                    }
                    if cycle.predicted.len() <= MAX_DOTS + 1 {
                        painter.circle(p, dot, color);
                    }
                    previous = Some(p);
                }
                // X_0 = x(t_n): what the controller measured.
                if let Some(e) = cycle.predicted.first() {
                    let p = [frame.x(cycle.instant), frame.y(e[i])];
                    painter.circle(p, 5.0 * dpr, palette::PREDICTED);
                    painter.circle(p, 3.0 * dpr, palette::PANEL);
                }
            }
        }
        draw_frame(painter, &frame, dpr);
    }

    /// A zoomed time plot as the page reads it: ticks at the sampling instants, named after
    /// t_n; the time's unit and δ in the axis title. The labels stay put while the window moves
    /// with t_n (they do not scroll).
    pub fn describe(&self, frame: &Frame, panel: &Panel, window: TimeWindow, info: &mut PanelInfo) {
        let y = self.limit(panel.kind);
        let torque = panel.kind == PanelKind::Torque;
        info.scrolls = false;
        info.x_label = format!("t [s], δ = {} s", crate::plot::format::significant_trimmed(frame.cycle.period, 3));
        info.y_label = if torque { "u1, u2 [N m]" } else { y_label(panel.kind) };
        info.x_range = [window.start, window.end];
        info.y_range = [-y, y];
        info.y_ticks = crate::plot::Ticks::new(-y, y, plot_tick_counts(panel.rect).1).collect();
        let d = frame.cycle.period;
        for t in cycle_ticks(frame) {
            let m = ((t - frame.cycle.instant) / d).round() as i32;
            let text = match m {
                0 => "tₙ".to_string(),
                1 => "tₙ+δ".to_string(),
                -1 => "tₙ−δ".to_string(),
                m if m < 0 => format!("tₙ−{}δ", -m),
                m => format!("tₙ+{m}δ"),
            };
            info.x_ticks.push(t);
            info.x_labels.push(TickLabel { value: t, text });
        }
        // The note sits in the header row, over no data; the jump's sizes are in the caption
        // under the figure (the note would go stale between descriptions).
        info.note = match panel.kind {
            PanelKind::Torque if self.jump_off_scale(frame) => {
                "U₁, U₂ off the scale (sizes in the caption); ◆ Uₖ held from tₙ+δ to tₙ+2δ (green)".into()
            }
            PanelKind::Torque => "◆ Uₖ held from tₙ+δ to tₙ+2δ (green)".into(),
            PanelKind::Error1 => "○ measured at tₙ; dashed: predicted over τ = kε".into(),
            _ => String::new(),
        };
    }

    /// True if the jump to consistency, U₁ or U₂, lies off the torque plot's scale.
    pub fn jump_off_scale(&self, frame: &Frame) -> bool {
        let y = self.limit(PanelKind::Torque);
        frame.cycle.sweep.torques.iter().take(FIRST_ON_SCALE - 1).any(|u| u[0].abs() > y || u[1].abs() > y)
    }
}

/// Which of the zoom's scales a time plot uses: e1, e2, the torques.
fn zoom_index(kind: PanelKind) -> usize {
    match kind {
        PanelKind::Error1 => 0,
        PanelKind::Error2 => 1,
        _ => 2,
    }
}
