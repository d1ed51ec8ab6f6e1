//! The numerics under Section 3's subspaces: orthogonal projectors onto images and preimages, a
//! range's basis, a small SVD of its own, balancing, eigenvalues of a block, and clusters of them.

use nalgebra::Complex;

use crate::analysis::sampled::loop_eigenvalues;
use crate::control::linear::Mat10;
use crate::error::Error;
use serde::{Deserialize, Serialize};

/// A singular value of a matrix of norm ≈ 1 below this is zero.
pub(super) const RANK_TOLERANCE: f64 = 1e-9;

/// Eigenvalues within this fraction of the spectrum's size of each other are one cluster (at
/// least; see `clusters`).
const CLUSTER_TOLERANCE: f64 = 1e-3;

/// Eigenvalues that coincide (to the solver's scatter of a Jordan block): their mean, 1/s, and
/// how many.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cluster {
    /// [Re, Im] of the cluster's mean, 1/s.
    pub value: [f64; 2],
    pub multiplicity: usize,
}

/// The projector onto M S and its dimension, S given by its orthogonal projector. `gap` is lowered
/// to the smallest singular value (over M's norm) counted as nonzero: the subspace is accurate to
/// about ε over it.
pub(super) fn image(m: &Mat10, s: &Mat10, gap: &mut f64) -> (Mat10, usize) {
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
pub(super) fn preimage(m: &Mat10, s: &Mat10, gap: &mut f64) -> (Mat10, usize) {
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
pub(super) fn range_basis(p: &Mat10) -> (Mat10, usize) {
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
pub(super) fn balanced(f: &Mat10) -> Result<(Mat10, [f64; 10], f64), Error> {
    if !f.iter().all(|v| v.is_finite()) {
        return Err(Error::Analysis("the linearized DAE has a non-finite entry"));
    }
    let mut a = *f;
    let scale = crate::analysis::sampled::balance(&mut a);
    let norm = a.norm();
    if norm == 0.0 {
        return Err(Error::Analysis("the linearized DAE is zero"));
    }
    Ok((a / norm, scale, norm))
}

/// The eigenvalues of the diagonal block of `m` at rows and columns `start .. start + n`, through
/// the 10×10 eigen-solver: the block padded with a value beyond every eigenvalue of it, whose
/// copies are dropped.
pub(super) fn block_eigenvalues(m: &Mat10, start: usize, n: usize) -> Vec<Complex<f64>> {
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
pub(super) fn clusters(ev: &[Complex<f64>], norm: f64) -> Vec<Cluster> {
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
