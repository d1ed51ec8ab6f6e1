//! What the time plots and the pole plot show: their curves and colours, their tick counts.

use crate::control::Traces;
use crate::plot::{palette, Color, Ticks};
use crate::view::layout::{PanelKind, Rect};
use crate::view::poles::RE_RANGE;
use crate::view::traces::TimeWindow;

/// About one time tick per this many CSS pixels of plot width.
const X_TICK_SPACING: f64 = 80.0;
/// About one value tick per this many CSS pixels of plot height (±Y gets an even split).
const Y_TICK_SPACING: f64 = 32.0;
/// About one Re s tick per this many CSS pixels of pole-plot width.
const POLE_X_TICK_SPACING: f64 = 30.0;

/// The y-axis label of a plot, with its unit.
pub(super) fn y_label(kind: PanelKind) -> &'static str {
    match kind {
        PanelKind::Error1 => "e1 [rad]",
        PanelKind::Error2 => "e2 [rad]",
        PanelKind::Torque => "T1, T2 [N m]",
        _ => "",
    }
}

/// The curves of a time plot and their colours (at most two per plot) for run A (0) or B (1).
/// Run A keeps the usual colours; run B draws everything in its own hue (T2 lighter).
pub(super) fn plot_series(kind: PanelKind, traces: &Traces, run: usize) -> [Option<(&[f64], Color)>; 2] {
    let b = run != 0;
    let pick = |a: Color, b_color: Color| if b { b_color } else { a };
    match kind {
        PanelKind::Error1 => [Some((traces.e1(), pick(palette::ERROR1, palette::RUN_B))), None],
        PanelKind::Error2 => [Some((traces.e2(), pick(palette::ERROR2, palette::RUN_B))), None],
        PanelKind::Torque => [
            Some((traces.torque1(), pick(palette::TORQUE1, palette::RUN_B))),
            Some((traces.torque2(), pick(palette::TORQUE2, palette::RUN_B_LIGHT))),
        ],
        _ => [None, None],
    }
}

/// How many time and value intervals a plot whose data area is `rect_css` (CSS pixels) gets at
/// most; an even value count keeps 0 and ±Y/2 as ticks of the symmetric range.
pub(super) fn plot_tick_counts(rect_css: Rect) -> (usize, usize) {
    let x_count = (rect_css.w / X_TICK_SPACING).floor().clamp(2.0, 12.0) as usize;
    let y_count = ((rect_css.h / Y_TICK_SPACING / 2.0).floor() * 2.0).clamp(2.0, 8.0) as usize;
    (x_count, y_count)
}

/// Time and value ticks for a plot whose data area is `rect_css` (CSS pixels).
pub(super) fn plot_ticks(rect_css: Rect, window: TimeWindow, y: f64) -> (Ticks, Ticks) {
    let (x_count, y_count) = plot_tick_counts(rect_css);
    (Ticks::new(window.start, window.end, x_count), Ticks::new(-y, y, y_count))
}

/// How many Re s and Im s intervals the pole plot gets at most.
pub(super) fn pole_tick_counts(rect_css: Rect) -> (usize, usize) {
    let x_count = (rect_css.w / POLE_X_TICK_SPACING).floor().clamp(2.0, 14.0) as usize;
    let y_count = (rect_css.h / Y_TICK_SPACING).floor().clamp(2.0, 16.0) as usize;
    (x_count, y_count)
}

/// Re s and Im s ticks of the pole plot whose data area is `rect_css` (CSS pixels) and whose Im s
/// range is `im`.
pub(super) fn pole_ticks(rect_css: Rect, im: [f64; 2]) -> (Ticks, Ticks) {
    let (x_count, y_count) = pole_tick_counts(rect_css);
    (Ticks::new(RE_RANGE[0], RE_RANGE[1], x_count), Ticks::new(im[0], im[1], y_count))
}
