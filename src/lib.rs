//! # flexarm
//!
//! A simulator, predictive controller and stability analysis that reproduce
//! D. von Wissel, R. Nikoukhah and S. L. Campbell, *On a new predictive control strategy:
//! application to a flexible-joint robot* (1994).
//!
//! A two-link arm whose first joint is a spring (motor angle θ, link angle q1) and which has Dahl
//! friction follows a 1-s slew. The Jankowski–Van Brussel controller integrates a stabilized
//! index-3 DAE with backward Euler over k = 12 steps of ε = δ/8 and applies the predicted torque
//! one sampling period δ later. For small δ the loop is unstable: two modes near 2.63 ± 29.58j are
//! left untouched by the controller. A preliminary linear feedback K_pr moves them to
//! ≈ −2.6 ± 29.6j, after which every small δ works.
//!
//! ## Map of the crate
//! | module | contents |
//! |---|---|
//! | [`params`] | parameters with the paper's defaults, validation, [`ConfigError`] |
//! | [`plant`] | eq. (4.1): mass matrix, forces, energy, the split RK4 / exact-Dahl integrator |
//! | [`friction`] | the Dahl model and the friction observer, eq. (4.4) |
//! | [`reference`] | the 9th-order slew and its derivatives |
//! | [`predictive`] | eqs. (2.3)–(2.4): backward Euler + Newton over the horizon |
//! | [`feedback`] | preliminary feedback: the paper's K_pr, the LQ design, a Riccati solver |
//! | [`closed_loop`] | the sampled-data loop of Fig. 2.1, traces, metrics, verdict |
//! | [`analysis`] | linearization, ρ, eigenvalues, the δ → 0 pair A4, stability maps |
//! | [`presets`] | the paper's figures as named configurations |
//! | [`svg`] | SVG figures for the CLI: stability maps and error traces |
//! | [`view`] | what the page draws, as plain geometry (no GPU types): arm, traces, axes |
//! | `web` | wasm32 only: the JS handle and the wgpu renderer |
//!
//! The core has no web types and no global state; it builds for native targets and wasm32.
//! Everything web-specific lives in `web`, compiled only for `wasm32`.

pub mod analysis;
pub mod closed_loop;
pub mod feedback;
pub mod friction;
pub mod params;
pub mod plant;
pub mod predictive;
pub mod presets;
pub mod reference;
pub mod svg;
pub mod view;

#[cfg(target_arch = "wasm32")]
pub mod web;

pub use closed_loop::{simulate, ClosedLoop, Metrics, RunReport, Verdict};
pub use params::{
    ConfigError, ControllerParameters, FrictionCompensation, InnerLoop, PlantParameters, PreliminaryFeedbackChoice,
    SimulationConfig, SlewParameters,
};

/// Everything that can go wrong in the library.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// A parameter is out of its allowed range.
    Config(ConfigError),
    /// A requested duration or time step is invalid.
    InvalidDuration(f64),
    /// A linear-algebra step of the analysis failed (singular matrix, no Riccati solution, ...).
    Analysis(&'static str),
}

impl core::fmt::Display for Error {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Error::Config(e) => e.fmt(f),
            Error::InvalidDuration(d) => {
                write!(f, "invalid duration = {d}: must be a finite number ≥ 0 s (at most 1e6 s)")
            }
            Error::Analysis(m) => write!(f, "analysis failed: {m}"),
        }
    }
}

impl std::error::Error for Error {}

impl From<ConfigError> for Error {
    fn from(e: ConfigError) -> Self {
        Error::Config(e)
    }
}
