//! Section 3 made computable for the arm shown: the largest output-nulling (A, B)-invariant
//! subspace V*, the decomposition (3.2) it makes, the spectra of Ā1 (the zero dynamics) and of the
//! quotient A4, the DAE index before and after the two stabilized differentiations, and what the
//! predictor's torque U_k depends on when k is not larger than that index.
//!
//! # How
//! The linear DAE of the stabilized constraint, linearized at rest, is the pencil
//! E ż = F z, z = (x, v), E = diag(I8, 0), F = [[A + BK, B], [C + DK, D]] (u = K x + v, K the
//! preliminary feedback, zeros for none). Both subspaces the argument rests on are Wong sequences
//! of it, computed here from scratch (not from the backward-Euler limit of
//! [`crate::control::linear::limit_pair`], which the tests compare it with):
//!
//! - the first, 𝒱₀ = ℝ¹⁰, 𝒱ᵢ₊₁ = F⁻¹(E 𝒱ᵢ), projected on x, is the recursion
//!   V₀ = ℝ⁸, Vᵢ₊₁ = {x ∈ Vᵢ : ∃u, A x + B u ∈ Vᵢ, C x + D u = 0} (the sequence decreases, so the
//!   intersection with Vᵢ is automatic); its limit 𝒱* is the graph of a friend F* over V*:
//!   (A + BF*) V* ⊂ V*, (C + DF*) V* = 0. The pencil's finite deflating subspace.
//! - the second, 𝒲₀ = {0}, 𝒲ᵢ₊₁ = E⁻¹(F 𝒲ᵢ), stops growing after ν steps, ν the index of the
//!   DAE in (x, u); its limit 𝒲* is the infinite deflating subspace.
//!
//! 𝒱* ⊕ 𝒲* = ℝ¹⁰ for a regular pencil, and the projector Π onto 𝒱* along 𝒲* is the δ → 0 limit
//! of the predictor (ERRATA.md: "project (x, 0) onto the finite deflating subspace"): K_lim x =
//! the v-part of Π (x, 0). In an orthonormal basis of V* followed by one of its complement,
//! A + B(K + K_lim) is block upper triangular, [[Ā1, A2], [0, A4]] — the decomposition (3.2) —
//! with Ā1 = (A + BF*)|V*, the zero dynamics, and A4 on ℝ⁸/V*.
//!
//! Every subspace is held as its orthogonal projector and every rank decided by an SVD of a 10×10
//! matrix (one-sided Jacobi, `svd`: nalgebra's gave wrong vectors for these matrices), on F
//! balanced by a diagonal similarity of powers of 2 (which leaves E = diag(I, 0) as it is and the
//! subspaces' dimensions and the spectra exactly as they are) and scaled to norm 1 (which moves no
//! subspace): a singular value counts as zero below 1e-9. The arm's scales span decades (K1/Ir1
//! against 1/Ir1 against α³), and a rank decided on the raw F would depend on the units.
//!
//! Each law's zero dynamics is a chain q → q̇ → w with (s + α)³: one Jordan block of size three,
//! whose eigenvalues any eigen-solver scatters by about the cube root of the matrix's error. So Ā1
//! is taken in the links' own coordinates (q, q̇, w), where it is the two chains with entries of
//! the size of α³ … 1 (`on_links`), and the spectra are reported as clusters, each with its mean
//! (as accurate as the matrix: the trace of its invariant subspace) and multiplicity: −2 ×6 for
//! α1 = α2 = 2, not six numbers around −2 (`clusters` says how near counts as one cluster).
//!
//! # k and the index
//! k backward-Euler steps of the pencil are ((E − εF)⁻¹E)^k = P⁻¹ diag((I − εJ)^(−k),
//! ((N − εI)⁻¹N)^k) P in Weierstrass form, N nilpotent with N^ν = 0. For ν = 3,
//! (N − εI)⁻¹N = −N/ε − N²/ε², its square N²/ε², its cube 0: the inconsistent part of the start
//! (x₀, 0) — for this arm the motor's θ and θ̇, off the links' law — is gone from step ν = 3 on,
//! and before that it enters with gains growing as 1/ε². [`HorizonProbe`] measures it at the
//! settings' δ: the gain from θ and θ̇ to the predictor's torque (U_k of eq. (2.4); with a
//! preliminary feedback the V_k on top of K x) and to its state X_k, and ρ of the sampled loop with
//! that k (the schema's slider starts at 4; k = 1 … 3 can be typed or linked to be tried). What it finds, on every arm
//! preset, α and rest angle `tests/structure.rs` tries: X_k forgets from k = 2, U_k from k = 3,
//! so k equal to the index is already enough (the paper asks k > 3); k = 1 and 2
//! give ρ > 1.3 at δ = 0.01 s, k = 3 the ρ of k = 4 to 1e-3.

use nalgebra::{Complex, SMatrix};
use serde::{Deserialize, Serialize};

use super::sampled::{loop_eigenvalues, sampled_loop_matrix, LinearSettings, LoopModel};
use crate::control::config::{SimulationConfig, DAE_INDEX};
use crate::control::feedback::FeedbackGain;
use crate::control::linear::{backward_euler_map, matrix_power, pencil, LinearModel, Mat10};
use crate::error::Error;

/// A singular value of a matrix of norm ≈ 1 below this is zero.
const RANK_TOLERANCE: f64 = 1e-9;

/// Eigenvalues within this fraction of the spectrum's size of each other are one cluster (at
/// least; see `clusters`).
const CLUSTER_TOLERANCE: f64 = 1e-3;

/// The horizons probed below and at the index.
pub const PROBED_HORIZONS: [usize; 4] = [1, 2, 3, 4];

/// Eigenvalues that coincide (to the solver's scatter of a Jordan block): their mean, 1/s, and
/// how many.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cluster {
    /// [Re, Im] of the cluster's mean, 1/s.
    pub value: [f64; 2],
    pub multiplicity: usize,
}

/// What the predictor with a short horizon k does at the settings' δ.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct HorizonProbe {
    /// k, the backward-Euler steps.
    pub k: usize,
    /// m (ε = δ/m): kε/δ as in the settings, kept within δ ≤ kε ≤ 2δ and ε ≤ δ.
    pub eps_ratio: f64,
    /// The largest |gain| from θ(tₙ) to the predictor's torque U_k (either row; with a preliminary
    /// feedback the V_k on top of K x), N m/rad.
    pub theta_gain: f64,
    /// The same from θ̇(tₙ), N m s/rad.
    pub theta_rate_gain: f64,
    /// p in theta_gain ∝ ε^(−p), measured between ε and ε/10: how it grows as δ → 0 (None where
    /// V_k has forgotten θ and θ̇).
    pub theta_gain_order: Option<f64>,
    /// The largest |gain| from θ(tₙ) or θ̇(tₙ) to the predicted state X_k (any entry).
    pub state_gain: f64,
    /// The predictor's largest gain on the other states (the links and w), for scale, N m/rad or
    /// N m s/rad.
    pub other_gain: f64,
    /// Whether V_k has forgotten θ and θ̇: their gains below 1e-9 of the largest entry of one
    /// step's map or of the sweep (rounding of what cancels).
    pub torque_forgets: bool,
    /// Whether X_k has (the same test on the state's gains).
    pub state_forgets: bool,
    /// ρ of the sampled loop at δ with this k and m; None if the loop could not be computed.
    pub rho: Option<f64>,
}

/// Section 3's structure for one arm, rest point and α.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Structure {
    /// α1, α2, 1/s.
    pub alpha: [f64; 2],
    /// q2 of the rest point, rad.
    pub q2: f64,
    /// dim V*, the largest output-nulling (A, B)-invariant subspace of the stabilized constraint.
    pub v_star_dim: usize,
    /// dim Vᵢ of the recursion, V₀ = ℝ⁸ first, up to V* (each once).
    pub v_star_sequence: Vec<usize>,
    /// Whether ℝ⁸ = V* ⊕ span(θ, θ̇): the quotient is the motor's angle and rate.
    pub quotient_is_motor: bool,
    /// The spectrum of Ā1 = (A + BF*)|V*, the zero dynamics, as clusters, leftmost first.
    pub zero_dynamics: Vec<Cluster>,
    /// Whether every zero lies in the open left half-plane (the arm is minimum phase).
    pub minimum_phase: bool,
    /// Whether the predictor's limit feedback K_lim has no gain on θ and θ̇ (their columns below
    /// 1e-9 of its largest entry): it leaves the quotient alone.
    pub limit_ignores_motor: bool,
    /// The spectrum on ℝ⁸/V* under the predictor's limit feedback, without preliminary feedback
    /// (A4), as clusters, upper first.
    pub quotient_open: Vec<Cluster>,
    /// The same with the settings' preliminary feedback (A4 with K), as clusters.
    pub quotient: Vec<Cluster>,
    /// Whether the quotient is stable (every eigenvalue's real part negative), without and with
    /// the preliminary feedback.
    pub quotient_open_stable: bool,
    pub quotient_stable: bool,
    /// Whether the settings have a preliminary feedback (a nonzero K).
    pub feedback: bool,
    /// The largest |entry| of A + B(K + K_lim) mapping V* out of V* (relative to the matrix):
    /// ≈ 0 confirms the block triangle (3.2).
    pub invariance_residual: f64,
    /// The index of the DAE in (x, u) with the path constraint q − q_d = 0 on the arm alone.
    pub index_path: usize,
    /// dim 𝒲ᵢ of its second Wong sequence, 𝒲₀ = {0} first, up to 𝒲* (each once).
    pub index_path_sequence: Vec<usize>,
    /// The finite zeros of the arm itself with its links as output (the path pencil's finite
    /// eigenvalues, its two idle states left out): 0 — the flexible-joint arm has none, so the zero
    /// dynamics of the stabilized constraint are the law's roots alone.
    pub arm_zeros: usize,
    /// The index with the stabilized constraint (4.3) and the integrators w (4.2).
    pub index_stabilized: usize,
    pub index_stabilized_sequence: Vec<usize>,
    /// The index the paper asks k to exceed ([`DAE_INDEX`]).
    pub schema_index: usize,
    /// δ and kε/δ of the settings, s and 1.
    pub delta: f64,
    pub horizon_ratio: f64,
    /// k = 1, 2, 3, 4 at the settings' δ.
    pub probes: Vec<HorizonProbe>,
    /// The smallest probed k from which the torque V_k has forgotten θ and θ̇ (None if none).
    pub torque_forgets_from: Option<usize>,
    /// The same for the predicted state X_k.
    pub state_forgets_from: Option<usize>,
}

impl Structure {
    /// The structure of `config`'s arm linearized at rest at the end of its slew (or at `q2`).
    pub fn of(config: &SimulationConfig, q2: Option<f64>) -> Result<Self, Error> {
        config.validate()?;
        Self::new(&LinearSettings::of(config, q2))
    }

    /// The structure for `settings`: the arm as the settings linearize it, with their preliminary
    /// feedback (the controller is taken to know the arm).
    pub fn new(settings: &LinearSettings) -> Result<Self, Error> {
        let loop_model = LoopModel::new(settings)?;
        let arm = loop_model.arm();
        let gain = loop_model.gain();
        let open = decompose(arm, &FeedbackGain::zeros())?;
        let with = decompose(arm, gain)?;
        let (index_stabilized, index_stabilized_sequence) = index(&pencil(arm, &FeedbackGain::zeros()))?;
        let (index_path, index_path_sequence) = index(&path_pencil(arm))?;
        let controller = settings.controller;
        let ratio = controller.horizon_steps as f64 / controller.eps_ratio;
        let probes: Vec<HorizonProbe> =
            PROBED_HORIZONS.iter().map(|&k| probe(&loop_model, k, ratio)).collect::<Result<_, _>>()?;
        let from = |test: fn(&HorizonProbe) -> bool| {
            // From k on: every probe at k and above forgets.
            (0..probes.len()).find(|&i| probes[i..].iter().all(test)).map(|i| probes[i].k)
        };
        Ok(Self {
            alpha: controller.alpha,
            q2: settings.rest[1],
            v_star_dim: open.v_star_dim,
            v_star_sequence: open.v_star_sequence,
            quotient_is_motor: open.quotient_is_motor,
            minimum_phase: stable(&open.zero_dynamics),
            limit_ignores_motor: {
                let k = &open.k_lim;
                let motor = k.column(2).amax().max(k.column(5).amax());
                motor <= 1e-9 * k.amax()
            },
            quotient_open_stable: stable(&open.quotient),
            quotient_stable: stable(&with.quotient),
            zero_dynamics: open.zero_dynamics,
            quotient_open: open.quotient,
            quotient: with.quotient,
            feedback: gain.iter().any(|g| *g != 0.0),
            invariance_residual: open.invariance_residual.max(with.invariance_residual),
            index_path,
            // 10 = 8 states and inputs + 2 idle states; 𝒲* is the infinite part.
            arm_zeros: 8usize.saturating_sub(*index_path_sequence.last().unwrap_or(&0)),
            index_path_sequence,
            index_stabilized,
            index_stabilized_sequence,
            schema_index: DAE_INDEX,
            delta: controller.sampling_period,
            horizon_ratio: ratio,
            torque_forgets_from: from(|p| p.torque_forgets),
            state_forgets_from: from(|p| p.state_forgets),
            probes,
        })
    }
}

impl Structure {
    /// Whether k equal to the index is already enough: the predictor's torque forgets the
    /// inconsistent start from k = the stabilized DAE's index on (the schema asks k > index).
    pub fn index_suffices(&self) -> bool {
        self.torque_forgets_from == Some(self.index_stabilized)
    }

    /// The probe at horizon `k`.
    pub fn probe(&self, k: usize) -> Option<&HorizonProbe> {
        self.probes.iter().find(|p| p.k == k)
    }
}

fn stable(spectrum: &[Cluster]) -> bool {
    spectrum.iter().all(|c| c.value[0] < 0.0)
}

/// The decomposition (3.2) of the stabilized DAE under preliminary feedback `gain`.
#[derive(Clone, Debug, PartialEq)]
pub struct Decomposition {
    pub v_star_dim: usize,
    pub v_star_sequence: Vec<usize>,
    pub quotient_is_motor: bool,
    /// The predictor's limit feedback K_lim (from the projector onto 𝒱* along 𝒲*), 2×8.
    pub k_lim: SMatrix<f64, 2, 8>,
    /// Ā1's spectrum and the quotient's, as clusters.
    pub zero_dynamics: Vec<Cluster>,
    pub quotient: Vec<Cluster>,
    /// Ā1's and the quotient's eigenvalues one by one, as the solver gives them.
    pub zero_dynamics_raw: Vec<Complex<f64>>,
    pub quotient_raw: Vec<Complex<f64>>,
    /// See [`Structure::invariance_residual`].
    pub invariance_residual: f64,
}

/// V*, its friend, K_lim and the two spectra of `model` under the preliminary feedback `gain`.
pub fn decompose(model: &LinearModel, gain: &FeedbackGain) -> Result<Decomposition, Error> {
    let (e, f) = pencil(model, gain);
    let (fb, scale, norm) = balanced(&f)?;
    // 𝒱*: 𝒱ᵢ₊₁ = F⁻¹(E 𝒱ᵢ), from ℝ¹⁰; V* = E 𝒱* (the x-part, with v = 0).
    let mut v = Mat10::identity();
    let mut v_star_sequence = vec![8];
    let mut dim_v = 10;
    // The smallest singular value any rank decision on the way to V* kept: V* is accurate to
    // about ε over it.
    let mut gap: f64 = 1.0;
    for _ in 0..=10 {
        let (next, dim) = preimage(&fb, &image(&e, &v, &mut gap).0, &mut gap);
        let x_dim = image(&e, &next, &mut gap).1;
        let repeated = dim == dim_v;
        v = next;
        dim_v = dim;
        if repeated {
            break;
        }
        // Vᵢ = E 𝒱ᵢ settles (Vᵢ₊₁ = Vᵢ) once its dimension repeats; 𝒱ᵢ may lose an input
        // direction one step later.
        if v_star_sequence.last() != Some(&x_dim) {
            v_star_sequence.push(x_dim);
        }
    }
    let (v_star, v_star_dim) = image(&e, &v, &mut gap);
    // 𝒲*: 𝒲ᵢ₊₁ = E⁻¹(F 𝒲ᵢ), from {0}.
    let (w, dim_w) = second_wong(&e, &fb).map(|(p, seq)| (p, *seq.last().unwrap_or(&0)))?;
    if dim_v + dim_w != 10 || dim_v != v_star_dim {
        return Err(Error::Analysis(
            "the linearized DAE's pencil is not regular: V* and its complement do not fill ℝ¹⁰",
        ));
    }
    // Π onto 𝒱* along 𝒲*: T = [basis 𝒱* | basis 𝒲*], Π = T diag(I, 0) T⁻¹.
    let (bv, _) = range_basis(&v);
    let (bw, _) = range_basis(&w);
    let mut t = bv;
    for j in 0..dim_w {
        t.set_column(dim_v + j, &bw.column(j));
    }
    let t_inv = t.try_inverse().ok_or(Error::Analysis("V* and the infinite subspace are not complementary"))?;
    let mut keep = Mat10::zeros();
    for i in 0..dim_v {
        keep[(i, i)] = 1.0;
    }
    let pi_balanced = t * keep * t_inv;
    // Back to the settings' coordinates: z = S z', Π = S Π' S⁻¹.
    let pi = Mat10::from_fn(|i, j| pi_balanced[(i, j)] * scale[i] / scale[j]);
    let k_lim: SMatrix<f64, 2, 8> = pi.fixed_view::<2, 8>(8, 0).into_owned();

    // The block triangle: an orthonormal basis of V* (balanced coordinates), then of its
    // complement in ℝ⁸, then e9, e10.
    let (bx, _) = range_basis(&v_star);
    let (by, dim_y) = range_basis(&(e - v_star));
    let mut q = bx;
    for j in 0..dim_y {
        q.set_column(v_star_dim + j, &by.column(j));
    }
    q[(8, 8)] = 1.0;
    q[(9, 9)] = 1.0;
    let closed = model.with_feedback(&(gain + k_lim));
    let mut closed_balanced = Mat10::zeros();
    for i in 0..8 {
        for j in 0..8 {
            closed_balanced[(i, j)] = closed[(i, j)] * scale[j] / scale[i];
        }
    }
    let blocks = q.transpose() * closed_balanced * q;
    let n1 = v_star_dim;
    let n2 = 8 - n1;
    let mut invariance_residual: f64 = 0.0;
    for i in n1..8 {
        for j in 0..n1 {
            invariance_residual = invariance_residual.max(blocks[(i, j)].abs());
        }
    }
    invariance_residual /= blocks.amax().max(f64::MIN_POSITIVE);
    let quotient_raw = block_eigenvalues(&blocks, n1, n2);
    // The quotient is the motor's (θ, θ̇) when they complete V*: their components off V* (rows 2
    // and 5 of the complement's orthonormal basis; the diagonal scaling keeps the axes) are
    // independent.
    let quotient_is_motor = n2 == 2 && {
        let m = nalgebra::Matrix2::new(by[(2, 0)], by[(2, 1)], by[(5, 0)], by[(5, 1)]);
        let norms = (by[(2, 0)].hypot(by[(2, 1)])) * (by[(5, 0)].hypot(by[(5, 1)]));
        m.determinant().abs() > 1e-6 * norms.max(f64::MIN_POSITIVE)
    };
    let zero_dynamics_raw = match quotient_is_motor.then(|| on_links(&bx, &scale, &closed)).flatten() {
        Some(a1) => block_eigenvalues(&a1, 0, 6),
        None => block_eigenvalues(&blocks, 0, n1),
    };
    Ok(Decomposition {
        v_star_dim,
        v_star_sequence,
        quotient_is_motor,
        k_lim,
        zero_dynamics: clusters(&zero_dynamics_raw, norm / gap),
        quotient: clusters(&quotient_raw, norm / gap),
        zero_dynamics_raw,
        quotient_raw,
        invariance_residual,
    })
}

/// The states off the motor, (q1, q2, q̇1, q̇2, w1, w2): V* is a graph over them where the motor
/// completes it.
const LINKS: [usize; 6] = [0, 1, 3, 4, 6, 7];

/// Ā1 in the links' own coordinates: V* as the graph x = G (q, q̇, w) (G's link rows the identity,
/// its motor rows θ*, θ̇* of the law), and Ā1 = the link rows of (A + B(K + K_lim)) G, in the
/// settings' units. The orthonormal basis of V* mixes states whose scales differ by decades
/// (w against θ̇ on a stiff joint), and there a Jordan block's eigenvalues scatter past the
/// clusters' tolerance (α = 0.1 1/s at K1 = 1.15e6 N m/rad: by 2e-3); in these coordinates Ā1 is
/// the two laws' chains, entries of the size of α³, 3α², 3α and 1. `basis`: V*'s orthonormal basis
/// (balanced coordinates) in its first six columns; `scale`: the balancing. None if the link rows
/// of the basis are singular.
fn on_links(basis: &Mat10, scale: &[f64; 10], closed: &nalgebra::SMatrix<f64, 8, 8>) -> Option<Mat10> {
    // X = the link rows of the basis, padded with the identity to use the 10×10 LU.
    let mut x = Mat10::identity();
    for (i, &r) in LINKS.iter().enumerate() {
        for j in 0..6 {
            x[(i, j)] = basis[(r, j)];
        }
    }
    let x_inv = x.try_inverse()?;
    // G (balanced) = basis · X⁻¹ (6 columns), then in the settings' units: row r times scale[r],
    // column j over scale[LINKS[j]], so that its link rows stay the identity.
    let mut g = nalgebra::SMatrix::<f64, 8, 6>::zeros();
    for r in 0..8 {
        for j in 0..6 {
            let mut v = 0.0;
            for l in 0..6 {
                v += basis[(r, l)] * x_inv[(l, j)];
            }
            g[(r, j)] = v * scale[r] / scale[LINKS[j]];
        }
    }
    let moved = closed * g;
    let mut a1 = Mat10::zeros();
    for (i, &r) in LINKS.iter().enumerate() {
        for j in 0..6 {
            a1[(i, j)] = moved[(r, j)];
        }
    }
    a1.iter().all(|v| v.is_finite()).then_some(a1)
}

/// The index of the DAE E ż = F z and the dimensions of its second Wong sequence: 𝒲₀ = {0},
/// 𝒲ᵢ₊₁ = E⁻¹(F 𝒲ᵢ); the index is the number of steps until 𝒲ᵢ₊₁ = 𝒲ᵢ.
pub fn index(pencil: &(Mat10, Mat10)) -> Result<(usize, Vec<usize>), Error> {
    let (e, f) = pencil;
    let (fb, _, _) = balanced(f)?;
    let (_, sequence) = second_wong(e, &fb)?;
    Ok((sequence.len() - 1, sequence))
}

/// The arm alone under the path constraint q − q_d = 0 as a pencil of the same size: z = (x, u),
/// x = (q1, q2, θ, q̇1, q̇2, θ̇, p1, p2) with two idle states p (ṗ = 0, in no equation else), which
/// add two finite eigenvalues and change no step of the second Wong sequence.
pub fn path_pencil(model: &LinearModel) -> (Mat10, Mat10) {
    let mut f = Mat10::zeros();
    f.fixed_view_mut::<6, 6>(0, 0).copy_from(&model.a.fixed_view::<6, 6>(0, 0));
    f.fixed_view_mut::<6, 2>(0, 8).copy_from(&model.b.fixed_view::<6, 2>(0, 0));
    f[(8, 0)] = 1.0;
    f[(9, 1)] = 1.0;
    let e = Mat10::from_fn(|i, j| if i == j && i < 8 { 1.0 } else { 0.0 });
    (e, f)
}

/// The second Wong sequence's limit (projector) and the dimensions on the way, 𝒲₀ = {0} first,
/// ending with the first repeat's dimension once.
fn second_wong(e: &Mat10, f: &Mat10) -> Result<(Mat10, Vec<usize>), Error> {
    let mut w = Mat10::zeros();
    let mut sequence = vec![0];
    for _ in 0..=10 {
        let mut gap = 1.0;
        let (next, dim) = preimage(e, &image(f, &w, &mut gap).0, &mut gap);
        let repeated = dim == *sequence.last().unwrap_or(&0);
        w = next;
        if repeated {
            return Ok((w, sequence));
        }
        sequence.push(dim);
    }
    Err(Error::Analysis("the Wong sequence did not settle"))
}

/// The projector onto M S and its dimension, S given by its orthogonal projector. `gap` is lowered
/// to the smallest singular value (over M's norm) counted as nonzero: the subspace is accurate to
/// about ε over it.
fn image(m: &Mat10, s: &Mat10, gap: &mut f64) -> (Mat10, usize) {
    let (us, sigma, _) = svd(&(m * s));
    let scale = m.norm();
    let mut p = Mat10::zeros();
    let mut dim = 0;
    for (i, sv) in sigma.iter().enumerate() {
        if *sv > RANK_TOLERANCE * scale {
            *gap = gap.min(sv / scale);
            let u = us.column(i) / *sv;
            p += u * u.transpose();
            dim += 1;
        }
    }
    (p, dim)
}

/// The projector onto M⁻¹(S) = ker((I − P_S) M) and its dimension; `gap` as for [`image`].
fn preimage(m: &Mat10, s: &Mat10, gap: &mut f64) -> (Mat10, usize) {
    let (_, sigma, v) = svd(&((Mat10::identity() - s) * m));
    let scale = m.norm();
    let mut p = Mat10::zeros();
    let mut dim = 0;
    for (i, sv) in sigma.iter().enumerate() {
        if *sv <= RANK_TOLERANCE * scale {
            p += v.column(i) * v.column(i).transpose();
            dim += 1;
        } else {
            *gap = gap.min(sv / scale);
        }
    }
    (p, dim)
}

/// An orthonormal basis of a projector's range in the first columns (the rest zero), and its size.
fn range_basis(p: &Mat10) -> (Mat10, usize) {
    let (us, sigma, _) = svd(p);
    let mut basis = Mat10::zeros();
    let mut dim = 0;
    for (i, sv) in sigma.iter().enumerate() {
        if *sv > 0.5 {
            basis.set_column(dim, &(us.column(i) / *sv));
            dim += 1;
        }
    }
    (basis, dim)
}

/// The singular value decomposition M = U Σ Vᵀ by one-sided Jacobi rotations (Hestenes): the
/// columns of M V are rotated until orthogonal to each other to rounding; then Σ holds their
/// lengths and U Σ is M V. Returns (M V, the singular values in no particular order, V). Why not
/// nalgebra's `svd`: for one of these very matrices (E·P on the paper's arm with K_pr at α = 0.5,
/// q2 = π/2: E·P has norm ≈ 2.6 and two zero rows) its U Σ Vᵀ missed M by 6e-3 in an entry, with
/// U and V orthonormal, and the recursion stalled at 7 dimensions short of V* (nalgebra issue 1172, "SVD:
/// occasional failure to decompose", open against 0.35); this one reproduces M to rounding.
fn svd(m: &Mat10) -> (Mat10, [f64; 10], Mat10) {
    let mut a = *m;
    let mut v = Mat10::identity();
    for _ in 0..60 {
        let mut rotated = false;
        for p in 0..9 {
            for q in p + 1..10 {
                let alpha = a.column(p).norm_squared();
                let beta = a.column(q).norm_squared();
                let gamma = a.column(p).dot(&a.column(q));
                if gamma == 0.0 || gamma.abs() <= 1e-15 * (alpha * beta).sqrt() {
                    continue;
                }
                rotated = true;
                let zeta = (beta - alpha) / (2.0 * gamma);
                let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
                let c = 1.0 / (1.0 + t * t).sqrt();
                let s = c * t;
                for x in [&mut a, &mut v] {
                    for r in 0..10 {
                        let (xp, xq) = (x[(r, p)], x[(r, q)]);
                        x[(r, p)] = c * xp - s * xq;
                        x[(r, q)] = s * xp + c * xq;
                    }
                }
            }
        }
        if !rotated {
            break;
        }
    }
    let mut sigma = [0.0; 10];
    for (j, s) in sigma.iter_mut().enumerate() {
        *s = a.column(j).norm();
    }
    (a, sigma, v)
}

/// F balanced by a diagonal similarity S⁻¹ F S of powers of 2 (Parlett–Reinsch, as LAPACK's
/// `gebal`), then divided by its norm: the same subspaces up to S, the same ranks, and singular
/// values of comparable sizes. Returns the matrix, S's diagonal and the norm divided by.
fn balanced(f: &Mat10) -> Result<(Mat10, [f64; 10], f64), Error> {
    if !f.iter().all(|v| v.is_finite()) {
        return Err(Error::Analysis("the linearized DAE has a non-finite entry"));
    }
    let mut a = *f;
    let scale = super::sampled::balance(&mut a);
    let norm = a.norm();
    if norm == 0.0 {
        return Err(Error::Analysis("the linearized DAE is zero"));
    }
    Ok((a / norm, scale, norm))
}

/// The eigenvalues of the diagonal block of `m` at rows and columns `start .. start + n`, through
/// the 10×10 eigen-solver: the block padded with a value beyond every eigenvalue of it, whose
/// copies are dropped.
fn block_eigenvalues(m: &Mat10, start: usize, n: usize) -> Vec<Complex<f64>> {
    if n == 0 {
        return Vec::new();
    }
    let mut bound: f64 = 0.0;
    for i in 0..n {
        for j in 0..n {
            bound = bound.max(m[(start + i, start + j)].abs());
        }
    }
    let pad = -(1.0 + 16.0 * bound * n as f64);
    let mut padded = Mat10::from_diagonal_element(pad);
    for i in 0..n {
        for j in 0..n {
            padded[(i, j)] = m[(start + i, start + j)];
        }
    }
    let mut ev = loop_eigenvalues(&padded);
    // The padding comes first by modulus.
    ev.drain(..10 - n);
    ev
}

/// Eigenvalues grouped where they lie within the scatter rounding gives a Jordan block of size
/// three of each other, each cluster's mean and size, leftmost first and of equal real parts the
/// upper first. The scatter: an error η in the matrix moves a triple eigenvalue of size |λ| by
/// about (η |λ|²)^(1/3). Here η = ε `norm`, `norm` the balanced pencil's norm over the smallest
/// singular value a rank decision on the way to V* kept (V* is accurate to ε over that, and Ā1
/// with it); the tolerance is ten times that scatter, and at least [`CLUSTER_TOLERANCE`] of the
/// spectrum's size.
fn clusters(ev: &[Complex<f64>], norm: f64) -> Vec<Cluster> {
    let size = ev.iter().map(|l| l.norm()).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let scatter = 10.0 * (f64::EPSILON * norm * size * size).cbrt();
    let tolerance = (CLUSTER_TOLERANCE * size).max(scatter);
    let mut group: Vec<usize> = (0..ev.len()).collect();
    // Single linkage: merge groups with a pair of members within the tolerance.
    for i in 0..ev.len() {
        for j in 0..i {
            if (ev[i] - ev[j]).norm() <= tolerance {
                let (from, to) = (group[i], group[j]);
                for g in group.iter_mut() {
                    if *g == from {
                        *g = to;
                    }
                }
            }
        }
    }
    let mut out: Vec<Cluster> = Vec::new();
    for g in 0..ev.len() {
        let members: Vec<Complex<f64>> = (0..ev.len()).filter(|&i| group[i] == g).map(|i| ev[i]).collect();
        if members.is_empty() {
            continue;
        }
        let mean = members.iter().sum::<Complex<f64>>() / members.len() as f64;
        out.push(Cluster { value: [mean.re, mean.im], multiplicity: members.len() });
    }
    crate::sort::sort_by(&mut out, |a, b| a.value[0].total_cmp(&b.value[0]).then(b.value[1].total_cmp(&a.value[1])));
    out
}

/// The predictor with horizon `k` at the settings' δ, m = k/`ratio` kept in [max(1, k/2), k].
fn probe(loop_model: &LoopModel, k: usize, ratio: f64) -> Result<HorizonProbe, Error> {
    let settings = loop_model.settings();
    let mut controller = settings.controller;
    controller.horizon_steps = k;
    let kf = k as f64;
    controller.eps_ratio = (kf / ratio).clamp((kf / 2.0).max(1.0), kf);
    let model = loop_model.predictor();
    let (e, f) = pencil(model, loop_model.gain());
    let sweep_at = |eps: f64| -> Result<(Mat10, f64), Error> {
        let step = backward_euler_map(&e, &f, eps)?;
        Ok((matrix_power(&step, k), step.amax()))
    };
    let eps = controller.integration_step();
    let (sweep, step_size) = sweep_at(eps)?;
    let motor_gains = |sweep: &Mat10| {
        let (mut theta, mut rate, mut other, mut state, mut state_other) = (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for row in 0..10 {
            for col in 0..8 {
                let g = sweep[(row, col)].abs();
                match (row >= 8, col) {
                    (true, 2) => theta = theta.max(g),
                    (true, 5) => rate = rate.max(g),
                    (true, _) => other = other.max(g),
                    (false, 2 | 5) => state = state.max(g),
                    (false, _) => state_other = state_other.max(g),
                }
            }
        }
        (theta, rate, other, state, state_other)
    };
    let (theta_gain, theta_rate_gain, other_gain, state_gain, state_other) = motor_gains(&sweep);
    // Zero to rounding: below 1e-9 of the largest entry of one step's map or of the sweep — what
    // cancels when the sweep forgets is of the step's size (the 1/ε² of the inconsistent start),
    // and its rounding is ≈ 1e-16 of it per step.
    let zero = 1e-9 * step_size.max(sweep.amax()).max(state_other);
    let torque_forgets = theta_gain.max(theta_rate_gain) <= zero;
    let theta_gain_order = if torque_forgets || theta_gain == 0.0 {
        None
    } else {
        let (finer, _) = sweep_at(eps / 10.0)?;
        Some((motor_gains(&finer).0 / theta_gain).log10())
    };
    let rho = sampled_loop_matrix(loop_model.arm(), model, loop_model.gain(), &controller, settings.inner_loop)
        .ok()
        .and_then(|m| loop_eigenvalues(&m).first().map(|l| l.norm()))
        .filter(|r| r.is_finite());
    Ok(HorizonProbe {
        k,
        eps_ratio: controller.eps_ratio,
        theta_gain,
        theta_rate_gain,
        theta_gain_order,
        state_gain,
        other_gain,
        torque_forgets,
        state_forgets: state_gain <= zero,
        rho,
    })
}
