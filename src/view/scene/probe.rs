//! What lies under the pointer, described for a tooltip by the panel it lies on (the nearest pole
//! of the pole plot or z-plane, the point of a stability map and what a click there runs, the δ
//! of ρ(δ)), and the (δ, α) a click on a map runs.

use super::Scene;
use crate::session::MapSide;
use crate::view::panel_info::Probe;

impl Scene {
    /// What lies at (x, y) (CSS pixels in the canvas): the nearest pole within `reach` pixels,
    /// else the point of a map or of ρ(δ) under the pointer; `None` elsewhere.
    pub fn probe(&self, x: f64, y: f64, reach: f64) -> Option<Probe> {
        let frame = &self.frame;
        frame.layout.panels.iter().find_map(|p| self.panels.probe(frame, p, x, y, reach))
    }

    /// The map and (δ, α) at (x, y), if (x, y) lies on a map.
    pub fn map_point(&self, x: f64, y: f64) -> Option<(MapSide, f64, f64)> {
        self.panels.maps.point_at(&self.frame, x, y)
    }
}
