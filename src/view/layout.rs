//! Where each panel goes on the canvas.
//!
//! The canvas is split into a *stage* (the arm picture, or two arms when two runs are compared)
//! and a column of *plots*: the time traces stacked, then the analysis panels (pole plot and the
//! two stability maps) in a row below them. On a wide canvas the stage takes the left ≈ 40 % and
//! the plots sit on the right; on a narrow or portrait canvas the stage sits on top and the plots
//! below it. The analysis panels share their row side by side, or wrap onto more rows when that
//! gives every panel more room (narrow canvases).
//!
//! Panel rectangles are in CSS pixels and, for plots, are exactly the data area: the axis ranges
//! map linearly onto them. Gutters around each plot are left free for the HTML tick labels and
//! titles that the page places over the canvas.
//!
//! The lists of panels are data ([`PanelKind`] values): new panels are added by extending the
//! enum and [`LayoutOptions::panels`], not by rewriting the arithmetic.

use serde::Serialize;

/// An axis-aligned rectangle: top-left corner (x, y) and size (w, h), y pointing down.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Rect {
    pub x: f64,
    pub y: f64,
    pub w: f64,
    pub h: f64,
}

impl Rect {
    pub const fn new(x: f64, y: f64, w: f64, h: f64) -> Self {
        Self { x, y, w, h }
    }

    pub fn right(&self) -> f64 {
        self.x + self.w
    }

    pub fn bottom(&self) -> f64 {
        self.y + self.h
    }

    pub fn center(&self) -> [f64; 2] {
        [self.x + self.w / 2.0, self.y + self.h / 2.0]
    }

    /// The rectangle with every coordinate multiplied by `factor` (CSS → physical pixels).
    pub fn scaled(&self, factor: f64) -> Rect {
        Rect::new(self.x * factor, self.y * factor, self.w * factor, self.h * factor)
    }

    /// The rectangle shrunk by the given margins; the size never becomes negative.
    pub fn inset(&self, left: f64, top: f64, right: f64, bottom: f64) -> Rect {
        Rect::new(self.x + left, self.y + top, (self.w - left - right).max(0.0), (self.h - top - bottom).max(0.0))
    }

    /// True if `other` lies entirely inside `self` (edges may touch).
    pub fn contains_rect(&self, other: &Rect) -> bool {
        const TOL: f64 = 1e-9;
        other.x >= self.x - TOL
            && other.y >= self.y - TOL
            && other.right() <= self.right() + TOL
            && other.bottom() <= self.bottom() + TOL
    }

    /// True if the interiors of the two rectangles overlap.
    pub fn overlaps(&self, other: &Rect) -> bool {
        self.x < other.right() && other.x < self.right() && self.y < other.bottom() && other.y < self.bottom()
    }
}

/// What a panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PanelKind {
    /// The arm, its motor, the flexible joint and the reference arm (run A).
    Arm,
    /// The second arm when two runs are compared (run B).
    ArmB,
    /// Tracking error of link 1, e1 = q1 − q_d1 over time.
    Error1,
    /// Tracking error of link 2, e2 = q2 − q_d2 over time.
    Error2,
    /// Applied torques T1, T2 over time.
    Torque,
    /// The sampled loop's eigenvalues as s = ln λ / δ, with the δ → 0 pair A4.
    Poles,
    /// The sampled loop's eigenvalues λ themselves, with the unit circle.
    ZPlane,
    /// ρ over δ at the current α, with the stable windows.
    RhoCurve,
    /// ρ over (δ, α) without preliminary feedback.
    MapOff,
    /// ρ over (δ, α) with preliminary feedback.
    MapOn,
}

impl PanelKind {
    /// The identifier the page sees in `Renderer.layout()`.
    pub fn id(self) -> &'static str {
        match self {
            PanelKind::Arm => "arm",
            PanelKind::ArmB => "arm-b",
            PanelKind::Error1 => "e1",
            PanelKind::Error2 => "e2",
            PanelKind::Torque => "torque",
            PanelKind::Poles => "poles",
            PanelKind::ZPlane => "z-plane",
            PanelKind::RhoCurve => "rho-curve",
            PanelKind::MapOff => "map-off",
            PanelKind::MapOn => "map-on",
        }
    }

    /// True for panels that plot quantities against time.
    pub fn is_time_plot(self) -> bool {
        matches!(self, PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque)
    }

    /// True for the arm pictures.
    pub fn is_stage(self) -> bool {
        matches!(self, PanelKind::Arm | PanelKind::ArmB)
    }

    /// True for the stability maps.
    pub fn is_map(self) -> bool {
        matches!(self, PanelKind::MapOff | PanelKind::MapOn)
    }

    /// True for the panels of the analysis row: pole plot (s or z), ρ(δ) and maps.
    pub fn is_analysis(self) -> bool {
        matches!(
            self,
            PanelKind::Poles | PanelKind::ZPlane | PanelKind::RhoCurve | PanelKind::MapOff | PanelKind::MapOn
        )
    }

    /// True for the two pictures of the loop's eigenvalues.
    pub fn is_pole_plot(self) -> bool {
        matches!(self, PanelKind::Poles | PanelKind::ZPlane)
    }
}

/// One panel: its kind and its rectangle in CSS pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Panel {
    pub kind: PanelKind,
    /// CSS pixels, origin top-left of the canvas. For plots: the data area only.
    pub rect: Rect,
}

/// Which panels to show.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayoutOptions {
    /// Adds the torque panel below the error panels.
    pub show_torque: bool,
    /// Adds the pole plot to the analysis row.
    pub show_poles: bool,
    /// The pole plot shows λ in the z-plane instead of s = ln λ / δ.
    pub z_plane: bool,
    /// Adds ρ(δ) at the current α to the analysis row.
    pub show_rho: bool,
    /// Adds the two stability maps to the analysis row.
    pub show_map: bool,
    /// Two runs side by side: a second arm on the stage.
    pub pair: bool,
}

impl Default for LayoutOptions {
    /// What the page shows by default: one run, no torque, the s-plane pole plot, ρ(δ), the maps.
    fn default() -> Self {
        Self { show_torque: false, show_poles: true, z_plane: false, show_rho: true, show_map: true, pair: false }
    }
}

/// The panels of a layout, grouped by where they go.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PanelLists {
    /// The arm pictures, sharing the stage.
    pub stage: Vec<PanelKind>,
    /// The time plots, stacked.
    pub plots: Vec<PanelKind>,
    /// The analysis panels, in a row below the time plots.
    pub analysis: Vec<PanelKind>,
}

impl LayoutOptions {
    /// The stage panels, the time plots and the analysis panels, in order.
    pub fn panels(&self) -> PanelLists {
        let mut stage = vec![PanelKind::Arm];
        if self.pair {
            stage.push(PanelKind::ArmB);
        }
        let mut plots = vec![PanelKind::Error1, PanelKind::Error2];
        if self.show_torque {
            plots.push(PanelKind::Torque);
        }
        let mut analysis = Vec::new();
        if self.show_poles {
            analysis.push(if self.z_plane { PanelKind::ZPlane } else { PanelKind::Poles });
        }
        if self.show_rho {
            analysis.push(PanelKind::RhoCurve);
        }
        if self.show_map {
            analysis.extend([PanelKind::MapOff, PanelKind::MapOn]);
        }
        PanelLists { stage, plots, analysis }
    }
}

/// Stage beside the plots, or stage above the plots.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arrangement {
    /// Wide canvas: stage on the left, plots on the right.
    SideBySide,
    /// Narrow or portrait canvas: stage on top, plots below.
    Stacked,
}

/// Margins in CSS pixels.
pub mod margins {
    /// Around the whole canvas.
    pub const OUTER: f64 = 8.0;
    /// Between the stage and the plot column.
    pub const GAP: f64 = 12.0;
    /// Left of a plot: room for the y tick labels.
    pub const PLOT_LEFT: f64 = 60.0;
    /// Above a plot: room for its title (the y label).
    pub const PLOT_TOP: f64 = 22.0;
    /// Below a plot: room for the time tick labels.
    pub const PLOT_BOTTOM: f64 = 20.0;
    /// Right of a plot.
    pub const PLOT_RIGHT: f64 = 10.0;
    /// Left of an analysis panel: its tick labels are short ("−40", "0.2").
    pub const ANALYSIS_LEFT: f64 = 44.0;
    /// Above the stage: room for a caption such as "spring twist ×20".
    pub const STAGE_TOP: f64 = 22.0;
}

/// Share of the canvas width given to the stage on a wide canvas.
pub const STAGE_WIDTH_SHARE: f64 = 0.4;
/// The same when the analysis row is shown (the row needs the width).
pub const STAGE_WIDTH_SHARE_WITH_ANALYSIS: f64 = 0.38;
/// Share of the canvas height given to the stage on a narrow canvas.
pub const STAGE_HEIGHT_SHARE: f64 = 0.42;
/// The same when the analysis panels are shown.
pub const STAGE_HEIGHT_SHARE_WITH_ANALYSIS: f64 = 0.3;
/// Canvases narrower than this (CSS px), or taller than wide × [`PORTRAIT_ASPECT`], stack.
pub const NARROW_WIDTH: f64 = 640.0;
/// Width / height below which the canvas counts as portrait.
pub const PORTRAIT_ASPECT: f64 = 1.05;
/// Height of one analysis row relative to one time-plot row (a single analysis row) ...
pub const ANALYSIS_ROW_WEIGHT: f64 = 1.6;
/// ... and per row when the analysis panels wrap onto several rows.
pub const WRAPPED_ANALYSIS_ROW_WEIGHT: f64 = 1.25;
/// A time plot's or analysis panel's data area is kept at least this tall (CSS px) when the
/// canvas has room for it, by shrinking the other rows towards the same minimum.
pub const MIN_PLOT_HEIGHT: f64 = 60.0;

/// The panels for one canvas size.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Canvas size in CSS pixels.
    pub css_width: f64,
    pub css_height: f64,
    /// Physical pixels per CSS pixel.
    pub device_pixel_ratio: f64,
    pub arrangement: Arrangement,
    pub panels: Vec<Panel>,
}

impl Layout {
    /// Lays out the panels chosen by `options` on a canvas of `css_width × css_height` CSS pixels.
    ///
    /// Non-finite or non-positive sizes count as 1 px and a bad ratio as 1, so the result is
    /// always usable (if tiny).
    pub fn compute(css_width: f64, css_height: f64, device_pixel_ratio: f64, options: &LayoutOptions) -> Layout {
        let sane = |v: f64| if v.is_finite() && v >= 1.0 { v } else { 1.0 };
        let (w, h) = (sane(css_width), sane(css_height));
        let dpr = if device_pixel_ratio.is_finite() && device_pixel_ratio > 0.0 { device_pixel_ratio } else { 1.0 };
        let arrangement =
            if w < NARROW_WIDTH || w < PORTRAIT_ASPECT * h { Arrangement::Stacked } else { Arrangement::SideBySide };
        let mut lists = options.panels();
        let inner = Rect::new(0.0, 0.0, w, h).inset(margins::OUTER, margins::OUTER, margins::OUTER, margins::OUTER);
        let (mut stage_area, plot_area) = split(inner, arrangement, !lists.analysis.is_empty());
        let mut panels = Vec::with_capacity(lists.stage.len() + lists.plots.len() + lists.analysis.len());
        // A single arm in a tall stage column leaves room under its square: ρ(δ) goes there.
        let under_arm = arrangement == Arrangement::SideBySide
            && lists.stage.len() == 1
            && stage_area.h - (stage_area.w + margins::STAGE_TOP) >= UNDER_ARM_MIN_HEIGHT;
        if under_arm {
            if let Some(i) = lists.analysis.iter().position(|k| *k == PanelKind::RhoCurve) {
                lists.analysis.remove(i);
                let arm_h = (stage_area.w + margins::STAGE_TOP)
                    .max(stage_area.h * 0.55)
                    .min(stage_area.h - UNDER_ARM_MIN_HEIGHT);
                let below = stage_area.inset(0.0, arm_h + margins::GAP, 0.0, 0.0);
                stage_area.h = arm_h;
                panels_push_analysis(below, PanelKind::RhoCurve, &mut panels);
            }
        }
        // Elsewhere it joins the analysis row only where that has room for one more panel: it shows
        // a slice of the map, which stays.
        if !under_arm && plot_area.h < ROOMY_PLOT_COLUMN {
            lists.analysis.retain(|k| *k != PanelKind::RhoCurve);
        }
        stage_panels(stage_area, &lists.stage, &mut panels);
        plot_column(plot_area, &lists.plots, &lists.analysis, &mut panels);
        // Panels in reading order: the stage first, then the plots, then the analysis row.
        panels.sort_by_key(|p| panel_order(p.kind));
        Layout { css_width: w, css_height: h, device_pixel_ratio: dpr, arrangement, panels }
    }

    /// The first panel of the given kind, if shown.
    pub fn panel(&self, kind: PanelKind) -> Option<&Panel> {
        self.panels.iter().find(|p| p.kind == kind)
    }

    /// Canvas size in physical pixels (what `canvas.width`/`height` must be), at least 1 × 1.
    pub fn physical_size(&self) -> (u32, u32) {
        let px = |css: f64| (css * self.device_pixel_ratio).round().clamp(1.0, u32::MAX as f64) as u32;
        (px(self.css_width), px(self.css_height))
    }

    /// A CSS-pixel rectangle in physical pixels.
    pub fn to_physical(&self, r: Rect) -> Rect {
        r.scaled(self.device_pixel_ratio)
    }
}

/// A plot column at least this tall (CSS px) takes ρ(δ) into its analysis row.
pub const ROOMY_PLOT_COLUMN: f64 = 640.0;

/// Height a panel under the arm needs at least (with its label gutters), CSS px.
pub const UNDER_ARM_MIN_HEIGHT: f64 = 150.0;

/// An analysis panel filling `cell` (less its label gutters).
fn panels_push_analysis(cell: Rect, kind: PanelKind, out: &mut Vec<Panel>) {
    out.push(Panel {
        kind,
        rect: cell.inset(margins::ANALYSIS_LEFT, margins::PLOT_TOP, margins::PLOT_RIGHT, margins::PLOT_BOTTOM),
    });
}

/// Where a panel kind comes in the list of panels.
fn panel_order(kind: PanelKind) -> u8 {
    match kind {
        PanelKind::Arm => 0,
        PanelKind::ArmB => 1,
        PanelKind::Error1 => 2,
        PanelKind::Error2 => 3,
        PanelKind::Torque => 4,
        PanelKind::Poles | PanelKind::ZPlane => 5,
        PanelKind::RhoCurve => 6,
        PanelKind::MapOff => 7,
        PanelKind::MapOn => 8,
    }
}

/// Splits the inner area into the stage area and the plot area.
fn split(inner: Rect, arrangement: Arrangement, analysis: bool) -> (Rect, Rect) {
    match arrangement {
        Arrangement::SideBySide => {
            let share = if analysis { STAGE_WIDTH_SHARE_WITH_ANALYSIS } else { STAGE_WIDTH_SHARE };
            let stage_w = (inner.w * share).round();
            let stage = Rect::new(inner.x, inner.y, stage_w, inner.h);
            let plots = inner.inset(stage_w + margins::GAP, 0.0, 0.0, 0.0);
            (stage, plots)
        }
        Arrangement::Stacked => {
            let share = if analysis { STAGE_HEIGHT_SHARE_WITH_ANALYSIS } else { STAGE_HEIGHT_SHARE };
            let stage_h = (inner.h * share).round();
            let stage = Rect::new(inner.x, inner.y, inner.w, stage_h);
            let plots = inner.inset(0.0, stage_h + margins::GAP, 0.0, 0.0);
            (stage, plots)
        }
    }
}

/// Stage panels share their area in equal columns or equal rows, whichever gives each arm the
/// larger square (two arms go side by side on a wide stage, one above the other on a tall one);
/// each panel sits below a caption strip.
fn stage_panels(area: Rect, kinds: &[PanelKind], out: &mut Vec<Panel>) {
    let n = kinds.len().max(1) as f64;
    let column_w = (area.w - margins::GAP * (n - 1.0)).max(0.0) / n;
    let column_h = (area.h - margins::STAGE_TOP).max(0.0);
    let row_h = (area.h - margins::GAP * (n - 1.0)).max(0.0) / n;
    let row_inner_h = (row_h - margins::STAGE_TOP).max(0.0);
    let in_columns = column_w.min(column_h) >= area.w.min(row_inner_h);
    for (i, &kind) in kinds.iter().enumerate() {
        let cell = if in_columns {
            Rect::new(area.x + i as f64 * (column_w + margins::GAP), area.y, column_w, area.h)
        } else {
            Rect::new(area.x, area.y + i as f64 * (row_h + margins::GAP), area.w, row_h)
        };
        out.push(Panel { kind, rect: cell.inset(0.0, margins::STAGE_TOP, 0.0, 0.0) });
    }
}

/// Row heights (time-plot row, analysis row) for `rows` analysis rows below `time_rows` time
/// plots in a column `height` tall: in proportion to their weights, but with every data area at
/// least [`MIN_PLOT_HEIGHT`] tall when that fits.
fn row_heights(height: f64, time_rows: usize, rows: usize) -> (f64, f64) {
    let weight = if rows > 1 { WRAPPED_ANALYSIS_ROW_WEIGHT } else { ANALYSIS_ROW_WEIGHT };
    let (nt, na) = (time_rows as f64, rows as f64);
    let unit = height / (nt + na * weight).max(1e-9);
    let (mut time_row, mut analysis_row) = (unit, unit * weight);
    let min_row = MIN_PLOT_HEIGHT + margins::PLOT_TOP + margins::PLOT_BOTTOM;
    if nt * min_row + na * min_row <= height {
        if time_rows > 0 && time_row < min_row {
            time_row = min_row;
            analysis_row = (height - nt * time_row) / na.max(1.0);
        } else if rows > 0 && analysis_row < min_row {
            analysis_row = min_row;
            time_row = (height - na * analysis_row) / nt.max(1.0);
        }
    }
    (time_row, analysis_row)
}

/// The time plots stacked, then the analysis panels in `columns` columns (rows filled from the
/// bottom, so a short first row holds the pole plot alone and the maps stay together).
fn place_plot_column(area: Rect, plots: &[PanelKind], analysis: &[PanelKind], columns: usize, out: &mut Vec<Panel>) {
    let columns = columns.clamp(1, analysis.len().max(1));
    let rows = analysis.len().div_ceil(columns);
    let (time_row, analysis_row) = row_heights(area.h, plots.len(), rows);
    for (i, &kind) in plots.iter().enumerate() {
        let row = Rect::new(area.x, area.y + i as f64 * time_row, area.w, time_row);
        out.push(Panel {
            kind,
            rect: row.inset(margins::PLOT_LEFT, margins::PLOT_TOP, margins::PLOT_RIGHT, margins::PLOT_BOTTOM),
        });
    }
    let top = area.y + plots.len() as f64 * time_row;
    let first_row = analysis.len() - (rows.saturating_sub(1)) * columns;
    let mut next = 0;
    for r in 0..rows {
        let count = if r == 0 { first_row } else { columns };
        let cell_w = area.w / count.max(1) as f64;
        for c in 0..count {
            let Some(&kind) = analysis.get(next) else { break };
            next += 1;
            let cell = Rect::new(area.x + c as f64 * cell_w, top + r as f64 * analysis_row, cell_w, analysis_row);
            out.push(Panel {
                kind,
                rect: cell.inset(margins::ANALYSIS_LEFT, margins::PLOT_TOP, margins::PLOT_RIGHT, margins::PLOT_BOTTOM),
            });
        }
    }
}

/// Lays out the plot column, choosing how many columns the analysis panels use: the choice that
/// makes the smallest data-area side (time plots' heights, analysis panels' widths and heights)
/// largest; fewer columns win ties.
fn plot_column(area: Rect, plots: &[PanelKind], analysis: &[PanelKind], out: &mut Vec<Panel>) {
    if analysis.is_empty() {
        place_plot_column(area, plots, analysis, 1, out);
        return;
    }
    let mut best = (analysis.len(), f64::NEG_INFINITY);
    let mut trial = Vec::with_capacity(plots.len() + analysis.len());
    for columns in 1..=analysis.len() {
        trial.clear();
        place_plot_column(area, plots, analysis, columns, &mut trial);
        let score = trial
            .iter()
            .map(|p| if p.kind.is_time_plot() { p.rect.h } else { p.rect.w.min(p.rect.h) })
            .fold(f64::INFINITY, f64::min);
        if score > best.1 + 1e-9 {
            best = (columns, score);
        }
    }
    place_plot_column(area, plots, analysis, best.0, out);
}
