//! The paper's Fig. 2.1 at one sampling instant (`control::cycle`): the prediction the page shows
//! is the controller's own, recomputed from the kept state when looking back; the torque U_k it
//! ends on is what the loop holds one period later; and — beyond the paper — the prediction is
//! blind to the motor: from X_2 on nothing in it depends on the measured θ, θ̇, at every δ.

use flexarm::analysis::predictor_gain;
use flexarm::control::feedback::resolve_gain;
use flexarm::control::linear::linearize_at_rest;
use flexarm::control::predictive::{Predictor, Sweep};
use flexarm::control::{Cycle, LoopState};
use flexarm::model::reference::Reference;
use flexarm::*;
use nalgebra::Vector2;

fn config(delta: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig::default();
    c.controller.sampling_period = delta;
    c.preliminary_feedback = pf;
    c
}

/// A loop that keeps its states and newest sweep, as the page's runs do.
fn page_loop(c: SimulationConfig) -> ClosedLoop {
    let mut sim = ClosedLoop::new(c).unwrap();
    sim.keep_history(30.0);
    sim.keep_sweep(true);
    sim
}

#[test]
fn the_prediction_shown_is_the_controllers_own_and_recomputing_it_from_the_kept_state_gives_the_same_bits() {
    for (delta, pf, k, m) in [
        (0.01, PreliminaryFeedbackChoice::Off, 12, 8.0),
        (0.01, PreliminaryFeedbackChoice::Paper, 12, 8.0),
        (0.05, PreliminaryFeedbackChoice::Lq, 20, 11.0),
        (0.002, PreliminaryFeedbackChoice::Off, 6, 4.0),
    ] {
        let mut c = config(delta, pf);
        c.controller.horizon_steps = k;
        c.controller.eps_ratio = m;
        c.reference.repeat_hold = Some(1.5);
        let mut sim = page_loop(c);
        let mut kept = Vec::new();
        while sim.time() < 2.5 {
            sim.advance_one_period();
            // Just after an instant's work: the newest sweep starts at the newest kept instant.
            let sweep = sim.latest_sweep().unwrap().clone();
            let newest = sim.history().span().unwrap()[1];
            assert_eq!(sweep.start, newest);
            assert!(sweep.complete && sweep.states.len() == k + 1 && sweep.torques.len() == k);
            kept.push(sweep);
        }
        // Looking back at every kept instant: the cycle computes the sweep again, bit for bit.
        let mut cycle = Cycle::new();
        for sweep in kept.iter().rev().take(200) {
            cycle.fill(sim.history(), None, sim.traces(), sweep.start + 1e-12);
            assert_eq!(cycle.instant, sweep.start);
            assert_eq!(cycle.sweep.states, sweep.states, "δ = {delta}, {pf:?}: X_j at {}", sweep.start);
            assert_eq!(cycle.sweep.torques, sweep.torques);
            assert_eq!(cycle.sweep.held, sweep.held, "V_k is what the loop held from the next instant");
            assert_eq!(cycle.predicted.len(), k + 1);
        }
        // At the newest instant the cycle copies the controller's sweep instead.
        let latest = sim.latest_sweep().unwrap();
        cycle.fill(sim.history(), Some(latest), sim.traces(), sim.time());
        assert_eq!(&cycle.sweep, latest);
    }
}

/// Fig. 2.1's caption: "The control value of u over the interval t_{ρ+1} to t_{ρ+2} is chosen to be
/// U_k^ρ." Without K_pr the controller's torque on that period is U_k itself; with it, V_k plus
/// the preliminary feedback, V_k = U_k − K_pr X_k.
#[test]
fn the_torque_chosen_at_t_n_is_held_from_t_n_plus_delta_to_t_n_plus_2_delta() {
    for pf in [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper] {
        let c = config(0.02, pf);
        let gain = resolve_gain(&c).unwrap();
        let mut sim = page_loop(c);
        sim.advance(1.3).unwrap();
        let mut cycle = Cycle::new();
        let tn = sim.history().at(1.0).unwrap().0.time;
        cycle.fill(sim.history(), sim.latest_sweep(), sim.traces(), tn);
        let u_k = cycle.chosen_torque().unwrap();
        let x_k = *cycle.sweep.states.last().unwrap();
        let v_k = u_k - gain * x_k;
        assert_eq!(cycle.sweep.held, Some(v_k), "{pf:?}");
        let hold = cycle.hold().unwrap();
        assert!((hold.start - (tn + 0.02)).abs() < 1e-9 && (hold.end - (tn + 0.04)).abs() < 1e-9);
        assert_eq!(hold.v, v_k);
        // The loop's own record: v over the hold is V_k, and the torque minus the friction
        // compensation is V_k plus K_pr x(t).
        let t = sim.traces().t();
        let rows: Vec<usize> = (0..t.len()).filter(|&i| t[i] > hold.start + 1e-9 && t[i] <= hold.end + 1e-9).collect();
        assert!(rows.len() >= 9, "{} rows", rows.len());
        for &i in &rows {
            let tr = sim.traces();
            let v = Vector2::new(tr.v1()[i], tr.v2()[i]);
            assert!((v - v_k).amax() < 1e-12 * (1.0 + v_k.amax()), "{pf:?} at {}: {v} vs {v_k}", t[i]);
            if pf == PreliminaryFeedbackChoice::Off {
                let u = Vector2::new(tr.torque1()[i] - tr.xf1_hat()[i], tr.torque2()[i] - tr.xf2_hat()[i]);
                assert!((u - u_k).amax() < 1e-9 * (1.0 + u_k.amax()), "u = {u}, U_k = {u_k}");
            }
        }
        // The polyline of applied torques is flat at U_k over the hold without K_pr.
        if pf == PreliminaryFeedbackChoice::Off {
            let [at, u1, u2] = &cycle.applied;
            let mut n = 0;
            for i in (0..at.len()).filter(|&i| at[i] > hold.start + 1e-9 && at[i] < hold.end - 1e-9) {
                assert!((u1[i] - u_k[0]).abs() < 1e-9 * (1.0 + u_k[0].abs()) && (u2[i] - u_k[1]).abs() < 1e-6);
                n += 1;
            }
            assert!(n >= 8);
        }
        // And U_k is the torque predicted for the middle of that period: kε = 1.5 δ.
        assert!((cycle.sweep.time(cycle.horizon_steps) - (tn + 1.5 * 0.02)).abs() < 1e-12);
    }
}

#[test]
fn at_the_newest_instant_the_hold_is_still_to_come() {
    let mut sim = page_loop(config(0.01, PreliminaryFeedbackChoice::Off));
    sim.advance(2.003).unwrap();
    let mut cycle = Cycle::new();
    cycle.fill(sim.history(), sim.latest_sweep(), sim.traces(), sim.time());
    assert!((cycle.instant - 2.0).abs() < 1e-9);
    let hold = cycle.hold().unwrap();
    assert!(hold.start > sim.time(), "planned, not run yet");
    assert_eq!(Some(hold.v), sim.latest_sweep().unwrap().held);
    // The applied torque stops at the present.
    assert!(*cycle.applied[0].last().unwrap() <= sim.time() + 1e-12);
    assert!(cycle.applied[0].iter().all(|&t| t < hold.start));
}

#[test]
fn a_cycle_is_empty_before_anything_is_kept() {
    let sim = ClosedLoop::new(SimulationConfig::default()).unwrap();
    let mut cycle = Cycle::new();
    cycle.fill(sim.history(), sim.latest_sweep(), sim.traces(), 0.0);
    assert!(cycle.is_empty());
}

/// The sweep from a state with the motor's angle and speed changed by `d_theta`, `d_omega`.
fn sweep_from(c: &SimulationConfig, state: &LoopState, d: [f64; 4]) -> Sweep {
    let predictor = Predictor::new(&c.plant, &c.controller);
    let reference = Reference::new(c.reference);
    let mut x = state.measured();
    x[0] += d[0];
    x[3] += d[1];
    x[2] += d[2];
    x[5] += d[3];
    let mut s = Sweep::default();
    predictor.predict_into(&reference, state.time, &x, &state.torque_guess, Some(&mut s)).unwrap();
    s
}

/// Beyond the paper (whose section 3 shows it only as δ → 0 and linearized): the predictor cannot
/// see the motor at any δ. Backward Euler's first step must meet link 1's law with the motor
/// wherever the links need it, so it moves θ there in one step of ε (an impulsive U_1), whatever θ
/// was; from X_2 on the sweep, and with it U_k and the held V_k, does not depend on the measured
/// θ or θ̇ at all. Only a preliminary feedback looks at the motor. Checked on the nonlinear
/// predictor in states of a running loop, over arms, α, δ, k and m, and on the linearized one.
#[test]
fn the_prediction_forgets_the_measured_motor_after_two_steps_at_every_delta() {
    let mut cases = 0;
    for (k1, ir1) in [(1.0, 1.0), (0.25, 1.0), (4.0, 1.0), (1.0, 0.25), (1.0, 4.0)] {
        for alpha in [0.5, 2.0, 3.0] {
            for (delta, k, m) in [(0.002, 12, 8.0), (0.01, 12, 8.0), (0.05, 12, 8.0), (0.2, 4, 3.0), (0.03, 24, 24.0)] {
                let mut c = config(delta, PreliminaryFeedbackChoice::Off);
                c.plant.k1 *= k1;
                c.plant.ir1 *= ir1;
                c.controller.alpha = [alpha; 2];
                c.controller.horizon_steps = k;
                c.controller.eps_ratio = m;
                let case = format!("K1×{k1} Ir1×{ir1} α={alpha} δ={delta} k={k} m={m}");
                // A state in the middle of the slew: moving, off its law.
                let mut sim = page_loop(c);
                sim.advance(0.5).unwrap();
                let state = *sim.history().at(0.5).unwrap().0;
                let base = sweep_from(&c, &state, [0.0; 4]);
                let motor = sweep_from(&c, &state, [0.0, 0.0, 2e-3, 0.3]);
                let link = sweep_from(&c, &state, [2e-3, 0.3, 0.0, 0.0]);
                let u_k = *base.torques.last().unwrap();
                let scale = 1.0 + u_k.amax();
                // The motor's change is gone from X_2 on, and from U_3 on (to rounding) ...
                for j in 2..=k {
                    let d = (motor.states[j] - base.states[j]).amax();
                    assert!(d < 1e-9, "{case}: X_{j} moved by {d:e}");
                }
                for j in 3..=k {
                    let d = (motor.torques[j - 1] - base.torques[j - 1]).amax();
                    assert!(d < 1e-7 * scale, "{case}: U_{j} moved by {d:e}");
                }
                // ... it was there at X_1 and in the impulsive U_1, U_2 ...
                assert!((motor.states[1] - base.states[1]).amax() > 0.01, "{case}: X_1 keeps the motor's change");
                assert!((motor.torques[0] - base.torques[0]).amax() > 1.0, "{case}");
                // U_2 too (the figure's caption says so: "from X₂ and U₃ on").
                // (its gain on θ is about I_r1/ε²: 0.9 N m for this 2e-3 rad at ε = 0.067 s)
                assert!((motor.torques[1] - base.torques[1]).amax() > 0.1, "{case}: U_2 keeps the motor's change");
                // ... while the same change of link 1 moves U_k.
                let d_link = (link.torques[k - 1] - u_k).amax();
                assert!(d_link > 1e3 * (motor.torques[k - 1] - u_k).amax().max(1e-12), "{case}: {d_link:e}");
                // Linearized at rest: the predictor's gain has zero θ and θ̇ columns.
                let model = linearize_at_rest(&c.plant, c.controller.alpha, [0.0, 0.0]);
                let gain = predictor_gain(&model, &resolve_gain(&c).unwrap(), &c.controller).unwrap();
                let links = gain.column(0).amax().max(gain.column(3).amax());
                let blind = gain.column(2).amax().max(gain.column(5).amax());
                assert!(blind < 1e-8 * links, "{case}: θ, θ̇ columns {blind:e} against {links:e}");
                cases += 1;
            }
        }
    }
    assert_eq!(cases, 75);
    // The lesson quotes this check.
    let lesson = include_str!("../www/lessons/paper.md");
    assert!(lesson.contains(&format!("over {cases} arms, α, δ, k and m")), "the lesson's count");
}
