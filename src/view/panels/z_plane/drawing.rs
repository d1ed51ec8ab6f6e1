//! The z-plane: the sampled loop's eigenvalues λ themselves against the unit circle — the picture
//! that decides stability (ρ = max |λ| < 1). The δ → 0 pair A4 is drawn where it would sit for
//! this δ, λ = exp(A4 δ), so the student sees the loop's flexible pair next to the limit it tends to.
//!
//! The panel is a window on the plane ([`ZView`]: a centre and a half-size, zoomed and panned by
//! the page, by default around the flexible pair): equal scale on both axes, the longer side
//! showing more. Everything outside the unit circle in view is shaded (|λ| > 1 grows), the disk
//! inside is the panel's colour; at any zoom only the part of the disk and of the circle in view
//! is drawn, cut to the panel ([`clip`]), from a bounded number of vertices.

use super::clip::{clip_segment, fill_clipped, fill_vertices};
use super::view::ZView;
use crate::analysis::StabilityReport;
use crate::plot::{palette, Ticks};
use crate::view::loop_poles::{exp_delta, flexible_pair, size, with_feedback, PoleStyle, MAX_LOOP_POLES};
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;

/// About one Re λ tick per this many CSS px (labels such as "0.98302" need about 55).
const X_TICK_SPACING: f64 = 80.0;
/// About one Im λ tick per this many CSS px.
const Y_TICK_SPACING: f64 = 36.0;
/// Points along the part of the unit circle in view.
const ARC_POINTS: usize = 128;

/// The z-plane's data area and the view shown in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZFrame {
    /// The panel's data area (physical or CSS px).
    pub rect: Rect,
    pub view: ZView,
}

impl ZFrame {
    pub fn new(rect: Rect, view: ZView) -> ZFrame {
        ZFrame { rect, view }
    }

    /// Pixels per unit of λ, the same along both axes.
    pub fn scale(&self) -> f64 {
        self.rect.w.min(self.rect.h).max(1e-9) / (2.0 * self.view.half)
    }

    /// The pixel of λ (not clamped).
    pub fn point(&self, z: [f64; 2]) -> Point {
        let [cx, cy] = self.rect.center();
        let s = self.scale();
        [cx + (z[0] - self.view.center[0]) * s, cy - (z[1] - self.view.center[1]) * s]
    }

    /// The λ at a pixel.
    pub fn value_at(&self, p: Point) -> [f64; 2] {
        let [cx, cy] = self.rect.center();
        let s = self.scale();
        [self.view.center[0] + (p[0] - cx) / s, self.view.center[1] + (cy - p[1]) / s]
    }

    /// The Re λ and Im λ ranges shown.
    pub fn ranges(&self) -> ([f64; 2], [f64; 2]) {
        let r = self.rect;
        let [x0, y1] = self.value_at([r.x, r.y]);
        let [x1, y0] = self.value_at([r.right(), r.bottom()]);
        ([x0, x1], [y0, y1])
    }

    /// True if pixel `p` lies in the data area.
    pub fn contains(&self, p: Point) -> bool {
        let r = self.rect;
        p[0] >= r.x && p[0] <= r.right() && p[1] >= r.y && p[1] <= r.bottom()
    }

    /// Where the marker of λ goes: its pixel if inside the data area, else the nearest point of
    /// the area inset by `margin` and the direction towards λ (a chevron at the edge).
    pub fn marker(&self, z: [f64; 2], margin: f64) -> (Point, Option<Point>) {
        let p = self.point(z);
        if self.contains(p) {
            return (p, None);
        }
        let m = margin.min(self.rect.w / 2.0).min(self.rect.h / 2.0).max(0.0);
        let inner = self.rect.inset(m, m, m, m);
        let c = [p[0].clamp(inner.x, inner.right()), p[1].clamp(inner.y, inner.bottom())];
        (c, Some([p[0] - c[0], p[1] - c[1]]))
    }

    /// The angles θ (of λ = e^{jθ}) between which the unit circle can cross the data area grown
    /// by `grow` px: all of it when the origin is in view, else the wedge the area subtends
    /// from the origin (less than half a turn).
    fn arc_range(&self, grow: f64) -> [f64; 2] {
        let r = self.rect.inset(-grow, -grow, -grow, -grow);
        let o = self.point([0.0, 0.0]);
        if o[0] >= r.x && o[0] <= r.right() && o[1] >= r.y && o[1] <= r.bottom() {
            return [0.0, core::f64::consts::TAU];
        }
        let angle = |p: Point| {
            let z = self.value_at(p);
            z[1].atan2(z[0])
        };
        let mid = angle(r.center());
        let (mut lo, mut hi) = (0.0f64, 0.0f64);
        for corner in [[r.x, r.y], [r.right(), r.y], [r.x, r.bottom()], [r.right(), r.bottom()]] {
            let d = (angle(corner) - mid + core::f64::consts::PI).rem_euclid(core::f64::consts::TAU)
                - core::f64::consts::PI;
            lo = lo.min(d);
            hi = hi.max(d);
        }
        [mid + lo, mid + hi]
    }
}

/// Re λ and Im λ ticks of a z-plane whose data area is `rect_css` (CSS px) showing `view`: a
/// grid line at each, and labels that stay within the panel's sides (a label hanging over the
/// end would run off the canvas or into the next panel's labels); a few more ticks than usual
/// where that leaves fewer than three labels (a projector's large text leaves small axes).
pub fn z_ticks(rect_css: Rect, view: ZView) -> (Ticks, Ticks) {
    let frame = ZFrame::new(rect_css, view);
    let ([x0, x1], [y0, y1]) = frame.ranges();
    let nx = (rect_css.w / X_TICK_SPACING).floor().clamp(2.0, 12.0) as usize;
    let ny = (rect_css.h / Y_TICK_SPACING).floor().clamp(2.0, 12.0) as usize;
    (labelled(x0, x1, nx, rect_css.w, true), labelled(y0, y1, ny, rect_css.h, false))
}

/// True if a tick label `extent` px long (along the axis) centred on `value` lies within the
/// axis of `length` px over `range`.
pub fn label_fits(value: f64, range: [f64; 2], length: f64, extent: f64) -> bool {
    let at = (value - range[0]) / (range[1] - range[0]) * length;
    at - extent / 2.0 >= 0.0 && at + extent / 2.0 <= length
}

/// Ticks over [lo, hi], about `count` intervals, with at least three labels that fit if a few
/// more ticks give them (else two).
fn labelled(lo: f64, hi: f64, count: usize, length: f64, across: bool) -> Ticks {
    let fitting = |t: Ticks| {
        let extent = label_extent(t.step, lo, hi, across);
        t.filter(|&v| label_fits(v, [lo, hi], length, extent)).count()
    };
    let extra = (count + 8).min(16).saturating_sub(count);
    let more = |least: usize| Ticks::first_with(lo, hi, count, extra, |t| fitting(t) >= least);
    more(3).or_else(|| more(2)).unwrap_or(Ticks::new(lo, hi, count))
}

/// A generous estimate of a tick label's length along its axis, CSS px, without writing it:
/// the digits [`crate::plot::format::TickFormat`] would print, a sign and a point (the exact
/// labels are checked again with their text, `scene::info`).
fn label_extent(step: f64, lo: f64, hi: f64, across: bool) -> f64 {
    use crate::view::text_metrics::{font, EM_PER_CHAR, LINE_HEIGHT};
    if !across {
        return font::TICK * LINE_HEIGHT;
    }
    let big = lo.abs().max(hi.abs());
    let decimals = (-(step.log10() + 1e-9).floor()).clamp(0.0, 6.0);
    let whole = if big >= 1.0 { big.log10().floor() + 1.0 } else { 1.0 };
    let digits = if big != 0.0 && !(1e-2..1e5).contains(&big) { 7.0 } else { whole + decimals };
    (digits * EM_PER_CHAR + 0.9 + 0.4) * font::TICK
}

/// An upper bound on the vertices [`draw_zplane_run`] writes for one run.
pub const RUN_VERTEX_BUDGET: usize = MAX_LOOP_POLES * (128 * 3 + 2 * 6 + 18) + 4 * (128 * 6 + 60) + 6;

/// An upper bound on the vertices [`draw_zplane_background`] writes: the shade, the disk, the
/// ring in pieces, the grid (at most 17 lines each way), the axes.
pub const BACKGROUND_VERTEX_BUDGET: usize =
    6 + fill_vertices(ARC_POINTS + 2) + ARC_POINTS * fill_vertices(4) + 6 * (2 * 18 + 2);

/// The background: everything in view outside the unit circle shaded (where |λ| > 1 grows),
/// the disk in the panel's colour, grid lines at the ticks, the axes, and the unit circle
/// emphasised — each only where it crosses the data area.
pub fn draw_zplane_background(painter: &mut Painter, frame: &ZFrame, ticks: (Ticks, Ticks), dpr: f64) {
    let rect = frame.rect;
    painter.rect(rect, palette::UNSTABLE_REGION);
    let o = frame.point([0.0, 0.0]);
    let radius = frame.scale();
    let on_circle = |theta: f64, r: f64| [o[0] + r * theta.cos(), o[1] - r * theta.sin()];
    // The disk: the whole polygon when the origin is in view, else the sector over the wedge.
    let [a0, a1] = frame.arc_range(0.0);
    let full = a1 - a0 >= core::f64::consts::TAU - 1e-12;
    let mut poly = [[0.0; 2]; ARC_POINTS + 2];
    let mut n = 0;
    if !full {
        poly[0] = o;
        n = 1;
    }
    let samples = if full { ARC_POINTS } else { ARC_POINTS + 1 };
    for i in 0..samples {
        poly[n] = on_circle(a0 + (a1 - a0) * i as f64 / ARC_POINTS as f64, radius);
        n += 1;
    }
    fill_clipped(painter, &poly[..n], rect, palette::PANEL);
    let grid = dpr.max(1.0);
    let (x_ticks, y_ticks) = ticks;
    for v in x_ticks {
        let x = frame.point([v, 0.0])[0];
        painter.line([x, rect.y], [x, rect.bottom()], grid, palette::GRID);
    }
    for v in y_ticks {
        let y = frame.point([0.0, v])[1];
        painter.line([rect.x, y], [rect.right(), y], grid, palette::GRID);
    }
    let axis = 1.5 * grid;
    if o[1] >= rect.y && o[1] <= rect.bottom() {
        painter.line([rect.x, o[1]], [rect.right(), o[1]], axis, palette::AXIS);
    }
    if o[0] >= rect.x && o[0] <= rect.right() {
        painter.line([o[0], rect.y], [o[0], rect.bottom()], axis, palette::AXIS);
    }
    // The unit circle: a ring of quads over the arc in view, each cut to the panel.
    let width = 2.5 * dpr;
    let [a0, a1] = frame.arc_range(width);
    let (inner, outer) = ((radius - width / 2.0).max(0.0), radius + width / 2.0);
    let theta = |i: usize| a0 + (a1 - a0) * i as f64 / ARC_POINTS as f64;
    let grown = rect.inset(-width, -width, -width, -width);
    for i in 0..ARC_POINTS {
        let (t0, t1) = (theta(i), theta(i + 1));
        let quad = [on_circle(t0, inner), on_circle(t0, outer), on_circle(t1, outer), on_circle(t1, inner)];
        let near = |p: &Point| p[0] >= grown.x && p[0] <= grown.right() && p[1] >= grown.y && p[1] <= grown.bottom();
        // A piece longer than the panel can cross it with both ends outside: test its segment.
        if quad.iter().any(near) || clip_segment(quad[1], quad[2], grown).is_some() {
            fill_clipped(painter, &quad, rect, palette::UNIT_CIRCLE);
        }
    }
}
/// One run's markers: the halo behind the flexible pair, A4 at exp(A4 δ) (rings without
/// preliminary feedback, diamonds with it), and the loop's λ as × (or +), red outside the circle.
pub fn draw_zplane_run(painter: &mut Painter, frame: &ZFrame, report: &StabilityReport, style: &PoleStyle, dpr: f64) {
    for i in flexible_pair(report).into_iter().flatten() {
        if let (p, None) = frame.marker(report.poles[i].discrete, size::EDGE * dpr) {
            painter.circle(p, size::HALO * dpr, palette::POLE_HALO);
        }
    }
    let delta = report.sampling_period;
    for s in report.limit_pair_open {
        match frame.marker(exp_delta(s, delta), size::EDGE * dpr) {
            (p, None) => painter.ring(p, size::A4_RING * dpr, size::A4_WIDTH * dpr, style.a4_open),
            (p, Some(d)) => painter.chevron(p, d, size::CHEVRON * dpr, 1.5 * dpr, style.a4_open),
        }
    }
    // Without preliminary feedback there is no "A4 with K_pr": the pair is A4 itself.
    for &s in with_feedback(report) {
        match frame.marker(exp_delta(s, delta), size::EDGE * dpr) {
            (p, None) => painter.diamond(p, size::A4_DIAMOND * dpr, size::A4_WIDTH * dpr, style.a4),
            (p, Some(d)) => painter.chevron(p, d, size::CHEVRON * dpr, 1.5 * dpr, style.a4),
        }
    }
    for pole in report.poles.iter().take(MAX_LOOP_POLES) {
        let z = pole.discrete;
        if !(z[0].is_finite() && z[1].is_finite()) {
            continue;
        }
        let color = if z[0].hypot(z[1]) > 1.0 { style.unstable } else { style.stable };
        match frame.marker(z, size::EDGE * dpr) {
            (p, None) if style.plus => painter.plus(p, size::CROSS * 1.2 * dpr, size::CROSS_WIDTH * dpr, color),
            (p, None) => painter.cross(p, size::CROSS * dpr, size::CROSS_WIDTH * dpr, color),
            (p, Some(d)) => painter.chevron(p, d, size::CHEVRON * dpr, size::CROSS_WIDTH * dpr, color),
        }
    }
}

/// Where a marker of λ sits on the page (CSS pixels) and whether it is in view.
pub fn marker_css(frame_css: &ZFrame, z: [f64; 2]) -> (Point, bool) {
    let (p, off) = frame_css.marker(z, size::EDGE);
    (p, off.is_none())
}

/// The flexible pair's upper eigenvalue (Im λ ≥ 0) of a run, if the analysis found the pair.
pub fn upper_flexible(report: &StabilityReport) -> Option<[f64; 2]> {
    flexible_pair(report)
        .into_iter()
        .flatten()
        .map(|i| report.poles[i].discrete)
        .find(|z| z[1] >= 0.0 && z[0].is_finite() && z[1].is_finite())
}

/// |λ| − 1 of an eigenvalue as a mark says it, signed: "|λ| − 1 = +0.0239" (how far outside
/// the circle, positive: it grows; negative: inside, it decays).
pub fn gap_text(z: [f64; 2]) -> String {
    let gap = z[0].hypot(z[1]) - 1.0;
    let sign = if gap > 0.0 { "+" } else { "" };
    format!("|λ| − 1 = {sign}{}", crate::plot::format::significant(gap, 3))
}

/// The radial tick from the unit circle to `z` (run A's flexible pair): the distance |λ| − 1
/// the mark names, drawn where it is in view.
pub fn draw_radial_tick(painter: &mut Painter, frame: &ZFrame, z: [f64; 2], dpr: f64) {
    let r = z[0].hypot(z[1]);
    if !(r > 0.0 && r.is_finite()) {
        return;
    }
    let a = frame.point([z[0] / r, z[1] / r]);
    let b = frame.point(z);
    if let Some((a, b)) = clip_segment(a, b, frame.rect) {
        painter.line(a, b, 1.5 * dpr, palette::AXIS);
    }
}
