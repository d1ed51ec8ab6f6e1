//! What part of the z-plane is shown: a centre and a half-size in units of λ, zoomed about a
//! point (the pointer stays on the same λ), panned, kept within limits, and — by default — chosen
//! around the flexible pair so that its distance from the unit circle can be seen.
//!
//! Why a default zoom rather than an inset: at Fig. 5.3 the flexible pair sits at |λ| = 1.024,
//! 3 px outside the circle in a whole-circle view of a 250-px panel. An inset would show the pair
//! twice, so every marker, tooltip, keyboard stop and label would need two places and a rule for
//! which one the pointer means, and in a square panel it would cover part of the circle. One
//! frame, zoomed only as far as the pair's distance from the circle needs ([`ZView::around`]),
//! keeps one place per eigenvalue; the view is the whole circle whenever that already shows the
//! distance (a pair well inside), and the whole circle is one key (`0`) or button away.

use serde::Serialize;

/// Half of the shorter side of "the whole circle": the unit circle and a margin. The widest view.
pub const WHOLE_HALF: f64 = 1.2;
/// The narrowest view: half of its shorter side, in units of λ.
pub const MIN_HALF: f64 = 1e-4;
/// The view's shorter side stays within ±this in Re λ and Im λ: its centre within ±(this −
/// half-size), so the widest view is the whole circle give or take 0.3 (eigenvalues beyond are
/// marked at the edge).
pub const CENTER_LIMIT: f64 = 1.5;
/// The default view puts the flexible pair at least this many CSS px from the unit circle.
pub const AUTO_GAP: f64 = 40.0;
/// The default view zooms no further than this half-size (a pair on the circle is read in the
/// mark's |λ| − 1, not by zooming to nothing).
pub const AUTO_MIN_HALF: f64 = 0.005;

/// A view of the z-plane: the centre (Re λ, Im λ) and half the span along the panel's shorter
/// side; both axes have the same scale, so the longer side shows more.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ZView {
    pub center: [f64; 2],
    pub half: f64,
}

impl Default for ZView {
    fn default() -> Self {
        ZView::WHOLE
    }
}

impl ZView {
    /// The whole unit circle, centred.
    pub const WHOLE: ZView = ZView { center: [0.0, 0.0], half: WHOLE_HALF };

    /// Within the limits: half-size from [`MIN_HALF`] to [`WHOLE_HALF`], centre within
    /// ±([`CENTER_LIMIT`] − half-size); anything not finite is the whole circle.
    pub fn clamped(self) -> ZView {
        let [x, y] = self.center;
        if !(x.is_finite() && y.is_finite() && self.half.is_finite()) {
            return ZView::WHOLE;
        }
        let half = self.half.clamp(MIN_HALF, WHOLE_HALF);
        let limit = CENTER_LIMIT - half;
        let c = |v: f64| v.clamp(-limit, limit);
        ZView { center: [c(x), c(y)], half }
    }

    /// Zoomed in by `factor` (> 1 in, < 1 out) about the point `at` (λ), which stays where it
    /// is on the screen: every point's offset from `at` shrinks by the same ratio as the view.
    /// At a limit the ratio is the one the limit allows, so `at` still stays put.
    pub fn zoomed_about(self, at: [f64; 2], factor: f64) -> ZView {
        if !(factor.is_finite() && factor > 0.0 && at[0].is_finite() && at[1].is_finite()) {
            return self;
        }
        let half = (self.half / factor).clamp(MIN_HALF, WHOLE_HALF);
        let ratio = half / self.half;
        let c = self.center;
        ZView { center: [at[0] + (c[0] - at[0]) * ratio, at[1] + (c[1] - at[1]) * ratio], half }.clamped()
    }

    /// Moved by `d` (λ): the view's centre goes to centre + d.
    pub fn panned(self, d: [f64; 2]) -> ZView {
        ZView { center: [self.center[0] + d[0], self.center[1] + d[1]], half: self.half }.clamped()
    }

    /// Rounded for the state string: the half-size to 3 significant digits, the centre to a
    /// thousandth of it (under a pixel in any panel), so a link stays short.
    pub fn rounded(self) -> ZView {
        let half = crate::schema::round_significant(self.half, 3);
        let quantum = 10f64.powf((half.log10() - 3.0).floor());
        let r = |v: f64| {
            let q = (v / quantum).round() * quantum;
            // Through the decimal text, so the state string prints 0.983 and not 0.98300000001.
            crate::schema::round_significant(q, 15)
        };
        ZView { center: [r(self.center[0]), r(self.center[1])], half }.clamped()
    }

    /// The default view for a panel whose shorter side is `short_px` CSS px: the whole circle if
    /// that already puts `pair` (the flexible pair's upper eigenvalue) [`AUTO_GAP`] px or more
    /// from the unit circle, else zoomed just enough for that, centred near the point midway
    /// between the pair and the circle (drifting towards the origin as the view widens, so the
    /// view turns into the whole circle without a jump). `None` (no pair) is the whole circle.
    pub fn around(pair: Option<[f64; 2]>, short_px: f64) -> ZView {
        let Some(p) = pair.filter(|p| p[0].is_finite() && p[1].is_finite()) else { return ZView::WHOLE };
        let r = p[0].hypot(p[1]);
        if !(r > 0.0 && short_px > 0.0) {
            return ZView::WHOLE;
        }
        let gap = r - 1.0;
        let half = (gap.abs() * short_px / (2.0 * AUTO_GAP)).max(AUTO_MIN_HALF);
        if half >= WHOLE_HALF {
            return ZView::WHOLE;
        }
        let mid = (1.0 + gap / 2.0) / r;
        let t = 1.0 - (half / WHOLE_HALF).powi(2);
        ZView { center: [p[0] * mid * t, p[1] * mid * t], half }.clamped()
    }
}
