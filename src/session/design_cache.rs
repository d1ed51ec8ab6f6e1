//! What the design's price was computed for ([`super::Session::design_status`] reads it; the
//! session's `design` module fills it).

use crate::analysis::{LinearSettings, StableWindows};
use crate::control::config::SimulationConfig;
use crate::control::price::TorquePrice;

/// The design's price, cached by the settings it was computed for.
#[derive(Clone, Debug, Default)]
pub struct DesignCache {
    /// The windows with the other inner loop than run A's (its own are the session's windows),
    /// by the linear settings they are of (δ normalized away).
    pub other_key: Option<LinearSettings>,
    pub other: Option<Result<StableWindows, String>>,
    /// The torque, by run A's configuration.
    pub torque_key: Option<SimulationConfig>,
    pub torque: Option<Result<TorquePrice, String>>,
    /// The configuration at the last refresh: the other loop's windows and the torque wait until
    /// it stays the same.
    pub seen: Option<SimulationConfig>,
}
