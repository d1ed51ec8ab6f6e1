//! The story built from run A's configuration and its analysis.

use super::phrases::{energy_text, frequency, kpr_cure, other_end_words};
use super::Story;
use crate::analysis::resonance::PaperFeedbackEffect;
use crate::analysis::{Pole, StabilityReport};
use crate::control::config::SimulationConfig;
use crate::plot::format::{minus, significant_trimmed};
use crate::words::numbers::{complex_pair, eigenvalues_2x2, per_second, rho as rho_text};

/// The story of run A's settings (`config`, the configuration its settings make — the loop takes
/// a change only at its next sampling instant, and the story must not mix the new analysis with
/// the old configuration) and their analysis, `report`.
pub fn story(config: &SimulationConfig, report: &StabilityReport) -> Story {
    let plant = &config.plant;
    let r = &report.resonance;
    let q2 = report.rest[1];
    let [a1, a2] = config.controller.alpha;
    let alpha = if a1 == a2 {
        format!("α = {} 1/s", significant_trimmed(a1, 3))
    } else {
        format!("α1 = {}, α2 = {} 1/s", significant_trimmed(a1, 3), significant_trimmed(a2, 3))
    };
    let [open_re, _] = report.limit_pair_open[0];
    // The pairs as the text quotes them: a conjugate pair, or two real eigenvalues where the
    // motor no longer swings (never "± 0.00j").
    let open_pair = minus(&crate::words::numbers::eigen_pair(report.limit_pair_open, 2));
    let loop_limit_pair = minus(&crate::words::numbers::eigen_pair(report.limit_pair, 2));
    // With a model error the loop's δ → 0 pair is not A4 (the closed forms are for a controller
    // that knows the arm): the texts name both.
    let model_error = config.has_model_error();
    // Below the DAE's index the applied torque is an impulsive first step: no δ → 0 limit, no A4.
    let below_index = config.controller.horizon_steps < crate::control::config::DAE_INDEX;
    let feed_says = if r.controller_feed > 0.0 {
        "the controller feeds the resonance"
    } else if r.controller_feed < 0.0 {
        "the controller drains the resonance"
    } else {
        "the controller neither feeds nor drains the resonance"
    };
    // Re A4 is a growth rate only while the pair swings; two real eigenvalues are decided by the
    // larger one (det A4 < 0 puts one in the right half-plane whatever the trace).
    let re_a4_says = if let Some([larger, _]) = r.real_eigenvalues() {
        if larger > 0.0 {
            minus(&format!(
                "A4 is two real eigenvalues here, the larger {:.2} 1/s > 0: the motor no longer swings, and in the \
                 limit a slow real mode grows (Re A4 is only their mean)",
                larger
            ))
        } else {
            "A4 is two real eigenvalues here, both < 0: the motor no longer swings, and in the limit it settles \
             (Re A4 is only their mean)"
                .into()
        }
    } else if r.real_part > 0.0 {
        "Re A4 > 0: in the limit the pair grows".into()
    } else {
        "Re A4 < 0: in the limit the pair dies out".to_string()
    };
    // With a model error A4 is what a controller that knew the arm would leave: say so.
    let re_a4_says = if model_error {
        format!(
            "{re_a4_says} — for a controller that knew this arm; with the model error the pair goes to {}, where it {}",
            open_pair.clone(),
            if open_re > 0.0 { "grows" } else { "dies out" }
        )
    } else {
        re_a4_says
    };
    let six_poles = if a1 == a2 {
        format!("{} 1/s, all six", minus(&significant_trimmed(-a1, 3)))
    } else {
        format!(
            "{} 1/s and {} 1/s, three of each",
            minus(&significant_trimmed(-a1, 3)),
            minus(&significant_trimmed(-a2, 3))
        )
    };
    let [first, second] = report.flexible_pair();
    let loop_pair = match first.map(|i| report.poles[i]) {
        _ if below_index => "not to be told apart (k below the DAE's index: no δ → 0 pair to follow)".to_string(),
        // At the Nyquist frequency the pair is two real negative eigenvalues, each flipping sign
        // every period.
        Some(p) if p.discrete[0] < 0.0 && p.discrete[1].abs() <= 1e-12 * p.discrete[0].abs() => {
            let lambda =
                |i: Option<usize>| i.map_or("—".into(), |i| minus(&format!("{:.3}", report.poles[i].discrete[0])));
            format!(
                "the Nyquist frequency π/δ = {:.1} rad/s, as two real eigenvalues λ = {} and {} that flip sign every period",
                core::f64::consts::PI / config.controller.sampling_period,
                lambda(first),
                lambda(second)
            )
        }
        // A motor damped past its swing: two real poles, never "± 0.00j".
        Some(Pole { continuous: Some([re, im]), .. }) if im == 0.0 => {
            match second.and_then(|i| report.poles[i].continuous) {
                Some([re2, _]) => {
                    format!("s = {}", minus(&crate::words::numbers::eigen_pair([[re, 0.0], [re2, 0.0]], 2)))
                }
                None => format!("s = {}", per_second(re)),
            }
        }
        Some(Pole { continuous: Some([re, im]), .. }) => format!("s = {}", complex_pair(re, im)),
        _ => "—".into(),
    };
    let paper = PaperFeedbackEffect::new(plant, config.controller.alpha, q2);
    // Both eigenvalues from the closed form: a pair the gains leave real is two numbers.
    let kpr_pair = {
        let m = crate::analysis::resonance::closed_form_a4(
            plant,
            config.controller.alpha,
            q2,
            &crate::control::feedback::paper_gain(),
        );
        eigenvalues_2x2(m.trace(), m.determinant())
    };
    // The minimum-energy LQ design reflects an unstable pair into the left half-plane and leaves a
    // stable one where it is (tests/resonance.rs checks it against the design).
    let lq_says = if model_error {
        "is designed on the controller's model, the paper's arm, where it reflects that arm's unstable pair into \
         the left half-plane"
            .to_string()
    } else if open_re > 0.0 {
        // Mirrored: each eigenvalue's real part changes sign (a real pair stays two real ones).
        let [[r0, i0], [r1, i1]] = report.limit_pair_open;
        let mirrored = minus(&crate::words::numbers::eigen_pair([[-r0.abs(), i0], [-r1.abs(), i1]], 2));
        format!("reflects the unstable pair into the left half-plane (here {mirrored})")
    } else {
        format!(
            "leaves a stable pair where it is (here {})",
            minus(&crate::words::numbers::eigen_pair(report.limit_pair_open, 2))
        )
    };
    let pf = config.preliminary_feedback;
    let loop_limit = match (pf == crate::control::config::PreliminaryFeedbackChoice::Off, model_error) {
        _ if below_index => {
            "no limit (k below the DAE's index: the torque's gain on the motor grows as 1/ε²)".to_string()
        }
        (true, false) => "A4 — the ring in the pole plot".to_string(),
        (true, true) => {
            format!("{} — the ring in the pole plot (not A4: the model error moves it)", open_pair.clone())
        }
        (false, _) => {
            let error = if model_error { " and the model error" } else { "" };
            format!("A4 with K_pr{error}, {loop_limit_pair} — the diamond in the pole plot")
        }
    };
    let flexible = report.flexible_pair();
    let rho_set_by = match report.poles.first() {
        _ if below_index => "a mode that has no δ → 0 limit (k below the DAE's index)".to_string(),
        Some(_) if flexible.contains(&Some(0)) => "the flexible pair".to_string(),
        Some(p) => match p.continuous {
            Some([re, im]) if im.abs() > 1e-9 => format!("another pair, at s = {}", complex_pair(re, im)),
            Some([re, _]) => format!("another mode, at s = {}", per_second(re)),
            None => "another mode".into(),
        },
        None => "—".into(),
    };
    let law = crate::analysis::lag::LagLaw::of(report);
    let delta = config.controller.sampling_period;
    let equations = crate::words::equations::equations(report, &law, config.controller.alpha, delta);
    let pi = core::f64::consts::PI;
    // The law is for a swing: where A4 is two real eigenvalues there is no turn to lag behind.
    let swings = r.real_eigenvalues().is_none();
    let lag_growth = if below_index {
        "none here: with k below the DAE's index the impulsive torque, not the lag, decides".into()
    } else if !swings {
        "none here: the motor does not swing (A4 is two real eigenvalues), so there is no turn to lag behind".into()
    } else if law.turn(delta) < pi {
        minus(&format!(
            "σ ≈ (3β/2) cos φ − B_v1/(2 I_r1) = {:.2} × {:.2} − {:.2} = {:.2} 1/s, a heuristic's estimate: near the \
             law's edge neither its sign nor its size is to be trusted (below)",
            law.feed,
            law.lag(delta).cos(),
            law.damping,
            law.growth(delta)
        ))
    } else {
        "none here: beyond ωδ = π the swing is aliased and the law says nothing".into()
    };
    let lag_window = match law.window() {
        _ if below_index => "no window from the law here: with k below the DAE's index it does not apply".into(),
        _ if !swings => "no window from the law: the motor does not swing here".into(),
        Some([lo, hi]) => {
            format!(
                "ωδ from arccos(B_v1/(3β I_r1))/1.5 = {:.2}, where σ = 0 (a lag φ₀ = {:.0}°), up to π: δ from {} to {} s, \
                 by the law",
                law.turn(lo),
                law.zero_crossing_lag().unwrap_or(0.0).to_degrees(),
                significant_trimmed(lo, 2),
                significant_trimmed(hi, 3)
            )
        }
        None => "every small δ, by the law: here the motor's damping outweighs the feed, and no lag is needed".into(),
    };
    // How much of the arm's own damping each viscous friction gives: the arm's pair with the other
    // one set to zero.
    let arm_damping = {
        let alone = |p: crate::model::PlantParameters| crate::analysis::resonance::arm_pair(&p, q2)[0].re;
        let motor = alone(crate::model::PlantParameters { bv2: 0.0, ..*plant });
        let joint2 = alone(crate::model::PlantParameters { bv1: 0.0, ..*plant });
        let both = format!("B_v1 alone would give {}, B_v2 alone {}", per_second(motor), per_second(joint2));
        if motor.abs() > 2.0 * joint2.abs() {
            format!("mostly the motor's B_v1, a little joint 2's B_v2 ({both})")
        } else if joint2.abs() > 2.0 * motor.abs() {
            format!("mostly joint 2's B_v2, a little the motor's B_v1 ({both})")
        } else {
            format!("the motor's B_v1 and joint 2's B_v2 together ({both})")
        }
    };
    let lag_bias = {
        use crate::analysis::lag::{GRID_DESCRIPTION, LOWER_EDGE_RATIO, LOWER_EDGE_TURN, UPPER_EDGE_TURNS};
        let here = if below_index {
            "With k below the DAE's index the law does not apply here at all.".to_string()
        } else if !swings {
            "This arm is outside it: its motor does not swing.".to_string()
        } else if !crate::analysis::lag::grid_covers(plant, config.controller.alpha) {
            format!("This arm at {alpha} lies outside the grid measured: the bounds are not known to hold here.")
        } else if law.in_domain() {
            format!("This arm at {alpha} lies inside that domain.")
        } else if law.feed <= law.damping {
            format!("At {alpha} this arm needs no window: the motor's damping outweighs the feed.")
        } else {
            format!(
                "This arm at {alpha} lies outside that domain (3β/2 = {:.2} ω > ω/4): there the law's edge is a rougher \
                 guide.",
                law.feed / law.omega
            )
        };
        format!(
            "The law is a heuristic, in the manner of a describing function: it keeps only cos φ of a push delayed by \
             1.5 δ, and the phase it assumes is not the computed one (the mechanism above). Measured against ρ over \
             {GRID_DESCRIPTION}, the true lower edge lies between {:.2} and {:.2} times the law's: the law's edge is \
             mostly early, and just above it the swing can still grow while σ < 0. In ωδ the true lower edges spread \
             from {:.2} to {:.2} rad, for the law's edge arccos(B_v1/(3α I_r1))/1.5 depends on α and on B_v1/I_r1, not \
             only on the swing. The upper edge is a separate argument: at ωδ = π the sampler cannot tell the swing's \
             phase, and where the swing ends the window it ends between {:.2} π and {:.2} π. {here}",
            LOWER_EDGE_RATIO[0],
            LOWER_EDGE_RATIO[1],
            LOWER_EDGE_TURN[0],
            LOWER_EDGE_TURN[1],
            UPPER_EDGE_TURNS[0],
            UPPER_EDGE_TURNS[1]
        )
    };
    let short_feed = {
        // What steering the links does to the swing, and where the pair goes as δ → 0 (from the
        // loop's own limit: with a model error it is not A4).
        let pair = format!("as δ → 0 the pair goes to {open_pair}");
        let feeds = r.controller_feed > 0.0;
        match r.real_eigenvalues().filter(|_| !model_error) {
            _ if below_index => format!(
                "With k = {} below the DAE's index, though, the torque applied keeps a large gain on the motor's \
                 angle: there is no δ → 0 pair, and the loop is unstable (ρ = {}).",
                config.controller.horizon_steps,
                rho_text(report.spectral_radius)
            ),
            Some([larger, _]) => format!(
                "On this arm, at {alpha}, the motor is damped past its swing: {pair}, and {}.",
                if larger > 0.0 {
                    "a slow real mode grows: the smallest δ fail"
                } else {
                    "it settles: the smallest δ work without Kₚᵣ"
                }
            ),
            None if open_re > 0.0 && feeds => format!(
                "On this arm, at {alpha}, steering the links feeds the swing faster than the motor's damping drains \
                 it: {pair}, and at small δ the ringing grows."
            ),
            None if open_re > 0.0 => format!("On this arm, at {alpha}, {pair}, and at small δ the ringing grows."),
            None if feeds => format!(
                "On this arm, at {alpha}, steering the links feeds the swing, but the motor's damping drains it \
                 faster: {pair}, the ringing dies out, and the smallest δ work without Kₚᵣ."
            ),
            None => format!(
                "On this arm, at {alpha}, steering the links drains the swing: {pair}, the ringing dies out, and the \
                 smallest δ work without Kₚᵣ."
            ),
        }
    };
    let alpha_small = {
        let small = 0.2;
        let at = crate::analysis::resonance::JointResonance::new(plant, [small; 2], q2);
        let pair = eigenvalues_2x2(at.trace(), at.determinant());
        let dies = at.eigenvalues.iter().all(|e| e.re < 0.0);
        let side = if small < r.alpha_star { "below" } else { "above" };
        format!(
            "On this arm α = 0.2 1/s is {side} α*: as δ → 0 the pair goes to {pair}, {}.",
            if dies {
                "which dies out, and the smallest δ work without Kₚᵣ"
            } else {
                "which grows: the smallest δ fail without Kₚᵣ"
            }
        )
    };
    let kpr_shift_rest = {
        let at = |q2: f64| PaperFeedbackEffect::new(plant, config.controller.alpha, q2).shift;
        format!("on this arm {} at q2 = 0, {} at q2 = π", per_second(at(0.0)), per_second(at(core::f64::consts::PI)))
    };
    let lag_compare = if pf == crate::control::config::PreliminaryFeedbackChoice::Off {
        format!("The loop itself changes at ln ρ/δ = {}.", per_second(report.growth_rate))
    } else {
        format!(
            "The law is made for the loop without Kₚᵣ; this run has a preliminary feedback on, so its ln ρ/δ = {} \
             is another loop's rate, not the law's to predict.",
            per_second(report.growth_rate)
        )
    };
    // The loop's own δ → 0 pair (with its preliminary feedback) swings, or is two real modes.
    let loop_swings = report.limit_pair[0][1] != 0.0 || report.limit_pair[1][1] != 0.0;
    let clause = |c: &str| if c.is_empty() { String::new() } else { format!("; {c}") };
    let rest_words = format!(
        "this rest point (q2 = {} rad)",
        if q2.abs() < 5e-13 { "0".into() } else { significant_trimmed(q2, 3) }
    );
    // The repeating slew also holds at its other end: what the paper's K_pr does there.
    let other_end = {
        let ends = [config.reference.start[1], config.reference.end[1]];
        let other = ends.into_iter().find(|e| (e - q2).abs() > 1e-9 && config.reference.repeat_hold.is_some());
        other_end_words(plant, config.controller.alpha, paper.pair[0] < 0.0, other)
    };
    Story {
        short_lag: if below_index {
            "Which δ work here is set by that impulsive torque, not by the lag of the torque behind the swing that \
             explains the windows for k ≥ 3."
                .into()
        } else if !model_error && open_re < 0.0 && r.real_eigenvalues().is_none() {
            format!(
                "Without it, on this arm at {alpha} every small δ already works: the motor's damping outweighs the \
                 controller's feed, and no lag is needed."
            )
        } else {
            "Without it, some larger δ work because the controller's torque arrives late, 1.5 δ after the measurement \
             on average, and a push that comes more than a quarter of a swing late brakes the ringing instead of \
             feeding it. How late is late enough depends on how fast the arm rings: another arm, other δ."
                .into()
        },
        horizon_note: if below_index {
            format!(
                "k = {} is below the DAE's index {}: the torque the controller applies is one of the prediction's \
                 impulsive first steps, with a large gain on the motor's measured angle (Section 3 below). What this \
                 explanation says of the δ → 0 limit, of A4 and of the torque's zero gain on the motor holds for \
                 k ≥ {} only.",
                config.controller.horizon_steps,
                crate::control::config::DAE_INDEX,
                crate::control::config::DAE_INDEX
            )
        } else {
            String::new()
        },
        arm_damping,
        lag_bias,
        short_feed,
        alpha_small,
        kpr_shift_rest,
        lag_compare,
        alpha: alpha.clone(),
        rest: format!("q2 = {} rad", if q2.abs() < 5e-13 { "0".into() } else { significant_trimmed(q2, 3) }),
        arm_pair: complex_pair(r.arm_pair[0], r.arm_pair[1]),
        omega_joint: frequency(r.omega_joint),
        // The damped swing's own frequency (Im of the arm's pair), not the undamped formula.
        omega_arm: frequency(r.arm_pair[1].abs()) + " for the arm alone",
        omega_clamped: format!("{:.1} rad/s", r.omega_clamped),
        j_eff: format!("{:.2} kg m²", r.j_eff),
        a4: if model_error {
            eigenvalues_2x2(r.trace, r.determinant)
        } else {
            minus(&crate::words::numbers::eigen_pair(report.limit_pair_open, 2))
        },
        a4_trace: per_second(r.trace),
        a4_det: format!("{:.0} 1/s²", r.determinant),
        re_a4: per_second(r.real_part),
        feed: per_second(r.controller_feed),
        motor_damping: per_second(r.motor_damping),
        feed_says: feed_says.into(),
        re_a4_says,
        mu: format!("{:.2}", r.mu),
        beta: per_second(r.beta),
        six_poles,
        alpha2_drain: if r.mu > 1e-9 {
            format!("{:.2} α1", (1.0 + r.mu) / r.mu)
        } else {
            "∞ (μ = 0 at this rest point)".into()
        },
        alpha_star: format!("{:.2} 1/s", r.alpha_star),
        delta: format!("{} s", significant_trimmed(delta, 3)),
        rho: rho_text(report.spectral_radius),
        growth: per_second(report.growth_rate),
        loop_pair,
        loop_limit,
        rho_set_by,
        kpr_shift: per_second(paper.shift),
        kpr_shift_t1: per_second(paper.shift_t1),
        kpr_shift_t2: per_second(paper.shift_t2),
        kpr_pair: kpr_pair.clone(),
        kpr_alpha_limit: format!("{:.2} 1/s", r.paper_alpha_limit),
        lq_says,
        arm: crate::schema::arm_text(&plant.values()),
        damping_needed: match r.damping_window(plant) {
            Some(t) => {
                // Two thresholds above the one that damps the pair, never merged: where the pair
                // turns real (the motor stops swinging) and where a real eigenvalue turns positive.
                let swing = if t.swings_below > 0.0 {
                    format!(
                        "the motor swings against link 1 below {:.0} N m s/rad; above that the pair is two real \
                         eigenvalues, and one of them grows only beyond {:.0} N m s/rad",
                        t.swings_below, t.unstable_above
                    )
                } else {
                    format!(
                        "the pair is two real eigenvalues at any B_v1, and one of them grows beyond {:.0} N m s/rad",
                        t.unstable_above
                    )
                };
                format!(
                    "B_v1 > {} I_r1 = {:.1} N m s/rad as δ → 0; {swing} (this arm: {} N m s/rad)",
                    // With α1 ≠ α2 the pair is fed 3β/2, β = α1 + μ (α1 − α2) (the explanation derives it).
                    if a1 == a2 {
                        "3α".to_string()
                    } else {
                        format!("3β (β = α1 + μ (α1 − α2) = {:.2} 1/s)", r.beta)
                    },
                    t.damped_above,
                    crate::schema::format_number(plant.bv1)
                )
            }
            None => format!(
                "none at these α: the controller drains the resonance (β = {:.2} 1/s ≤ 0; this arm: {} N m s/rad)",
                r.beta,
                crate::schema::format_number(plant.bv1)
            ),
        },
        // Beside the feedback's selector while the paper's gains run on another arm or α.
        kpr_note: {
            let arm = *plant != crate::model::PlantParameters::default();
            let alpha = config.controller.alpha != [crate::control::feedback::PAPER_GAIN_ALPHA; 2];
            let differs = match (arm, alpha) {
                (true, true) => "the arm and α differ",
                (true, false) => "the arm differs",
                (false, true) => "α differs",
                (false, false) => "",
            };
            if pf == crate::control::config::PreliminaryFeedbackChoice::Twist {
                // Re A4 = 3β/2 − (Bv1 + k_d)/(2 I_r1): damped for k_d > 3β Ir1 − Bv1, and below the
                // damping at which the motor stops swinging (det A4 = 0).
                let window = crate::analysis::design::DampingWindow::of(
                    plant,
                    config.controller.alpha,
                    q2,
                    config.twist.stiffness,
                );
                let three = if a1 == a2 { "3α" } else { "3β" };
                let swing = window.swings_below.filter(|s| *s > window.lower).map_or(String::new(), |s| {
                    format!(
                        "; above {} N m s/rad the motor no longer swings against link 1 (two real eigenvalues)",
                        significant_trimmed(s, 3)
                    )
                });
                let upper = window.upper.map_or(String::new(), |u| {
                    format!(
                        " and below {} N m s/rad, beyond which a slow real mode grows (a stiffer twist spring k_p \
                         raises this bound){swing}",
                        significant_trimmed(u, 3)
                    )
                });
                format!(
                    "Your twist damper ({}) adds −k_d/(2 Ir1) = {} to Re A4, whatever α, beside the controller's feed \
                     {three}/2 = {} and the motor's own −Bv1/(2 Ir1) = {}: as δ → 0 the pair is damped for \
                     k_d > {three} Ir1 − Bv1 = {} N m s/rad{upper}.",
                    crate::words::settings::twist_gains(config),
                    per_second(r.feedback_shift),
                    per_second(r.controller_feed),
                    per_second(-r.motor_damping),
                    significant_trimmed(window.lower, 3)
                )
            } else if differs.is_empty() || pf != crate::control::config::PreliminaryFeedbackChoice::Paper {
                String::new()
            } else {
                format!(
                    "The paper's Kₚᵣ keeps its fixed gains, designed for the paper's arm at α = 2 1/s; here {differs}. \
                     The LQ design is redone for the arm and α set."
                )
            }
        },
        model_note: if model_error {
            let with = if pf == crate::control::config::PreliminaryFeedbackChoice::Off {
                String::new()
            } else {
                format!(", and {loop_limit_pair} with its preliminary feedback")
            };
            format!(
                "The controller assumes the paper's arm, not this one: its predictor, friction observer and LQ design \
                 work on the paper's numbers. As δ → 0 the loop tends to {} without Kₚᵣ{with} — not to A4 = {}, \
                 which the formulas here give for a controller that knows this arm.",
                open_pair.clone(),
                eigenvalues_2x2(r.trace, r.determinant)
            )
        } else {
            String::new()
        },
        omega_a4: frequency(law.omega),

        turn: format!("{:.2} rad ({:.3} of a turn)", law.turn(delta), law.turn(delta) / (2.0 * pi)),
        lag: {
            // Past a whole turn, say where in the turn it is: that decides push or brake.
            let degrees = law.lag(delta).to_degrees();
            let turns = (degrees / 360.0).floor();
            if turns >= 1.0 {
                format!(
                    "{:.2} rad ({degrees:.0}°, that is {:.0}° past whole turns)",
                    law.lag(delta),
                    degrees - 360.0 * turns
                )
            } else {
                format!("{:.2} rad ({degrees:.0}°)", law.lag(delta))
            }
        },
        lag_growth,
        lag_window,
        math_constraint: equations.constraint,
        math_re_a4: equations.re_a4,
        math_rho: equations.rho,
        math_growth: equations.growth,
        math_lag: equations.lag,
        // Below the DAE's index there is no pair to balance.
        math_energy: if below_index { String::new() } else { equations.energy },
        structure_v_star: String::new(),
        structure_zero_dynamics: String::new(),
        structure_quotient: String::new(),
        structure_index: String::new(),
        structure_horizon: String::new(),
        energy: if below_index {
            "Not here: with k below the DAE's index there is no flexible pair to follow.".into()
        } else {
            report.swing_energy.map_or(String::new(), |e| energy_text(&e, law.lag(delta), delta, loop_swings))
        },
        kpr_cure: if below_index {
            format!(
                "With k = {} below the DAE's index {}, small δ fail with or without Kₚᵣ: the applied torque is an \
                 impulsive first step of the prediction (ρ = {} here; Section 3 below).",
                config.controller.horizon_steps,
                crate::control::config::DAE_INDEX,
                rho_text(report.spectral_radius)
            )
        } else {
            kpr_cure(&paper, &kpr_pair, r, a1 == a2, &alpha, &rest_words, &other_end)
        },
        kpr_works: if below_index {
            format!(
                "not while k = {} is below the DAE's index {}: the loop is unstable (ρ = {})",
                config.controller.horizon_steps,
                crate::control::config::DAE_INDEX,
                rho_text(report.spectral_radius)
            )
        } else if paper.pair[0] < 0.0 {
            format!("every small δ works at {rest_words} — smaller δ even gives smaller errors{}", clause(&other_end))
        } else {
            format!(
                "still the smallest δ fail here: at {alpha} the pair it makes at {rest_words} is in the right \
                 half-plane{}",
                clause(&other_end)
            )
        },
    }
}
