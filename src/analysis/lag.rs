//! Why some larger δ work without a preliminary feedback — which the paper leaves "not clear" —:
//! the lag of the held torque behind the swing (found here; `tests/lag.rs` checks it against ρ
//! over arms and α).
//!
//! The torque computed from the measurement at t_ρ acts on [t_ρ + δ, t_ρ + 2δ) (Fig. 2.1): on
//! the swing it arrives on average 1.5 δ late, by when the swing, turning at ω = |Im A4|, has
//! moved on by the phase φ = 1.5 ωδ. As δ → 0 the controller's feed 3β/2 pushes the swing along
//! (Re A4 = 3β/2 − B_v1/(2 I_r1) > 0); lagged by φ only cos φ of it still pushes, and past a
//! quarter turn it brakes. The swing then grows at about
//!
//! σ(δ) ≈ (3β/2) cos(1.5 ωδ) − B_v1/(2 I_r1),
//!
//! which turns negative at ωδ = arccos(B_v1/(3β I_r1))/1.5 — π/3 for a motor without damping.
//! At ωδ = π the swing turns half a turn per period (the Nyquist frequency π/δ): the sampler sees
//! it flip every period and cannot tell its phase, and beyond it the swing is aliased — the lag
//! argument ends there. So the controller alone works for ωδ from about arccos(…)/1.5 to about
//! π, whatever the arm: the window that scales as 1/ω when the spring or the motor changes.
//!
//! How well: the true lower edge lies 0–25 % above the law's (the predictor's horizon and the
//! hold shift the effective lag a little below 1.5 δ), the true upper edge between 0.84 π and π.

use super::sampled::StabilityReport;

/// The lag law of one loop's resonance (its closed-form feed and damping, its swing ω).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LagLaw {
    /// ω = |Im A4|, rad/s: how fast the swing turns as δ → 0 without preliminary feedback.
    pub omega: f64,
    /// The controller's feed 3β/2 and the motor's damping B_v1/(2 I_r1), 1/s.
    pub feed: f64,
    pub damping: f64,
}

/// Where the lagged feed stops pushing the swing: the law's lower edge in ωδ, rad per period.
/// `None` where the motor's damping already outweighs the feed as δ → 0 (no window needed).
pub fn lower_turn(feed: f64, damping: f64) -> Option<f64> {
    (feed > damping).then(|| (damping / feed).acos() / 1.5)
}

impl LagLaw {
    /// The law of a report's resonance (ω from its δ → 0 pair without preliminary feedback).
    pub fn of(report: &StabilityReport) -> Self {
        let r = &report.resonance;
        Self { omega: report.limit_pair_open[0][1].abs(), feed: r.controller_feed, damping: r.motor_damping }
    }

    /// ωδ, rad: how far the swing turns in one sampling period.
    pub fn turn(&self, delta: f64) -> f64 {
        self.omega * delta
    }

    /// φ = 1.5 ωδ, rad: how far the swing has turned when the torque acts (on average).
    pub fn lag(&self, delta: f64) -> f64 {
        1.5 * self.turn(delta)
    }

    /// σ ≈ (3β/2) cos φ − B_v1/(2 I_r1), 1/s: the swing's growth the law predicts (for ωδ < π).
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
