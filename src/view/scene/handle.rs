//! The flexible pair as a handle on the pole plot: whether the pointer is on run A's δ → 0 pair
//! with its preliminary feedback (the diamond), and the s under the pointer as it drags. The
//! session places the pair there and the settings change ([`crate::session::Session::place_pair`]):
//! the handle holds no state of its own.

use super::Scene;
use crate::schema::PanelKind;
use crate::view::loop_poles::PoleKind;
use crate::view::panels::pole_plot::PolePlot;

impl Scene {
    /// True when run A's A4-with-K_pr marker (either of the pair, or its chevron at the edge when
    /// out of view) is within `reach` px of (x, y) on the s-plane pole plot (CSS px of the layout).
    pub fn pair_handle_at(&self, x: f64, y: f64, reach: f64) -> bool {
        if !self.frame.layout.panels.iter().any(|p| p.kind == PanelKind::Poles) {
            return false;
        }
        self.pole_info().iter().any(|p| {
            // Out of view it is the chevron at the plot's edge: still the handle.
            p.run == "A"
                && p.kind == PoleKind::A4
                && matches!((p.x, p.y), (Some(px), Some(py)) if (px - x).hypot(py - y) <= reach)
        })
    }

    /// Holds the pole plot's scale while the pair is dragged (`true`), or fits it again.
    pub fn hold_pole_plot(&mut self, hold: bool) {
        let panel = self.frame.layout.panels.iter().find(|p| p.kind == PanelKind::Poles).map(|p| p.rect);
        self.frame.pole_im_held = match (hold, panel) {
            (true, Some(rect)) => Some(PolePlot::frame(&self.frame, rect).im),
            _ => None,
        };
    }

    /// The s = (Re, Im) under (x, y) on the s-plane pole plot, beyond its edges too (a drag held
    /// past them); None without the pole plot.
    pub fn pole_plot_point(&self, x: f64, y: f64) -> Option<[f64; 2]> {
        let panel = self.frame.layout.panels.iter().find(|p| p.kind == PanelKind::Poles)?;
        Some(PolePlot::frame(&self.frame, panel.rect).s_at(x, y))
    }
}
