//! Why some larger δ work without a preliminary feedback — which the paper leaves "not clear" —:
//! a heuristic, the lag of the held torque behind the swing (`tests/lag.rs`, `tests/lag_bias.rs`
//! measure it against ρ). The exact statement is the swing's energy balance over one period,
//! |λ|² − 1 = W_v + W_K − D ([`super::energy`]); this law only estimates its first term.
//!
//! The torque computed from the measurement at t_ρ acts on [t_ρ + δ, t_ρ + 2δ) (Fig. 2.1): on
//! the swing it arrives on average 1.5 δ late, by when the swing, turning at ω = |Im A4|, has
//! moved on by about φ = 1.5 ωδ. As δ → 0 the controller's feed 3β/2 pushes the swing along
//! (Re A4 = 3β/2 − B_v1/(2 I_r1) > 0). Treating the lagged feed like a describing function —
//! only cos φ of it still in phase with the swing — gives the growth
//!
//! σ(δ) ≈ (3β/2) cos(1.5 ωδ) − B_v1/(2 I_r1),
//!
//! which turns negative where φ = arccos(B_v1/(3β I_r1)) ([`LagLaw::zero_crossing_lag`]): before a
//! quarter turn wherever the motor is damped (83° on the paper's arm at α = 2), π/2 only for a
//! motor without damping. The law's lower edge, ωδ = arccos(B_v1/(3β I_r1))/1.5, depends on α and
//! on B_v1/I_r1, not on the spring: it is not the same on every arm.
//!
//! How well, measured over the grid of [`GRID_DESCRIPTION`] (`tests/lag_bias.rs`): the true lower
//! edge is [`LOWER_EDGE_RATIO`] times the law's. The law's edge is early on nearly every arm (late,
//! by a few %, only on stiff arms with heavy, lightly damped motors at small α), the more so the
//! faster the swing grows against its turn (3β/2 near ω/4: a soft spring, a heavy motor, a large
//! α). Just above its edge σ < 0 while the loop's swing still grows (the paper's arm at α = 2 and
//! δ = 0.034 s: σ = −0.17 1/s, ρ = 1.004): near the edge the law's sign is not to be trusted. In ωδ
//! the true lower edges spread over [`LOWER_EDGE_TURN`] rad. Nor is the law's phase the computed
//! one: the held T1 leads θ̇ as δ → 0 and lags it by less than 1.5 ωδ at small δ
//! (`SwingEnergy::lag`).
//!
//! The upper edge is a separate argument, not the law's (its σ returns to zero only at
//! 1.5 ωδ = 2π − φ₀, ωδ ≈ 3.22 on the paper's arm): at ωδ = π the swing turns half a turn per
//! period (the Nyquist frequency π/δ), the sampler sees it flip every period and cannot tell its
//! phase. Where the swing ends the window, it does so at ωδ within [`UPPER_EDGE_TURNS`] × π;
//! elsewhere a slow mode ends it (not before the lower bound) or it runs on.

use super::sampled::StabilityReport;

/// The grid [`LOWER_EDGE_RATIO`], [`LOWER_EDGE_TURN`] and [`UPPER_EDGE_TURNS`] are measured over
/// (`tests/lag_bias.rs` iterates over these arrays and asserts every point inside the bounds):
/// the factors on the paper's K1, I_r1 and B_v1, and α1 = α2, 1/s.
pub const GRID_STIFFNESS: [f64; 5] = [0.25, 0.5, 1.0, 2.0, 4.0];
pub const GRID_MOTOR_INERTIA: [f64; 5] = [0.25, 0.5, 1.0, 2.0, 4.0];
pub const GRID_MOTOR_DAMPING: [f64; 3] = [0.5, 1.0, 2.0];
pub const GRID_ALPHA: [f64; 4] = [0.5, 1.0, 2.0, 3.0];
/// The domain within the grid: where the law has a window (3β/2 > B_v1/(2 I_r1)) and the swing
/// turns fast against its growth, 3β/2 ≤ this × ω ([`LagLaw::in_domain`]).
pub const DOMAIN_FEED_PER_OMEGA: f64 = 0.25;
/// The grid and domain in words, for the page.
pub const GRID_DESCRIPTION: &str = "K1 and I_r1 each ¼, ½, 1, 2 and 4 times the paper's, B_v1 ½, 1 and 2 times, \
     α = 0.5, 1, 2 and 3 1/s, at rest with q2 = 0, no preliminary feedback, wherever the law has a window and \
     3β/2 ≤ ω/4";

/// The true lower edge of the loop's first stable window (where the flexible pair stops setting
/// ρ > 1) over the law's, min and max over the grid's domain, rounded outward to two decimals.
pub const LOWER_EDGE_RATIO: [f64; 2] = [0.96, 1.20];
/// ωδ at the true lower edge, rad, min and max over the grid's domain, rounded outward.
pub const LOWER_EDGE_TURN: [f64; 2] = [0.18, 1.21];
/// ωδ at the true upper edge of that window, in units of π, min and max over the grid's domain
/// where the swing sets it, rounded outward; where a slow mode ends the window (or none in the
/// range), it ends past the lower bound.
pub const UPPER_EDGE_TURNS: [f64; 2] = [0.94, 1.11];

/// Whether the grid the bounds are measured over covers this arm and α: α1 = α2 within
/// [`GRID_ALPHA`]'s span, K1, I_r1 and B_v1 within their factors' span of the paper's, and the rest
/// of the arm the paper's (the grid kept it so).
pub fn grid_covers(plant: &crate::model::PlantParameters, alpha: [f64; 2]) -> bool {
    let paper = crate::model::PlantParameters::default();
    let within = |v: f64, span: &[f64]| {
        let (lo, hi) = (span[0], span[span.len() - 1]);
        v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9)
    };
    let rest_is_papers =
        crate::model::PlantParameters { k1: paper.k1, ir1: paper.ir1, bv1: paper.bv1, ..*plant } == paper;
    alpha[0] == alpha[1]
        && within(alpha[0], &GRID_ALPHA)
        && within(plant.k1 / paper.k1, &GRID_STIFFNESS)
        && within(plant.ir1 / paper.ir1, &GRID_MOTOR_INERTIA)
        && within(plant.bv1 / paper.bv1, &GRID_MOTOR_DAMPING)
        && rest_is_papers
}

/// The lag law of one loop's resonance (its closed-form feed and damping, its swing ω).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LagLaw {
    /// ω = |Im A4|, rad/s: how fast the swing turns as δ → 0 without preliminary feedback.
    pub omega: f64,
    /// The controller's feed 3β/2 and the motor's damping B_v1/(2 I_r1), 1/s.
    pub feed: f64,
    pub damping: f64,
}

/// The lag φ₀ = arccos(B_v1/(3β I_r1)), rad, at which the law's lagged feed stops outweighing the
/// motor's damping. `None` where the damping already outweighs the feed as δ → 0.
pub fn zero_crossing(feed: f64, damping: f64) -> Option<f64> {
    (feed > damping).then(|| (damping / feed).acos())
}

/// Where the law's lagged feed stops pushing the swing: its lower edge in ωδ, φ₀/1.5, rad per
/// period. `None` where the motor's damping already outweighs the feed as δ → 0 (no window needed).
pub fn lower_turn(feed: f64, damping: f64) -> Option<f64> {
    zero_crossing(feed, damping).map(|phi| phi / 1.5)
}

impl LagLaw {
    /// The law of a report's resonance (ω from its δ → 0 pair without preliminary feedback).
    pub fn of(report: &StabilityReport) -> Self {
        let r = &report.resonance;
        Self { omega: report.limit_pair_open[0][1].abs(), feed: r.controller_feed, damping: r.motor_damping }
    }

    /// φ₀, rad: the lag at which the law's σ turns negative ([`zero_crossing`]).
    pub fn zero_crossing_lag(&self) -> Option<f64> {
        zero_crossing(self.feed, self.damping)
    }

    /// Whether the law has a window and the swing turns fast against its growth,
    /// 3β/2 ≤ [`DOMAIN_FEED_PER_OMEGA`] ω: the domain its measured bounds hold in.
    pub fn in_domain(&self) -> bool {
        self.feed > self.damping && self.feed <= DOMAIN_FEED_PER_OMEGA * self.omega
    }

    /// ωδ, rad: how far the swing turns in one sampling period.
    pub fn turn(&self, delta: f64) -> f64 {
        self.omega * delta
    }

    /// φ = 1.5 ωδ, rad: how far the swing has turned when the torque acts (on average).
    pub fn lag(&self, delta: f64) -> f64 {
        1.5 * self.turn(delta)
    }

    /// σ ≈ (3β/2) cos φ − B_v1/(2 I_r1), 1/s: the swing's growth the law estimates (for ωδ < π;
    /// near its zero its sign is not the loop's, see the module's doc).
    pub fn growth(&self, delta: f64) -> f64 {
        self.feed * self.lag(delta).cos() - self.damping
    }

    /// The law's window of δ, s: from the lower turn to ωδ = π. `None` where no window is needed
    /// (the motor damps the swing at every small δ) or the swing does not turn (ω = 0).
    pub fn window(&self) -> Option<[f64; 2]> {
        let low = lower_turn(self.feed, self.damping)?;
        (self.omega > 0.0).then(|| [low / self.omega, core::f64::consts::PI / self.omega])
    }
}
