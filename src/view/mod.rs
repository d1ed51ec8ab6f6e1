//! What the page draws, as plain geometry with no GPU or web types (so it is testable natively):
//! panels laid out in CSS pixels, tessellated into coloured triangles that the wgpu renderer in
//! `web` uploads as they are.
//!
//! | module | contents |
//! |---|---|
//! | [`painter`] | [`Vertex`], [`Painter`]: thick lines, polylines, circles, rectangles → triangle list |
//! | [`layout`] | [`Layout`]: where the arm and the plots go for a canvas size; [`LayoutOptions`]: which panels are asked for, and the notice of those not in view |
//! | [`autoscale`] | the error/torque autoscale with hysteresis |
//! | [`arm`] | the arm, motor, magnified spring twist and reference arm |
//! | [`traces`] | scrolling time plots with min/max decimation |
//! | [`markers`] | the pole markers' style and sizes, the flexible pair (shared by s- and z-plane) |
//! | [`poles`] | the pole plot: s = ln λ / δ, the imaginary axis, the δ → 0 pair A4 |
//! | [`zplane`] | the loop's eigenvalues λ against the unit circle |
//! | [`rho_curve`] | ρ(δ) at the current α with the stable windows |
//! | [`map`] | stability maps ρ(δ, α) on log axes with the ρ = 1 contour, and their markers |
//! | [`scene`] | [`Scene`]: one frame from a session's runs, and its description for the page |
//! | [`labels`] | where every text over the canvas goes (ticks, titles, notes), without overlaps |
//! | [`legend`] | the key to the markers, lines and shades shown, and the colour bar of ρ |
//! | [`figure`] | a figure per panel: one panel laid out alone, drawn and written as SVG |
//! | [`text_size`] | the figure's text scale (the `text` setting, presentation mode's floor) |
//!
//! Ticks, number formats, colours and contours come from [`crate::plot`]. Simulation values
//! arrive as f64 and stay f64 until a vertex is written (f32, physical pixels).
//!
//! Architecture invariant: `view` reads the session and draws; it computes no physics.

pub mod arm;
pub mod autoscale;
pub mod figure;
pub mod labels;
pub mod layout;
pub mod legend;
pub mod map;
pub mod markers;
pub mod options;
pub mod painter;
pub mod panel_info;
pub mod poles;
pub mod rect;
pub mod rho_curve;
pub mod scene;
pub mod text_metrics;
pub mod text_size;
pub mod tick_labels;
pub mod traces;
pub mod zplane;

pub use crate::plot::{palette, Color};
pub use labels::{Label, LabelClass};
pub use layout::{Layout, LayoutOptions, Panel, PanelKind, Rect, Tab};
pub use map::MapSide;
pub use painter::{Painter, Vertex};
pub use poles::{PoleInfo, PoleKind};
pub use scene::{OptionsUpdate, PanelInfo, Probe, RunState, Scene, SeriesInfo, ViewOptions};
pub use text_size::TextSize;
