//! What the design's price was computed for ([`super::Session::design_status`] reads it; the
//! session's `design` module fills it).

use crate::analysis::design::DigitalPrice;
use crate::analysis::LinearSettings;
use crate::control::config::SimulationConfig;
use crate::control::price::TorquePrice;

/// The design's price, cached by the settings it was computed for.
#[derive(Clone, Debug, Default)]
pub struct DesignCache {
    /// Windows analog and sampled, by run A's linear settings with δ and the inner loop normalized.
    pub price_key: Option<LinearSettings>,
    pub price: Option<Result<DigitalPrice, String>>,
    /// The torque, by run A's configuration.
    pub torque_key: Option<SimulationConfig>,
    pub torque: Option<Result<TorquePrice, String>>,
    /// The configuration at the last refresh: the torque waits until it stays the same.
    pub seen: Option<SimulationConfig>,
}
