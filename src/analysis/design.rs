//! The preliminary feedback as a design: the twist gains that place the flexible pair where one
//! wants it (or why none in their ranges does), and the digital price of a design — where along δ
//! the loop is stable with the feedback acting continuously (an analog inner loop) and held over
//! each sampling period (a sampled one, as the computer would apply it). More damping cures small
//! δ and, sampled, shrinks the largest δ that works.

use nalgebra::Complex;
use serde::Serialize;

use super::resonance::{twist_placing, JointResonance};
use super::sampled::LinearSettings;
use super::windows::{stable_windows, StableWindows};
use crate::control::config::{InnerLoop, PreliminaryFeedbackChoice};
use crate::error::Error;
use crate::model::params::PlantParameters;
use crate::schema::{Kind, TWIST_DAMPING, TWIST_STIFFNESS};

/// Why no twist feedback in the gains' ranges places the pair at a target.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
pub enum Unplaceable {
    /// The target is on (or below) the real axis: a pair there is two real modes, not a swing.
    RealAxis,
    /// Right of the pair with no damper (Re = `re_max`): it would take a negative k_d, a damper
    /// that pushes the swing.
    NeedsNegativeDamping { re_max: f64 },
    /// Slower than the spring alone allows (|s| below `norm_min`, rad/s, at this real part): it
    /// would take a negative k_p, softening the joint.
    NeedsNegativeStiffness { norm_min: f64 },
    /// A gain beyond its setting's range (`key`, the gain it would take and the range's end).
    BeyondRange { key: &'static str, value: f64, max: f64 },
}

/// The twist gains [k_p, k_d] that put the δ → 0 pair at `target` (and its conjugate) at rest at
/// link-2 angle `q2` for α, within the gains' ranges ([`TWIST_STIFFNESS`], [`TWIST_DAMPING`]).
pub fn place_twist(
    plant: &PlantParameters,
    alpha: [f64; 2],
    q2: f64,
    target: Complex<f64>,
) -> Result<[f64; 2], Unplaceable> {
    if !(target.im > 0.0 && target.re.is_finite() && target.im.is_finite()) {
        return Err(Unplaceable::RealAxis);
    }
    let [stiffness, damping] = twist_placing(plant, alpha, q2, target);
    if damping < 0.0 {
        return Err(Unplaceable::NeedsNegativeDamping { re_max: JointResonance::new(plant, alpha, q2).real_part() });
    }
    if stiffness < 0.0 {
        // det A4 = |s|² is linear in k_p with slope a01/Ir1: at this real part the slowest pair
        // any k_p ≥ 0 makes is the one of k_p = 0.
        let a01 = JointResonance::new(plant, alpha, q2).a4[(0, 1)];
        let norm_min = (target.norm_sqr() - stiffness * a01 / plant.ir1).max(0.0).sqrt();
        return Err(Unplaceable::NeedsNegativeStiffness { norm_min });
    }
    for (param, value) in [(&TWIST_STIFFNESS, stiffness), (&TWIST_DAMPING, damping)] {
        if let Kind::Number(spec) = param.kind {
            if value > spec.max {
                return Err(Unplaceable::BeyondRange { key: param.key, value, max: spec.max });
            }
        }
    }
    Ok([stiffness, damping])
}

/// The stable windows of δ with the preliminary feedback acting continuously and held over δ.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DigitalPrice {
    /// The inner loop analog: u = K_pr x at every instant.
    pub analog: StableWindows,
    /// The inner loop sampled: K_pr x taken at the sampling instants and held.
    pub sampled: StableWindows,
}

impl DigitalPrice {
    /// The windows of `settings` (its δ and inner loop ignored) over `range`, s.
    pub fn of(settings: &LinearSettings, range: [f64; 2]) -> Result<Self, Error> {
        let with = |inner_loop| stable_windows(&LinearSettings { inner_loop, ..*settings }, range);
        Ok(Self { analog: with(InnerLoop::Continuous)?, sampled: with(InnerLoop::Sampled)? })
    }

    /// The windows of one inner loop.
    pub fn windows(&self, inner: InnerLoop) -> &StableWindows {
        match inner {
            InnerLoop::Continuous => &self.analog,
            InnerLoop::Sampled => &self.sampled,
        }
    }
}

/// The largest stable δ, δ_max: the top of the lowest window — as δ grows past the δ that work,
/// where the loop first fails (None if no δ works; the range's end if it never fails in it).
/// Islands of stability above it (the swing aliased onto a lucky phase) are not counted: the
/// smallest change of the arm moves them.
pub fn largest_stable_delta(windows: &StableWindows) -> Option<f64> {
    windows.windows.first().map(|w| w[1])
}

/// True when every δ from the range's start up to some δ works: the cure of small δ.
pub fn small_delta_cured(windows: &StableWindows) -> bool {
    windows.windows.first().is_some_and(|w| w[0] <= windows.range[0])
}

/// The twist damping that keeps the δ → 0 pair stable for a twist stiffness k_p, N m s/rad: above
/// k_d* = 3β Ir1 − Bv1 (tr A4 < 0: the pair damped) and, while the controller feeds the resonance
/// (3β > 0), below the damping at which det A4 = 0 — beyond it the motor no longer swings against
/// link 1 and a slow real mode grows. A stiffer twist spring raises that upper bound:
/// det A4 = a00 (a11 − k_d/Ir1) − a01 (a10 − k_p/Ir1). Between the two the pair stops swinging
/// first, at `swings_below` (tr² = 4 det), and stays stable as two real eigenvalues up to `upper`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DampingWindow {
    pub lower: f64,
    /// None where the controller drains the resonance (3β ≤ 0): no upper bound.
    pub upper: Option<f64>,
    /// The k_d above which the pair is two real eigenvalues (the motor no longer swings against
    /// link 1), N m s/rad; None where it never swings (a01 (a10 − k_p/Ir1) ≥ 0).
    pub swings_below: Option<f64>,
}

impl DampingWindow {
    pub fn of(plant: &PlantParameters, alpha: [f64; 2], q2: f64, stiffness: f64) -> Self {
        let a = JointResonance::new(plant, alpha, q2).a4;
        let ir1 = plant.ir1;
        let lower = ir1 * a.trace();
        let upper =
            (a[(0, 0)] > 0.0).then(|| ir1 * (a[(1, 1)] - a[(0, 1)] * (a[(1, 0)] - stiffness / ir1) / a[(0, 0)]));
        // (a00 − a11 + k_d/Ir1)² = −4 a01 (a10 − k_p/Ir1): the discriminant of A4 vanishes.
        let spring = -a[(0, 1)] * (a[(1, 0)] - stiffness / ir1);
        let swings_below = (spring > 0.0).then(|| ir1 * (2.0 * spring.sqrt() - a[(0, 0)] + a[(1, 1)]));
        Self { lower, upper, swings_below }
    }

    /// True when k_d lies in the window.
    pub fn contains(&self, damping: f64) -> bool {
        damping > self.lower && self.upper.is_none_or(|u| damping < u)
    }
}

/// Whether a preliminary feedback choice is a design the page lets one place by hand.
pub fn placeable(pf: PreliminaryFeedbackChoice) -> bool {
    pf == PreliminaryFeedbackChoice::Twist
}
