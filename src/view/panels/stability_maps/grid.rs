//! Stability maps: ρ over (δ, α) with both axes logarithmic, the cells coloured by ρ or by
//! ln ρ/δ ([`Measure`]), the ρ = 1 contour by marching squares (the same line under both), and
//! the marker of the current configuration.
//!
//! The grid arrives from the session's map job row by row (ρ row-major by α, rows not yet
//! computed missing). The cells and the contour change only when the page hands over new rows, so they are
//! tessellated once into the scene's static layer; only the markers are drawn every frame.

use crate::plot::color::Measure;
use crate::plot::contour::{chain_segments, marching_squares};
use crate::plot::ticks::log_ticks;
use crate::plot::{palette, Color};
use crate::schema::PanelKind;
pub use crate::session::map_cache::MapSide;
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;

/// The panel that shows a side's map.
pub fn panel_of(side: MapSide) -> PanelKind {
    match side {
        MapSide::Off => PanelKind::MapOff,
        MapSide::On => PanelKind::MapOn,
    }
}

/// The map a panel shows, if it is a map.
pub fn side_of(kind: PanelKind) -> Option<MapSide> {
    match kind {
        PanelKind::MapOff => Some(MapSide::Off),
        PanelKind::MapOn => Some(MapSide::On),
        _ => None,
    }
}

/// δ range of an empty map panel, s.
pub const DEFAULT_DELTA_RANGE: [f64; 2] = [0.002, 0.25];
/// α range of an empty map panel, 1/s.
pub const DEFAULT_ALPHA_RANGE: [f64; 2] = [0.1, 5.0];

/// A stability map as the scene keeps it: the grid and ρ, NaN where not computed yet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StabilityGrid {
    deltas: Vec<f64>,
    alphas: Vec<f64>,
    /// `alphas.len() × deltas.len()`, row-major by α.
    rho: Vec<f64>,
}

impl StabilityGrid {
    /// Copies a (possibly partial) map: `rho` holds the first rows, row-major by α. Both axes
    /// need at least two strictly increasing, positive, finite values. Keeps its memory, so
    /// handing over the same map again as rows arrive does not allocate.
    pub fn set(&mut self, deltas: &[f64], alphas: &[f64], rho: &[f64]) -> Result<(), String> {
        let axis_ok = |v: &[f64]| {
            v.len() >= 2 && v.iter().all(|x| x.is_finite() && *x > 0.0) && v.windows(2).all(|w| w[1] > w[0])
        };
        if !axis_ok(deltas) || !axis_ok(alphas) {
            return Err("a stability map needs at least two increasing, positive sampling periods and α values".into());
        }
        let cells = deltas.len() * alphas.len();
        if rho.len() > cells {
            return Err(format!(
                "a {} × {} stability map has {cells} cells, got {} values",
                alphas.len(),
                deltas.len(),
                rho.len()
            ));
        }
        self.deltas.clear();
        self.deltas.extend_from_slice(deltas);
        self.alphas.clear();
        self.alphas.extend_from_slice(alphas);
        self.rho.clear();
        self.rho.extend_from_slice(rho);
        self.rho.resize(cells, f64::NAN);
        Ok(())
    }

    /// Forgets the map.
    pub fn clear(&mut self) {
        self.deltas.clear();
        self.alphas.clear();
        self.rho.clear();
    }

    pub fn is_empty(&self) -> bool {
        self.deltas.is_empty()
    }

    pub fn deltas(&self) -> &[f64] {
        &self.deltas
    }

    pub fn alphas(&self) -> &[f64] {
        &self.alphas
    }

    /// ρ row-major by α, NaN where not computed.
    pub fn rho(&self) -> &[f64] {
        &self.rho
    }

    /// ρ at (α index, δ index); NaN outside the grid or where not computed.
    pub fn at(&self, alpha_index: usize, delta_index: usize) -> f64 {
        if delta_index >= self.deltas.len() {
            return f64::NAN;
        }
        self.rho.get(alpha_index * self.deltas.len() + delta_index).copied().unwrap_or(f64::NAN)
    }

    /// The grid's δ (s) and ρ at the grid point nearest (δ, α) in log scale (the δ gives that
    /// cell's ln ρ/δ); ρ is NaN outside the grid or not computed.
    pub fn near(&self, delta: f64, alpha: f64) -> (f64, f64) {
        let nearest = |values: &[f64], v: f64| {
            (0..values.len()).min_by(|&i, &j| (values[i] / v).ln().abs().total_cmp(&(values[j] / v).ln().abs()))
        };
        match (nearest(&self.deltas, delta), nearest(&self.alphas, alpha)) {
            (Some(j), Some(i)) if delta > 0.0 && alpha > 0.0 => (self.deltas[j], self.at(i, j)),
            _ => (delta, f64::NAN),
        }
    }

    /// The δ range the panel shows: the grid's first and last δ, or the default when empty.
    pub fn delta_range(&self) -> [f64; 2] {
        match (self.deltas.first(), self.deltas.last()) {
            (Some(&a), Some(&b)) => [a, b],
            _ => DEFAULT_DELTA_RANGE,
        }
    }

    /// The α range the panel shows.
    pub fn alpha_range(&self) -> [f64; 2] {
        match (self.alphas.first(), self.alphas.last()) {
            (Some(&a), Some(&b)) => [a, b],
            _ => DEFAULT_ALPHA_RANGE,
        }
    }
}

/// A map panel's data area in physical pixels with logarithmic δ (x) and α (y) axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogFrame {
    pub rect: Rect,
    /// δ at the left and right edges.
    pub x_range: [f64; 2],
    /// α at the bottom and top edges.
    pub y_range: [f64; 2],
}

impl LogFrame {
    /// Horizontal pixel of ln δ = `lx` (not clamped).
    pub fn x_log(&self, lx: f64) -> f64 {
        let (a, b) = (self.x_range[0].ln(), self.x_range[1].ln());
        self.rect.x + self.rect.w * (lx - a) / (b - a)
    }

    /// Vertical pixel of ln α = `ly` (not clamped).
    pub fn y_log(&self, ly: f64) -> f64 {
        let (a, b) = (self.y_range[0].ln(), self.y_range[1].ln());
        self.rect.bottom() - self.rect.h * (ly - a) / (b - a)
    }

    /// The pixel of (δ, α).
    pub fn point(&self, delta: f64, alpha: f64) -> Point {
        [self.x_log(delta.ln()), self.y_log(alpha.ln())]
    }
}

/// About one tick label per this many CSS pixels along a map axis.
const TICK_SPACING_X: f64 = 46.0;
const TICK_SPACING_Y: f64 = 26.0;

/// The δ and α ticks of a map panel whose data area is `rect_css` (CSS pixels).
pub fn map_ticks(rect_css: Rect, grid: &StabilityGrid) -> (Vec<f64>, Vec<f64>) {
    let [d0, d1] = grid.delta_range();
    let [a0, a1] = grid.alpha_range();
    let nx = (rect_css.w / TICK_SPACING_X).floor().clamp(1.0, 20.0) as usize;
    let ny = (rect_css.h / TICK_SPACING_Y).floor().clamp(1.0, 20.0) as usize;
    (log_ticks(d0, d1, nx), log_ticks(a0, a1, ny))
}

/// Cell boundaries (in ln units) around grid values `ln_values`: midway between neighbours, the
/// outer ones at the first and last value (the panel shows exactly the grid's range).
fn boundaries(ln_values: &[f64], out: &mut Vec<f64>) {
    out.clear();
    let n = ln_values.len();
    if n == 0 {
        return;
    }
    out.push(ln_values[0]);
    for w in ln_values.windows(2) {
        out.push(0.5 * (w[0] + w[1]));
    }
    out.push(ln_values[n - 1]);
}

/// Draws a whole map panel's static part into `painter`: background, filled cells coloured by
/// `measure` (runs of equal colour merged into one quad), faint grid lines at the ticks and the
/// ρ = 1 contour (always from ρ: it is ln ρ/δ = 0 too).
/// Allocates (scratch vectors, the contour): call it when the map or the layout changes, not
/// per frame.
pub fn draw_map_static(
    painter: &mut Painter,
    frame: &LogFrame,
    grid: &StabilityGrid,
    ticks: (&[f64], &[f64]),
    measure: Measure,
    dpr: f64,
) {
    let r = frame.rect;
    painter.rect(r, palette::MAP_PENDING);
    if !grid.is_empty() {
        let ln_d: Vec<f64> = grid.deltas().iter().map(|d| d.ln()).collect();
        let ln_a: Vec<f64> = grid.alphas().iter().map(|a| a.ln()).collect();
        let (mut bx, mut by) = (Vec::new(), Vec::new());
        boundaries(&ln_d, &mut bx);
        boundaries(&ln_a, &mut by);
        let xs: Vec<f64> = bx.iter().map(|&l| frame.x_log(l)).collect();
        let ys: Vec<f64> = by.iter().map(|&l| frame.y_log(l)).collect();
        let color_at = |i: usize, j: usize| measure.color(grid.at(i, j), grid.deltas()[j]);
        for i in 0..ln_a.len() {
            let (y_bottom, y_top) = (ys[i], ys[i + 1]);
            let mut j = 0;
            while j < ln_d.len() {
                let color = color_at(i, j);
                let mut k = j + 1;
                while k < ln_d.len() && color_at(i, k) == color {
                    k += 1;
                }
                painter.rect(Rect::new(xs[j], y_top, xs[k] - xs[j], y_bottom - y_top), color);
                j = k;
            }
        }
        draw_grid_lines(painter, frame, ticks, dpr);
        let segments = marching_squares(&ln_d, &ln_a, grid.rho(), 1.0);
        let lines = chain_segments(&segments);
        let to_px = |p: &[f64; 2]| [frame.x_log(p[0]), frame.y_log(p[1])];
        for line in &lines {
            painter.polyline(line.iter().map(to_px), 4.0 * dpr, palette::CONTOUR_HALO);
        }
        for line in &lines {
            painter.polyline(line.iter().map(to_px), 2.0 * dpr, palette::CONTOUR);
        }
    } else {
        draw_grid_lines(painter, frame, ticks, dpr);
    }
}

/// Faint lines at the ticks; those on the panel's edges are left to the frame (they would poke
/// out of the panel by half their width).
fn draw_grid_lines(painter: &mut Painter, frame: &LogFrame, ticks: (&[f64], &[f64]), dpr: f64) {
    let r = frame.rect;
    let w = dpr.max(1.0);
    for &d in ticks.0 {
        let x = frame.x_log(d.ln());
        if x - w / 2.0 >= r.x && x + w / 2.0 <= r.right() {
            painter.line([x, r.y], [x, r.bottom()], w, palette::MAP_GRID);
        }
    }
    for &a in ticks.1 {
        let y = frame.y_log(a.ln());
        if y - w / 2.0 >= r.y && y + w / 2.0 <= r.bottom() {
            painter.line([r.x, y], [r.right(), y], w, palette::MAP_GRID);
        }
    }
}

/// An upper bound on the vertices [`draw_map_marker`] writes (circles ≤ 128 segments).
pub const MARKER_VERTEX_BUDGET: usize = 2 * 128 * 3 + 2 * 128 * 6 + 8 * 6 + 24;

/// The marker of a configuration (δ, α1) on a map: a crosshair with a solid centre when the map
/// is the one for its preliminary feedback (`filled`), a hollow ring on the other map. Outside
/// the map's range it becomes a chevron at the nearest edge, pointing to where it would be.
pub fn draw_map_marker(
    painter: &mut Painter,
    frame: &LogFrame,
    delta: f64,
    alpha: f64,
    filled: bool,
    color: Color,
    dpr: f64,
) {
    if !(delta > 0.0 && alpha > 0.0 && delta.is_finite() && alpha.is_finite()) {
        return;
    }
    let p = frame.point(delta, alpha);
    let inner = frame.rect.inset(6.0 * dpr, 6.0 * dpr, 6.0 * dpr, 6.0 * dpr);
    let c = [p[0].clamp(inner.x, inner.right()), p[1].clamp(inner.y, inner.bottom())];
    let outside = frame.rect.x > p[0] || p[0] > frame.rect.right() || frame.rect.y > p[1] || p[1] > frame.rect.bottom();
    if outside {
        let dir = [p[0] - c[0], p[1] - c[1]];
        painter.chevron(c, dir, 5.0 * dpr, 3.5 * dpr, palette::MARKER_HALO);
        painter.chevron(c, dir, 5.0 * dpr, 1.75 * dpr, color);
        return;
    }
    let r = 6.0 * dpr;
    if filled {
        let arm = 12.0 * dpr;
        for (a, b) in [([c[0] - arm, c[1]], [c[0] - r, c[1]]), ([c[0] + r, c[1]], [c[0] + arm, c[1]])] {
            painter.line(a, b, 3.5 * dpr, palette::MARKER_HALO);
            painter.line(a, b, 1.5 * dpr, color);
        }
        for (a, b) in [([c[0], c[1] - arm], [c[0], c[1] - r]), ([c[0], c[1] + r], [c[0], c[1] + arm])] {
            painter.line(a, b, 3.5 * dpr, palette::MARKER_HALO);
            painter.line(a, b, 1.5 * dpr, color);
        }
        painter.circle(c, r, palette::MARKER_HALO);
        painter.ring(c, r * 0.8, 1.5 * dpr, color);
        painter.circle(c, r * 0.45, color);
    } else {
        painter.ring(c, r, 3.5 * dpr, palette::MARKER_HALO);
        painter.ring(c, r, 1.5 * dpr, color);
    }
}
