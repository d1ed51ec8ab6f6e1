//! The figure's panels in words: which of those asked for a small canvas does not show, and where
//! they are.

use crate::schema::{PanelKind, Tab};

/// What a notice says of the panels asked for that a layout does not show (`hidden`, in the
/// order asked), or None when every one is in view: which they are and the tabs they are on,
/// e.g. "ρ(δ) and the stability maps do not fit beside the rest at this size: see the tabs
/// “Poles and ρ(δ)” and “Stability maps” (or open flexarm ↗)".
pub fn hidden_note(hidden: &[PanelKind]) -> Option<String> {
    if hidden.is_empty() {
        return None;
    }
    let both_maps = hidden.contains(&PanelKind::MapOff) && hidden.contains(&PanelKind::MapOn);
    let both_errors = hidden.contains(&PanelKind::Error1) && hidden.contains(&PanelKind::Error2);
    let mut names: Vec<&str> = Vec::with_capacity(hidden.len());
    for &k in hidden {
        let name = match k {
            PanelKind::MapOff | PanelKind::MapOn if both_maps => "the stability maps",
            PanelKind::Error1 | PanelKind::Error2 if both_errors => "the errors",
            k => k.name(),
        };
        if !names.contains(&name) {
            names.push(name);
        }
    }
    let tabs: Vec<String> = Tab::ALL
        .into_iter()
        .filter(|t| hidden.iter().any(|k| t.holds(*k)))
        .map(|t| format!("“{}”", t.label()))
        .collect();
    let verb = if names.len() == 1 && !names[0].starts_with("the stability") && names[0] != "the errors" {
        "does"
    } else {
        "do"
    };
    let tab_word = if tabs.len() == 1 { "the tab" } else { "the tabs" };
    Some(format!(
        "{} {verb} not fit beside the rest at this size: see {tab_word} {} (or open flexarm ↗)",
        capitalised(&and_list(&names)),
        and_list(&tabs)
    ))
}

/// "a", "a and b", "a, b and c".
fn and_list<S: AsRef<str>>(items: &[S]) -> String {
    match items {
        [] => String::new(),
        [one] => one.as_ref().to_string(),
        [rest @ .., last] => {
            let head: Vec<&str> = rest.iter().map(|s| s.as_ref()).collect();
            format!("{} and {}", head.join(", "), last.as_ref())
        }
    }
}

/// The text with its first letter upper-case ("The z-plane"; "ρ(δ)" stays as it is).
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    match chars.next() {
        Some(c) if c.is_ascii_lowercase() => c.to_ascii_uppercase().to_string() + chars.as_str(),
        _ => text.to_string(),
    }
}

/// A panel as the figure's description names it ("the pole plot s = ln λ / δ"); `rate`: ρ(δ) and
/// the maps show ln ρ/δ. None for the panels named with another (run B's arm, e2, the second map).
pub fn spoken(kind: PanelKind, rate: bool) -> Option<&'static str> {
    Some(match kind {
        PanelKind::Arm => "the arm (top view)",
        PanelKind::Error1 => "the tracking errors e1, e2 over time",
        PanelKind::Torque => "the torques",
        PanelKind::Velocity => "link 1's velocity q̇1, true and as the controller estimated it",
        PanelKind::Poles => "the pole plot s = ln λ / δ",
        PanelKind::ZPlane => "the loop's eigenvalues λ with the unit circle",
        PanelKind::RhoCurve if rate => "the rate ln ρ/δ along δ",
        PanelKind::RhoCurve => "ρ along δ",
        PanelKind::MapOff if rate => "the stability maps coloured by ln ρ/δ",
        PanelKind::MapOff => "the stability maps ρ(δ, α)",
        PanelKind::StudyError => {
            "the tracking error and T1's noise against δ, with these sensors and with perfect ones"
        }
        PanelKind::ArmB | PanelKind::Error2 | PanelKind::StudyTorque | PanelKind::MapOn => return None,
    })
}

/// "The figure shows the arm (top view), the tracking errors e1, e2 over time, …." for the
/// panels `kinds` drawn.
pub fn figure_contents(kinds: &[PanelKind], rate: bool) -> String {
    let shown: Vec<&str> = kinds.iter().filter_map(|k| spoken(*k, rate)).collect();
    format!("The figure shows {}.", shown.join(", "))
}

/// One run in the figure's description: " Run B (settings): Stable — ρ = …; at t = 3.00 s the
/// errors are …; observed: …." (`settings` when two runs are compared; `looking_back` at a kept
/// instant; `errors` where the error plots are drawn).
pub fn figure_run(
    name: &str,
    settings: Option<&str>,
    headline: &str,
    detail: &str,
    at: f64,
    looking_back: bool,
    errors: Option<&str>,
    observed: &str,
) -> String {
    let when = if looking_back { "looking back at" } else { "at" };
    let who = settings.map_or(String::new(), |s| format!("Run {name} ({s}): "));
    // Without the error plots, the instant alone.
    let errors = errors.map_or(String::new(), |e| format!(" the errors are {e}"));
    format!(" {who}{headline} — {detail}; {when} t = {at:.2} s{errors}; {observed}.")
}
