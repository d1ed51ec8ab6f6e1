//! The z-plane's view in the scene: the page's zoom (`zsize`, `zre`, `zim`) or the default around
//! run A's flexible pair, and what the page's wheel, pinch, drag, buttons and keys make of it.
//! The page forwards the pointer's position and the gesture's size; the maths is here.

use super::Scene;
use crate::session::ViewSettings;
use crate::view::layout::{PanelKind, Rect};
use crate::view::zplane::{upper_flexible, ZFrame, ZView};

/// The explicit view the view settings ask for, or None for the default.
pub(super) fn z_view_of(v: &ViewSettings) -> Option<ZView> {
    (v.z_size > 0.0).then(|| ZView { center: v.z_center, half: v.z_size }.clamped())
}

impl Scene {
    /// The z-plane's data area, CSS px, if it is shown.
    pub fn z_panel(&self) -> Option<Rect> {
        self.layout.panel(PanelKind::ZPlane).map(|p| p.rect)
    }

    /// The view the z-plane shows: the page's, or around run A's flexible pair (see
    /// [`ZView::around`]), sized by the panel's shorter side in CSS px.
    pub fn z_view(&self) -> ZView {
        if let Some(v) = self.options.z_view {
            return v;
        }
        let short = self.z_panel().map_or(0.0, |r| r.w.min(r.h));
        ZView::around(self.runs[0].report.as_ref().and_then(upper_flexible), short)
    }

    /// Shows `view` (None: the default) at once, before the session's settings reach the next
    /// frame: gestures faster than frames (a pinch zooms and pans in one event) build on it.
    pub fn set_z_view(&mut self, view: Option<ZView>) {
        if self.options.z_view != view {
            self.options.z_view = view;
            self.info_generation += 1;
        }
    }

    /// The z-plane's frame on `rect` (the panel's rectangle, CSS or physical px).
    pub(super) fn z_frame(&self, rect: Rect) -> ZFrame {
        ZFrame::new(rect, self.z_view())
    }

    /// The view after zooming by `factor` (> 1 in) about (x, y) (CSS px), which keeps its λ under
    /// the pointer; None if (x, y) is not on the z-plane.
    pub fn zoom_z(&self, x: f64, y: f64, factor: f64) -> Option<ZView> {
        let rect = self.z_panel()?;
        let frame = self.z_frame(rect);
        frame.contains([x, y]).then(|| frame.view.zoomed_about(frame.value_at([x, y]), factor))
    }

    /// The view after zooming by `factor` about the panel's centre (the buttons and keys).
    pub fn zoom_z_center(&self, factor: f64) -> Option<ZView> {
        self.z_panel()?;
        let v = self.z_view();
        Some(v.zoomed_about(v.center, factor))
    }

    /// The view after dragging the plane by (dx, dy) CSS px (the plane follows the pointer).
    pub fn pan_z(&self, dx: f64, dy: f64) -> Option<ZView> {
        let rect = self.z_panel()?;
        let s = self.z_frame(rect).scale();
        Some(self.z_view().panned([-dx / s, dy / s]))
    }
}
