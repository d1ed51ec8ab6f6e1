//! The key to the figures: what each marker, line and shade of the panels shown means, and the
//! colour bar of ρ — written here from the same palette and ramp the panels are drawn with, so the
//! key cannot describe another picture. The page draws each glyph and text.

use serde::Serialize;

use super::layout::PanelKind;
use super::poles::PoleStyle;
use crate::plot::color::{ramp_color, rho_position, RHO_SHOWN};
use crate::plot::{format, palette, Color};

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
    /// CSS colour.
    pub color: String,
    pub text: String,
}

/// The colour bar of ρ on the maps: the ramp as CSS gradient stops and its labelled ticks, each
/// at a position in [0, 1] along the bar.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RhoScale {
    pub stops: Vec<(f64, String)>,
    pub ticks: Vec<(f64, String)>,
}

/// A group of entries, for one kind of panel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LegendGroup {
    pub title: &'static str,
    pub items: Vec<LegendItem>,
    /// The maps' colour bar (maps only).
    pub scale: Option<RhoScale>,
}

fn item(glyph: Glyph, color: Color, text: &str) -> LegendItem {
    LegendItem { glyph, color: color.css(), text: text.to_string() }
}

/// The key to the panels `kinds`, with run B's markers when two runs are compared.
pub fn legend(kinds: &[PanelKind], pair: bool) -> Vec<LegendGroup> {
    let mut groups = Vec::new();
    let has = |k: PanelKind| kinds.contains(&k);
    let z = has(PanelKind::ZPlane);
    if has(PanelKind::Poles) || z {
        let a = PoleStyle::RUN_A;
        let mut items = vec![
            item(Glyph::Cross, a.stable, "pole of the sampled loop"),
            item(
                Glyph::Cross,
                a.unstable,
                if z { "one outside |λ| = 1: it grows" } else { "one with Re s > 0: it grows" },
            ),
        ];
        if pair {
            items.push(item(Glyph::Plus, PoleStyle::RUN_B.stable, "run B's poles"));
        }
        items.extend([
            item(Glyph::Halo, palette::POLE_HALO, "the flexible pair (the joint's resonance)"),
            item(Glyph::Ring, a.a4_open, "A4 without K_pr: where the pair goes as δ → 0"),
            item(Glyph::Diamond, a.a4, "A4 with K_pr"),
            item(
                Glyph::Swatch,
                palette::UNSTABLE_REGION,
                if z { "outside the unit circle: unstable" } else { "right half-plane: unstable" },
            ),
            item(Glyph::Chevron, a.stable, "beyond the plot (at its edge)"),
        ]);
        if !z {
            items.push(item(Glyph::Dashed, palette::NYQUIST, "π/δ, the Nyquist frequency (when in range)"));
        }
        groups.push(LegendGroup { title: if z { "z-plane" } else { "pole plot" }, items, scale: None });
    }
    if has(PanelKind::RhoCurve) {
        groups.push(LegendGroup {
            title: "ρ(δ)",
            items: vec![
                item(Glyph::Line, palette::ERROR1, "ρ along δ at this α"),
                item(Glyph::Swatch, palette::WINDOW_BAND, "ρ < 1: the stable windows of δ"),
                item(Glyph::Line, palette::POLE_STABLE, "ρ = 1, and the δ running now"),
            ],
            scale: None,
        });
    }
    if has(PanelKind::MapOff) || has(PanelKind::MapOn) {
        let mut items = vec![
            item(Glyph::Line, palette::CONTOUR, "ρ = 1: the edge of stability"),
            item(Glyph::Ring, palette::MAP_MARKER, "the (δ, α) running now"),
            item(Glyph::Line, palette::WINDOW_MARK, "the stable windows of δ at this α"),
        ];
        if pair {
            items.push(item(Glyph::Ring, palette::RUN_B, "run B's (δ, α)"));
        }
        groups.push(LegendGroup { title: "stability maps", items, scale: Some(rho_scale()) });
    }
    groups
}

/// The ρ colour bar, from the ramp the maps are drawn with.
pub fn rho_scale() -> RhoScale {
    const STOPS: usize = 17;
    let stops = (0..STOPS)
        .map(|i| {
            let p = i as f64 / (STOPS - 1) as f64;
            (p, ramp_color(p).css())
        })
        .collect();
    let [lo, hi] = RHO_SHOWN;
    let ticks = [lo, 0.95, 1.0, 1.05, hi]
        .into_iter()
        .map(|rho| {
            (
                rho_position(rho),
                if rho == lo {
                    format!("≤ {}", format::number(rho))
                } else if rho == hi {
                    format!("≥ {}", format::number(rho))
                } else {
                    format::number(rho)
                },
            )
        })
        .collect();
    RhoScale { stops, ticks }
}
