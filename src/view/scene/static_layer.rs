//! The static layer: what changes only with a map, the stable windows or the layout — the maps'
//! cells and contours and ρ(δ)'s curve — rebuilt then and not every frame.

use super::Scene;
use crate::analysis::StableWindows;
use crate::view::layout::{Panel, PanelKind};
use crate::view::map::{draw_map_static, map_ticks, side_of, LogFrame};
use crate::view::rho_curve::{curve_range, draw_rho_static, lag_band, rho_ticks, turn_omega, RhoFrame};

impl Scene {
    pub(super) fn rebuild_static(&mut self) {
        self.static_painter.clear();
        let dpr = self.layout.device_pixel_ratio;
        let measure = self.options.measure;
        for panel in &self.layout.panels {
            if panel.kind == PanelKind::RhoCurve {
                let frame = self.rho_frame(panel, true);
                let (x_ticks, y_ticks) = rho_ticks(panel.rect, &frame);
                let ticks = (&x_ticks[..], &y_ticks[..]);
                let lag = lag_band(self.runs[0].config.as_ref(), self.runs[0].report.as_ref());
                let omega = turn_omega(self.runs[0].report.as_ref());
                let windows = self.windows.as_ref();
                draw_rho_static(&mut self.static_painter, &frame, windows, lag, omega, ticks, measure, dpr);
                continue;
            }
            let Some(side) = side_of(panel.kind) else { continue };
            let grid = &self.maps[side.index()];
            let frame = LogFrame {
                rect: self.layout.to_physical(panel.rect),
                x_range: grid.delta_range(),
                y_range: grid.alpha_range(),
            };
            let (x_ticks, y_ticks) = map_ticks(panel.rect, grid);
            draw_map_static(&mut self.static_painter, &frame, grid, (&x_ticks, &y_ticks), measure, dpr);
        }
        self.static_generation += 1;
    }

    /// The ρ(δ) panel's frame (ρ or ln ρ/δ, as the view's measure says), in physical pixels or
    /// (for descriptions) CSS pixels.
    pub(super) fn rho_frame(&self, panel: &Panel, physical: bool) -> RhoFrame {
        let rect = if physical { self.layout.to_physical(panel.rect) } else { panel.rect };
        let x_range = self.windows.as_ref().map_or(crate::schema::DELTA_SPEC.control, |w| w.range);
        RhoFrame { rect, x_range, y_range: curve_range(self.windows.as_ref(), self.options.measure) }
    }

    /// Takes run A's stable windows, rebuilding ρ(δ) when they changed.
    pub(super) fn update_windows(&mut self, windows: Option<&StableWindows>) {
        if self.windows.as_ref() == windows {
            return;
        }
        match (&mut self.windows, windows) {
            (Some(mine), Some(w)) => mine.clone_from(w),
            (mine, w) => *mine = w.cloned(),
        }
        self.rebuild_static();
        self.info_generation += 1;
    }
}
