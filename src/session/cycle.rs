//! The caption of the zoom on one sampling instant (the paper's Fig. 2.1, live): what run A's
//! controller measured at the instant t_n shown, how far it predicted, the torque U_k it chose and
//! when the loop holds it — every number read off the run's kept states and its newest sweep (no
//! prediction is made for the words; the view draws the same sweep).

use super::Session;
use crate::plot::format::sig;

impl Session {
    /// The zoom's caption ("" when the zoom is off or nothing is kept yet).
    pub fn cycle_caption(&self) -> String {
        if !self.settings().view.shown().predict {
            return String::new();
        }
        let sim = self.a.closed_loop();
        let history = sim.history();
        let t = self.viewing().unwrap_or_else(|| sim.time());
        let Some((state, config)) = history.at(t) else {
            return "Fig. 2.1: no sampling instant yet.".into();
        };
        let tn = state.time;
        let c = &config.controller;
        let ms = |s: f64| format!("{} ms", sig(1e3 * s, 3));
        let next = history.after(tn).and_then(|t| history.at(t)).map(|(s, _)| *s);
        // U_k is the next instant's Newton seed; what is held from it, its v. At the newest
        // instant both are in the controller's own sweep.
        let (chosen, held, to_come) = match next {
            Some(s) if s.v_next.is_some() => (Some(s.torque_guess), s.v_next, false),
            _ => {
                let sweep = sim.latest_sweep().filter(|s| s.start == tn && s.complete);
                (sweep.and_then(|s| s.torques.last().copied()), sweep.and_then(|s| s.held), true)
            }
        };
        let t1 = next.map_or(tn + c.sampling_period, |s| s.time);
        let t2 = history.after(t1).unwrap_or(t1 + c.sampling_period);
        let pair = |v: nalgebra::Vector2<f64>| format!("({}, {}) N m", sig(v[0], 4), sig(v[1], 3));
        let mut text = format!(
            "Fig. 2.1 at tₙ = {tn:.3} s (δ = {} s): the controller measured x(tₙ) (○) and predicted k = {} steps of \
             ε = {}, τ = kε = {} ahead (dashed).",
            crate::plot::format::sig_trim(c.sampling_period, 3),
            c.horizon_steps,
            ms(c.integration_step()),
            ms(c.horizon()),
        );
        match (chosen, held) {
            (Some(u), Some(v)) => {
                text += &format!(" It chose Uₖ = {} (◆),", pair(u));
                if (u - v).amax() > 1e-9 * (1.0 + u.amax()) {
                    text += &format!(
                        " of which the predictive part v = Uₖ − K_pr Xₖ = {} is held and K_pr adds its feedback on the \
                         measured state,",
                        pair(v)
                    );
                }
                text += &format!(" held from tₙ + δ = {t1:.3} s to tₙ + 2δ = {t2:.3} s (green)");
                text += if to_come { ": still to come, the run is at tₙ." } else { "." };
            }
            _ => text += " The prediction failed here: the run diverged.",
        }
        text += " Its first two steps, with impulsive torques U₁ and U₂, put the motor where the links' law needs \
                 it: from X₂ on, nothing it predicts depends on the motor's measured angle or speed. Step ▸ and ◂ \
                 move tₙ by one period.";
        text
    }
}
