//! Linear stability analysis of the sampled loop: its one-period map linearized at rest, the
//! eigenvalues and spectral radius ρ ([`sampled`]), stability maps ρ(δ, α) as resumable jobs
//! ([`map`]), the stable windows of δ ([`windows`]), and the flexible joint's resonance, the pair
//! A4, in closed form ([`resonance`]), and why some larger δ work without preliminary feedback: the
//! lag of the held torque behind the swing ([`lag`]). With sensors on, the loop is a digital
//! controller: its 16-state map from the measured angles ([`digital`]), whose ρ `LoopModel` then
//! reports, and the noise floor the encoders' quantization leaves on the errors and the torque
//! ([`noise`]).
//!
//! Architecture invariant: `analysis` reads the controller (`control`) and the arm (`model`) and
//! is read by the session, the CLI and the figures; it never runs the nonlinear simulation.

pub mod design;
pub mod digital;
pub mod energy;
pub mod judgement;
pub mod lag;
pub mod noise;
pub mod resonance;
pub mod sampled;
pub mod sensor_study;
pub mod stability_map;
pub mod structure;
pub mod swing;
pub mod windows;

pub use digital::{digital_loop, DigitalLoop, MatDigital, DIGITAL_STATES};
pub use noise::{digital_spectrum, discrete_lyapunov, noise_floor, NoiseFloor};
pub use sampled::{
    analyze, describes, loop_eigenvalues, sampled_loop_matrix, spectral_radius, LinearSettings, LoopModel, Pole,
    StabilityReport,
};
pub use stability_map::{log_space, stability_map, MapGrid, MapJob, MapRows, StabilityMap};
pub use windows::{stable_intervals, stable_windows, StableWindows};

/// The linearization and the δ → 0 limit live with the controller they describe.
pub use crate::control::linear::{limit_pair, linearize_at_rest, predictor_gain, LimitPair, LinearModel};
