//! The story's sentences that need a decision of their own: a frequency, a phase, the swing's
//! energy over one period, and the cure (the paper's K_pr on this arm) with its reason.

use crate::analysis::resonance::PaperFeedbackEffect;
use crate::plot::format::significant_trimmed;
use crate::words::numbers::{eigenvalues_2x2, energy_shares, percent};

/// A frequency as every sentence of the story writes it: "29.40 rad/s (4.68 Hz)".
pub(super) fn frequency(omega: f64) -> String {
    format!("{omega:.2} rad/s ({:.2} Hz)", omega / (2.0 * core::f64::consts::PI))
}

/// Where the held torque is against the motor's velocity, its lag in degrees in (−180°, 180°]:
/// "is in phase with …" within half a degree (a phase that rounds to 0° is neither ahead nor
/// behind), "lags … by 21°", "runs 21° ahead of …".
pub fn phase_words(lag: f64) -> String {
    let rounded = lag.round();
    if lag.abs() < 0.5 {
        "is in phase with the motor's velocity".into()
    } else if rounded.abs() >= 180.0 {
        "is in antiphase with the motor's velocity".into()
    } else {
        let (verb, tail) =
            if lag > 0.0 { ("lags the motor's velocity by ", "") } else { ("runs ", " ahead of the motor's velocity") };
        format!("{verb}{:.0}°{tail}", rounded.abs())
    }
}

/// The swing's energy over one period at δ, in words (`law_lag`: the lag law's φ, for comparison).
pub(super) fn energy_text(e: &crate::analysis::energy::SwingEnergy, law_lag: f64, delta: f64, swings: bool) -> String {
    // Both the computed lag and the law's φ in (−180°, 180°]: behind (lags) or ahead.
    let signed = |degrees: f64| {
        let d = degrees.rem_euclid(360.0);
        if d > 180.0 {
            d - 360.0
        } else {
            d
        }
    };
    let lag = signed(e.lag.to_degrees());
    let phase = phase_words(lag);
    let role =
        if lag.abs() < 90.0 { "less than a quarter turn: it pushes" } else { "more than a quarter turn: it brakes" };
    let law = {
        let l = signed(law_lag.to_degrees());
        // Two numbers, two meanings: the lag computed over one period, and the law's estimate.
        let side = if l.abs() < 0.5 {
            ""
        } else if l >= 0.0 {
            " behind"
        } else {
            " ahead"
        };
        format!(
            " (computed over one period; the lag law estimates φ = 1.5 ωδ, whole turns dropped, at {:.0}°{side})",
            l.abs()
        )
    };
    let share = |v: f64, whose: &str| {
        if v >= 0.0 {
            format!("puts {}{whose} in", percent(v))
        } else {
            format!("takes {}{whose} out", percent(-v))
        }
    };
    let [held, preliminary, damping, net] = energy_shares(e);
    let feedback =
        if e.preliminary_feedback != 0.0 { format!(", Kₚᵣ {}", share(preliminary, "")) } else { String::new() };
    // A pair damped past its swing has no phase to lag by: only the balance is said.
    let (head, what) = if swings {
        (format!("the held torque {phase}{law} — {role}. Over each period it"), "swing")
    } else {
        (
            "the pair is two real modes, not a swing (no phase to lag by). Over each period the held torque"
                .to_string(),
            "pair",
        )
    };
    format!(
        "At δ = {} s {head} {}{feedback}, and the arm's damping takes {} out: the {what}'s energy changes by {}{} a \
         period, so it {}.",
        significant_trimmed(delta, 3),
        share(held, if swings { " of the swing's energy" } else { " of the pair's energy" }),
        percent(damping),
        if net > 0.0 { "+" } else { "" },
        percent(net),
        if net > 0.0 { "grows" } else { "dies out" }
    )
}

/// Why a fixed preliminary feedback leaves the δ → 0 pair unstable at these α, from where its
/// α bound comes: the controller's feed against the damping it adds (tr A4), or a motor damped
/// past its swing, where one real eigenvalue crosses zero (det A4).
pub fn gains_fail_because(bound: &crate::analysis::resonance::AlphaBound) -> &'static str {
    if bound.lost_to_det() {
        "the motor is damped past its swing and one real eigenvalue of the pair crosses zero (det A4 < 0)"
    } else {
        "the controller's feed 3α/2 outweighs their damping"
    }
}

/// "In short"'s cure, from what the paper's K_pr does to the pair on this arm at these α (the
/// pair it makes, and for α1 = α2 the largest α it keeps stable): "every small δ" only where the
/// pair it leaves dies out as δ → 0.
pub(super) fn kpr_cure(
    paper: &PaperFeedbackEffect,
    pair: &str,
    r: &crate::analysis::resonance::ResonanceReport,
    equal: bool,
    alpha: &str,
    rest: &str,
    other_end: &str,
) -> String {
    let limit = format!("{:.2} 1/s", r.paper_alpha_limit);
    if paper.pair[0] < 0.0 {
        let range = if equal {
            format!(" — on this arm, at {rest}, for every α below {limit}")
        } else {
            format!(" at {rest}")
        };
        format!(
            "A preliminary feedback Kₚᵣ damps the ringing first (the paper's gains move the pair to {pair} \
             at {alpha}); then every small δ works{range}.{}",
            sentence(other_end)
        )
    } else {
        let range = if equal { format!(" only for α below {limit} on this arm at {rest}") } else { String::new() };
        format!(
            "A preliminary feedback Kₚᵣ damps the ringing first — the paper's gains do so{range}: at \
             {alpha} they leave the pair at {pair}, {}, and small δ still fail (the LQ design, redone for the arm \
             and α, damps it).{}",
            gains_fail_because(&r.paper_bound),
            sentence(other_end)
        )
    }
}

/// A clause as a sentence of its own after another: " Where …." (empty stays empty).
fn sentence(clause: &str) -> String {
    // The clauses begin "where" (char::to_uppercase would bring Unicode's case tables, ≈ 7 kB of
    // wasm, for one letter).
    match clause.strip_prefix("where") {
        Some(rest) => format!(" Where{rest}."),
        None if clause.is_empty() => String::new(),
        None => format!(" {clause}."),
    }
}

/// Where the repeating slew also rests at its other end (`q2`), what the paper's K_pr leaves there
/// at these α, when it differs in stability from the analysis' rest point: " Where the slew
/// holds at q2 = 4.71 rad the pair sits at 0.34 ± 23.72j 1/s: small δ fail there." Empty otherwise.
pub(super) fn other_end_words(
    plant: &crate::model::PlantParameters,
    alpha: [f64; 2],
    here_stable: bool,
    q2: Option<f64>,
) -> String {
    let Some(q2) = q2 else { return String::new() };
    let m = crate::analysis::resonance::closed_form_a4(plant, alpha, q2, &crate::control::feedback::paper_gain());
    let stable = m.complex_eigenvalues().iter().all(|e| e.re < 0.0);
    if stable == here_stable {
        return String::new();
    }
    // A clause: " Where …" after a sentence, "; where …" inside one (the callers join it).
    format!(
        "where the repeating slew holds at its other end (q2 = {} rad) the paper's gains leave the pair at {}: small \
         δ {} there (“Linearize at: where the arm is headed” shows it)",
        significant_trimmed(q2, 3),
        eigenvalues_2x2(m.trace(), m.determinant()),
        if stable { "work" } else { "fail" }
    )
}
