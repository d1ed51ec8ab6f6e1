//! The controller and the closed loop: the predictive controller of eqs. (2.3)–(2.4), the
//! stabilized DAE linearized and its δ → 0 limit, the preliminary feedback K_pr (paper and LQ),
//! and the sampled loop of Fig. 2.1 that records traces, metrics and a verdict; `timing`, one
//! sampling instant's prediction as work to be timed against δ ("faster than real-time").
//!
//! Module graph (no cycles): `config` ← `predictive` ← `linear` ← `feedback` ← `closed_loop` ←
//! `batch` (with `traces` and `metrics`). Architecture invariant: `control` knows nothing of the
//! stability analysis of the sampled loop, the session or the page.

pub mod batch;
pub mod closed_loop;
pub mod config;
pub mod cycle;
pub mod feedback;
pub mod history;
pub mod linear;
pub mod metrics;
pub mod predictive;
pub mod price;
pub mod sensing;
pub mod sensor_sweep;
pub mod timing;
pub mod traces;
pub mod work;

pub use batch::{simulate, simulate_in_chunks, RunReport};
pub use closed_loop::ClosedLoop;
pub use config::{ControllerParameters, FrictionCompensation, InnerLoop, PreliminaryFeedbackChoice, SimulationConfig};
pub use cycle::Cycle;
pub use history::{History, LoopState};
pub use metrics::{DivergenceReason, Metrics, Verdict};
pub use price::{torque_price, TorqueFigures, TorquePrice};
pub use timing::{ControllerTime, ControllerWorkload, TimingPlan};
pub use traces::{Column, Snapshot, TraceEnvelope, Traces};
pub use work::Work;
