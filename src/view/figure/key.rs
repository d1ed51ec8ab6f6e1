//! Under a figure's panels: its key (the legend groups of its panels, the glyphs as the page's key
//! draws them, the maps' colour bar) and its caption — what it shows, and the whole state string,
//! broken over as many lines as it needs and never cut.

use core::fmt::Write as _;

use super::svg::{break_lines, escape, px, wrap, Doc, INK, INK_SOFT, MONO, MONO_EM};
use crate::plot::{palette, Color};
use crate::view::legend::{Glyph, LegendGroup, LegendItem};

/// Font sizes of the key and the caption, px (those of the page's key).
const KEY_TITLE: f64 = 13.0;
const KEY_TEXT: f64 = 12.0;
const CAPTION: f64 = 12.0;
const STATE: f64 = 11.0;
/// Line pitch of the key's and caption's texts, in ems.
const PITCH: f64 = 1.35;
/// A key column's least width and the gap between columns, px.
const KEY_COLUMN: f64 = 300.0;
const KEY_COLUMN_GAP: f64 = 16.0;
/// The colour bar's size, px.
const BAR: (f64, f64) = (260.0, 12.0);

/// A glyph of the key, 14 × 14 px with its top-left at (x, y): the shapes of `www/js/legend.js`.
fn glyph(doc: &mut Doc, g: Glyph, color: &str, x: f64, y: f64) {
    let stroke = format!("stroke=\"{color}\" stroke-width=\"2\" fill=\"none\"");
    let shape = match g {
        Glyph::Cross => format!("<path d=\"M3 3L11 11M11 3L3 11\" {stroke}/>"),
        Glyph::Plus => format!("<path d=\"M7 2V12M2 7H12\" {stroke}/>"),
        Glyph::Ring => format!("<circle cx=\"7\" cy=\"7\" r=\"4.5\" {stroke}/>"),
        Glyph::Diamond => format!("<path d=\"M7 2L12 7L7 12L2 7Z\" {stroke}/>"),
        Glyph::Halo => format!("<circle cx=\"7\" cy=\"7\" r=\"6\" fill=\"{color}\"/>"),
        Glyph::Line => format!("<path d=\"M1 7H13\" {stroke}/>"),
        Glyph::Dashed => format!("<path d=\"M1 7H13\" {stroke} stroke-dasharray=\"3 2\"/>"),
        Glyph::Swatch => {
            format!("<rect x=\"1\" y=\"2\" width=\"12\" height=\"10\" fill=\"{color}\" stroke=\"#9aa0a8\"/>")
        }
        Glyph::Chevron => format!("<path d=\"M10 2L4 7L10 12\" {stroke}/>"),
    };
    doc.out.push_str("<g transform=\"translate(");
    px(&mut doc.out, x);
    doc.out.push(' ');
    px(&mut doc.out, y);
    let _ = writeln!(doc.out, ")\">{shape}</g>");
}

/// The key's height for `width` px, and (with a document) the key drawn from `top`.
pub fn key(doc: Option<&mut Doc>, groups: &[LegendGroup], x: f64, top: f64, width: f64) -> f64 {
    let mut doc = doc;
    let mut y = top;
    for g in groups {
        y += KEY_TITLE * PITCH;
        if let Some(d) = doc.as_deref_mut() {
            d.text(x, y - 0.3 * KEY_TITLE, KEY_TITLE, "start", 700, INK, "key-title", g.title);
        }
        // A wide figure (a slide) sets the items in columns, filled top to bottom: the key then
        // takes less of its height.
        let columns = ((width / KEY_COLUMN).floor() as usize).clamp(1, 3).min(g.items.len().max(1));
        let per_column = g.items.len().div_ceil(columns);
        let column_width = (width - (columns - 1) as f64 * KEY_COLUMN_GAP) / columns as f64;
        let mut bottom = y;
        for (c, items) in g.items.chunks(per_column.max(1)).enumerate() {
            let left = x + c as f64 * (column_width + KEY_COLUMN_GAP);
            let mut yc = y;
            for item in items {
                let lines = wrap(&item.text, column_width - 22.0, KEY_TEXT, false);
                if let Some(d) = doc.as_deref_mut() {
                    let color = if d.dark { item.dark.as_str() } else { item.color.as_str() };
                    glyph(d, item.glyph, color, left + 2.0, yc + 2.0);
                    for (k, line) in lines.iter().enumerate() {
                        let base = yc + KEY_TEXT + k as f64 * KEY_TEXT * PITCH;
                        d.text(left + 22.0, base, KEY_TEXT, "start", 400, INK, "key", line);
                    }
                }
                yc += lines.len() as f64 * KEY_TEXT * PITCH + 3.0;
            }
            bottom = bottom.max(yc);
        }
        y = bottom;
        if let Some(scale) = &g.scale {
            let bar_x = x + 60.0;
            if let Some(d) = doc.as_deref_mut() {
                d.text(x, y + BAR.1, KEY_TITLE, "start", 700, INK, "key", scale.name);
                let id = format!("scale-{}", (y * 10.0).round());
                let stops = if d.dark { &scale.dark_stops } else { &scale.stops };
                let _ = write!(d.out, "<defs><linearGradient id=\"{id}\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\">");
                for (p, c) in stops {
                    let _ = write!(d.out, "<stop offset=\"{}\" stop-color=\"{c}\"/>", (p * 1000.0).round() / 1000.0);
                }
                let _ = writeln!(d.out, "</linearGradient></defs>");
                d.out.push_str("<rect x=\"");
                px(&mut d.out, bar_x);
                d.out.push_str("\" y=\"");
                px(&mut d.out, y + 2.0);
                let _ = writeln!(d.out, "\" width=\"{}\" height=\"{}\" fill=\"url(#{id})\"/>", BAR.0, BAR.1);
                for (p, t) in &scale.ticks {
                    let tx = bar_x + p * BAR.0;
                    d.rect(tx - 0.5, y + 2.0 + BAR.1, 1.0, 4.0, INK_SOFT);
                    d.text(tx, y + 2.0 + BAR.1 + 4.0 + KEY_TEXT, KEY_TEXT, "middle", 400, INK_SOFT, "key", t);
                }
            }
            y += BAR.1 + 8.0 + KEY_TEXT * PITCH;
        }
        y += 6.0;
    }
    y - top
}

/// The caption's lines: what the figure shows (prose), and the state string broken after its
/// `&` where it can be (the lines put together are the state string).
pub struct Caption {
    pub head: Vec<String>,
    pub state: Vec<String>,
}

impl Caption {
    pub fn new(head: &str, state: &str, width: f64) -> Caption {
        let mono = |s: &str| s.chars().count() as f64 * MONO_EM * STATE;
        // "state: " is written before the first line.
        let state_width = width - mono("state: ");
        Caption { head: wrap(head, width, CAPTION, false), state: break_lines(state, state_width, &mono, &['&']) }
    }

    pub fn height(&self) -> f64 {
        self.head.len() as f64 * CAPTION * PITCH + self.state.len() as f64 * STATE * PITCH + 8.0
    }

    /// Writes the caption from `top` at x: a rule, the head, then the state lines (each a
    /// `<text class="state">`, whitespace kept).
    pub fn write(&self, doc: &mut Doc, x: f64, top: f64, width: f64) {
        doc.rect(x, top, width, 1.0, INK_SOFT);
        let mut y = top + 4.0;
        for line in &self.head {
            y += CAPTION * PITCH;
            doc.text(x, y - 0.3 * CAPTION, CAPTION, "start", 400, INK, "caption", line);
        }
        let indent = "state: ".chars().count() as f64 * MONO_EM * STATE;
        for (k, line) in self.state.iter().enumerate() {
            y += STATE * PITCH;
            let base = y - 0.3 * STATE;
            if k == 0 {
                doc.out.push_str("<text x=\"");
                px(&mut doc.out, x);
                doc.out.push_str("\" y=\"");
                px(&mut doc.out, base);
                let _ = write!(doc.out, "\" font-size=\"{STATE}\" font-family=\"{MONO}\"");
                doc.fill(INK_SOFT);
                doc.out.push_str(">state:</text>\n");
            }
            doc.out.push_str("<text class=\"state\" xml:space=\"preserve\" x=\"");
            px(&mut doc.out, x + indent);
            doc.out.push_str("\" y=\"");
            px(&mut doc.out, base);
            let _ = write!(doc.out, "\" font-size=\"{STATE}\" font-family=\"{MONO}\"");
            doc.fill(INK);
            let _ = writeln!(doc.out, ">{}</text>", escape(line));
        }
    }
}

/// Keys of the time plots' curves (the page says them in its run blocks): which colour is which
/// curve, run B's hue, the previous run's ghost.
pub fn curve_key(curves: &[(Color, &str)], pair: Option<Color>, ghost: Option<Color>) -> Option<LegendGroup> {
    let item = |c: Color, text: &str| crate::view::legend::item(Glyph::Line, c, text);
    let mut items: Vec<LegendItem> = curves.iter().map(|(c, t)| item(*c, t)).collect();
    items.push(LegendItem { glyph: Glyph::Swatch, ..item(palette::MOTION, "shaded: the reference moves (a slew)") });
    if let Some(b) = pair {
        items.push(item(b, "run B (thinner, in its own hue)"));
    }
    if let Some(g) = ghost {
        items.push(item(g, "the previous run, faint"));
    }
    (!items.is_empty()).then_some(LegendGroup { title: "curves", items, scale: None })
}
