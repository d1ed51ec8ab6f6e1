//! Publication-ready SVG figures (stability maps, error traces) as plain strings.
//!
//! The figures are standalone SVG 1.1 documents (no scripts, no external resources) written by
//! hand: [`stability_map_svg`] and [`stability_maps_svg`] draw ρ over (δ, α) on logarithmic axes
//! with a diverging colour map centred on ρ = 1 and the ρ = 1 contour; [`error_traces_svg`] draws
//! the tracking errors e1 and e2 over time in two stacked panels.
//!
//! Every number written is finite: cells, points and markers with NaN or infinite coordinates
//! are left out. Text is XML-escaped.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use crate::analysis::StabilityMap;
use crate::closed_loop::Traces;

/// ρ at and below which the colour map is saturated blue (stable).
pub const RHO_COLOUR_MIN: f64 = 0.8;
/// ρ at and above which the colour map is saturated red (unstable).
pub const RHO_COLOUR_MAX: f64 = 1.2;
/// Exponent of the colour scale's compression around ρ = 1 (1 would be linear in ρ).
pub const COLOUR_GAMMA: f64 = 0.5;
/// At most this many points are drawn per trace; longer traces are reduced to the minimum and
/// maximum of each of `MAX_TRACE_POINTS / 2` buckets, which keeps the envelope of oscillations.
pub const MAX_TRACE_POINTS: usize = 2000;

const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";
const INK: &str = "#1a1a1a";
const GRID: &str = "#e3e3e3";
const CONTOUR: &str = "#111111";
const TRACE_COLOURS: [&str; 2] = ["#1f5fa8", "#c8501a"];

/// The diverging colour map: (position in [0, 1], RGB). 0 is ρ ≤ 0.8, ½ is ρ = 1, 1 is ρ ≥ 1.2.
const COLOUR_STOPS: [(f64, [f64; 3]); 5] = [
    (0.0, [30.0, 72.0, 150.0]),
    (0.25, [110.0, 160.0, 210.0]),
    (0.5, [248.0, 248.0, 248.0]),
    (0.75, [230.0, 128.0, 102.0]),
    (1.0, [160.0, 22.0, 36.0]),
];

/// Position of ρ on the colour scale in [0, 1]: ½ at ρ = 1, 0 at [`RHO_COLOUR_MIN`] and below, 1 at
/// [`RHO_COLOUR_MAX`] and above, and in between ½ ± ½ (|ρ − 1| / 0.2)^[`COLOUR_GAMMA`]. The
/// compression makes the |ρ − 1| of a few per cent typical near the boundary clearly coloured.
fn colour_position(rho: f64) -> f64 {
    let d = rho - 1.0;
    let half_range = if d < 0.0 { 1.0 - RHO_COLOUR_MIN } else { RHO_COLOUR_MAX - 1.0 };
    let s = (d.abs() / half_range).min(1.0).powf(COLOUR_GAMMA);
    (0.5 + 0.5 * d.signum() * s).clamp(0.0, 1.0)
}

fn colour_at(position: f64) -> [u8; 3] {
    let p = position.clamp(0.0, 1.0);
    let mut rgb = COLOUR_STOPS[COLOUR_STOPS.len() - 1].1;
    for w in COLOUR_STOPS.windows(2) {
        let ((p0, c0), (p1, c1)) = (w[0], w[1]);
        if p <= p1 {
            let s = (p - p0) / (p1 - p0);
            rgb = [0, 1, 2].map(|k| c0[k] + s * (c1[k] - c0[k]));
            break;
        }
    }
    rgb.map(|c| c.round().clamp(0.0, 255.0) as u8)
}

/// The colour of a cell with spectral radius `rho` (stable blue → white at ρ = 1 → unstable red,
/// saturated outside [`RHO_COLOUR_MIN`], [`RHO_COLOUR_MAX`], compressed around 1 as described at
/// `colour_position`); `None` for NaN.
pub fn rho_colour(rho: f64) -> Option<[u8; 3]> {
    (!rho.is_nan()).then(|| colour_at(colour_position(rho)))
}

fn hex([r, g, b]: [u8; 3]) -> String {
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// Escapes text for element content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            // Characters that XML 1.0 does not allow at all.
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// A coordinate with two decimals, trailing zeros trimmed; never NaN or inf (callers skip those).
fn num(v: f64) -> String {
    if !v.is_finite() {
        return "0".into();
    }
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// A tick label: up to six significant digits, trailing zeros trimmed, a real minus sign.
fn tick_label(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".into();
    }
    let e = v.abs().log10().floor() as i32;
    let s = if (-4..=5).contains(&e) {
        let s = format!("{:.*}", (5 - e).clamp(0, 12) as usize, v);
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let m = v / 10f64.powi(e);
        let m = format!("{m:.3}");
        let m = m.trim_end_matches('0').trim_end_matches('.');
        format!("{m}e{e}")
    };
    s.replace('-', "−")
}

// ------------------------------------------------------------------------------------------ writer

/// An SVG document under construction.
struct Svg {
    out: String,
}

impl Svg {
    fn new(width: f64, height: f64, title: &str) -> Self {
        let mut out = String::with_capacity(64 * 1024);
        let _ = write!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" font-family=\"{FONT}\" fill=\"{INK}\">\n<title>{t}</title>\n\
             <rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n",
            w = num(width),
            h = num(height),
            t = escape(title),
        );
        Svg { out }
    }

    /// Text at (x, y) (the baseline); `anchor` is start, middle or end; `extra` more attributes.
    fn text(&mut self, x: f64, y: f64, size: f64, anchor: &str, extra: &str, content: &str) {
        let _ = writeln!(
            self.out,
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{anchor}\"{extra}>{}</text>",
            num(x),
            num(y),
            num(size),
            escape(content)
        );
    }

    /// Text rotated by −90° about its anchor point (a vertical axis title).
    fn vertical_text(&mut self, x: f64, y: f64, size: f64, content: &str) {
        let extra = format!(" transform=\"rotate(-90 {} {})\"", num(x), num(y));
        self.text(x, y, size, "middle", &extra, content);
    }

    /// A straight line from (x1, y1) to (x2, y2); `style` is (stroke colour, stroke width).
    fn line(&mut self, x1: f64, y1: f64, x2: f64, y2: f64, (stroke, width): (&str, f64)) {
        let _ = writeln!(
            self.out,
            "<path d=\"M{} {}L{} {}\" stroke=\"{stroke}\" stroke-width=\"{}\" fill=\"none\"/>",
            num(x1),
            num(y1),
            num(x2),
            num(y2),
            num(width)
        );
    }

    fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, attrs: &str) {
        let _ = writeln!(
            self.out,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" {attrs}/>",
            num(x),
            num(y),
            num(w),
            num(h)
        );
    }

    /// The figure's title, centred at x, its first baseline at y = 30.
    fn heading(&mut self, x: f64, heading: &Heading) {
        for (k, line) in heading.lines.iter().enumerate() {
            let y = 30.0 + k as f64 * (heading.size + 5.0);
            self.text(x, y, heading.size, "middle", " font-weight=\"bold\"", line);
        }
    }

    fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A figure title laid out in one or two lines.
struct Heading {
    lines: Vec<String>,
    size: f64,
    /// Height added by the second line, px.
    extra: f64,
}

/// Estimated width of bold text, px (an average glyph is about 0.62 em wide).
fn bold_width(text: &str, size: f64) -> f64 {
    text.chars().count() as f64 * 0.62 * size
}

/// Fits a title into `width` px: one line at 17 px if it fits, else two lines broken at a space
/// (preferably after "—", ":" or ",", or before "("), shrinking the font if a line is still too wide.
fn fit_title(title: &str, width: f64) -> Heading {
    const SIZE: f64 = 17.0;
    if bold_width(title, SIZE) <= width {
        return Heading { lines: vec![title.to_string()], size: SIZE, extra: 0.0 };
    }
    let chars: Vec<char> = title.chars().collect();
    let n = chars.len();
    let mut best: Option<(f64, usize)> = None;
    for i in 1..n.saturating_sub(1) {
        if chars[i] != ' ' {
            continue;
        }
        let longer = i.max(n - i - 1) as f64;
        let natural = matches!(chars[i - 1], '—' | ':' | ',' | ';') || chars[i + 1] == '(';
        let bonus = if natural { 0.15 * n as f64 } else { 0.0 };
        if best.is_none_or(|(score, _)| longer - bonus < score) {
            best = Some((longer - bonus, i));
        }
    }
    let lines = match best {
        Some((_, i)) => vec![chars[..i].iter().collect::<String>(), chars[i + 1..].iter().collect()],
        None => vec![title.to_string()],
    };
    let widest = lines.iter().map(|l| bold_width(l, 1.0)).fold(0.0, f64::max);
    let size = (width / widest.max(1.0)).clamp(9.0, SIZE);
    let extra = (lines.len() - 1) as f64 * (size + 5.0);
    Heading { lines, size, extra }
}

// -------------------------------------------------------------------------------------------- axes

/// A value axis mapped onto pixels: `lo` ↦ `p0`, `hi` ↦ `p1` (for vertical axes p0 is the bottom).
#[derive(Clone, Copy, Debug)]
struct Axis {
    lo: f64,
    hi: f64,
    log: bool,
    p0: f64,
    p1: f64,
}

impl Axis {
    fn pos(&self, v: f64) -> f64 {
        let (a, b, x) = if self.log { (self.lo.ln(), self.hi.ln(), v.ln()) } else { (self.lo, self.hi, v) };
        self.p0 + (x - a) / (b - a) * (self.p1 - self.p0)
    }

    /// Pixel position of ln v on a log axis.
    fn pos_ln(&self, ln_v: f64) -> f64 {
        let (a, b) = (self.lo.ln(), self.hi.ln());
        self.p0 + (ln_v - a) / (b - a) * (self.p1 - self.p0)
    }

    fn contains(&self, v: f64) -> bool {
        let tol = if self.log { 1e-9 * self.hi } else { 1e-9 * (self.hi - self.lo) };
        v.is_finite() && v >= self.lo - tol && v <= self.hi + tol
    }
}

/// The range of the positive finite values, widened if it is a single value.
fn log_range(values: &[f64]) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = 0.0f64;
    for &v in values.iter().filter(|v| v.is_finite() && **v > 0.0) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !(lo.is_finite() && hi > 0.0) {
        return (0.1, 1.0);
    }
    if hi / lo < 1.0 + 1e-9 {
        return (lo / 1.5, hi * 1.5);
    }
    (lo, hi)
}

/// Ticks of a log axis: (labelled, unlabelled). Labelled on 1-2-5 per decade, or on powers of
/// ten when that gives too many; at least two labelled ticks.
fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let inside = |v: f64| v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
    let (e0, e1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let with = |mantissas: &[f64]| -> Vec<f64> {
        let mut v = Vec::new();
        for e in e0..=e1 {
            for &m in mantissas {
                // Round to the decimal value so that labels read 0.002, not 0.0020000000000000005.
                let x = m * 10f64.powi(e);
                let x = format!("{x:.12e}").parse::<f64>().unwrap_or(x);
                if inside(x) {
                    v.push(x);
                }
            }
        }
        v
    };
    let one_two_five = with(&[1.0, 2.0, 5.0]);
    let all = with(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
    let major = if one_two_five.len() > 10 {
        let powers = with(&[1.0]);
        if powers.len() >= 2 {
            powers
        } else {
            one_two_five
        }
    } else if one_two_five.len() >= 2 {
        one_two_five
    } else if all.len() >= 2 {
        all.clone()
    } else {
        vec![lo, hi]
    };
    let minor = all.into_iter().filter(|v| !major.iter().any(|m| (m - v).abs() <= 1e-9 * v)).collect();
    (major, minor)
}

/// A "nice" step (1, 2 or 5 × 10ⁿ) giving about `target` intervals over `span`.
fn nice_step(span: f64, target: f64) -> f64 {
    let raw = (span / target).max(f64::MIN_POSITIVE);
    let mag = 10f64.powf(raw.log10().floor());
    let r = raw / mag;
    mag * if r <= 1.0 {
        1.0
    } else if r <= 2.0 {
        2.0
    } else if r <= 5.0 {
        5.0
    } else {
        10.0
    }
}

/// Ticks of a linear axis from `lo` to `hi` with the given step (snapped so zero prints as 0).
fn linear_ticks(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    if last < first || last - first > 1000 {
        return vec![];
    }
    (first..=last)
        .map(|i| {
            let v = i as f64 * step;
            let v = format!("{v:.12e}").parse::<f64>().unwrap_or(v);
            if v.abs() < 1e-12 * step {
                0.0
            } else {
                v
            }
        })
        .collect()
}

// --------------------------------------------------------------------------------- stability maps

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
    idx.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
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

/// An edge of the marching-squares grid: horizontal between (r, c) and (r, c + 1), vertical
/// between (r, c) and (r + 1, c), in sorted grid indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum GridEdge {
    H(usize, usize),
    V(usize, usize),
}

/// The ρ = 1 contour of a map as polylines in pixel coordinates (marching squares on the grid in
/// log δ, log α, with linear interpolation of ρ along cell edges; saddles are split by the mean
/// of the four corners). Cells with a NaN or infinite corner are skipped.
fn rho_contour(panel: &MapPanel) -> Vec<(Vec<(f64, f64)>, bool)> {
    let map = panel.map;
    let cols = sorted_positive(&map.sampling_periods);
    let rows = sorted_positive(&map.alphas);
    let nd = map.sampling_periods.len();
    if cols.len() < 2 || rows.len() < 2 || map.spectral_radius.len() < nd * map.alphas.len() {
        return vec![];
    }
    let value = |r: usize, c: usize| map.spectral_radius[rows[r] * nd + cols[c]] - 1.0;
    let xs: Vec<f64> = cols.iter().map(|&c| map.sampling_periods[c].ln()).collect();
    let ys: Vec<f64> = rows.iter().map(|&r| map.alphas[r].ln()).collect();
    let crossing = |e: GridEdge| -> (f64, f64) {
        let ((r0, c0), (r1, c1)) = match e {
            GridEdge::H(r, c) => ((r, c), (r, c + 1)),
            GridEdge::V(r, c) => ((r, c), (r + 1, c)),
        };
        let (v0, v1) = (value(r0, c0), value(r1, c1));
        let t = (v0 / (v0 - v1)).clamp(0.0, 1.0);
        let lx = xs[c0] + t * (xs[c1] - xs[c0]);
        let ly = ys[r0] + t * (ys[r1] - ys[r0]);
        (panel.x.pos_ln(lx), panel.y.pos_ln(ly))
    };
    let mut segments: Vec<(GridEdge, GridEdge)> = Vec::new();
    for r in 0..rows.len() - 1 {
        for c in 0..cols.len() - 1 {
            let corners = [value(r, c), value(r, c + 1), value(r + 1, c + 1), value(r + 1, c)];
            if corners.iter().any(|v| !v.is_finite()) {
                continue;
            }
            let above = corners.map(|v| v >= 0.0);
            // Cell sides in order bottom, right, top, left, each between consecutive corners.
            let sides = [GridEdge::H(r, c), GridEdge::V(r, c + 1), GridEdge::H(r + 1, c), GridEdge::V(r, c)];
            let cut: Vec<GridEdge> = (0..4).filter(|&k| above[k] != above[(k + 1) % 4]).map(|k| sides[k]).collect();
            match cut.len() {
                2 => segments.push((cut[0], cut[1])),
                4 => {
                    let centre_above = corners.iter().sum::<f64>() / 4.0 >= 0.0;
                    let [bottom, right, top, left] = sides;
                    if centre_above == above[0] {
                        segments.push((bottom, right));
                        segments.push((top, left));
                    } else {
                        segments.push((bottom, left));
                        segments.push((right, top));
                    }
                }
                _ => {}
            }
        }
    }
    // Join the segments into polylines: each crossing point belongs to at most two segments.
    let mut at: BTreeMap<GridEdge, Vec<usize>> = BTreeMap::new();
    for (i, &(a, b)) in segments.iter().enumerate() {
        at.entry(a).or_default().push(i);
        at.entry(b).or_default().push(i);
    }
    let mut used = vec![false; segments.len()];
    let mut starts: Vec<GridEdge> = at.iter().filter(|(_, s)| s.len() == 1).map(|(e, _)| *e).collect();
    starts.extend(segments.iter().map(|s| s.0));
    let mut lines = Vec::new();
    for start in starts {
        let mut chain = vec![start];
        let mut current = start;
        while let Some(&i) = at.get(&current).and_then(|s| s.iter().find(|&&i| !used[i])) {
            used[i] = true;
            let (a, b) = segments[i];
            current = if a == current { b } else { a };
            chain.push(current);
        }
        if chain.len() >= 2 {
            let closed = chain.len() > 2 && chain.first() == chain.last();
            if closed {
                chain.pop();
            }
            let pts: Vec<(f64, f64)> =
                chain.into_iter().map(crossing).filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
            if pts.len() >= 2 {
                lines.push((pts, closed));
            }
        }
    }
    lines
}

const MAP_LEFT: f64 = 84.0;
const MAP_GAP: f64 = 100.0;
const MAP_WIDTH: f64 = 440.0;
const MAP_HEIGHT: f64 = 330.0;

/// A figure of ρ over (δ, α): logarithmic axes (δ [s] horizontal, α [1/s] vertical), cells
/// coloured by [`rho_colour`], the ρ = 1 contour, a colour bar, and a marker at `current`
/// (δ, α) if given and inside the grid.
pub fn stability_map_svg(map: &StabilityMap, title: &str, current: Option<(f64, f64)>) -> String {
    stability_maps_svg(&[(map, "")], title, current)
}

/// Several stability maps side by side with one shared colour bar, each under its own label
/// (e.g. without and with preliminary feedback); the marker, if any, is drawn on every panel.
pub fn stability_maps_svg(maps: &[(&StabilityMap, &str)], title: &str, current: Option<(f64, f64)>) -> String {
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
        draw_map_panel(&mut svg, panel, i, current);
    }
    colour_bar(&mut svg, bar_x, top, bottom);

    // Legend under the plots.
    let ly = bottom + 80.0;
    let lx = MAP_LEFT;
    svg.line(lx, ly - 4.0, lx + 28.0, ly - 4.0, (CONTOUR, 2.0));
    svg.text(lx + 36.0, ly, 13.0, "start", "", "ρ = 1: stability boundary (ρ < 1 ⇔ linearly stable)");
    if let Some((d, a)) = current.filter(|(d, a)| panels.iter().any(|p| p.x.contains(*d) && p.y.contains(*a))) {
        marker(&mut svg, lx + 14.0, ly + 18.0);
        let text = format!("marked: δ = {} s, α = {} 1/s", tick_label(d), tick_label(a));
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

fn draw_map_panel(svg: &mut Svg, p: &MapPanel, index: usize, current: Option<(f64, f64)>) {
    let (left, right, top, bottom) = (p.x.p0, p.x.p1, p.y.p1, p.y.p0);
    let map = p.map;
    if !p.label.is_empty() {
        svg.text((left + right) / 2.0, top - 12.0, 15.0, "middle", "", p.label);
    }
    // Cells with no value show the background.
    svg.rect(left, top, right - left, bottom - top, "fill=\"#d0d0d0\"");

    let cols = sorted_positive(&map.sampling_periods);
    let rows = sorted_positive(&map.alphas);
    let nd = map.sampling_periods.len();
    let xe = cell_edges(&map.sampling_periods, &cols, &p.x);
    let ye = cell_edges(&map.alphas, &rows, &p.y);
    let _ = writeln!(svg.out, "<g shape-rendering=\"crispEdges\" stroke=\"none\">");
    for (ri, &r) in rows.iter().enumerate() {
        let (y0, y1) = (ye[ri + 1], ye[ri]);
        let mut run: Option<(f64, String)> = None;
        let flush = |svg: &mut Svg, run: &mut Option<(f64, String)>, x_end: f64| {
            if let Some((x_start, fill)) = run.take() {
                svg.rect(x_start, y0, x_end - x_start, y1 - y0, &format!("fill=\"{fill}\""));
            }
        };
        for (ci, &c) in cols.iter().enumerate() {
            let fill = map.spectral_radius.get(r * nd + c).and_then(|&rho| rho_colour(rho)).map(hex);
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
            "<path id=\"rho-contour-{index}\" d=\"{d}\" fill=\"none\" stroke=\"{CONTOUR}\" stroke-width=\"2\" \
             stroke-linejoin=\"round\" stroke-linecap=\"round\"/>"
        );
    }

    // Frame, ticks and labels.
    svg.rect(left, top, right - left, bottom - top, &format!("fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\""));
    let (xmaj, xmin) = log_ticks(p.x.lo, p.x.hi);
    let (ymaj, ymin) = log_ticks(p.y.lo, p.y.hi);
    let mut ticks = String::new();
    for (v, len) in xmaj.iter().map(|v| (v, 6.0)).chain(xmin.iter().map(|v| (v, 3.0))) {
        let x = p.x.pos(*v);
        let _ = write!(ticks, "M{} {}v{}", num(x), num(bottom), num(len));
    }
    for (v, len) in ymaj.iter().map(|v| (v, 6.0)).chain(ymin.iter().map(|v| (v, 3.0))) {
        let y = p.y.pos(*v);
        let _ = write!(ticks, "M{} {}h{}", num(left), num(y), num(-len));
    }
    let _ = writeln!(svg.out, "<path d=\"{ticks}\" stroke=\"{INK}\" stroke-width=\"1\" fill=\"none\"/>");
    for v in &xmaj {
        svg.text(p.x.pos(*v), bottom + 21.0, 13.0, "middle", "", &tick_label(*v));
    }
    for v in &ymaj {
        svg.text(left - 9.0, p.y.pos(*v), 13.0, "end", " dy=\"0.35em\"", &tick_label(*v));
    }
    svg.text((left + right) / 2.0, bottom + 48.0, 14.0, "middle", "", "sampling period δ [s]");
    svg.vertical_text(left - 56.0, (top + bottom) / 2.0, 14.0, "stabilizing constant α [1/s]");

    if let Some((d, a)) = current {
        if d > 0.0 && a > 0.0 && p.x.contains(d) && p.y.contains(a) {
            marker(svg, p.x.pos(d), p.y.pos(a));
        }
    }
}

/// The vertical colour bar from `top` to `bottom` at x, labelled "ρ (spectral radius)".
fn colour_bar(svg: &mut Svg, x: f64, top: f64, bottom: f64) {
    let w = 18.0;
    let _ = write!(svg.out, "<defs><linearGradient id=\"rho-colour-bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">");
    for (pos, _) in COLOUR_STOPS {
        let _ = write!(svg.out, "<stop offset=\"{}\" stop-color=\"{}\"/>", num(pos), hex(colour_at(pos)));
    }
    let _ = writeln!(svg.out, "</linearGradient></defs>");
    svg.rect(x, top, w, bottom - top, "fill=\"url(#rho-colour-bar)\"");
    svg.rect(x, top, w, bottom - top, &format!("fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\""));
    let y_of = |rho: f64| bottom - colour_position(rho) * (bottom - top);
    let ticks = [RHO_COLOUR_MIN, 0.9, 0.95, 0.98, 1.0, 1.02, 1.05, 1.1, RHO_COLOUR_MAX];
    for (k, &rho) in ticks.iter().enumerate() {
        let y = y_of(rho);
        svg.line(x + w, y, x + w + 5.0, y, (INK, 1.0));
        let label = match k {
            0 => format!("≤ {}", tick_label(rho)),
            k if k == ticks.len() - 1 => format!("≥ {}", tick_label(rho)),
            _ => tick_label(rho),
        };
        svg.text(x + w + 8.0, y, 13.0, "start", " dy=\"0.35em\"", &label);
    }
    // ρ = 1 is drawn like the contour.
    let y1 = y_of(1.0);
    svg.line(x - 3.0, y1, x + w, y1, (CONTOUR, 2.0));
    svg.text(x + w / 2.0, top - 8.0, 12.0, "middle", "", "unstable");
    svg.text(x + w / 2.0, bottom + 18.0, 12.0, "middle", "", "stable");
    svg.vertical_text(x + w + 72.0, (top + bottom) / 2.0, 14.0, "ρ (spectral radius)");
}

// ---------------------------------------------------------------------------------- error traces

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
/// a legend. Long traces are decimated to at most [`MAX_TRACE_POINTS`] points per line.
pub fn error_traces_svg(traces: &Traces, title: &str) -> String {
    let width = TRACE_LEFT + TRACE_WIDTH + 30.0;
    let heading = fit_title(title, width - 40.0);
    let dy = heading.extra;
    let height = 580.0 + dy;
    let tops = [78.0 + dy, 78.0 + dy + TRACE_PANEL + 34.0];
    let mut svg = Svg::new(width, height, title);
    svg.heading(width / 2.0, &heading);

    let finite_t: Vec<f64> = traces.t.iter().copied().filter(|v| v.is_finite()).collect();
    let (t0, t1) = match (finite_t.iter().copied().reduce(f64::min), finite_t.iter().copied().reduce(f64::max)) {
        (Some(a), Some(b)) if b > a => (a, b),
        (Some(a), _) => (a, a + 1.0),
        _ => (0.0, 1.0),
    };
    let tx = Axis { lo: t0, hi: t1, log: false, p0: TRACE_LEFT, p1: TRACE_LEFT + TRACE_WIDTH };
    let t_ticks = linear_ticks(t0, t1, nice_step(t1 - t0, 8.0));

    let series: [(&[f64], &str, &str); 2] =
        [(&traces.e1, "e1", "link 1 error e1"), (&traces.e2, "e2", "link 2 error e2")];
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
        let step = nice_step(hi - lo, 5.0);
        let (lo, hi) = ((lo / step - 1e-9).floor() * step, (hi / step + 1e-9).ceil() * step);
        let ya = Axis { lo, hi, log: false, p0: bottom, p1: top };
        let y_ticks = linear_ticks(lo, hi, step);

        // Grid, zero line, frame.
        let mut grid = String::new();
        for v in &t_ticks {
            let _ = write!(grid, "M{} {}V{}", num(tx.pos(*v)), num(top), num(bottom));
        }
        for v in y_ticks.iter().filter(|v| **v != 0.0) {
            let _ = write!(grid, "M{} {}H{}", num(tx.p0), num(ya.pos(*v)), num(tx.p1));
        }
        let _ = writeln!(svg.out, "<path d=\"{grid}\" stroke=\"{GRID}\" stroke-width=\"1\" fill=\"none\"/>");
        svg.line(tx.p0, ya.pos(0.0), tx.p1, ya.pos(0.0), ("#8a8a8a", 1.2));

        // The trace.
        let mut d = String::new();
        for run in decimate(&traces.t, &scaled, MAX_TRACE_POINTS) {
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
                TRACE_COLOURS[k]
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
            svg.text(tx.p0 - 8.0, ya.pos(*v), 13.0, "end", " dy=\"0.35em\"", &tick_label(*v));
        }
        svg.vertical_text(tx.p0 - 62.0, (top + bottom) / 2.0, 14.0, &format!("{name} [{unit}]"));
        if k == 1 {
            for v in &t_ticks {
                svg.text(tx.pos(*v), bottom + 20.0, 13.0, "middle", "", &tick_label(*v));
            }
            svg.text((tx.p0 + tx.p1) / 2.0, bottom + 46.0, 14.0, "middle", "", "time t [s]");
        }

        // Legend entry, top right above the panels.
        let lx = tx.p1 - 330.0 + 170.0 * k as f64;
        svg.line(lx, 56.0 + dy, lx + 26.0, 56.0 + dy, (TRACE_COLOURS[k], 2.5));
        svg.text(lx + 32.0, 60.5 + dy, 13.0, "start", "", legend);
    }
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::log_space;

    /// A synthetic map: ρ = 1 on the circle of radius 1 around the grid's centre in log space.
    fn synthetic_map() -> StabilityMap {
        let deltas = log_space(0.002, 0.25, 30);
        let alphas = log_space(0.1, 5.0, 20);
        let (cx, cy) = ((0.002f64.ln() + 0.25f64.ln()) / 2.0, (0.1f64.ln() + 5.0f64.ln()) / 2.0);
        let mut rho = Vec::new();
        for a in &alphas {
            for d in &deltas {
                let r2 = (d.ln() - cx).powi(2) + (a.ln() - cy).powi(2);
                rho.push(0.8 + 0.2 * r2);
            }
        }
        StabilityMap { sampling_periods: deltas, alphas, spectral_radius: rho }
    }

    fn count(s: &str, pat: &str) -> usize {
        s.matches(pat).count()
    }

    fn assert_wellformed(svg: &str) {
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""), "{}", &svg[..80.min(svg.len())]);
        assert!(svg.trim_end().ends_with("</svg>"));
        assert_eq!(count(svg, "<svg"), 1);
        assert!(svg.contains("viewBox=\"0 0 ") && svg.contains("width=\"") && svg.contains("height=\""));
        // Paired elements open and close equally often; the others are self-closing.
        for tag in ["text", "g", "title", "defs", "linearGradient"] {
            assert_eq!(
                count(svg, &format!("<{tag}>")) + count(svg, &format!("<{tag} ")),
                count(svg, &format!("</{tag}>")),
                "<{tag}>"
            );
        }
        for tag in ["path", "rect", "circle", "stop"] {
            let opened = count(svg, &format!("<{tag} "));
            let closed = svg
                .split(&format!("<{tag} "))
                .skip(1)
                .filter(|rest| rest.split('>').next().unwrap().ends_with('/'))
                .count();
            assert_eq!(opened, closed, "every <{tag}> is self-closing");
        }
        assert_eq!(count(svg, "<"), count(svg, ">"), "angle brackets balance (text is escaped)");
        for bad in ["NaN", "inf", "Infinity"] {
            assert!(!svg.contains(bad), "{bad} in the output");
        }
    }

    #[test]
    fn map_figure_is_wellformed_with_axes_colour_bar_contour_and_marker() {
        let map = synthetic_map();
        let svg = stability_map_svg(&map, "ρ <map> & more", Some((0.01, 2.0)));
        assert_wellformed(&svg);
        assert!(svg.contains("sampling period δ [s]"));
        assert!(svg.contains("stabilizing constant α [1/s]"));
        assert!(svg.contains("ρ (spectral radius)"));
        assert!(svg.contains("ρ &lt;map&gt; &amp; more"), "title escaped");
        assert!(!svg.contains("<map>"));
        let contour = svg.split("id=\"rho-contour-0\" d=\"").nth(1).expect("a contour path");
        let d = contour.split('"').next().unwrap();
        // A closed ring: one subpath, many vertices, closed.
        assert_eq!(count(d, "M"), 1, "{d}");
        assert!(count(d, "L") > 20 && d.ends_with('Z'), "{d}");
        assert!(svg.contains("<circle"), "the marker");
        // 1-2-5 tick labels per decade.
        for label in
            [">0.002<", ">0.005<", ">0.01<", ">0.02<", ">0.05<", ">0.1<", ">0.2<", ">0.5<", ">1<", ">2<", ">5<"]
        {
            assert!(svg.contains(label), "tick {label}");
        }
    }

    #[test]
    fn contour_points_lie_on_the_unit_level() {
        let map = synthetic_map();
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
        let (cx, cy) = ((dl.ln() + dh.ln()) / 2.0, (al.ln() + ah.ln()) / 2.0);
        for &(x, y) in &lines[0].0 {
            let lx = dl.ln() + x * (dh.ln() - dl.ln());
            let ly = al.ln() + y * (ah.ln() - al.ln());
            let r = ((lx - cx).powi(2) + (ly - cy).powi(2)).sqrt();
            // Linear interpolation of a quadratic on a coarse grid: within a few per cent.
            assert!((r - 1.0).abs() < 0.05, "radius {r}");
        }
    }

    #[test]
    fn nan_cells_and_points_are_skipped() {
        let mut map = synthetic_map();
        map.spectral_radius[5] = f64::NAN;
        map.spectral_radius[77] = f64::INFINITY;
        let svg = stability_map_svg(&map, "t", Some((f64::NAN, 2.0)));
        assert_wellformed(&svg);
        let svg = stability_maps_svg(&[(&map, "a"), (&map, "b")], "two", None);
        assert_wellformed(&svg);
        assert!(svg.contains("rho-contour-1"));
        // Degenerate grids still give a valid document.
        let single = StabilityMap { sampling_periods: vec![0.01], alphas: vec![2.0], spectral_radius: vec![0.9] };
        assert_wellformed(&stability_map_svg(&single, "one cell", None));
        let empty = StabilityMap { sampling_periods: vec![], alphas: vec![], spectral_radius: vec![] };
        assert_wellformed(&stability_map_svg(&empty, "empty", None));
    }

    #[test]
    fn colours_diverge_around_one() {
        assert_eq!(rho_colour(1.0), Some([248, 248, 248]));
        let blue = rho_colour(0.5).unwrap();
        let red = rho_colour(2.0).unwrap();
        assert!(blue[2] > blue[0] && red[0] > red[2]);
        assert_eq!(rho_colour(0.8), rho_colour(0.1));
        assert_eq!(rho_colour(f64::NAN), None);
    }

    fn traces(n: usize, amplitude: f64) -> Traces {
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.002).collect();
        let e1 = t.iter().map(|t| amplitude * (30.0 * t).sin() * (0.03 * t).exp()).collect();
        let e2 = t.iter().map(|t| -0.5 * amplitude * (7.0 * t).cos()).collect();
        Traces { t, e1, e2, ..Default::default() }
    }

    #[test]
    fn traces_figure_is_wellformed_with_units_legend_and_decimation() {
        let tr = traces(30_000, 2e-3);
        let svg = error_traces_svg(&tr, "δ = 0.01 s & PF <off>");
        assert_wellformed(&svg);
        assert!(svg.contains("time t [s]"));
        assert!(svg.contains("e1 [mrad]") && svg.contains("e2 [mrad]"), "errors in mrad for mrad-sized traces");
        assert!(svg.contains("link 1 error e1") && svg.contains("link 2 error e2"), "legend");
        assert!(svg.contains("δ = 0.01 s &amp; PF &lt;off&gt;"));
        for name in ["e1", "e2"] {
            let d = svg.split(&format!("id=\"trace-{name}\" d=\"")).nth(1).unwrap().split('"').next().unwrap();
            let points = count(d, "M") + count(d, "L");
            assert!((1000..=MAX_TRACE_POINTS).contains(&points), "{name}: {points} points");
        }
        // The envelope survives decimation: the largest |e1| is still drawn.
        let runs = decimate(&tr.t, &tr.e1, MAX_TRACE_POINTS);
        let max_drawn = runs.iter().flatten().fold(0.0f64, |m, p| m.max(p.1.abs()));
        let max_all = tr.e1.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert_eq!(max_drawn, max_all);
    }

    #[test]
    fn traces_with_gaps_large_values_or_nothing_are_valid() {
        let mut tr = traces(500, 1.5);
        tr.e1[100] = f64::NAN;
        tr.e2[200] = f64::INFINITY;
        let svg = error_traces_svg(&tr, "diverged");
        assert_wellformed(&svg);
        assert!(svg.contains("e1 [rad]"));
        let d = svg.split("id=\"trace-e1\" d=\"").nth(1).unwrap().split('"').next().unwrap();
        assert_eq!(count(d, "M"), 2, "the NaN splits the line");
        assert_wellformed(&error_traces_svg(&Traces::default(), "empty"));
        assert_wellformed(&error_traces_svg(&traces(1, 0.0), "one sample"));
    }

    #[test]
    fn long_titles_wrap_into_two_lines() {
        let short = fit_title("ρ over (δ, α)", 600.0);
        assert_eq!((short.lines.len(), short.extra), (1, 0.0));
        let long = "Tracking errors: δ = 0.01 s, α = 2 1/s, PF off — diverged at t = 4.138 s (a tracking error \
                    exceeded 3.1416 rad)";
        let h = fit_title(long, 780.0);
        assert_eq!(h.lines.len(), 2);
        assert!(h.lines[0].ends_with('—'), "{:?}", h.lines);
        assert!(h.lines.iter().all(|l| bold_width(l, h.size) <= 780.0));
        let svg = error_traces_svg(&traces(10, 1e-3), long);
        assert_wellformed(&svg);
        assert!(svg.contains(">diverged at t = 4.138 s (a tracking error exceeded 3.1416 rad)</text>"));
    }

    #[test]
    fn ticks_are_nice() {
        let (major, minor) = log_ticks(0.002, 0.25);
        assert_eq!(major, vec![0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2]);
        assert!(minor.contains(&0.003) && minor.contains(&0.09));
        let (major, _) = log_ticks(1e-6, 1e3);
        assert_eq!(major.len(), 10, "powers of ten only: {major:?}");
        assert_eq!(log_ticks(0.03, 0.045).0.len(), 2);
        assert_eq!(linear_ticks(-0.3, 0.7, nice_step(1.0, 5.0)), vec![-0.2, 0.0, 0.2, 0.4, 0.6]);
        assert_eq!(tick_label(0.002), "0.002");
        assert_eq!(tick_label(-1.5), "−1.5");
        assert_eq!(tick_label(2e-7), "2e−7");
        assert_eq!(tick_label(250.0), "250");
        assert_eq!(escape("a<b & 'c' > \"d\""), "a&lt;b &amp; &#39;c&#39; &gt; &quot;d&quot;");
    }
}
