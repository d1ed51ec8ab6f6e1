//! Tessellation of lines, polylines, circles and rectangles into one reusable triangle list.
//!
//! Everything is in physical pixels with the origin at the top-left of the canvas and y
//! pointing down, the way the renderer's vertex shader expects it. Geometry arrives in f64 and
//! becomes f32 only when a vertex is written.

use super::layout::Rect;
use crate::plot::Color;

/// A point in physical pixels, (x right, y down).
pub type Point = [f64; 2];

/// One vertex of the triangle list: what the GPU vertex buffer holds.
///
/// `#[repr(C)]` with six `f32` and no padding: 24 bytes, position at offset 0, colour at 8.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// Physical pixels, origin top-left.
    pub position: [f32; 2],
    /// sRGB-encoded red, green, blue and straight (not premultiplied) alpha, each in [0, 1].
    pub color: [f32; 4],
}

impl Vertex {
    /// Size of one vertex in the vertex buffer, bytes.
    pub const SIZE: usize = core::mem::size_of::<Vertex>();
    /// Byte offset of `color` inside a vertex.
    pub const COLOR_OFFSET: usize = 8;
}

/// Collects coloured triangles for one frame.
///
/// [`Painter::clear`] keeps the allocation, so after the first few frames have grown the buffer
/// to the scene's size, drawing allocates nothing.
#[derive(Clone, Debug, Default)]
pub struct Painter {
    vertices: Vec<Vertex>,
}

/// Circles get one segment per this many pixels of circumference (within the bounds below).
const CIRCLE_PIXELS_PER_SEGMENT: f64 = 3.0;
const CIRCLE_MIN_SEGMENTS: usize = 12;
const CIRCLE_MAX_SEGMENTS: usize = 128;

impl Painter {
    pub fn new() -> Self {
        Self::default()
    }

    /// A painter with room for `vertices` vertices before its first reallocation.
    pub fn with_capacity(vertices: usize) -> Self {
        Self { vertices: Vec::with_capacity(vertices) }
    }

    /// Makes room for at least `vertices` vertices in total, so frames up to that size never
    /// reallocate.
    pub fn reserve_total(&mut self, vertices: usize) {
        self.vertices.reserve(vertices.saturating_sub(self.vertices.len()));
    }

    /// Forgets the previous frame's triangles but keeps the memory.
    pub fn clear(&mut self) {
        self.vertices.clear();
    }

    /// The triangle list: every three vertices form one triangle.
    pub fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }

    /// The triangle list as raw bytes for the GPU vertex buffer.
    pub fn vertex_bytes(&self) -> &[u8] {
        bytemuck::cast_slice(&self.vertices)
    }

    /// Number of vertices written this frame.
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// Vertices the painter can hold without reallocating.
    pub fn capacity(&self) -> usize {
        self.vertices.capacity()
    }

    fn vertex(&mut self, p: Point, color: Color) {
        self.vertices.push(Vertex { position: [p[0] as f32, p[1] as f32], color: color.0 });
    }

    /// One filled triangle.
    // The drawing primitives are called from many places: kept out of line, they cost the page's
    // module a few kB less, and drawing is nowhere near the frame's budget.
    #[inline(never)]
    pub fn triangle(&mut self, a: Point, b: Point, c: Point, color: Color) {
        self.vertex(a, color);
        self.vertex(b, color);
        self.vertex(c, color);
    }

    /// A filled convex quadrilateral with corners `a, b, c, d` in order around it.
    #[inline(never)]
    pub fn quad(&mut self, a: Point, b: Point, c: Point, d: Point, color: Color) {
        self.triangle(a, b, c, color);
        self.triangle(a, c, d, color);
    }

    /// A filled axis-aligned rectangle.
    #[inline(never)]
    pub fn rect(&mut self, r: Rect, color: Color) {
        let (x0, y0, x1, y1) = (r.x, r.y, r.right(), r.bottom());
        self.quad([x0, y0], [x1, y0], [x1, y1], [x0, y1], color);
    }

    /// The outline of a rectangle, `width` pixels thick, drawn inside the rectangle.
    #[inline(never)]
    pub fn rect_outline(&mut self, r: Rect, width: f64, color: Color) {
        let w = width.min(r.w / 2.0).min(r.h / 2.0).max(0.0);
        self.rect(Rect::new(r.x, r.y, r.w, w), color);
        self.rect(Rect::new(r.x, r.bottom() - w, r.w, w), color);
        self.rect(Rect::new(r.x, r.y + w, w, r.h - 2.0 * w), color);
        self.rect(Rect::new(r.right() - w, r.y + w, w, r.h - 2.0 * w), color);
    }

    /// A straight segment `width` pixels thick with square-cut ends.
    #[inline(never)]
    pub fn line(&mut self, a: Point, b: Point, width: f64, color: Color) {
        if let Some(n) = unit_normal(a, b) {
            let h = width / 2.0;
            let o = [n[0] * h, n[1] * h];
            self.quad(add(a, o), add(b, o), sub(b, o), sub(a, o), color);
        }
    }

    /// Starts a polyline of the given width and colour; feed it points with [`Stroke::to`].
    ///
    /// With `joins`, the corners get a bevel so thick lines show no notches; thin data traces
    /// can skip them to halve the vertex count.
    pub fn stroke(&mut self, width: f64, color: Color, joins: bool) -> Stroke<'_> {
        Stroke { painter: self, half: width / 2.0, color, joins, last: None, last_normal: None }
    }

    /// A dashed straight line: `dash` pixels drawn, `gap` pixels left out, from `a` to `b`.
    #[inline(never)]
    pub fn dashed_line(&mut self, a: Point, b: Point, width: f64, dash: f64, gap: f64, color: Color) {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let length = dx.hypot(dy);
        if !(length.is_finite() && length > 0.0 && dash > 0.0) {
            return;
        }
        let (ux, uy) = (dx / length, dy / length);
        let mut s = 0.0;
        // At most this many dashes, so a degenerate call cannot flood the frame.
        for _ in 0..512 {
            if s >= length {
                break;
            }
            let e = (s + dash).min(length);
            self.line([a[0] + ux * s, a[1] + uy * s], [a[0] + ux * e, a[1] + uy * e], width, color);
            s = e + gap;
        }
    }

    /// A polyline through `points` with bevelled corners.
    pub fn polyline(&mut self, points: impl IntoIterator<Item = Point>, width: f64, color: Color) {
        let mut stroke = self.stroke(width, color, true);
        for p in points {
            stroke.to(p);
        }
    }

    /// Segments for a circle of radius `r` pixels: smooth at any size, cheap when small.
    fn circle_segments(r: f64) -> usize {
        let n = (core::f64::consts::TAU * r.abs() / CIRCLE_PIXELS_PER_SEGMENT).ceil();
        if n.is_finite() {
            (n as usize).clamp(CIRCLE_MIN_SEGMENTS, CIRCLE_MAX_SEGMENTS)
        } else {
            CIRCLE_MIN_SEGMENTS
        }
    }

    /// A filled disc.
    #[inline(never)]
    pub fn circle(&mut self, center: Point, r: f64, color: Color) {
        if !(r > 0.0 && r.is_finite()) {
            return;
        }
        let n = Self::circle_segments(r);
        let mut prev = polar(center, r, 0.0);
        for i in 1..=n {
            let p = polar(center, r, core::f64::consts::TAU * i as f64 / n as f64);
            self.triangle(center, prev, p, color);
            prev = p;
        }
    }

    /// An × marker: two diagonals of half-size `r` (pixels) through `center`.
    #[inline(never)]
    pub fn cross(&mut self, center: Point, r: f64, width: f64, color: Color) {
        let [x, y] = center;
        self.line([x - r, y - r], [x + r, y + r], width, color);
        self.line([x - r, y + r], [x + r, y - r], width, color);
    }

    /// A + marker: a horizontal and a vertical bar of half-length `r` through `center`.
    #[inline(never)]
    pub fn plus(&mut self, center: Point, r: f64, width: f64, color: Color) {
        let [x, y] = center;
        self.line([x - r, y], [x + r, y], width, color);
        self.line([x, y - r], [x, y + r], width, color);
    }

    /// The outline of a diamond (a square on its corner) with half-diagonal `r`.
    #[inline(never)]
    pub fn diamond(&mut self, center: Point, r: f64, width: f64, color: Color) {
        let [x, y] = center;
        let corners = [[x, y - r], [x + r, y], [x, y + r], [x - r, y], [x, y - r], [x + r, y]];
        // Running once past the start closes the outline with a proper corner join.
        let mut stroke = self.stroke(width, color, true);
        for p in corners {
            stroke.to(p);
        }
    }

    /// A chevron (an open arrow head) of size `r` at `center`, pointing along `direction`
    /// (any non-zero vector in pixel space; nothing is drawn for a zero or non-finite one).
    #[inline(never)]
    pub fn chevron(&mut self, center: Point, direction: Point, r: f64, width: f64, color: Color) {
        let len = direction[0].hypot(direction[1]);
        if !(len > 0.0 && len.is_finite()) {
            return;
        }
        let (dx, dy) = (direction[0] / len, direction[1] / len);
        let tip = [center[0] + dx * r * 0.5, center[1] + dy * r * 0.5];
        let back = [center[0] - dx * r * 0.5, center[1] - dy * r * 0.5];
        let a = [back[0] - dy * r, back[1] + dx * r];
        let b = [back[0] + dy * r, back[1] - dx * r];
        self.polyline([a, tip, b], width, color);
    }

    /// A circle outline `width` pixels thick, centred on radius `r`.
    #[inline(never)]
    pub fn ring(&mut self, center: Point, r: f64, width: f64, color: Color) {
        self.arc(center, r, 0.0, core::f64::consts::TAU, width, color);
    }

    /// An arc of radius `r` from angle `a0` to `a1` (radians, measured as on screen: from +x
    /// towards +y, i.e. clockwise because y points down), `width` pixels thick.
    #[inline(never)]
    pub fn arc(&mut self, center: Point, r: f64, a0: f64, a1: f64, width: f64, color: Color) {
        if !(r > 0.0 && r.is_finite() && a0.is_finite() && a1.is_finite()) {
            return;
        }
        let span = a1 - a0;
        let full = Self::circle_segments(r) as f64;
        let n = ((span.abs() / core::f64::consts::TAU) * full).ceil().max(1.0) as usize;
        let (inner, outer) = ((r - width / 2.0).max(0.0), r + width / 2.0);
        let mut prev = (polar(center, inner, a0), polar(center, outer, a0));
        for i in 1..=n {
            let a = a0 + span * i as f64 / n as f64;
            let next = (polar(center, inner, a), polar(center, outer, a));
            self.quad(prev.0, prev.1, next.1, next.0, color);
            prev = next;
        }
    }
}

/// A polyline under construction; see [`Painter::stroke`].
pub struct Stroke<'a> {
    painter: &'a mut Painter,
    half: f64,
    color: Color,
    joins: bool,
    last: Option<Point>,
    last_normal: Option<Point>,
}

impl Stroke<'_> {
    /// Extends the line to `p`. A non-finite point lifts the pen (the line resumes at the next
    /// finite point), so NaN samples of a diverged run leave a gap instead of a spike.
    pub fn to(&mut self, p: Point) {
        if !(p[0].is_finite() && p[1].is_finite()) {
            self.lift();
            return;
        }
        let Some(a) = self.last else {
            self.last = Some(p);
            return;
        };
        let Some(n) = unit_normal(a, p) else {
            return; // a repeated point adds nothing
        };
        let o = [n[0] * self.half, n[1] * self.half];
        if self.joins {
            if let Some(n0) = self.last_normal {
                let o0 = [n0[0] * self.half, n0[1] * self.half];
                // Both bevel triangles: whichever side is the outside of the corner gets filled.
                self.painter.triangle(a, add(a, o0), add(a, o), self.color);
                self.painter.triangle(a, sub(a, o0), sub(a, o), self.color);
            }
        }
        self.painter.quad(add(a, o), add(p, o), sub(p, o), sub(a, o), self.color);
        self.last = Some(p);
        self.last_normal = Some(n);
    }

    /// Ends the current piece; the next point starts a new one.
    pub fn lift(&mut self) {
        self.last = None;
        self.last_normal = None;
    }
}

fn add(a: Point, b: Point) -> Point {
    [a[0] + b[0], a[1] + b[1]]
}

fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1]]
}

/// The point at distance `r` from `c` in direction `angle` (screen convention, y down).
pub fn polar(c: Point, r: f64, angle: f64) -> Point {
    [c[0] + r * angle.cos(), c[1] + r * angle.sin()]
}

/// Unit vector perpendicular to a → b, or None for a zero-length or non-finite segment.
fn unit_normal(a: Point, b: Point) -> Option<Point> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy);
    (len > 1e-9 && len.is_finite()).then(|| [-dy / len, dx / len])
}
