//! The processor in words: how long the controller's prediction takes against δ. The paper: "to
//! be implementable, the numerical integration of the DAE has to be faster than real-time".

use crate::control::timing::ControllerTime;
use crate::plot::format::{number, significant_trimmed};

/// One sampling instant's prediction against δ, e.g. "the controller's prediction (k = 12
/// backward-Euler steps) takes 6.1 µs per sample here: 0.31 % of δ = 2 ms — faster than real
/// time", or "… takes 140 µs per sample here: 140 % of δ = 0.1 ms: slower than real time, this δ
/// cannot be implemented on this computer".
pub fn processor(t: &ControllerTime) -> String {
    let steps = if t.horizon_steps == 1 { "step" } else { "steps" };
    let what = format!("the controller's prediction (k = {} backward-Euler {steps})", t.horizon_steps);
    if !t.is_measured() {
        return format!("{what} could not be timed here: the clock did not see it");
    }
    let head = format!(
        "{what} takes {} per sample here: {} % of δ = {}",
        short_duration(t.seconds_per_sample),
        significant_trimmed(100.0 * t.share(), 2),
        period(t.sampling_period)
    );
    if t.fits() {
        head + " — faster than real time"
    } else {
        head + ": slower than real time, this δ cannot be implemented on this computer"
    }
}

/// A short time in the unit its size asks for, two significant digits: "85 ns", "6.1 µs",
/// "1.4 ms", "2.5 s".
pub fn short_duration(seconds: f64) -> String {
    let (value, unit) = if seconds < 1e-6 {
        (seconds * 1e9, "ns")
    } else if seconds < 1e-3 {
        (seconds * 1e6, "µs")
    } else if seconds < 1.0 {
        (seconds * 1e3, "ms")
    } else {
        (seconds, "s")
    };
    format!("{} {unit}", significant_trimmed(value, 2))
}

/// δ in ms below a second, in s from one on, as set: "2 ms", "0.1 ms", "10 ms", "1.5 s".
pub fn period(seconds: f64) -> String {
    if seconds < 1.0 {
        format!("{} ms", number(seconds * 1e3))
    } else {
        format!("{} s", number(seconds))
    }
}
