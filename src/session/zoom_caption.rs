//! The caption of the zoom on one sampling instant (the paper's Fig. 2.1, live): what run A's
//! controller measured at the instant tₙ shown, how far it predicted, the torques it predicted
//! first and last, and when the loop holds the last — from the same [`Cycle`] the view draws (the
//! controller's own newest sweep, or computed again from the kept state when looking back).

use super::Session;
use crate::control::Cycle;
use crate::plot::format::{scientific, significant, significant_trimmed};

impl Session {
    /// The zoom's caption ("" when the zoom is off).
    pub fn cycle_caption(&self) -> String {
        if !self.settings().view.shown().predict {
            return String::new();
        }
        let sim = self.a.closed_loop();
        let now = sim.time();
        let t = self.viewing().unwrap_or(now);
        let mut cycle = Cycle::new();
        cycle.fill(sim.history(), sim.latest_sweep(), sim.traces(), t);
        if cycle.is_empty() {
            return "Fig. 2.1: no sampling instant yet.".into();
        }
        let tn = cycle.instant;
        let sweep = &cycle.sweep;
        let ms = |s: f64| format!("{} ms", significant(1e3 * s, 3));
        let pair = |v: nalgebra::Vector2<f64>| format!("({}, {}) N m", significant(v[0], 4), significant(v[1], 3));
        let mut text = format!(
            "Fig. 2.1 at tₙ = {tn:.3} s (δ = {} s): the controller measured x(tₙ) (○) and predicted k = {} steps of \
             ε = {}, τ = kε = {} ahead (dashed): at each step the torques U = (u1, u2) that keep both links on \
             their law.",
            significant_trimmed(cycle.period, 3),
            cycle.horizon_steps,
            ms(sweep.step),
            ms(cycle.horizon),
        );
        if let [u1, u2, ..] = sweep.torques[..] {
            text += &format!(
                " The first two, U₁ = ({}, {}) and U₂ = ({}, {}) N m, are impulsive: they put the motor where the \
                 links' law needs it (U₂ still depends on the motor's measured angle), and from X₂ and U₃ on nothing it \
                 predicts depends on the motor's measured angle or speed.",
                scientific(u1[0], 2),
                scientific(u1[1], 2),
                scientific(u2[0], 2),
                scientific(u2[1], 2),
            );
        }
        match (cycle.chosen_torque(), sweep.held, cycle.hold()) {
            (Some(u), Some(v), Some(hold)) => {
                text += &format!(" The last, Uₖ = {} (◆),", pair(u));
                if (u - v).amax() > 1e-9 * (1.0 + u.amax()) {
                    text += &format!(
                        " of which the predictive part v = Uₖ − K_pr Xₖ = {} is held while K_pr adds its feedback on \
                         the measured state,",
                        pair(v)
                    );
                }
                text += &format!(" is held from tₙ + δ = {:.3} s to tₙ + 2δ = {:.3} s (green)", hold.start, hold.end);
                text += &if hold.start < now - 1e-9 {
                    ".".to_string()
                } else if (now - tn).abs() < 1e-9 {
                    ": still to come, the run is at tₙ.".to_string()
                } else {
                    format!(": still to come, the run is at t = {now:.3} s.")
                };
            }
            _ => text += " The prediction failed here: the run diverged.",
        }
        text + " Step ▸ and ◂ move tₙ by one period."
    }
}
