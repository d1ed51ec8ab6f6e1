//! Colours: the [`Color`] type, the [`palette`] of every picture (canvas and SVG), and the
//! diverging ramps of the stability maps — of the spectral radius ρ ([`rho_color`]) and of the
//! rate ln ρ/δ ([`rate_color`]), chosen by a [`Measure`] — written once.

/// A colour: sRGB-encoded components and straight alpha.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Color(pub [f32; 4]);

impl Color {
    /// An opaque colour from `0xRRGGBB`.
    pub const fn hex(rgb: u32) -> Self {
        let r = ((rgb >> 16) & 0xff) as f32 / 255.0;
        let g = ((rgb >> 8) & 0xff) as f32 / 255.0;
        let b = (rgb & 0xff) as f32 / 255.0;
        Color([r, g, b, 1.0])
    }

    /// The same colour with opacity `alpha` (0 transparent, 1 opaque).
    pub const fn with_alpha(self, alpha: f32) -> Self {
        let [r, g, b, _] = self.0;
        Color([r, g, b, alpha])
    }

    /// Linear interpolation between `self` (f = 0) and `other` (f = 1); f is clamped to [0, 1].
    pub fn lerp(self, other: Color, f: f64) -> Color {
        let f = if f.is_nan() { 0.0 } else { f.clamp(0.0, 1.0) as f32 };
        let mut c = self.0;
        for (a, b) in c.iter_mut().zip(other.0) {
            *a += (b - *a) * f;
        }
        Color(c)
    }

    /// The colour for a dark scheme: its lightness inverted, its hue and chroma kept (white
    /// paper becomes black, dark ink light, a deep blue a light blue). Every channel moves by
    /// 1 − max − min, which maps HSL lightness L to 1 − L. The shader applies the same formula
    /// to every vertex in the dark scheme (`web/shader.wgsl`).
    pub fn for_dark(self) -> Color {
        let [r, g, b, a] = self.0;
        let shift = 1.0 - r.max(g).max(b) - r.min(g).min(b);
        Color([r + shift, g + shift, b + shift, a])
    }

    /// The colour as a CSS string: `#rrggbb`, or `rgba(r, g, b, a)` when not opaque.
    pub fn css(self) -> String {
        let [r, g, b, a] = self.0;
        let byte = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        if a >= 1.0 {
            format!("#{:02x}{:02x}{:02x}", byte(r), byte(g), byte(b))
        } else {
            format!("rgba({}, {}, {}, {})", byte(r), byte(g), byte(b), (a.clamp(0.0, 1.0) * 1000.0).round() / 1000.0)
        }
    }

    /// Components as the wgpu clear colour wants them (f64).
    pub fn to_f64(self) -> [f64; 4] {
        self.0.map(f64::from)
    }
}

/// The colours of the picture: a calm light background, readable on a projector.
pub mod palette {
    use super::Color;

    /// Canvas background (behind the panels).
    pub const BACKGROUND: Color = Color::hex(0xf3f1ec);
    /// Panel fill.
    pub const PANEL: Color = Color::hex(0xffffff);
    /// Panel frame.
    pub const FRAME: Color = Color::hex(0xb9b6ae);
    /// Grid lines.
    pub const GRID: Color = Color::hex(0xe4e1da);
    /// Zero line and the arm's 0-rad direction.
    pub const AXIS: Color = Color::hex(0x9c988f);
    /// Shading of the time intervals where the reference moves.
    pub const MOTION: Color = Color::hex(0xfbf0d2);

    /// Link 1: dark blue.
    pub const LINK1: Color = Color::hex(0x1d3f8c);
    /// Link 2: teal.
    pub const LINK2: Color = Color::hex(0x13958f);
    /// The elbow joint.
    pub const JOINT: Color = Color::hex(0x2b2b33);
    /// The reference arm: translucent grey.
    pub const GHOST: Color = Color::hex(0x6f6f6f).with_alpha(0.33);

    /// Motor disc, its edge and its angle marker: orange.
    pub const MOTOR: Color = Color::hex(0xf7c98f);
    pub const MOTOR_EDGE: Color = Color::hex(0xd9731a);
    pub const MOTOR_MARKER: Color = Color::hex(0xa34700);
    /// The spring, relaxed and fully stretched (the colour blends with the drawn twist).
    pub const SPRING_RELAXED: Color = Color::hex(0xe98a1e);
    pub const SPRING_STRETCHED: Color = Color::hex(0xc42a1c);
    /// The circle the spring coils along.
    pub const SPRING_TRACK: Color = Color::hex(0xe98a1e).with_alpha(0.25);

    /// e1: blue; e2: red-orange.
    pub const ERROR1: Color = Color::hex(0x1f5fc4);
    pub const ERROR2: Color = Color::hex(0xe0521b);
    /// Torques, with the colours of their links' errors.
    pub const TORQUE1: Color = ERROR1;
    pub const TORQUE2: Color = ERROR2;

    /// e1, e2 as the controller read them (the sensors' staircase), lighter, under the true ones.
    pub const MEASURED1: Color = Color::hex(0x8fb8ee);
    pub const MEASURED2: Color = Color::hex(0xf3a985);
    /// Link 1's velocity q̇1 (dark teal) and the controller's estimate of it, lighter, under it.
    pub const VELOCITY1: Color = Color::hex(0x0f6e69);
    pub const VELOCITY1_EST: Color = Color::hex(0x8ed1c9);
    /// The motors' torque limit ±L.
    pub const TORQUE_LIMIT: Color = Color::hex(0xa1261d);

    /// Run B of a comparison: one violet hue for its curves, poles and map marker ...
    pub const RUN_B: Color = Color::hex(0x8a3cc2);
    /// ... and a lighter violet for its T2 and its A4-without-feedback rings.
    pub const RUN_B_LIGHT: Color = Color::hex(0xc39be0);

    /// Pole plot: loop poles with Re s ≤ 0 (dark) and Re s > 0 (red).
    pub const POLE_STABLE: Color = Color::hex(0x24242c);
    pub const POLE_UNSTABLE: Color = Color::hex(0xd7191c);
    /// The amber halo behind the flexible pair.
    pub const POLE_HALO: Color = Color::hex(0xf5b301).with_alpha(0.45);
    /// A4 without preliminary feedback (rings) and with it (diamonds).
    pub const A4_OPEN: Color = Color::hex(0x7d7670);
    pub const A4_FEEDBACK: Color = Color::hex(0x168a45);
    /// The unstable half-plane Re s > 0, faintly tinted.
    pub const UNSTABLE_REGION: Color = Color::hex(0xfcecea);
    /// The imaginary axis Re s = 0, emphasised.
    pub const IMAGINARY_AXIS: Color = Color::hex(0x3b3b44);

    /// Stability map: ρ = 1 (near white), stable shades towards ρ = 0.8, unstable towards 1.2.
    pub const MAP_NEUTRAL: Color = Color::hex(0xf7f6f2);
    pub const MAP_STABLE_MID: Color = Color::hex(0x8dbfdf);
    pub const MAP_STABLE_FAR: Color = Color::hex(0x1b5599);
    pub const MAP_UNSTABLE_MID: Color = Color::hex(0xf4a37c);
    pub const MAP_UNSTABLE_FAR: Color = Color::hex(0xae1c24);
    /// Cells not computed yet.
    pub const MAP_PENDING: Color = Color::hex(0xdcdad5);
    /// Faint grid lines over the map cells.
    pub const MAP_GRID: Color = Color::hex(0xffffff).with_alpha(0.45);
    /// The ρ = 1 contour and the white halo under it.
    pub const CONTOUR: Color = Color::hex(0x141418);
    pub const CONTOUR_HALO: Color = Color::hex(0xffffff).with_alpha(0.7);
    /// Run A's marker on the maps, and the white halo that keeps markers readable on dark cells.
    pub const MAP_MARKER: Color = Color::hex(0x101014);
    pub const MARKER_HALO: Color = Color::hex(0xffffff).with_alpha(0.9);

    /// The previous run's errors, kept faint after a restart.
    pub const GHOST_TRACE: Color = Color::hex(0x8a877f).with_alpha(0.55);
    /// The slope the linear analysis predicts, ln ρ / δ, over the log |e| plot.
    pub const PREDICTED: Color = Color::hex(0x111116);
    /// The stable windows of δ: bands on the ρ(δ) plot, marks on the map.
    pub const WINDOW_BAND: Color = Color::hex(0xd9ecf7);
    pub const WINDOW_MARK: Color = Color::hex(0x0b6e3a);
    /// The lag law's window of δ over the ρ(δ) plot ([`crate::analysis::lag`]).
    pub const LAG_BAND: Color = Color::hex(0xc27c0e);
    /// Over log |e|: the flexible pair's amplitude in the error (the swing, amber like the pair's
    /// halo in the pole plot) and the rest of the error without it (grey).
    pub const SWING: Color = Color::hex(0xd39a00);
    pub const SPLIT_REST: Color = Color::hex(0x8a877f);
    /// The Nyquist frequency ±π/δ in the s-plane.
    pub const NYQUIST: Color = Color::hex(0x8c5a00);
    /// The unit circle of the z-plane.
    pub const UNIT_CIRCLE: Color = Color::hex(0x3b3b44);
    /// The instant looked back at, across the time plots.
    /// Fig. 2.1 zoom: the prediction's horizon τ = kε from t_n, and the period its U_k is held on.
    pub const HORIZON_BAND: Color = Color::hex(0x8a6cc4).with_alpha(0.16);
    pub const HOLD_BAND: Color = Color::hex(0x3c9a52).with_alpha(0.18);
    /// The arm the controller predicts at t_n + kε (translucent, over the arm).
    pub const PREDICTED_ARM: Color = Color::hex(0x7b3fb0).with_alpha(0.55);
    pub const CURSOR: Color = Color::hex(0x2b2b33).with_alpha(0.8);
}

/// ρ is shown between these bounds; beyond them the colour saturates.
pub const RHO_SHOWN: [f64; 2] = [0.8, 1.2];

/// ln ρ/δ is shown within ± this, 1/s; beyond it the colour saturates. 5 1/s is the fastest decay
/// the controller is asked for (α ≤ 5 1/s), twice the growth of Fig. 5.3 (2.4 1/s), and 97 % of the
/// default maps' cells lie within it (they span about −4.4 to +7 1/s); an error growing at
/// 5 1/s gains e^50 over the page's 10-s window, so faster reads the same. With the square root,
/// ±0.2 1/s sits where ρ = 1 ± 0.008 does on the ρ ramp: visibly coloured.
pub const RATE_SHOWN: f64 = 5.0;

/// Where a signed deviation `u` (in units of its saturation bound) sits on the ramp: ½ at 0,
/// ½ ± ½ √|u| up to |u| = 1, then 0 or 1. The square root keeps small deviations visibly
/// coloured. NaN for NaN.
fn diverging_position(u: f64) -> f64 {
    let t = u.abs().min(1.0).sqrt();
    if u.is_nan() {
        f64::NAN
    } else if u < 0.0 {
        0.5 - 0.5 * t
    } else {
        0.5 + 0.5 * t
    }
}

/// Where ρ sits on the colour ramp, in [0, 1]: ½ at ρ = 1, 0 at ρ ≤ 0.8, 1 at ρ ≥ 1.2, and in
/// between ½ ± ½ √(|ρ − 1| / 0.2). The square root keeps ρ = 0.98 and 1.02 visibly coloured.
/// NaN for NaN.
pub fn rho_position(rho: f64) -> f64 {
    let (lo, hi) = (RHO_SHOWN[0], RHO_SHOWN[1]);
    diverging_position(if rho < 1.0 { (rho - 1.0) / (1.0 - lo) } else { (rho - 1.0) / (hi - 1.0) })
}

/// Where the rate ln ρ/δ (1/s) sits on the colour ramp: ½ at 0, ½ ± ½ √(|rate| / [`RATE_SHOWN`]),
/// saturating at ± [`RATE_SHOWN`]. NaN for NaN.
pub fn rate_position(rate: f64) -> f64 {
    diverging_position(rate / RATE_SHOWN)
}

/// The ramp at position `p` in [0, 1]: dark blue (stable) through near white (ρ = 1) to dark
/// red (unstable).
pub fn ramp_color(p: f64) -> Color {
    let p = if p.is_finite() { p.clamp(0.0, 1.0) } else { 0.5 };
    let t = (2.0 * p - 1.0).abs();
    let (mid, far) = if p < 0.5 {
        (palette::MAP_STABLE_MID, palette::MAP_STABLE_FAR)
    } else {
        (palette::MAP_UNSTABLE_MID, palette::MAP_UNSTABLE_FAR)
    };
    if t <= 0.5 {
        palette::MAP_NEUTRAL.lerp(mid, t * 2.0)
    } else {
        mid.lerp(far, (t - 0.5) * 2.0)
    }
}

/// The colour of ρ on the maps: [`ramp_color`] at [`rho_position`]; light grey for NaN (not
/// computed yet).
pub fn rho_color(rho: f64) -> Color {
    if rho.is_nan() {
        return palette::MAP_PENDING;
    }
    ramp_color(rho_position(rho))
}

/// The colour of the rate ln ρ/δ (1/s) on the maps: [`ramp_color`] at [`rate_position`]; light
/// grey for NaN (not computed yet).
pub fn rate_color(rate: f64) -> Color {
    if rate.is_nan() {
        return palette::MAP_PENDING;
    }
    ramp_color(rate_position(rate))
}

/// What the stability maps and ρ(δ) show. ρ is per sampling period: it tends to 1 as δ → 0 for
/// any loop, so its shades cannot be compared across δ; ln ρ/δ is per second and can. Both say
/// stable exactly where ρ < 1 ⇔ ln ρ/δ < 0, so the ρ = 1 contour is the same line under both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Measure {
    /// The spectral radius ρ of one sampling period.
    #[default]
    Rho,
    /// The rate ln ρ/δ, 1/s: errors grow (> 0) or die out (< 0) as e^(rate·t).
    Rate,
}

impl Measure {
    /// The measure named `rho` or `rate` (the view parameter's values).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "rho" => Some(Measure::Rho),
            "rate" => Some(Measure::Rate),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Measure::Rho => "rho",
            Measure::Rate => "rate",
        }
    }

    /// The value shown for spectral radius `rho` at sampling period `delta` (s).
    pub fn value(self, rho: f64, delta: f64) -> f64 {
        match self {
            Measure::Rho => rho,
            Measure::Rate => rho.ln() / delta,
        }
    }

    /// The value at the edge of stability (ρ = 1): 1 or 0.
    pub fn border(self) -> f64 {
        match self {
            Measure::Rho => 1.0,
            Measure::Rate => 0.0,
        }
    }

    /// Where a shown value sits on the colour ramp, in [0, 1].
    pub fn position(self, value: f64) -> f64 {
        match self {
            Measure::Rho => rho_position(value),
            Measure::Rate => rate_position(value),
        }
    }

    /// The colour of a map cell with spectral radius `rho` at `delta` (s).
    pub fn color(self, rho: f64, delta: f64) -> Color {
        if rho.is_nan() {
            return palette::MAP_PENDING;
        }
        ramp_color(self.position(self.value(rho, delta)))
    }

    /// The symbol with its unit, as a colour bar names it: "ρ" or "ln ρ/δ (1/s)".
    pub fn symbol(self) -> &'static str {
        match self {
            Measure::Rho => "ρ",
            Measure::Rate => "ln ρ/δ (1/s)",
        }
    }

    /// The quantity as a figure's title names it.
    pub fn quantity(self) -> &'static str {
        match self {
            Measure::Rho => "Spectral radius ρ",
            Measure::Rate => "Rate ln ρ/δ (1/s)",
        }
    }

    /// The edge of stability in words: "ρ = 1" or "ln ρ/δ = 0".
    pub fn border_text(self) -> &'static str {
        match self {
            Measure::Rho => "ρ = 1",
            Measure::Rate => "ln ρ/δ = 0",
        }
    }
}
