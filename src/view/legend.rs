//! The key to the figures, as the page and the figures draw it: groups of entries (a glyph, its
//! colour in both schemes, what it means) and the maps' colour bar (of ρ or of ln ρ/δ), from the
//! same palette and ramp the panels are drawn with, so the key cannot describe another picture.
//! Each panel writes its own group ([`super::panels`]); the page draws each glyph and text.

use serde::Serialize;

use crate::plot::color::{ramp_color, Measure, RATE_SHOWN, RHO_SHOWN};
use crate::plot::{format, Color};

/// How a legend glyph looks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Glyph {
    Cross,
    Plus,
    Ring,
    Diamond,
    /// A filled translucent disc.
    Halo,
    /// A short solid line.
    Line,
    /// A short dashed line.
    Dashed,
    /// A filled square (a shaded region).
    Swatch,
    /// A chevron at a plot's edge.
    Chevron,
}

/// One entry of the key.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LegendItem {
    pub glyph: Glyph,
    /// CSS colour, and the same in the dark scheme (lightness inverted, as the canvas's shader
    /// inverts it: [`Color::for_dark`]).
    pub color: String,
    pub dark: String,
    pub text: String,
    /// The entry's name alone, for the compact key of presentation mode: the text before its
    /// explanation (before the first ": " or " (").
    pub short: String,
}

/// The colour bar of the maps: what it measures, the ramp as CSS gradient stops and its labelled
/// ticks, each at a position in [0, 1] along the bar.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MapScale {
    /// The bar's title: "ρ" or "ln ρ/δ (1/s)".
    pub name: &'static str,
    /// The bar in words, for screen readers.
    pub label: String,
    pub stops: Vec<(f64, String)>,
    /// The stops in the dark scheme.
    pub dark_stops: Vec<(f64, String)>,
    pub ticks: Vec<(f64, String)>,
}

/// A group of entries, for one kind of panel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LegendGroup {
    pub title: &'static str,
    pub items: Vec<LegendItem>,
    /// The maps' colour bar (maps only).
    pub scale: Option<MapScale>,
}

pub fn item(glyph: Glyph, color: Color, text: &str) -> LegendItem {
    LegendItem { glyph, color: color.css(), dark: color.for_dark().css(), text: text.to_string(), short: short(text) }
}

/// An entry's name without its explanation: without a last parenthesis that ends it, and up to
/// the first ": " of what is left ("the (δ, α) running now" keeps its parenthesis).
pub fn short(text: &str) -> String {
    let base = match text.rfind(" (") {
        Some(at) if text.ends_with(')') => &text[..at],
        _ => text,
    };
    base.split(": ").next().unwrap_or(base).to_string()
}

/// The maps' colour bar for `measure`, from the ramp the maps are drawn with.
pub fn map_scale(measure: Measure) -> MapScale {
    const STOPS: usize = 17;
    let stops_in = |dark: bool| {
        (0..STOPS)
            .map(|i| {
                let p = i as f64 / (STOPS - 1) as f64;
                let c = ramp_color(p);
                (p, if dark { c.for_dark() } else { c }.css())
            })
            .collect::<Vec<_>>()
    };
    let (stops, dark_stops) = (stops_in(false), stops_in(true));
    let values = match measure {
        Measure::Rho => [RHO_SHOWN[0], 0.95, 1.0, 1.05, RHO_SHOWN[1]],
        Measure::Rate => [-RATE_SHOWN, -1.0, 0.0, 1.0, RATE_SHOWN],
    };
    let ticks: Vec<(f64, String)> = values
        .iter()
        .enumerate()
        .map(|(k, &v)| {
            let text = match k {
                0 => format!("≤ {}", format::number(v)),
                4 => format!("≥ {}", format::number(v)),
                _ => format::number(v),
            };
            (measure.position(v), text)
        })
        .collect();
    let border = format::number(measure.border());
    let label = format!(
        "colour of {}: blue below {border} (stable), white at {border}, red above {border} (unstable); from {}",
        measure.symbol(),
        ticks.iter().map(|t| t.1.as_str()).collect::<Vec<_>>().join(", ")
    );
    MapScale { name: measure.symbol(), label, stops, dark_stops, ticks }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_short_form_is_the_name_before_its_explanation() {
        use super::short;
        assert_eq!(short("the reference arm: where the arm should be"), "the reference arm");
        assert_eq!(short("the motor's angle θ on its disc (grey: the reference's)"), "the motor's angle θ on its disc");
        assert_eq!(short("Uₖ, the torque at tₙ + kε: the only one used"), "Uₖ, the torque at tₙ + kε");
        assert_eq!(short("A4 with K_pr"), "A4 with K_pr");
        assert_eq!(short("the (δ, α) running now"), "the (δ, α) running now");
        assert_eq!(
            short("e^(A4 δ), A4 without K_pr: the pair's δ → 0 limit (not a pole of this loop)"),
            "e^(A4 δ), A4 without K_pr"
        );
    }
}
