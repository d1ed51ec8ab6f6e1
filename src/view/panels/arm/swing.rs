//! The flexible pair's shape on the arm: its eigenvector (how q1, q2 and θ move, with their
//! relative amplitudes and phases) turning at the pair's frequency in this loop, slowed down,
//! about the rest point of run A's analysis — on demand, while the simulation may be paused.

use nalgebra::Complex;

use super::drawing::ArmPose;
use crate::plot::{format, palette};
use crate::view::legend::{item as legend_item, Glyph, LegendGroup};
use crate::view::panels::contract::Frame;

/// The swing's animation is this many times slower than the swing itself.
pub const SWING_SLOWDOWN: f64 = 10.0;
/// The largest angle the drawn swing moves an angle of the arm by, rad.
const SWING_DRAWN_AMPLITUDE: f64 = 0.35;

/// The flexible pair's shape in run A's analysis: its frequency in the loop, rad/s (the pole's,
/// arg λ / δ), its rest point, and the motions of q1, q2 and θ (complex amplitudes, scaled so that
/// the largest is 1).
pub fn swing_shape(frame: &Frame) -> Option<SwingShape> {
    let report = frame.runs[0].report.as_ref()?;
    let mode = report.swing_mode.as_ref()?;
    let [re, im] = &mode.shape;
    let c = |i: usize| [re[i], im[i]];
    let parts = [c(0), c(1), c(2)];
    let largest = parts.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
    if !(largest > 0.0 && largest.is_finite()) {
        return None;
    }
    let omega = mode.eigenvalue[1].atan2(mode.eigenvalue[0]).abs() / report.sampling_period;
    Some(SwingShape { omega, rest: report.rest, motion: parts.map(|[a, b]| [a / largest, b / largest]) })
}

/// The arm in the swing's shape at this moment of the animation (when the view shows it).
pub fn swing_pose(frame: &Frame) -> Option<ArmPose> {
    if !frame.options.show_swing {
        return None;
    }
    let shape = swing_shape(frame)?;
    // Real part of the motion turning at ω, slowed down: Re(v e^{iφ}).
    let phase = shape.omega / SWING_SLOWDOWN * frame.clock;
    let (sin, cos) = phase.sin_cos();
    let at = |[a, b]: [f64; 2]| SWING_DRAWN_AMPLITUDE * (a * cos - b * sin);
    let [q1, q2, theta] = shape.motion.map(at);
    Some(ArmPose { q1: shape.rest[0] + q1, q2: shape.rest[1] + q2, theta: shape.rest[0] + theta })
}

/// The flexible pair's motion: how q1, q2 and θ swing, relative to the largest of them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SwingShape {
    /// The pair's frequency in this loop, rad/s.
    pub omega: f64,
    /// The rest point (q1, q2), rad.
    pub rest: [f64; 2],
    /// q1, q2 and θ's complex amplitudes (real, imaginary), the largest of unit size.
    pub motion: [[f64; 2]; 3],
}

/// The key to the swing's shape, with its numbers: the pair's frequency in this loop and how far
/// and how late link 1 and link 2 move for the motor's 1.
pub fn swing_legend(frame: &Frame) -> Option<LegendGroup> {
    if !frame.options.show_swing {
        return None;
    }
    let shape = swing_shape(frame)?;
    let [q1, q2, theta] = shape.motion.map(|[a, b]| Complex::new(a, b));
    let relative = |z: Complex<f64>| {
        let r = z / theta;
        let degrees = r.arg().to_degrees();
        let when = if degrees.abs() >= 150.0 {
            format!("{:.0}° {}: against it", degrees.abs(), if degrees < 0.0 { "behind" } else { "ahead" })
        } else if degrees.abs() <= 30.0 {
            format!("{:.0}° {}: with it", degrees.abs(), if degrees < 0.0 { "behind" } else { "ahead" })
        } else {
            format!("{:.0}° {}", degrees.abs(), if degrees < 0.0 { "behind" } else { "ahead" })
        };
        format!("{} × the motor's angle, {when}", format::significant(r.norm(), 2))
    };
    let hz = shape.omega / core::f64::consts::TAU;
    let text = format!(
        "the arm in the flexible pair's shape, {SWING_SLOWDOWN}× slower than its {} rad/s ({} Hz) in this loop, \
             about the rest point — link 1 (q1): {}; link 2 (q2, at its joint): {}",
        format::significant(shape.omega, 3),
        format::significant(hz, 2),
        relative(q1),
        relative(q2),
    );
    Some(LegendGroup {
        title: "the swing's shape",
        items: vec![legend_item(Glyph::Line, palette::SWING, &text)],
        scale: None,
    })
}
