//! The flexible pair as a mode of the sampled loop: its eigenvectors of the one-period map Φ,
//! and the pair's coordinate in any state of the loop — so that a run's errors can be split into
//! the swing's share and the rest (beyond the paper; `tests/swing.rs` checks the split against a
//! simulation).
//!
//! With v the right eigenvector (Φ v = λ v) and u the left one (uᵀ Φ = λ uᵀ) scaled so that
//! uᵀ v = 1, the pair's coordinate in a loop state ζ is c = uᵀ ζ, and the pair's share of ζ is
//! c v + conj(c v) = 2 Re(c v). Linearized, c is multiplied by λ every period: the swing's
//! amplitude 2 |c| |v_i| in a component i grows or shrinks by |λ| per period, whatever the other
//! modes do.

use nalgebra::{Complex, SVector};
use serde::{Deserialize, Serialize};

use crate::control::linear::Mat10;

/// The flexible pair's mode at one δ.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SwingMode {
    /// λ (Im λ ≥ 0).
    pub eigenvalue: [f64; 2],
    /// The right eigenvector v, real and imaginary parts (unit length).
    pub shape: [[f64; 10]; 2],
    /// The left eigenvector u, real and imaginary parts, scaled so that uᵀ v = 1.
    pub projector: [[f64; 10]; 2],
}

impl SwingMode {
    /// The pair's mode of `phi` for its eigenvalue `lambda`; None if an eigenvector is not found.
    pub fn new(phi: &Mat10, lambda: Complex<f64>) -> Option<Self> {
        let v = eigenvector(phi, lambda)?;
        let u = eigenvector(&phi.transpose(), lambda)?;
        let dot = (0..10).fold(Complex::new(0.0, 0.0), |acc, i| acc + u[i] * v[i]);
        if !(dot.norm() > 1e-12) {
            return None;
        }
        let u = u.map(|c| c / dot);
        Some(Self {
            eigenvalue: [lambda.re, lambda.im],
            shape: [v.map(|c| c.re), v.map(|c| c.im)],
            projector: [u.map(|c| c.re), u.map(|c| c.im)],
        })
    }

    /// c = uᵀ ζ: the pair's coordinate in the loop state ζ = (x − x_rest, v).
    pub fn coordinate(&self, zeta: &[f64; 10]) -> Complex<f64> {
        let [re, im] = &self.projector;
        let dot = |u: &[f64; 10]| u.iter().zip(zeta).map(|(a, b)| a * b).sum::<f64>();
        Complex::new(dot(re), dot(im))
    }

    /// The pair's share of component `i` of a state whose coordinate is `c`, 2 Re(c vᵢ), and its
    /// amplitude, 2 |c| |vᵢ|.
    pub fn part(&self, c: Complex<f64>, i: usize) -> (f64, f64) {
        let v = Complex::new(self.shape[0][i], self.shape[1][i]);
        (2.0 * (c * v).re, 2.0 * c.norm() * v.norm())
    }

    /// The right eigenvector as real and imaginary vectors.
    pub(crate) fn shape_vectors(&self) -> [SVector<f64, 10>; 2] {
        self.shape.map(SVector::<f64, 10>::from)
    }
}

/// The eigenvector of `phi` for the eigenvalue `lambda` (unit length), by two steps of inverse
/// iteration. Gaussian elimination written out on arrays: a generic complex LU would
/// add kilobytes to the page's module for one 10×10 solve.
#[inline(never)]
fn eigenvector(phi: &Mat10, lambda: Complex<f64>) -> Option<[Complex<f64>; 10]> {
    const N: usize = 10;
    let shift = lambda + Complex::new(1e-10, 1e-10) * lambda.norm().max(1e-12);
    let mut v = [Complex::new(1.0, 0.3); N];
    for _ in 0..2 {
        let mut m = [[Complex::new(0.0, 0.0); N]; N];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, c) in row.iter_mut().enumerate() {
                *c = Complex::new(phi[(i, j)], 0.0) - if i == j { shift } else { Complex::new(0.0, 0.0) };
            }
        }
        for col in 0..N {
            let pivot = (col..N).max_by(|&a, &b| m[a][col].norm().total_cmp(&m[b][col].norm()))?;
            m.swap(col, pivot);
            v.swap(col, pivot);
            let p = m[col][col];
            if p.norm() == 0.0 {
                return None;
            }
            for r in col + 1..N {
                let f = m[r][col] / p;
                for c in col..N {
                    let sub = f * m[col][c];
                    m[r][c] -= sub;
                }
                let sub = f * v[col];
                v[r] -= sub;
            }
        }
        for r in (0..N).rev() {
            let mut acc = v[r];
            for c in r + 1..N {
                acc -= m[r][c] * v[c];
            }
            v[r] = acc / m[r][r];
        }
        let norm = v.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
        if !(norm > 0.0 && norm.is_finite()) {
            return None;
        }
        v.iter_mut().for_each(|c| *c /= norm);
    }
    Some(v)
}
