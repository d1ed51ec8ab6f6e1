//! Publication-ready SVG figures (stability maps, error traces) as plain strings, drawn from the
//! same [`crate::plot`] decisions as the page: the same ticks, number format, colour ramp and
//! contour tracer.
//!
//! The figures are standalone SVG 1.1 documents (no scripts, no external resources):
//! [`stability_maps_svg`] draws ρ over (δ, α) on logarithmic axes with the ρ = 1 contour and a
//! colour bar; [`error_traces_svg`] the tracking errors e1 and e2 over time in two stacked panels.
//! Each carries the state string of the settings it shows in its `<desc>`.
//!
//! Every number written is finite: cells, points and markers with NaN or infinite coordinates
//! are left out. Text is XML-escaped.

use std::fmt::Write as _;

mod map;
mod traces;

pub use map::{stability_map_svg, stability_maps_svg};
pub use traces::{error_traces_svg, MAX_TRACE_POINTS};

const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";
/// Text and frames.
pub(crate) const INK: &str = "#1a1a1a";

pub use crate::words::markup::escape;

/// A coordinate with two decimals, trailing zeros trimmed; never NaN or inf (callers skip those).
pub(crate) fn num(v: f64) -> String {
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

// ------------------------------------------------------------------------------------------ writer

/// An SVG document under construction.
pub(crate) struct Svg {
    pub(crate) out: String,
}

impl Svg {
    pub(crate) fn new(width: f64, height: f64, title: &str) -> Self {
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
    pub(crate) fn text(&mut self, x: f64, y: f64, size: f64, anchor: &str, extra: &str, content: &str) {
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
    pub(crate) fn vertical_text(&mut self, x: f64, y: f64, size: f64, content: &str) {
        let extra = format!(" transform=\"rotate(-90 {} {})\"", num(x), num(y));
        self.text(x, y, size, "middle", &extra, content);
    }

    /// A straight line from (x1, y1) to (x2, y2); `style` is (stroke colour, stroke width).
    pub(crate) fn line(&mut self, x1: f64, y1: f64, x2: f64, y2: f64, (stroke, width): (&str, f64)) {
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

    pub(crate) fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, attrs: &str) {
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
    pub(crate) fn heading(&mut self, x: f64, heading: &Heading) {
        for (k, line) in heading.lines.iter().enumerate() {
            let y = 30.0 + k as f64 * (heading.size + 5.0);
            self.text(x, y, heading.size, "middle", " font-weight=\"bold\"", line);
        }
    }

    pub(crate) fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A figure title laid out in one or two lines.
pub(crate) struct Heading {
    pub(crate) lines: Vec<String>,
    pub(crate) size: f64,
    /// Height added by the second line, px.
    pub(crate) extra: f64,
}

/// Estimated width of bold text, px (an average glyph is about 0.62 em wide).
pub(crate) fn bold_width(text: &str, size: f64) -> f64 {
    text.chars().count() as f64 * 0.62 * size
}

/// Fits a title into `width` px: one line at 17 px if it fits, else two lines broken at a space
/// (preferably after "—", ":" or ",", or before "("), shrinking the font if a line is still too wide.
pub(crate) fn fit_title(title: &str, width: f64) -> Heading {
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

impl Svg {
    /// The state string of the settings the figure shows, in its `<desc>`.
    pub(crate) fn describe(&mut self, state: Option<&str>) {
        if let Some(state) = state {
            let _ = writeln!(self.out, "<desc>flexarm state: {}</desc>", escape(state));
        }
    }
}

// -------------------------------------------------------------------------------------------- axes

/// A value axis mapped onto pixels: `lo` ↦ `p0`, `hi` ↦ `p1` (for vertical axes p0 is the bottom).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Axis {
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    pub(crate) log: bool,
    pub(crate) p0: f64,
    pub(crate) p1: f64,
}

impl Axis {
    pub(crate) fn pos(&self, v: f64) -> f64 {
        let (a, b, x) = if self.log { (self.lo.ln(), self.hi.ln(), v.ln()) } else { (self.lo, self.hi, v) };
        self.p0 + (x - a) / (b - a) * (self.p1 - self.p0)
    }

    /// Pixel position of ln v on a log axis.
    pub(crate) fn pos_ln(&self, ln_v: f64) -> f64 {
        let (a, b) = (self.lo.ln(), self.hi.ln());
        self.p0 + (ln_v - a) / (b - a) * (self.p1 - self.p0)
    }

    pub(crate) fn contains(&self, v: f64) -> bool {
        let tol = if self.log { 1e-9 * self.hi } else { 1e-9 * (self.hi - self.lo) };
        v.is_finite() && v >= self.lo - tol && v <= self.hi + tol
    }
}

/// The range of the positive finite values, widened if it is a single value.
pub(crate) fn log_range(values: &[f64]) -> (f64, f64) {
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
