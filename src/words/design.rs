//! The design of the preliminary feedback in words: where the pair is, what the design costs on an
//! analog and on a sampled inner loop, in motor torque, what the paper's gain is made of, and why a
//! target cannot be placed.

use serde::Serialize;

use super::numbers::{complex_pair, per_second};
use super::settings::{feedback_short, windows};
use crate::analysis::design::{largest_stable_delta, small_delta_cured, Unplaceable};
use crate::analysis::StableWindows;
use crate::control::config::InnerLoop;
use crate::control::feedback::TwistParts;
use crate::control::price::{TorqueFigures, TorquePrice, POKE, SWING};
use crate::plot::format::{minus, significant_trimmed};

/// The design's facts as the page shows them beside the feedback's settings.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DesignStatus {
    /// "A4 with twist K_pr: −1.49 ± 28.82j 1/s (damped)".
    pub pair: String,
    /// The pair (re, im ≥ 0), 1/s: where the handle stands.
    pub target: [f64; 2],
    /// The pair can be placed by hand (the twist feedback).
    pub placeable: bool,
    /// The windows with the feedback analog and sampled, and the largest stable δ of each, s.
    pub analog: String,
    pub sampled: String,
    pub delta_max: [Option<f64>; 2],
    /// The one of the two the run uses: "analog" or "sampled".
    pub inner: &'static str,
    /// The motor torque during the slew and after a poke ("" while it is computed).
    pub torque: String,
    /// The gain split into its twist part and the rest.
    pub parts: String,
}

/// "peak 98 N m, RMS 56 N m" for T1.
fn t1(f: &TorqueFigures) -> String {
    format!("peak {} N m, RMS {} N m", significant_trimmed(f.peak[0], 3), significant_trimmed(f.rms[0], 3))
}

/// The motor torque T1 a design takes with the run's inner loop (`inner`: "analog", "sampled"):
/// during the slew and in the swing after a poke.
pub fn torque(price: &TorquePrice, inner: &str) -> String {
    let (poke, duration) = POKE;
    let head = format!("Motor torque T1 (this run's {inner} inner loop) during the slew: {}", t1(&price.slew));
    if price.diverged && price.poke.peak == [0.0; 2] {
        return format!("{head}; the run diverged before the poke.");
    }
    let diverged = if price.diverged { " — the run diverged: these are its figures up to then" } else { "" };
    format!(
        "{head}; in the {} s after a poke ({} N m for {} s): {}{diverged}.",
        significant_trimmed(SWING, 2),
        significant_trimmed(poke[0], 3),
        significant_trimmed(duration, 2),
        t1(&price.poke)
    )
}

/// One inner loop's windows with its largest stable δ: "Analog inner loop (K_pr at every instant):
/// stable only for δ < 0.2160 s — every small δ works".
fn inner_line(name: &str, w: Option<&StableWindows>) -> String {
    let Some(w) = w else { return format!("{name}: computed once the settings rest…") };
    let cure = if small_delta_cured(w) { " — every small δ works" } else { " — small δ fail" };
    let max = match largest_stable_delta(w) {
        Some(d) if d >= w.range[1] => format!("; it never fails up to {} s", w.range[1]),
        Some(d) if w.windows.len() > 1 => match w.windows.last() {
            // A last window that runs to the range's end is no island.
            Some(last) if last[1] >= w.range[1] => format!(
                "; δ_max = {} s (then unstable, and stable again from {} s to the end of the range)",
                significant_trimmed(d, 3),
                significant_trimmed(last[0], 3)
            ),
            _ => format!("; δ_max = {} s (then unstable but for islands)", significant_trimmed(d, 3)),
        },
        Some(d) => format!("; δ_max = {} s", significant_trimmed(d, 3)),
        None => String::new(),
    };
    format!("{name}: {}{cure}{max}.", windows(w))
}

/// The gain's twist part: "T1 = 102.7 (q1 − θ) + 16.49 (q̇1 − θ̇) + the rest (each ≤ 0.4)".
pub fn parts(p: &TwistParts) -> String {
    let term = |v: f64, what: &str| format!("{} {what}", minus(&significant_trimmed(v, 4)));
    format!(
        "Its T1 row is {} + {} + a rest of at most {} (N m per rad or rad/s) per state (T2's: {} + {} + …): mostly a \
         spring and a damper between motor and link 1.",
        term(p.t1[0], "(q1 − θ)"),
        term(p.t1[1], "(q̇1 − θ̇)"),
        significant_trimmed(p.rest, 2),
        term(p.t2[0], "(q1 − θ)"),
        term(p.t2[1], "(q̇1 − θ̇)")
    )
}

/// The design status from its facts: the δ → 0 pair with the feedback, the windows of both inner
/// loops (analog, sampled; None while computed), the torque (None while computed) and the gain's
/// parts. `digital`: the sensors make the controller digital — one loop, K_pr from the readings
/// held over δ, whose windows are `windows[0]`.
pub fn status(
    pf: crate::control::config::PreliminaryFeedbackChoice,
    inner: InnerLoop,
    digital: bool,
    pair: [[f64; 2]; 2],
    windows: [Option<&StableWindows>; 2],
    torque_price: Option<&TorquePrice>,
    gain_parts: &TwistParts,
) -> DesignStatus {
    let [re, im] = pair[0];
    let [re2, _] = pair[1];
    let says = if re.max(re2) < 0.0 { "damped" } else { "growing: small δ fail" };
    // An overdamped pair is two real modes: name both (the slower one decides).
    let shown = if im.abs() > 1e-9 {
        complex_pair(re, im.abs())
    } else {
        minus(&format!("{:.2} and {:.2} 1/s, two real modes: no swing", re.max(re2), re.min(re2)))
    };
    DesignStatus {
        pair: format!("A4 with {}: {shown} ({says})", feedback_short(pf)),
        target: [re, im.abs()],
        placeable: crate::analysis::design::placeable(pf),
        analog: if digital {
            inner_line("Digital controller (the sensors on: Kₚᵣ x from the readings, held over δ)", windows[0])
        } else {
            inner_line("Analog inner loop (Kₚᵣ x at every instant)", windows[0])
        },
        sampled: if digital {
            String::new()
        } else {
            inner_line("Sampled inner loop (Kₚᵣ x held over δ, as a computer applies it)", windows[1])
        },
        delta_max: windows.map(|w| w.and_then(largest_stable_delta)),
        inner: inner_name(inner),
        torque: torque_price.map_or_else(String::new, |t| torque(t, inner_name(inner))),
        // The twist feedback is its own parts; no feedback has none.
        parts: match pf {
            crate::control::config::PreliminaryFeedbackChoice::Paper
            | crate::control::config::PreliminaryFeedbackChoice::Lq => parts(gain_parts),
            _ => String::new(),
        },
    }
}

/// "analog" or "sampled".
fn inner_name(inner: InnerLoop) -> &'static str {
    match inner {
        InnerLoop::Continuous => "analog",
        InnerLoop::Sampled => "sampled",
    }
}

/// Why a target cannot be placed.
pub fn unplaceable(u: &Unplaceable) -> String {
    match *u {
        Unplaceable::RealAxis => {
            "the pair must stay above the real axis (Im s > 0): there it would be two real modes, not a swing".into()
        }
        Unplaceable::NeedsNegativeDamping { re_max } => format!(
            "it would take a damper that pushes the swing (k_d < 0): with k_d ≥ 0 the pair cannot go right of \
             Re s = {}, where it sits with no damper",
            per_second(re_max)
        ),
        Unplaceable::NeedsNegativeStiffness { norm_min } => format!(
            "it would take a spring that softens the joint (k_p < 0): with k_p ≥ 0 the pair at this real part has \
             |s| ≥ {} rad/s",
            significant_trimmed(norm_min, 4)
        ),
        Unplaceable::BeyondRange { key, value, max } => {
            let (symbol, unit) = crate::schema::param(key).map_or((key, ""), |p| (p.symbol, p.unit));
            format!(
                "it would take {symbol} = {} {unit} (at most {} {unit})",
                significant_trimmed(value, 4),
                significant_trimmed(max, 4)
            )
        }
    }
}
