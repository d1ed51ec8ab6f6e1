//! Section 3's structure in words, for the arm shown: V*, the zero dynamics Ā1 on it, the quotient
//! A4 the predictor leaves alone and K_pr moves, the index before and after the two stabilized
//! differentiations, and what k at or below that index does. Every number arrives in a
//! [`Structure`]; nothing here is computed beyond formatting it.

use serde::Serialize;

use super::numbers::rho;
use super::settings::feedback_short;
use crate::analysis::structure::{Cluster, HorizonProbe, Structure};
use crate::control::config::PreliminaryFeedbackChoice;
use crate::plot::format::{minus, scientific, significant_trimmed};

/// The structure's sentences, one per fact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StructureWords {
    /// "V*, the states from which both links can be kept on their law (4.3), is 6-dimensional
    /// (the recursion: 8 → 7 → 6); the motor's θ and θ̇ complete it to ℝ⁸."
    pub v_star: String,
    /// "On V* the controller places Ā1, the zero dynamics, at −2 1/s (×6): stable, the arm is
    /// minimum phase."
    pub zero_dynamics: String,
    /// "It leaves the quotient ℝ⁸/V* alone (no gain on θ, θ̇): A4 = 2.64 ± 29.58j 1/s, unstable;
    /// paper K_pr moves it to −2.48 ± 29.60j 1/s, stable."
    pub quotient: String,
    /// "Index 5 with the path constraint q = q_d, 3 with the stabilized constraint (4.3) …"
    pub index: String,
    /// What k at and below the index does, at the settings' δ.
    pub horizon: String,
}

impl StructureWords {
    /// The sentences in reading order.
    pub fn lines(&self) -> [&str; 5] {
        [&self.v_star, &self.zero_dynamics, &self.quotient, &self.index, &self.horizon]
    }
}

/// A rate as the structure's sentences write it: four significant digits, trimmed ("−2", "−0.5").
fn rate(v: f64) -> String {
    significant_trimmed(v, 4)
}

/// A spectrum of clusters: "−2 1/s (×6)", "−2 1/s (×3) and −0.5 1/s (×3)", "2.64 ± 29.58j 1/s" (a
/// conjugate pair once, its lower half dropped).
fn spectrum(clusters: &[Cluster]) -> String {
    let tiny = |c: &Cluster| c.value[1].abs() <= 1e-9 * c.value[0].hypot(c.value[1]).max(1e-300);
    let parts: Vec<String> = clusters
        .iter()
        .filter(|c| tiny(c) || c.value[1] > 0.0)
        .map(|c| {
            let times = if c.multiplicity > 1 { format!(" (×{})", c.multiplicity) } else { String::new() };
            if tiny(c) {
                format!("{} 1/s{times}", rate(c.value[0]))
            } else {
                minus(&format!("{:.2} ± {:.2}j 1/s{times}", c.value[0], c.value[1]))
            }
        })
        .collect();
    match parts.as_slice() {
        [] => "nowhere (V* = 0)".into(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// "1/ε²" for a gain growing as ε^−p (p rounded to a whole power).
fn growth(order: f64) -> String {
    match order.round() as i64 {
        1 => "1/ε".into(),
        2 => "1/ε²".into(),
        3 => "1/ε³".into(),
        p => format!("ε^−{p}"),
    }
}

/// One short horizon's line: "k = 2 (m = 1.33): U₂ reacts to θ(tₙ) with 3.45e4 N m/rad (∝ 1/ε²),
/// ρ = 2.036".
fn probe(p: &HorizonProbe) -> String {
    let loop_rho = p.rho.map_or("ρ not computable".into(), |r| format!("ρ = {}", rho(r)));
    let head = format!(
        "k = {} (m = {}, kε = {}δ)",
        p.k,
        significant_trimmed(p.eps_ratio, 3),
        significant_trimmed(p.k as f64 / p.eps_ratio, 3)
    );
    if p.torque_forgets {
        return format!("{head}: no gain on θ, θ̇, {loop_rho}");
    }
    let order = p.theta_gain_order.map_or(String::new(), |o| format!(" (∝ {})", growth(o)));
    let rate_gain = if p.theta_rate_gain > 0.0 && p.theta_rate_gain >= 1e-9 * p.theta_gain {
        format!(" and to θ̇ with {} N m s/rad", scientific(p.theta_rate_gain, 3))
    } else {
        String::new()
    };
    format!(
        "{head}: U{} reacts to θ(tₙ) with {} N m/rad{order}{rate_gain}, {loop_rho}",
        subscript(p.k),
        scientific(p.theta_gain, 3)
    )
}

fn subscript(k: usize) -> String {
    k.to_string().chars().map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c)).collect()
}

/// The sentences of `s`, with `pf` naming the settings' preliminary feedback.
pub fn structure(s: &Structure, pf: PreliminaryFeedbackChoice) -> StructureWords {
    let sequence: Vec<String> = s.v_star_sequence.iter().map(|d| d.to_string()).collect();
    let complement = if s.quotient_is_motor { "; the motor's θ and θ̇ complete it to ℝ⁸" } else { "" };
    let v_star = format!(
        "V*, the states from which both links can be kept on their law (4.3), is {}-dimensional (the recursion Vᵢ: \
         {}){complement}.",
        s.v_star_dim,
        sequence.join(" → ")
    );
    // The zeros are those of the constraint (4.3) as output: the law's roots, plus any finite
    // zeros of the arm itself with its links as output (none for this arm).
    let why = match (s.arm_zeros, s.minimum_phase) {
        (0, true) => "the roots of the law (4.3) chosen for the links, stable by design: the arm with its links as \
                      output has no finite zeros of its own (minimum phase)"
            .to_string(),
        (n, true) => format!("the law's roots and the arm's own {n} finite zeros, all stable (minimum phase)"),
        (n, false) => {
            format!("not all stable: the arm's own {n} finite zeros include unstable ones (not minimum phase)")
        }
    };
    let zero_dynamics = format!(
        "On V* the controller places Ā1, the zero dynamics of the constraint as output, at {}: {why}.",
        spectrum(&s.zero_dynamics)
    );
    let verdict = |stable: bool| if stable { "stable" } else { "unstable" };
    let (alone, moved) = if s.limit_ignores_motor {
        (
            "Its limit feedback has no gain on θ, θ̇, which complete V*: on the quotient ℝ⁸/V* the closed loop induces",
            " — the arm's swing as the law moves it (its α moves it), not a pole the controller places",
        )
    } else {
        ("On the quotient ℝ⁸/V* the closed loop induces", "")
    };
    let mut quotient =
        format!("{alone} A4 = {}, {}{moved}", spectrum(&s.quotient_open), verdict(s.quotient_open_stable));
    if s.feedback {
        quotient += &format!(
            "; with {} it moves to {}, {}",
            feedback_short(pf),
            spectrum(&s.quotient),
            verdict(s.quotient_stable)
        );
    }
    quotient.push('.');
    let dims = |d: &[usize]| d.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(", ");
    let index = format!(
        "Index {} of the DAE in (x, u) with the path constraint q = q_d (dim 𝒲ᵢ: {}), {} with the stabilized \
         constraint (4.3) and w (dim 𝒲ᵢ: {}): {} differentiations fewer.",
        s.index_path,
        dims(&s.index_path_sequence),
        s.index_stabilized,
        dims(&s.index_stabilized_sequence),
        s.index_path as i64 - s.index_stabilized as i64
    );
    let forgets = match (s.torque_forgets_from, s.state_forgets_from) {
        (Some(u), Some(x)) => {
            format!("backward Euler forgets the motor's inconsistent start in X_k from k = {x} on and in U_k from k = {u} on")
        }
        (Some(u), None) => format!("backward Euler forgets the motor's inconsistent start in U_k from k = {u} on"),
        _ => "backward Euler does not forget the motor's inconsistent start within k = 4".into(),
    };
    let enough =
        if s.index_suffices() { format!(", so k = {} is already enough", s.index_stabilized) } else { String::new() };
    let probes: Vec<String> = s.probes.iter().map(probe).collect();
    let horizon = format!(
        "The paper asks k larger than the index {}; {forgets}{enough}. At δ = {} s, with kε as near this run's {}δ \
         as ε ≤ δ allows: {}.",
        s.schema_index,
        significant_trimmed(s.delta, 3),
        significant_trimmed(s.horizon_ratio, 3),
        probes.join("; ")
    );
    StructureWords { v_star, zero_dynamics, quotient, index, horizon }
}
