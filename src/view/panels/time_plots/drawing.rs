//! Time plots: a scrolling window [t − W, t], grid, zero line, shading while the reference
//! moves, and curves decimated to at most two vertices per pixel column.

use crate::model::reference::Reference;
use crate::plot::{palette, Color};
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;
use crate::view::time_window::TimeWindow;

/// An upper bound on the vertices one plot `width_px` physical pixels wide writes with
/// `series` curves and at most `ticks` grid lines: ≤ 2 points per column per curve (6 vertices
/// per segment), shading runs, grid, zero line, background and frame.
pub fn vertex_budget(width_px: f64, series: usize, ticks: usize) -> usize {
    let columns = if width_px.is_finite() { width_px.ceil().max(1.0) as usize } else { 1 };
    let curves = series * (2 * columns + 1) * 6;
    let shading = (columns / 2 + 1) * 6;
    let lines = (ticks + 1) * 6;
    curves + shading + lines + 6 + 24
}

/// The largest finite |v| of the slice (0 if there is none).
pub fn max_abs(values: &[f64]) -> f64 {
    values.iter().filter(|v| v.is_finite()).fold(0.0, |m, v| m.max(v.abs()))
}

/// A plot's data area in physical pixels and the data ranges mapped onto it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlotFrame {
    pub rect: Rect,
    pub window: TimeWindow,
    /// Values from y_lo (bottom edge) to y_hi (top edge).
    pub y_lo: f64,
    pub y_hi: f64,
    /// The plot shows log |v| (then 0 < y_lo < y_hi).
    pub log: bool,
}

impl PlotFrame {
    /// Horizontal pixel of time `t`.
    pub fn x(&self, t: f64) -> f64 {
        self.rect.x + self.rect.w * (t - self.window.start) / self.window.width()
    }

    /// Vertical pixel of value `v`, clamped to the data area (of |v| on a log plot; 0 sits at
    /// the bottom edge).
    pub fn y(&self, v: f64) -> f64 {
        let f = if self.log {
            (v.abs() / self.y_lo).ln() / (self.y_hi / self.y_lo).ln()
        } else {
            (v - self.y_lo) / (self.y_hi - self.y_lo)
        };
        let y = self.rect.bottom() - self.rect.h * f;
        if y.is_nan() {
            self.rect.bottom()
        } else {
            y.clamp(self.rect.y, self.rect.bottom())
        }
    }

    /// True if `v` lies within the plot's value range (|v| on a log plot).
    pub fn contains(&self, v: f64) -> bool {
        let v = if self.log { v.abs() } else { v };
        v >= self.y_lo && v <= self.y_hi
    }

    /// Time at horizontal pixel `x`.
    fn time_at(&self, x: f64) -> f64 {
        self.window.start + self.window.width() * (x - self.rect.x) / self.rect.w
    }
}

/// The plot background, the shading where the reference moves, grid lines at the ticks and the
/// zero line. `x_ticks`, `y_ticks` give the tick positions; `dpr` sets the line widths.
pub fn draw_background(
    painter: &mut Painter,
    frame: &PlotFrame,
    x_ticks: impl Iterator<Item = f64>,
    y_ticks: impl Iterator<Item = f64>,
    reference: Option<&Reference>,
    dpr: f64,
) {
    painter.rect(frame.rect, palette::PANEL);
    if let Some(reference) = reference {
        shade_motion(painter, frame, reference);
    }
    let r = frame.rect;
    let grid = dpr.max(1.0);
    for t in x_ticks {
        let x = frame.x(t);
        painter.line([x, r.y], [x, r.bottom()], grid, palette::GRID);
    }
    for v in y_ticks {
        let y = frame.y(v);
        painter.line([r.x, y], [r.right(), y], grid, palette::GRID);
    }
    if !frame.log && frame.y_lo < 0.0 && frame.y_hi > 0.0 {
        let y = frame.y(0.0);
        painter.line([r.x, y], [r.right(), y], 1.5 * grid, palette::AXIS);
    }
}

/// Shades the pixel columns where the reference is moving (cheap: one test per column).
fn shade_motion(painter: &mut Painter, frame: &PlotFrame, reference: &Reference) {
    let r = frame.rect;
    let columns = r.w.ceil().max(0.0) as usize;
    let mut run_start: Option<f64> = None;
    for c in 0..=columns {
        let x = r.x + c as f64;
        let moving = c < columns && reference.is_moving(frame.time_at(x + 0.5));
        match (moving, run_start) {
            (true, None) => run_start = Some(x),
            (false, Some(x0)) => {
                let x1 = x.min(r.right());
                painter.rect(Rect::new(x0, r.y, x1 - x0, r.h), palette::MOTION);
                run_start = None;
            }
            _ => {}
        }
    }
}

/// The frame line around a plot, drawn last so curves at the edge stay tidy.
pub fn draw_frame(painter: &mut Painter, frame: &PlotFrame, dpr: f64) {
    painter.rect_outline(frame.rect, dpr.max(1.0), palette::FRAME);
}

/// Draws `values` against `times` (equal lengths, times sorted) over the frame's window.
///
/// With more samples than two per pixel column, each column is reduced to its minimum and
/// maximum in the order they occur, so spikes survive and a 10 000-sample window costs no
/// more than the plot is wide. Non-finite samples leave a gap.
pub fn draw_series(painter: &mut Painter, frame: &PlotFrame, times: &[f64], values: &[f64], width: f64, color: Color) {
    series(painter, frame, times, values, width, color, None);
}

/// Like [`draw_series`], but every value held within the plot's range, the stroke's half width
/// inside its top and bottom edges: a curve far noisier than the scale (a differenced velocity)
/// runs along the edges instead of off the panel. True if any sample in the window was held.
pub fn draw_series_clamped(
    painter: &mut Painter,
    frame: &PlotFrame,
    times: &[f64],
    values: &[f64],
    width: f64,
    color: Color,
) -> bool {
    // The stroke's half width in the data's unit, so that its edges stay inside the frame.
    let margin =
        (0.5 * width / frame.rect.h.max(1e-9) * (frame.y_hi - frame.y_lo)).min(0.5 * (frame.y_hi - frame.y_lo));
    series(painter, frame, times, values, width, color, Some([frame.y_lo + margin, frame.y_hi - margin]))
}

/// How many plot ranges beyond an edge a clipped curve may go before it is no longer followed
/// ([`draw_series_within`]).
const FAR: f64 = 10.0;

/// Like [`draw_series`], but clipped at the plot's top and bottom edges instead of running along
/// them: each segment between two samples is cut where it crosses an edge, so a piece that leaves
/// the range ends exactly on the edge and nothing is drawn while the curve is outside — nor where
/// it jumps from beyond one edge to beyond the other between two samples — and not at all from the
/// first sample [`FAR`] ranges beyond an edge on (a diverged run). For a faint comparison curve (the
/// previous run) that must not look like data at the limit.
pub fn draw_series_within(
    painter: &mut Painter,
    frame: &PlotFrame,
    times: &[f64],
    values: &[f64],
    width: f64,
    color: Color,
) {
    let n = times.len().min(values.len());
    let range = frame.window.indices(&times[..n]);
    let columns = frame.rect.w.ceil().max(1.0) as usize;
    // A piece's start on an edge adds a point: as they are, at most one sample per column, so that
    // the frame's reserve of two points per column holds.
    let dense = range.len() > columns;
    // The plot's own coordinate, where a piece of the curve is straight on screen: v, or ln |v| on
    // a log plot (zero floored far below the range, so that the arithmetic stays finite).
    let (lo, hi) = if frame.log { (frame.y_lo.ln(), frame.y_hi.ln()) } else { (frame.y_lo, frame.y_hi) };
    let coord = |v: f64| if frame.log { v.abs().ln().max(lo - 50.0) } else { v };
    let value = |c: f64| if frame.log { c.exp() } else { c };
    let mut feed = Feed { stroke: painter.stroke(width, color, false), frame, columns, dense, column: None };
    let mut prev: Option<(f64, f64)> = None;
    // The stroke ends at the previous sample (it was inside).
    let mut open = false;
    for i in range {
        let (t, v) = (times[i], values[i]);
        if !(t.is_finite() && v.is_finite()) {
            feed.lift();
            (prev, open) = (None, false);
            continue;
        }
        let c = coord(v);
        // A curve that has left the plot by ten ranges is not followed further: a run diverging
        // at hundreds of times the scale would cross it at every swing in near-vertical strokes,
        // a grey comb over the data.
        if !frame.log && (c > hi + FAR * (hi - lo) || c < lo - FAR * (hi - lo)) {
            break;
        }
        match prev {
            Some((t0, c0)) => {
                // The part of the segment c0 → c inside [lo, hi], as fractions f0 ≤ f1 of it.
                let d = c - c0;
                let (f0, f1) = if d == 0.0 {
                    if (lo..=hi).contains(&c) {
                        (0.0, 1.0)
                    } else {
                        (1.0, 0.0)
                    }
                } else {
                    let (a, b) = ((lo - c0) / d, (hi - c0) / d);
                    (a.min(b).max(0.0), a.max(b).min(1.0))
                };
                // A segment that jumps right across the range (no sample inside: a diverged run's
                // swings of hundreds of radians) would draw a stray stroke from edge to edge.
                let across = f0 > 0.0 && f1 < 1.0;
                if f0 <= f1 && !across {
                    // Where it enters and leaves: a sample, or the edge it crosses.
                    let start = if f0 <= 0.0 {
                        c0
                    } else if c0 < lo {
                        lo
                    } else {
                        hi
                    };
                    let end = if f1 >= 1.0 {
                        c
                    } else if c > hi {
                        hi
                    } else {
                        lo
                    };
                    if !(open && f0 <= 0.0) {
                        feed.lift();
                        feed.to(t0 + f0 * (t - t0), value(start));
                    }
                    feed.to(t0 + f1 * (t - t0), value(end));
                    open = f1 >= 1.0;
                    if !open {
                        feed.lift();
                    }
                } else {
                    open = false;
                }
            }
            None if (lo..=hi).contains(&c) => {
                feed.to(t, v);
                open = true;
            }
            None => open = false,
        }
        prev = Some((t, c));
    }
    feed.lift();
}

/// Points on their way to a stroke: as they are, or, with more samples than two per pixel column,
/// reduced to each column's extremes: the one reduction both draw_series and draw_series_within use.
struct Feed<'a, 'p> {
    stroke: crate::view::painter::Stroke<'p>,
    frame: &'a PlotFrame,
    columns: usize,
    dense: bool,
    column: Option<ColumnExtremes>,
}

impl Feed<'_, '_> {
    fn to(&mut self, t: f64, v: f64) {
        if !self.dense {
            self.stroke.to(point(self.frame, t, v));
            return;
        }
        let v = if self.frame.log { v.abs() } else { v };
        let x = (self.frame.x(t) - self.frame.rect.x).floor().clamp(0.0, (self.columns - 1) as f64) as usize;
        match &mut self.column {
            Some(c) if c.index == x => c.add(v),
            _ => {
                self.flush();
                self.column = Some(ColumnExtremes::new(x, v));
            }
        }
    }

    fn flush(&mut self) {
        if let Some(c) = self.column.take() {
            let stroke = &mut self.stroke;
            c.emit(self.frame, &mut |p| stroke.to(p));
        }
    }

    fn lift(&mut self) {
        self.flush();
        self.stroke.lift();
    }
}

/// The series over the frame's window, each value held within `hold` if given; true if any
/// sample in the window lay outside the plot's range there.
fn series(
    painter: &mut Painter,
    frame: &PlotFrame,
    times: &[f64],
    values: &[f64],
    width: f64,
    color: Color,
    hold: Option<[f64; 2]>,
) -> bool {
    let n = times.len().min(values.len());
    let range = frame.window.indices(&times[..n]);
    let columns = frame.rect.w.ceil().max(1.0) as usize;
    let dense = range.len() > 2 * columns;
    let mut held = false;
    let mut feed = Feed { stroke: painter.stroke(width, color, false), frame, columns, dense, column: None };
    for i in range {
        let (t, v) = (times[i], values[i]);
        if !v.is_finite() {
            feed.lift();
        } else if let Some([lo, hi]) = hold {
            held |= v < frame.y_lo || v > frame.y_hi;
            feed.to(t, v.clamp(lo, hi));
        } else {
            feed.to(t, v);
        }
    }
    feed.lift();
    held
}

fn point(frame: &PlotFrame, t: f64, v: f64) -> Point {
    if v.is_finite() {
        [frame.x(t), frame.y(v)]
    } else {
        [f64::NAN, f64::NAN]
    }
}

/// The extremes of the samples that fall into one pixel column.
struct ColumnExtremes {
    index: usize,
    min: f64,
    max: f64,
    /// True if the minimum came before the maximum.
    min_first: bool,
}

impl ColumnExtremes {
    fn new(index: usize, v: f64) -> Self {
        Self { index, min: v, max: v, min_first: true }
    }

    fn add(&mut self, v: f64) {
        if v < self.min {
            self.min = v;
            self.min_first = false;
        } else if v > self.max {
            self.max = v;
            self.min_first = true;
        }
    }

    /// One or two points at the column centre, in the order the extremes occurred.
    fn emit(&self, frame: &PlotFrame, to: &mut impl FnMut(Point)) {
        let x = frame.rect.x + self.index as f64 + 0.5;
        let (a, b) = if self.min_first { (self.min, self.max) } else { (self.max, self.min) };
        to([x, frame.y(a)]);
        if b != a {
            to([x, frame.y(b)]);
        }
    }
}
