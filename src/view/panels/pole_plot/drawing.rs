//! The pole plot: the sampled closed loop's eigenvalues as continuous-time equivalents
//! s = ln λ / δ, the imaginary axis that separates stable from unstable, and the δ → 0 pair A4
//! without and with the preliminary feedback — the picture of *why* small δ goes unstable.
//!
//! The analysis comes from the session, which computes it once per change that matters; drawing
//! the ten poles and four A4 markers per frame is cheap.

use crate::analysis::StabilityReport;
use crate::plot::palette;
use crate::view::loop_poles::{
    flexible_pair, nyquist, size, with_feedback, PoleStyle, IM_RANGE, MAX_LOOP_POLES, RE_RANGE,
};
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;

/// The Im s range that shows the flexible pairs of `reports` — their δ → 0 limits with and
/// without K_pr, a quarter beyond — in steps of 20 rad/s, at least [`IM_RANGE`].
pub fn im_range<'a>(reports: impl IntoIterator<Item = &'a StabilityReport>) -> [f64; 2] {
    let fastest = reports
        .into_iter()
        .flat_map(|r| [r.limit_pair_open[0][1], r.limit_pair[0][1]])
        .filter(|w| w.is_finite())
        .fold(0.0f64, |m, w| m.max(w.abs()));
    let half = (1.25 * fastest / 20.0).ceil() * 20.0;
    let half = half.clamp(IM_RANGE[1], 400.0);
    [-half, half]
}

/// The pole plot's data area in physical pixels and the s-plane region mapped onto it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoleFrame {
    pub rect: Rect,
    pub re: [f64; 2],
    pub im: [f64; 2],
}

impl PoleFrame {
    /// The default view on a data area.
    pub fn new(rect: Rect) -> PoleFrame {
        PoleFrame { rect, re: RE_RANGE, im: IM_RANGE }
    }

    /// The default view, its Im s range widened to show these analyses' flexible pairs (a
    /// stiffer spring or a lighter motor swings faster than ±40 rad/s).
    pub fn fitting<'a>(rect: Rect, reports: impl IntoIterator<Item = &'a StabilityReport>) -> PoleFrame {
        PoleFrame { rect, re: RE_RANGE, im: im_range(reports) }
    }

    /// Horizontal pixel of Re s (not clamped).
    pub fn x(&self, re: f64) -> f64 {
        self.rect.x + self.rect.w * (re - self.re[0]) / (self.re[1] - self.re[0])
    }

    /// Vertical pixel of Im s (not clamped).
    pub fn y(&self, im: f64) -> f64 {
        self.rect.bottom() - self.rect.h * (im - self.im[0]) / (self.im[1] - self.im[0])
    }

    /// The s = (Re, Im) at a pixel (not clamped): the inverse of [`Self::x`], [`Self::y`].
    pub fn s_at(&self, x: f64, y: f64) -> [f64; 2] {
        let re = self.re[0] + (x - self.rect.x) / self.rect.w * (self.re[1] - self.re[0]);
        let im = self.im[0] + (self.rect.bottom() - y) / self.rect.h * (self.im[1] - self.im[0]);
        [re, im]
    }

    /// Where the marker of s goes: its pixel if inside the view (inset by `margin` pixels), else
    /// the nearest point of the inset view and the direction towards s.
    pub fn marker(&self, s: [f64; 2], margin: f64) -> (Point, Option<Point>) {
        let p = [self.x(s[0]), self.y(s[1])];
        let inside = s[0] >= self.re[0] && s[0] <= self.re[1] && s[1] >= self.im[0] && s[1] <= self.im[1];
        if inside {
            return (p, None);
        }
        let m = margin.min(self.rect.w / 2.0).min(self.rect.h / 2.0).max(0.0);
        let inner = self.rect.inset(m, m, m, m);
        let c = [p[0].clamp(inner.x, inner.right()), p[1].clamp(inner.y, inner.bottom())];
        let dir = [p[0] - c[0], p[1] - c[1]];
        (c, Some(dir))
    }
}

/// An upper bound on the vertices [`draw_flexible_halo`], [`draw_a4`] and [`draw_poles`] write
/// for one run (circles ≤ 128 segments).
pub const RUN_VERTEX_BUDGET: usize = MAX_LOOP_POLES * (128 * 3 + 2 * 6 + 18) + 4 * (128 * 6 + 60);

/// The background of the pole plot: panel, the unstable half-plane tinted, grid lines at the
/// ticks, the real axis and — emphasised — the imaginary axis Re s = 0.
pub fn draw_pole_background(
    painter: &mut Painter,
    frame: &PoleFrame,
    x_ticks: impl Iterator<Item = f64>,
    y_ticks: impl Iterator<Item = f64>,
    dpr: f64,
) {
    let r = frame.rect;
    painter.rect(r, palette::PANEL);
    let x0 = frame.x(0.0).clamp(r.x, r.right());
    if x0 < r.right() {
        painter.rect(Rect::new(x0, r.y, r.right() - x0, r.h), palette::UNSTABLE_REGION);
    }
    let grid = dpr.max(1.0);
    for re in x_ticks {
        let x = frame.x(re);
        painter.line([x, r.y], [x, r.bottom()], grid, palette::GRID);
    }
    for im in y_ticks {
        let y = frame.y(im);
        painter.line([r.x, y], [r.right(), y], grid, palette::GRID);
    }
    if frame.im[0] < 0.0 && frame.im[1] > 0.0 {
        let y = frame.y(0.0);
        painter.line([r.x, y], [r.right(), y], 1.5 * grid, palette::AXIS);
    }
    if frame.re[0] < 0.0 && frame.re[1] > 0.0 {
        painter.line([x0, r.y], [x0, r.bottom()], 2.5 * dpr, palette::IMAGINARY_AXIS);
    }
}

/// The δ → 0 pair A4 of one run: rings without preliminary feedback, diamonds with it.
pub fn draw_a4(painter: &mut Painter, frame: &PoleFrame, report: &StabilityReport, style: &PoleStyle, dpr: f64) {
    for s in report.limit_pair_open {
        match frame.marker(s, size::EDGE * dpr) {
            (p, None) => painter.ring(p, size::A4_RING * dpr, size::A4_WIDTH * dpr, style.a4_open),
            (p, Some(d)) => painter.chevron(p, d, size::CHEVRON * dpr, 1.5 * dpr, style.a4_open),
        }
    }
    // Without preliminary feedback there is no "A4 with K_pr": the pair is A4 itself.
    for &s in with_feedback(report) {
        match frame.marker(s, size::EDGE * dpr) {
            (p, None) => painter.diamond(p, size::A4_DIAMOND * dpr, size::A4_WIDTH * dpr, style.a4),
            (p, Some(d)) => painter.chevron(p, d, size::CHEVRON * dpr, 1.5 * dpr, style.a4),
        }
    }
}

/// The amber halo behind the flexible pair of one run (drawn first, under the A4 markers).
pub fn draw_flexible_halo(painter: &mut Painter, frame: &PoleFrame, report: &StabilityReport, dpr: f64) {
    for i in flexible_pair(report).into_iter().flatten() {
        let Some(s) = report.poles[i].continuous else { continue };
        if let (p, None) = frame.marker(s, size::EDGE * dpr) {
            painter.circle(p, size::HALO * dpr, palette::POLE_HALO);
        }
    }
}

/// The loop poles of one run: × (or +) markers coloured by stability, poles outside the view as
/// chevrons at the edge. Poles with λ = 0 are skipped.
pub fn draw_poles(painter: &mut Painter, frame: &PoleFrame, report: &StabilityReport, style: &PoleStyle, dpr: f64) {
    for pole in report.poles.iter().take(MAX_LOOP_POLES) {
        let Some(s) = pole.continuous else { continue };
        if !(s[0].is_finite() && s[1].is_finite()) {
            continue;
        }
        let color = if s[0] > 0.0 { style.unstable } else { style.stable };
        match frame.marker(s, size::EDGE * dpr) {
            (p, None) => {
                if style.plus {
                    painter.plus(p, size::CROSS * 1.2 * dpr, size::CROSS_WIDTH * dpr, color);
                } else {
                    painter.cross(p, size::CROSS * dpr, size::CROSS_WIDTH * dpr, color);
                }
            }
            (p, Some(d)) => painter.chevron(p, d, size::CHEVRON * dpr, size::CROSS_WIDTH * dpr, color),
        }
    }
}

/// The dashed lines Im s = ±π/δ (where they fall inside the view).
pub fn draw_nyquist(painter: &mut Painter, frame: &PoleFrame, delta: f64, dpr: f64) {
    let w = nyquist(delta);
    let r = frame.rect;
    for im in [w, -w] {
        if im > frame.im[0] && im < frame.im[1] {
            let y = frame.y(im);
            painter.dashed_line([r.x, y], [r.right(), y], 1.5 * dpr, 5.0 * dpr, 4.0 * dpr, palette::NYQUIST);
        }
    }
}
