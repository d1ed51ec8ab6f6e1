//! The flexible joint's resonance and what the controller does to it, in closed form: the pair
//! A4 of section 3 (the δ → 0 limit) written in the arm's own parameters.
//!
//! # Why the pair exists
//! Linearized at rest at link angle q2, with the friction cancelled, let c_i = ë_i + 3α_i ė_i +
//! 3α_i² e_i + w_i be what is left of constraint (4.3). The limit controller reads only the links
//! (its gain has zero columns for θ and θ̇). It can impose c2 = 0 through T2, but reaches link 1
//! only through the spring: the links obey their law (c = 0) exactly when the motor sits at
//! θ* = q1 + (M11 r1 + M12 r2)/K1, with r_i = −3α_i q̇_i − 3α_i² q_i − w_i the acceleration the law
//! asks of link i. What the controller cannot see is the gap z = θ − θ* and its rate
//! y = θ̇ − θ̇*|_{c=0}. Differentiating along eq. (4.1) gives
//!
//! ```text
//! ż = 3β z + y
//! ẏ = −(K1/Ir1 + K1/J_eff + 6γ) z − (Bv1/Ir1) y
//! ```
//!
//! with J_eff = A1 − A2 − (A3²/A2) cos² q2 (link 1's inertia as the spring feels it, link 2 free),
//! μ = (A2 + A3 cos q2)²/(A2 J_eff), β = α1 + μ (α1 − α2), γ = α1² + μ (α1² − α2²). A gap z > 0
//! accelerates link 1 by K1 z/J_eff ahead of its law; reading only the links, the controller
//! answers by moving θ* the other way, and the gap widens at the rate 3β. So
//! Re A4 = 3β/2 − Bv1/(2 Ir1) (= 3α/2 − Bv1/(2 Ir1) for α1 = α2): the controller feeds the
//! joint's resonance, and only the motor's own damping opposes it. The frequency is close to the
//! two-inertia resonance √(K1 (1/Ir1 + 1/J_eff)) of motor against link.
//!
//! A preliminary feedback K acts on the pair only through its columns for θ and θ̇ (the
//! predictor cancels the rest on V*): with ΔT = K_θ z + K_θ̇ y it adds ΔT1/Ir1 to ẏ, and T2 reaches
//! the pair through the mass matrix ([`closed_form_a4`]).
//!
//! `tests/resonance.rs` checks all of it against the numerical limit of [`super::limit_pair`].

use nalgebra::{Complex, Matrix2};
use serde::{Deserialize, Serialize};

use crate::control::predictive::FeedbackGain;
use crate::model::params::PlantParameters;

/// The closed-form quantities of the joint's resonance at one rest point and α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointResonance {
    /// q2 of the rest point, rad.
    pub q2: f64,
    /// α1, α2, 1/s.
    pub alpha: [f64; 2],
    /// J_eff = A1 − A2 − (A3²/A2) cos² q2, kg m²: link 1's inertia as the spring feels it.
    pub j_eff: f64,
    /// μ = (A2 + A3 cos q2)²/(A2 J_eff): how much of α2 reaches the pair when α1 ≠ α2.
    pub mu: f64,
    /// β = α1 + μ (α1 − α2), 1/s: the rate 3β at which the controller widens the gap z.
    pub beta: f64,
    /// A4 without preliminary feedback, in the coordinates (z, y) = (θ − θ*, θ̇ − θ̇*).
    pub a4: Matrix2<f64>,
    /// Its eigenvalues, positive imaginary part first, 1/s.
    pub eigenvalues: [Complex<f64>; 2],
    /// ω = √(K1 (1/Ir1 + 1/J_eff)), rad/s: the motor swinging against link 1 (two inertias).
    pub omega_joint: f64,
    /// √(K1/Ir1), rad/s: the motor against a clamped link.
    pub omega_clamped: f64,
    /// Bv1/(2 Ir1), 1/s: the damping the motor's own viscous friction gives the pair.
    pub motor_damping: f64,
    /// 3β/2, 1/s: the negative damping the controller injects.
    pub controller_feed: f64,
}

impl JointResonance {
    /// The resonance of `plant` (validated: J_eff > 0) at rest at `q2` under α.
    pub fn new(plant: &PlantParameters, alpha: [f64; 2], q2: f64) -> Self {
        let p = plant;
        let m = Mass::at(p, q2);
        let [a1, a2] = alpha;
        let beta = a1 + m.mu * (a1 - a2);
        let gamma = a1 * a1 + m.mu * (a1 * a1 - a2 * a2);
        let a4 = Matrix2::new(3.0 * beta, 1.0, -(p.k1 / p.ir1 + p.k1 / m.j_eff + 6.0 * gamma), -p.bv1 / p.ir1);
        Self {
            q2,
            alpha,
            j_eff: m.j_eff,
            mu: m.mu,
            beta,
            a4,
            eigenvalues: ordered(a4.complex_eigenvalues()),
            omega_joint: (p.k1 * (1.0 / p.ir1 + 1.0 / m.j_eff)).sqrt(),
            omega_clamped: (p.k1 / p.ir1).sqrt(),
            motor_damping: p.bv1 / (2.0 * p.ir1),
            controller_feed: 1.5 * beta,
        }
    }

    /// Re A4 = 3β/2 − Bv1/(2 Ir1), 1/s.
    pub fn real_part(&self) -> f64 {
        self.controller_feed - self.motor_damping
    }

    /// tr A4 = 3β − Bv1/Ir1, 1/s.
    pub fn trace(&self) -> f64 {
        self.a4.trace()
    }

    /// det A4, 1/s²: the square of the pair's natural frequency.
    pub fn determinant(&self) -> f64 {
        self.a4.determinant()
    }
}

/// α* = Bv1/(3 Ir1), 1/s: for α1 = α2 below it the motor's damping outweighs what the
/// controller feeds the resonance, and the δ → 0 pair is stable without any preliminary
/// feedback.
pub fn alpha_star(plant: &PlantParameters) -> f64 {
    plant.bv1 / (3.0 * plant.ir1)
}

/// Where the δ → 0 pair stops being stable as α = α1 = α2 grows from 0, under a fixed preliminary
/// feedback `gain` (zeros for none). For α1 = α2 the pair is A4(α) = [[3α, 1], [−(c + 6α²), −b]]
/// with b = (Bv1 − K_θ̇,1)/Ir1 − λ K_θ̇,2 and c = K1/Ir1 + K1/J_eff − K_θ,1/Ir1 − λ K_θ,2
/// ([`closed_form_a4`]), so
///
/// ```text
/// tr A4 = 3α − b            (zero at α = b/3: α* for no feedback)
/// det A4 = 6α² − 3bα + c    (zero at α = (3b ± √(9b² − 24c))/12 where 9b² ≥ 24c)
/// ```
///
/// The pair is stable exactly where tr A4 < 0 and det A4 > 0. Where det A4 has real roots the
/// smaller one lies below b/3, so a heavily damped motor (b² ≥ 8c/3) loses the pair to det first:
/// the pair is then two real eigenvalues and one of them crosses zero (the motor no longer
/// swings, and a slow real mode grows) before tr A4 reaches zero.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AlphaBound {
    /// α where tr A4 = 0, 1/s (α* = Bv1/(3 Ir1) without feedback; may be ≤ 0).
    pub trace_zero: f64,
    /// The smaller α ≥ 0 where det A4 = 0, 1/s, if det A4 has a real root there.
    pub det_zero: Option<f64>,
}

impl AlphaBound {
    /// The bound of the pair under `gain` at rest at `q2`.
    pub fn new(plant: &PlantParameters, q2: f64, gain: &FeedbackGain) -> Self {
        // The matrix at α = 0 gives b and c; the α terms are the closed form's own.
        let a = closed_form_a4(plant, [0.0, 0.0], q2, gain);
        let (b, c) = (-a[(1, 1)], -a[(1, 0)]);
        let disc = 9.0 * b * b - 24.0 * c;
        let det_zero = if c <= 0.0 {
            // det A4 ≤ 0 already at α = 0: a real eigenvalue is ≥ 0 for every α.
            Some(0.0)
        } else if disc >= 0.0 && b > 0.0 {
            Some((3.0 * b - disc.sqrt()) / 12.0)
        } else {
            None
        };
        Self { trace_zero: b / 3.0, det_zero }
    }

    /// The pair is stable for 0 ≤ α < this, 1/s (0 where it is unstable already at α = 0).
    pub fn stable_below(&self) -> f64 {
        self.det_zero.map_or(self.trace_zero, |d| d.min(self.trace_zero)).max(0.0)
    }

    /// Whether det A4 = 0 comes first (the pair turns real and a real eigenvalue crosses zero),
    /// rather than tr A4 = 0 (a swing that starts to grow).
    pub fn lost_to_det(&self) -> bool {
        self.det_zero.is_some_and(|d| d < self.trace_zero)
    }
}

/// Whether a 2×2 real matrix with this trace and determinant has a complex pair (a swing):
/// tr² < 4 det.
pub fn swings(trace: f64, det: f64) -> bool {
    trace * trace < 4.0 * det
}

/// B4: how the torques enter the pair, in (ż, ẏ) per N m of (T1, T2) (its columns): T1 adds
/// T1/Ir1 to ẏ; T2 changes both link accelerations (c = M⁻¹ [0; T2]), and so θ*'s rate (κ, zero
/// for α1 = α2) and link 1's acceleration in θ*'s second derivative (λ):
///
/// ```text
/// B4 = [[0, κ], [1/Ir1, λ]],  κ = 3 M11 M12 (α2 − α1)/(A2 J_eff K1),
///                            λ = M12/(A2 J_eff) − 6 M11 M12 (α2² − α1²)/(A2 J_eff K1)
/// ```
///
/// A feedback ΔT = K (z, y) on the pair's coordinates (K's columns for θ and θ̇) makes the pair
/// A4 + B4 K ([`closed_form_a4`]): the input matrix a design targeting the pair needs.
pub fn input_matrix(plant: &PlantParameters, alpha: [f64; 2], q2: f64) -> Matrix2<f64> {
    let p = plant;
    let m = Mass::at(p, q2);
    let [a1, a2] = alpha;
    let det = p.a2 * m.j_eff;
    let kappa = 3.0 * m.m11 * m.m12 * (a2 - a1) / (det * p.k1);
    let lambda = m.m12 / det - 6.0 * m.m11 * m.m12 * (a2 * a2 - a1 * a1) / (det * p.k1);
    Matrix2::new(0.0, kappa, 1.0 / p.ir1, lambda)
}

/// A4 in closed form with the preliminary feedback `gain` acting continuously (u = K x + v):
/// the pair of [`JointResonance`] plus B4 ([`input_matrix`]) times K's columns for θ and θ̇ (the
/// predictor cancels the rest on V*).
pub fn closed_form_a4(plant: &PlantParameters, alpha: [f64; 2], q2: f64, gain: &FeedbackGain) -> Matrix2<f64> {
    let base = JointResonance::new(plant, alpha, q2).a4;
    // ΔT = K_θ z + K_θ̇ y: the rows are T1 and T2.
    let on_pair = Matrix2::new(gain[(0, 2)], gain[(0, 5)], gain[(1, 2)], gain[(1, 5)]);
    base + input_matrix(plant, alpha, q2) * on_pair
}

/// The twist feedback ([`crate::control::feedback::twist_gain`]) that places the δ → 0 pair at
/// `target` and its conjugate: (k_p, k_d) in N m/rad and N m s/rad. The twist adds
/// −(k_p z + k_d y)/Ir1 to ẏ, so tr A4 = tr A4⁰ − k_d/Ir1 fixes k_d from 2 Re target, and then
/// det A4, linear in k_p, fixes k_p from |target|². Any pair is reachable this way (two gains for
/// the two coefficients of the characteristic polynomial); whether the gains are sensible is the
/// settings' ranges' business.
pub fn twist_placing(plant: &PlantParameters, alpha: [f64; 2], q2: f64, target: Complex<f64>) -> [f64; 2] {
    let a = JointResonance::new(plant, alpha, q2).a4;
    let ir1 = plant.ir1;
    // tr = a00 + a11 − k_d/Ir1 = 2 Re λ.
    let damping = ir1 * (a.trace() - 2.0 * target.re);
    // det = a00 (a11 − k_d/Ir1) − a01 (a10 − k_p/Ir1) = |λ|².
    let stiffness =
        ir1 / a[(0, 1)] * (target.norm_sqr() - a[(0, 0)] * (a[(1, 1)] - damping / ir1) + a[(0, 1)] * a[(1, 0)]);
    [stiffness, damping]
}

/// How far a preliminary feedback moves the pair's real part (half the change of tr A4), 1/s.
/// For α1 = α2 it does not depend on α: ½ [K_θ̇,1/Ir1 + (A2 + A3 cos q2) K_θ̇,2/(A2 J_eff)],
/// through its gains on θ̇ alone; with α1 ≠ α2 its T2 part changes with them.
pub fn feedback_shift(plant: &PlantParameters, alpha: [f64; 2], q2: f64, gain: &FeedbackGain) -> f64 {
    let open = JointResonance::new(plant, alpha, q2).a4;
    0.5 * (closed_form_a4(plant, alpha, q2, gain).trace() - open.trace())
}

/// The largest α (α1 = α2) for which a fixed preliminary feedback with Re-shift `shift` (from
/// [`feedback_shift`] at α1 = α2) keeps the δ → 0 pair stable: 3α/2 − Bv1/(2 Ir1) + shift < 0 (α*
/// itself for no feedback).
pub fn alpha_limit(plant: &PlantParameters, shift: f64) -> f64 {
    (plant.bv1 / (2.0 * plant.ir1) - shift) / 1.5
}

/// The arm's own pair with no controller (no torque, the friction cancelled) at rest at `q2`:
/// the oscillatory eigenvalues of eq. (4.1) linearized, positive imaginary part first.
pub fn arm_pair(plant: &PlantParameters, q2: f64) -> [Complex<f64>; 2] {
    let model = super::linearize_at_rest(plant, [1.0, 1.0], [0.0, q2]);
    // The 6×6 mechanical block, padded into the 10×10 size the loop's eigenvalues already use
    // (one eigen-solver in the page's module, not two); the padding adds four zeros.
    let mut m = crate::control::linear::Mat10::zeros();
    m.fixed_view_mut::<6, 6>(0, 0).copy_from(&model.a.fixed_view::<6, 6>(0, 0));
    let ev = m.complex_eigenvalues();
    let top = ev.iter().copied().fold(Complex::new(0.0, 0.0), |best, z| if z.im > best.im { z } else { best });
    [top, top.conj()]
}

fn rows(m: &Matrix2<f64>) -> [[f64; 2]; 2] {
    [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]]
}

fn ordered(ev: nalgebra::Vector2<Complex<f64>>) -> [Complex<f64>; 2] {
    if ev[0].im >= ev[1].im {
        [ev[0], ev[1]]
    } else {
        [ev[1], ev[0]]
    }
}

/// The mass matrix's entries at q2 and the two derived inertias.
struct Mass {
    m11: f64,
    m12: f64,
    j_eff: f64,
    mu: f64,
}

impl Mass {
    fn at(p: &PlantParameters, q2: f64) -> Self {
        let c = q2.cos();
        let m11 = p.a1 + 2.0 * p.a3 * c;
        let m12 = p.a2 + p.a3 * c;
        // det M2 = A2 M11 − M12² = A2 J_eff.
        let j_eff = p.a1 - p.a2 - p.a3 * p.a3 / p.a2 * c * c;
        Self { m11, m12, j_eff, mu: m12 * m12 / (p.a2 * j_eff) }
    }
}

/// The joint's resonance at a loop's rest point, as the reports carry it (numbers only).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResonanceReport {
    /// J_eff, kg m².
    pub j_eff: f64,
    /// μ.
    pub mu: f64,
    /// β = α1 + μ (α1 − α2), 1/s.
    pub beta: f64,
    /// A4 without preliminary feedback in (z, y), rows.
    pub a4: [[f64; 2]; 2],
    /// A4 with the loop's preliminary feedback acting continuously, in (z, y), rows.
    pub a4_with_feedback: [[f64; 2]; 2],
    /// B4, how the torques (T1, T2: the columns) enter (ż, ẏ), rows ([`input_matrix`]).
    pub a4_input: [[f64; 2]; 2],
    /// tr A4, 1/s; det A4, 1/s².
    pub trace: f64,
    pub determinant: f64,
    /// Re A4 = 3β/2 − Bv1/(2 Ir1), and its two parts, 1/s.
    pub real_part: f64,
    pub controller_feed: f64,
    pub motor_damping: f64,
    /// √(K1 (1/Ir1 + 1/J_eff)) and √(K1/Ir1), rad/s.
    pub omega_joint: f64,
    pub omega_clamped: f64,
    /// The arm's own pair with no controller (friction cancelled), upper one, 1/s.
    pub arm_pair: [f64; 2],
    /// α* = Bv1/(3 Ir1), 1/s.
    pub alpha_star: f64,
    /// Where the pair without preliminary feedback stops being stable as α = α1 = α2 grows.
    pub open_bound: AlphaBound,
    /// The same under the loop's fixed preliminary feedback (None without one, or where the gain
    /// changes with α), and under the paper's K_pr whatever the loop's own feedback.
    pub feedback_bound: Option<AlphaBound>,
    pub paper_bound: AlphaBound,
    /// What the loop's preliminary feedback adds to Re A4, 1/s (0 without one).
    pub feedback_shift: f64,
    /// For a fixed gain (the paper's), the largest α = α1 = α2 it keeps the pair stable at, 1/s.
    pub feedback_alpha_limit: Option<f64>,
    /// The same for the paper's K_pr whatever the loop's own feedback (the maps with K_pr use it).
    pub paper_alpha_limit: f64,
}

impl ResonanceReport {
    /// The report for `plant` at rest at `q2` under α, with the preliminary feedback `gain`
    /// (`fixed`: the gain does not change with α, so its α limit means something).
    pub fn new(plant: &PlantParameters, alpha: [f64; 2], q2: f64, gain: &FeedbackGain, fixed: bool) -> Self {
        let r = JointResonance::new(plant, alpha, q2);
        let own = arm_pair(plant, q2)[0];
        let shift = feedback_shift(plant, alpha, q2, gain);
        let damps = fixed && shift < 0.0;
        // Where det A4 reaches zero first (a heavily damped motor) the trace's limit is too high.
        let feedback_bound = damps.then(|| AlphaBound::new(plant, q2, gain));
        // The limit is for α1 = α2, where the shift does not depend on α.
        let paper_bound = AlphaBound::new(plant, q2, &crate::control::feedback::paper_gain());
        Self {
            j_eff: r.j_eff,
            mu: r.mu,
            beta: r.beta,
            a4: rows(&r.a4),
            a4_with_feedback: rows(&closed_form_a4(plant, alpha, q2, gain)),
            a4_input: rows(&input_matrix(plant, alpha, q2)),
            trace: r.trace(),
            determinant: r.determinant(),
            real_part: r.real_part(),
            controller_feed: r.controller_feed,
            motor_damping: r.motor_damping,
            omega_joint: r.omega_joint,
            omega_clamped: r.omega_clamped,
            arm_pair: [own.re, own.im],
            alpha_star: alpha_star(plant),
            open_bound: AlphaBound::new(plant, q2, &FeedbackGain::zeros()),
            feedback_bound,
            paper_bound,
            feedback_shift: shift,
            feedback_alpha_limit: feedback_bound.map(|b| b.stable_below()),
            paper_alpha_limit: paper_bound.stable_below(),
        }
    }
}

impl ResonanceReport {
    /// A4's two eigenvalues where they are real (tr² ≥ 4 det: the motor no longer swings), the
    /// larger first; None for a swing, whose real part is Re A4.
    pub fn real_eigenvalues(&self) -> Option<[f64; 2]> {
        if swings(self.trace, self.determinant) {
            return None;
        }
        let root = (self.trace * self.trace / 4.0 - self.determinant).max(0.0).sqrt();
        Some([self.real_part + root, self.real_part - root])
    }

    /// The motor damping B_v1 that decides the pair without preliminary feedback as δ → 0, N m s/rad,
    /// three thresholds: the pair dies out above 3β I_r1 (tr A4 < 0); it stops swinging above
    /// I_r1 (2 √(det A4 + 3β B_v1/I_r1) − 3β) (tr² = 4 det: two real eigenvalues, both still
    /// stable); and a real one grows only above the bound where det A4 < 0. None where the
    /// controller drains the resonance (β ≤ 0) and no damping is needed. `plant` is the arm the
    /// report is of.
    pub fn damping_window(&self, plant: &PlantParameters) -> Option<DampingThresholds> {
        if self.beta <= 0.0 {
            return None;
        }
        // det A4 without the motor's damping term: Ω² = K1/Ir1 + K1/J_eff + 6γ, which B_v1 leaves.
        let stiffness = self.determinant + 3.0 * self.beta * plant.bv1 / plant.ir1;
        Some(DampingThresholds {
            damped_above: 3.0 * self.beta * plant.ir1,
            // (3β + B_v1/Ir1)² = 4 Ω²: the discriminant of A4 vanishes.
            swings_below: plant.ir1 * (2.0 * stiffness.max(0.0).sqrt() - 3.0 * self.beta),
            unstable_above: stiffness * plant.ir1 / (3.0 * self.beta),
        })
    }
}

/// The motor damping's three thresholds for the δ → 0 pair without preliminary feedback, N m s/rad
/// ([`ResonanceReport::damping_window`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DampingThresholds {
    /// Above it the pair dies out (tr A4 < 0).
    pub damped_above: f64,
    /// Below it the motor swings (a complex pair); above it two real eigenvalues.
    pub swings_below: f64,
    /// Above it one real eigenvalue is positive (det A4 < 0).
    pub unstable_above: f64,
}

/// What the paper's K_pr, acting continuously, does to the pair at α and the rest point q2: the
/// pair it makes (the upper eigenvalue, 1/s), its shift of Re A4 and the parts of that shift
/// through T1 and through T2 (its two rows), 1/s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperFeedbackEffect {
    pub pair: [f64; 2],
    pub shift: f64,
    pub shift_t1: f64,
    pub shift_t2: f64,
}

impl PaperFeedbackEffect {
    pub fn new(plant: &PlantParameters, alpha: [f64; 2], q2: f64) -> Self {
        let paper = crate::control::feedback::paper_gain();
        let pair = closed_form_a4(plant, alpha, q2, &paper).complex_eigenvalues();
        let upper = if pair[0].im >= pair[1].im { pair[0] } else { pair[1] };
        let row = |r: usize| FeedbackGain::from_fn(|i, j| if i == r { paper[(i, j)] } else { 0.0 });
        let shift_of = |gain: &FeedbackGain| feedback_shift(plant, alpha, q2, gain);
        Self {
            pair: [upper.re, upper.im],
            shift: shift_of(&paper),
            shift_t1: shift_of(&row(0)),
            shift_t2: shift_of(&row(1)),
        }
    }
}
