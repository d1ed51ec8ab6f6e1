//! The panels of the figure and the tabs a phone shows them on, as the vocabulary every layer
//! shares: one spelling each. The session decides which tab a change brings into view, the words
//! name a panel, the view draws it, the page reads the ids through [`super::schema`]'s export.
//! Which panels a view asks for and where they go are the view's business.

use serde::Serialize;

/// What a panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum PanelKind {
    /// The arm, its motor, the flexible joint and the reference arm (run A).
    Arm,
    /// The second arm when two runs are compared (run B).
    ArmB,
    /// Tracking error of link 1, e1 = q1 − q_d1 over time.
    Error1,
    /// Tracking error of link 2, e2 = q2 − q_d2 over time.
    Error2,
    /// Applied torques T1, T2 over time.
    Torque,
    /// Link 1's velocity q̇1 over time, true and as the digital controller estimated it (with the
    /// `measured` switch on and the sensors digital).
    Velocity,
    /// The sampled loop's eigenvalues as s = ln λ / δ, with the δ → 0 pair A4.
    Poles,
    /// The sampled loop's eigenvalues λ themselves, with the unit circle.
    ZPlane,
    /// ρ over δ at the current α, with the stable windows.
    RhoCurve,
    /// The sensor study (issue 36): the slew's error and the error at rest against δ, with the
    /// settings' sensors and with perfect ones, and the linear prediction.
    StudyError,
    /// The sensor study: T1's noise at rest and its peak against δ, with the torque limit.
    StudyTorque,
    /// ρ over (δ, α) without preliminary feedback.
    MapOff,
    /// ρ over (δ, α) with preliminary feedback.
    MapOn,
}

impl PanelKind {
    pub const ALL: [PanelKind; 13] = [
        PanelKind::Arm,
        PanelKind::ArmB,
        PanelKind::Error1,
        PanelKind::Error2,
        PanelKind::Torque,
        PanelKind::Velocity,
        PanelKind::Poles,
        PanelKind::ZPlane,
        PanelKind::RhoCurve,
        PanelKind::StudyError,
        PanelKind::StudyTorque,
        PanelKind::MapOff,
        PanelKind::MapOn,
    ];

    /// Where the kind comes in the list of panels: the order of this enum.
    pub const fn order(self) -> u8 {
        self as u8
    }

    /// The identifier the page sees in `Renderer.layout()` and in the schema's `panels`.
    pub const fn id(self) -> &'static str {
        match self {
            PanelKind::Arm => "arm",
            PanelKind::ArmB => "arm-b",
            PanelKind::Error1 => "e1",
            PanelKind::Error2 => "e2",
            PanelKind::Torque => "torque",
            PanelKind::Velocity => "velocity",
            PanelKind::Poles => "poles",
            PanelKind::ZPlane => "z-plane",
            PanelKind::RhoCurve => "rho-curve",
            PanelKind::StudyError => "study-error",
            PanelKind::StudyTorque => "study-torque",
            PanelKind::MapOff => "map-off",
            PanelKind::MapOn => "map-on",
        }
    }

    /// The panel with this id.
    pub fn from_id(id: &str) -> Option<PanelKind> {
        PanelKind::ALL.into_iter().find(|k| k.id() == id)
    }

    /// The panel in words, as a notice names it ("the z-plane", "ρ(δ)").
    pub const fn name(self) -> &'static str {
        match self {
            PanelKind::Arm => "the arm",
            PanelKind::ArmB => "run B's arm",
            PanelKind::Error1 => "e1",
            PanelKind::Error2 => "e2",
            PanelKind::Torque => "the torques",
            PanelKind::Velocity => "link 1's velocity",
            PanelKind::Poles => "the pole plot",
            PanelKind::ZPlane => "the z-plane",
            PanelKind::RhoCurve => "ρ(δ)",
            PanelKind::StudyError => "the error against δ",
            PanelKind::StudyTorque => "T1 against δ",
            PanelKind::MapOff => "the map without K_pr",
            PanelKind::MapOn => "the map with K_pr",
        }
    }

    /// True for panels that plot quantities against time.
    pub fn is_time_plot(self) -> bool {
        matches!(self, PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque | PanelKind::Velocity)
    }

    /// True for the arm pictures.
    pub fn is_stage(self) -> bool {
        matches!(self, PanelKind::Arm | PanelKind::ArmB)
    }

    /// True for the stability maps.
    pub fn is_map(self) -> bool {
        matches!(self, PanelKind::MapOff | PanelKind::MapOn)
    }

    /// True for the panels of the analysis row: pole plot (s or z), ρ(δ) and maps.
    pub fn is_analysis(self) -> bool {
        matches!(
            self,
            PanelKind::Poles
                | PanelKind::ZPlane
                | PanelKind::RhoCurve
                | PanelKind::StudyError
                | PanelKind::StudyTorque
                | PanelKind::MapOff
                | PanelKind::MapOn
        )
    }

    /// True for the sensor study's two panels.
    pub fn is_study(self) -> bool {
        matches!(self, PanelKind::StudyError | PanelKind::StudyTorque)
    }

    /// True for the two pictures of the loop's eigenvalues.
    pub fn is_pole_plot(self) -> bool {
        matches!(self, PanelKind::Poles | PanelKind::ZPlane)
    }

    /// The tab that holds it on a narrow canvas.
    pub fn tab(self) -> Tab {
        if self.is_stage() || self.is_time_plot() {
            Tab::Run
        } else if self.is_map() {
            Tab::Maps
        } else if self.is_study() {
            Tab::Study
        } else {
            Tab::Poles
        }
    }
}

/// One of the views a phone shows at a time (a narrow canvas cannot show every panel readably).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Tab {
    /// The arm(s) and the time plots.
    #[default]
    Run,
    /// The pole plot (s or z) and ρ(δ).
    Poles,
    /// The two stability maps.
    Maps,
    /// The sensor study's error and torque against δ.
    Study,
}

impl Tab {
    pub const ALL: [Tab; 4] = [Tab::Run, Tab::Poles, Tab::Study, Tab::Maps];

    /// The word in the state string (`tab=poles`).
    pub const fn id(self) -> &'static str {
        match self {
            Tab::Run => "run",
            Tab::Poles => "poles",
            Tab::Maps => "maps",
            Tab::Study => "study",
        }
    }

    /// What the tab bar says.
    pub const fn label(self) -> &'static str {
        match self {
            Tab::Run => "Arm and errors",
            Tab::Poles => "Poles and ρ(δ)",
            Tab::Maps => "Stability maps",
            Tab::Study => "Error against δ",
        }
    }

    pub fn from_id(id: &str) -> Option<Tab> {
        Tab::ALL.into_iter().find(|t| t.id() == id)
    }

    /// True if `kind` belongs to this tab.
    pub fn holds(self, kind: PanelKind) -> bool {
        kind.tab() == self
    }
}
