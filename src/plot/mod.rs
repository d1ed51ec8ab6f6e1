//! The plotting foundation every picture shares — the canvas's view geometry, the HTML labels
//! over it and the SVG figures: ticks (linear and logarithmic), number formatting, colours (the
//! palette and the ρ ramp) and contour tracing. Each is implemented once, here.
//!
//! Architecture invariant: `plot` depends on nothing else in the crate but `sort`.

pub mod color;
pub mod contour;
pub mod format;
pub mod ticks;

pub use color::{palette, rho_color, Color};
pub use ticks::{log_ticks, nice_ceil, Ticks};
