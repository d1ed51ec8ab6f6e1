//! The error-traces figure: e1 and e2 over time in two stacked panels sharing the time axis.

use std::fmt::Write as _;

use super::{fit_title, num, Axis, Svg, INK};
use crate::control::Traces;
use crate::plot::format;
use crate::plot::palette;
use crate::plot::Ticks;

/// At most this many points are drawn per trace; longer traces are reduced to the minimum and
/// maximum of each of `MAX_TRACE_POINTS / 2` buckets, which keeps the envelope of oscillations.
pub const MAX_TRACE_POINTS: usize = 2000;

/// Splits (t, y) into runs of finite points and reduces each to at most about `max_points`
/// points in total, keeping each bucket's minimum and maximum in time order.
fn decimate(t: &[f64], y: &[f64], max_points: usize) -> Vec<Vec<(f64, f64)>> {
    let n = t.len().min(y.len());
    let finite = |i: usize| t[i].is_finite() && y[i].is_finite();
    let count = (0..n).filter(|&i| finite(i)).count();
    let buckets = (max_points / 2).max(1);
    let size = count.div_ceil(buckets).max(1);
    let mut runs: Vec<Vec<usize>> = Vec::new();
    let mut current: Vec<usize> = Vec::new();
    for i in 0..n {
        if finite(i) {
            current.push(i);
        } else if !current.is_empty() {
            runs.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        runs.push(current);
    }
    runs.into_iter()
        .map(|run| {
            if size == 1 {
                return run.iter().map(|&i| (t[i], y[i])).collect();
            }
            let mut pts = Vec::with_capacity(2 * run.len() / size + 2);
            for chunk in run.chunks(size) {
                let (mut lo, mut hi) = (chunk[0], chunk[0]);
                for &i in chunk {
                    if y[i] < y[lo] {
                        lo = i;
                    }
                    if y[i] > y[hi] {
                        hi = i;
                    }
                }
                let (a, b) = if lo <= hi { (lo, hi) } else { (hi, lo) };
                pts.push((t[a], y[a]));
                if b != a {
                    pts.push((t[b], y[b]));
                }
            }
            pts
        })
        .collect()
}

/// The display unit of an error trace with largest magnitude `max`: (unit, factor from rad).
fn error_unit(max: f64) -> (&'static str, f64) {
    if max.is_nan() || max <= 0.0 || max >= 0.1 {
        ("rad", 1.0)
    } else if max >= 1e-4 {
        ("mrad", 1e3)
    } else {
        ("µrad", 1e6)
    }
}

const TRACE_LEFT: f64 = 92.0;
const TRACE_WIDTH: f64 = 700.0;
const TRACE_PANEL: f64 = 190.0;

/// A figure of the tracking errors e1 and e2 over time t [s] in two stacked panels sharing the
/// time axis, each with its own scale (rad, mrad or µrad, whichever reads best), a zero line and
/// a legend. Long traces are decimated to at most [`MAX_TRACE_POINTS`] points per line. `state`
/// (the state string of the run) goes into the figure's `<desc>`.
pub fn error_traces_svg(traces: &Traces, title: &str, state: Option<&str>) -> String {
    let width = TRACE_LEFT + TRACE_WIDTH + 30.0;
    let heading = fit_title(title, width - 40.0);
    let dy = heading.extra;
    let height = 580.0 + dy;
    let tops = [78.0 + dy, 78.0 + dy + TRACE_PANEL + 34.0];
    let mut svg = Svg::new(width, height, title);
    svg.describe(state);
    svg.heading(width / 2.0, &heading);

    let time = traces.t();
    let finite_t = || time.iter().copied().filter(|v| v.is_finite());
    let (t0, t1) = match (finite_t().reduce(f64::min), finite_t().reduce(f64::max)) {
        (Some(a), Some(b)) if b > a => (a, b),
        (Some(a), _) => (a, a + 1.0),
        _ => (0.0, 1.0),
    };
    let tx = Axis { lo: t0, hi: t1, log: false, p0: TRACE_LEFT, p1: TRACE_LEFT + TRACE_WIDTH };
    let t_ticks: Vec<f64> = Ticks::new(t0, t1, 8).collect();
    let colours = [palette::ERROR1.css(), palette::ERROR2.css()];

    let series: [(&[f64], &str, &str); 2] =
        [(traces.e1(), "e1", "link 1 error e1"), (traces.e2(), "e2", "link 2 error e2")];
    for (k, (values, name, legend)) in series.into_iter().enumerate() {
        let (top, bottom) = (tops[k], tops[k] + TRACE_PANEL);
        let max = values.iter().filter(|v| v.is_finite()).fold(0.0f64, |m, v| m.max(v.abs()));
        let (unit, factor) = error_unit(max);
        let scaled: Vec<f64> = values.iter().map(|v| v * factor).collect();
        let (mut lo, mut hi) =
            scaled.iter().filter(|v| v.is_finite()).fold((0.0f64, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
        if hi - lo <= 0.0 {
            (lo, hi) = (-1.0, 1.0);
        }
        // Widen the range to whole steps so the frame sits on ticks.
        let step = Ticks::new(lo, hi, 5).step;
        let (lo, hi) = ((lo / step - 1e-9).floor() * step, (hi / step + 1e-9).ceil() * step);
        let ya = Axis { lo, hi, log: false, p0: bottom, p1: top };
        let y_ticks: Vec<f64> = Ticks::new(lo, hi, 5).collect();

        // Grid, zero line, frame.
        let mut grid = String::new();
        for v in &t_ticks {
            let _ = write!(grid, "M{} {}V{}", num(tx.pos(*v)), num(top), num(bottom));
        }
        for v in y_ticks.iter().filter(|v| **v != 0.0) {
            let _ = write!(grid, "M{} {}H{}", num(tx.p0), num(ya.pos(*v)), num(tx.p1));
        }
        let _ = writeln!(
            svg.out,
            "<path d=\"{grid}\" stroke=\"{}\" stroke-width=\"1\" fill=\"none\"/>",
            palette::GRID.css()
        );
        svg.line(tx.p0, ya.pos(0.0), tx.p1, ya.pos(0.0), (&palette::AXIS.css(), 1.2));

        // The trace.
        let mut d = String::new();
        for run in decimate(time, &scaled, MAX_TRACE_POINTS) {
            for (i, (t, v)) in run.iter().enumerate() {
                let (x, y) = (tx.pos(*t), ya.pos(*v));
                if x.is_finite() && y.is_finite() {
                    let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { "L" }, num(x), num(y));
                }
            }
        }
        if !d.is_empty() {
            let _ = writeln!(
                svg.out,
                "<path id=\"trace-{name}\" d=\"{d}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.4\" \
                 stroke-linejoin=\"round\"/>",
                colours[k]
            );
        } else {
            svg.text((tx.p0 + tx.p1) / 2.0, (top + bottom) / 2.0, 14.0, "middle", "", "no data");
        }

        svg.rect(
            tx.p0,
            top,
            tx.p1 - tx.p0,
            bottom - top,
            &format!("fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\""),
        );
        let mut ticks = String::new();
        for v in &t_ticks {
            let _ = write!(ticks, "M{} {}v5", num(tx.pos(*v)), num(bottom));
        }
        for v in &y_ticks {
            let _ = write!(ticks, "M{} {}h-5", num(tx.p0), num(ya.pos(*v)));
        }
        let _ = writeln!(svg.out, "<path d=\"{ticks}\" stroke=\"{INK}\" stroke-width=\"1\" fill=\"none\"/>");
        for v in &y_ticks {
            svg.text(tx.p0 - 8.0, ya.pos(*v), 13.0, "end", " dy=\"0.35em\"", &format::number(*v));
        }
        svg.vertical_text(tx.p0 - 62.0, (top + bottom) / 2.0, 14.0, &format!("{name} [{unit}]"));
        if k == 1 {
            for v in &t_ticks {
                svg.text(tx.pos(*v), bottom + 20.0, 13.0, "middle", "", &format::number(*v));
            }
            svg.text((tx.p0 + tx.p1) / 2.0, bottom + 46.0, 14.0, "middle", "", "time t [s]");
        }

        // Legend entry, top right above the panels.
        let lx = tx.p1 - 330.0 + 170.0 * k as f64;
        svg.line(lx, 56.0 + dy, lx + 26.0, 56.0 + dy, (&colours[k], 2.5));
        svg.text(lx + 32.0, 60.5 + dy, 13.0, "start", "", legend);
    }
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimation_keeps_the_envelope_and_splits_at_gaps() {
        let t: Vec<f64> = (0..30_000).map(|i| i as f64 * 0.002).collect();
        let y: Vec<f64> = t.iter().map(|t| 2e-3 * (30.0 * t).sin() * (0.03 * t).exp()).collect();
        let runs = decimate(&t, &y, MAX_TRACE_POINTS);
        let points: usize = runs.iter().map(Vec::len).sum();
        assert!((1000..=MAX_TRACE_POINTS).contains(&points), "{points}");
        let max_drawn = runs.iter().flatten().fold(0.0f64, |m, p| m.max(p.1.abs()));
        assert_eq!(max_drawn, y.iter().fold(0.0f64, |m, v| m.max(v.abs())));
        let mut gap = y.clone();
        gap[100] = f64::NAN;
        assert_eq!(decimate(&t[..500], &gap[..500], MAX_TRACE_POINTS).len(), 2);
    }

    #[test]
    fn units_follow_the_size() {
        assert_eq!(error_unit(0.5).0, "rad");
        assert_eq!(error_unit(2e-3).0, "mrad");
        assert_eq!(error_unit(5e-5).0, "µrad");
    }
}
