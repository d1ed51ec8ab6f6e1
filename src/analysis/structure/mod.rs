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

use super::sampled::{LinearSettings, LoopModel};
use crate::control::config::{SimulationConfig, DAE_INDEX};
use crate::control::feedback::FeedbackGain;
use crate::control::linear::{pencil, LinearModel, Mat10};
use crate::error::Error;

mod horizon;
mod subspace;

pub use horizon::HorizonProbe;
pub use subspace::Cluster;

use horizon::probe;
use subspace::{balanced, block_eigenvalues, clusters, image, preimage, range_basis};

/// The horizons probed below and at the index.
pub const PROBED_HORIZONS: [usize; 4] = [1, 2, 3, 4];

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
