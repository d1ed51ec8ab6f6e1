//! What the two pictures of the loop's eigenvalues (the s-plane pole plot and the z-plane) share:
//! how a run's markers look, their sizes, which two eigenvalues are the flexible pair, each
//! marker described for the page ([`PoleInfo`]) and read out in a tooltip ([`readout`]).

pub mod readout;

use serde::Serialize;

use crate::analysis::StabilityReport;
use crate::plot::{palette, Color};
use crate::view::legend::{item, Glyph, LegendGroup};

/// The sampled loop has this many eigenvalues (8 plant/integrator states + 2 held inputs).
pub const MAX_LOOP_POLES: usize = 10;

/// How a run's markers look.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoleStyle {
    /// Loop poles as × (run A) or + (run B).
    pub plus: bool,
    /// Loop poles with Re s ≤ 0.
    pub stable: Color,
    /// Loop poles with Re s > 0.
    pub unstable: Color,
    /// A4 without preliminary feedback (rings).
    pub a4_open: Color,
    /// A4 with the configured preliminary feedback (diamonds).
    pub a4: Color,
}

impl PoleStyle {
    /// The style of run A (0) or B (1).
    pub fn of_run(run: usize) -> PoleStyle {
        if run == 0 {
            PoleStyle::RUN_A
        } else {
            PoleStyle::RUN_B
        }
    }

    pub const RUN_A: PoleStyle = PoleStyle {
        plus: false,
        stable: palette::POLE_STABLE,
        unstable: palette::POLE_UNSTABLE,
        a4_open: palette::A4_OPEN,
        a4: palette::A4_FEEDBACK,
    };
    pub const RUN_B: PoleStyle = PoleStyle {
        plus: true,
        stable: palette::RUN_B,
        unstable: palette::POLE_UNSTABLE,
        a4_open: palette::RUN_B_LIGHT,
        a4: palette::RUN_B,
    };
}

/// The indices (into `report.poles`) of the flexible pair (see [`StabilityReport::flexible_pair`]).
pub fn flexible_pair(report: &StabilityReport) -> [Option<usize>; 2] {
    report.flexible_pair()
}

/// Marker sizes, CSS pixels (the z-plane draws the same markers).
pub mod size {
    pub const CROSS: f64 = 5.0;
    pub const CROSS_WIDTH: f64 = 2.0;
    pub const HALO: f64 = 10.0;
    pub const A4_RING: f64 = 11.0;
    pub const A4_WIDTH: f64 = 1.75;
    pub const A4_DIAMOND: f64 = 7.0;
    pub const CHEVRON: f64 = 5.0;
    pub const EDGE: f64 = 8.0;
}

/// The δ → 0 pair with the preliminary feedback, if there is one (none when it is off: the pair
/// then is A4 without it, already marked).
pub fn with_feedback(report: &StabilityReport) -> &[[f64; 2]] {
    if report.limit_pair == report.limit_pair_open {
        &[]
    } else {
        &report.limit_pair
    }
}

/// Re s shown by default, 1/s: the flexible pair at ≈ ±2.6 and the slow poles at ≈ −2.
pub const RE_RANGE: [f64; 2] = [-8.0, 6.0];
/// Im s shown by default, rad/s: the flexible pair at ≈ ±29.6.
pub const IM_RANGE: [f64; 2] = [-40.0, 40.0];
/// What a marker in the pole plot stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PoleKind {
    /// An eigenvalue of the sampled loop.
    Loop,
    /// The δ → 0 pair A4 without preliminary feedback.
    A4Open,
    /// The δ → 0 pair A4 with the configured preliminary feedback.
    A4,
}

/// One marker of the pole plot as the page sees it (for hover readouts).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PoleInfo {
    /// "A" or "B".
    pub run: &'static str,
    pub kind: PoleKind,
    /// Re s, 1/s.
    pub re: f64,
    /// Im s, rad/s.
    pub im: f64,
    /// Damping ratio −Re s / |s| (null for s = 0).
    pub zeta: Option<f64>,
    /// |s|, rad/s.
    pub omega: f64,
    /// Re s > 0.
    pub unstable: bool,
    /// One of the flexible pair (the loop's complex pair with the largest |Im s|).
    pub flexible: bool,
    /// λ: the loop's eigenvalue; for A4, exp(A4 δ), where the limit pair would sit at this δ.
    pub lambda: [f64; 2],
    /// |λ| and its angle, rad (per sampling period).
    pub modulus: f64,
    pub angle: f64,
    /// The flexible pair when its true frequency (|Im A4|) is above the Nyquist frequency π/δ:
    /// s = ln λ / δ then shows an alias.
    pub aliased: bool,
    /// The marker's centre in CSS pixels (canvas top-left origin) in the pole plot shown (s- or
    /// z-plane); for a pole outside the shown range, the chevron at the panel's edge. Null when
    /// the pole plot is hidden.
    pub x: Option<f64>,
    pub y: Option<f64>,
    /// False if the pole lies outside the shown range (drawn as a chevron at the edge).
    pub in_view: bool,
    /// One keyboard stop per ± pair (its readout names both): the upper half (Im λ ≥ 0), so a
    /// real λ is a stop of its own.
    pub keyboard_stop: bool,
}

/// λ = exp(s δ) for a continuous-time s.
pub fn exp_delta(s: [f64; 2], delta: f64) -> [f64; 2] {
    let r = (s[0] * delta).exp();
    [r * (s[1] * delta).cos(), r * (s[1] * delta).sin()]
}

/// The Nyquist frequency π/δ, rad/s: s = ln λ / δ cannot show a mode faster than this.
pub fn nyquist(delta: f64) -> f64 {
    core::f64::consts::PI / delta
}

/// True if the flexible mode of `report` is faster than the Nyquist frequency: its loop poles in
/// the s-plane are aliases.
pub fn flexible_aliased(report: &StabilityReport) -> bool {
    report.limit_pair[0][1].abs() > nyquist(report.sampling_period)
}

/// Where a marker sits on the page (CSS px; None when no pole plot is shown) and whether it is in
/// view, for its s and its λ: the pole plot shown decides.
pub type Placement<'a> = &'a dyn Fn([f64; 2], [f64; 2]) -> (Option<[f64; 2]>, bool);

/// The placement when no pole plot is shown: no position, in view if s lies in the s-plane's
/// default range.
pub fn unplaced(s: [f64; 2], _lambda: [f64; 2]) -> (Option<[f64; 2]>, bool) {
    (None, s[0] >= RE_RANGE[0] && s[0] <= RE_RANGE[1] && s[1] >= IM_RANGE[0] && s[1] <= IM_RANGE[1])
}

/// Appends the markers of one run's analysis to `out` for the page, placed by the pole plot shown.
pub fn describe_poles(report: &StabilityReport, run: &'static str, place: Placement<'_>, out: &mut Vec<PoleInfo>) {
    let flexible = flexible_pair(report);
    let aliased = flexible_aliased(report);
    let delta = report.sampling_period;
    let mut push = |kind: PoleKind, s: [f64; 2], lambda: [f64; 2], flexible: bool| {
        let omega = s[0].hypot(s[1]);
        let (pos, in_view) = place(s, lambda);
        out.push(PoleInfo {
            run,
            kind,
            re: s[0],
            im: s[1],
            zeta: (omega > 0.0).then(|| -s[0] / omega),
            omega,
            unstable: s[0] > 0.0,
            flexible,
            lambda,
            modulus: lambda[0].hypot(lambda[1]),
            angle: lambda[1].atan2(lambda[0]),
            aliased: flexible && aliased,
            x: pos.map(|p| p[0]),
            y: pos.map(|p| p[1]),
            in_view,
            keyboard_stop: lambda[1] >= 0.0,
        });
    };
    for (i, pole) in report.poles.iter().enumerate() {
        if let Some(s) = pole.continuous {
            if s[0].is_finite() && s[1].is_finite() {
                push(PoleKind::Loop, s, pole.discrete, flexible.contains(&Some(i)));
            }
        }
    }
    for s in report.limit_pair_open {
        push(PoleKind::A4Open, s, exp_delta(s, delta), false);
    }
    // Without preliminary feedback there is no "A4 with K_pr": the pair is A4 itself.
    for &s in with_feedback(report) {
        push(PoleKind::A4, s, exp_delta(s, delta), false);
    }
}

/// The key to the loop's eigenvalues, on the z-plane (`z`) or the s-plane, with run B's markers
/// when two runs are compared.
pub fn legend_group(z: bool, pair: bool) -> LegendGroup {
    let a = PoleStyle::RUN_A;
    let mut items = vec![
        item(Glyph::Cross, a.stable, "pole of the sampled loop"),
        item(Glyph::Cross, a.unstable, if z { "one outside |λ| = 1: it grows" } else { "one with Re s > 0: it grows" }),
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
    LegendGroup { title: if z { "z-plane" } else { "pole plot" }, items, scale: None }
}
