//! What the time plots show: their curves and colours, their axis titles, their tick counts.

use crate::control::Traces;
use crate::plot::{palette, Color, Ticks};
use crate::schema::PanelKind;
use crate::view::rect::Rect;
use crate::view::time_window::TimeWindow;

/// Plot curve widths, CSS pixels: run A, and run B drawn a little thinner over it.
pub const CURVE_WIDTH: f64 = 1.75;
pub const CURVE_WIDTH_B: f64 = 1.5;
/// Decades a log |e| plot spans below its top.
pub const LOG_DECADES: i32 = 6;
/// Vertices of one dashed predicted-slope line at most (512 dashes).
pub const DASHED_LINE_BUDGET: usize = 512 * 6;

/// About one time tick per this many CSS pixels of plot width.
const X_TICK_SPACING: f64 = 80.0;
/// About one value tick per this many CSS pixels of plot height (±Y gets an even split).
const Y_TICK_SPACING: f64 = 32.0;

/// The y-axis label of a plot, with its unit.
pub fn y_label(kind: PanelKind) -> &'static str {
    match kind {
        PanelKind::Error1 => "e1 [rad]",
        PanelKind::Error2 => "e2 [rad]",
        PanelKind::Torque => "T1, T2 [N m]",
        PanelKind::Velocity => "q̇1 [rad/s]",
        _ => "",
    }
}

/// The curves of a time plot and their colours (at most two per plot) for run A (0) or B (1).
/// Run A keeps the usual colours; run B draws everything in its own hue (T2 lighter).
pub fn plot_series(kind: PanelKind, traces: &Traces, run: usize) -> [Option<(&[f64], Color)>; 2] {
    let b = run != 0;
    let pick = |a: Color, b_color: Color| if b { b_color } else { a };
    match kind {
        PanelKind::Error1 => [Some((traces.e1(), pick(palette::ERROR1, palette::RUN_B))), None],
        PanelKind::Error2 => [Some((traces.e2(), pick(palette::ERROR2, palette::RUN_B))), None],
        PanelKind::Torque => [
            Some((traces.torque1(), pick(palette::TORQUE1, palette::RUN_B))),
            Some((traces.torque2(), pick(palette::TORQUE2, palette::RUN_B_LIGHT))),
        ],
        PanelKind::Velocity => [Some((traces.q1_dot(), pick(palette::VELOCITY1, palette::RUN_B))), None],
        _ => [None, None],
    }
}

/// How many time and value intervals a plot whose data area is `rect_css` (CSS pixels) gets at
/// most; an even value count keeps 0 and ±Y/2 as ticks of the symmetric range.
pub fn plot_tick_counts(rect_css: Rect) -> (usize, usize) {
    let x_count = (rect_css.w / X_TICK_SPACING).floor().clamp(2.0, 12.0) as usize;
    let y_count = ((rect_css.h / Y_TICK_SPACING / 2.0).floor() * 2.0).clamp(2.0, 8.0) as usize;
    (x_count, y_count)
}

/// Time and value ticks for a plot whose data area is `rect_css` (CSS pixels).
pub fn plot_ticks(rect_css: Rect, window: TimeWindow, y: f64) -> (Ticks, Ticks) {
    let (x_count, y_count) = plot_tick_counts(rect_css);
    // Three time labels at least on a short axis (a projector's large text).
    (Ticks::at_least(window.start, window.end, x_count, 3), Ticks::new(-y, y, y_count))
}
