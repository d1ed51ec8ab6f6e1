//! # flexarm
//!
//! A simulator, predictive controller and stability analysis that reproduce
//! D. von Wissel, R. Nikoukhah and S. L. Campbell, *On a new predictive control strategy:
//! application to a flexible-joint robot* (1994).
//!
//! A two-link arm whose first joint is a spring (motor angle θ, link angle q1) and which has Dahl
//! friction follows a 1-s slew. The Jankowski–Van Brussel controller integrates a stabilized
//! index-3 DAE with backward Euler over k = 12 steps of ε = δ/8 and applies the predicted torque
//! one sampling period δ later. For small δ the loop is unstable: the joint's resonance (motor and
//! link 1 against each other through the spring) is a motion the controller's torque has no gain on —
//! its gain is exactly zero on θ and θ̇ — and, on the paper's arm, feeds; in the limit δ → 0 it is the pair A4 ≈ 2.63 ± 29.58j, with
//! Re A4 = 3α/2 − Bv1/(2 Ir1) ([`analysis::resonance`]). A preliminary linear feedback K_pr damps
//! the motor and moves the pair to ≈ −2.5 ± 29.6j, after which every small δ works.
//!
//! ## Map of the crate (lower layers first; see ARCHITECTURE.md)
//! | module | contents |
//! |---|---|
//! | [`error`] | one error family: [`Error`], [`ConfigError`], [`ParseError`] |
//! | [`schema`] | every user-settable parameter once: key, label, unit, range and why, default, help |
//! | [`model`] | the arm, eq. (4.1), its one stepper, Dahl friction (4.4), the reference slew |
//! | [`control`] | predictive controller (2.3)–(2.4), linearization and δ → 0 limit, K_pr, the closed loop of Fig. 2.1 |
//! | [`analysis`] | ρ and eigenvalues of the sampled loop, stability maps, stable windows of δ, the pair A4 in closed form |
//! | [`words`] | facts in words: verdicts, judgements, the explanation's numbers, for the page and the CLI alike |
//! | [`lesson`] | the guided lesson as data: `www/lessons/paper.md`, read into steps, questions and goals |
//! | [`session`] | what a user has open: settings and state string, runs A and B, analyses, maps, the timeline, the lesson's progress |
//! | [`classroom`] | the lesson, the answers, student mode, a link's moment and embeds, around a session |
//! | [`plot`] | ticks, number format, colours, contours — shared by the canvas and the SVG figures |
//! | [`view`] | what the page draws, as plain geometry (no GPU types), and every figure as SVG from it ([`view::figure`]) |
//! | [`offline`] | the page as one self-contained HTML file that opens from disk, carrying its start and a teacher's lesson |
//! | `web` | wasm32 only: the JS handle and the wgpu renderer |
//!
//! The core has no web types and no global state; it builds for native targets and wasm32.

pub mod analysis;
pub mod classroom;
pub mod control;
pub mod error;
pub mod lesson;
pub mod model;
pub mod offline;
pub mod plot;
pub mod schema;
pub mod session;
pub mod sort;
pub mod view;
pub mod words;

#[cfg(target_arch = "wasm32")]
pub mod web;

pub use control::config::{
    ControllerParameters, FrictionCompensation, InnerLoop, PreliminaryFeedbackChoice, SimulationConfig,
};
pub use control::{simulate, ClosedLoop, Metrics, RunReport, Verdict};
pub use error::{ConfigError, Error, ParseError};
pub use model::params::{PlantParameters, SlewParameters};
