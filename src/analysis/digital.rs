//! The digital controller's loop linearized at rest (sensors on, [`crate::control::sensing`]):
//! everything the controller computes is sampled at t_n from the measured angles and held.
//!
//! At t_n, with deviations from rest and the friction cancelled:
//!
//! - m_n = q_n + η_n, the measured angles (q = (q1, q2, θ), η_n the angles' white error);
//! - ν_raw,n = q̇_n (`Exact`) or (m_n − m_{n−1})/δ (`Difference`), and the velocity estimate
//!   ν_n = β ν_{n−1} + (1 − β) ν_raw,n through the low-pass filter, β = e^(−δ/τ_v) (0 without it);
//! - X_m,n = (m_n, ν_n, w_n), the measured controller state (w the integrators, now the
//!   controller's own states, no longer the plant's);
//! - u_n = v_n + K X_m,n, held over [t_n, t_{n+1});
//! - v_{n+1} = K_pred X_m,n (the prediction, applied one period later, Fig. 2.1);
//! - w_{n+1} = w_n + δ diag(α1³, α2³) (m_n,1, m_n,2) (the integrator fed the held measured angle);
//! - p_{n+1} = Φ_p p_n + Γ_p u_n, p = (q, q̇) the plant's six states under a zero-order hold;
//! - m_prev,n+1 = m_n, kept for the difference; ν_prev,n+1 = ν_n, kept for the filter.
//!
//! So ζ = (p, w, v, m_prev, ν_prev) ∈ ℝ¹⁶ and ζ_{n+1} = F ζ_n + G η_n, u_n = H ζ_n + J η_n. With
//! `Exact` velocities m_prev is read by nobody, and without a filter ν_prev: their eigenvalues
//! are 0, kept for one size.

use nalgebra::{Complex, SMatrix};

use crate::control::config::ControllerParameters;
use crate::control::linear::{expm, predictor_gain, LinearModel, Mat10};
use crate::control::predictive::FeedbackGain;
use crate::control::sensing::{VelocityEstimator, VelocitySource};
use crate::error::Error;

/// The number of states of the digital loop, ζ = (q, q̇, w, v, m_prev, ν_prev).
pub const DIGITAL_STATES: usize = 16;

/// The digital loop's one-period map, 16×16.
pub type MatDigital = SMatrix<f64, DIGITAL_STATES, DIGITAL_STATES>;
const N: usize = DIGITAL_STATES;

/// The digital loop linearized at rest: ζ_{n+1} = F ζ_n + G η_n, u_n = H ζ_n + J η_n, and the
/// measured controller state X_m,n = S ζ_n + T η_n, with ζ = (q, q̇, w, v, m_prev, ν_prev)
/// (indices 0–2, 3–5, 6–7, 8–9, 10–12, 13–15) and η_n ∈ ℝ³ the error of the measured angles
/// (q1, q2, θ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DigitalLoop {
    /// F, the one-period map.
    pub f: MatDigital,
    /// G, how the angles' error η_n enters ζ_{n+1}.
    pub g: SMatrix<f64, N, 3>,
    /// H, the held torque u_n from ζ_n.
    pub h: SMatrix<f64, 2, N>,
    /// J, the held torque u_n from η_n.
    pub j: SMatrix<f64, 2, 3>,
    /// S, the measured state X_m,n = (m, ν, w) from ζ_n.
    pub s: SMatrix<f64, 8, N>,
    /// T, the measured state X_m,n from η_n.
    pub t: SMatrix<f64, 8, 3>,
}

/// Builds the digital loop at the controller's δ: Φ_p and Γ_p from the arm (`model`), K_pred from
/// the controller's model of it (`predictor`), as [`super::sampled::sampled_loop_matrix`] does.
pub fn digital_loop(
    model: &LinearModel,
    predictor: &LinearModel,
    gain: &FeedbackGain,
    controller: &ControllerParameters,
    velocity: VelocityEstimator,
) -> Result<DigitalLoop, Error> {
    let delta = controller.sampling_period;
    // The plant's six rows must not read w: it is the controller's state in this loop.
    if model.a.fixed_view::<6, 2>(0, 6).amax() != 0.0 {
        return Err(Error::Analysis("the linearized plant reads the integrators"));
    }
    let k_pred = predictor_gain(predictor, gain, controller)?;
    // Zero-order hold of u on the six plant states: e^([A_p B_p; 0 0] δ) in the 10×10 size.
    let mut aug = Mat10::zeros();
    aug.fixed_view_mut::<6, 6>(0, 0).copy_from(&(model.a.fixed_view::<6, 6>(0, 0) * delta));
    aug.fixed_view_mut::<6, 2>(0, 8).copy_from(&(model.b.fixed_view::<6, 2>(0, 0) * delta));
    let transition = expm(&aug);
    let phi_p: SMatrix<f64, 6, 6> = transition.fixed_view::<6, 6>(0, 0).into_owned();
    let gamma_p: SMatrix<f64, 6, 2> = transition.fixed_view::<6, 2>(0, 8).into_owned();

    let mut s = SMatrix::<f64, 8, N>::zeros();
    let mut t = SMatrix::<f64, 8, 3>::zeros();
    // ν_n = β ν_prev + (1 − β) ν_raw: with β = 0 exactly the raw estimate.
    let beta = velocity.memory(delta);
    let fresh = 1.0 - beta;
    for i in 0..3 {
        s[(i, i)] = 1.0;
        t[(i, i)] = 1.0;
        match velocity.source {
            VelocitySource::Exact => s[(3 + i, 3 + i)] = fresh,
            VelocitySource::Difference => {
                s[(3 + i, i)] = fresh / delta;
                s[(3 + i, 10 + i)] = -fresh / delta;
                t[(3 + i, i)] = fresh / delta;
            }
        }
        s[(3 + i, 13 + i)] = beta;
    }
    s[(6, 6)] = 1.0;
    s[(7, 7)] = 1.0;
    let mut h = gain * s;
    h[(0, 8)] += 1.0;
    h[(1, 9)] += 1.0;
    let j = gain * t;

    let mut f = MatDigital::zeros();
    let mut g = SMatrix::<f64, N, 3>::zeros();
    let plant_rows = gamma_p * h;
    f.fixed_view_mut::<6, N>(0, 0).copy_from(&plant_rows);
    let free = f.fixed_view::<6, 6>(0, 0) + phi_p;
    f.fixed_view_mut::<6, 6>(0, 0).copy_from(&free);
    g.fixed_view_mut::<6, 3>(0, 0).copy_from(&(gamma_p * j));
    for i in 0..2 {
        let gain_w = delta * controller.alpha[i].powi(3);
        f[(6 + i, 6 + i)] = 1.0;
        for c in 0..N {
            f[(6 + i, c)] += gain_w * s[(i, c)];
        }
        for c in 0..3 {
            g[(6 + i, c)] += gain_w * t[(i, c)];
        }
    }
    f.fixed_view_mut::<2, N>(8, 0).copy_from(&(k_pred * s));
    g.fixed_view_mut::<2, 3>(8, 0).copy_from(&(k_pred * t));
    f.fixed_view_mut::<3, N>(10, 0).copy_from(&s.fixed_view::<3, N>(0, 0));
    g.fixed_view_mut::<3, 3>(10, 0).copy_from(&t.fixed_view::<3, 3>(0, 0));
    f.fixed_view_mut::<3, N>(13, 0).copy_from(&s.fixed_view::<3, N>(3, 0));
    g.fixed_view_mut::<3, 3>(13, 0).copy_from(&t.fixed_view::<3, 3>(3, 0));
    Ok(DigitalLoop { f, g, h, j, s, t })
}

/// Eigenvalues of the digital loop's map, largest modulus first, computed on the map balanced
/// (as [`super::sampled::loop_eigenvalues`] does for the 10-state map, and for the same reason:
/// its entries span from 1/δ on the differenced velocity to the arm's smallest couplings).
pub fn digital_eigenvalues(m: &MatDigital) -> Vec<Complex<f64>> {
    let mut a = *m;
    if a.iter().all(|v| v.is_finite()) {
        balance(&mut a);
    }
    let mut ev: Vec<Complex<f64>> = a.complex_eigenvalues().iter().copied().collect();
    crate::sort::sort_by(&mut ev, |a, b| b.norm().total_cmp(&a.norm()).then(b.im.total_cmp(&a.im)));
    ev
}

/// ρ of the digital loop's map (0 for an empty spectrum).
pub fn digital_spectral_radius(m: &MatDigital) -> f64 {
    digital_eigenvalues(m).first().map(|c| c.norm()).unwrap_or(0.0)
}

/// Balances `a` in place (D⁻¹ a D, D diagonal powers of 2, as `sampled::balanced` and `digital_eigenvalues` do) and returns D's
/// diagonal. `a` must be finite. Balancing leaves the eigenvalues as they are and takes out the
/// error a badly scaled map puts in them.
pub(crate) fn balance<const N: usize>(a: &mut SMatrix<f64, N, N>) -> [f64; N] {
    let mut scale = [1.0; N];
    // Sweeps until no scaling shrinks a row and column by 5 %; a few suffice, the cap is a guard.
    for _ in 0..100 {
        let mut changed = false;
        for i in 0..N {
            let (mut col, mut row) = (0.0, 0.0);
            for j in (0..N).filter(|&j| j != i) {
                col += a[(j, i)].abs();
                row += a[(i, j)].abs();
            }
            if col == 0.0 || row == 0.0 || !(col + row).is_finite() {
                continue;
            }
            let sum = col + row;
            // The power of 2 that brings col·f within a factor 2 of row/f (c = col·f² against row).
            let mut f = 1.0;
            let mut c = col;
            while c < row / 2.0 && f < 1e150 {
                f *= 2.0;
                c *= 4.0;
            }
            while c > row * 2.0 && f > 1e-150 {
                f /= 2.0;
                c /= 4.0;
            }
            if (col * f + row / f) < 0.95 * sum {
                changed = true;
                scale[i] *= f;
                for j in 0..N {
                    a[(i, j)] /= f;
                    a[(j, i)] *= f;
                }
            }
        }
        if !changed {
            break;
        }
    }
    scale
}
