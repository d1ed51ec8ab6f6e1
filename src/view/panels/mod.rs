//! Every panel of the figure, each in its own folder with everything about it — how it is drawn,
//! described for the page, read out under the pointer, keyed, titled as a figure — behind one
//! interface ([`contract::PanelView`]). The scene lays the panels out, keeps what they share
//! ([`contract::Frame`]) and asks them; it knows no panel's insides.
//!
//! | folder | panels |
//! |---|---|
//! | [`arm`] | the arm (run A's, and run B's when compared), the swing's shape |
//! | [`time_plots`] | e1, e2, the torques; log \|e\| and its split; the zoom on one instant (Fig. 2.1) |
//! | [`pole_plot`] | the loop's eigenvalues as s = ln λ/δ, with A4 |
//! | [`z_plane`] | the loop's eigenvalues λ against the unit circle |
//! | [`rho_curve`] | ρ(δ) at this α, with the stable windows |
//! | [`stability_maps`] | ρ over (δ, α) without and with the preliminary feedback |
//!
//! Architecture invariant: no panel imports another (`tests/architecture.rs`); what two share is
//! below them ([`crate::view::loop_poles`], [`crate::view::rho_readout`], …).

pub mod arm;
pub mod contract;
pub mod pole_plot;
pub mod rho_curve;
pub mod stability_maps;
pub mod time_plots;
pub mod z_plane;

use crate::schema::PanelKind;
use arm::Arm;
use contract::PanelView;
use pole_plot::PolePlot;
use rho_curve::RhoCurve;
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
    pub maps: StabilityMaps,
}

impl Panels {
    /// The panel type that draws `kind`.
    pub fn get(&self, kind: PanelKind) -> &dyn PanelView {
        match kind {
            PanelKind::Arm | PanelKind::ArmB => &self.arm,
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => &self.time_plots,
            PanelKind::Poles => &self.pole_plot,
            PanelKind::ZPlane => &self.z_plane,
            PanelKind::RhoCurve => &self.rho_curve,
            PanelKind::MapOff | PanelKind::MapOn => &self.maps,
        }
    }

    /// The same, to draw with.
    pub fn get_mut(&mut self, kind: PanelKind) -> &mut dyn PanelView {
        match kind {
            PanelKind::Arm | PanelKind::ArmB => &mut self.arm,
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => &mut self.time_plots,
            PanelKind::Poles => &mut self.pole_plot,
            PanelKind::ZPlane => &mut self.z_plane,
            PanelKind::RhoCurve => &mut self.rho_curve,
            PanelKind::MapOff | PanelKind::MapOn => &mut self.maps,
        }
    }

    /// Each panel type once, in the order their keys are listed.
    pub fn each(&self) -> [&dyn PanelView; 6] {
        [&self.arm, &self.time_plots, &self.pole_plot, &self.z_plane, &self.rho_curve, &self.maps]
    }
}
