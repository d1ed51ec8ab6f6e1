//! The text of tick labels: linear ticks in the shortest form that tells them apart, labelled log
//! ticks that fit along an axis, and linear ticks counted as steps from a middle tick where their
//! full numbers are too wide.

use super::panel_info::TickLabel;
use super::text_metrics::{bold_width, font};
use crate::plot::format::{self, TickFormat};
use crate::plot::ticks::label_log_ticks;

/// Text labels for linear ticks.
pub fn linear_labels(ticks: &[f64]) -> Vec<TickLabel> {
    let f = TickFormat::for_ticks(ticks);
    ticks.iter().map(|&value| TickLabel { value, text: f.format(value) }).collect()
}

/// Labels of linear ticks as whole steps from the middle tick, in a power of ten ("−4", "0",
/// "4" for 0.70702, 0.70710, 0.70718), and the title's clause that reads them ("Im λ = 0.70710 +
/// n × 1e−5", shorter forms where that is wider than `room` px); None for fewer than two ticks
/// or no form that fits.
pub fn offset_labels(ticks: &[f64], room: f64) -> Option<(Vec<TickLabel>, String)> {
    let (&a, &b) = (ticks.first()?, ticks.get(1)?);
    let step = b - a;
    let unit = 10f64.powf((step.log10() + 1e-9).floor());
    let mid = ticks[ticks.len() / 2];
    let labels = ticks
        .iter()
        .map(|&value| TickLabel { value, text: format::minus(&format!("{}", ((value - mid) / unit).round() as i64)) })
        .collect();
    let (m, u) = (TickFormat::for_ticks(ticks).format(mid), format::log_tick(unit));
    let forms = [format!("Im λ = {m} + n × {u}"), format!("Im λ = {m} + n·{u}"), format!("{m} + n·{u}")];
    let base = forms.into_iter().find(|f| bold_width(f, font::TITLE) <= room)?;
    Some((labels, base))
}

/// Text labels for the log ticks that fit along `length` pixels; where `spacing` leaves fewer than
/// three on a short axis, four fifths of it (the spacing is the widest label's: shorter labels
/// still clear each other, which the layout's no-overlap check confirms).
pub fn log_labels(ticks: &[f64], range: [f64; 2], length: f64, spacing: f64) -> Vec<TickLabel> {
    let mut values = label_log_ticks(ticks, range[0], range[1], length, spacing);
    if values.len() < 3 {
        let closer = label_log_ticks(ticks, range[0], range[1], length, spacing * 0.8);
        if closer.len() > values.len() {
            values = closer;
        }
    }
    values.into_iter().map(|value| TickLabel { value, text: format::log_tick(value) }).collect()
}
