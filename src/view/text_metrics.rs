//! How much room text takes over the canvas: the font sizes, and widths estimated from the
//! characters (on the generous side; the end-to-end tests compare the estimate with the browser's
//! own measure), and text shortened to fit a width. A leaf: it knows no panel, no layout.

/// Font sizes, CSS px (all at least 11: readable on a phone and a projector).
pub mod font {
    /// Tick labels.
    pub const TICK: f64 = 12.0;
    /// Axis titles and panel titles.
    pub const TITLE: f64 = 13.0;
    /// Notes and marks at points.
    pub const NOTE: f64 = 12.0;
}

/// Estimated width of an ordinary character in ems: generous for the page's sans-serif (digits
/// of DejaVu Sans are 0.64 em, most letters narrower).
pub const EM_PER_CHAR: f64 = 0.64;
/// Height of a line of text in ems.
pub const LINE_HEIGHT: f64 = 1.3;
/// Estimated width of `text` at `size` px in the regular weight: [`EM_PER_CHAR`] a character,
/// more for the wide ones (the minus sign, dashes, Greek letters), less for the narrow ones.
pub fn text_width(text: &str, size: f64) -> f64 {
    text.chars().map(char_em).sum::<f64>() * size
}

/// The same in bold (titles and axis labels).
pub fn bold_width(text: &str, size: f64) -> f64 {
    BOLD * text_width(text, size)
}

/// Bold text is this much wider.
const BOLD: f64 = 1.1;

/// Estimated width of a character, ems (generous: the browser's sans-serif is at most this).
fn char_em(c: char) -> f64 {
    match c {
        '−' | '—' | '…' | '×' | 'm' | 'M' | 'W' | 'w' | '%' => 0.9,
        'α'..='ω' | 'Α'..='Ω' => 0.72,
        '.' | ',' | ':' | ';' | ' ' | 'i' | 'j' | 'l' | '|' | '\'' | '!' => 0.4,
        '(' | ')' | '[' | ']' | 'f' | 't' | 'r' | 'I' | '/' => 0.5,
        _ => EM_PER_CHAR,
    }
}

/// `text` in bold, shortened with "…" to fit `width` px at `size` px (empty if not even that fits).
pub fn fit(text: &str, width: f64, size: f64) -> String {
    if bold_width(text, size) <= width {
        return text.to_string();
    }
    let mut out = String::new();
    for c in text.chars() {
        let next = format!("{out}{c}…");
        if bold_width(&next, size) > width {
            break;
        }
        out.push(c);
    }
    let out = out.trim_end();
    if out.chars().count() < 1 {
        return String::new();
    }
    format!("{out}…")
}

/// A note or title made of clauses separated by "; ", most important first: as many whole
/// clauses as fit, never a clause cut short (the key or a tooltip says the rest); only a title
/// whose first clause is too long on its own is shortened with "…" (a note is then left out).
pub fn fit_clauses(text: &str, width: f64, size: f64) -> String {
    let mut out = String::new();
    for clause in text.split("; ") {
        let next = if out.is_empty() { clause.to_string() } else { format!("{out}; {clause}") };
        if bold_width(&next, size) > width {
            break;
        }
        out = next;
    }
    if out.is_empty() {
        fit(text.split("; ").next().unwrap_or(""), width, size)
    } else {
        out
    }
}
