//! Linear stability analysis: the sampled closed loop linearized at rest, its eigenvalues and
//! spectral radius ρ, the δ → 0 limit pair A4 of section 3, and the stability map ρ(δ, α).
//!
//! Everything here is built from the same plant and constraint functions the simulation uses
//! ([`crate::plant::Plant`]), linearized at rest (zero velocities, θ = q1, no torque), where the
//! Coriolis terms and ∂M/∂q2 · q̈ vanish. The friction is taken as cancelled by the observer
//! (continuous compensation), so the analysis describes the friction-free loop.

use nalgebra::{Complex, Matrix2, SMatrix};
use serde::{Deserialize, Serialize};

use crate::feedback::{resolve_gain, FeedbackGain};
use crate::params::{ControllerParameters, InnerLoop, PlantParameters, SimulationConfig};
use crate::plant::Plant;
use crate::predictive::StateVector;
use crate::Error;

type Mat8 = SMatrix<f64, 8, 8>;
type Mat10 = SMatrix<f64, 10, 10>;

/// The arm, the integrators w and the stabilized constraint linearized at rest:
/// ẋ = A x + B u, constraint 0 = C x + D u (in deviations from `rest`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearModel {
    pub a: Mat8,
    pub b: SMatrix<f64, 8, 2>,
    pub c: SMatrix<f64, 2, 8>,
    pub d: SMatrix<f64, 2, 2>,
    /// The operating point X at rest.
    pub rest: StateVector,
}

/// Linearizes plant, integrators (4.2) and constraint (4.3) at rest at link angles `q_rest`.
pub fn linearize_at_rest(plant: &PlantParameters, alpha: [f64; 2], q_rest: [f64; 2]) -> LinearModel {
    let model = Plant::new(*plant);
    let q = nalgebra::Vector3::new(q_rest[0], q_rest[1], q_rest[0]);
    let v = nalgebra::Vector3::zeros();
    let (dr_dq, dr_dv) = model.force_jacobians(&q, &v);
    let m_inv = model.mass_matrix(q_rest[1]).try_inverse().expect("validated mass matrix is invertible");
    let acc_q = m_inv * dr_dq;
    let acc_v = m_inv * dr_dv;
    let acc_u = m_inv * Plant::input_matrix();

    let mut a = Mat8::zeros();
    let mut b = SMatrix::<f64, 8, 2>::zeros();
    for i in 0..3 {
        a[(i, 3 + i)] = 1.0;
        for j in 0..3 {
            a[(3 + i, j)] = acc_q[(i, j)];
            a[(3 + i, 3 + j)] = acc_v[(i, j)];
        }
        for j in 0..2 {
            b[(3 + i, j)] = acc_u[(i, j)];
        }
    }
    let mut c = SMatrix::<f64, 2, 8>::zeros();
    let mut d = SMatrix::<f64, 2, 2>::zeros();
    for i in 0..2 {
        let al = alpha[i];
        a[(6 + i, i)] = al * al * al;
        // y_i = q̈_i + 3α q̇_i + 3α² q_i + w_i, with q̈_i from the equations of motion.
        for j in 0..8 {
            c[(i, j)] = a[(3 + i, j)];
        }
        c[(i, 3 + i)] += 3.0 * al;
        c[(i, i)] += 3.0 * al * al;
        c[(i, 6 + i)] += 1.0;
        for j in 0..2 {
            d[(i, j)] = b[(3 + i, j)];
        }
    }
    let rest = StateVector::from_column_slice(&[q_rest[0], q_rest[1], q_rest[0], 0.0, 0.0, 0.0, 0.0, 0.0]);
    LinearModel { a, b, c, d, rest }
}

/// The pencil (E, F) of the linear DAE E ż = F z, z = (x, v), for the plant with the
/// preliminary feedback u = K x + v folded in: F = [[A + BK, B], [C + DK, D]], E = diag(I8, 0).
fn pencil(model: &LinearModel, gain: &FeedbackGain) -> (Mat10, Mat10) {
    let a = model.a + model.b * gain;
    let c = model.c + model.d * gain;
    let mut f = Mat10::zeros();
    f.fixed_view_mut::<8, 8>(0, 0).copy_from(&a);
    f.fixed_view_mut::<8, 2>(0, 8).copy_from(&model.b);
    f.fixed_view_mut::<2, 8>(8, 0).copy_from(&c);
    f.fixed_view_mut::<2, 2>(8, 8).copy_from(&model.d);
    let mut e = Mat10::zeros();
    for i in 0..8 {
        e[(i, i)] = 1.0;
    }
    (e, f)
}

/// One backward-Euler step of the linear DAE as a map z_j ↦ z_{j+1} = (E − εF)⁻¹ E z_j.
fn backward_euler_map(e: &Mat10, f: &Mat10, eps: f64) -> Result<Mat10, Error> {
    let lhs = e - f * eps;
    lhs.lu().solve(e).ok_or(Error::Analysis("the backward-Euler step of the linearized DAE is singular"))
}

fn matrix_power(m: &Mat10, mut k: usize) -> Mat10 {
    let mut result = Mat10::identity();
    let mut base = *m;
    while k > 0 {
        if k & 1 == 1 {
            result *= base;
        }
        base = base * base;
        k >>= 1;
    }
    result
}

/// The linearized predictor at finite δ: V_k = K_pred x_0 (k steps of ε = δ/m), a 2×8 gain.
pub fn predictor_gain(
    model: &LinearModel,
    gain: &FeedbackGain,
    controller: &ControllerParameters,
) -> Result<SMatrix<f64, 2, 8>, Error> {
    let (e, f) = pencil(model, gain);
    let step = backward_euler_map(&e, &f, controller.integration_step())?;
    let sweep = matrix_power(&step, controller.horizon_steps);
    Ok(sweep.fixed_view::<2, 8>(8, 0).into_owned())
}

/// The δ → 0 limit of the predictive controller and the pair it leaves untouched.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LimitPair {
    /// K_lim: the limit of the predictor's V_k as a feedback on x_0.
    pub k_lim: SMatrix<f64, 2, 8>,
    /// Ψ: x ↦ x2, the motor coordinates (θ, θ̇) measured from the invariant subspace V*.
    pub coordinates: SMatrix<f64, 2, 8>,
    /// A4: the closed loop A + B(K + K_lim) on the quotient ℝ⁸/V*, in the coordinates x2.
    pub a4: Matrix2<f64>,
    /// B2 = Ψ B: how (T1, T2) enter x2.
    pub b2: Matrix2<f64>,
    /// The eigenvalues of A4, positive imaginary part first.
    pub eigenvalues: [Complex<f64>; 2],
    /// The largest entry of (I − Π_x) outside the θ and θ̇ rows: ≈ 0 confirms that the limit
    /// controller ignores the motor coordinates.
    pub off_motor_residual: f64,
}

/// Computes the δ → 0 limit of the predictor for the plant with preliminary feedback `gain`.
///
/// Backward Euler on a linear index-3 DAE forgets its inconsistent start after three steps,
/// whatever ε: ((E − εF)⁻¹E)^k = Q diag((I − εJ)^(−k), 0) Q⁻¹ for k ≥ 3 in Weierstrass form. So
/// the k-step map at any moderate ε has exactly the range (finite deflating subspace) and kernel
/// (infinite one) of the limit projector Π; Newton's iteration X ← X(2I − X) pushes its nonzero
/// eigenvalues (1 − ελ)^(−k) to 1 and keeps the zero ones, giving Π. Then K_lim x = the v-part of
/// Π (x, 0), V* = range of Π's x-part, and A4 is A + B(K + K_lim) on ℝ⁸/V*.
pub fn limit_pair(model: &LinearModel, gain: &FeedbackGain) -> Result<LimitPair, Error> {
    let (e, f) = pencil(model, gain);
    // The finite spectrum of the pencil is the constrained error dynamics at −α; keep ελ small.
    let alpha_max = model.a[(6, 0)].cbrt().max(model.a[(7, 1)].cbrt()).max(1e-3);
    let eps = 0.1 / alpha_max;
    let step = backward_euler_map(&e, &f, eps)?;
    let mut proj = matrix_power(&step, 4);
    let mut converged = false;
    for _ in 0..80 {
        let next = proj * (Mat10::identity() * 2.0 - proj);
        let change = (next - proj).amax();
        proj = next;
        if change < 1e-13 * proj.amax().max(1.0) {
            converged = true;
            break;
        }
    }
    if !converged {
        return Err(Error::Analysis("the limit projector did not converge"));
    }
    let proj_x: Mat8 = proj.fixed_view::<8, 8>(0, 0).into_owned();
    let k_lim: SMatrix<f64, 2, 8> = proj.fixed_view::<2, 8>(8, 0).into_owned();
    let complement = Mat8::identity() - proj_x;
    let mut coordinates = SMatrix::<f64, 2, 8>::zeros();
    coordinates.set_row(0, &complement.row(2));
    coordinates.set_row(1, &complement.row(5));
    let mut off_motor_residual: f64 = 0.0;
    for r in [0, 1, 3, 4, 6, 7] {
        off_motor_residual = off_motor_residual.max(complement.row(r).amax());
    }
    let closed = model.a + model.b * (gain + k_lim);
    let projected = coordinates * closed;
    let a4 = Matrix2::new(projected[(0, 2)], projected[(0, 5)], projected[(1, 2)], projected[(1, 5)]);
    let b2 = coordinates * model.b;
    let ev = a4.complex_eigenvalues();
    let eigenvalues = if ev[0].im >= ev[1].im { [ev[0], ev[1]] } else { [ev[1], ev[0]] };
    Ok(LimitPair { k_lim, coordinates, a4, b2, eigenvalues, off_motor_residual })
}

/// The sampled closed loop linearized at rest, as a map of ζ = (x(t_ρ), v on [t_ρ, t_ρ+1)):
/// x_{ρ+1} = Φ x_ρ + Γ v_ρ (+ Γ K x_ρ for a sampled inner loop), v_{ρ+1} = K_pred x_ρ
/// (the prediction from x(t_ρ) is applied one period later, Fig. 2.1).
pub fn sampled_loop_matrix(
    model: &LinearModel,
    gain: &FeedbackGain,
    controller: &ControllerParameters,
    inner_loop: InnerLoop,
) -> Result<Mat10, Error> {
    let delta = controller.sampling_period;
    let k_pred = predictor_gain(model, gain, controller)?;
    let a_plant = match inner_loop {
        InnerLoop::Continuous => model.a + model.b * gain,
        InnerLoop::Sampled => model.a,
    };
    let mut aug = Mat10::zeros();
    aug.fixed_view_mut::<8, 8>(0, 0).copy_from(&(a_plant * delta));
    aug.fixed_view_mut::<8, 2>(0, 8).copy_from(&(model.b * delta));
    let transition = aug.exp();
    let phi: Mat8 = transition.fixed_view::<8, 8>(0, 0).into_owned();
    let gamma: SMatrix<f64, 8, 2> = transition.fixed_view::<8, 2>(0, 8).into_owned();
    let phi = match inner_loop {
        InnerLoop::Continuous => phi,
        InnerLoop::Sampled => phi + gamma * gain,
    };
    let mut m = Mat10::zeros();
    m.fixed_view_mut::<8, 8>(0, 0).copy_from(&phi);
    m.fixed_view_mut::<8, 2>(0, 8).copy_from(&gamma);
    m.fixed_view_mut::<2, 8>(8, 0).copy_from(&k_pred);
    Ok(m)
}

/// One eigenvalue of the sampled loop.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pole {
    /// λ, the eigenvalue of the one-period map.
    pub discrete: [f64; 2],
    /// s = ln λ / δ, its continuous-time equivalent, 1/s (`None` for λ = 0).
    pub continuous: Option<[f64; 2]>,
}

/// The stability analysis of one configuration.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityReport {
    /// δ, s.
    pub sampling_period: f64,
    /// Link angles of the rest point, rad.
    pub rest: [f64; 2],
    /// ρ, the spectral radius of the one-period map: the loop is stable iff ρ < 1.
    pub spectral_radius: f64,
    /// ln ρ / δ, the asymptotic growth rate of the errors, 1/s.
    pub growth_rate: f64,
    /// All ten eigenvalues, largest |λ| first.
    pub poles: Vec<Pole>,
    /// The δ → 0 pair A4 without preliminary feedback, 1/s.
    pub limit_pair_open: [[f64; 2]; 2],
    /// The δ → 0 pair A4 with the configured preliminary feedback, 1/s.
    pub limit_pair: [[f64; 2]; 2],
}

fn pair(c: &[Complex<f64>; 2]) -> [[f64; 2]; 2] {
    [[c[0].re, c[0].im], [c[1].re, c[1].im]]
}

/// Eigenvalues of the one-period map, largest modulus first.
pub fn loop_eigenvalues(m: &Mat10) -> Vec<Complex<f64>> {
    let mut ev: Vec<Complex<f64>> = m.complex_eigenvalues().iter().copied().collect();
    ev.sort_by(|a, b| b.norm().total_cmp(&a.norm()).then(b.im.total_cmp(&a.im)));
    ev
}

/// Analyses `config` linearized at rest at its final configuration, or at link-2 angle `q2`.
pub fn analyze(config: &SimulationConfig, q2: Option<f64>) -> Result<StabilityReport, Error> {
    config.validate()?;
    let rest = [config.reference.end[0], q2.unwrap_or(config.reference.end[1])];
    let gain = resolve_gain(config)?;
    let model = linearize_at_rest(&config.plant, config.controller.alpha, rest);
    let m = sampled_loop_matrix(&model, &gain, &config.controller, config.inner_loop)?;
    let ev = loop_eigenvalues(&m);
    let delta = config.controller.sampling_period;
    let spectral_radius = ev.first().map(|c| c.norm()).unwrap_or(0.0);
    let poles = ev
        .iter()
        .map(|l| Pole {
            discrete: [l.re, l.im],
            continuous: if l.norm() > 0.0 {
                let s = l.ln() / delta;
                Some([s.re, s.im])
            } else {
                None
            },
        })
        .collect();
    let open = limit_pair(&model, &FeedbackGain::zeros())?;
    let with_pf = limit_pair(&model, &gain)?;
    Ok(StabilityReport {
        sampling_period: delta,
        rest,
        spectral_radius,
        growth_rate: spectral_radius.ln() / delta,
        poles,
        limit_pair_open: pair(&open.eigenvalues),
        limit_pair: pair(&with_pf.eigenvalues),
    })
}

/// The spectral radius alone (the inner loop of stability maps and sweeps).
pub fn spectral_radius(config: &SimulationConfig, q2: Option<f64>) -> Result<f64, Error> {
    config.validate()?;
    let rest = [config.reference.end[0], q2.unwrap_or(config.reference.end[1])];
    let gain = resolve_gain(config)?;
    let model = linearize_at_rest(&config.plant, config.controller.alpha, rest);
    let m = sampled_loop_matrix(&model, &gain, &config.controller, config.inner_loop)?;
    Ok(loop_eigenvalues(&m).first().map(|c| c.norm()).unwrap_or(0.0))
}

/// ρ over a grid of sampling periods and stabilizing constants (α1 = α2 = α).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityMap {
    /// δ values, s.
    pub sampling_periods: Vec<f64>,
    /// α values, 1/s.
    pub alphas: Vec<f64>,
    /// ρ for alpha index i and δ index j at `i * sampling_periods.len() + j`.
    pub spectral_radius: Vec<f64>,
}

impl StabilityMap {
    /// ρ at (α index, δ index).
    pub fn at(&self, alpha_index: usize, delta_index: usize) -> f64 {
        self.spectral_radius[alpha_index * self.sampling_periods.len() + delta_index]
    }
}

/// Computes ρ on the grid `alphas × sampling_periods`, all other settings from `config`.
pub fn stability_map(
    config: &SimulationConfig,
    sampling_periods: &[f64],
    alphas: &[f64],
) -> Result<StabilityMap, Error> {
    let mut rho = Vec::with_capacity(sampling_periods.len() * alphas.len());
    for &alpha in alphas {
        stability_map_row(config, alpha, sampling_periods, &mut rho)?;
    }
    Ok(StabilityMap { sampling_periods: sampling_periods.to_vec(), alphas: alphas.to_vec(), spectral_radius: rho })
}

/// One row of a stability map: ρ for α1 = α2 = `alpha` at each of `sampling_periods`, appended
/// to `out`. Maps are computed row by row so that a page can spread the work over frames.
pub fn stability_map_row(
    config: &SimulationConfig,
    alpha: f64,
    sampling_periods: &[f64],
    out: &mut Vec<f64>,
) -> Result<(), Error> {
    let mut c = *config;
    c.controller.alpha = [alpha, alpha];
    c.validate()?;
    let gain = resolve_gain(&c)?;
    let model = linearize_at_rest(&c.plant, c.controller.alpha, [c.reference.end[0], c.reference.end[1]]);
    for &delta in sampling_periods {
        let mut ctrl = c.controller;
        ctrl.sampling_period = delta;
        ctrl.validate()?;
        let m = sampled_loop_matrix(&model, &gain, &ctrl, c.inner_loop)?;
        out.push(loop_eigenvalues(&m).first().map(|l| l.norm()).unwrap_or(0.0));
    }
    Ok(())
}

/// Geometric spacing from `lo` to `hi` with `n` points (for logarithmic axes).
pub fn log_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    match n {
        0 => vec![],
        1 => vec![lo],
        _ => (0..n).map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64)).collect(),
    }
}
