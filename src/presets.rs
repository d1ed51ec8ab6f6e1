//! Named configurations that reproduce the paper's figures and its remarks.

use crate::params::{PreliminaryFeedbackChoice, SimulationConfig};

/// A named starting point: the paper's figures and two of its remarks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Preset {
    /// Short identifier used in URLs and on the command line.
    pub id: &'static str,
    /// One-line description for a student.
    pub title: &'static str,
    /// δ, s.
    pub sampling_period: f64,
    /// α1 = α2, 1/s.
    pub alpha: f64,
    pub preliminary_feedback: PreliminaryFeedbackChoice,
}

impl Preset {
    /// `base` with this preset's δ, α and preliminary feedback.
    pub fn apply(&self, base: &SimulationConfig) -> SimulationConfig {
        let mut c = *base;
        c.controller.sampling_period = self.sampling_period;
        c.controller.alpha = [self.alpha, self.alpha];
        c.preliminary_feedback = self.preliminary_feedback;
        c
    }
}

/// All presets, in the order a student meets them.
pub const PRESETS: [Preset; 5] = [
    Preset {
        id: "fig5.1",
        title: "Fig. 5.1: δ = 0.04 s with preliminary feedback (satisfactory errors)",
        sampling_period: 0.04,
        alpha: 2.0,
        preliminary_feedback: PreliminaryFeedbackChoice::Paper,
    },
    Preset {
        id: "fig5.2",
        title: "Fig. 5.2: δ = 0.01 s with preliminary feedback (smaller errors)",
        sampling_period: 0.01,
        alpha: 2.0,
        preliminary_feedback: PreliminaryFeedbackChoice::Paper,
    },
    Preset {
        id: "fig5.3",
        title: "Fig. 5.3: δ = 0.01 s without preliminary feedback (unstable)",
        sampling_period: 0.01,
        alpha: 2.0,
        preliminary_feedback: PreliminaryFeedbackChoice::Off,
    },
    Preset {
        id: "large-delta",
        title: "Large δ works without preliminary feedback (δ = 0.06 s)",
        sampling_period: 0.06,
        alpha: 2.0,
        preliminary_feedback: PreliminaryFeedbackChoice::Off,
    },
    Preset {
        id: "small-alpha",
        title: "Smaller α slows the growth (α = 0.5, no preliminary feedback)",
        sampling_period: 0.01,
        alpha: 0.5,
        preliminary_feedback: PreliminaryFeedbackChoice::Off,
    },
];

/// The preset with identifier `id`.
pub fn preset(id: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.id == id)
}
