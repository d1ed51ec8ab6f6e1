//! The study's two panels as geometry: what each curve is (one table, [`SERIES`], that the
//! drawing, the key and the tooltip all read), the log–log frame over δ, and the drawing.

use crate::analysis::sensor_study::StudyRow;
use crate::plot::ticks::log_ticks;
use crate::plot::{palette, Color};
use crate::schema::PanelKind;
use crate::view::delta_axis::DeltaAxis;
use crate::view::painter::Painter;
use crate::view::rect::Rect;

/// How a curve is stroked: the settings' sensors solid, perfect ones dashed, the linear
/// prediction dotted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    Solid,
    Dashed,
    Dotted,
}

/// One curve of a study panel.
#[derive(Clone, Copy, Debug)]
pub struct Series {
    pub panel: PanelKind,
    /// What the key and the tooltip call it.
    pub label: &'static str,
    pub color: Color,
    pub stroke: Stroke,
    /// Dots at the δ simulated (the prediction is a line only).
    pub dots: bool,
    /// Significant digits read out: the table's.
    pub digits: usize,
    /// Its value in a row, if there is one yet (rad or N m).
    pub value: fn(&StudyRow) -> Option<f64>,
}

/// Significant digits of a value read out, as the table prints it.
const DIGITS: usize = 2;

/// Every curve, the error panel's first. The same columns as the study's table
/// ([`crate::words::sensors::study_table`]).
pub const SERIES: [Series; 8] = [
    Series {
        panel: PanelKind::StudyError,
        label: "max |e| during the slew, these sensors",
        color: palette::ERROR1,
        stroke: Stroke::Solid,
        dots: true,
        digits: DIGITS,
        value: StudyRow::slew_error,
    },
    Series {
        panel: PanelKind::StudyError,
        label: "max |e| during the slew, perfect sensors",
        color: palette::SPLIT_REST,
        stroke: Stroke::Dashed,
        dots: true,
        digits: DIGITS,
        value: StudyRow::ideal_slew_error,
    },
    Series {
        panel: PanelKind::StudyError,
        label: "RMS e at rest, these sensors",
        color: palette::ERROR2,
        stroke: Stroke::Solid,
        dots: true,
        digits: DIGITS,
        value: StudyRow::rest_error,
    },
    Series {
        panel: PanelKind::StudyError,
        label: "the sensors' noise in e, predicted (RMS; the linear model with white noise — the quantizer at rest, \
                the friction and the limit add what only the simulation shows)",
        color: palette::PREDICTED,
        stroke: Stroke::Dotted,
        dots: false,
        digits: DIGITS,
        value: StudyRow::predicted_error,
    },
    Series {
        panel: PanelKind::StudyTorque,
        label: "T1 noise at rest (RMS about its mean), these sensors",
        color: palette::TORQUE1,
        stroke: Stroke::Solid,
        dots: true,
        digits: DIGITS,
        value: StudyRow::torque_noise,
    },
    Series {
        panel: PanelKind::StudyTorque,
        label: "T1 noise at rest, perfect sensors",
        color: palette::SPLIT_REST,
        stroke: Stroke::Dashed,
        dots: true,
        digits: DIGITS,
        value: StudyRow::ideal_torque_noise,
    },
    Series {
        panel: PanelKind::StudyTorque,
        label: "peak |T1|, these sensors",
        color: palette::ERROR2,
        stroke: Stroke::Solid,
        dots: true,
        digits: 3,
        value: StudyRow::peak_torque,
    },
    Series {
        panel: PanelKind::StudyTorque,
        label:
            "the sensors' noise in T1, predicted (RMS; the linear model with white noise, valid while the arm moves)",
        color: palette::PREDICTED,
        stroke: Stroke::Dotted,
        dots: false,
        digits: DIGITS,
        value: StudyRow::predicted_torque,
    },
];

/// The curves of one panel.
pub fn series_of(kind: PanelKind) -> impl Iterator<Item = &'static Series> {
    SERIES.iter().filter(move |s| s.panel == kind)
}

/// A log axis spans at most this many decades below its largest value: a perfect robot's torque
/// noise at rest can be 1e-9 N m, which would flatten everything else; lower values sit on the
/// bottom edge.
pub const MAX_DECADES: f64 = 4.0;

/// A study panel's data area: the δ axis of ρ(δ) across (so that a δ sits at the same x in
/// both), a log value up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StudyFrame {
    pub axis: DeltaAxis,
    pub y_range: [f64; 2],
}

impl StudyFrame {
    /// Vertical pixel of a value, clamped to the data area (values ≤ 0 at the bottom).
    pub fn y(&self, v: f64) -> f64 {
        let [a, b] = self.y_range;
        let f = if v > 0.0 { (v / a).ln() / (b / a).ln() } else { 0.0 };
        self.axis.rect.bottom() - self.axis.rect.h * f.clamp(0.0, 1.0)
    }
}

/// The value range of a panel: whole decades around its curves' values (and `limit`, on the
/// torque panel), at most [`MAX_DECADES`] deep, at least one; `fallback` with no values yet.
pub fn value_range(kind: PanelKind, rows: &[StudyRow], limit: Option<f64>, fallback: [f64; 2]) -> [f64; 2] {
    let mut hi = f64::NEG_INFINITY;
    let mut lo = f64::INFINITY;
    let extra = if kind == PanelKind::StudyTorque { limit } else { None };
    for v in rows.iter().flat_map(|r| series_of(kind).filter_map(move |s| (s.value)(r))).chain(extra) {
        if v > 0.0 && v.is_finite() {
            hi = hi.max(v);
            lo = lo.min(v);
        }
    }
    if !hi.is_finite() {
        return fallback;
    }
    let top = hi.log10().ceil();
    let bottom = lo.log10().floor().max(top - MAX_DECADES).min(top - 1.0);
    [10f64.powf(bottom), 10f64.powf(top)]
}

/// The δ and value ticks of a panel whose data area is `rect_css` (CSS pixels).
pub fn study_ticks(rect_css: Rect, frame: &StudyFrame) -> (Vec<f64>, Vec<f64>) {
    let nx = (rect_css.w / 46.0).floor().clamp(1.0, 20.0) as usize;
    let ny = (rect_css.h / 22.0).floor().clamp(2.0, 10.0) as usize;
    (log_ticks(frame.axis.range[0], frame.axis.range[1], nx), log_ticks(frame.y_range[0], frame.y_range[1], ny))
}

/// The curves, the limit, the best δ ringed and the δ where ρ ≥ 1 crossed out (along the top):
/// the static layer, drawn when the study moves.
pub fn draw_study(
    painter: &mut Painter,
    kind: PanelKind,
    frame: &StudyFrame,
    rows: &[StudyRow],
    best: Option<usize>,
    limit: Option<f64>,
    ticks: (&[f64], &[f64]),
    dpr: f64,
) {
    let (r, axis) = (frame.axis.rect, frame.axis);
    painter.rect(r, palette::PANEL);
    axis.draw_grid(painter, ticks.0, ticks.1.iter().map(|&v| frame.y(v)), dpr);
    if let Some(l) = limit.filter(|_| kind == PanelKind::StudyTorque) {
        let y = frame.y(l);
        painter.dashed_line([r.x, y], [r.right(), y], 1.5 * dpr, 6.0 * dpr, 4.0 * dpr, palette::TORQUE_LIMIT);
    }
    for s in series_of(kind) {
        let points = rows.iter().map(|row| (s.value)(row).map(|v| [axis.x(row.sampling_period), frame.y(v)]));
        let width = if s.stroke == Stroke::Solid { 2.0 } else { 1.5 } * dpr;
        let mut last: Option<[f64; 2]> = None;
        for p in points {
            if let (Some(a), Some(b)) = (last, p) {
                match s.stroke {
                    Stroke::Solid => painter.line(a, b, width, s.color),
                    Stroke::Dashed => painter.dashed_line(a, b, width, 6.0 * dpr, 4.0 * dpr, s.color),
                    Stroke::Dotted => painter.dashed_line(a, b, width, 2.0 * dpr, 3.0 * dpr, s.color),
                }
            }
            if let (Some(p), true) = (p, s.dots) {
                painter.circle(p, 3.0 * dpr, s.color);
            }
            last = p;
        }
    }
    // The best δ, ringed on the curve it is judged by (the slew's error).
    if let Some(row) = best.and_then(|i| rows.get(i)).filter(|_| kind == PanelKind::StudyError) {
        if let Some(v) = row.slew_error() {
            painter.ring([axis.x(row.sampling_period), frame.y(v)], 7.0 * dpr, 2.0 * dpr, palette::WINDOW_MARK);
        }
    }
    // Where ρ ≥ 1 or the run diverged: crossed out along the top, whatever the short run showed.
    for row in rows {
        if row.unstable() || row.diverged() {
            let c = [axis.x(row.sampling_period), r.y + 7.0 * dpr];
            painter.cross(c, 4.5 * dpr, 2.0 * dpr, palette::POLE_UNSTABLE);
        }
    }
}
