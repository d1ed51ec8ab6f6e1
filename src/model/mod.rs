//! The arm, eq. (4.1): its parameters, the plant with its one stepper, Dahl friction and the
//! friction observer (4.4), and the reference slew of section 5.
//!
//! Architecture invariant: `model` knows nothing of the controller, the analysis or the page.

pub mod friction;
pub mod params;
pub mod plant;
pub mod reference;

pub use params::{PlantParameters, SlewParameters};
pub use plant::{Plant, PlantState};
pub use reference::{Reference, ReferenceSample};
