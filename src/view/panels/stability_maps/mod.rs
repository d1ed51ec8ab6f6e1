//! The two stability maps, ρ over (δ, α) without and with the preliminary feedback: the cells
//! and the ρ = 1 contour in the static layer ([`grid`]), the runs' (δ, α) and run A's stable
//! windows of δ marked every frame, and what lies under the pointer (a click runs there). The maps
//! keep their grids between frames, copied from the session's map jobs as rows arrive.

pub mod grid;

use grid::{
    draw_map_marker, draw_map_static, map_ticks, side_of, LogFrame, MapSide, StabilityGrid, MARKER_VERTEX_BUDGET,
};

use crate::analysis::MapRows;
use crate::control::config::PreliminaryFeedbackChoice;
use crate::plot::{format, palette, Color};
use crate::schema::PanelKind;
use crate::view::layout::Panel;
use crate::view::legend::{item, map_scale, Glyph, LegendGroup};
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe, Region, TipLine};
use crate::view::panels::contract::{Frame, PanelView, Runs};
use crate::view::rho_readout::stability_lines;
use crate::view::tick_labels::log_labels;
use crate::words::settings::{design_point, map_caption, point as point_text, with_feedback};

/// What the rows of a side's map are, given run A's feedback (α, or k_d on the design map).
fn rows_of(frame: &Frame, side: MapSide) -> MapRows {
    side.rows(frame.runs[0].config.map(|c| c.preliminary_feedback).unwrap_or_default())
}

/// A configuration's place along a map's rows: its α, or its twist damping on the design map.
fn row_value(config: &crate::control::config::SimulationConfig, rows: MapRows) -> f64 {
    match rows {
        MapRows::Alpha => config.controller.alpha[0],
        MapRows::TwistDamping => config.twist.damping,
    }
}

/// Least distance between log-axis labels, CSS px (x: a label's width, y: its height).
const LOG_LABEL_SPACING: [f64; 2] = [38.0, 17.0];

/// The maps ([`PanelKind::MapOff`], [`PanelKind::MapOn`]) and their grids.
#[derive(Clone, Debug, Default)]
pub struct StabilityMaps {
    /// Without ([`MapSide::Off`]) and with ([`MapSide::On`]) preliminary feedback.
    grids: [StabilityGrid; 2],
    /// Which session map (and how many rows of it) each grid holds.
    sources: [Option<(u64, usize)>; 2],
}

impl StabilityMaps {
    /// The map of one side.
    pub fn grid(&self, side: MapSide) -> &StabilityGrid {
        &self.grids[side.index()]
    }

    /// Takes a (possibly partial) map: `rho` row-major by α for the first rows.
    pub fn set(&mut self, side: MapSide, deltas: &[f64], alphas: &[f64], rho: &[f64]) -> Result<(), String> {
        self.grids[side.index()].set(deltas, alphas, rho)?;
        self.sources[side.index()] = None;
        Ok(())
    }

    /// Takes the rows of a session map (`source`: its generation and rows) unless the grid has
    /// them already; true if it took them.
    pub fn follow(&mut self, side: MapSide, source: (u64, usize), deltas: &[f64], alphas: &[f64], rho: &[f64]) -> bool {
        if self.sources[side.index()] == Some(source) {
            return false;
        }
        if self.grids[side.index()].set(deltas, alphas, rho).is_ok() {
            self.sources[side.index()] = Some(source);
            return true;
        }
        false
    }

    /// Forgets both maps.
    pub fn clear(&mut self) {
        for g in &mut self.grids {
            g.clear();
        }
        self.sources = [None; 2];
    }

    /// The map and (δ, α) at (x, y) (CSS px), if (x, y) lies on a map of the layout.
    pub fn point_at(&self, frame: &Frame, x: f64, y: f64) -> Option<(MapSide, f64, f64)> {
        let panel = frame
            .layout
            .panels
            .iter()
            .find(|p| side_of(p.kind).is_some() && p.rect.w > 0.0 && p.rect.h > 0.0 && p.contains(x, y))?;
        let side = side_of(panel.kind)?;
        let grid = &self.grids[side.index()];
        let r = panel.rect;
        let fx = ((x - r.x) / r.w).clamp(0.0, 1.0);
        let fy = (1.0 - (y - r.y) / r.h).clamp(0.0, 1.0);
        let along = |f: f64, [lo, hi]: [f64; 2]| lo * (hi / lo).powf(f);
        Some((side, along(fx, grid.delta_range()), along(fy, grid.alpha_range())))
    }

    fn log_frame(&self, frame: &Frame, panel: &Panel, side: MapSide) -> LogFrame {
        let grid = &self.grids[side.index()];
        LogFrame {
            rect: frame.layout.to_physical(panel.rect),
            x_range: grid.delta_range(),
            y_range: grid.alpha_range(),
        }
    }
}

impl PanelView for StabilityMaps {
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (440.0, 330.0)
    }

    fn vertex_budget(&self, frame: &Frame, _panel: &Panel) -> usize {
        24 + 2 * 6 * 8 + frame.run_count() * MARKER_VERTEX_BUDGET
    }

    fn draw_static(&self, frame: &Frame, panel: &Panel, painter: &mut Painter) {
        let Some(side) = side_of(panel.kind) else { return };
        let grid = &self.grids[side.index()];
        let map = self.log_frame(frame, panel, side);
        let (x_ticks, y_ticks) = map_ticks(panel.rect, grid);
        let dpr = frame.layout.device_pixel_ratio;
        draw_map_static(painter, &map, grid, (&x_ticks, &y_ticks), frame.options.measure, dpr);
    }

    fn draw(&mut self, frame: &Frame, _runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let Some(side) = side_of(panel.kind) else { return };
        let dpr = frame.layout.device_pixel_ratio;
        let map = self.log_frame(frame, panel, side);
        let rows = rows_of(frame, side);
        // The design map's boundaries: between k_d* = 3β Ir1 − Bv1 and the damping at which the
        // motor stops swinging (det A4 = 0) the δ → 0 pair is damped.
        if let (MapRows::TwistDamping, Some(config), Some(report)) =
            (rows, &frame.runs[0].config, &frame.runs[0].report)
        {
            let window = crate::analysis::design::DampingWindow::of(
                &config.plant,
                config.controller.alpha,
                report.rest[1],
                config.twist.stiffness,
            );
            for bound in [Some(window.lower), window.upper].into_iter().flatten().filter(|b| *b > 0.0) {
                let y = map.y_log(bound.ln());
                if y >= map.rect.y && y <= map.rect.bottom() {
                    let (a, b) = ([map.rect.x, y], [map.rect.right(), y]);
                    painter.line(a, b, 4.0 * dpr, palette::MARKER_HALO);
                    painter.dashed_line(a, b, 2.0 * dpr, 7.0 * dpr, 4.0 * dpr, palette::A4_FEEDBACK);
                }
            }
        }
        // Run A's stable windows of δ at its α (or k_d), on the map of its feedback.
        if let (Some(config), Some(windows)) = (&frame.runs[0].config, &frame.windows) {
            if MapSide::for_feedback(config.preliminary_feedback) == side {
                let y = map.y_log(row_value(config, rows).ln());
                if y >= map.rect.y && y <= map.rect.bottom() {
                    for [lo, hi] in &windows.windows {
                        let (x0, x1) = (map.x_log(lo.ln()), map.x_log(hi.ln()));
                        let (x0, x1) = (x0.max(map.rect.x), x1.min(map.rect.right()));
                        if x1 > x0 {
                            painter.line([x0, y], [x1, y], 7.0 * dpr, palette::MARKER_HALO);
                            painter.line([x0, y], [x1, y], 3.5 * dpr, palette::WINDOW_MARK);
                        }
                    }
                }
            }
        }
        for run in (0..frame.run_count()).rev() {
            let Some(config) = &frame.runs[run].config else { continue };
            let filled = MapSide::for_feedback(config.preliminary_feedback) == side;
            let color: Color = if run == 0 { palette::MAP_MARKER } else { palette::RUN_B };
            let delta = config.controller.sampling_period;
            draw_map_marker(painter, &map, delta, row_value(config, rows), filled, color, dpr);
        }
        painter.rect_outline(map.rect, dpr.max(1.0), palette::FRAME);
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        let side = side_of(panel.kind).unwrap_or(MapSide::Off);
        let grid = &self.grids[side.index()];
        let (x_ticks, y_ticks) = map_ticks(r, grid);
        let rows = rows_of(frame, side);
        info.x_label = "δ [s]".into();
        info.y_label = match rows {
            MapRows::Alpha => "α [1/s]",
            MapRows::TwistDamping => "k_d [N m s/rad]",
        };
        info.x_range = grid.delta_range();
        info.y_range = grid.alpha_range();
        info.x_labels = log_labels(&x_ticks, info.x_range, r.w, LOG_LABEL_SPACING[0]);
        info.y_labels = log_labels(&y_ticks, info.y_range, r.h, LOG_LABEL_SPACING[1]);
        info.x_ticks = x_ticks;
        info.y_ticks = y_ticks;
        info.x_scale = "log";
        info.y_scale = "log";
        let pf = frame.runs[0].config.map(|c| c.preliminary_feedback).unwrap_or_default();
        info.note = map_caption(side, pf, frame.options.measure);
        // The map with K_pr depends on how it acts: say so when it is held over δ.
        let sampled = frame.runs[0].config.is_some_and(|c| c.inner_loop == crate::control::config::InnerLoop::Sampled);
        if side == MapSide::On && sampled {
            info.note += ", sampled";
        }
        info.region = Some(Region {
            label: match (side, rows) {
                (MapSide::On, MapRows::TwistDamping) => {
                    "Design map: ρ over δ and your twist damping k_d at this α. Arrow keys move the running point: \
                     left and right change δ, up and down k_d; Enter runs there."
                }
                (MapSide::Off, _) => {
                    "Stability map without K_pr. Arrow keys move the running point: left and right change δ, up and \
                     down α; Enter runs without K_pr."
                }
                (MapSide::On, MapRows::Alpha) => {
                    "Stability map with K_pr. Arrow keys move the running point: left and right change δ, up and down \
                     α; Enter runs with K_pr."
                }
            },
            keys: "map",
            map: Some(side),
        });
        info
    }

    fn probe(&self, frame: &Frame, panel: &Panel, x: f64, y: f64, _reach: f64) -> Option<Probe> {
        if !(panel.rect.w > 0.0 && panel.rect.h > 0.0 && panel.contains(x, y)) {
            return None;
        }
        let (side, delta, alpha) = self.point_at(frame, x, y)?;
        let rows = rows_of(frame, side);
        let (cell_delta, rho) = self.grids[side.index()].near(delta, alpha);
        let spec = |p: &crate::schema::Param| *p.number().expect("δ, α and k_d are numbers");
        let d = spec(&crate::schema::DELTA).snap(delta);
        let pf = frame.runs[0].config.map(|c| c.preliminary_feedback).unwrap_or_default();
        let mut lines = vec![];
        match rows {
            MapRows::Alpha => lines.push(TipLine::plain(point_text(delta, alpha))),
            MapRows::TwistDamping => lines.push(TipLine::plain(design_point(delta, alpha))),
        }
        stability_lines(rho, cell_delta, &mut lines);
        // Where the paper's gains stop damping the resonance, the map says why it turns red.
        let limit = frame.runs[0].report.as_ref().map(|r| r.resonance.paper_alpha_limit);
        if let (PreliminaryFeedbackChoice::Paper, Some(limit), MapRows::Alpha) = (side.feedback(pf), limit, rows) {
            if alpha > limit {
                lines.push(TipLine::plain(format!(
                    "above α = {} 1/s the paper's K_pr leaves the δ → 0 pair unstable: at this α the smallest δ fail; its \
                     shift of Re A4 is the same at every α, while the controller's feed 3α/2 grows",
                    format::significant(limit, 3)
                )));
            }
        }
        // What a click runs: the point rounded as the controls round it (the session snaps the
        // same way), beside the map cell's ρ above.
        lines.push(TipLine::plain(match rows {
            MapRows::Alpha => format!(
                "click to run at δ = {} s, α = {} 1/s",
                crate::schema::format_number(d),
                crate::schema::format_number(spec(&crate::schema::ALPHA).snap(alpha))
            ),
            MapRows::TwistDamping => format!(
                "click to run at δ = {} s, k_d = {} N m s/rad",
                crate::schema::format_number(d),
                crate::schema::format_number(spec(&crate::schema::TWIST_DAMPING).snap(alpha))
            ),
        }));
        let title = with_feedback(side.feedback(pf));
        Some(Probe { kind: "map", title, lines, x, y, map: Some(side), delta: Some(delta), alpha: Some(alpha) })
    }

    fn legend(&self, frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        if !kinds.iter().any(|k| k.is_map()) {
            return Vec::new();
        }
        let rate = frame.options.measure == crate::plot::color::Measure::Rate;
        let mut items = vec![
            item(
                Glyph::Line,
                palette::CONTOUR,
                if rate { "ln ρ/δ = 0 (ρ = 1): the edge of stability" } else { "ρ = 1: the edge of stability" },
            ),
            item(Glyph::Ring, palette::MAP_MARKER, "the (δ, α) running now"),
            item(Glyph::Line, palette::WINDOW_MARK, "the stable windows of δ at this α"),
        ];
        if frame.pair {
            items.push(item(Glyph::Ring, palette::RUN_B, "run B's (δ, α)"));
        }
        if kinds.iter().any(|&k| side_of(k).is_some_and(|s| rows_of(frame, s) == MapRows::TwistDamping)) {
            items.push(item(
                Glyph::Dashed,
                palette::A4_FEEDBACK,
                "design map: the δ → 0 pair is stable between the dashed lines, k_d = 3α I_r1 − B_v1 and where det A4 = 0 \
                 (a slow real mode grows above it; the motor stops swinging well before, still stable)",
            ));
        }
        vec![LegendGroup { title: "stability maps", items, scale: Some(map_scale(frame.options.measure)) }]
    }

    fn figure_title(&self, frame: &Frame, _kinds: &[PanelKind]) -> String {
        format!("{} of the sampled loop over (δ, α)", frame.options.measure.quantity())
    }
}
