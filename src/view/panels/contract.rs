//! What a panel is to the scene: one interface, [`PanelView`], and what every panel reads from
//! the scene — the [`Frame`] (the state kept between frames: options, layout, the runs'
//! configurations and analyses, the stable windows, the time, the zoom's cycle) and, while a frame
//! is drawn, the runs' own data ([`Runs`]).
//!
//! Why a trait and not one enum with a `match` per concern: a panel's concerns (drawing, its
//! description for the page, its tooltip, its key, its figure) change together, and a trait keeps
//! them in the panel's own folder, where the compiler asks for every one of them; the scene holds
//! one value of each panel type (the place for a panel's own state: the time plots' scales, the
//! maps' grids) and dispatches on [`PanelKind`] in one function ([`super::Panels::get`]). A new
//! panel is a folder, a variant of [`PanelKind`] and a line there.

use crate::analysis::{StabilityReport, StableWindows};
use crate::control::config::SimulationConfig;
use crate::control::predictive::Sweep;
use crate::control::{Cycle, History, Snapshot, Traces};
use crate::model::reference::Reference;
use crate::schema::PanelKind;
use crate::view::layout::{Layout, Panel};
use crate::view::legend::LegendGroup;
use crate::view::loop_poles::readout::{probe_poles, PoleScene};
use crate::view::loop_poles::{describe_poles, Placement, PoleInfo};
use crate::view::options::ViewOptions;
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe};
use crate::view::time_window::TimeWindow;

/// Sampling periods the zoom shows before t_n and after t_n + 2δ.
const ZOOM_MARGIN: f64 = 0.25;

/// One panel type: everything about the panels of one [`PanelKind`] family (the arm and run B's
/// arm; e1, e2 and the torques; …).
pub trait PanelView {
    /// An upper bound on the vertices [`PanelView::draw`] writes for `panel` (the painter reserves
    /// it once per layout, so that drawing never reallocates).
    fn vertex_budget(&self, frame: &Frame, panel: &Panel) -> usize;

    /// Draws what changes only with the panel's data (the maps' cells, ρ(δ)'s curve) into the
    /// static layer, rebuilt only when that data or the layout changes.
    fn draw_static(&self, _frame: &Frame, _panel: &Panel, _painter: &mut Painter) {}

    /// Draws the panel for this frame into the per-frame layer (physical pixels).
    fn draw(&mut self, frame: &Frame, runs: &Runs<'_>, panel: &Panel, painter: &mut Painter);

    /// The panel as the page reads it: axes, ticks and their labels, title, note, marks (CSS px).
    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo;

    /// What lies at (x, y) (CSS px) for a tooltip, if it is this panel's.
    fn probe(&self, _frame: &Frame, _panel: &Panel, _x: f64, _y: f64, _reach: f64) -> Option<Probe> {
        None
    }

    /// Every marker of the loop's eigenvalues (both runs' when compared) placed on this panel,
    /// for hover readouts, if it is a picture of them.
    fn pole_markers(&self, _frame: &Frame, _panel: &Panel) -> Option<Vec<PoleInfo>> {
        None
    }

    /// The key to this family's marks, lines and shades when the panels `kinds` are shown.
    fn legend(&self, _frame: &Frame, _kinds: &[PanelKind]) -> Vec<LegendGroup> {
        Vec::new()
    }

    /// Keys that carry this frame's numbers (the swing's shape), after every panel's key.
    fn readings(&self, _frame: &Frame) -> Vec<LegendGroup> {
        Vec::new()
    }

    /// A figure's title for the panels `kinds` of this family ([`crate::view::figure`]).
    fn figure_title(&self, frame: &Frame, kinds: &[PanelKind]) -> String;

    /// The data area of `kind` in a figure (w, h), px: what reads well on a slide or a printed page.
    fn figure_size(&self, kind: PanelKind) -> (f64, f64);
}

/// The state of one run that a frame draws.
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

/// The runs of the frame being drawn: A, and B beside it when two are compared.
#[derive(Clone, Copy, Debug)]
pub struct Runs<'a> {
    pub a: RunState<'a>,
    pub b: Option<RunState<'a>>,
}

impl<'a> Runs<'a> {
    /// A, then B if there is one.
    pub fn each(&self) -> [Option<&RunState<'a>>; 2] {
        [Some(&self.a), self.b.as_ref()]
    }
}

/// What the scene remembers of a run between frames, for its descriptions.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RunMemory {
    pub config: Option<SimulationConfig>,
    pub report: Option<StabilityReport>,
}

impl RunMemory {
    /// Takes the run's configuration and analysis, copying only what changed; true if anything did.
    pub fn update(&mut self, config: Option<&SimulationConfig>, report: Option<&StabilityReport>) -> bool {
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

/// Run names, as the page sees them.
pub const RUN_NAMES: [&str; 2] = ["A", "B"];

/// What the scene knows between frames, which every panel reads.
#[derive(Clone, Debug)]
pub struct Frame {
    pub options: ViewOptions,
    /// Two runs side by side (set by the latest draw).
    pub pair: bool,
    pub layout: Layout,
    /// Run A's and B's configuration and analysis as of the latest frame.
    pub runs: [RunMemory; 2],
    /// Run A's stable windows of δ as of the latest frame (ρ(δ) and the marks on the maps).
    pub windows: Option<StableWindows>,
    /// The lesson's step hides the windows until its answer (`hide: windows`): ρ(δ) says so.
    pub windows_hidden: bool,
    /// Simulated time of the latest frame, s (the later of the two runs').
    pub time: f64,
    /// The instant looked back at (a vertical line in the time plots), or None.
    pub cursor: Option<f64>,
    /// The zoom on one sampling instant (Fig. 2.1), kept between frames: the time plots draw it,
    /// the arm draws the predicted arm Xₖ.
    pub cycle: Cycle,
    /// Wall-clock seconds of the latest frame (the swing's animation).
    pub clock: f64,
    /// The pole plot's Im s range held while the pair is dragged (its fit to the pair would
    /// otherwise rescale the plot under the pointer); None: fitted.
    pub pole_im_held: Option<[f64; 2]>,
}

impl Frame {
    /// How many runs the frame shows.
    pub fn run_count(&self) -> usize {
        if self.pair {
            2
        } else {
            1
        }
    }

    /// The analyses of the runs shown.
    pub fn reports(&self) -> impl Iterator<Item = &StabilityReport> {
        self.runs[..self.run_count()].iter().filter_map(|m| m.report.as_ref())
    }

    /// Every run's loop eigenvalues as markers on a picture of them, `place` putting each (s, λ)
    /// on it (CSS px) and saying whether it is in view: what the pole plot and the z-plane list.
    pub fn pole_markers(&self, place: Placement<'_>) -> Vec<PoleInfo> {
        let mut out = Vec::new();
        for (memory, name) in self.runs.iter().zip(RUN_NAMES).take(self.run_count()) {
            if let Some(report) = &memory.report {
                describe_poles(report, name, place, &mut out);
            }
        }
        out
    }

    /// The marker among `poles` at (x, y) on the pole picture `panel` (the z-plane's if
    /// `z_plane`), read out for a tooltip.
    pub fn probe_poles(
        &self,
        poles: &[PoleInfo],
        panel: &Panel,
        z_plane: bool,
        x: f64,
        y: f64,
        reach: f64,
    ) -> Option<Probe> {
        let scene = PoleScene {
            poles,
            panel: panel.rect,
            z_plane,
            pair: self.pair,
            hide_prediction: self.options.hide_prediction,
            sampling_period: self.runs[0].report.as_ref().map_or(1.0, |r| r.sampling_period),
        };
        probe_poles(&scene, x, y, reach)
    }

    /// The zoom's window, if the zoom is on and has an instant to show: three sampling periods
    /// and a quarter on each side, [t_n − 1.25 δ, t_n + 2.25 δ].
    pub fn cycle_window(&self) -> Option<TimeWindow> {
        if !self.options.show_cycle || self.cycle.is_empty() {
            return None;
        }
        let (t, d) = (self.cycle.instant, self.cycle.period);
        Some(TimeWindow { start: t - (1.0 + ZOOM_MARGIN) * d, end: t + (2.0 + ZOOM_MARGIN) * d })
    }

    /// True if run A's controller reads sensors (a digital controller): what it estimated then
    /// differs from the true state, and the `measured` switch has something to show.
    pub fn digital(&self) -> bool {
        self.runs[0].config.is_some_and(|c| c.sensors.is_digital())
    }

    /// True while the time plots are zoomed on one sampling instant.
    pub fn zoomed(&self) -> bool {
        self.cycle_window().is_some()
    }

    /// The time plots' window: the newest W seconds, or, when looking back, W seconds around
    /// the instant looked at (within what was run); zoomed on one sampling instant, three
    /// periods around it.
    pub fn window(&self) -> TimeWindow {
        if let Some(zoom) = self.cycle_window() {
            return zoom;
        }
        let width = self.options.time_window;
        match self.cursor {
            Some(c) if c.is_finite() => TimeWindow::ending_at(self.time.min((c + 0.5 * width).max(width)), width),
            _ => TimeWindow::ending_at(self.time, width),
        }
    }

    /// The panel of `kind` in the layout, if shown.
    pub fn panel(&self, kind: PanelKind) -> Option<&Panel> {
        self.layout.panel(kind)
    }
}
