//! How large the figure's text is, and with it everything laid out around text.
//!
//! The canvas is laid out for a smaller screen — its CSS size divided by the *text scale* s — and
//! drawn s times larger: fonts, tick gutters, curve widths and markers all grow together, the way
//! a browser's zoom works but decided here, so the no-overlap guarantee of [`super::labels`] (checked
//! at every layout size) holds at every text size, and a plot never shrinks while its text grows.
//! What the page is told (labels, panel rectangles, pointer positions) is converted between the
//! page's CSS pixels and the layout's by [`super::Scene`]'s `page_*` methods.

use serde::Serialize;

use super::text_metrics::font;

/// The `text` setting: the figure's text size.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum TextSize {
    /// 12-px ticks, as designed for a laptop.
    #[default]
    Normal,
    Large,
    Larger,
    Largest,
}

impl TextSize {
    /// From the setting's value (`text=larger`); unknown names are normal.
    pub fn from_name(name: &str) -> TextSize {
        match name {
            "large" => TextSize::Large,
            "larger" => TextSize::Larger,
            "largest" => TextSize::Largest,
            _ => TextSize::Normal,
        }
    }

    /// How much larger than normal.
    pub fn factor(self) -> f64 {
        match self {
            TextSize::Normal => 1.0,
            TextSize::Large => 1.25,
            TextSize::Larger => 1.5,
            TextSize::Largest => 2.0,
        }
    }
}

/// The smallest text a projected figure may have, CSS px, on a screen of `css_height` lines: read
/// from the back of a room, 18 px on a 1080-line screen (1920 × 1080) and 14 px on a 768-line one
/// (1024 × 768) — proportional to the height above 768 lines, 14 px below.
pub fn presentation_min_text(css_height: f64) -> f64 {
    (14.0 + (css_height - 768.0).max(0.0) * (4.0 / 312.0)).min(24.0)
}

/// The canvas' text scale: the setting's factor; in presentation mode at least what makes the
/// smallest text ([`font::TICK`]) reach [`presentation_min_text`] of the screen's height
/// (`screen_height`, CSS px — the whole screen, not the canvas, which a bar of controls shortens).
/// Never below 1 or above 3.
pub fn text_scale(size: TextSize, present: bool, screen_height: f64) -> f64 {
    let chosen = size.factor();
    let scale = if present && screen_height.is_finite() {
        chosen.max(presentation_min_text(screen_height) / font::TICK)
    } else {
        chosen
    };
    scale.clamp(1.0, 3.0)
}
