//! The level line of a gridded function by marching squares ([`marching_squares`]), joined into
//! polylines ([`chain_segments`]): the ρ = 1 contour of the stability maps on the canvas and in
//! the SVG figures.

use std::collections::HashMap;

/// A contour segment: two points in the caller's coordinates.
pub type Segment = [[f64; 2]; 2];

/// The segments where the bilinear-ish interpolant of `values` crosses `level` (marching
/// squares). `values[iy * xs.len() + ix]` is the value at (xs[ix], ys[iy]); missing entries (a
/// shorter slice) and NaN count as unknown and the squares touching them are skipped.
///
/// Crossings are placed by linear interpolation along the square's edges, always from the lower
/// to the higher grid index, so neighbouring squares produce bit-identical shared endpoints
/// (which [`chain_segments`] relies on). Saddles are resolved with the mean of the four corners.
pub fn marching_squares(xs: &[f64], ys: &[f64], values: &[f64], level: f64) -> Vec<Segment> {
    let (nx, ny) = (xs.len(), ys.len());
    let mut out = Vec::new();
    if nx < 2 || ny < 2 {
        return out;
    }
    let value = |ix: usize, iy: usize| values.get(iy * nx + ix).copied().unwrap_or(f64::NAN);
    // The crossing on the edge from node a to node b (a before b in index order).
    let cross = |a: (usize, usize), b: (usize, usize)| -> [f64; 2] {
        let (va, vb) = (value(a.0, a.1), value(b.0, b.1));
        let t = ((level - va) / (vb - va)).clamp(0.0, 1.0);
        let t = if t.is_finite() { t } else { 0.5 };
        let (xa, ya, xb, yb) = (xs[a.0], ys[a.1], xs[b.0], ys[b.1]);
        // A crossing on a node is that node exactly, whichever edge finds it.
        if t == 0.0 {
            [xa, ya]
        } else if t == 1.0 {
            [xb, yb]
        } else {
            [xa + t * (xb - xa), ya + t * (yb - ya)]
        }
    };
    let push = |out: &mut Vec<Segment>, s: Segment| {
        // A contour touching a node gives zero-length pieces: nothing to draw or chain.
        if s[0] != s[1] {
            out.push(s);
        }
    };
    for iy in 0..ny - 1 {
        for ix in 0..nx - 1 {
            let corners = [(ix, iy), (ix + 1, iy), (ix + 1, iy + 1), (ix, iy + 1)];
            let v = corners.map(|(x, y)| value(x, y));
            if v.iter().any(|v| v.is_nan()) {
                continue;
            }
            let above = v.map(|v| v >= level);
            // Edges: 0 bottom (c0–c1), 1 right (c1–c2), 2 top (c3–c2), 3 left (c0–c3).
            let edge = |e: usize| match e {
                0 => cross(corners[0], corners[1]),
                1 => cross(corners[1], corners[2]),
                2 => cross(corners[3], corners[2]),
                _ => cross(corners[0], corners[3]),
            };
            let crossed = [above[0] != above[1], above[1] != above[2], above[3] != above[2], above[0] != above[3]];
            let count = crossed.iter().filter(|c| **c).count();
            if count == 2 {
                let mut it = (0..4).filter(|&e| crossed[e]);
                let (a, b) = (it.next().unwrap_or(0), it.next().unwrap_or(0));
                push(&mut out, [edge(a), edge(b)]);
            } else if count == 4 {
                let centre_above = (v[0] + v[1] + v[2] + v[3]) / 4.0 >= level;
                // Corners 0 and 2 share a side of the level, 1 and 3 the other. If the centre is
                // on the side of corners 0 and 2 they are joined and 1 and 3 are cut off, else
                // the other way round.
                if centre_above == above[0] {
                    push(&mut out, [edge(0), edge(1)]); // around corner 1
                    push(&mut out, [edge(2), edge(3)]); // around corner 3
                } else {
                    push(&mut out, [edge(3), edge(0)]); // around corner 0
                    push(&mut out, [edge(1), edge(2)]); // around corner 2
                }
            }
        }
    }
    out
}

/// Joins segments that share endpoints (exactly, bit for bit) into polylines. A closed contour
/// comes back with its first point repeated at the end.
pub fn chain_segments(segments: &[Segment]) -> Vec<Vec<[f64; 2]>> {
    let key = |p: [f64; 2]| (p[0].to_bits(), p[1].to_bits());
    let mut ends: HashMap<(u64, u64), Vec<usize>> = HashMap::new();
    for (i, s) in segments.iter().enumerate() {
        ends.entry(key(s[0])).or_default().push(i);
        ends.entry(key(s[1])).or_default().push(i);
    }
    let mut used = vec![false; segments.len()];
    // The unused segment touching `p`, and its other end.
    let mut next_from = |p: [f64; 2], used: &mut Vec<bool>| -> Option<[f64; 2]> {
        let list = ends.get_mut(&key(p))?;
        while let Some(i) = list.pop() {
            if !used[i] {
                used[i] = true;
                let s = segments[i];
                return Some(if key(s[0]) == key(p) { s[1] } else { s[0] });
            }
        }
        None
    };
    let mut lines = Vec::new();
    for i in 0..segments.len() {
        if used[i] {
            continue;
        }
        used[i] = true;
        let mut forward = vec![segments[i][0], segments[i][1]];
        while let Some(p) = next_from(*forward.last().unwrap_or(&segments[i][1]), &mut used) {
            forward.push(p);
        }
        let mut backward = Vec::new();
        let mut tail = segments[i][0];
        while let Some(p) = next_from(tail, &mut used) {
            backward.push(p);
            tail = p;
        }
        backward.reverse();
        backward.extend(forward);
        lines.push(backward);
    }
    lines
}
