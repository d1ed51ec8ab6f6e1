//! What the page draws, as plain geometry with no GPU or web types (so it is testable natively):
//! panels laid out in CSS pixels, tessellated into coloured triangles that the wgpu renderer in
//! `web` uploads as they are.
//!
//! | module | contents |
//! |---|---|
//! | [`panels`] | every panel in its own folder (the arm, the time plots, the pole plot, the z-plane, ρ(δ), the maps) behind one interface, [`panels::contract::PanelView`] |
//! | [`scene`] | [`Scene`]: lays the panels out, keeps what persists between frames, asks each panel to draw, describe, read out and key itself |
//! | [`layout`] | [`Layout`]: where the panels go for a canvas size; [`LayoutOptions`]: which panels are asked for, and the notice of those not in view |
//! | [`loop_poles`] | what the s-plane pole plot and the z-plane share: markers, their readouts |
//! | [`rho_readout`] | ρ read out in a tooltip (ρ(δ) and the maps) |
//! | [`delta_axis`] | the log δ axis and grid that ρ(δ) and the sensor study's panels share |
//! | [`labels`] | where every text over the canvas goes (ticks, titles, notes), without overlaps |
//! | [`legend`] | the key's groups and the maps' colour bar |
//! | [`figure`] | every figure as SVG (the page's, `flexarm figure`, `simulate --svg`, `map --svg`): its panels laid out alone, drawn and written |
//! | [`panel_info`], [`text_metrics`], [`tick_labels`] | the leaves: what the page reads of a panel; text widths; tick label text |
//! | [`painter`], [`rect`], [`autoscale`], [`time_window`] | triangles; rectangles; the error/torque autoscale; the time plots' window |
//! | [`options`], [`text_size`] | what the page can change about the picture; the figure's text scale |
//!
//! Ticks, number formats, colours and contours come from [`crate::plot`]. Simulation values
//! arrive as f64 and stay f64 until a vertex is written (f32, physical pixels).
//!
//! Architecture invariant: `view` reads the session and draws; it computes no physics.

pub mod autoscale;
pub mod delta_axis;
pub mod figure;
pub mod labels;
pub mod layout;
pub mod legend;
pub mod loop_poles;
pub mod options;
pub mod painter;
pub mod panel_info;
pub mod panels;
pub mod rect;
pub mod rho_readout;
pub mod scene;
pub mod text_metrics;
pub mod text_size;
pub mod tick_labels;
pub mod time_window;

pub use crate::plot::{palette, Color};
pub use labels::{Label, LabelClass};
pub use layout::{Layout, LayoutOptions, Panel, PanelKind, Rect, Tab};
pub use loop_poles::{PoleInfo, PoleKind};
pub use painter::{Painter, Vertex};
pub use panels::stability_maps::grid::MapSide;
pub use scene::{OptionsUpdate, PanelInfo, Probe, RunState, Scene, SeriesInfo, ViewOptions};
pub use text_size::TextSize;
