//! The key to the figures: what each marker, line and shade of the panels shown means, and the
//! maps' colour bar (of ρ or of ln ρ/δ) — written here from the same palette and ramp the panels
//! are drawn with, so the key cannot describe another picture. The page draws each glyph and text.

use serde::Serialize;

use super::layout::PanelKind;
use super::poles::PoleStyle;
use crate::plot::color::{ramp_color, Measure, RATE_SHOWN, RHO_SHOWN};
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
    /// CSS colour, and the same in the dark scheme (lightness inverted, as the canvas's shader
    /// inverts it: [`Color::for_dark`]).
    pub color: String,
    pub dark: String,
    pub text: String,
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

pub(crate) fn item(glyph: Glyph, color: Color, text: &str) -> LegendItem {
    LegendItem { glyph, color: color.css(), dark: color.for_dark().css(), text: text.to_string() }
}

/// The key to the panels `kinds`, with run B's markers when two runs are compared; ρ(δ) and the
/// maps show `measure`; `log_errors`: the error plots are log |e|, with the predicted slope.
pub fn legend(kinds: &[PanelKind], pair: bool, measure: Measure, log_errors: bool, zoom: bool) -> Vec<LegendGroup> {
    let rate = measure == Measure::Rate;
    let mut groups = Vec::new();
    let has = |k: PanelKind| kinds.contains(&k);
    if has(PanelKind::Arm) {
        groups.push(LegendGroup {
            title: "arm",
            items: vec![
                item(Glyph::Line, palette::GHOST, "the reference arm: where the arm should be"),
                item(
                    Glyph::Line,
                    palette::AXIS,
                    "the thin line from the base: 0 rad, where the angles are measured from",
                ),
                item(
                    Glyph::Line,
                    palette::SPRING_STRETCHED,
                    "the spring between motor and link 1: its twist θ − q1 drawn magnified (orange relaxed, red wound)",
                ),
                item(Glyph::Line, palette::MOTOR_MARKER, "the motor's angle θ on its disc (grey: the reference's)"),
            ],
            scale: None,
        });
    }
    if zoom && has(PanelKind::Torque) {
        groups.push(LegendGroup {
            title: "Fig. 2.1: one sampling instant tₙ",
            items: vec![
                item(Glyph::Ring, palette::PREDICTED, "x(tₙ): the state the controller measures at tₙ"),
                item(
                    Glyph::Swatch,
                    palette::HORIZON_BAND,
                    "the horizon τ = kε: from x(tₙ) it predicts X₁ … Xₖ and U₁ … Uₖ, k backward-Euler steps of ε \
                     (dashed, a dot per step)",
                ),
                item(
                    Glyph::Chevron,
                    palette::ERROR1,
                    "U₁, U₂ off the scale: the first steps put the motor where the links' law needs it, whatever was \
                     measured — from X₂ on the prediction no longer depends on the measured θ, θ̇",
                ),
                item(Glyph::Diamond, palette::PREDICTED, "Uₖ, the torque at tₙ + kε: the only one used"),
                item(
                    Glyph::Swatch,
                    palette::HOLD_BAND,
                    "tₙ + δ to tₙ + 2δ: Uₖ is held there, one period after the measurement (u = v + K_pr x: steps of v)",
                ),
                item(Glyph::Dashed, palette::PREDICTED, "Uₖ still to come: the run is at tₙ"),
                item(Glyph::Line, palette::PREDICTED_ARM, "on the arm: Xₖ, the arm as predicted for tₙ + kε"),
            ],
            scale: None,
        });
    }
    if log_errors && has(PanelKind::Error1) {
        // The panel's note names the line only where there is room; the key always does.
        groups.push(LegendGroup {
            title: "log |e|",
            items: vec![
                item(Glyph::Dashed, palette::PREDICTED, "the slope ln ρ/δ the linear analysis predicts"),
                item(
                    Glyph::Line,
                    palette::SWING,
                    "the swing: the flexible pair's amplitude in the error, from the run's state at each sampling \
                     instant while the reference rests (it changes ×|λ| per period)",
                ),
                item(Glyph::Line, palette::SPLIT_REST, "the rest of the error, without the swing"),
            ],
            scale: None,
        });
    }
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
            item(Glyph::Halo, palette::POLE_HALO, "the flexible pair: the joint's resonance in this loop"),
            item(
                Glyph::Ring,
                a.a4_open,
                if z {
                    "e^(A4 δ), A4 without K_pr: the pair's δ → 0 limit (not a pole of this loop)"
                } else {
                    "A4 without K_pr: where the pair goes as δ → 0"
                },
            ),
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
        let [curve, band, border] = if rate {
            [
                "ln ρ/δ (1/s) along δ at this α",
                "ln ρ/δ < 0: the stable windows of δ",
                "ln ρ/δ = 0, and the δ running now",
            ]
        } else {
            ["ρ along δ at this α", "ρ < 1: the stable windows of δ", "ρ = 1, and the δ running now"]
        };
        groups.push(LegendGroup {
            title: if rate { "ln ρ/δ along δ" } else { "ρ(δ)" },
            items: vec![
                item(Glyph::Line, palette::ERROR1, curve),
                item(Glyph::Swatch, palette::WINDOW_BAND, band),
                item(Glyph::Line, palette::POLE_STABLE, border),
                // Drawn only without preliminary feedback: the law explains the controller alone.
                item(
                    Glyph::Line,
                    palette::LAG_BAND,
                    "no Kₚᵣ: the window the lag law gives, ωδ up to π (see “Why some larger δ work”)",
                ),
                item(
                    Glyph::Line,
                    palette::AXIS,
                    "top axis ωδ: how far the swing turns in one period (ω = |Im A4|; π = half a swing, 2π = one)",
                ),
            ],
            scale: None,
        });
    }
    if has(PanelKind::MapOff) || has(PanelKind::MapOn) {
        let mut items = vec![
            item(
                Glyph::Line,
                palette::CONTOUR,
                if rate { "ln ρ/δ = 0 (ρ = 1): the edge of stability" } else { "ρ = 1: the edge of stability" },
            ),
            item(Glyph::Ring, palette::MAP_MARKER, "the (δ, α) running now"),
            item(Glyph::Line, palette::WINDOW_MARK, "the stable windows of δ at this α"),
        ];
        if pair {
            items.push(item(Glyph::Ring, palette::RUN_B, "run B's (δ, α)"));
        }
        groups.push(LegendGroup { title: "stability maps", items, scale: Some(map_scale(measure)) });
    }
    groups
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
