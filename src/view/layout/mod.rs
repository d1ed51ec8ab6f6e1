//! Where each panel goes on the canvas, decided from its size and aspect.
//!
//! The panels are the *stage* (the arm picture, or two arms when two runs are compared), the
//! *time plots* (errors, torques) and the *analysis panels* (pole plot, ρ(δ), the two stability
//! maps). A wide canvas shows them all in two bands: the stage and the time plots side by side on
//! top, the analysis panels across the whole width below, with the split and the number of
//! columns chosen so that the smallest panel is as large as it can be ([`Arrangement::Bands`]).
//! Without analysis panels (the intro) the stage sits left of the time plots. A portrait canvas
//! stacks stage, time plots and analysis panels. A phone-sized canvas shows one [`Tab`] at a time:
//! the arm and its errors, the poles and ρ(δ), or the maps.
//!
//! Panel rectangles are in CSS pixels and, for plots, are exactly the data area: the axis ranges
//! map linearly onto them. Gutters around each plot are left free for the HTML tick labels and
//! titles that the page places over the canvas.
//!
//! The lists of panels are data ([`PanelKind`] values): new panels are added by extending the
//! enum and [`LayoutOptions::panels`], not by rewriting the arithmetic.

use serde::Serialize;

mod asked;

pub use super::rect::Rect;
pub use crate::schema::{PanelKind, Tab};
pub use asked::{LayoutOptions, Panel, PanelLists};

/// How the panels are arranged.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Arrangement {
    /// Wide canvas: stage on the left, a column of plots on the right (the time plots, and any
    /// analysis panels under them when that suits better than bands).
    SideBySide,
    /// Wide canvas with analysis panels: stage and time plots side by side in a top band, the
    /// analysis panels across the whole width below them.
    Bands,
    /// Portrait canvas: stage on top, the time plots below, the analysis panels below them.
    Stacked,
    /// Narrow canvas (a phone): only the panels of one [`Tab`], stacked.
    Tabbed,
}

/// Margins in CSS pixels.
pub mod margins {
    /// Around the whole canvas.
    pub const OUTER: f64 = 8.0;
    /// Between the stage and the plot column, and between bands.
    pub const GAP: f64 = 12.0;
    /// Left of a time plot: room for the y tick labels.
    pub const PLOT_LEFT: f64 = 60.0;
    /// Above a time plot: its header (the y label left, the x label right).
    pub const PLOT_TOP: f64 = 22.0;
    /// Below a time plot: the time tick labels.
    pub const PLOT_BOTTOM: f64 = 20.0;
    /// Right of a plot.
    pub const PLOT_RIGHT: f64 = 10.0;
    /// Left of an analysis panel: its tick labels are short ("−40", "0.2").
    pub const ANALYSIS_LEFT: f64 = 44.0;
    /// Above an analysis panel: its title, then its y label.
    pub const ANALYSIS_TOP: f64 = 40.0;
    /// Below an analysis panel: the tick labels, then its x label.
    pub const ANALYSIS_BOTTOM: f64 = 40.0;
    /// Above the stage: room for a caption such as "arm, top view".
    pub const STAGE_TOP: f64 = 22.0;
}

/// The label gutters (left, top, right, bottom) around a panel's rectangle, CSS px.
pub fn gutters(kind: PanelKind) -> [f64; 4] {
    use margins::*;
    if kind.is_stage() {
        [0.0, STAGE_TOP, 0.0, 0.0]
    } else if kind.is_analysis() {
        [ANALYSIS_LEFT, ANALYSIS_TOP, PLOT_RIGHT, ANALYSIS_BOTTOM]
    } else {
        [PLOT_LEFT, PLOT_TOP, PLOT_RIGHT, PLOT_BOTTOM]
    }
}

/// Share of the canvas width given to the stage on a wide canvas without analysis panels.
pub const STAGE_WIDTH_SHARE: f64 = 0.4;
/// The same when the analysis panels sit in the column right of it.
pub const STAGE_WIDTH_SHARE_WITH_ANALYSIS: f64 = 0.34;
/// Share of the canvas height given to the stage on a portrait canvas.
pub const STAGE_HEIGHT_SHARE: f64 = 0.42;
/// The same when the analysis panels are shown.
pub const STAGE_HEIGHT_SHARE_WITH_ANALYSIS: f64 = 0.3;
/// Canvases narrower than this (CSS px) show one tab at a time ...
pub const TABBED_WIDTH: f64 = 600.0;
/// ... and so do wider ones where showing every panel at once would leave one with a data-area
/// side (a time plot's height, an analysis panel's shorter side) below this, CSS px.
pub const MIN_READABLE_SIDE: f64 = 70.0;
/// Width / height below which the canvas counts as portrait.
pub const PORTRAIT_ASPECT: f64 = 1.05;
/// Height of one analysis row relative to one time-plot row when stacked (a single row) ...
pub const ANALYSIS_ROW_WEIGHT: f64 = 1.6;
/// ... and per row when the analysis panels wrap onto several rows.
pub const WRAPPED_ANALYSIS_ROW_WEIGHT: f64 = 1.25;
/// A time plot's or analysis panel's data area is kept at least this tall (CSS px) when the
/// canvas has room for it, by shrinking the other rows towards the same minimum.
pub const MIN_PLOT_HEIGHT: f64 = 60.0;
/// The least data height a stacked time plot is given, when the stage can make room for it, CSS px.
const MIN_STACKED_PLOT: f64 = 16.0;
/// The top band's share of the height that the band layout tries, from … to … in steps.
const BAND_SHARES: [f64; 10] = [0.40, 0.44, 0.48, 0.52, 0.56, 0.60, 0.64, 0.68, 0.72, 0.76];

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
    /// The tabs offered (a narrow canvas; empty otherwise) and the one shown.
    pub tabs: Vec<Tab>,
    pub tab: Option<Tab>,
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
        let lists = options.panels();
        let inner = Rect::new(0.0, 0.0, w, h).inset(margins::OUTER, margins::OUTER, margins::OUTER, margins::OUTER);
        let mut panels = Vec::with_capacity(lists.stage.len() + lists.plots.len() + lists.analysis.len());
        let portrait = w < PORTRAIT_ASPECT * h;
        // Tabs only where there is something to switch between: panels on two tabs or more.
        let offered = options.tabs();
        let can_tab = offered.len() > 1;
        let mut tabbed = can_tab && w < TABBED_WIDTH;
        if !tabbed && !lists.analysis.is_empty() {
            // Everything at once only where everything stays readable; else one tab at a time.
            let all = Layout::compute_all(inner, &lists, portrait, &mut panels);
            if !can_tab || smallest_side(&panels) >= MIN_READABLE_SIDE {
                crate::sort::sort_by_key(&mut panels, |p| p.kind.order());
                return Layout {
                    css_width: w,
                    css_height: h,
                    device_pixel_ratio: dpr,
                    arrangement: all,
                    panels,
                    tabs: Vec::new(),
                    tab: None,
                };
            }
            panels.clear();
            tabbed = true;
        }
        let (arrangement, tabs, tab) = if tabbed {
            let tab = if offered.contains(&options.tab) { options.tab } else { offered[0] };
            match tab {
                Tab::Run => {
                    run_panels(inner, &lists, portrait, &mut panels);
                }
                _ => {
                    let shown: Vec<PanelKind> = lists.analysis.iter().copied().filter(|k| tab.holds(*k)).collect();
                    plot_column(inner, &[], &shown, &mut panels);
                }
            }
            (Arrangement::Tabbed, offered, Some(tab))
        } else {
            // No analysis panels: the stage and the time plots (either may be left out).
            let arrangement = run_panels(inner, &lists, portrait, &mut panels);
            (arrangement, Vec::new(), None)
        };
        // Panels in reading order: the stage first, then the plots, then the analysis panels.
        crate::sort::sort_by_key(&mut panels, |p| p.kind.order());
        Layout { css_width: w, css_height: h, device_pixel_ratio: dpr, arrangement, panels, tabs, tab }
    }

    /// Every panel at once (with analysis panels): stacked on a portrait canvas; else two bands,
    /// or the stage beside one column of everything else when that gives the smallest panel more
    /// room (few analysis panels under many time plots).
    fn compute_all(inner: Rect, lists: &PanelLists, portrait: bool, out: &mut Vec<Panel>) -> Arrangement {
        if portrait {
            stacked(inner, &lists.stage, &lists.plots, &lists.analysis, out);
            return Arrangement::Stacked;
        }
        let mut column = Vec::with_capacity(out.capacity());
        let rest = beside_stage(inner, STAGE_WIDTH_SHARE_WITH_ANALYSIS, &lists.stage, false, &mut column);
        plot_column(rest, &lists.plots, &lists.analysis, &mut column);
        bands(inner, lists, out);
        if smallest_side(&column) > smallest_side(out) + 1e-9 {
            *out = column;
            Arrangement::SideBySide
        } else {
            Arrangement::Bands
        }
    }

    /// The first panel of the given kind, if shown.
    pub fn panel(&self, kind: PanelKind) -> Option<&Panel> {
        self.panels.iter().find(|p| p.kind == kind)
    }

    /// The panels `requested` asks for that this layout does not show (a narrow canvas shows
    /// one tab at a time), in the order asked: what an embed must announce rather than drop.
    pub fn hidden(&self, requested: &LayoutOptions) -> Vec<PanelKind> {
        requested.panels().all().filter(|k| self.panel(*k).is_none()).collect()
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

/// A panel filling `cell` less its label gutters.
fn panel_in(cell: Rect, kind: PanelKind) -> Panel {
    let [l, t, r, b] = gutters(kind);
    Panel { kind, rect: cell.inset(l, t, r, b) }
}

/// The stage and the time plots alone: stacked on a narrow canvas, else side by side. Either may
/// be left out (an embed of the arm alone, or of the plots alone): the other takes the canvas.
fn run_panels(inner: Rect, lists: &PanelLists, narrow: bool, out: &mut Vec<Panel>) -> Arrangement {
    if narrow {
        stacked(inner, &lists.stage, &lists.plots, &[], out);
        return Arrangement::Stacked;
    }
    let rest = beside_stage(inner, STAGE_WIDTH_SHARE, &lists.stage, lists.plots.is_empty(), out);
    place_plot_column(rest, &lists.plots, &[], 1, out);
    Arrangement::SideBySide
}

/// Places the stage at the left of `inner`, `share` of its width (all of it if `alone`: nothing
/// else is shown), and returns the area right of it (all of `inner` without a stage).
fn beside_stage(inner: Rect, share: f64, stage: &[PanelKind], alone: bool, out: &mut Vec<Panel>) -> Rect {
    if stage.is_empty() {
        return inner;
    }
    if alone {
        stage_panels(inner, stage, out);
        return Rect::new(inner.right(), inner.y, 0.0, inner.h);
    }
    let stage_w = (inner.w * share).round();
    stage_panels(Rect::new(inner.x, inner.y, stage_w, inner.h), stage, out);
    inner.inset(stage_w + margins::GAP, 0.0, 0.0, 0.0)
}

/// Stage on top, then the time plots, then the analysis panels (wrapped onto rows); without a
/// stage the plots start at the top, and a stage alone takes the whole height.
fn stacked(inner: Rect, stage: &[PanelKind], plots: &[PanelKind], analysis: &[PanelKind], out: &mut Vec<Panel>) {
    if stage.is_empty() {
        plot_column(inner, plots, analysis, out);
        return;
    }
    if plots.is_empty() && analysis.is_empty() {
        stage_panels(inner, stage, out);
        return;
    }
    let share = if analysis.is_empty() { STAGE_HEIGHT_SHARE } else { STAGE_HEIGHT_SHARE_WITH_ANALYSIS };
    let mut stage_h = (inner.h * share).round();
    if plots.contains(&PanelKind::Velocity) {
        // A fourth time plot on a small canvas: the stage gives up height until each plot keeps
        // a readable strip (at most down to a quarter of the canvas). Only with the velocity
        // panel, so that every other layout stays as it was.
        let needed = plots.len() as f64 * (margins::PLOT_TOP + margins::PLOT_BOTTOM + MIN_STACKED_PLOT)
            + if analysis.is_empty() {
                0.0
            } else {
                MIN_PLOT_HEIGHT + margins::ANALYSIS_TOP + margins::ANALYSIS_BOTTOM
            };
        stage_h = stage_h.min((inner.h - margins::GAP - needed).round()).max((inner.h * 0.25).round());
    }
    stage_panels(Rect::new(inner.x, inner.y, inner.w, stage_h), stage, out);
    plot_column(inner.inset(0.0, stage_h + margins::GAP, 0.0, 0.0), plots, analysis, out);
}

/// The band layout: a top band with the stage and the time plots side by side, the analysis
/// panels across the whole width below. The split and the number of analysis columns are chosen
/// to make the smallest data-area side (time plots' heights, analysis panels' widths and heights,
/// three quarters of an arm's side) largest.
fn bands(inner: Rect, lists: &PanelLists, out: &mut Vec<Panel>) {
    let mut best: Option<(f64, Vec<Panel>)> = None;
    let mut trial = Vec::with_capacity(lists.stage.len() + lists.plots.len() + lists.analysis.len());
    for share in BAND_SHARES {
        for columns in 1..=lists.analysis.len() {
            trial.clear();
            place_bands(inner, lists, share, columns, &mut trial);
            let score = smallest_side(&trial);
            if best.as_ref().is_none_or(|(b, _)| score > *b + 1e-9) {
                best = Some((score, trial.clone()));
            }
        }
    }
    out.extend(best.map(|(_, panels)| panels).unwrap_or_default());
}

/// What a layout is judged by: its smallest data-area side — a time plot's height, an analysis
/// panel's shorter side, three quarters of an arm's (an arm reads well smaller).
fn smallest_side(panels: &[Panel]) -> f64 {
    panels
        .iter()
        .map(|p| match p.kind {
            k if k.is_stage() => 0.75 * p.rect.w.min(p.rect.h),
            k if k.is_time_plot() => p.rect.h,
            _ => p.rect.w.min(p.rect.h),
        })
        .fold(f64::INFINITY, f64::min)
}

/// One candidate band layout.
fn place_bands(inner: Rect, lists: &PanelLists, share: f64, columns: usize, out: &mut Vec<Panel>) {
    // Without a stage and time plots there is no top band: the analysis panels take it all.
    let top_band = !(lists.stage.is_empty() && lists.plots.is_empty());
    let top_h = if top_band { (inner.h * share).round() } else { 0.0 };
    if !lists.stage.is_empty() {
        let arms = lists.stage.len() as f64;
        // The arms are squares as tall as the band (below their captions), at most half the width.
        let side = (top_h - margins::STAGE_TOP).min((inner.w * 0.5 - margins::GAP * (arms - 1.0)) / arms).max(0.0);
        let stage_w = side * arms + margins::GAP * (arms - 1.0);
        stage_panels(Rect::new(inner.x, inner.y, stage_w, top_h), &lists.stage, out);
        let plots = Rect::new(inner.x + stage_w + margins::GAP, inner.y, inner.w - stage_w - margins::GAP, top_h);
        place_plot_column(plots, &lists.plots, &[], 1, out);
    } else {
        place_plot_column(Rect::new(inner.x, inner.y, inner.w, top_h), &lists.plots, &[], 1, out);
    }
    let bottom = if top_band { inner.inset(0.0, top_h + margins::GAP, 0.0, 0.0) } else { inner };
    let rows = lists.analysis.len().div_ceil(columns.max(1));
    let row_h = bottom.h / rows.max(1) as f64;
    place_grid(bottom, &lists.analysis, columns, row_h, out);
}

/// Analysis panels in `columns` columns from `area`'s top, rows `row_h` tall (rows filled from
/// the bottom, so a short first row holds the pole plot alone and the maps stay together).
fn place_grid(area: Rect, analysis: &[PanelKind], columns: usize, row_h: f64, out: &mut Vec<Panel>) {
    let columns = columns.clamp(1, analysis.len().max(1));
    let rows = analysis.len().div_ceil(columns);
    let first_row = analysis.len() - (rows.saturating_sub(1)) * columns;
    let mut next = 0;
    for r in 0..rows {
        let count = if r == 0 { first_row } else { columns };
        let cell_w = area.w / count.max(1) as f64;
        for c in 0..count {
            let Some(&kind) = analysis.get(next) else { break };
            next += 1;
            out.push(panel_in(Rect::new(area.x + c as f64 * cell_w, area.y + r as f64 * row_h, cell_w, row_h), kind));
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
        out.push(panel_in(cell, kind));
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
    let min_time = MIN_PLOT_HEIGHT + margins::PLOT_TOP + margins::PLOT_BOTTOM;
    let min_analysis = MIN_PLOT_HEIGHT + margins::ANALYSIS_TOP + margins::ANALYSIS_BOTTOM;
    if nt * min_time + na * min_analysis <= height {
        if time_rows > 0 && time_row < min_time {
            time_row = min_time;
            analysis_row = (height - nt * time_row) / na.max(1.0);
        } else if rows > 0 && analysis_row < min_analysis {
            analysis_row = min_analysis;
            time_row = (height - na * analysis_row) / nt.max(1.0);
        }
    }
    (time_row, analysis_row)
}

/// The time plots stacked, then the analysis panels in `columns` columns.
fn place_plot_column(area: Rect, plots: &[PanelKind], analysis: &[PanelKind], columns: usize, out: &mut Vec<Panel>) {
    let columns = columns.clamp(1, analysis.len().max(1));
    let rows = analysis.len().div_ceil(columns);
    let (time_row, analysis_row) = row_heights(area.h, plots.len(), rows);
    for (i, &kind) in plots.iter().enumerate() {
        out.push(panel_in(Rect::new(area.x, area.y + i as f64 * time_row, area.w, time_row), kind));
    }
    let top = area.y + plots.len() as f64 * time_row;
    place_grid(Rect::new(area.x, top, area.w, area.bottom() - top), analysis, columns, analysis_row, out);
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
