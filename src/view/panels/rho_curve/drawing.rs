//! ρ(δ) at the current α: the spectral radius (or, under [`Measure::Rate`], the rate ln ρ/δ)
//! against the sampling period, with the stable windows (ρ < 1 ⇔ ln ρ/δ < 0) shaded and the
//! current δ marked — the horizontal slice of the stability map, readable as a curve. Clicking or
//! dragging on it picks δ.

use crate::analysis::lag::LagLaw;
use crate::analysis::{StabilityReport, StableWindows};
use crate::control::config::{PreliminaryFeedbackChoice, SimulationConfig};
use crate::plot::color::Measure;
use crate::plot::ticks::log_ticks;
use crate::plot::{palette, Color, Ticks};
use crate::view::delta_axis::DeltaAxis;
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;

/// ρ shown at least over this range; widened to the data (within [0, 2]).
pub const RHO_RANGE_MIN: [f64; 2] = [0.9, 1.1];
/// ln ρ/δ shown at least over this range, 1/s; widened to the data in whole 1/s (within
/// ± [`RATE_RANGE_MAX`]).
pub const RATE_RANGE_MIN: [f64; 2] = [-1.0, 1.0];
/// ln ρ/δ beyond ± this (1/s) runs along the panel's edge: over the page's 10-s window even
/// 1 1/s is a factor e^10, so a wider axis would only flatten the curve near 0, where it matters.
pub const RATE_RANGE_MAX: f64 = 20.0;

/// The ρ(δ) panel's data area with a logarithmic δ axis and a linear axis of ρ or ln ρ/δ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RhoFrame {
    pub rect: Rect,
    /// δ at the left and right edges, s.
    pub x_range: [f64; 2],
    /// ρ (or ln ρ/δ, 1/s) at the bottom and top edges.
    pub y_range: [f64; 2],
}

impl RhoFrame {
    /// The δ axis, shared with the sensor study's panels.
    pub fn axis(&self) -> DeltaAxis {
        DeltaAxis { rect: self.rect, range: self.x_range }
    }

    /// Horizontal pixel of δ (not clamped).
    pub fn x(&self, delta: f64) -> f64 {
        self.axis().x(delta)
    }

    /// Vertical pixel of a value (ρ or ln ρ/δ), clamped to the data area.
    pub fn y(&self, v: f64) -> f64 {
        let [a, b] = self.y_range;
        (self.rect.bottom() - self.rect.h * (v - a) / (b - a)).clamp(self.rect.y, self.rect.bottom())
    }

    /// δ at horizontal pixel `x`, within the range.
    pub fn delta_at(&self, x: f64) -> f64 {
        self.axis().delta_at(x)
    }
}

/// The range to show for a scan: for ρ at least [`RHO_RANGE_MIN`], out to the data in steps of
/// 0.1, never beyond [0, 2]; for ln ρ/δ at least [`RATE_RANGE_MIN`], out to the data in whole
/// 1/s, never beyond ± [`RATE_RANGE_MAX`].
pub fn curve_range(windows: Option<&StableWindows>, measure: Measure) -> [f64; 2] {
    // Steps per unit: tenths of ρ, whole 1/s.
    let (per_unit, [mut lo, mut hi], [min, max]) = match measure {
        Measure::Rho => (10.0, RHO_RANGE_MIN, [0.0, 2.0]),
        Measure::Rate => (1.0, RATE_RANGE_MIN, [-RATE_RANGE_MAX, RATE_RANGE_MAX]),
    };
    for [d, r] in windows.map_or(&[][..], |w| &w.scan[..]) {
        let v = measure.value(*r, *d);
        if v.is_finite() {
            lo = lo.min((v * per_unit).floor() / per_unit);
            hi = hi.max((v * per_unit).ceil() / per_unit);
        }
    }
    [lo.max(min), hi.min(max)]
}

/// The δ and value ticks of a panel whose data area is `rect_css` (CSS pixels).
pub fn rho_ticks(rect_css: Rect, frame: &RhoFrame) -> (Vec<f64>, Vec<f64>) {
    let nx = (rect_css.w / 46.0).floor().clamp(1.0, 20.0) as usize;
    let ny = (rect_css.h / 26.0).floor().clamp(2.0, 10.0) as usize;
    (
        log_ticks(frame.x_range[0], frame.x_range[1], nx),
        Ticks::at_least(frame.y_range[0], frame.y_range[1], ny, 3).collect(),
    )
}

/// The second axis along the top: where the swing turns ωδ = π/8, π/4, …, 8π radians per period
/// (ω = |Im A4|), as (δ, label) inside `x_range`. 2π is one whole swing per period.
pub fn turn_ticks(omega: f64, x_range: [f64; 2]) -> impl Iterator<Item = (f64, &'static str)> {
    const TURNS: [(f64, &str); 7] =
        [(0.125, "π/8"), (0.25, "π/4"), (0.5, "π/2"), (1.0, "π"), (2.0, "2π"), (4.0, "4π"), (8.0, "8π")];
    TURNS.into_iter().filter_map(move |(f, text)| {
        let delta = f * core::f64::consts::PI / omega;
        (omega > 0.0 && delta >= x_range[0] && delta <= x_range[1]).then_some((delta, text))
    })
}

/// ω = |Im A4| of run A, rad/s, for the second axis (None without an analysis).
pub fn turn_omega(report: Option<&StabilityReport>) -> Option<f64> {
    report.map(|r| LagLaw::of(r).omega).filter(|w| *w > 0.0 && w.is_finite())
}

/// The lag law's window of δ for a run without preliminary feedback (what the law explains: the
/// controller alone); `None` with one, without an analysis, or where no window is needed.
pub fn lag_band(config: Option<&SimulationConfig>, report: Option<&StabilityReport>) -> Option<[f64; 2]> {
    let off = config?.preliminary_feedback == PreliminaryFeedbackChoice::Off;
    off.then(|| LagLaw::of(report?).window()).flatten()
}

/// The static part: background, the windows shaded, grid lines, the border of stability (ρ = 1
/// or ln ρ/δ = 0), the curve of `measure`, and along the top the lag law's window (`lag`) and the
/// ticks of the ωδ axis (`omega`, [`turn_ticks`]).
/// Allocates nothing itself, but is drawn only when the windows or the layout change.
pub fn draw_rho_static(
    painter: &mut Painter,
    frame: &RhoFrame,
    windows: Option<&StableWindows>,
    lag: Option<[f64; 2]>,
    omega: Option<f64>,
    ticks: (&[f64], &[f64]),
    measure: Measure,
    dpr: f64,
) {
    let r = frame.rect;
    painter.rect(r, palette::PANEL);
    let Some(w) = windows else { return };
    for [lo, hi] in &w.windows {
        let (x0, x1) = (frame.x(*lo).max(r.x), frame.x(*hi).min(r.right()));
        if x1 > x0 {
            painter.rect(Rect::new(x0, r.y, x1 - x0, r.h), palette::WINDOW_BAND);
        }
    }
    frame.axis().draw_grid(painter, ticks.0, ticks.1.iter().map(|&v| frame.y(v)), dpr);
    let y1 = frame.y(measure.border());
    painter.line([r.x, y1], [r.right(), y1], 1.5 * dpr, palette::CONTOUR);
    let mut stroke = painter.stroke(2.0 * dpr, palette::ERROR1, true);
    for [d, rho] in &w.scan {
        let v = measure.value(*rho, *d);
        stroke.to(if v.is_finite() { [frame.x(*d), frame.y(v)] } else { [f64::NAN, f64::NAN] });
    }
    drop(stroke);
    if let Some([lo, hi]) = lag {
        let (x0, x1) = (frame.x(lo).max(r.x), frame.x(hi).min(r.right()));
        if x1 > x0 {
            painter.rect(Rect::new(x0, r.y, x1 - x0, 4.0 * dpr), palette::LAG_BAND);
        }
    }
    for (delta, _) in omega.into_iter().flat_map(|w| turn_ticks(w, frame.x_range)) {
        let x = frame.x(delta);
        painter.line([x, r.y], [x, r.y + 7.0 * dpr], 1.5 * dpr, palette::AXIS);
    }
}

/// An upper bound on the vertices [`draw_rho_marker`] writes.
pub const MARKER_VERTEX_BUDGET: usize = 3 * 6 + 2 * 128 * 3;

/// A run's δ: a vertical line and a dot at (δ, value), the value being ρ or ln ρ/δ as the panel
/// shows; at the edge if δ lies outside the range.
pub fn draw_rho_marker(painter: &mut Painter, frame: &RhoFrame, delta: f64, value: f64, color: Color, dpr: f64) {
    if !(delta > 0.0 && delta.is_finite()) {
        return;
    }
    let r = frame.rect;
    let x = frame.x(delta).clamp(r.x, r.right());
    painter.line([x, r.y], [x, r.bottom()], 1.5 * dpr, color.with_alpha(0.6));
    if value.is_finite() {
        let p: Point = [x, frame.y(value)];
        painter.circle(p, 5.5 * dpr, palette::MARKER_HALO);
        painter.circle(p, 4.0 * dpr, color);
    }
}
