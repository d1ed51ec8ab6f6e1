//! One frame of the page's picture, built from a session (one run or two side by side): the
//! layout, the autoscales that persist between frames, the stability maps, and the painters that
//! collect the triangles. [`info`] describes the frame for the page's HTML labels and tooltips.
//!
//! [`Scene`] is everything the renderer needs except the GPU. It keeps two triangle lists: the
//! *static* layer ([`Scene::static_vertices`]: the stability maps' cells and contours, rebuilt
//! only when a map or the layout changes, with [`Scene::static_generation`] counting rebuilds)
//! and the per-frame layer ([`Scene::vertices`]: everything else, drawn over the static layer).
//! The analyses come with the runs (the session computes them once per change); the scene keeps
//! a copy of the latest for its descriptions, updated only when it changes.

pub mod compare;
mod cycle;
mod draw;
pub mod info;
mod page;
mod plots;
mod probe;
mod sources;
mod split;
mod static_layer;
mod swing;
mod zplane;

use plots::{plot_series, plot_tick_counts, plot_ticks, pole_tick_counts, pole_ticks, y_label};

use super::arm::VERTEX_BUDGET as ARM_VERTEX_BUDGET;
use super::autoscale::{Autoscale, AutoscaleSettings};
use super::layout::{Layout, Panel, PanelKind, Tab};
use super::map::{StabilityGrid, MARKER_VERTEX_BUDGET};
use super::painter::{Painter, Vertex};
use super::poles::{PoleStyle, RUN_VERTEX_BUDGET as POLE_RUN_VERTEX_BUDGET};
use super::rho_curve::MARKER_VERTEX_BUDGET as RHO_MARKER_VERTEX_BUDGET;
use super::traces::{vertex_budget, TimeWindow};
use super::zplane::{
    BACKGROUND_VERTEX_BUDGET as ZPLANE_BACKGROUND_BUDGET, RUN_VERTEX_BUDGET as ZPLANE_RUN_VERTEX_BUDGET,
};
use crate::analysis::{StabilityReport, StableWindows};
use crate::control::config::SimulationConfig;
use crate::control::predictive::Sweep;
use crate::control::{Cycle, History, Snapshot, Traces};
use crate::model::reference::Reference;
use crate::plot::{palette, Color};
use crate::session::{MapSide, ViewSettings};

pub use super::options::{OptionsUpdate, ViewOptions, MAX_SPRING_MAGNIFICATION, MAX_TIME_WINDOW};
pub use super::panel_info::{Mark, PanelInfo, TickLabel};
pub use info::SeriesInfo;
pub use probe::{Probe, TipLine};
pub use swing::{SwingShape, SWING_SLOWDOWN};

/// The state of one run that the scene draws.
#[derive(Clone, Copy, Debug)]
pub struct RunState<'a> {
    pub snapshot: &'a Snapshot,
    pub traces: &'a Traces,
    /// Shades the intervals where the reference moves (run A's only).
    pub reference: Option<&'a Reference>,
    /// The configuration in force: its (δ, α1) gives the map markers. None draws no markers.
    pub config: Option<&'a SimulationConfig>,
    /// The linear analysis of the run's settings: the pole plot. None draws no poles.
    pub analysis: Option<&'a StabilityReport>,
    /// The stable windows of δ at the run's α: ρ(δ) and the marks on the map (run A's only).
    pub windows: Option<&'a StableWindows>,
    /// The previous run's traces, drawn faint in the error plots (run A's only).
    pub ghost: Option<&'a Traces>,
    /// The loop's kept states at its sampling instants: the split of log |e| and the zoom on one
    /// instant (run A's only).
    pub history: Option<&'a History>,
    /// The controller's newest prediction whole (Fig. 2.1), if the loop keeps it.
    pub sweep: Option<&'a Sweep>,
}

impl<'a> RunState<'a> {
    /// A run's state and traces alone: no reference, configuration, analysis, windows, ghost or
    /// history (each may be set after).
    pub fn bare(snapshot: &'a Snapshot, traces: &'a Traces) -> Self {
        Self {
            snapshot,
            traces,
            reference: None,
            config: None,
            analysis: None,
            windows: None,
            ghost: None,
            history: None,
            sweep: None,
        }
    }
}

/// What the scene remembers of a run between frames, for its descriptions.
#[derive(Clone, Debug, Default, PartialEq)]
struct RunMemory {
    config: Option<SimulationConfig>,
    report: Option<StabilityReport>,
}

impl RunMemory {
    /// Takes the run's configuration and analysis, copying only what changed; true if anything did.
    fn update(&mut self, config: Option<&SimulationConfig>, report: Option<&StabilityReport>) -> bool {
        let mut changed = false;
        if self.config.as_ref() != config {
            self.config = config.copied();
            changed = true;
        }
        if self.report.as_ref() != report {
            match (&mut self.report, report) {
                (Some(mine), Some(r)) => mine.clone_from(r),
                (mine, r) => *mine = r.cloned(),
            }
            changed = true;
        }
        changed
    }
}

/// Plot curve widths, CSS pixels: run A, and run B drawn a little thinner over it.
const CURVE_WIDTH: f64 = 1.75;
const CURVE_WIDTH_B: f64 = 1.5;
/// Decades a log |e| plot spans below its top.
const LOG_DECADES: i32 = 6;
/// Vertices of one dashed predicted-slope line at most (512 dashes).
const DASHED_LINE_BUDGET: usize = 512 * 6;

/// Run names, as the page sees them.
const RUN_NAMES: [&str; 2] = ["A", "B"];

/// The picture: layout, persistent autoscales, the latest analyses and maps, the triangle lists.
#[derive(Clone, Debug)]
pub struct Scene {
    options: ViewOptions,
    /// Two runs side by side (set by the latest draw).
    pair: bool,
    layout: Layout,
    painter: Painter,
    /// The stability maps' cells and contours: rebuilt only when they or the layout change.
    static_painter: Painter,
    static_generation: u64,
    scale_e1: Autoscale,
    scale_e2: Autoscale,
    scale_torque: Autoscale,
    /// Simulated time of the latest frame, s (the later of the two runs').
    time: f64,
    /// The instant looked back at (a vertical line in the time plots), or None.
    cursor: Option<f64>,
    /// Run A's and B's configuration and analysis as of the latest frame.
    runs: [RunMemory; 2],
    /// The maps without ([`MapSide::Off`]) and with ([`MapSide::On`]) preliminary feedback.
    maps: [StabilityGrid; 2],
    /// Which session map (and how many rows of it) each grid holds.
    map_sources: [Option<(u64, usize)>; 2],
    /// Run A's stable windows of δ as of the latest frame (ρ(δ) and the marks on the maps).
    windows: Option<StableWindows>,
    /// Increases whenever [`Scene::panel_info`] would describe the frame differently.
    info_generation: u64,
    info_signature: [f64; 6],
    /// Run A's errors split into the swing and the rest (log |e|), kept between frames.
    split: split::SplitBuffers,
    /// The zoom on one sampling instant (Fig. 2.1), kept between frames, and its scales (e1, e2,
    /// torque).
    cycle: Cycle,
    zoom_scales: [Autoscale; 3],
    /// Wall-clock seconds of the latest frame (the swing's animation).
    clock: f64,
    /// The canvas as the page has it: CSS width and height, device-pixel ratio; and the screen's
    /// height (CSS px), which presentation mode's text size follows.
    page: [f64; 3],
    screen_height: f64,
    /// Page CSS px per layout px: the text scale ([`crate::view::text_size::text_scale`]).
    scale: f64,
    /// The error plots are log |e| because the compared runs differ by a decade ([`compare`]).
    auto_log: bool,
}

impl Scene {
    /// A scene for a canvas of the given CSS size and device-pixel ratio.
    pub fn new(options: ViewOptions, css_width: f64, css_height: f64, device_pixel_ratio: f64) -> Self {
        let mut scene = Self {
            layout: Layout::compute(css_width, css_height, device_pixel_ratio, &options.layout_options(false)),
            page: [css_width, css_height, device_pixel_ratio],
            screen_height: f64::NAN,
            scale: 1.0,
            auto_log: false,
            options,
            pair: false,
            painter: Painter::new(),
            static_painter: Painter::new(),
            static_generation: 0,
            scale_e1: Autoscale::new(AutoscaleSettings::ERROR),
            scale_e2: Autoscale::new(AutoscaleSettings::ERROR),
            scale_torque: Autoscale::new(AutoscaleSettings::TORQUE),
            time: 0.0,
            cursor: None,
            runs: Default::default(),
            maps: Default::default(),
            map_sources: [None; 2],
            windows: None,
            info_generation: 0,
            info_signature: [f64::NAN; 6],
            split: Default::default(),
            cycle: Cycle::new(),
            clock: 0.0,
            zoom_scales: [
                Autoscale::new(AutoscaleSettings::ERROR),
                Autoscale::new(AutoscaleSettings::ERROR),
                Autoscale::new(AutoscaleSettings::TORQUE),
            ],
        };
        scene.relayout();
        scene
    }

    pub fn options(&self) -> &ViewOptions {
        &self.options
    }

    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The panels the view asks for that this layout does not show (on a narrow canvas, those
    /// of the other tabs): an embed announces them rather than dropping them silently.
    pub fn hidden_panels(&self) -> Vec<PanelKind> {
        self.layout.hidden(&self.options.layout_options(self.pair))
    }

    /// True if the latest frame compared two runs.
    pub fn is_pair(&self) -> bool {
        self.pair
    }

    /// Validates and applies a partial options update (re-laying out if panels change).
    pub fn set_options(&mut self, update: &OptionsUpdate) -> Result<(), String> {
        self.options.apply(update)?;
        self.relayout();
        Ok(())
    }

    /// Shows what the session's view settings say (the intro: the arm and the errors only),
    /// re-laying out only when that changes.
    pub fn follow_view(&mut self, view: &ViewSettings) {
        let v = view.shown();
        let next = ViewOptions {
            show_arm: v.picture,
            show_errors: v.errors,
            exact_panels: v.embed,
            show_poles: v.poles,
            z_plane: v.z_plane,
            show_rho: v.rho,
            show_map: v.map,
            measure: v.measure,
            show_torque: v.torque,
            log_errors: v.log,
            show_cycle: v.predict,
            show_swing: v.swing,
            tab: Tab::from_id(v.tab).unwrap_or_default(),
            hide_prediction: v.answers_hidden,
            z_view: zplane::z_view_of(&v),
            text: crate::view::text_size::TextSize::from_name(v.text),
            present: v.present,
            time_window: if v.window.is_finite() && v.window > 0.0 {
                v.window.min(MAX_TIME_WINDOW)
            } else {
                self.options.time_window
            },
            ..self.options
        };
        if next != self.options {
            // Zooming the z-plane changes its drawing and description, not the layout.
            let zoom_only = ViewOptions { z_view: self.options.z_view, ..next } == self.options;
            self.options = next;
            if zoom_only {
                self.info_generation += 1;
            } else {
                self.relayout();
            }
        }
    }

    /// Lays the panels out for a new canvas size.
    pub fn resize(&mut self, css_width: f64, css_height: f64, device_pixel_ratio: f64) {
        self.page = [css_width, css_height, device_pixel_ratio];
        self.relayout();
    }

    /// Lays out again, reserves room for the largest frame this layout can produce (so that
    /// drawing never reallocates) and rebuilds the static layer. Only a new size or a new set of
    /// panels gets here; drawing a frame never does. The panels are laid out for the canvas
    /// divided by the text scale and drawn that much larger (see [`crate::view::text_size`]).
    pub(super) fn relayout(&mut self) {
        let [w, h, dpr] = self.page;
        let screen = if self.screen_height.is_finite() { self.screen_height } else { h };
        self.scale = crate::view::text_size::text_scale(self.options.text, self.options.present, screen);
        let dpr = if dpr.is_finite() && dpr > 0.0 { dpr } else { 1.0 };
        self.layout =
            Layout::compute(w / self.scale, h / self.scale, dpr * self.scale, &self.options.layout_options(self.pair));
        let budget: usize = self.layout.panels.iter().map(|panel| self.vertex_budget(panel)).sum();
        self.painter.reserve_total(budget);
        self.rebuild_static();
        self.info_generation += 1;
    }

    /// Draws on `layout` instead of the one computed for the canvas: a figure of one panel
    /// ([`crate::view::figure`]), at text scale 1. A later resize or change of the panels shown
    /// lays out for the canvas again.
    pub fn set_layout(&mut self, layout: Layout) {
        self.layout = layout;
        self.scale = 1.0;
        let budget: usize = self.layout.panels.iter().map(|panel| self.vertex_budget(panel)).sum();
        self.painter.reserve_total(budget);
        self.rebuild_static();
        self.info_generation += 1;
    }

    /// An upper bound on the vertices one panel writes into the per-frame layer.
    fn vertex_budget(&self, panel: &Panel) -> usize {
        let runs = if self.pair { 2 } else { 1 };
        match panel.kind {
            PanelKind::Arm | PanelKind::ArmB => ARM_VERTEX_BUDGET,
            PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => {
                // Each run's curves, the ghost's, and a predicted slope per run.
                let per_run = plot_series(panel.kind, &Traces::default(), 0).iter().flatten().count();
                let series = per_run * (runs + 1) + split::SPLIT_SERIES;
                let (x_ticks, y_ticks) = plot_tick_counts(panel.rect);
                vertex_budget(
                    self.layout.to_physical(panel.rect).w,
                    series,
                    x_ticks + y_ticks + LOG_DECADES as usize + 4,
                ) + runs * DASHED_LINE_BUDGET
                    + 6 // the cursor
                    + if self.options.show_cycle { cycle::ZOOM_VERTEX_BUDGET } else { 0 }
            }
            PanelKind::Poles => {
                let (x_ticks, y_ticks) = pole_tick_counts(panel.rect);
                let background = 6 * (x_ticks + y_ticks + 8) + 2 * 6 + 24 + 2 * DASHED_LINE_BUDGET;
                background + runs * POLE_RUN_VERTEX_BUDGET
            }
            PanelKind::ZPlane => ZPLANE_BACKGROUND_BUDGET + 24 + runs * ZPLANE_RUN_VERTEX_BUDGET,
            PanelKind::RhoCurve => 24 + runs * RHO_MARKER_VERTEX_BUDGET,
            PanelKind::MapOff | PanelKind::MapOn => 24 + 2 * 6 * 8 + runs * MARKER_VERTEX_BUDGET,
        }
    }

    /// Canvas size in physical pixels.
    pub fn physical_size(&self) -> (u32, u32) {
        self.layout.physical_size()
    }

    /// The latest frame's per-frame triangle list (drawn over the static layer).
    pub fn vertices(&self) -> &[Vertex] {
        self.painter.vertices()
    }

    /// The painter of the per-frame layer (for its byte view and capacity).
    pub fn painter(&self) -> &Painter {
        &self.painter
    }

    /// The static layer: the stability maps' cells and contours (drawn first).
    pub fn static_vertices(&self) -> &[Vertex] {
        self.static_painter.vertices()
    }

    /// The painter of the static layer.
    pub fn static_painter(&self) -> &Painter {
        &self.static_painter
    }

    /// Increases whenever the static layer is rebuilt: upload it again when this changes.
    pub fn static_generation(&self) -> u64 {
        self.static_generation
    }

    /// Increases whenever the panels' description ([`Scene::panel_info`], [`Scene::pole_info`])
    /// changes: layout, scales, ticks, analyses, maps. Between changes only the time window moves.
    pub fn info_generation(&self) -> u64 {
        self.info_generation
    }

    /// The time window of the latest frame, s.
    pub fn time_window(&self) -> TimeWindow {
        self.window()
    }

    /// The background colour the renderer clears to.
    pub fn background(&self) -> Color {
        palette::BACKGROUND
    }

    /// Hands over a (possibly partial) stability map: `rho` row-major by α for the first rows.
    /// Rebuilds the static layer; call again as more rows arrive.
    pub fn set_map(&mut self, side: MapSide, deltas: &[f64], alphas: &[f64], rho: &[f64]) -> Result<(), String> {
        self.maps[side.index()].set(deltas, alphas, rho)?;
        self.map_sources[side.index()] = None;
        self.rebuild_static();
        self.info_generation += 1;
        Ok(())
    }

    /// Forgets both maps.
    pub fn clear_maps(&mut self) {
        for m in &mut self.maps {
            m.clear();
        }
        self.map_sources = [None; 2];
        self.rebuild_static();
        self.info_generation += 1;
    }

    /// The map of one side as the scene holds it.
    pub fn map(&self, side: MapSide) -> &StabilityGrid {
        &self.maps[side.index()]
    }

    /// The pole plot's frame on `rect` (physical or CSS pixels): its Im s range fits the shown
    /// runs' flexible pairs.
    pub(super) fn pole_frame(&self, rect: super::layout::Rect) -> super::poles::PoleFrame {
        let reports = self.runs[..self.run_count()].iter().filter_map(|m| m.report.as_ref());
        super::poles::PoleFrame::fitting(rect, reports)
    }

    /// The configuration and analysis of run A (0) or B (1) as of the latest frame.
    pub fn analysis(&self, run: usize) -> Option<&StabilityReport> {
        self.runs.get(run).and_then(|r| r.report.as_ref())
    }

    /// Builds the frame for run A, and run B beside it if given. Allocates nothing once the
    /// painter has grown to the scene's size, except when the mode (one run / two runs) changes
    /// (a new layout) or a run's analysis changes (a copy for the descriptions).
    pub fn draw_runs(&mut self, a: RunState<'_>, b: Option<RunState<'_>>) -> &[Vertex] {
        let pair = b.is_some();
        if pair != self.pair {
            self.pair = pair;
            self.relayout();
        }
        let mut changed = self.runs[0].update(a.config, a.analysis);
        changed |= match &b {
            Some(b) => self.runs[1].update(b.config, b.analysis),
            None => self.runs[1].update(None, None),
        };
        if changed {
            self.info_generation += 1;
        }
        self.update_windows(a.windows);
        let time_of = |r: &RunState<'_>| if r.snapshot.time.is_finite() { r.snapshot.time } else { f64::NAN };
        let now = match &b {
            Some(b) => time_of(&a).max(time_of(b)),
            None => time_of(&a),
        };
        if now.is_nan() || now < self.time {
            // The simulation restarted: the old data are gone, so are their scales.
            self.scale_e1.reset();
            self.scale_e2.reset();
            self.scale_torque.reset();
            for s in &mut self.zoom_scales {
                s.reset();
            }
        }
        self.time = if now.is_finite() { now } else { 0.0 };
        self.painter.clear();
        self.update_cycle(&a);
        let window = self.window();
        self.update_auto_log(&a, b.as_ref(), window);
        let zoom = self.cycle_window().is_some();
        for i in 0..self.layout.panels.len() {
            let panel = self.layout.panels[i];
            match panel.kind {
                PanelKind::Arm => self.draw_arm(panel, a.snapshot),
                PanelKind::ArmB => {
                    if let Some(b) = &b {
                        self.draw_arm(panel, b.snapshot);
                    }
                }
                PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque if zoom => {
                    self.draw_cycle_plot(panel, window, &a)
                }
                PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque => {
                    self.draw_plot(panel, window, &a, b.as_ref())
                }
                PanelKind::Poles => self.draw_pole_plot(panel),
                PanelKind::ZPlane => self.draw_zplane(panel),
                PanelKind::RhoCurve => self.draw_rho_markers(panel),
                PanelKind::MapOff | PanelKind::MapOn => self.draw_map_overlay(panel),
            }
        }
        self.note_info_changes(window);
        self.painter.vertices()
    }

    /// Bumps the info generation when the scales or the time ticks changed this frame.
    fn note_info_changes(&mut self, window: TimeWindow) {
        let first_tick = self
            .layout
            .panels
            .iter()
            .find(|p| p.kind.is_time_plot())
            .and_then(|p| plot_ticks(p.rect, window, 1.0).0.next())
            .unwrap_or(f64::NAN);
        // Zoomed, the window moves every period but its ticks stay where they are (t_n − δ …).
        let zoom = self.cycle_window().is_some();
        let signature = if zoom {
            [
                self.zoom_scales[0].limit(),
                self.zoom_scales[1].limit(),
                self.zoom_scales[2].limit(),
                if self.jump_off_scale() { 1.0 } else { 0.0 },
                window.width(),
                3.0,
            ]
        } else {
            [
                self.scale_e1.limit(),
                self.scale_e2.limit(),
                self.scale_torque.limit(),
                first_tick,
                window.width(),
                if self.pair { 2.0 } else { 1.0 },
            ]
        };
        let same = signature.iter().zip(&self.info_signature).all(|(a, b)| a == b || (a.is_nan() && b.is_nan()));
        if !same {
            self.info_signature = signature;
            self.info_generation += 1;
        }
    }

    /// The time plots' window: the newest W seconds, or, when looking back, W seconds around
    /// the instant looked at (within what was run); zoomed on one sampling instant, three
    /// periods around it.
    fn window(&self) -> TimeWindow {
        if let Some(zoom) = self.cycle_window() {
            return zoom;
        }
        let width = self.options.time_window;
        match self.cursor {
            Some(c) if c.is_finite() => TimeWindow::ending_at(self.time.min((c + 0.5 * width).max(width)), width),
            _ => TimeWindow::ending_at(self.time, width),
        }
    }

    /// The instant looked back at, if any.
    pub fn cursor(&self) -> Option<f64> {
        self.cursor
    }

    /// How many runs the frame shows.
    fn run_count(&self) -> usize {
        if self.pair {
            2
        } else {
            1
        }
    }

    fn scale_mut(&mut self, kind: PanelKind) -> Option<&mut Autoscale> {
        match kind {
            PanelKind::Error1 => Some(&mut self.scale_e1),
            PanelKind::Error2 => Some(&mut self.scale_e2),
            PanelKind::Torque => Some(&mut self.scale_torque),
            _ => None,
        }
    }

    fn scale(&self, kind: PanelKind) -> Option<&Autoscale> {
        match kind {
            PanelKind::Error1 => Some(&self.scale_e1),
            PanelKind::Error2 => Some(&self.scale_e2),
            PanelKind::Torque => Some(&self.scale_torque),
            _ => None,
        }
    }
}

/// The pole-plot style of run A (0) or B (1).
fn run_pole_style(run: usize) -> PoleStyle {
    if run == 0 {
        PoleStyle::RUN_A
    } else {
        PoleStyle::RUN_B
    }
}
