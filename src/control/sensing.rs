//! What a real controller reads and can apply: encoders, measurement noise, velocities from the
//! measured angles, and a torque limit (all off by default: the paper's perfect robot).
//!
//! The paper ends on "the size of δ should only be lower bounded by limitations of the processor
//! or state estimator". With any of these sensors on the loop becomes a **digital controller**:
//! at each sampling instant t_n the computer reads the angles
//!
//! m_n = Q(q(t_n)) + η_n,  Q(q) = Δ·round(q/Δ),  Δ = 2π/N (N counts per revolution),
//!
//! with η_n seeded Gaussian noise; it estimates the velocities (exactly, as the paper, or as the
//! backward difference ν_n = (m_n − m_{n−1})/δ); and everything it computes is held over the
//! period: the preliminary feedback K_pr X_m(t_n) (an analog K_pr would need analog
//! velocities), the integrators w fed by the held measured angle, ẇ = α³(m_n − q_d(t)), and the
//! friction observer fed by the held velocity estimate. A first-order low-pass filter of time
//! constant τ_v may smooth that estimate, ν_n = β ν_{n−1} + (1 − β) ν_raw,n with β = e^(−δ/τ_v):
//! it bounds the differenced velocity's noise (σ/τ_v instead of √2 σ/δ) at the price of a lag
//! of about τ_v. The predictor starts from the measured
//! X_m = (m, ν, w), never the true state. A torque limit clamps T1 and T2 (the motor's and link 2's)
//! whether or not the rest is on.

use nalgebra::{Vector2, Vector3};
use serde::{Deserialize, Serialize};

use crate::error::ConfigError;
use crate::schema;

/// How the controller gets the velocities q̇1, q̇2, θ̇ (and the friction observer its input).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum VelocitySource {
    /// Measured exactly, as the paper assumes (tachometers without noise).
    #[default]
    Exact,
    /// The backward difference of the measured angles over one period, (m_n − m_{n−1})/δ: what
    /// an encoder alone gives. Its noise is √2 σ/δ: it grows as δ shrinks.
    Difference,
}

impl VelocitySource {
    /// The word in URLs, on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            VelocitySource::Exact => "exact",
            VelocitySource::Difference => "difference",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "exact" => Some(VelocitySource::Exact),
            "difference" => Some(VelocitySource::Difference),
            _ => None,
        }
    }
}

/// The sensors and the actuators' limit. `Default` is the paper's perfect robot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SensorModel {
    /// Encoder counts per revolution on q1, q2 and θ; 0 = exact angles.
    pub encoder_counts: f64,
    /// Standard deviation of white Gaussian noise on each measured angle, rad; 0 = none.
    pub noise: f64,
    /// The seed of the noise (a setting, so that a link reproduces a run bit for bit).
    pub seed: u64,
    pub velocity: VelocitySource,
    /// The time constant τ_v of the first-order low-pass filter on the velocity estimate, s;
    /// 0 = no filter.
    pub velocity_filter: f64,
    /// |T1|, |T2| at most this, N m; 0 = no limit.
    pub torque_limit: f64,
}

/// How the controller estimates the velocities: from where, and through which filter. The linear
/// analysis ([`crate::analysis::digital`]) needs exactly this of the sensors.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct VelocityEstimator {
    pub source: VelocitySource,
    /// τ_v, s; 0 = no filter.
    pub filter: f64,
}

impl VelocityEstimator {
    /// The filter's weight on the last estimate over an interval `dt`: β = e^(−dt/τ_v) (0 without
    /// a filter, so that the estimate is the raw one exactly).
    pub fn memory(&self, dt: f64) -> f64 {
        if self.filter > 0.0 {
            (-dt / self.filter).exp()
        } else {
            0.0
        }
    }
}

impl Default for SensorModel {
    fn default() -> Self {
        Self {
            encoder_counts: 0.0,
            noise: 0.0,
            seed: 1,
            velocity: VelocitySource::Exact,
            velocity_filter: 0.0,
            torque_limit: 0.0,
        }
    }
}

impl SensorModel {
    /// True if the controller reads something other than the true state: it is then the digital
    /// controller of the module's description. (A torque limit alone leaves the paper's loop.)
    pub fn is_digital(&self) -> bool {
        self.encoder_counts > 0.0
            || self.noise > 0.0
            || self.velocity != VelocitySource::Exact
            || self.velocity_filter > 0.0
    }

    /// How the controller estimates the velocities.
    pub fn estimator(&self) -> VelocityEstimator {
        VelocityEstimator { source: self.velocity, filter: self.velocity_filter }
    }

    /// The encoder's count Δ = 2π/N, rad (0 for exact angles).
    pub fn count(&self) -> f64 {
        if self.encoder_counts > 0.0 {
            std::f64::consts::TAU / self.encoder_counts
        } else {
            0.0
        }
    }

    /// The variance of one measured angle's error as white noise: Δ²/12 (the quantizer's, where
    /// the angle moves over many counts between samples) + σ².
    pub fn angle_variance(&self) -> f64 {
        let q = self.count();
        q * q / 12.0 + self.noise * self.noise
    }

    /// The torque limit, if any, N m.
    pub fn limit(&self) -> Option<f64> {
        (self.torque_limit > 0.0).then_some(self.torque_limit)
    }

    /// Checks each value against its schema entry.
    pub fn validate(&self) -> Result<(), ConfigError> {
        schema::ENCODER.check(self.encoder_counts)?;
        schema::NOISE.check(self.noise)?;
        schema::SEED.check(self.seed as f64)?;
        schema::VELOCITY_FILTER.check(self.velocity_filter)?;
        schema::TORQUE_LIMIT.check(self.torque_limit)?;
        Ok(())
    }

    /// The angle as the encoder reads it (no noise): the nearest count.
    pub fn quantize(&self, angle: f64) -> f64 {
        let q = self.count();
        if q > 0.0 {
            (angle / q).round() * q
        } else {
            angle
        }
    }
}

/// A small deterministic generator of Gaussian noise: SplitMix64 for uniform bits, Box–Muller
/// for the normal pair. Its whole state is two words, kept with the loop's state so that a run
/// continued from a kept instant draws the same numbers.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct NoiseSource {
    state: u64,
    /// The second of the last Box–Muller pair, not yet used.
    spare: Option<f64>,
}

impl NoiseSource {
    pub fn new(seed: u64) -> Self {
        Self { state: seed, spare: None }
    }

    fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in (0, 1].
    fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 1.0) * (1.0 / (1u64 << 53) as f64)
    }

    /// A standard normal number.
    pub fn normal(&mut self) -> f64 {
        if let Some(s) = self.spare.take() {
            return s;
        }
        let r = (-2.0 * self.uniform().ln()).sqrt();
        let phi = std::f64::consts::TAU * self.uniform();
        self.spare = Some(r * phi.sin());
        r * phi.cos()
    }
}

/// What the controller read at its last sampling instant: the measured angles m_n, the velocity
/// estimate ν_n and the noise source's state (all of it part of the loop's state, so that a run
/// continued from a kept instant reads the same).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measurement {
    /// m_n = (q1, q2, θ) as read, rad.
    pub angles: Vector3<f64>,
    /// ν_n = (q̇1, q̇2, θ̇) as estimated, rad/s.
    pub velocities: Vector3<f64>,
    /// The errors as read, m_n − q_d(t_n) for links 1 and 2, rad: what the integrators w
    /// integrate over the period (a digital integrator, w_{n+1} = w_n + δ α³ (m_n − q_d(t_n))).
    pub error: Vector2<f64>,
    /// When m_n was read (None before the first reading), s.
    pub time: Option<f64>,
    pub noise: NoiseSource,
}

impl Measurement {
    /// Nothing read yet; the noise drawn from `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            angles: Vector3::zeros(),
            velocities: Vector3::zeros(),
            error: Vector2::zeros(),
            time: None,
            noise: NoiseSource::new(seed),
        }
    }

    /// Reads the true angles `q` and velocities `qdot` at time `t`, when the reference is at link
    /// angles `reference`, through `sensors`. The
    /// difference runs over the time since the last reading (δ, or the old δ across a change of
    /// it); the first reading has no predecessor and estimates rest.
    pub fn read(&mut self, sensors: &SensorModel, t: f64, q: &Vector3<f64>, qdot: &Vector3<f64>, reference: [f64; 2]) {
        let mut m = Vector3::zeros();
        for i in 0..3 {
            m[i] = sensors.quantize(q[i]);
            if sensors.noise > 0.0 {
                m[i] += sensors.noise * self.noise.normal();
            }
        }
        let raw = match (sensors.velocity, self.time) {
            (VelocitySource::Exact, _) => *qdot,
            (VelocitySource::Difference, Some(t0)) if t > t0 => (m - self.angles) / (t - t0),
            (VelocitySource::Difference, _) => Vector3::zeros(),
        };
        // The filter runs over the time since the last reading; the first reading starts it.
        self.velocities = match self.time {
            Some(t0) if sensors.velocity_filter > 0.0 && t > t0 => {
                let beta = sensors.estimator().memory(t - t0);
                self.velocities * beta + raw * (1.0 - beta)
            }
            _ => raw,
        };
        self.angles = m;
        self.error = Vector2::new(m[0] - reference[0], m[1] - reference[1]);
        self.time = Some(t);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quantizer_is_within_half_a_count() {
        let s = SensorModel { encoder_counts: 1024.0, ..SensorModel::default() };
        let q = s.count();
        for i in 0..10_000 {
            let a = -3.0 + i as f64 * 6.1e-4;
            assert!((s.quantize(a) - a).abs() <= 0.5 * q * (1.0 + 1e-12), "{a}");
        }
        assert_eq!(SensorModel::default().quantize(0.123), 0.123);
    }

    /// The filtered difference of white angle noise σ at rest: ν_n = β ν_{n−1} + (1 − β)(η_n −
    /// η_{n−1})/δ has variance σ² (1 − β)²/δ² · 2/(1 + β) (the impulse response 1, −(1 − β)βᵏ⁻¹
    /// summed in squares) — about σ²/τ_v² for δ ≪ τ_v, where the unfiltered difference has 2σ²/δ².
    #[test]
    fn the_filter_bounds_the_differenced_velocitys_noise() {
        let sigma = 1e-3;
        for (delta, tau) in [(0.001, 0.02), (0.004, 0.02), (0.002, 0.002), (0.01, 0.0)] {
            let s = SensorModel {
                noise: sigma,
                seed: 5,
                velocity: VelocitySource::Difference,
                velocity_filter: tau,
                ..SensorModel::default()
            };
            let mut m = Measurement::new(s.seed);
            let n = 200_000;
            let mut sum_sq = 0.0;
            for i in 0..n + 100 {
                m.read(&s, i as f64 * delta, &Vector3::zeros(), &Vector3::zeros(), [0.0, 0.0]);
                if i >= 100 {
                    sum_sq += m.velocities[0] * m.velocities[0];
                }
            }
            let beta = s.estimator().memory(delta);
            let expected = sigma * sigma * (1.0 - beta).powi(2) / (delta * delta) * 2.0 / (1.0 + beta);
            let ratio = sum_sq / n as f64 / expected;
            assert!((ratio - 1.0).abs() < 0.03, "δ = {delta}, τ_v = {tau}: {ratio}");
            if tau > 0.0 && delta < tau {
                // Bounded near σ/τ_v whatever δ.
                let rms = (sum_sq / n as f64).sqrt();
                assert!(rms < 1.1 * sigma / tau, "δ = {delta}, τ_v = {tau}: {rms}");
            }
        }
    }

    #[test]
    fn the_filtered_estimate_of_a_steady_motion_is_exact() {
        // A ramp's difference is its slope; the filter's gain at zero frequency is 1.
        let s = SensorModel { velocity: VelocitySource::Difference, velocity_filter: 0.02, ..SensorModel::default() };
        let (mut m, slope, delta) = (Measurement::new(1), 0.7, 0.005);
        for i in 0..400 {
            let t = i as f64 * delta;
            m.read(&s, t, &Vector3::repeat(slope * t), &Vector3::zeros(), [0.0, 0.0]);
        }
        assert!((m.velocities[0] - slope).abs() < 1e-6 * slope, "{}", m.velocities[0]);
    }

    #[test]
    fn the_noise_is_standard_normal_and_repeats_with_its_seed() {
        let mut a = NoiseSource::new(7);
        let n = 200_000;
        let xs: Vec<f64> = (0..n).map(|_| a.normal()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n as f64;
        // Standard errors: 1/√n ≈ 0.0022 for the mean, √(2/n) ≈ 0.0032 for the variance.
        assert!(mean.abs() < 0.01 && (var - 1.0).abs() < 0.015, "{mean} {var}");
        let mut b = NoiseSource::new(7);
        assert!(xs.iter().take(100).all(|x| *x == b.normal()));
        let mut c = NoiseSource::new(8);
        assert_ne!(xs[0], c.normal());
    }
}
