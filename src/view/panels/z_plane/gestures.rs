//! The z-plane's view: the page's zoom (`zsize`, `zre`, `zim`) or the default around run A's
//! flexible pair, and what the page's wheel, pinch, drag, buttons and keys make of it. The page
//! forwards the pointer's position and the gesture's size; the maths is here.

use super::drawing::{upper_flexible, ZFrame};
use super::view::ZView;
use crate::schema::PanelKind;
use crate::session::ViewSettings;
use crate::view::panels::contract::Frame;
use crate::view::rect::Rect;

/// The explicit view the view settings ask for, or None for the default.
pub fn z_view_of(v: &ViewSettings) -> Option<ZView> {
    (v.z_size > 0.0).then(|| ZView { center: v.z_center, half: v.z_size }.clamped())
}

/// The z-plane's data area, CSS px, if it is shown.
pub fn z_panel(frame: &Frame) -> Option<Rect> {
    frame.panel(PanelKind::ZPlane).map(|p| p.rect)
}

/// The view the z-plane shows: the page's, or around run A's flexible pair (see
/// [`ZView::around`]), sized by the panel's shorter side in CSS px.
pub fn z_view(frame: &Frame) -> ZView {
    if let Some(v) = frame.options.z_view {
        return v;
    }
    let short = z_panel(frame).map_or(0.0, |r| r.w.min(r.h));
    ZView::around(frame.runs[0].report.as_ref().and_then(upper_flexible), short)
}

/// The z-plane's frame on `rect` (the panel's rectangle, CSS or physical px).
pub fn z_frame(frame: &Frame, rect: Rect) -> ZFrame {
    ZFrame::new(rect, z_view(frame))
}

/// The view after zooming by `factor` (> 1 in) about (x, y) (CSS px), which keeps its λ under the
/// pointer; None if (x, y) is not on the z-plane.
pub fn zoom_z(frame: &Frame, x: f64, y: f64, factor: f64) -> Option<ZView> {
    let rect = z_panel(frame)?;
    let plane = z_frame(frame, rect);
    plane.contains([x, y]).then(|| plane.view.zoomed_about(plane.value_at([x, y]), factor))
}

/// The view after zooming by `factor` about the panel's centre (the buttons and keys).
pub fn zoom_z_center(frame: &Frame, factor: f64) -> Option<ZView> {
    z_panel(frame)?;
    let v = z_view(frame);
    Some(v.zoomed_about(v.center, factor))
}

/// The view after dragging the plane by (dx, dy) CSS px (the plane follows the pointer).
pub fn pan_z(frame: &Frame, dx: f64, dy: f64) -> Option<ZView> {
    let rect = z_panel(frame)?;
    let s = z_frame(frame, rect).scale();
    Some(z_view(frame).panned([-dx / s, dy / s]))
}
