//! The δ axis that ρ(δ) and the sensor study's panels share: δ on a log scale across a data area,
//! so that a δ sits at the same place in each; and the grid lines both draw at their ticks.

use crate::plot::palette;
use crate::view::painter::Painter;
use crate::view::rect::Rect;

/// A data area with a logarithmic δ axis across it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeltaAxis {
    pub rect: Rect,
    /// δ at the left and right edges, s.
    pub range: [f64; 2],
}

impl DeltaAxis {
    /// Horizontal pixel of δ (not clamped).
    pub fn x(&self, delta: f64) -> f64 {
        let [a, b] = self.range;
        self.rect.x + self.rect.w * (delta / a).ln() / (b / a).ln()
    }

    /// δ at horizontal pixel `x`, within the range.
    pub fn delta_at(&self, x: f64) -> f64 {
        let [a, b] = self.range;
        let f = ((x - self.rect.x) / self.rect.w).clamp(0.0, 1.0);
        a * (b / a).powf(f)
    }

    /// The grid: a vertical line at each δ tick inside the area (not on its edges), a horizontal
    /// one at each value tick's pixel `ys`.
    pub fn draw_grid(&self, painter: &mut Painter, deltas: &[f64], ys: impl Iterator<Item = f64>, dpr: f64) {
        let r = self.rect;
        let width = dpr.max(1.0);
        for &d in deltas {
            let x = self.x(d);
            if x > r.x + width && x < r.right() - width {
                painter.line([x, r.y], [x, r.bottom()], width, palette::GRID);
            }
        }
        for y in ys {
            if y > r.y + width && y < r.bottom() - width {
                painter.line([r.x, y], [r.right(), y], width, palette::GRID);
            }
        }
    }
}
