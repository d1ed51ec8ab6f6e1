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

    /// In presentation mode, how much larger than the screen's floor: 15 % a step, so that each
    /// size is visibly larger than the last while the figure still holds its panels (3× on a
    /// 1080-line screen left no room for the pole plot).
    fn over_floor(self) -> f64 {
        match self {
            TextSize::Normal => 1.0,
            TextSize::Large => 1.15,
            TextSize::Larger => 1.32,
            TextSize::Largest => 1.52,
        }
    }
}

/// The smallest text a projected figure may have, CSS px, on a screen of `css_height` lines: read
/// from the back of a room, 18 px on a 1080-line screen (1920 × 1080) and 14 px on a 768-line one
/// (1024 × 768) — proportional to the height above 768 lines, 14 px below.
pub fn presentation_min_text(css_height: f64) -> f64 {
    (14.0 + (css_height - 768.0).max(0.0) * (4.0 / 312.0)).min(24.0)
}

/// The canvas' text scale: the setting's factor; in presentation mode at least its step over the
/// screen's floor — the scale that makes the smallest text ([`font::TICK`]) reach
/// [`presentation_min_text`] of the screen's height (`screen_height`, CSS px — the whole screen,
/// not the canvas, which a bar of controls shortens) — so that Normal meets the floor and each
/// larger size is larger again (a floor that swallowed the choice made Large and Larger look
/// like Normal on a 1080-line screen). Never below 1 or above 3.
pub fn text_scale(size: TextSize, present: bool, screen_height: f64) -> f64 {
    let floor = present_floor(present, screen_height);
    let scale = if present { size.factor().max(floor * size.over_floor()) } else { size.factor() };
    scale.clamp(1.0, 3.0)
}

/// The presentation floor's scale: 1 outside presentation mode.
fn present_floor(present: bool, screen_height: f64) -> f64 {
    if present && screen_height.is_finite() {
        (presentation_min_text(screen_height) / font::TICK).max(1.0)
    } else {
        1.0
    }
}

/// How much larger than Normal the page's own text in presentation mode is (the bar and the
/// verdict in it, the key, Fig. 2.1's caption): the canvas' text scale over the floor's, so the
/// bar grows with the figure's labels, size for size.
pub fn page_text_factor(size: TextSize, present: bool, screen_height: f64) -> f64 {
    text_scale(size, present, screen_height) / present_floor(present, screen_height)
}
