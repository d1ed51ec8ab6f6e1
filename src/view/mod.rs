//! What the page draws, as plain geometry with no GPU or web types (so it is testable natively):
//! panels laid out in CSS pixels, tessellated into coloured triangles that the wgpu renderer in
//! `web` uploads as they are.
//!
//! | module | contents |
//! |---|---|
//! | [`painter`] | [`Vertex`], [`Painter`]: thick lines, polylines, circles, rectangles → triangle list |
//! | [`layout`] | [`Layout`]: where the arm and the plots go for a canvas size ([`PanelKind`]) |
//! | [`axes`] | 1-2-5 ticks and the error/torque autoscale with hysteresis |
//! | [`arm`] | the arm, motor, magnified spring twist and reference arm |
//! | [`traces`] | scrolling time plots with min/max decimation |
//! | [`poles`] | the pole plot: s = ln λ / δ, the imaginary axis, the δ → 0 pair A4 |
//! | [`map`] | stability maps ρ(δ, α) on log axes, the ρ = 1 contour (marching squares) |
//! | [`scene`] | [`Scene`]: one frame from one or two [`ClosedLoop`](crate::ClosedLoop)s, plus panel info for labels |
//!
//! Simulation values arrive as f64 and stay f64 until a vertex is written (f32, physical pixels).

pub mod arm;
pub mod axes;
pub mod layout;
pub mod map;
pub mod painter;
pub mod poles;
pub mod scene;
pub mod traces;

pub use layout::{Layout, LayoutOptions, Panel, PanelKind, Rect};
pub use map::MapSide;
pub use painter::{Color, Painter, Vertex};
pub use poles::{PoleInfo, PoleKind};
pub use scene::{OptionsUpdate, PanelInfo, RunState, Scene, SeriesInfo, ViewOptions};

/// The colours of the picture: a calm light background, readable on a projector.
pub mod palette {
    use super::Color;

    /// Canvas background (behind the panels).
    pub const BACKGROUND: Color = Color::hex(0xf3f1ec);
    /// Panel fill.
    pub const PANEL: Color = Color::hex(0xffffff);
    /// Panel frame.
    pub const FRAME: Color = Color::hex(0xb9b6ae);
    /// Grid lines.
    pub const GRID: Color = Color::hex(0xe4e1da);
    /// Zero line and the arm's 0-rad direction.
    pub const AXIS: Color = Color::hex(0x9c988f);
    /// Shading of the time intervals where the reference moves.
    pub const MOTION: Color = Color::hex(0xfbf0d2);

    /// Link 1: dark blue.
    pub const LINK1: Color = Color::hex(0x1d3f8c);
    /// Link 2: teal.
    pub const LINK2: Color = Color::hex(0x13958f);
    /// The elbow joint.
    pub const JOINT: Color = Color::hex(0x2b2b33);
    /// The reference arm: translucent grey.
    pub const GHOST: Color = Color::hex(0x6f6f6f).with_alpha(0.33);

    /// Motor disc, its edge and its angle marker: orange.
    pub const MOTOR: Color = Color::hex(0xf7c98f);
    pub const MOTOR_EDGE: Color = Color::hex(0xd9731a);
    pub const MOTOR_MARKER: Color = Color::hex(0xa34700);
    /// The spring, relaxed and fully stretched (the colour blends with the drawn twist).
    pub const SPRING_RELAXED: Color = Color::hex(0xe98a1e);
    pub const SPRING_STRETCHED: Color = Color::hex(0xc42a1c);
    /// The circle the spring coils along.
    pub const SPRING_TRACK: Color = Color::hex(0xe98a1e).with_alpha(0.25);

    /// e1: blue; e2: red-orange.
    pub const ERROR1: Color = Color::hex(0x1f5fc4);
    pub const ERROR2: Color = Color::hex(0xe0521b);
    /// Torques, with the colours of their links' errors.
    pub const TORQUE1: Color = ERROR1;
    pub const TORQUE2: Color = ERROR2;

    /// Run B of a comparison: one violet hue for its curves, poles and map marker ...
    pub const RUN_B: Color = Color::hex(0x8a3cc2);
    /// ... and a lighter violet for its T2 and its A4-without-feedback rings.
    pub const RUN_B_LIGHT: Color = Color::hex(0xc39be0);

    /// Pole plot: loop poles with Re s ≤ 0 (dark) and Re s > 0 (red).
    pub const POLE_STABLE: Color = Color::hex(0x24242c);
    pub const POLE_UNSTABLE: Color = Color::hex(0xd7191c);
    /// The amber halo behind the flexible pair.
    pub const POLE_HALO: Color = Color::hex(0xf5b301).with_alpha(0.45);
    /// A4 without preliminary feedback (rings) and with it (diamonds).
    pub const A4_OPEN: Color = Color::hex(0x7d7670);
    pub const A4_FEEDBACK: Color = Color::hex(0x168a45);
    /// The unstable half-plane Re s > 0, faintly tinted.
    pub const UNSTABLE_REGION: Color = Color::hex(0xfcecea);
    /// The imaginary axis Re s = 0, emphasised.
    pub const IMAGINARY_AXIS: Color = Color::hex(0x3b3b44);

    /// Stability map: ρ = 1 (near white), stable shades towards ρ = 0.8, unstable towards 1.2.
    pub const MAP_NEUTRAL: Color = Color::hex(0xf7f6f2);
    pub const MAP_STABLE_MID: Color = Color::hex(0x8dbfdf);
    pub const MAP_STABLE_FAR: Color = Color::hex(0x1b5599);
    pub const MAP_UNSTABLE_MID: Color = Color::hex(0xf4a37c);
    pub const MAP_UNSTABLE_FAR: Color = Color::hex(0xae1c24);
    /// Cells not computed yet.
    pub const MAP_PENDING: Color = Color::hex(0xdcdad5);
    /// Faint grid lines over the map cells.
    pub const MAP_GRID: Color = Color::hex(0xffffff).with_alpha(0.45);
    /// The ρ = 1 contour and the white halo under it.
    pub const CONTOUR: Color = Color::hex(0x141418);
    pub const CONTOUR_HALO: Color = Color::hex(0xffffff).with_alpha(0.7);
    /// Run A's marker on the maps, and the white halo that keeps markers readable on dark cells.
    pub const MAP_MARKER: Color = Color::hex(0x101014);
    pub const MARKER_HALO: Color = Color::hex(0xffffff).with_alpha(0.9);
}
