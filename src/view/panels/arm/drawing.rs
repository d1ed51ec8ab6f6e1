//! The arm picture: links, motor, flexible joint and the reference ("ghost") arm.
//!
//! Angles follow the paper: link 1 is at q1 from the +x axis (counter-clockwise, y up), link 2 at
//! q1 + q2, and the motor at the absolute angle θ. The spring between motor and link 1 twists by
//! θ − q1, which is tiny (K1 ≈ 1150 N m/rad: a few mrad at rest), so it is drawn magnified: the
//! spring runs from the link-1 direction to q1 + M·(θ − q1) with M = [`DEFAULT_SPRING_MAGNIFICATION`]
//! unless the page chooses another value. The motor marker itself shows the true θ.

use core::f64::consts::PI;

use crate::plot::{palette, Color};
use crate::view::painter::{Painter, Point};
use crate::view::rect::Rect;

/// Drawn length of link 1 (picture units).
///
/// The paper gives the arm only through its inertias A1, A2, A3 and Ir1, not its link lengths, so
/// the picture uses L1 = 1 and L2 = 0.75 — plausible proportions, with no effect on the physics.
pub const LINK1_LENGTH: f64 = 1.0;
/// Drawn length of link 2 (picture units); see [`LINK1_LENGTH`].
pub const LINK2_LENGTH: f64 = 0.75;

/// Default magnification of the spring twist θ − q1 in the picture.
pub const DEFAULT_SPRING_MAGNIFICATION: f64 = 20.0;

/// The drawn twist is clamped to this many radians (just under a full turn), so a diverging run
/// shows a fully wound spring instead of one that wraps around.
pub const MAX_DRAWN_TWIST: f64 = 1.8 * PI;

/// Half-width of the square world region shown, in picture units: the full reach plus a margin.
pub const WORLD_HALF_EXTENT: f64 = (LINK1_LENGTH + LINK2_LENGTH) * 1.12;

/// The configuration of the arm that the picture needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmPose {
    /// Link-1 angle from +x, rad.
    pub q1: f64,
    /// Link-2 angle relative to link 1, rad.
    pub q2: f64,
    /// Absolute motor angle, rad.
    pub theta: f64,
}

impl ArmPose {
    /// The elbow in picture units, base at the origin, y up.
    pub fn elbow(&self) -> [f64; 2] {
        [LINK1_LENGTH * self.q1.cos(), LINK1_LENGTH * self.q1.sin()]
    }

    /// The tip in picture units, base at the origin, y up.
    pub fn tip(&self) -> [f64; 2] {
        let [ex, ey] = self.elbow();
        let a = self.q1 + self.q2;
        [ex + LINK2_LENGTH * a.cos(), ey + LINK2_LENGTH * a.sin()]
    }

    /// The spring twist θ − q1, rad.
    pub fn twist(&self) -> f64 {
        self.theta - self.q1
    }

    fn is_finite(&self) -> bool {
        self.q1.is_finite() && self.q2.is_finite() && self.theta.is_finite()
    }
}

/// The direction (rad, world convention) where the drawn spring ends: q1 + M·(θ − q1), with the
/// magnified twist clamped to ±[`MAX_DRAWN_TWIST`].
pub fn spring_end_angle(pose: &ArmPose, magnification: f64) -> f64 {
    pose.q1 + drawn_twist(pose, magnification)
}

/// M·(θ − q1) clamped to ±[`MAX_DRAWN_TWIST`] (0 if not finite).
pub fn drawn_twist(pose: &ArmPose, magnification: f64) -> f64 {
    let t = magnification * pose.twist();
    if t.is_finite() {
        t.clamp(-MAX_DRAWN_TWIST, MAX_DRAWN_TWIST)
    } else {
        0.0
    }
}

/// An upper bound on the vertices [`draw_arm_panel`] writes (circles have at most 128 segments,
/// the spring at most [`MAX_DRAWN_TWIST`] / 0.2 half-waves); the scene reserves this much.
pub const VERTEX_BUDGET: usize = 6000;

/// Maps picture units (y up) to physical pixels (y down) inside a panel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmFrame {
    /// The base, physical pixels.
    pub base: Point,
    /// Physical pixels per picture unit.
    pub scale: f64,
    /// Physical pixels per CSS pixel (for line widths).
    pub dpr: f64,
}

impl ArmFrame {
    /// Base at the centre of `panel_px` (physical pixels), the full reach fitting the smaller side.
    pub fn fit(panel_px: Rect, dpr: f64) -> ArmFrame {
        let half = panel_px.w.min(panel_px.h) / 2.0;
        ArmFrame { base: panel_px.center(), scale: (half / WORLD_HALF_EXTENT).max(0.0), dpr }
    }

    /// A world point (picture units) in physical pixels.
    pub fn point(&self, p: [f64; 2]) -> Point {
        [self.base[0] + self.scale * p[0], self.base[1] - self.scale * p[1]]
    }

    /// A length in picture units in physical pixels.
    pub fn length(&self, l: f64) -> f64 {
        self.scale * l
    }

    /// A width of `css` CSS pixels in physical pixels.
    pub fn css(&self, css: f64) -> f64 {
        css * self.dpr
    }

    /// The world range shown along x and y (picture units): the panel's full extent.
    pub fn world_range(&self, panel_px: Rect) -> ([f64; 2], [f64; 2]) {
        if self.scale <= 0.0 {
            return ([0.0, 0.0], [0.0, 0.0]);
        }
        let x0 = (panel_px.x - self.base[0]) / self.scale;
        let x1 = (panel_px.right() - self.base[0]) / self.scale;
        let y0 = (self.base[1] - panel_px.bottom()) / self.scale;
        let y1 = (self.base[1] - panel_px.y) / self.scale;
        ([x0, x1], [y0, y1])
    }
}

/// Sizes of the picture's parts, in picture units unless noted.
mod size {
    /// Motor disc radius.
    pub const MOTOR: f64 = 0.13;
    /// Mean radius of the drawn torsional spring.
    pub const SPRING: f64 = 0.3;
    /// Zig-zag amplitude of the spring.
    pub const SPRING_AMPLITUDE: f64 = 0.05;
    /// One zig-zag half-wave per this many radians of drawn twist.
    pub const SPRING_WAVE: f64 = 0.2;
    /// Link thicknesses.
    pub const LINK1_WIDTH: f64 = 0.075;
    pub const LINK2_WIDTH: f64 = 0.06;
    /// Elbow and tip circles.
    pub const ELBOW: f64 = 0.05;
    pub const TIP: f64 = 0.038;
}

/// Draws the whole arm panel: background, reference arm, spring, links, motor.
pub fn draw_arm_panel(
    painter: &mut Painter,
    panel_px: Rect,
    dpr: f64,
    actual: &ArmPose,
    reference: &ArmPose,
    magnification: f64,
) {
    painter.rect(panel_px, palette::PANEL);
    painter.rect_outline(panel_px, dpr, palette::FRAME);
    let frame = ArmFrame::fit(panel_px, dpr);
    if frame.scale <= 0.0 {
        return;
    }
    draw_workspace(painter, &frame);
    if reference.is_finite() {
        draw_links(painter, &frame, reference, LinkColors::GHOST);
    }
    if actual.is_finite() {
        draw_spring(painter, &frame, actual, magnification);
        draw_links(painter, &frame, actual, LinkColors::ARM);
        let reference_theta = if reference.is_finite() { Some(reference.theta) } else { None };
        draw_motor(painter, &frame, actual.theta, reference_theta);
    }
}

/// Over an arm panel drawn by [`draw_arm_panel`]: another pose of the arm as a coloured outline —
/// its links, and a tab where its spring ends (the twist magnified as the arm's) — e.g. the arm the
/// controller predicts (Fig. 2.1's X_k).
pub fn draw_arm_outline(
    painter: &mut Painter,
    panel_px: Rect,
    dpr: f64,
    pose: &ArmPose,
    magnification: f64,
    color: Color,
) {
    let frame = ArmFrame::fit(panel_px, dpr);
    if frame.scale <= 0.0 || !pose.is_finite() {
        return;
    }
    // Thinner than the arm, so that the arm shows through where they coincide.
    let (elbow, tip) = (frame.point(pose.elbow()), frame.point(pose.tip()));
    painter.line(frame.base, elbow, frame.css(2.5), color);
    painter.line(elbow, tip, frame.css(2.5), color);
    painter.ring(elbow, frame.length(size::ELBOW), frame.css(1.5), color);
    painter.ring(tip, frame.length(size::TIP), frame.css(1.5), color);
    let end = -spring_end_angle(pose, magnification);
    let (inner, outer) = (frame.length(size::MOTOR), frame.length(size::SPRING + 2.0 * size::SPRING_AMPLITUDE));
    painter.line(at(frame.base, inner, end), at(frame.base, outer, end), frame.css(3.0), color);
}

/// A faint reach circle and the 0-rad direction, so angles can be read against something.
fn draw_workspace(painter: &mut Painter, frame: &ArmFrame) {
    let reach = frame.length(LINK1_LENGTH + LINK2_LENGTH);
    painter.ring(frame.base, reach, frame.css(1.0), palette::GRID);
    let zero_end = frame.point([(LINK1_LENGTH + LINK2_LENGTH) * 1.05, 0.0]);
    painter.line(frame.base, zero_end, frame.css(1.0), palette::AXIS);
}

#[derive(Clone, Copy)]
struct LinkColors {
    link1: Color,
    link2: Color,
    joint: Color,
    tip: Color,
}

impl LinkColors {
    const ARM: LinkColors =
        LinkColors { link1: palette::LINK1, link2: palette::LINK2, joint: palette::JOINT, tip: palette::LINK2 };
    const GHOST: LinkColors =
        LinkColors { link1: palette::GHOST, link2: palette::GHOST, joint: palette::GHOST, tip: palette::GHOST };
}

fn draw_links(painter: &mut Painter, frame: &ArmFrame, pose: &ArmPose, colors: LinkColors) {
    let base = frame.base;
    let elbow = frame.point(pose.elbow());
    let tip = frame.point(pose.tip());
    let w1 = frame.length(size::LINK1_WIDTH).max(frame.css(3.0));
    let w2 = frame.length(size::LINK2_WIDTH).max(frame.css(2.5));
    painter.line(base, elbow, w1, colors.link1);
    painter.line(elbow, tip, w2, colors.link2);
    painter.circle(elbow, frame.length(size::ELBOW).max(w1 * 0.7), colors.joint);
    painter.circle(tip, frame.length(size::TIP).max(w2 * 0.7), colors.tip);
}

/// The torsional spring: a zig-zag arc around the base from the link-1 direction to the
/// magnified motor direction, coloured from relaxed orange to stretched red.
fn draw_spring(painter: &mut Painter, frame: &ArmFrame, pose: &ArmPose, magnification: f64) {
    let r = frame.length(size::SPRING);
    let amplitude = frame.length(size::SPRING_AMPLITUDE);
    let width = frame.css(2.5);
    painter.ring(frame.base, r, frame.css(1.5), palette::SPRING_TRACK);

    let twist = drawn_twist(pose, magnification);
    let color = palette::SPRING_RELAXED.lerp(palette::SPRING_STRETCHED, twist.abs() / (0.5 * PI));
    // Screen angles run clockwise (y down): a world angle φ is −φ on screen.
    let start = -pose.q1;
    let span = -twist;
    let half_waves = ((twist.abs() / size::SPRING_WAVE).ceil() as usize).max(2);
    let mut stroke = painter.stroke(width, color, true);
    stroke.to(at(frame.base, r, start));
    for i in 1..half_waves {
        let a = start + span * i as f64 / half_waves as f64;
        let side = if i % 2 == 1 { 1.0 } else { -1.0 };
        stroke.to(at(frame.base, r + side * amplitude, a));
    }
    let end = start + span;
    stroke.to(at(frame.base, r, end));
    // The spring's motor-side anchor: a radial tab from the motor rim out through the coil.
    let tab_inner = at(frame.base, frame.length(size::MOTOR), end);
    let tab_outer = at(frame.base, r + amplitude, end);
    painter.line(tab_inner, tab_outer, frame.css(2.5), color);
}

/// The motor: a disc at the base and a radial marker at the true motor angle θ, over a grey
/// marker at the reference's motor angle (q_d1: the reference arm's spring is relaxed).
fn draw_motor(painter: &mut Painter, frame: &ArmFrame, theta: f64, reference_theta: Option<f64>) {
    let r = frame.length(size::MOTOR);
    painter.circle(frame.base, r, palette::MOTOR);
    painter.ring(frame.base, r, frame.css(1.5), palette::MOTOR_EDGE);
    if let Some(theta_d) = reference_theta {
        let ghost_end = at(frame.base, r * 0.95, -theta_d);
        painter.line(frame.base, ghost_end, frame.css(3.0), palette::GHOST);
    }
    let marker_end = at(frame.base, r * 0.95, -theta);
    painter.line(frame.base, marker_end, frame.css(3.0), palette::MOTOR_MARKER);
    painter.circle(frame.base, frame.css(2.5), palette::MOTOR_MARKER);
}

/// The point at radius `r` and screen angle `a` (clockwise from +x) around `c`.
fn at(c: Point, r: f64, a: f64) -> Point {
    crate::view::painter::polar(c, r, a)
}
