//! Where each panel goes on the canvas.
//!
//! The canvas is split into a *stage* (the arm picture) and a column of *plots* (time traces).
//! On a wide canvas the stage takes the left ≈ 40 % and the plots stack on the right; on a narrow
//! or portrait canvas the stage sits on top and the plots stack below it.
//!
//! Panel rectangles are in CSS pixels and, for plots, are exactly the data area: the axis ranges
//! map linearly onto them. Gutters around each plot are left free for the HTML tick labels and
//! titles that the page places over the canvas.
//!
//! The lists of panels are data ([`PanelKind`] values), so later panels — a pole plot, a
//! stability map, a second arm for a side-by-side comparison — are added by extending the enum
//! and [`LayoutOptions::panels`], not by rewriting the arithmetic.

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

/// What a panel shows. New kinds (pole plot, stability map, second arm) will be added here.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PanelKind {
    /// The arm, its motor, the flexible joint and the reference arm.
    Arm,
    /// Tracking error of link 1, e1 = q1 − q_d1 over time.
    Error1,
    /// Tracking error of link 2, e2 = q2 − q_d2 over time.
    Error2,
    /// Applied torques T1, T2 over time.
    Torque,
}

impl PanelKind {
    /// The identifier the page sees in `Renderer.layout()`.
    pub fn id(self) -> &'static str {
        match self {
            PanelKind::Arm => "arm",
            PanelKind::Error1 => "e1",
            PanelKind::Error2 => "e2",
            PanelKind::Torque => "torque",
        }
    }

    /// True for panels that plot quantities against time.
    pub fn is_time_plot(self) -> bool {
        matches!(self, PanelKind::Error1 | PanelKind::Error2 | PanelKind::Torque)
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
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LayoutOptions {
    /// Adds the torque panel below the error panels.
    pub show_torque: bool,
}

impl LayoutOptions {
    /// The stage panels (shown side by side) and the plot panels (stacked), in order.
    pub fn panels(&self) -> (Vec<PanelKind>, Vec<PanelKind>) {
        let stage = vec![PanelKind::Arm];
        let mut plots = vec![PanelKind::Error1, PanelKind::Error2];
        if self.show_torque {
            plots.push(PanelKind::Torque);
        }
        (stage, plots)
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
    /// Above the stage: room for a caption such as "spring twist ×20".
    pub const STAGE_TOP: f64 = 22.0;
}

/// Share of the canvas width given to the stage on a wide canvas.
pub const STAGE_WIDTH_SHARE: f64 = 0.4;
/// Share of the canvas height given to the stage on a narrow canvas.
pub const STAGE_HEIGHT_SHARE: f64 = 0.42;
/// Canvases narrower than this (CSS px), or taller than wide × [`PORTRAIT_ASPECT`], stack.
pub const NARROW_WIDTH: f64 = 640.0;
/// Width / height below which the canvas counts as portrait.
pub const PORTRAIT_ASPECT: f64 = 1.05;

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
        let (stage_kinds, plot_kinds) = options.panels();
        let inner = Rect::new(0.0, 0.0, w, h).inset(margins::OUTER, margins::OUTER, margins::OUTER, margins::OUTER);
        let (stage_area, plot_area) = split(inner, arrangement);
        let mut panels = Vec::with_capacity(stage_kinds.len() + plot_kinds.len());
        panels.extend(side_by_side(stage_area, &stage_kinds));
        panels.extend(stacked_plots(plot_area, &plot_kinds));
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

/// Splits the inner area into the stage area and the plot area.
fn split(inner: Rect, arrangement: Arrangement) -> (Rect, Rect) {
    match arrangement {
        Arrangement::SideBySide => {
            let stage_w = (inner.w * STAGE_WIDTH_SHARE).round();
            let stage = Rect::new(inner.x, inner.y, stage_w, inner.h);
            let plots = inner.inset(stage_w + margins::GAP, 0.0, 0.0, 0.0);
            (stage, plots)
        }
        Arrangement::Stacked => {
            let stage_h = (inner.h * STAGE_HEIGHT_SHARE).round();
            let stage = Rect::new(inner.x, inner.y, inner.w, stage_h);
            let plots = inner.inset(0.0, stage_h + margins::GAP, 0.0, 0.0);
            (stage, plots)
        }
    }
}

/// Stage panels share their area in equal columns, each below a caption strip.
fn side_by_side(area: Rect, kinds: &[PanelKind]) -> impl Iterator<Item = Panel> + '_ {
    let n = kinds.len().max(1) as f64;
    let column_w = (area.w - margins::GAP * (n - 1.0)).max(0.0) / n;
    kinds.iter().enumerate().map(move |(i, &kind)| {
        let column = Rect::new(area.x + i as f64 * (column_w + margins::GAP), area.y, column_w, area.h);
        Panel { kind, rect: column.inset(0.0, margins::STAGE_TOP, 0.0, 0.0) }
    })
}

/// Plot panels share their area in equal rows; each row keeps gutters for its labels.
fn stacked_plots(area: Rect, kinds: &[PanelKind]) -> impl Iterator<Item = Panel> + '_ {
    let n = kinds.len().max(1) as f64;
    let row_h = area.h / n;
    kinds.iter().enumerate().map(move |(i, &kind)| {
        let row = Rect::new(area.x, area.y + i as f64 * row_h, area.w, row_h);
        Panel {
            kind,
            rect: row.inset(margins::PLOT_LEFT, margins::PLOT_TOP, margins::PLOT_RIGHT, margins::PLOT_BOTTOM),
        }
    })
}
