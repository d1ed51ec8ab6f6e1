//! A run's settings in words, and the sentences that name its feedback, a point of a map, a map,
//! its errors and the stable windows of δ: "no K_pr, δ = 0.01 s, α = 2 1/s", "ρ, paper Kₚᵣ",
//! "Without preliminary feedback (α = 2 1/s) the loop is stable only for …".

use crate::analysis::stability_map::MapSide;
use crate::analysis::StableWindows;
use crate::control::config::{PreliminaryFeedbackChoice, SimulationConfig};
use crate::plot::color::Measure;
use crate::plot::format::{scientific, significant, significant_trimmed};

/// "no K_pr", "paper K_pr", "LQ K_pr", "twist K_pr".
pub fn feedback_short(pf: PreliminaryFeedbackChoice) -> &'static str {
    match pf {
        PreliminaryFeedbackChoice::Off => "no K_pr",
        PreliminaryFeedbackChoice::Paper => "paper K_pr",
        PreliminaryFeedbackChoice::Lq => "LQ K_pr",
        PreliminaryFeedbackChoice::Twist => "twist K_pr",
    }
}

/// The twist feedback's gains: "k_p = 0 N m/rad, k_d = 16 N m s/rad".
pub fn twist_gains(c: &SimulationConfig) -> String {
    format!(
        "k_p = {} N m/rad, k_d = {} N m s/rad",
        significant_trimmed(c.twist.stiffness, 4),
        significant_trimmed(c.twist.damping, 4)
    )
}

/// "δ = 0.05 s, α = 2 1/s" for tooltips.
pub fn point(delta: f64, alpha: f64) -> String {
    format!("δ = {} s, α = {} 1/s", significant(delta, 3), significant(alpha, 3))
}

/// A point of the design map: "δ = 0.01 s, k_d = 16 N m s/rad".
pub fn design_point(delta: f64, damping: f64) -> String {
    format!("δ = {} s, k_d = {} N m s/rad", significant(delta, 3), significant(damping, 3))
}

/// "ρ, no Kₚᵣ", "ρ, paper Kₚᵣ" ("rate, no Kₚᵣ" … when the maps show the rate) for the map of
/// `side` beside run A's feedback `pf`: short enough for a narrow map's title, with K_pr's
/// subscript as the page's controls write it.
pub fn map_caption(side: MapSide, pf: PreliminaryFeedbackChoice, measure: Measure) -> String {
    // The quantity by its short name: the colour bar and the row's title give it in full.
    let what = match measure {
        Measure::Rho => "ρ",
        Measure::Rate => "rate",
    };
    match side.feedback(pf) {
        PreliminaryFeedbackChoice::Off => format!("{what}, no Kₚᵣ"),
        PreliminaryFeedbackChoice::Paper => format!("{what}, paper Kₚᵣ"),
        PreliminaryFeedbackChoice::Lq => format!("{what}, LQ Kₚᵣ"),
        PreliminaryFeedbackChoice::Twist => format!("{what} over k_d, twist Kₚᵣ"),
    }
}

/// "without preliminary feedback" or "with paper K_pr" (a map's tooltip title).
pub fn with_feedback(pf: PreliminaryFeedbackChoice) -> String {
    match pf {
        PreliminaryFeedbackChoice::Off => "without preliminary feedback".to_string(),
        f => format!("with {}", feedback_short(f)),
    }
}

/// The errors e1, e2: "1.23e−3, −4.56e−4 rad".
pub fn errors(e: [f64; 2]) -> String {
    // Exponents where errors are small (comparable at a glance), plain numbers near a radian.
    let f = |v: f64| if v.abs() >= 0.1 { significant(v, 3) } else { scientific(v, 3) };
    format!("{}, {} rad", f(e[0]), f(e[1]))
}

/// A run's settings: "no K_pr, δ = 0.01 s, α = 2 1/s", and what departs from the paper's model
/// (", friction compensation held"), so that "your settings" never hide it.
pub fn run(c: &SimulationConfig) -> String {
    let [a1, a2] = c.controller.alpha;
    let alpha = if a1 == a2 {
        format!("α = {}", significant_trimmed(a1, 3))
    } else {
        format!("α = {}, {}", significant_trimmed(a1, 3), significant_trimmed(a2, 3))
    };
    let delta = c.controller.sampling_period;
    let mut text =
        format!("{}, δ = {} s, {alpha} 1/s", feedback_short(c.preliminary_feedback), significant_trimmed(delta, 3));
    let paper = SimulationConfig::default();
    if c.preliminary_feedback == PreliminaryFeedbackChoice::Twist {
        text += &format!(", {}", twist_gains(c));
    }
    if c.preliminary_feedback == PreliminaryFeedbackChoice::Lq && c.lq != paper.lq {
        let w = |v: f64| crate::plot::format::significant(v, 2);
        text += &format!(", LQ weights q_z = {}, q_y = {}, r = {}", w(c.lq.twist), w(c.lq.twist_rate), w(c.lq.torque));
    }
    if c.friction_compensation != paper.friction_compensation {
        text += &format!(", friction compensation {}", c.friction_compensation.name());
    }
    if c.inner_loop != paper.inner_loop {
        text += &format!(", inner loop {}", c.inner_loop.name());
    }
    let (k, m) = (c.controller.horizon_steps, c.controller.eps_ratio);
    if k != paper.controller.horizon_steps || m != paper.controller.eps_ratio {
        text += &format!(", k = {k}, m = {}", significant_trimmed(m, 3));
    }
    if c.plant != paper.plant {
        text += &format!(", arm: {}", crate::schema::arm_text(&c.plant.values()));
    }
    if c.has_model_error() {
        text += ", the controller assumes the paper's arm (a model error)";
    }
    if c.sensors != paper.sensors {
        text += &format!(", {}", crate::words::sensors::sensors_text(&c.sensors));
    }
    if c.reference.repeat_hold.is_some() {
        text += ", slew repeating";
    }
    text
}

/// The windows in words: "stable only for 0.0350 s < δ < 0.1007 s and 0.1069 s < δ < …",
/// "stable for every δ from 0.002 s to 0.25 s", "unstable for every δ from … to … s".
pub fn windows(w: &StableWindows) -> String {
    let [lo, hi] = w.range;
    let edge = |v: f64| format!("{v:.4}");
    match w.windows.as_slice() {
        [] => format!("unstable for every δ from {} s to {} s", lo, hi),
        [[a, b]] if *a <= lo && *b >= hi => format!("stable for every δ from {lo} s to {hi} s"),
        windows => {
            let parts: Vec<String> = windows
                .iter()
                .map(|[a, b]| match (*a <= lo, *b >= hi) {
                    (true, false) => format!("δ < {} s", edge(*b)),
                    (false, true) => format!("δ > {} s", edge(*a)),
                    _ => format!("{} s < δ < {} s", edge(*a), edge(*b)),
                })
                .collect();
            let list = match parts.split_last() {
                Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
                _ => parts.join(""),
            };
            format!("stable only for {list} (between {lo} s and {hi} s)")
        }
    }
}

/// The windows of a run's settings in a sentence: "Without preliminary feedback (α = 2 1/s) the
/// loop is stable only for …".
pub fn windows_sentence(pf: PreliminaryFeedbackChoice, alpha: [f64; 2], w: &StableWindows) -> String {
    let who = match pf {
        PreliminaryFeedbackChoice::Off => "Without preliminary feedback".to_string(),
        pf => format!("With {}", feedback_short(pf)),
    };
    let alpha = if alpha[0] == alpha[1] {
        format!("α = {} 1/s", significant_trimmed(alpha[0], 3))
    } else {
        format!("α1 = {}, α2 = {} 1/s", significant_trimmed(alpha[0], 3), significant_trimmed(alpha[1], 3))
    };
    format!("{who} ({alpha}) the loop is {}.", windows(w))
}
