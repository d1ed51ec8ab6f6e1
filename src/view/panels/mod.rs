//! Every panel of the figure, each in its own folder with everything about it — how it is drawn,
//! described for the page, read out under the pointer, keyed, titled as a figure — behind one
//! interface ([`contract::PanelView`]). The scene lays the panels out, keeps what they share
//! ([`contract::Frame`]) and asks them through [`Panels`], which dispatches on the panel's kind;
//! it knows no panel's insides.
//!
//! | folder | panels |
//! |---|---|
//! | [`arm`] | the arm (run A's, and run B's when compared), the swing's shape |
//! | [`time_plots`] | e1, e2, the torques; log \|e\| and its split; the zoom on one instant (Fig. 2.1) |
//! | [`pole_plot`] | the loop's eigenvalues as s = ln λ/δ, with A4 |
//! | [`z_plane`] | the loop's eigenvalues λ against the unit circle |
//! | [`rho_curve`] | ρ(δ) at this α, with the stable windows |
//! | [`sensor_study`] | the error and T1 against δ with a real robot's sensors (issue 36) |
//! | [`stability_maps`] | ρ over (δ, α) without and with the preliminary feedback |
//!
//! Architecture invariant: no panel imports another (`tests/architecture.rs`); what two share is
//! below them ([`crate::view::loop_poles`], [`crate::view::rho_readout`], …).

pub mod arm;
pub mod contract;
pub mod pole_plot;
pub mod rho_curve;
pub mod sensor_study;
pub mod stability_maps;
pub mod time_plots;
pub mod z_plane;

use crate::schema::PanelKind;
use crate::view::layout::Panel;
use crate::view::legend::LegendGroup;
use crate::view::loop_poles::PoleInfo;
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe};
use arm::Arm;
use contract::{Frame, PanelView, Runs};
use pole_plot::PolePlot;
use rho_curve::RhoCurve;
use sensor_study::StudyPanels;
use stability_maps::StabilityMaps;
use time_plots::TimePlots;
use z_plane::ZPlane;

/// One of each panel type, with its state between frames.
#[derive(Clone, Debug, Default)]
pub struct Panels {
    pub arm: Arm,
    pub time_plots: TimePlots,
    pub pole_plot: PolePlot,
    pub z_plane: ZPlane,
    pub rho_curve: RhoCurve,
    pub study: StudyPanels,
    pub maps: StabilityMaps,
}

/// Calls `$call` on the panel type that draws `$kind`, bound to `$p` (statically: each arm is
/// that type's own method, which the compiler may inline).
macro_rules! dispatch {
    ($panels:expr, $kind:expr, $p:ident => $call:expr) => {
        match $kind {
            PanelKind::Arm | PanelKind::ArmB => {
                let $p = &$panels.arm;
                $call
            }
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque | PanelKind::Velocity => {
                let $p = &$panels.time_plots;
                $call
            }
            PanelKind::Poles => {
                let $p = &$panels.pole_plot;
                $call
            }
            PanelKind::ZPlane => {
                let $p = &$panels.z_plane;
                $call
            }
            PanelKind::RhoCurve => {
                let $p = &$panels.rho_curve;
                $call
            }
            PanelKind::StudyError | PanelKind::StudyTorque => {
                let $p = &$panels.study;
                $call
            }
            PanelKind::MapOff | PanelKind::MapOn => {
                let $p = &$panels.maps;
                $call
            }
        }
    };
}

/// One kind of each panel type, in the order their keys are listed.
const ONE_OF_EACH: [PanelKind; 7] = [
    PanelKind::Arm,
    PanelKind::Error1,
    PanelKind::Poles,
    PanelKind::ZPlane,
    PanelKind::RhoCurve,
    PanelKind::StudyError,
    PanelKind::MapOff,
];

impl Panels {
    pub fn vertex_budget(&self, frame: &Frame, panel: &Panel) -> usize {
        dispatch!(self, panel.kind, p => p.vertex_budget(frame, panel))
    }

    pub fn draw_static(&self, frame: &Frame, panel: &Panel, painter: &mut Painter) {
        dispatch!(self, panel.kind, p => p.draw_static(frame, panel, painter))
    }

    pub fn draw(&mut self, frame: &Frame, runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        match panel.kind {
            PanelKind::Arm | PanelKind::ArmB => self.arm.draw(frame, runs, panel, painter),
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque | PanelKind::Velocity => {
                self.time_plots.draw(frame, runs, panel, painter)
            }
            PanelKind::Poles => self.pole_plot.draw(frame, runs, panel, painter),
            PanelKind::ZPlane => self.z_plane.draw(frame, runs, panel, painter),
            PanelKind::RhoCurve => self.rho_curve.draw(frame, runs, panel, painter),
            PanelKind::StudyError | PanelKind::StudyTorque => self.study.draw(frame, runs, panel, painter),
            PanelKind::MapOff | PanelKind::MapOn => self.maps.draw(frame, runs, panel, painter),
        }
    }

    pub fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        dispatch!(self, panel.kind, p => p.describe(frame, panel))
    }

    pub fn probe(&self, frame: &Frame, panel: &Panel, x: f64, y: f64, reach: f64) -> Option<Probe> {
        dispatch!(self, panel.kind, p => p.probe(frame, panel, x, y, reach))
    }

    pub fn pole_markers(&self, frame: &Frame, panel: &Panel) -> Option<Vec<PoleInfo>> {
        dispatch!(self, panel.kind, p => p.pole_markers(frame, panel))
    }

    pub fn figure_size(&self, kind: PanelKind) -> (f64, f64) {
        dispatch!(self, kind, p => p.figure_size(kind))
    }

    pub fn figure_title(&self, frame: &Frame, kinds: &[PanelKind]) -> String {
        kinds.first().map_or_else(String::new, |k| dispatch!(self, *k, p => p.figure_title(frame, kinds)))
    }

    /// Every panel type's key for the panels `kinds` shown, then the keys that carry this frame's
    /// numbers.
    pub fn legend(&self, frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        let mut groups = Vec::new();
        for k in ONE_OF_EACH {
            groups.extend(dispatch!(self, k, p => p.legend(frame, kinds)));
        }
        for k in ONE_OF_EACH {
            groups.extend(dispatch!(self, k, p => p.readings(frame)));
        }
        groups
    }
}
