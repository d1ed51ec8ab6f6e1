//! One frame of the page's picture, built from a session (one run or two side by side): the
//! scene lays the panels out, keeps what persists between frames — what they share
//! ([`Frame`]) and each panel's own state ([`Panels`]) — and asks each panel to draw itself,
//! describe itself for the page ([`info`]), say what lies under the pointer ([`probe`]) and give
//! its key. It knows no panel's insides.
//!
//! [`Scene`] is everything the renderer needs except the GPU. It keeps two triangle lists: the
//! *static* layer ([`Scene::static_vertices`]: the stability maps' cells and contours and ρ(δ)'s
//! curve, rebuilt only when they or the layout change, with [`Scene::static_generation`] counting
//! rebuilds) and the per-frame layer ([`Scene::vertices`]: everything else, drawn over the static
//! layer). The analyses come with the runs (the session computes them once per change); the scene
//! keeps a copy of the latest for its descriptions, updated only when it changes.

mod handle;
pub mod info;
mod page;
pub mod probe;
mod sources;

use super::layout::{Layout, PanelKind};
use super::painter::{Painter, Vertex};
use super::panels::contract::{Frame, Runs};
use super::panels::z_plane::gestures::z_view_of;
use super::panels::z_plane::view::ZView;
use super::panels::Panels;
use crate::analysis::{StabilityReport, StableWindows};
use crate::control::Cycle;
use crate::plot::{palette, Color};
use crate::session::{MapSide, ViewSettings};
use crate::view::panels::stability_maps::grid::StabilityGrid;
use crate::view::time_window::TimeWindow;

pub use super::options::{OptionsUpdate, ViewOptions, MAX_SPRING_MAGNIFICATION, MAX_TIME_WINDOW};
pub use super::panel_info::{Mark, PanelInfo, Probe, TickLabel, TipLine};
pub use super::panels::arm::swing::{SwingShape, SWING_SLOWDOWN};
pub use super::panels::contract::RunState;
pub use info::SeriesInfo;

/// The picture: layout, what persists between frames, the triangle lists.
#[derive(Clone, Debug)]
pub struct Scene {
    /// What every panel reads: options, layout, the runs' analyses, windows, time, the zoom.
    frame: Frame,
    /// One of each panel type, with its own state (scales, the maps' grids).
    panels: Panels,
    painter: Painter,
    /// The stability maps' cells and contours, ρ(δ)'s curve: rebuilt only when they or the
    /// layout change.
    static_painter: Painter,
    static_generation: u64,
    /// Increases whenever [`Scene::panel_info`] would describe the frame differently.
    info_generation: u64,
    info_signature: [f64; 8],
    /// The canvas as the page has it: CSS width and height, device-pixel ratio; and the screen's
    /// height (CSS px), which presentation mode's text size follows.
    page: [f64; 3],
    screen_height: f64,
    /// Page CSS px per layout px: the text scale ([`crate::view::text_size::text_scale`]).
    scale: f64,
    /// Whether run A's controller was digital when the panels were laid out (the `measured`
    /// switch then adds the velocity panel).
    digital: bool,
    /// The z-plane's view held whatever the view settings say: a figure's, as the screen shows it.
    z_pin: Option<ZView>,
}

impl Scene {
    /// A scene for a canvas of the given CSS size and device-pixel ratio.
    pub fn new(options: ViewOptions, css_width: f64, css_height: f64, device_pixel_ratio: f64) -> Self {
        let layout = Layout::compute(css_width, css_height, device_pixel_ratio, &options.layout_options(false, false));
        let mut scene = Self {
            frame: Frame {
                options,
                pair: false,
                layout,
                runs: Default::default(),
                windows: None,
                windows_hidden: false,
                time: 0.0,
                cursor: None,
                cycle: Cycle::new(),
                clock: 0.0,
                pole_im_held: None,
            },
            panels: Panels::default(),
            painter: Painter::new(),
            static_painter: Painter::new(),
            static_generation: 0,
            info_generation: 0,
            info_signature: [f64::NAN; 8],
            page: [css_width, css_height, device_pixel_ratio],
            screen_height: f64::NAN,
            scale: 1.0,
            digital: false,
            z_pin: None,
        };
        scene.relayout();
        scene
    }

    pub fn options(&self) -> &ViewOptions {
        &self.frame.options
    }

    pub fn layout(&self) -> &Layout {
        &self.frame.layout
    }

    /// What the panels read: the state kept between frames.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// The panels the view asks for that this layout does not show (on a narrow canvas, those
    /// of the other tabs): an embed announces them rather than dropping them silently.
    pub fn hidden_panels(&self) -> Vec<PanelKind> {
        self.frame.layout.hidden(&self.frame.options.layout_options(self.frame.pair, self.digital))
    }

    /// True if the latest frame compared two runs.
    pub fn is_pair(&self) -> bool {
        self.frame.pair
    }

    /// Validates and applies a partial options update (re-laying out if panels change).
    pub fn set_options(&mut self, update: &OptionsUpdate) -> Result<(), String> {
        self.frame.options.apply(update)?;
        self.relayout();
        Ok(())
    }

    /// Shows what the session's view settings say (the intro: the arm and the errors only),
    /// re-laying out only when that changes.
    pub fn follow_view(&mut self, view: &ViewSettings) {
        let v = view.shown();
        let options = &self.frame.options;
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
            show_measured: v.measured,
            show_study: v.study,
            show_cycle: v.predict,
            show_swing: v.swing,
            tab: v.tab,
            hide_prediction: v.answers_hidden,
            z_view: self.z_pin.or_else(|| z_view_of(&v)),
            text: crate::view::text_size::TextSize::from_name(v.text),
            present: v.present,
            time_window: if v.window.is_finite() && v.window > 0.0 {
                v.window.min(MAX_TIME_WINDOW)
            } else {
                options.time_window
            },
            ..*options
        };
        if next != *options {
            // Zooming the z-plane changes its drawing and description, not the layout.
            let zoom_only = ViewOptions { z_view: options.z_view, ..next } == *options;
            self.frame.options = next;
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
    fn relayout(&mut self) {
        let [w, h, dpr] = self.page;
        let screen = if self.screen_height.is_finite() { self.screen_height } else { h };
        let options = &self.frame.options;
        self.scale = crate::view::text_size::text_scale(options.text, options.present, screen);
        let dpr = if dpr.is_finite() && dpr > 0.0 { dpr } else { 1.0 };
        self.digital = self.frame.digital();
        let asked = options.layout_options(self.frame.pair, self.digital);
        self.frame.layout = Layout::compute(w / self.scale, h / self.scale, dpr * self.scale, &asked);
        self.reserve();
    }

    /// Draws on `layout` instead of the one computed for the canvas: a figure of one panel
    /// ([`crate::view::figure`]), at text scale 1. A later resize or change of the panels shown
    /// lays out for the canvas again.
    pub fn set_layout(&mut self, layout: Layout) {
        self.frame.layout = layout;
        self.scale = 1.0;
        self.reserve();
    }

    /// Reserves the painter's room for this layout's largest frame and rebuilds the static layer.
    fn reserve(&mut self) {
        let frame = &self.frame;
        let budget: usize = frame.layout.panels.iter().map(|panel| self.panels.vertex_budget(frame, panel)).sum();
        self.painter.reserve_total(budget);
        self.rebuild_static();
        self.info_generation += 1;
    }

    /// Draws the static layer again: each panel's part that changes only with its data.
    fn rebuild_static(&mut self) {
        self.static_painter.clear();
        for panel in &self.frame.layout.panels {
            self.panels.draw_static(&self.frame, panel, &mut self.static_painter);
        }
        self.static_generation += 1;
    }

    /// Canvas size in physical pixels.
    pub fn physical_size(&self) -> (u32, u32) {
        self.frame.layout.physical_size()
    }

    /// The latest frame's per-frame triangle list (drawn over the static layer).
    pub fn vertices(&self) -> &[Vertex] {
        self.painter.vertices()
    }

    /// The painter of the per-frame layer (for its byte view and capacity).
    pub fn painter(&self) -> &Painter {
        &self.painter
    }

    /// The static layer: the stability maps' cells and contours, ρ(δ)'s curve (drawn first).
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
        self.frame.window()
    }

    /// The background colour the renderer clears to.
    pub fn background(&self) -> Color {
        palette::BACKGROUND
    }

    /// Hands over a (possibly partial) stability map: `rho` row-major by α for the first rows.
    /// Rebuilds the static layer; call again as more rows arrive.
    pub fn set_map(&mut self, side: MapSide, deltas: &[f64], alphas: &[f64], rho: &[f64]) -> Result<(), String> {
        self.panels.maps.set(side, deltas, alphas, rho)?;
        self.rebuild_static();
        self.info_generation += 1;
        Ok(())
    }

    /// Forgets both maps.
    pub fn clear_maps(&mut self) {
        self.panels.maps.clear();
        self.rebuild_static();
        self.info_generation += 1;
    }

    /// The map of one side as the scene holds it.
    pub fn map(&self, side: MapSide) -> &StabilityGrid {
        self.panels.maps.grid(side)
    }

    /// The analysis of run A (0) or B (1) as of the latest frame.
    pub fn analysis(&self, run: usize) -> Option<&StabilityReport> {
        self.frame.runs.get(run).and_then(|r| r.report.as_ref())
    }

    /// Takes run A's stable windows, rebuilding ρ(δ) when they changed.
    fn update_windows(&mut self, windows: Option<&StableWindows>) {
        if self.frame.windows.as_ref() == windows {
            return;
        }
        match (&mut self.frame.windows, windows) {
            (Some(mine), Some(w)) => mine.clone_from(w),
            (mine, w) => *mine = w.cloned(),
        }
        self.rebuild_static();
        self.info_generation += 1;
    }

    /// Builds the frame for run A, and run B beside it if given. Allocates nothing once the
    /// painter has grown to the scene's size, except when the mode (one run / two runs) changes
    /// (a new layout) or a run's analysis changes (a copy for the descriptions).
    pub fn draw_runs(&mut self, a: RunState<'_>, b: Option<RunState<'_>>) -> &[Vertex] {
        let pair = b.is_some();
        if pair != self.frame.pair {
            self.frame.pair = pair;
            self.relayout();
        }
        let runs = Runs { a, b };
        let mut changed = self.frame.runs[0].update(a.config, a.analysis);
        changed |= match &b {
            Some(b) => self.frame.runs[1].update(b.config, b.analysis),
            None => self.frame.runs[1].update(None, None),
        };
        if changed {
            self.info_generation += 1;
            let switched = self.frame.options.show_measured || self.frame.options.show_study;
            if self.frame.digital() != self.digital && switched {
                // The sensors turned digital or off: the velocity panel or the study's come or go.
                self.relayout();
            }
        }
        self.update_windows(a.windows);
        let time_of = |r: &RunState<'_>| if r.snapshot.time.is_finite() { r.snapshot.time } else { f64::NAN };
        let now = match &b {
            Some(b) => time_of(&a).max(time_of(b)),
            None => time_of(&a),
        };
        if now.is_nan() || now < self.frame.time {
            // The simulation restarted: the old data are gone, so are their scales.
            self.panels.time_plots.reset_scales();
        }
        self.frame.time = if now.is_finite() { now } else { 0.0 };
        self.painter.clear();
        self.update_cycle(&a);
        let window = self.frame.window();
        if self.panels.time_plots.update_auto_log(&self.frame, &runs, window) {
            self.info_generation += 1;
        }
        for panel in &self.frame.layout.panels {
            self.panels.draw(&self.frame, &runs, panel, &mut self.painter);
        }
        self.note_info_changes(window);
        self.painter.vertices()
    }

    /// Brings the zoom to the sampling instant run A shows (its newest, or the one looked back at).
    fn update_cycle(&mut self, a: &RunState<'_>) {
        if !self.frame.options.show_cycle {
            return;
        }
        match a.history {
            Some(history) => self.frame.cycle.fill(history, a.sweep, a.traces, a.snapshot.time),
            None => self.frame.cycle.instant = f64::NAN,
        }
    }

    /// Bumps the info generation when the time plots' scales or ticks changed this frame.
    fn note_info_changes(&mut self, window: TimeWindow) {
        let signature = self.panels.time_plots.signature(&self.frame, window);
        let same = signature.iter().zip(&self.info_signature).all(|(a, b)| a == b || (a.is_nan() && b.is_nan()));
        if !same {
            self.info_signature = signature;
            self.info_generation += 1;
        }
    }

    /// The instant looked back at, if any.
    pub fn cursor(&self) -> Option<f64> {
        self.frame.cursor
    }

    /// True while the error plots are log |e| because the compared runs differ by a decade.
    pub fn auto_log(&self) -> bool {
        self.panels.time_plots.auto_log()
    }

    /// Wall-clock seconds, for the animations that run while the simulation is paused.
    pub fn set_clock(&mut self, seconds: f64) {
        if seconds.is_finite() {
            self.frame.clock = seconds;
        }
    }

    /// True while something moves without the simulation (the swing's shape): draw every frame.
    pub fn animating(&self) -> bool {
        self.frame.options.show_swing && self.swing_shape().is_some()
    }

    /// The flexible pair's shape in run A's analysis (see [`SwingShape`]).
    pub fn swing_shape(&self) -> Option<SwingShape> {
        super::panels::arm::swing::swing_shape(&self.frame)
    }

    // ------------------------------------------------------------------------------ z-plane

    /// The z-plane's data area, CSS px, if it is shown.
    pub fn z_panel(&self) -> Option<super::rect::Rect> {
        super::panels::z_plane::gestures::z_panel(&self.frame)
    }

    /// The view the z-plane shows: the page's, or around run A's flexible pair.
    pub fn z_view(&self) -> ZView {
        super::panels::z_plane::gestures::z_view(&self.frame)
    }

    /// Holds the z-plane at `view` (none: as the view settings say): a figure shows what the
    /// screen shows, though its panel is larger than the screen's.
    pub fn pin_z_view(&mut self, view: Option<ZView>) {
        self.z_pin = view;
        if view.is_some() {
            self.set_z_view(view);
        }
    }

    /// Shows `view` (None: the default) at once, before the session's settings reach the next
    /// frame: gestures faster than frames (a pinch zooms and pans in one event) build on it.
    pub fn set_z_view(&mut self, view: Option<ZView>) {
        if self.frame.options.z_view != view {
            self.frame.options.z_view = view;
            self.info_generation += 1;
        }
    }

    /// The view after zooming by `factor` (> 1 in) about (x, y) (CSS px), which keeps its λ under
    /// the pointer; None if (x, y) is not on the z-plane.
    pub fn zoom_z(&self, x: f64, y: f64, factor: f64) -> Option<ZView> {
        super::panels::z_plane::gestures::zoom_z(&self.frame, x, y, factor)
    }

    /// The view after zooming by `factor` about the panel's centre (the buttons and keys).
    pub fn zoom_z_center(&self, factor: f64) -> Option<ZView> {
        super::panels::z_plane::gestures::zoom_z_center(&self.frame, factor)
    }

    /// The view after dragging the plane by (dx, dy) CSS px (the plane follows the pointer).
    pub fn pan_z(&self, dx: f64, dy: f64) -> Option<ZView> {
        super::panels::z_plane::gestures::pan_z(&self.frame, dx, dy)
    }
}
