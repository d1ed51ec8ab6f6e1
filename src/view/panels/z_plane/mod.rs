//! The z-plane: the sampled loop's eigenvalues λ themselves against the unit circle, the picture
//! that decides stability (ρ = max |λ| < 1), with the δ → 0 pair where it would sit for this δ,
//! λ = exp(A4 δ) ([`drawing`]); a window on the plane the page zooms and pans ([`view`],
//! [`gestures`]), cut to the panel ([`clip`]). What it shares with the s-plane pole plot is
//! [`crate::view::loop_poles`].

pub mod clip;
pub mod drawing;
pub mod gestures;
pub mod view;

use drawing::{
    draw_radial_tick, draw_zplane_background, draw_zplane_run, gap_text, label_fits, marker_css, upper_flexible,
    z_ticks, BACKGROUND_VERTEX_BUDGET, RUN_VERTEX_BUDGET,
};
use gestures::z_frame;
use view::WHOLE_HALF;

use crate::plot::palette;
use crate::schema::PanelKind;
use crate::view::layout::{margins, Panel};
use crate::view::legend::LegendGroup;
use crate::view::loop_poles::readout::flexible_mark;
use crate::view::loop_poles::{legend_group, PoleInfo, PoleStyle};
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe, Region, TickLabel};
use crate::view::panels::contract::{Frame, PanelView, Runs};
use crate::view::text_metrics::{font, text_width, LINE_HEIGHT};
use crate::view::tick_labels::{linear_labels, offset_labels};

/// The z-plane ([`PanelKind::ZPlane`]).
#[derive(Clone, Debug, Default)]
pub struct ZPlane;

impl PanelView for ZPlane {
    /// Landscape, as a slide is: both axes keep one scale, so the wider side shows more of Re λ.
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (660.0, 360.0)
    }

    fn vertex_budget(&self, frame: &Frame, _panel: &Panel) -> usize {
        BACKGROUND_VERTEX_BUDGET + 24 + frame.run_count() * RUN_VERTEX_BUDGET
    }

    fn draw(&mut self, frame: &Frame, _runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let dpr = frame.layout.device_pixel_ratio;
        let plane = z_frame(frame, frame.layout.to_physical(panel.rect));
        let ticks = z_ticks(panel.rect, plane.view);
        draw_zplane_background(painter, &plane, ticks, dpr);
        // How far run A's flexible pair is from the circle: the mark names it, this shows it.
        if let Some(z) = frame.runs[0].report.as_ref().and_then(upper_flexible) {
            draw_radial_tick(painter, &plane, z, dpr);
        }
        for run in (0..frame.run_count()).rev() {
            if let Some(report) = &frame.runs[run].report {
                draw_zplane_run(painter, &plane, report, &PoleStyle::of_run(run), dpr);
            }
        }
        painter.rect_outline(plane.rect, dpr.max(1.0), palette::FRAME);
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        let plane = z_frame(frame, r);
        let (x_range, y_range) = plane.ranges();
        let (x_ticks, y_ticks) = z_ticks(r, plane.view);
        info.x_label = "Re λ".into();
        info.y_label = "Im λ";
        info.x_range = x_range;
        info.y_range = y_range;
        info.x_ticks = x_ticks.collect();
        info.y_ticks = y_ticks.collect();
        info.note = "eigenvalues λ; outside |λ| = 1: grows".into();
        let zoom = WHOLE_HALF / plane.view.half;
        if zoom > 1.05 {
            info.note += &format!("; zoomed ×{}", crate::plot::format::significant_trimmed(zoom, 2));
        }
        let poles = self.pole_markers(frame, panel).unwrap_or_default();
        info.marks = flexible_mark(&poles, r.w, Some(gap_text));
        // Only labels within the panel's sides (the grid lines stay).
        let fits_x = |t: &TickLabel| label_fits(t.value, x_range, r.w, text_width(&t.text, font::TICK));
        let fits_y = |t: &TickLabel| label_fits(t.value, y_range, r.h, font::TICK * LINE_HEIGHT);
        info.x_labels = linear_labels(&info.x_ticks).into_iter().filter(fits_x).collect();
        let y_labels = linear_labels(&info.y_ticks);
        // Labels wider than the gutter (0.70705 at the closest zoom) count steps from a tick in
        // the middle instead, which the title names.
        let room = margins::ANALYSIS_LEFT - 4.0;
        let wide = y_labels.iter().any(|t| text_width(&t.text, font::TICK) > room);
        let title_room = r.w + margins::ANALYSIS_LEFT;
        info.y_labels = match (wide, offset_labels(&info.y_ticks, title_room)) {
            (true, Some((labels, base))) => {
                info.note = format!("{base}; {}", info.note);
                labels
            }
            (true, None) => Vec::new(),
            _ => y_labels,
        };
        info.y_labels.retain(fits_y);
        // No x label fits the panel's sides: every tick keeps its label rather than none.
        if info.x_labels.is_empty() {
            info.x_labels = linear_labels(&info.x_ticks);
        }
        info.region = Some(Region {
            label: "The loop’s eigenvalues λ and the unit circle. Arrow keys step from one to the next and read it; \
                    plus and minus zoom, 0 shows the whole circle, P the flexible pair, Shift with the arrows pans.",
            keys: "zplane",
            map: None,
        });
        info
    }

    fn pole_markers(&self, frame: &Frame, panel: &Panel) -> Option<Vec<PoleInfo>> {
        let plane = z_frame(frame, panel.rect);
        let place = |_: [f64; 2], lambda: [f64; 2]| {
            let (p, in_view) = marker_css(&plane, lambda);
            (Some(p), in_view)
        };
        Some(frame.pole_markers(&place))
    }

    fn probe(&self, frame: &Frame, panel: &Panel, x: f64, y: f64, reach: f64) -> Option<Probe> {
        let poles = self.pole_markers(frame, panel)?;
        frame.probe_poles(&poles, panel, true, x, y, reach)
    }

    fn legend(&self, frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        if kinds.contains(&PanelKind::ZPlane) {
            vec![legend_group(true, frame.pair)]
        } else {
            Vec::new()
        }
    }

    fn figure_title(&self, _frame: &Frame, _kinds: &[PanelKind]) -> String {
        "Eigenvalues λ of the sampled loop (z-plane)".into()
    }
}
