//! Which panels a figure asks for (the options that choose them, the tabs a narrow canvas then
//! offers), and — when a canvas is too small to show every panel asked for at once — the words
//! that say which are not in view and where they are (an embed must never drop a panel silently).
//! What the panels and tabs are is the schema's vocabulary ([`crate::schema::PanelKind`],
//! [`crate::schema::Tab`]); where they go is [`super`]'s business.

use crate::schema::{PanelKind, Tab};
use crate::view::rect::Rect;

/// One panel: its kind and its rectangle in CSS pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Panel {
    pub kind: PanelKind,
    /// CSS pixels, origin top-left of the canvas. For plots: the data area only.
    pub rect: Rect,
}

impl Panel {
    /// True if (x, y) (CSS px) lies on the panel's data area, edges included.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        let r = &self.rect;
        x >= r.x && x <= r.right() && y >= r.y && y <= r.bottom()
    }
}

/// Which panels to show.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayoutOptions {
    /// Shows the arm picture (two with `pair`); off, the stage is left out (an embed of plots only).
    pub show_arm: bool,
    /// Shows the error plots e1, e2.
    pub show_errors: bool,
    /// Adds the torque panel below the error panels.
    pub show_torque: bool,
    /// Adds the pole plot to the analysis row.
    pub show_poles: bool,
    /// The pole plot shows λ in the z-plane instead of s = ln λ / δ.
    pub z_plane: bool,
    /// Adds ρ(δ) at the current α to the analysis row.
    pub show_rho: bool,
    /// Adds the two stability maps to the analysis row.
    pub show_map: bool,
    /// Two runs side by side: a second arm on the stage.
    pub pair: bool,
    /// The view a narrow canvas shows (a wide one shows them all).
    pub tab: Tab,
}

impl Default for LayoutOptions {
    /// What the page's full view shows by default: one run, the arm and its errors, no torque,
    /// the s-plane pole plot, ρ(δ), the maps.
    fn default() -> Self {
        Self {
            show_arm: true,
            show_errors: true,
            show_torque: false,
            show_poles: true,
            z_plane: false,
            show_rho: true,
            show_map: true,
            pair: false,
            tab: Tab::Run,
        }
    }
}

/// The panels of a layout, grouped by where they go.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PanelLists {
    /// The arm pictures, sharing the stage.
    pub stage: Vec<PanelKind>,
    /// The time plots, stacked.
    pub plots: Vec<PanelKind>,
    /// The analysis panels, in a row below the time plots.
    pub analysis: Vec<PanelKind>,
}

impl PanelLists {
    /// Every panel, stage first.
    pub fn all(&self) -> impl Iterator<Item = PanelKind> + '_ {
        self.stage.iter().chain(&self.plots).chain(&self.analysis).copied()
    }
}

impl LayoutOptions {
    /// The stage panels, the time plots and the analysis panels, in order.
    pub fn panels(&self) -> PanelLists {
        let mut stage = Vec::new();
        if self.show_arm {
            stage.push(PanelKind::Arm);
            if self.pair {
                stage.push(PanelKind::ArmB);
            }
        }
        let mut plots = Vec::new();
        if self.show_errors {
            plots.extend([PanelKind::Error1, PanelKind::Error2]);
        }
        if self.show_torque {
            plots.push(PanelKind::Torque);
        }
        let mut analysis = Vec::new();
        if self.show_poles {
            analysis.push(if self.z_plane { PanelKind::ZPlane } else { PanelKind::Poles });
        }
        if self.show_rho {
            analysis.push(PanelKind::RhoCurve);
        }
        if self.show_map {
            analysis.extend([PanelKind::MapOff, PanelKind::MapOn]);
        }
        PanelLists { stage, plots, analysis }
    }

    /// The tabs a narrow canvas offers: those that have panels (the run's first).
    pub fn tabs(&self) -> Vec<Tab> {
        let lists = self.panels();
        Tab::ALL.into_iter().filter(|t| lists.all().any(|k| t.holds(k))).collect()
    }
}

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
