//! The SVG writer of the figures: the painter's triangles as filled paths (consecutive triangles
//! of one colour merged into one path, coordinates rounded to 0.1 px), texts, and line breaking
//! by estimated width (the same estimate [`crate::view::labels`] places the canvas's labels by).

use core::fmt::Write as _;

use crate::plot::Color;
use crate::view::labels::{Label, LabelClass};
use crate::view::painter::Vertex;
use crate::view::text_metrics::{bold_width, text_width, LINE_HEIGHT};

pub(crate) use crate::plot::format::escape;

/// The figures' font: the widths of [`crate::view::labels`] are estimated for DejaVu Sans.
pub const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";
/// The state string's font: a monospace font, so that its lines' widths are certain.
pub const MONO: &str = "DejaVu Sans Mono, Menlo, Consolas, monospace";
/// Width of a monospace character, ems (DejaVu Sans Mono: 0.602; a little more for others).
pub const MONO_EM: f64 = 0.62;

/// The page's ink for titles and axes, its softer ink for ticks, a mark's ink and backing
/// (`www/style.css`: `--ink`, `--ink-soft`, `--mark-ink`, `--mark-bg`).
pub const INK: Color = Color::hex(0x1b2330);
pub const INK_SOFT: Color = Color::hex(0x4a5566);
pub const MARK_INK: Color = Color::hex(0x5c4200);
pub const MARK_BG: Color = Color([1.0, 1.0, 1.0, 0.85]);

/// A figure under construction.
pub struct Doc {
    pub out: String,
    /// The dark scheme: every colour's lightness inverted, as the canvas's shader does.
    pub dark: bool,
}

/// A length in tenths of a pixel, without a trailing ".0": "12", "12.5", "-0.3".
pub fn px(out: &mut String, v: f64) {
    let tenths = if v.is_finite() { (v * 10.0).round() as i64 } else { 0 };
    if tenths < 0 {
        out.push('-');
    }
    let a = tenths.unsigned_abs();
    let _ = write!(out, "{}", a / 10);
    if a % 10 != 0 {
        out.push('.');
        out.push((b'0' + (a % 10) as u8) as char);
    }
}

/// A figure's background for a slide: the page's paper, white, or none (the slide's own shows).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Background {
    #[default]
    Page,
    White,
    Transparent,
}

impl Doc {
    /// The document's head: size (`width` × `height` in its own units, `scale` px each: a larger
    /// text size lays the figure out smaller and draws it that much larger), title, the state
    /// string in its description, the background (`page`: `background` in the scheme; white:
    /// white whatever the scheme; transparent: none).
    pub fn new(
        [width, height, scale]: [f64; 3],
        title: &str,
        state: &str,
        background: (Color, Background),
        dark: bool,
    ) -> Doc {
        let mut doc = Doc { out: String::with_capacity(256 * 1024), dark };
        let o = &mut doc.out;
        o.push_str("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"");
        px(o, (width * scale).round());
        o.push_str("\" height=\"");
        px(o, (height * scale).round());
        o.push_str("\" viewBox=\"0 0 ");
        px(o, width);
        o.push(' ');
        px(o, height);
        let _ = write!(o, "\" font-family=\"{FONT}\">\n<title>{}</title>\n", escape(title));
        let _ = writeln!(o, "<desc>flexarm state: {}</desc>", escape(state));
        let (paper, choice) = background;
        if choice == Background::Transparent {
            return doc;
        }
        let _ = write!(o, "<rect id=\"background\" x=\"0\" y=\"0\" width=\"");
        px(o, width);
        o.push_str("\" height=\"");
        px(o, height);
        o.push('"');
        if choice == Background::White {
            doc.out.push_str(" fill=\"#ffffff\"");
        } else {
            doc.fill(paper);
        }
        doc.out.push_str("/>\n");
        doc
    }

    /// The colour as drawn in this scheme.
    pub fn color(&self, c: Color) -> Color {
        if self.dark {
            c.for_dark()
        } else {
            c
        }
    }

    /// ` fill="#rrggbb"` and its opacity where not opaque.
    pub fn fill(&mut self, c: Color) {
        self.paint("fill", c);
    }

    fn paint(&mut self, what: &str, c: Color) {
        let c = self.color(c);
        let _ = write!(self.out, " {what}=\"{}\"", c.with_alpha(1.0).css());
        if c.0[3] < 1.0 {
            let _ = write!(self.out, " {what}-opacity=\"{}\"", (c.0[3].clamp(0.0, 1.0) * 1000.0).round() / 1000.0);
        }
    }

    /// The triangles as filled paths: a run of triangles of one colour (as written: 8 bits a
    /// channel) is one path, each triangle turned the same way round so that the path fills their
    /// union; the two triangles of an axis-aligned rectangle are written as one rectangle, joined
    /// with the next one of its colour in the same row (a map's cells); triangles that round to
    /// nothing are left out.
    ///
    /// `overlap` (px) widens each rectangle right and down: a map's cells then cover the hairline
    /// seams a rasterizer leaves between abutting shapes (each later cell covers the overlap).
    pub fn triangles(&mut self, vertices: &[Vertex], overlap: f64) {
        let mut w = PathRun { color: None, d: String::new(), row: None, slanted: false, crisp: false };
        let tris: Vec<&[Vertex]> = vertices.chunks_exact(3).collect();
        let mut i = 0;
        while i < tris.len() {
            let t = tris[i];
            let color = rgba_key(t[0].color);
            if let Some(mut r) = tris.get(i + 1).and_then(|u| as_rect(t, u)) {
                r[2] += overlap;
                r[3] += overlap;
                w.switch(self, Some(color));
                match &mut w.row {
                    Some(row) if row[1] == r[1] && row[3] == r[3] && (row[2] - overlap - r[0]).abs() < 0.05 => {
                        row[2] = r[2]
                    }
                    _ => {
                        w.end_row();
                        w.row = Some(r);
                    }
                }
                i += 2;
                continue;
            }
            i += 1;
            let p = |i: usize| [t[i].position[0] as f64, t[i].position[1] as f64];
            let (a, mut b, mut c) = (p(0), p(1), p(2));
            if !(a.iter().chain(&b).chain(&c).all(|v| v.is_finite())) {
                continue;
            }
            let cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            if cross.abs() < 0.005 {
                continue;
            }
            if cross < 0.0 {
                core::mem::swap(&mut b, &mut c);
            }
            w.switch(self, Some(color));
            w.end_row();
            w.slanted = true;
            for (k, q) in [a, b, c].iter().enumerate() {
                w.d.push(if k == 0 {
                    'M'
                } else if k == 1 {
                    'L'
                } else {
                    ' '
                });
                px(&mut w.d, q[0]);
                w.d.push(' ');
                px(&mut w.d, q[1]);
            }
            w.d.push('Z');
        }
        w.switch(self, None);
        if w.crisp {
            self.out.push_str("</g>\n");
        }
    }

    /// A text with its baseline at y; `anchor` start, middle or end; `weight` 400, 600 or 700.
    #[allow(clippy::too_many_arguments)]
    pub fn text(
        &mut self,
        x: f64,
        y: f64,
        size: f64,
        anchor: &str,
        weight: u16,
        color: Color,
        class: &str,
        text: &str,
    ) {
        self.out.push_str("<text class=\"");
        self.out.push_str(class);
        self.out.push_str("\" x=\"");
        px(&mut self.out, x);
        self.out.push_str("\" y=\"");
        px(&mut self.out, y);
        self.out.push_str("\" font-size=\"");
        px(&mut self.out, size);
        self.out.push('"');
        if anchor != "start" {
            let _ = write!(self.out, " text-anchor=\"{anchor}\"");
        }
        if weight != 400 {
            let _ = write!(self.out, " font-weight=\"{weight}\"");
        }
        self.fill(color);
        let _ = writeln!(self.out, ">{}</text>", escape(text));
    }

    /// A label placed by [`crate::view::labels`], as the page shows it: its box's alignment point
    /// on its anchor, the page's weight and ink for its class (a mark on its light backing).
    pub fn label(&mut self, l: &Label) {
        let (weight, color) = match l.class {
            LabelClass::Tick => (400, INK_SOFT),
            LabelClass::Axis | LabelClass::Note => (600, INK),
            LabelClass::Title => (700, INK),
            LabelClass::Mark => (600, MARK_INK),
        };
        let bold = weight > 400;
        let w = if bold { bold_width(&l.text, l.size) } else { text_width(&l.text, l.size) };
        let h = l.size * LINE_HEIGHT;
        let (left, top) = (l.x - l.align[0] * w, l.y - l.align[1] * h);
        if l.class == LabelClass::Mark {
            self.rect(left - 2.0, top, w + 4.0, h, MARK_BG);
        }
        let (x, anchor) = match l.align[0] {
            a if a < 0.25 => (left, "start"),
            a if a > 0.75 => (left + w, "end"),
            _ => (left + w / 2.0, "middle"),
        };
        // The alphabetic baseline in a line box of 1.3 em (DejaVu Sans: ascent 0.93 em, descent
        // 0.24 em, centred in the box).
        let baseline = top + (LINE_HEIGHT - 1.17) / 2.0 * l.size + 0.93 * l.size;
        let class = match l.class {
            LabelClass::Tick => "tick",
            LabelClass::Axis => "axis",
            LabelClass::Title => "title",
            LabelClass::Note => "note",
            LabelClass::Mark => "mark",
        };
        self.text(x, baseline, l.size, anchor, weight, color, class, &l.text);
    }

    /// A filled rectangle.
    pub fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, color: Color) {
        self.out.push_str("<rect x=\"");
        px(&mut self.out, x);
        self.out.push_str("\" y=\"");
        px(&mut self.out, y);
        self.out.push_str("\" width=\"");
        px(&mut self.out, w.max(0.0));
        self.out.push_str("\" height=\"");
        px(&mut self.out, h.max(0.0));
        self.out.push('"');
        self.fill(color);
        self.out.push_str("/>\n");
    }

    pub fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A colour as written (8 bits a channel): consecutive triangles that look the same share a path.
fn rgba_key(c: [f32; 4]) -> u32 {
    let b = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u32;
    (b(c[0]) << 24) | (b(c[1]) << 16) | (b(c[2]) << 8) | b(c[3])
}

/// Two triangles that make the axis-aligned rectangle [`crate::view::painter::Painter::rect`]
/// draws — (a, b, c) and (a, c, d) — as [x0, y0, x1, y1], else None.
fn as_rect(t: &[Vertex], u: &[Vertex]) -> Option<[f64; 4]> {
    if t[0].color != u[0].color || t[0].position != u[0].position || t[2].position != u[1].position {
        return None;
    }
    let [a, b, c, d] = [t[0].position, t[1].position, t[2].position, u[2].position];
    let rect = a[1] == b[1] && b[0] == c[0] && c[1] == d[1] && d[0] == a[0] && a[0] < b[0] && a[1] < d[1];
    rect.then(|| [a[0] as f64, a[1] as f64, c[0] as f64, c[1] as f64])
}

/// The path being written: its colour, its data, and a row of rectangles not yet written.
struct PathRun {
    color: Option<u32>,
    d: String,
    row: Option<[f64; 4]>,
    /// The path holds a triangle: antialiased; rectangles alone are drawn with crisp edges, so
    /// that a map's cells show no seams between them.
    slanted: bool,
    /// A group of crisp paths is open.
    crisp: bool,
}

impl PathRun {
    /// Writes the pending rectangle into the path data.
    fn end_row(&mut self) {
        if let Some([x0, y0, x1, y1]) = self.row.take() {
            // Relative lengths: the shortest text (a map has thousands of cells).
            let (x0, y0) = ((x0 * 10.0).round() / 10.0, (y0 * 10.0).round() / 10.0);
            let (w, h) = ((x1 - x0) as f32 as f64, (y1 - y0) as f32 as f64);
            self.d.push('M');
            px(&mut self.d, x0);
            self.d.push(' ');
            px(&mut self.d, y0);
            self.d.push('h');
            px(&mut self.d, w);
            self.d.push('v');
            px(&mut self.d, h);
            self.d.push('h');
            px(&mut self.d, -w);
            self.d.push('z');
        }
    }

    /// Goes on in `color`: a new colour writes the path so far.
    fn switch(&mut self, doc: &mut Doc, color: Option<u32>) {
        if color == self.color {
            return;
        }
        self.end_row();
        if let (Some(c), false) = (self.color, self.d.is_empty()) {
            if self.crisp == self.slanted {
                doc.out.push_str(if self.crisp { "</g>\n" } else { "<g shape-rendering=\"crispEdges\">\n" });
                self.crisp = !self.crisp;
            }
            doc.out.push_str("<path d=\"");
            doc.out.push_str(&self.d);
            doc.out.push('"');
            let ch = |k: u32| ((c >> k) & 0xff) as f32 / 255.0;
            doc.fill(Color([ch(24), ch(16), ch(8), ch(0)]));
            doc.out.push_str("/>\n");
        }
        self.d.clear();
        self.slanted = false;
        self.color = color;
    }
}

/// `text` broken into lines at most `width` px wide as `measure` estimates them: after any of
/// `breaks` where possible, else inside a word (never cut: the lines put together are `text`).
pub fn break_lines(text: &str, width: f64, measure: &dyn Fn(&str) -> f64, breaks: &[char]) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    let mut piece = String::new();
    let mut pieces: Vec<String> = Vec::new();
    for c in text.chars() {
        piece.push(c);
        if breaks.contains(&c) {
            pieces.push(core::mem::take(&mut piece));
        }
    }
    if !piece.is_empty() {
        pieces.push(piece);
    }
    for piece in pieces {
        let joined = format!("{line}{piece}");
        if measure(joined.trim_end()) <= width {
            line = joined;
            continue;
        }
        if !line.is_empty() {
            lines.push(core::mem::take(&mut line));
        }
        // A piece too long for a line of its own is broken between characters.
        for c in piece.chars() {
            line.push(c);
            if measure(line.trim_end()) > width && line.chars().count() > 1 {
                line.pop();
                lines.push(core::mem::take(&mut line));
                line.push(c);
            }
        }
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// Prose broken at spaces for a width, each line without its trailing space.
pub fn wrap(text: &str, width: f64, size: f64, bold: bool) -> Vec<String> {
    let measure = |s: &str| if bold { bold_width(s, size) } else { text_width(s, size) };
    break_lines(text, width, &measure, &[' ']).into_iter().map(|l| l.trim_end().to_string()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tenths_are_written_short() {
        let mut s = String::new();
        for v in [12.0, 12.54, -0.26, 0.04, -0.04, f64::NAN] {
            px(&mut s, v);
            s.push(',');
        }
        assert_eq!(s, "12,12.5,-0.3,0,0,0,");
    }

    #[test]
    fn lines_put_together_give_the_text() {
        let text = "delta=0.01&alpha=2&pf=off&averyveryveryverylongvalueindeedthatcannotfit=1&x=2";
        let measure = |s: &str| s.chars().count() as f64;
        let lines = break_lines(text, 20.0, &measure, &['&']);
        assert_eq!(lines.concat(), text);
        assert!(lines.iter().all(|l| l.chars().count() <= 20), "{lines:?}");
        assert_eq!(lines[0], "delta=0.01&alpha=2&");
    }
}
