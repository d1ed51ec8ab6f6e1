//! The plant: eq. (4.1), a horizontal two-link arm whose first joint is a spring K1 between the
//! motor (angle θ) and link 1 (angle q1), with Dahl friction on the motor and on joint 2.
//!
//! Generalised coordinates are ordered q = (q1, q2, θ), the same order as the controller's state
//! X = (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2).
//!
//! # Integrator
//! One plant step of length h is a Strang splitting:
//! 1. friction half step: xf advanced over h/2 by the exact exponential update of
//!    [`crate::model::friction::dahl_update`] at the current velocities;
//! 2. the mechanical states (q, q̇) advanced over h by classical RK4 with xf frozen;
//! 3. friction half step at the new velocities.
//!
//! The friction states are stiff (ε/|v| ≈ 1e-4 s) and are never stepped explicitly; RK4 only sees
//! the ≈ 30 rad/s flexible mode (ωh ≈ 0.03 at the default h = 1 ms) and the ≈ 160 rad/s
//! presliding spring Fc/ε of stuck friction. `tests/plant.rs` measures the error against a step
//! 16 times finer.

use nalgebra::{Matrix3, SVector, Vector2, Vector3};

use crate::model::friction::advance_friction;
use crate::model::params::PlantParameters;

/// The physical state of the arm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlantState {
    /// q = (q1, q2, θ), rad.
    pub q: Vector3<f64>,
    /// q̇ = (q̇1, q̇2, θ̇), rad/s.
    pub qdot: Vector3<f64>,
    /// Dahl friction torques xf = (xf1 on the motor, xf2 on joint 2), N m.
    pub friction: Vector2<f64>,
}

impl PlantState {
    /// At rest at link angles (q1, q2), with the spring unstretched (θ = q1) and no friction.
    pub fn at_rest(q1: f64, q2: f64) -> Self {
        Self { q: Vector3::new(q1, q2, q1), qdot: Vector3::zeros(), friction: Vector2::zeros() }
    }

    /// True if every component is a finite number.
    pub fn is_finite(&self) -> bool {
        self.q.iter().chain(self.qdot.iter()).chain(self.friction.iter()).all(|v| v.is_finite())
    }
}

/// The arm's equations of motion, eq. (4.1) with the mass matrix of ERRATA.md.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plant {
    pub params: PlantParameters,
}

impl Plant {
    pub fn new(params: PlantParameters) -> Self {
        Self { params }
    }

    /// M(q2) = [[A1 + 2 A3 c2, A2 + A3 c2, 0], [A2 + A3 c2, A2, 0], [0, 0, Ir1]], eq. (4.1)
    /// (the OCR's 2 A3 off the diagonal is wrong: only A3 conserves energy).
    #[inline]
    pub fn mass_matrix(&self, q2: f64) -> Matrix3<f64> {
        let p = &self.params;
        let c2 = q2.cos();
        let m12 = p.a2 + p.a3 * c2;
        Matrix3::new(p.a1 + 2.0 * p.a3 * c2, m12, 0.0, m12, p.a2, 0.0, 0.0, 0.0, p.ir1)
    }

    /// ∂M/∂q2.
    #[inline]
    pub fn mass_matrix_dq2(&self, q2: f64) -> Matrix3<f64> {
        let a3s = self.params.a3 * q2.sin();
        Matrix3::new(-2.0 * a3s, -a3s, 0.0, -a3s, 0.0, 0.0, 0.0, 0.0, 0.0)
    }

    /// The right-hand side r of M q̈ = r, eq. (4.1), for friction torques xf and input torques
    /// T = (T1 on the motor, T2 on joint 2):
    /// r1 = A3 q̇2 (2 q̇1 + q̇2) s2 + K1 (θ − q1),
    /// r2 = −Bv2 q̇2 − xf2 − A3 q̇1² s2 + T2,
    /// r3 = −Bv1 θ̇ − xf1 + T1 + K1 (q1 − θ).
    #[inline]
    pub fn forces(
        &self,
        q: &Vector3<f64>,
        qdot: &Vector3<f64>,
        friction: &Vector2<f64>,
        torque: &Vector2<f64>,
    ) -> Vector3<f64> {
        self.forces_stretched(q[1], q[2] - q[0], qdot, friction, torque)
    }

    /// [`Plant::forces`] from q2 and the joint's stretch θ − q1, given apart: the predictor forms
    /// the stretch of a step from the previous one and the step's small change, free of the
    /// rounding of the absolute angles (which, divided by ε², would swamp its torques).
    #[inline]
    pub fn forces_stretched(
        &self,
        q2: f64,
        stretch: f64,
        qdot: &Vector3<f64>,
        friction: &Vector2<f64>,
        torque: &Vector2<f64>,
    ) -> Vector3<f64> {
        let p = &self.params;
        let s2 = q2.sin();
        Vector3::new(
            p.a3 * qdot[1] * (2.0 * qdot[0] + qdot[1]) * s2 + p.k1 * stretch,
            -p.bv2 * qdot[1] - friction[1] - p.a3 * qdot[0] * qdot[0] * s2 + torque[1],
            -p.bv1 * qdot[2] - friction[0] + torque[0] - p.k1 * stretch,
        )
    }

    /// The size of each row of [`Plant::forces_stretched`] (friction-free): the sum of its terms'
    /// magnitudes, the scale of its rounding error (Newton's floor in the predictor).
    #[inline]
    pub fn force_magnitudes(&self, q2: f64, stretch: f64, qdot: &Vector3<f64>, torque: &Vector2<f64>) -> Vector3<f64> {
        let p = &self.params;
        let s2 = q2.sin().abs();
        let spring = (p.k1 * stretch).abs();
        Vector3::new(
            (p.a3 * qdot[1] * (2.0 * qdot[0] + qdot[1])).abs() * s2 + spring,
            (p.bv2 * qdot[1]).abs() + p.a3 * qdot[0] * qdot[0] * s2 + torque[1].abs(),
            (p.bv1 * qdot[2]).abs() + torque[0].abs() + spring,
        )
    }

    /// Jacobians (∂r/∂q, ∂r/∂q̇) of [`Plant::forces`] (independent of friction and torque).
    #[inline]
    pub fn force_jacobians(&self, q: &Vector3<f64>, qdot: &Vector3<f64>) -> (Matrix3<f64>, Matrix3<f64>) {
        let p = &self.params;
        let (s2, c2) = q[1].sin_cos();
        let (v1, v2) = (qdot[0], qdot[1]);
        #[rustfmt::skip]
        let dq = Matrix3::new(
            -p.k1, p.a3 * v2 * (2.0 * v1 + v2) * c2, p.k1,
            0.0,   -p.a3 * v1 * v1 * c2,             0.0,
            p.k1,  0.0,                              -p.k1,
        );
        #[rustfmt::skip]
        let dv = Matrix3::new(
            2.0 * p.a3 * v2 * s2,  2.0 * p.a3 * (v1 + v2) * s2, 0.0,
            -2.0 * p.a3 * v1 * s2, -p.bv2,                      0.0,
            0.0,                   0.0,                         -p.bv1,
        );
        (dq, dv)
    }

    /// How the input torques enter r: T1 drives θ (row 3), T2 drives q2 (row 2).
    #[inline]
    pub fn input_matrix() -> nalgebra::Matrix3x2<f64> {
        nalgebra::Matrix3x2::new(0.0, 0.0, 0.0, 1.0, 1.0, 0.0)
    }

    /// q̈ = M(q2)⁻¹ r; M is block diagonal, so a 2×2 solve and a division.
    #[inline]
    pub fn acceleration(
        &self,
        q: &Vector3<f64>,
        qdot: &Vector3<f64>,
        friction: &Vector2<f64>,
        torque: &Vector2<f64>,
    ) -> Vector3<f64> {
        let r = self.forces(q, qdot, friction, torque);
        self.solve_mass(q[1], &r)
    }

    /// M(q2)⁻¹ r.
    #[inline]
    pub fn solve_mass(&self, q2: f64, r: &Vector3<f64>) -> Vector3<f64> {
        let p = &self.params;
        let c2 = q2.cos();
        let (m11, m12, m22) = (p.a1 + 2.0 * p.a3 * c2, p.a2 + p.a3 * c2, p.a2);
        let det = m11 * m22 - m12 * m12;
        Vector3::new((m22 * r[0] - m12 * r[1]) / det, (m11 * r[1] - m12 * r[0]) / det, r[2] / p.ir1)
    }

    /// E = ½ q̇ᵀ M q̇ + ½ K1 (θ − q1)², J; conserved when damping, friction and torques vanish.
    pub fn energy(&self, q: &Vector3<f64>, qdot: &Vector3<f64>) -> f64 {
        let stretch = q[2] - q[0];
        0.5 * qdot.dot(&(self.mass_matrix(q[1]) * qdot)) + 0.5 * self.params.k1 * stretch * stretch
    }

    /// One plant step of length `h` (see the module docs) with the input torques given as a
    /// function of the mechanical state (q, q̇) and the friction state (frozen during the RK4 part).
    pub fn step(
        &self,
        state: &mut PlantState,
        h: f64,
        torque: impl Fn(&Vector3<f64>, &Vector3<f64>, &Vector2<f64>) -> Vector2<f64>,
    ) {
        let mut none = SVector::<f64, 0>::zeros();
        self.step_with(state, &mut none, h, |_, q, v, _, xf| torque(q, v, xf), |_, _, _| SVector::zeros());
    }

    /// One plant step of length `h` with `R` states riding along (the controller's integrators w
    /// in the closed loop): the same split step as [`Plant::step`], with the riders advanced by
    /// the same RK4 stages as (q, q̇). `torque(s, q, q̇, riders, xf)` and `rider_rate(s, q, riders)`
    /// receive s, the time since the start of the step.
    pub fn step_with<const R: usize>(
        &self,
        state: &mut PlantState,
        riders: &mut SVector<f64, R>,
        h: f64,
        torque: impl Fn(f64, &Vector3<f64>, &Vector3<f64>, &SVector<f64, R>, &Vector2<f64>) -> Vector2<f64>,
        rider_rate: impl Fn(f64, &Vector3<f64>, &SVector<f64, R>) -> SVector<f64, R>,
    ) {
        self.friction_half_step(state, 0.5 * h);
        let friction = state.friction;
        let x = Stages { mechanical: mechanical_vector(state), riders: *riders };
        let x = rk4(x, h, |s, x: &Stages<R>| {
            let (q, v) = split_mechanical(&x.mechanical);
            let a = self.acceleration(&q, &v, &friction, &torque(s, &q, &v, &x.riders, &friction));
            Stages { mechanical: join_mechanical(&v, &a), riders: rider_rate(s, &q, &x.riders) }
        });
        let (q, v) = split_mechanical(&x.mechanical);
        state.q = q;
        state.qdot = v;
        *riders = x.riders;
        self.friction_half_step(state, 0.5 * h);
    }

    /// Advances the friction states alone over `dt` at the current velocities (part of a split step).
    #[inline]
    pub fn friction_half_step(&self, state: &mut PlantState, dt: f64) {
        advance_friction(&self.params, &mut state.friction, state.qdot[2], state.qdot[1], dt);
    }
}

/// (q, q̇) as one 6-vector.
#[inline]
pub(crate) fn mechanical_vector(s: &PlantState) -> SVector<f64, 6> {
    join_mechanical(&s.q, &s.qdot)
}

#[inline]
pub(crate) fn join_mechanical(a: &Vector3<f64>, b: &Vector3<f64>) -> SVector<f64, 6> {
    SVector::<f64, 6>::new(a[0], a[1], a[2], b[0], b[1], b[2])
}

#[inline]
pub(crate) fn split_mechanical(x: &SVector<f64, 6>) -> (Vector3<f64>, Vector3<f64>) {
    (Vector3::new(x[0], x[1], x[2]), Vector3::new(x[3], x[4], x[5]))
}

/// What one RK4 stage carries: (q, q̇) and the riders. Component-wise arithmetic, so the result
/// is the same as RK4 on the stacked vector.
#[derive(Clone, Copy, Debug)]
struct Stages<const R: usize> {
    mechanical: SVector<f64, 6>,
    riders: SVector<f64, R>,
}

impl<const R: usize> core::ops::Add for Stages<R> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self { mechanical: self.mechanical + o.mechanical, riders: self.riders + o.riders }
    }
}

impl<const R: usize> core::ops::Mul<f64> for Stages<R> {
    type Output = Self;
    #[inline]
    fn mul(self, k: f64) -> Self {
        Self { mechanical: self.mechanical * k, riders: self.riders * k }
    }
}

/// One classical fourth-order Runge–Kutta step of ẋ = f(s, x), where s is the time since the
/// start of the step.
#[inline]
pub(crate) fn rk4<T>(x: T, h: f64, f: impl Fn(f64, &T) -> T) -> T
where
    T: Copy + core::ops::Add<Output = T> + core::ops::Mul<f64, Output = T>,
{
    let k1 = f(0.0, &x);
    let k2 = f(0.5 * h, &(x + k1 * (0.5 * h)));
    let k3 = f(0.5 * h, &(x + k2 * (0.5 * h)));
    let k4 = f(h, &(x + k3 * h));
    x + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0)
}
