//! What the two pictures of the loop's eigenvalues (the s-plane pole plot and the z-plane) share:
//! how a run's markers look, their sizes, and which two eigenvalues are the flexible pair.

use crate::analysis::StabilityReport;
use crate::plot::{palette, Color};

/// The sampled loop has this many eigenvalues (8 plant/integrator states + 2 held inputs).
pub const MAX_LOOP_POLES: usize = 10;

/// How a run's markers look.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoleStyle {
    /// Loop poles as × (run A) or + (run B).
    pub plus: bool,
    /// Loop poles with Re s ≤ 0.
    pub stable: Color,
    /// Loop poles with Re s > 0.
    pub unstable: Color,
    /// A4 without preliminary feedback (rings).
    pub a4_open: Color,
    /// A4 with the configured preliminary feedback (diamonds).
    pub a4: Color,
}

impl PoleStyle {
    pub const RUN_A: PoleStyle = PoleStyle {
        plus: false,
        stable: palette::POLE_STABLE,
        unstable: palette::POLE_UNSTABLE,
        a4_open: palette::A4_OPEN,
        a4: palette::A4_FEEDBACK,
    };
    pub const RUN_B: PoleStyle = PoleStyle {
        plus: true,
        stable: palette::RUN_B,
        unstable: palette::POLE_UNSTABLE,
        a4_open: palette::RUN_B_LIGHT,
        a4: palette::RUN_B,
    };
}

/// The indices (into `report.poles`) of the flexible pair (see [`StabilityReport::flexible_pair`]).
pub fn flexible_pair(report: &StabilityReport) -> [Option<usize>; 2] {
    report.flexible_pair()
}

/// Marker sizes, CSS pixels (the z-plane draws the same markers).
pub mod size {
    pub const CROSS: f64 = 5.0;
    pub const CROSS_WIDTH: f64 = 2.0;
    pub const HALO: f64 = 10.0;
    pub const A4_RING: f64 = 11.0;
    pub const A4_WIDTH: f64 = 1.75;
    pub const A4_DIAMOND: f64 = 7.0;
    pub const CHEVRON: f64 = 5.0;
    pub const EDGE: f64 = 8.0;
}

/// The δ → 0 pair with the preliminary feedback, if there is one (none when it is off: the pair
/// then is A4 without it, already marked).
pub fn with_feedback(report: &StabilityReport) -> &[[f64; 2]] {
    if report.limit_pair == report.limit_pair_open {
        &[]
    } else {
        &report.limit_pair
    }
}
