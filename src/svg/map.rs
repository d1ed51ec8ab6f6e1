//! The stability-map figure: ρ over (δ, α) on logarithmic axes, cells coloured by ρ or by ln ρ/δ
//! (a [`Measure`], the same ramps as the page's maps), the ρ = 1 contour (ln ρ/δ = 0: the same
//! line under both), a colour bar, and a marker at the current settings.

use std::fmt::Write as _;

use super::{fit_title, log_range, num, Axis, Svg, INK};
use crate::analysis::StabilityMap;
use crate::plot::color::{ramp_color, Measure, RATE_SHOWN, RHO_SHOWN};
use crate::plot::contour::{chain_segments, marching_squares};
use crate::plot::format;
use crate::plot::palette;
use crate::plot::ticks::{log_minor_ticks, log_ticks};

const MAP_LEFT: f64 = 84.0;
const MAP_GAP: f64 = 100.0;
const MAP_WIDTH: f64 = 440.0;
const MAP_HEIGHT: f64 = 330.0;
/// At most this many labelled ticks per log axis (then powers of ten only).
const MAX_LOG_LABELS: usize = 9;

/// The geometry of one map panel.
struct MapPanel<'a> {
    map: &'a StabilityMap,
    label: &'a str,
    x: Axis,
    y: Axis,
}

/// Indices of the positive finite values, sorted by value (the grid may come in any order).
fn sorted_positive(values: &[f64]) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..values.len()).filter(|&i| values[i].is_finite() && values[i] > 0.0).collect();
    crate::sort::sort_by(&mut idx, |&a, &b| values[a].total_cmp(&values[b]));
    idx
}

/// Pixel edges of the cells around sorted grid values: geometric midpoints, clipped to the axis.
fn cell_edges(values: &[f64], order: &[usize], axis: &Axis) -> Vec<f64> {
    let n = order.len();
    let mut edges = Vec::with_capacity(n + 1);
    edges.push(axis.pos(axis.lo));
    for k in 1..n {
        let (a, b) = (values[order[k - 1]], values[order[k]]);
        edges.push(axis.pos_ln(0.5 * (a.ln() + b.ln())));
    }
    edges.push(axis.pos(axis.hi));
    edges
}

/// The ρ = 1 contour of a map as polylines in pixel coordinates, each with a flag "closed":
/// [`marching_squares`] on the grid in (ln δ, ln α), joined by [`chain_segments`].
fn rho_contour(panel: &MapPanel) -> Vec<(Vec<(f64, f64)>, bool)> {
    let map = panel.map;
    let cols = sorted_positive(&map.sampling_periods);
    let rows = sorted_positive(&map.alphas);
    let nd = map.sampling_periods.len();
    if cols.len() < 2 || rows.len() < 2 || map.spectral_radius.len() < nd * map.alphas.len() {
        return vec![];
    }
    let xs: Vec<f64> = cols.iter().map(|&c| map.sampling_periods[c].ln()).collect();
    let ys: Vec<f64> = rows.iter().map(|&r| map.alphas[r].ln()).collect();
    // Infinite ρ counts as unknown, like NaN.
    let values: Vec<f64> = rows
        .iter()
        .flat_map(|&r| cols.iter().map(move |&c| map.spectral_radius[r * nd + c]))
        .map(|v| if v.is_finite() { v } else { f64::NAN })
        .collect();
    chain_segments(&marching_squares(&xs, &ys, &values, 1.0))
        .into_iter()
        .filter_map(|mut line| {
            let closed = line.len() > 3 && line.first() == line.last();
            if closed {
                line.pop();
            }
            let pts: Vec<(f64, f64)> = line
                .iter()
                .map(|p| (panel.x.pos_ln(p[0]), panel.y.pos_ln(p[1])))
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect();
            (pts.len() >= 2).then_some((pts, closed))
        })
        .collect()
}

/// A figure of ρ over (δ, α): logarithmic axes (δ [s] horizontal, α [1/s] vertical), cells
/// coloured by [`crate::plot::rho_color`], the ρ = 1 contour, a colour bar, and a marker at
/// `current` (δ, α) if given and inside the grid.
pub fn stability_map_svg(map: &StabilityMap, title: &str, current: Option<(f64, f64)>) -> String {
    stability_maps_svg(&[(map, "")], title, current, None, Measure::Rho)
}

/// Several stability maps side by side with one shared colour bar, each under its own label
/// (e.g. without and with preliminary feedback), cells coloured by `measure`; the marker, if
/// any, is drawn on every panel. `state` (the state string of the settings) goes into the
/// figure's `<desc>`.
pub fn stability_maps_svg(
    maps: &[(&StabilityMap, &str)],
    title: &str,
    current: Option<(f64, f64)>,
    state: Option<&str>,
    measure: Measure,
) -> String {
    let n = maps.len().max(1) as f64;
    let labelled = maps.iter().any(|(_, l)| !l.is_empty());
    let plots_right = MAP_LEFT + n * MAP_WIDTH + (n - 1.0) * MAP_GAP;
    let bar_x = plots_right + 30.0;
    let width = bar_x + 120.0;
    let heading = fit_title(title, width - 40.0);
    let top = heading.extra + if labelled { 76.0 } else { 56.0 };
    let bottom = top + MAP_HEIGHT;
    let height = bottom + 112.0;

    let mut svg = Svg::new(width, height, title);
    svg.describe(state);
    svg.heading(width / 2.0, &heading);

    let panels: Vec<MapPanel> = maps
        .iter()
        .enumerate()
        .map(|(i, &(map, label))| {
            let left = MAP_LEFT + i as f64 * (MAP_WIDTH + MAP_GAP);
            let (dl, dh) = log_range(&map.sampling_periods);
            let (al, ah) = log_range(&map.alphas);
            MapPanel {
                map,
                label,
                x: Axis { lo: dl, hi: dh, log: true, p0: left, p1: left + MAP_WIDTH },
                y: Axis { lo: al, hi: ah, log: true, p0: bottom, p1: top },
            }
        })
        .collect();

    for (i, panel) in panels.iter().enumerate() {
        draw_map_panel(&mut svg, panel, i, current, measure);
    }
    colour_bar(&mut svg, bar_x, top, bottom, measure);

    // Legend under the plots.
    let ly = bottom + 80.0;
    let lx = MAP_LEFT;
    svg.line(lx, ly - 4.0, lx + 28.0, ly - 4.0, (&palette::CONTOUR.css(), 2.0));
    let boundary = match measure {
        Measure::Rho => "ρ = 1: stability boundary (ρ < 1 ⇔ linearly stable)",
        Measure::Rate => "ln ρ/δ = 0 (ρ = 1): stability boundary (ln ρ/δ < 0 ⇔ linearly stable)",
    };
    svg.text(lx + 36.0, ly, 13.0, "start", "", boundary);
    if let Some((d, a)) = current.filter(|(d, a)| panels.iter().any(|p| p.x.contains(*d) && p.y.contains(*a))) {
        marker(&mut svg, lx + 14.0, ly + 18.0);
        let text = format!("marked: δ = {} s, α = {} 1/s", format::number(d), format::number(a));
        svg.text(lx + 36.0, ly + 22.0, 13.0, "start", "", &text);
    }
    svg.finish()
}

fn marker(svg: &mut Svg, x: f64, y: f64) {
    let _ = writeln!(
        svg.out,
        "<circle cx=\"{x}\" cy=\"{y}\" r=\"6\" fill=\"none\" stroke=\"#ffffff\" stroke-width=\"4\"/>\n\
         <circle cx=\"{x}\" cy=\"{y}\" r=\"6\" fill=\"none\" stroke=\"{INK}\" stroke-width=\"2\"/>\n\
         <circle cx=\"{x}\" cy=\"{y}\" r=\"1.6\" fill=\"{INK}\"/>",
        x = num(x),
        y = num(y)
    );
}

fn draw_map_panel(svg: &mut Svg, p: &MapPanel, index: usize, current: Option<(f64, f64)>, measure: Measure) {
    let (left, right, top, bottom) = (p.x.p0, p.x.p1, p.y.p1, p.y.p0);
    let map = p.map;
    if !p.label.is_empty() {
        svg.text((left + right) / 2.0, top - 12.0, 15.0, "middle", "", p.label);
    }
    // Cells with no value show the colour of "not computed".
    svg.rect(left, top, right - left, bottom - top, &format!("fill=\"{}\"", palette::MAP_PENDING.css()));

    let cols = sorted_positive(&map.sampling_periods);
    let rows = sorted_positive(&map.alphas);
    let nd = map.sampling_periods.len();
    let xe = cell_edges(&map.sampling_periods, &cols, &p.x);
    let ye = cell_edges(&map.alphas, &rows, &p.y);
    let _ = writeln!(svg.out, "<g shape-rendering=\"crispEdges\" stroke=\"none\">");
    for (ri, &r) in rows.iter().enumerate() {
        let (y0, y1) = (ye[ri + 1], ye[ri]);
        // Runs of equal colour become one rectangle.
        let mut run: Option<(f64, String)> = None;
        let flush = |svg: &mut Svg, run: &mut Option<(f64, String)>, x_end: f64| {
            if let Some((x_start, fill)) = run.take() {
                svg.rect(x_start, y0, x_end - x_start, y1 - y0, &format!("fill=\"{fill}\""));
            }
        };
        for (ci, &c) in cols.iter().enumerate() {
            let delta = map.sampling_periods[c];
            let fill = map
                .spectral_radius
                .get(r * nd + c)
                .filter(|rho| !rho.is_nan())
                .map(|&rho| measure.color(rho, delta).css());
            match (&run, fill) {
                (Some((_, f)), Some(fill)) if *f == fill => {}
                (_, fill) => {
                    flush(svg, &mut run, xe[ci]);
                    run = fill.map(|f| (xe[ci], f));
                }
            }
        }
        flush(svg, &mut run, xe[cols.len()]);
    }
    let _ = writeln!(svg.out, "</g>");

    // The ρ = 1 contour.
    let lines = rho_contour(p);
    if !lines.is_empty() {
        let mut d = String::new();
        for (pts, closed) in &lines {
            for (k, (x, y)) in pts.iter().enumerate() {
                let _ = write!(d, "{}{} {}", if k == 0 { "M" } else { "L" }, num(*x), num(*y));
            }
            if *closed {
                d.push('Z');
            }
        }
        let _ = writeln!(
            svg.out,
            "<path id=\"rho-contour-{index}\" d=\"{d}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\" \
             stroke-linejoin=\"round\" stroke-linecap=\"round\"/>",
            palette::CONTOUR.css()
        );
    }

    // Frame, ticks and labels.
    svg.rect(left, top, right - left, bottom - top, &format!("fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\""));
    let xmaj = log_ticks(p.x.lo, p.x.hi, MAX_LOG_LABELS);
    let ymaj = log_ticks(p.y.lo, p.y.hi, MAX_LOG_LABELS);
    let (xmin, ymin) = (log_minor_ticks(p.x.lo, p.x.hi, &xmaj), log_minor_ticks(p.y.lo, p.y.hi, &ymaj));
    let mut ticks = String::new();
    for (v, len) in xmaj.iter().map(|v| (v, 6.0)).chain(xmin.iter().map(|v| (v, 3.0))) {
        let _ = write!(ticks, "M{} {}v{}", num(p.x.pos(*v)), num(bottom), num(len));
    }
    for (v, len) in ymaj.iter().map(|v| (v, 6.0)).chain(ymin.iter().map(|v| (v, 3.0))) {
        let _ = write!(ticks, "M{} {}h{}", num(left), num(p.y.pos(*v)), num(-len));
    }
    let _ = writeln!(svg.out, "<path d=\"{ticks}\" stroke=\"{INK}\" stroke-width=\"1\" fill=\"none\"/>");
    for v in &xmaj {
        svg.text(p.x.pos(*v), bottom + 21.0, 13.0, "middle", "", &format::number(*v));
    }
    for v in &ymaj {
        svg.text(left - 9.0, p.y.pos(*v), 13.0, "end", " dy=\"0.35em\"", &format::number(*v));
    }
    svg.text((left + right) / 2.0, bottom + 48.0, 14.0, "middle", "", "sampling period δ [s]");
    svg.vertical_text(left - 56.0, (top + bottom) / 2.0, 14.0, "stabilizing constant α [1/s]");

    if let Some((d, a)) = current {
        if d > 0.0 && a > 0.0 && p.x.contains(d) && p.y.contains(a) {
            marker(svg, p.x.pos(d), p.y.pos(a));
        }
    }
}

/// The vertical colour bar of `measure` from `top` to `bottom` at x, titled "ρ (spectral
/// radius)" or "ln ρ/δ (1/s), per second": the same ramp as the cells, with the border of
/// stability (ρ = 1, ln ρ/δ = 0) drawn like the contour.
fn colour_bar(svg: &mut Svg, x: f64, top: f64, bottom: f64, measure: Measure) {
    let w = 18.0;
    let _ = write!(svg.out, "<defs><linearGradient id=\"rho-colour-bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">");
    for k in 0..=16 {
        let pos = k as f64 / 16.0;
        let _ = write!(svg.out, "<stop offset=\"{}\" stop-color=\"{}\"/>", num(pos), ramp_color(pos).css());
    }
    let _ = writeln!(svg.out, "</linearGradient></defs>");
    svg.rect(x, top, w, bottom - top, "fill=\"url(#rho-colour-bar)\"");
    svg.rect(x, top, w, bottom - top, &format!("fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\""));
    let y_of = |v: f64| bottom - measure.position(v) * (bottom - top);
    let (ticks, name) = match measure {
        Measure::Rho => ([RHO_SHOWN[0], 0.9, 0.95, 0.98, 1.0, 1.02, 1.05, 1.1, RHO_SHOWN[1]], "ρ (spectral radius)"),
        Measure::Rate => ([-RATE_SHOWN, -2.0, -1.0, -0.2, 0.0, 0.2, 1.0, 2.0, RATE_SHOWN], "ln ρ/δ (1/s), per second"),
    };
    for (k, &v) in ticks.iter().enumerate() {
        let y = y_of(v);
        svg.line(x + w, y, x + w + 5.0, y, (INK, 1.0));
        let label = match k {
            0 => format!("≤ {}", format::number(v)),
            k if k == ticks.len() - 1 => format!("≥ {}", format::number(v)),
            _ => format::number(v),
        };
        svg.text(x + w + 8.0, y, 13.0, "start", " dy=\"0.35em\"", &label);
    }
    let y1 = y_of(measure.border());
    svg.line(x - 3.0, y1, x + w, y1, (&palette::CONTOUR.css(), 2.0));
    svg.text(x + w / 2.0, top - 8.0, 12.0, "middle", "", "unstable");
    svg.text(x + w / 2.0, bottom + 18.0, 12.0, "middle", "", "stable");
    svg.vertical_text(x + w + 72.0, (top + bottom) / 2.0, 14.0, name);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::log_space;

    #[test]
    fn the_contour_of_a_cone_is_one_closed_ring_on_the_unit_level() {
        let deltas = log_space(0.002, 0.25, 30);
        let alphas = log_space(0.1, 5.0, 20);
        let (cx, cy) = ((0.002f64.ln() + 0.25f64.ln()) / 2.0, (0.1f64.ln() + 5.0f64.ln()) / 2.0);
        let rho = alphas
            .iter()
            .flat_map(|a| deltas.iter().map(move |d| 0.8 + 0.2 * ((d.ln() - cx).powi(2) + (a.ln() - cy).powi(2))))
            .collect();
        let map = StabilityMap { sampling_periods: deltas, alphas, spectral_radius: rho };
        let (dl, dh) = log_range(&map.sampling_periods);
        let (al, ah) = log_range(&map.alphas);
        let panel = MapPanel {
            map: &map,
            label: "",
            x: Axis { lo: dl, hi: dh, log: true, p0: 0.0, p1: 1.0 },
            y: Axis { lo: al, hi: ah, log: true, p0: 0.0, p1: 1.0 },
        };
        let lines = rho_contour(&panel);
        assert_eq!(lines.len(), 1);
        assert!(lines[0].1, "closed");
        for &(x, y) in &lines[0].0 {
            let lx = dl.ln() + x * (dh.ln() - dl.ln());
            let ly = al.ln() + y * (ah.ln() - al.ln());
            let r = ((lx - cx).powi(2) + (ly - cy).powi(2)).sqrt();
            // Linear interpolation of a quadratic on a coarse grid: within a few per cent.
            assert!((r - 1.0).abs() < 0.05, "radius {r}");
        }
    }
}
