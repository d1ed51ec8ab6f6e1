//! Where every text over the canvas goes: tick labels, axis titles, panel titles and notes, marks
//! at points. Decided here, from the panels' descriptions, so that a native test can check that no
//! two texts overlap at any canvas size; the page only puts each text at its anchor.
//!
//! A label is an anchor point (CSS px, origin top-left of the canvas), an alignment (which point
//! of the text's box sits on the anchor: 0 left/top, 0.5 centre, 1 right/bottom) and a font size.
//! Its box is estimated from the number of characters ([`EM_PER_CHAR`]), on the generous side;
//! the end-to-end tests compare the estimate with the browser's own measure.
//!
//! Around a time plot: its y label left and its x label right in the header row above it, the
//! tick labels left of and below it. Around an analysis panel: its title (what it shows) in a
//! first header row, its y label in a second, the tick labels, and its x label below them. Texts
//! that would not fit their row are shortened with "…" (the page's description of the canvas
//! carries the full words).

use serde::Serialize;

use super::layout::{margins, PanelKind, Rect};
use super::panel_info::{PanelInfo, TickLabel};
use super::text_metrics::{bold_width, fit, fit_clauses, font, text_width, LINE_HEIGHT};

/// Space between a panel's edge and its tick labels, CSS px.
const TICK_GAP: f64 = 4.0;

/// What a label is, for its style.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LabelClass {
    Tick,
    /// An axis title (the unit in brackets).
    Axis,
    /// What a panel shows.
    Title,
    Note,
    /// A text at a point inside a panel (the flexible pair).
    Mark,
}

/// One text over the canvas.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Label {
    /// The panel it belongs to (its id).
    pub panel: &'static str,
    pub class: LabelClass,
    pub text: String,
    /// The anchor, CSS px.
    pub x: f64,
    pub y: f64,
    /// Which point of the text's box sits on the anchor.
    pub align: [f64; 2],
    /// Font size, CSS px.
    pub size: f64,
    /// A time tick: its time, for moving it with the scrolling window (None otherwise).
    pub time: Option<f64>,
    /// The estimated width of the text, CSS px (what the overlap checks use).
    pub width: f64,
    /// The whole text where `text` is shortened to fit (the page gives it as the label's title),
    /// else empty.
    pub full: String,
}

impl Label {
    /// The text's box as estimated (CSS px).
    pub fn bounds(&self) -> Rect {
        let bold = matches!(self.class, LabelClass::Title | LabelClass::Axis | LabelClass::Note | LabelClass::Mark);
        let w = if bold { bold_width(&self.text, self.size) } else { text_width(&self.text, self.size) };
        let h = self.size * LINE_HEIGHT;
        Rect::new(self.x - self.align[0] * w, self.y - self.align[1] * h, w, h)
    }
}

/// Where a value sits along an axis from `r0` to `r1` (0 at the start, 1 at the end).
fn fraction(v: f64, range: [f64; 2], log: bool) -> f64 {
    if log {
        (v / range[0]).ln() / (range[1] / range[0]).ln()
    } else {
        (v - range[0]) / (range[1] - range[0]).max(f64::MIN_POSITIVE)
    }
}

/// Every label of the panels `(kind, description)`.
pub fn place_labels(panels: &[(PanelKind, PanelInfo)]) -> Vec<Label> {
    let mut out = Vec::new();
    for (kind, p) in panels {
        let label = |class, text: String, x, y, align, size| Label {
            panel: p.id,
            class,
            text,
            x,
            y,
            align,
            size,
            time: None,
            width: 0.0,
            full: String::new(),
        };
        // A label shortened from `full` carries it.
        let whole = |mut l: Label, full: &str| {
            if l.text != full {
                l.full = full.to_string();
            }
            l
        };
        if kind.is_stage() {
            out.push(whole(
                // Whole clauses ("arm at tₙ; violet: …"): what does not fit is in the key.
                label(
                    LabelClass::Title,
                    fit_clauses(&p.title, p.width, font::TITLE),
                    p.x,
                    p.y - 3.0,
                    [0.0, 1.0],
                    font::TITLE,
                ),
                &p.title,
            ));
            continue;
        }
        ticks(kind, p, &mut out);
        let (left, right) =
            (p.x - if kind.is_analysis() { margins::ANALYSIS_LEFT } else { margins::PLOT_LEFT }, p.x + p.width);
        if kind.is_analysis() {
            // Header row 1: what the panel shows; row 2: the y axis; below the ticks: the x axis.
            let title = fit_clauses(&p.note, right - left, font::TITLE);
            let row1 = p.y - margins::ANALYSIS_TOP + 2.0;
            out.push(whole(label(LabelClass::Title, title, left, row1, [0.0, 0.0], font::TITLE), &p.note));
            let x_label = fit(&p.x_label, p.width, font::TITLE);
            // Under the tick row with a gap, so that a tick at the right end (0.1 s) keeps its label.
            let below = p.y + p.height + TICK_GAP + font::TICK * LINE_HEIGHT + LABEL_GAP;
            out.push(whole(
                label(LabelClass::Axis, x_label.clone(), right, below, [1.0, 0.0], font::TITLE),
                &p.x_label,
            ));
            // A second x axis (ωδ on ρ(δ)) in the y label's row: its title right after the y
            // label, as many clauses as fit before the first tick label kept, then the ticks.
            if !p.x2_labels.is_empty() {
                let start = p.x - TICK_GAP + bold_width(p.y_label, font::TITLE) + 12.0;
                let at = |t: &TickLabel| p.x + fraction(t.value, p.x_range, p.x_scale == "log") * p.width;
                let ticks: Vec<&TickLabel> = p.x2_labels.iter().filter(|t| at(t) > start).collect();
                let mut first = 0;
                // The whole title, else its symbol alone ("ωδ", what the ticks count), else one
                // tick fewer.
                let symbol = p.x2_label.split(' ').next().unwrap_or("");
                let title = loop {
                    let end = ticks.get(first).map_or(right, |t| at(t) - text_width(&t.text, font::TICK) / 2.0 - 8.0);
                    let title = fit_clauses(&p.x2_label, end - start, font::NOTE);
                    if !title.is_empty() && !title.ends_with('…') {
                        break title;
                    }
                    if bold_width(symbol, font::NOTE) <= end - start {
                        break symbol.to_string();
                    }
                    if first >= ticks.len() {
                        break title;
                    }
                    first += 1;
                };
                out.push(whole(label(LabelClass::Axis, title, start, p.y - 2.0, [0.0, 1.0], font::NOTE), &p.x2_label));
                for t in &ticks[first..] {
                    out.push(label(LabelClass::Tick, t.text.clone(), at(t), p.y - 2.0, [0.5, 1.0], font::TICK));
                }
            }
            let y_room = p.width + TICK_GAP;
            out.push(whole(
                label(
                    LabelClass::Axis,
                    fit(p.y_label, y_room, font::TITLE),
                    p.x - TICK_GAP,
                    p.y - 2.0,
                    [0.0, 1.0],
                    font::TITLE,
                ),
                p.y_label,
            ));
        } else {
            // The header row: the y label left, the x label right, a note between if it fits.
            let x_w = bold_width(&p.x_label, font::TITLE);
            let y_label = fit(p.y_label, p.width - x_w - 12.0, font::TITLE);
            let y_w = bold_width(&y_label, font::TITLE);
            out.push(whole(
                label(LabelClass::Axis, y_label, p.x - TICK_GAP, p.y - 2.0, [0.0, 1.0], font::TITLE),
                p.y_label,
            ));
            out.push(label(LabelClass::Axis, p.x_label.clone(), right + TICK_GAP, p.y - 2.0, [1.0, 1.0], font::TITLE));
            if !p.note.is_empty() {
                let room = p.width - x_w - y_w - 36.0;
                // A note says what the key says too: left out rather than cut.
                let note = fit_clauses(&p.note, room, font::NOTE);
                let note = if note.ends_with('…') { String::new() } else { note };
                let at = p.x - TICK_GAP + y_w + 16.0;
                out.push(whole(label(LabelClass::Note, note, at, p.y - 2.0, [0.0, 1.0], font::NOTE), &p.note));
            }
        }
        marks(p, &mut out);
    }
    out.retain(|l| !l.text.is_empty());
    for l in &mut out {
        l.width = l.bounds().w;
    }
    drop_collisions(out)
}

/// Titles and axis labels stay (the layout leaves them room); a tick label, note or mark that
/// would overlap a label already kept, or a plot's data, is left out (a corner tick, a crowded
/// tick of a narrow panel).
fn drop_collisions(labels: Vec<Label>) -> Vec<Label> {
    let rank = |l: &Label| match l.class {
        LabelClass::Title | LabelClass::Axis => 0,
        LabelClass::Tick => 1,
        LabelClass::Note => 2,
        LabelClass::Mark => 3,
    };
    let mut order: Vec<usize> = (0..labels.len()).collect();
    crate::sort::sort_by_key(&mut order, |&i| rank(&labels[i]));
    let mut kept: Vec<(usize, Rect)> = Vec::with_capacity(labels.len());
    for i in order {
        let b = labels[i].bounds();
        let free = kept.iter().all(|(_, k)| !overlaps(&b, k));
        if rank(&labels[i]) == 0 || free {
            kept.push((i, b));
        }
    }
    let mut keep = vec![false; labels.len()];
    for (i, _) in kept {
        keep[i] = true;
    }
    labels.into_iter().zip(keep).filter_map(|(l, k)| k.then_some(l)).collect()
}

/// Labels closer than this (CSS px) read as one ("ρ" against "1.10"): a tick, note or mark that
/// near a kept label is left out.
pub const LABEL_GAP: f64 = 2.0;

/// Boxes closer than [`LABEL_GAP`].
fn overlaps(a: &Rect, b: &Rect) -> bool {
    let g = LABEL_GAP;
    a.x < b.right() + g && b.x < a.right() + g && a.y < b.bottom() + g && b.y < a.bottom() + g
}

/// The tick labels left of and below a plot.
fn ticks(kind: &PanelKind, p: &PanelInfo, out: &mut Vec<Label>) {
    for t in &p.y_labels {
        let f = fraction(t.value, p.y_range, p.y_scale == "log");
        let y = p.y + p.height - f * p.height;
        // A tick at the top edge hangs below it: centred on it, it would touch the y axis's title
        // just above and be left out (the maps' top α had no label).
        let top = f >= 1.0 - 1e-9;
        out.push(Label {
            panel: p.id,
            class: LabelClass::Tick,
            text: t.text.clone(),
            x: p.x - TICK_GAP,
            y,
            align: [1.0, if top { 0.0 } else { 0.5 }],
            size: font::TICK,
            time: None,
            width: 0.0,
            full: String::new(),
        });
    }
    for t in &p.x_labels {
        let f = fraction(t.value, p.x_range, p.x_scale == "log");
        out.push(Label {
            panel: p.id,
            class: LabelClass::Tick,
            text: t.text.clone(),
            x: p.x + f * p.width,
            y: p.y + p.height + TICK_GAP,
            align: [0.5, 0.0],
            size: font::TICK,
            time: (kind.is_time_plot() && p.scrolls).then_some(t.value),
            width: 0.0,
            full: String::new(),
        });
    }
}

/// Texts at points: beside the point, up and to the right, or flipped to stay inside the panel.
fn marks(p: &PanelInfo, out: &mut Vec<Label>) {
    for m in &p.marks {
        let text = fit(&m.text, p.width - 8.0, font::NOTE);
        let w = bold_width(&text, font::NOTE);
        let h = font::NOTE * LINE_HEIGHT;
        let right = m.x + 9.0 + w <= p.x + p.width;
        let up = m.y - 9.0 - h >= p.y;
        let (x, ax) = if right { (m.x + 9.0, 0.0) } else { ((m.x - 9.0).max(p.x + w), 1.0) };
        let (y, ay) = if up { (m.y - 9.0, 1.0) } else { ((m.y + 9.0).min(p.y + p.height - h), 0.0) };
        let full = if text != m.text { m.text.clone() } else { String::new() };
        out.push(Label {
            panel: p.id,
            class: LabelClass::Mark,
            text,
            x,
            y,
            align: [ax, ay],
            size: font::NOTE,
            time: None,
            width: 0.0,
            full,
        });
    }
}
