//! The rectangle every panel, label and hit test is measured in.

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

    /// True if the interiors of the two rectangles overlap (by more than rounding: edges that
    /// touch do not).
    pub fn overlaps(&self, other: &Rect) -> bool {
        const TOL: f64 = 1e-9;
        self.x < other.right() - TOL
            && other.x < self.right() - TOL
            && self.y < other.bottom() - TOL
            && other.y < self.bottom() - TOL
    }
}
