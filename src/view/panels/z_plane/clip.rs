//! Convex polygons cut to a rectangle, in fixed-size buffers: the z-plane's disk and ring are
//! far larger than the panel when zoomed in, and only the part in view is drawn (nothing spills
//! onto the gutters, and the vertex count stays bounded).

use crate::plot::Color;
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;

/// The most corners a polygon handed to [`fill_clipped`] may have.
pub const MAX_CORNERS: usize = 140;
/// Cutting by four sides adds at most four corners.
const MAX_OUT: usize = MAX_CORNERS + 4;

/// The vertices [`fill_clipped`] writes for a polygon of `corners` corners, at most.
pub const fn fill_vertices(corners: usize) -> usize {
    3 * (corners + 4 - 2)
}

/// Fills the convex polygon `poly` (corners in order, either sense) where it lies inside `rect`
/// (Sutherland–Hodgman against the four sides, then a fan). Corners beyond [`MAX_CORNERS`] are
/// ignored. Allocates nothing.
pub fn fill_clipped(painter: &mut Painter, poly: &[Point], rect: Rect, color: Color) {
    let mut a = [[0.0; 2]; MAX_OUT];
    let mut b = [[0.0; 2]; MAX_OUT];
    let n = poly.len().min(MAX_CORNERS);
    a[..n].copy_from_slice(&poly[..n]);
    // Each side: (axis, bound, keep the side where the coordinate is ≥ bound?).
    let sides = [(0, rect.x, true), (0, rect.right(), false), (1, rect.y, true), (1, rect.bottom(), false)];
    let mut len = n;
    for (axis, bound, above) in sides {
        len = clip_side(&a[..len], &mut b, axis, bound, above);
        a[..len].copy_from_slice(&b[..len]);
        if len < 3 {
            return;
        }
    }
    for i in 1..len - 1 {
        painter.triangle(a[0], a[i], a[i + 1], color);
    }
}

/// One Sutherland–Hodgman step: the part of `input` on the kept side of `coordinate = bound`.
fn clip_side(input: &[Point], out: &mut [Point; MAX_OUT], axis: usize, bound: f64, above: bool) -> usize {
    let inside = |p: &Point| if above { p[axis] >= bound } else { p[axis] <= bound };
    let mut len = 0;
    let mut push = |p: Point, len: &mut usize| {
        if *len < MAX_OUT {
            out[*len] = p;
            *len += 1;
        }
    };
    let Some(&last) = input.last() else { return 0 };
    let mut prev = last;
    for &cur in input {
        let (pi, ci) = (inside(&prev), inside(&cur));
        if pi != ci {
            let t = (bound - prev[axis]) / (cur[axis] - prev[axis]);
            let mut x = [prev[0] + t * (cur[0] - prev[0]), prev[1] + t * (cur[1] - prev[1])];
            x[axis] = bound;
            push(x, &mut len);
        }
        if ci {
            push(cur, &mut len);
        }
        prev = cur;
    }
    len
}

/// The segment a–b cut to `rect` (Liang–Barsky), or None if it misses.
pub fn clip_segment(a: Point, b: Point, rect: Rect) -> Option<(Point, Point)> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in
        [(-d[0], a[0] - rect.x), (d[0], rect.right() - a[0]), (-d[1], a[1] - rect.y), (d[1], rect.bottom() - a[1])]
    {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then(|| ([a[0] + t0 * d[0], a[1] + t0 * d[1]], [a[0] + t1 * d[0], a[1] + t1 * d[1]]))
}
