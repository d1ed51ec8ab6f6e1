//! Which panels a figure asks for (the options that choose them, the tabs a narrow canvas then
//! offers); when a canvas is too small to show every panel asked for at once, [`super::Layout`]
//! says which are not in view and [`crate::words::panels::hidden_note`] says it in words (an embed
//! must never drop a panel silently).
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
    /// Adds link 1's velocity, true and as estimated, below them (the `measured` switch with
    /// digital sensors).
    pub show_velocity: bool,
    /// Adds the sensor study's two panels (error, torque against δ) after ρ(δ) (the `study`
    /// switch with digital sensors).
    pub show_study: bool,
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
            show_velocity: false,
            show_study: false,
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
        if self.show_velocity {
            plots.push(PanelKind::Velocity);
        }
        let mut analysis = Vec::new();
        if self.show_poles {
            analysis.push(if self.z_plane { PanelKind::ZPlane } else { PanelKind::Poles });
        }
        if self.show_rho {
            analysis.push(PanelKind::RhoCurve);
        }
        if self.show_study {
            analysis.extend([PanelKind::StudyError, PanelKind::StudyTorque]);
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
