//! The prescribed slew of section 5: a 9th-order polynomial with zero velocity, acceleration,
//! jerk and snap at both ends,
//! q_d(t) = q_d0 + (q_df − q_d0) s(t/t_f),  s(τ) = 126τ⁵ − 420τ⁶ + 540τ⁷ − 315τ⁸ + 70τ⁹
//! (the OCR prints −126τ⁵; then s(1) ≠ 1, see ERRATA.md), s = 0 before and 1 after the slew.

use nalgebra::Vector2;

use crate::model::params::SlewParameters;

/// q_d and its first two time derivatives for both links at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceSample {
    /// q_d, rad.
    pub q: Vector2<f64>,
    /// q̇_d, rad/s.
    pub qdot: Vector2<f64>,
    /// q̈_d, rad/s².
    pub qddot: Vector2<f64>,
}

/// The reference trajectory: one slew (the paper), or there and back repeatedly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reference {
    pub params: SlewParameters,
}

/// s(τ), s'(τ), s''(τ) of the normalised 9th-order profile, clamped outside [0, 1].
#[inline]
pub fn profile(tau: f64) -> (f64, f64, f64) {
    if tau <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    if tau >= 1.0 {
        return (1.0, 0.0, 0.0);
    }
    let t2 = tau * tau;
    let t3 = t2 * tau;
    let t4 = t3 * tau;
    // Horner forms of 126τ⁵ − 420τ⁶ + 540τ⁷ − 315τ⁸ + 70τ⁹ and its derivatives.
    let s = t4 * tau * (126.0 + tau * (-420.0 + tau * (540.0 + tau * (-315.0 + tau * 70.0))));
    let ds = t4 * (630.0 + tau * (-2520.0 + tau * (3780.0 + tau * (-2520.0 + tau * 630.0))));
    let dds = t3 * (2520.0 + tau * (-12600.0 + tau * (22680.0 + tau * (-17640.0 + tau * 5040.0))));
    (s, ds, dds)
}

impl Reference {
    pub fn new(params: SlewParameters) -> Self {
        Self { params }
    }

    /// q_d, q̇_d, q̈_d at time t (s).
    pub fn sample(&self, t: f64) -> ReferenceSample {
        let p = &self.params;
        let tf = p.slew_time;
        let start = Vector2::from(p.start);
        let end = Vector2::from(p.end);
        let (from, to, local) = match p.repeat_hold {
            None => (start, end, t),
            Some(hold) => {
                // Slew there, hold, slew back, hold; period 2 (t_f + hold).
                let leg = tf + hold;
                let phase = t.rem_euclid(2.0 * leg);
                if t < 0.0 {
                    (start, end, t)
                } else if phase < leg {
                    (start, end, phase)
                } else {
                    (end, start, phase - leg)
                }
            }
        };
        let (s, ds, dds) = profile(local / tf);
        let span = to - from;
        ReferenceSample { q: from + span * s, qdot: span * (ds / tf), qddot: span * (dds / (tf * tf)) }
    }

    /// q_df of the leg under way at time t: where the arm is headed, or holds (the start before
    /// t = 0, the slew's end afterwards; alternately the end and the start when it repeats).
    pub fn target(&self, t: f64) -> [f64; 2] {
        let p = &self.params;
        match p.repeat_hold {
            _ if t < 0.0 => p.start,
            None => p.end,
            Some(hold) => {
                let leg = p.slew_time + hold;
                if t.rem_euclid(2.0 * leg) < leg {
                    p.end
                } else {
                    p.start
                }
            }
        }
    }

    /// When the rest the reference is in at time t began (−∞ before the first slew), or None
    /// while it moves.
    pub fn rest_since(&self, t: f64) -> Option<f64> {
        let tf = self.params.slew_time;
        if t <= 0.0 {
            return Some(f64::NEG_INFINITY);
        }
        match self.params.repeat_hold {
            None => (t >= tf).then_some(tf),
            Some(hold) => {
                let phase = t.rem_euclid(tf + hold);
                (phase >= tf).then_some(t - phase + tf)
            }
        }
    }

    /// True while the reference moves (a slew is in progress) at time t.
    pub fn is_moving(&self, t: f64) -> bool {
        let tf = self.params.slew_time;
        match self.params.repeat_hold {
            None => t > 0.0 && t < tf,
            Some(hold) => t > 0.0 && t.rem_euclid(tf + hold) < tf,
        }
    }
}
