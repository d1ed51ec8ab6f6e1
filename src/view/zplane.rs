//! The z-plane: the sampled loop's eigenvalues λ themselves against the unit circle — the picture
//! that decides stability (ρ = max |λ| < 1). The δ → 0 pair A4 is drawn where it would sit for
//! this δ, λ = exp(A4 δ), so the student sees the loop's flexible pair next to the limit it tends to.

use super::layout::Rect;
use super::markers::{flexible_pair, size, with_feedback, PoleStyle, MAX_LOOP_POLES};
use super::painter::{Painter, Point};
use crate::analysis::StabilityReport;
use crate::plot::palette;

/// The half-width of the square region shown: the unit circle and a margin beyond it.
pub const Z_RANGE: f64 = 1.3;

/// The z-plane's data area: the largest centred square of a rectangle, mapping
/// [−Z_RANGE, Z_RANGE]² onto it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZFrame {
    /// The panel's data area.
    pub rect: Rect,
    /// The square drawn in.
    pub square: Rect,
}

impl ZFrame {
    pub fn new(rect: Rect) -> ZFrame {
        let side = rect.w.min(rect.h).max(0.0);
        let square = Rect::new(rect.x + (rect.w - side) / 2.0, rect.y + (rect.h - side) / 2.0, side, side);
        ZFrame { rect, square }
    }

    /// Pixels per unit of λ.
    pub fn scale(&self) -> f64 {
        self.square.w / (2.0 * Z_RANGE)
    }

    /// The pixel of λ (not clamped).
    pub fn point(&self, z: [f64; 2]) -> Point {
        let [cx, cy] = self.square.center();
        [cx + z[0] * self.scale(), cy - z[1] * self.scale()]
    }

    /// The λ at a pixel.
    pub fn value_at(&self, p: Point) -> [f64; 2] {
        let [cx, cy] = self.square.center();
        [(p[0] - cx) / self.scale(), (cy - p[1]) / self.scale()]
    }

    /// Where the marker of λ goes: its pixel if inside the square (inset by `margin`), else the
    /// nearest point of the inset square and the direction towards λ.
    pub fn marker(&self, z: [f64; 2], margin: f64) -> (Point, Option<Point>) {
        let p = self.point(z);
        if z[0].abs() <= Z_RANGE && z[1].abs() <= Z_RANGE {
            return (p, None);
        }
        let m = margin.min(self.square.w / 2.0).max(0.0);
        let inner = self.square.inset(m, m, m, m);
        let c = [p[0].clamp(inner.x, inner.right()), p[1].clamp(inner.y, inner.bottom())];
        (c, Some([p[0] - c[0], p[1] - c[1]]))
    }
}

/// λ = exp(s δ) for a continuous-time s.
pub fn exp_delta(s: [f64; 2], delta: f64) -> [f64; 2] {
    let r = (s[0] * delta).exp();
    [r * (s[1] * delta).cos(), r * (s[1] * delta).sin()]
}

/// An upper bound on the vertices [`draw_zplane_run`] writes for one run.
pub const RUN_VERTEX_BUDGET: usize = MAX_LOOP_POLES * (128 * 3 + 2 * 6 + 18) + 4 * (128 * 6 + 60);

/// The background: panel tinted outside the unit circle (where |λ| > 1 grows), grid lines at
/// ±1 and ±½, the axes, and the unit circle emphasised.
pub fn draw_zplane_background(painter: &mut Painter, frame: &ZFrame, dpr: f64) {
    // All of the plane outside the circle is unstable, not only the square around it.
    painter.rect(frame.rect, palette::UNSTABLE_REGION);
    let c = frame.point([0.0, 0.0]);
    painter.circle(c, frame.scale(), palette::PANEL);
    let grid = dpr.max(1.0);
    let s = frame.square;
    for v in [-1.0, -0.5, 0.5, 1.0] {
        let x = frame.point([v, 0.0])[0];
        let y = frame.point([0.0, v])[1];
        painter.line([x, s.y], [x, s.bottom()], grid, palette::GRID);
        painter.line([s.x, y], [s.right(), y], grid, palette::GRID);
    }
    painter.line([s.x, c[1]], [s.right(), c[1]], 1.5 * grid, palette::AXIS);
    painter.line([c[0], s.y], [c[0], s.bottom()], 1.5 * grid, palette::AXIS);
    painter.ring(c, frame.scale(), 2.5 * dpr, palette::UNIT_CIRCLE);
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
