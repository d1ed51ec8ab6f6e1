//! Section 3 made computable (issue 37): V* by its recursion, the zero dynamics Ā1 on it, the
//! quotient A4, the index before and after the stabilized differentiations, and what a horizon k
//! at or below the index does — each checked against what it must be, over the arm presets, α
//! (equal and unequal) and the rest angle q2, and each check shown to reject a wrong answer.

use flexarm::analysis::resonance::closed_form_a4;
use flexarm::analysis::structure::*;
use flexarm::analysis::*;
use flexarm::control::config::{ControllerParameters, DAE_INDEX};
use flexarm::control::feedback::{paper_gain, FeedbackGain};
use flexarm::session::presets::{arm, ARMS};
use flexarm::*;
use nalgebra::Complex;
use std::f64::consts::PI;
use std::process::Command;

const ALPHAS: [[f64; 2]; 6] = [[0.5, 0.5], [2.0, 2.0], [5.0, 5.0], [0.5, 2.0], [5.0, 0.5], [2.0, 5.0]];
const Q2: [f64; 3] = [0.0, 0.5 * PI, PI];

fn config(plant: PlantParameters, alpha: [f64; 2], pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { plant, preliminary_feedback: pf, ..SimulationConfig::default() };
    c.controller.alpha = alpha;
    c
}

/// Every (arm preset, α, q2) with the paper's K_pr and without: the structure and its settings.
fn grid() -> Vec<(&'static str, [f64; 2], f64, PreliminaryFeedbackChoice, Structure)> {
    let mut out = Vec::new();
    for a in ARMS {
        for alpha in ALPHAS {
            for q2 in Q2 {
                for pf in [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper] {
                    let s = Structure::of(&config(a.plant(), alpha, pf), Some(q2))
                        .unwrap_or_else(|e| panic!("{} α = {alpha:?} q2 = {q2}: {e}", a.id));
                    out.push((a.id, alpha, q2, pf, s));
                }
            }
        }
    }
    assert_eq!(out.len(), 6 * 6 * 3 * 2);
    out
}

/// Whether `zeros` is {−α1 ×3, −α2 ×3} to 1e-6 relative (one cluster of six for α1 = α2).
fn laws_poles(zeros: &[Cluster], alpha: [f64; 2]) -> bool {
    let mut expected: Vec<(f64, usize)> =
        if alpha[0] == alpha[1] { vec![(-alpha[0], 6)] } else { vec![(-alpha[0], 3), (-alpha[1], 3)] };
    expected.sort_by(|a, b| a.0.total_cmp(&b.0));
    zeros.len() == expected.len()
        && zeros.iter().zip(&expected).all(|(c, (v, m))| {
            c.multiplicity == *m && (c.value[0] - v).abs() <= 1e-6 * v.abs() && c.value[1].abs() <= 1e-6 * v.abs()
        })
}

/// The largest distance from an eigenvalue of `expected` to the nearest of `got`, over |expected|.
fn spectrum_gap(got: &[Cluster], expected: &[Complex<f64>]) -> f64 {
    let got: Vec<Complex<f64>> =
        got.iter().flat_map(|c| std::iter::repeat_n(Complex::new(c.value[0], c.value[1]), c.multiplicity)).collect();
    let scale = expected.iter().map(|l| l.norm()).fold(0.0, f64::max);
    if got.len() != expected.len() {
        return f64::INFINITY;
    }
    expected.iter().map(|l| got.iter().map(|g| (g - l).norm()).fold(f64::INFINITY, f64::min)).fold(0.0, f64::max)
        / scale
}

#[test]
fn v_star_is_six_dimensional_and_its_zero_dynamics_are_the_laws_poles() {
    for (id, alpha, q2, pf, s) in grid() {
        let at = format!("{id} α = {alpha:?} q2 = {q2} {pf:?}");
        assert_eq!(s.v_star_dim, 6, "{at}");
        assert_eq!(s.v_star_sequence, [8, 7, 6], "{at}");
        assert!(s.quotient_is_motor, "{at}: θ, θ̇ complete V*");
        assert!(laws_poles(&s.zero_dynamics, alpha), "{at}: Ā1 = {:?}", s.zero_dynamics);
        assert!(s.minimum_phase, "{at}");
        assert!(s.invariance_residual < 1e-10, "{at}: (3.2) is block triangular, residual {:e}", s.invariance_residual);
        assert!(s.limit_ignores_motor, "{at}: K_lim has no gain on θ, θ̇");
    }
    // The check rejects what is not the laws' poles: an integrator w1 gain of 1.1 α³ instead of α³
    // (the chain's polynomial is then no longer (s + α)³), and the right poles with the wrong α.
    let plant = PlantParameters::default();
    let mut model = linearize_at_rest(&plant, [2.0, 2.0], [0.0, 0.0]);
    assert!(laws_poles(&decompose(&model, &FeedbackGain::zeros()).unwrap().zero_dynamics, [2.0, 2.0]));
    model.a[(6, 0)] *= 1.1;
    let wrong = decompose(&model, &FeedbackGain::zeros()).unwrap();
    assert_eq!(wrong.v_star_dim, 6);
    assert!(!laws_poles(&wrong.zero_dynamics, [2.0, 2.0]), "{:?}", wrong.zero_dynamics);
    let right = Structure::of(&config(plant, [0.5, 2.0], PreliminaryFeedbackChoice::Off), None).unwrap();
    assert!(laws_poles(&right.zero_dynamics, [0.5, 2.0]));
    assert!(!laws_poles(&right.zero_dynamics, [0.5, 2.000_01]));
    assert!(!laws_poles(&right.zero_dynamics, [2.0, 2.0]));
}

#[test]
fn the_quotient_is_a4_in_closed_form_with_and_without_the_papers_gain() {
    let mut worst: f64 = 0.0;
    for (id, alpha, q2, pf, s) in grid() {
        let at = format!("{id} α = {alpha:?} q2 = {q2} {pf:?}");
        let plant = arm(id).unwrap().plant();
        let open = closed_form_a4(&plant, alpha, q2, &FeedbackGain::zeros()).complex_eigenvalues();
        let gap = spectrum_gap(&s.quotient_open, open.as_slice());
        assert!(gap < 1e-6, "{at}: {:?} vs {open:?}", s.quotient_open);
        let with = match pf {
            PreliminaryFeedbackChoice::Paper => closed_form_a4(&plant, alpha, q2, &paper_gain()),
            _ => closed_form_a4(&plant, alpha, q2, &FeedbackGain::zeros()),
        }
        .complex_eigenvalues();
        let gap_with = spectrum_gap(&s.quotient, with.as_slice());
        assert!(gap_with < 1e-6, "{at}: {:?} vs {with:?}", s.quotient);
        assert_eq!(s.feedback, pf == PreliminaryFeedbackChoice::Paper);
        assert_eq!(s.quotient_open_stable, open.iter().all(|l| l.re < 0.0), "{at}");
        assert_eq!(s.quotient_stable, with.iter().all(|l| l.re < 0.0), "{at}");
        worst = worst.max(gap).max(gap_with);
    }
    // The paper's numbers (ERRATA.md): 2.639 ± 29.58j, and with the printed K_pr −2.48 ± 29.6j.
    let paper = |pf| Structure::of(&config(PlantParameters::default(), [2.0, 2.0], pf), Some(0.0)).unwrap();
    let off = paper(PreliminaryFeedbackChoice::Off);
    assert!(
        (off.quotient_open[0].value[0] - 2.639).abs() < 1e-3 && (off.quotient_open[0].value[1] - 29.58).abs() < 1e-2
    );
    let on = paper(PreliminaryFeedbackChoice::Paper);
    assert!((on.quotient[0].value[0] + 2.478).abs() < 1e-3 && (on.quotient[0].value[1] - 29.60).abs() < 1e-2);
    // The check tells A4 from a neighbour's: the same arm with K1 one percent off.
    let stiffer = PlantParameters { k1: 1.01 * PlantParameters::default().k1, ..PlantParameters::default() };
    let neighbour = closed_form_a4(&stiffer, [2.0, 2.0], 0.0, &FeedbackGain::zeros()).complex_eigenvalues();
    assert!(spectrum_gap(&off.quotient_open, neighbour.as_slice()) > 1e3 * worst.max(1e-12));
}

#[test]
fn the_limit_feedback_from_the_wong_sequences_is_the_backward_euler_limit() {
    // Two ways to K_lim: the projector onto 𝒱* along 𝒲* here, the purified k-step backward-Euler
    // map in `limit_pair`.
    for a in ARMS {
        for alpha in [[2.0, 2.0], [0.5, 2.0]] {
            for gain in [FeedbackGain::zeros(), paper_gain()] {
                let model = linearize_at_rest(&a.plant(), alpha, [0.5 * PI, 0.7]);
                let ours = decompose(&model, &gain).unwrap().k_lim;
                let theirs = limit_pair(&model, &gain).unwrap().k_lim;
                let gap = (ours - theirs).amax() / theirs.amax();
                assert!(gap < 1e-8, "{} α = {alpha:?}: {gap:e}", a.id);
            }
        }
    }
}

#[test]
fn the_index_is_five_with_the_path_constraint_and_three_stabilized() {
    for a in ARMS {
        for q2 in Q2 {
            let s = Structure::of(&config(a.plant(), [2.0, 2.0], PreliminaryFeedbackChoice::Off), Some(q2)).unwrap();
            assert_eq!((s.index_path, s.index_stabilized), (5, 3), "{} q2 = {q2}", a.id);
            assert_eq!(s.index_path_sequence, [0, 2, 4, 6, 7, 8], "{}", a.id);
            assert_eq!(s.index_stabilized_sequence, [0, 2, 3, 4], "{}", a.id);
            assert_eq!(s.schema_index, s.index_stabilized, "the schema's DAE_INDEX is the computed one");
        }
    }
    assert_eq!(DAE_INDEX, 3);
    // The index follows the constraint: on the velocities q̇ − q̇_d = 0 it is one less than on the
    // angles; on the torques themselves (u = 0) it is 1.
    let model = linearize_at_rest(&PlantParameters::default(), [2.0, 2.0], [0.0, 0.0]);
    let (e, f) = path_pencil(&model);
    assert_eq!(index(&(e, f)).unwrap().0, 5);
    let mut velocity = f;
    velocity[(8, 0)] = 0.0;
    velocity[(9, 1)] = 0.0;
    velocity[(8, 3)] = 1.0;
    velocity[(9, 4)] = 1.0;
    assert_eq!(index(&(e, velocity)).unwrap().0, 4);
    let mut torque = f;
    torque[(8, 0)] = 0.0;
    torque[(9, 1)] = 0.0;
    torque[(8, 8)] = 1.0;
    torque[(9, 9)] = 1.0;
    assert_eq!(index(&(e, torque)).unwrap().0, 1);
}

#[test]
fn below_the_index_the_torque_remembers_the_motors_inconsistent_start() {
    let plant = PlantParameters::default();
    let s = Structure::of(&config(plant, [2.0, 2.0], PreliminaryFeedbackChoice::Off), Some(0.0)).unwrap();
    let delta = s.delta;
    let eps = |p: &HorizonProbe| delta / p.eps_ratio;
    let [k1, k2, k3, k4] = [1, 2, 3, 4].map(|k| *s.probe(k).unwrap());
    // kε = 1.5 δ as the settings' k = 12, m = 8; ε ≤ δ.
    assert_eq!(s.horizon_ratio, 1.5);
    assert_eq!([k1.eps_ratio, k2.eps_ratio, k3.eps_ratio], [1.0, 4.0 / 3.0, 2.0]);
    // k = 1 and 2 carry the inconsistent start into the torque, with gains growing as 1/ε²: for
    // this arm, U1 = (Ir1/ε² + Bv1/ε) θ + (Ir1/ε) θ̇ + …, U2 = (Ir1/ε²) θ + … (no θ̇).
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
    assert!(close(k1.theta_gain, plant.ir1 / eps(&k1).powi(2) + plant.bv1 / eps(&k1)), "{k1:?}");
    assert!(close(k1.theta_rate_gain, plant.ir1 / eps(&k1)), "{k1:?}");
    assert!(close(k2.theta_gain, plant.ir1 / eps(&k2).powi(2)), "{k2:?}");
    assert!(k2.theta_rate_gain < 1e-9 * k2.theta_gain, "{k2:?}");
    assert!((k2.theta_gain_order.unwrap() - 2.0).abs() < 1e-9);
    assert!((k1.theta_gain_order.unwrap() - 2.0).abs() < 0.05);
    // At the settings' own ε = δ/8 that is the 1.24e6 N m/rad.
    let model = linearize_at_rest(&plant, [2.0, 2.0], [0.0, 0.0]);
    let two = ControllerParameters { horizon_steps: 2, eps_ratio: 8.0, ..ControllerParameters::default() };
    let gain = predictor_gain(&model, &FeedbackGain::zeros(), &two).unwrap();
    let theta = gain[(0, 2)].abs().max(gain[(1, 2)].abs());
    assert!((theta - 1.2409e6).abs() < 1e2, "{theta}");
    // From k = 3 on, the index, there is none: k = 3 is already enough. The state forgets a step
    // earlier.
    assert!(!k1.torque_forgets && !k2.torque_forgets && k3.torque_forgets && k4.torque_forgets);
    assert!(!k1.state_forgets && k2.state_forgets && k3.state_forgets);
    assert_eq!((s.torque_forgets_from, s.state_forgets_from), (Some(3), Some(2)));
    assert!(s.index_suffices());
    assert!(k3.theta_gain < 1e-9 * k2.theta_gain && k3.theta_gain_order.is_none());
    // And the loop: k = 1, 2 unstable (ρ ≈ 1.45, 2.1), k = 3 as k = 4 (the pair A4, unstable
    // without K_pr at δ = 0.01 s).
    let rho = |p: &HorizonProbe| p.rho.unwrap();
    assert!(rho(&k1) > 1.4 && rho(&k2) > 2.0, "{} {}", rho(&k1), rho(&k2));
    assert!((rho(&k3) - rho(&k4)).abs() < 1e-4, "{} {}", rho(&k3), rho(&k4));
    // With the paper's K_pr, k = 3 is stable as k = 4 is, and as the settings' k = 12.
    let c = config(plant, [2.0, 2.0], PreliminaryFeedbackChoice::Paper);
    let with = Structure::of(&c, Some(0.0)).unwrap();
    let twelve = analyze(&c, Some(0.0)).unwrap().spectral_radius;
    let [w3, w4] = [3, 4].map(|k| with.probe(k).unwrap().rho.unwrap());
    assert!(w3 < 1.0 && w4 < 1.0 && twelve < 1.0);
    assert!((w3 - twelve).abs() < 1e-3 && (w4 - twelve).abs() < 1e-3, "{w3} {w4} {twelve}");
    assert!(with.probe(2).unwrap().rho.unwrap() > 1.0);
}

#[test]
fn k_equal_to_the_index_forgets_over_arms_alpha_and_rest_points() {
    for (id, alpha, q2, pf, s) in grid() {
        let at = format!("{id} α = {alpha:?} q2 = {q2} {pf:?}");
        assert_eq!(s.torque_forgets_from, Some(3), "{at}: {:?}", s.probes);
        assert_eq!(s.state_forgets_from, Some(2), "{at}");
        let rho: Vec<f64> = s.probes.iter().map(|p| p.rho.unwrap()).collect();
        assert!(rho[0] > 1.3 && rho[1] > 1.6, "{at}: k = 1, 2 are unstable: {rho:?}");
        assert!((rho[2] - rho[3]).abs() < 1e-3, "{at}: k = 3 as k = 4: {rho:?}");
    }
}

#[test]
fn the_sentences_say_the_structures_numbers() {
    let paper = PlantParameters::default();
    let s = Structure::of(&config(paper, [2.0, 2.0], PreliminaryFeedbackChoice::Paper), Some(0.0)).unwrap();
    let w = flexarm::words::structure::structure(&s, PreliminaryFeedbackChoice::Paper);
    assert!(w.v_star.contains("is 6-dimensional (the recursion Vᵢ: 8 → 7 → 6)"), "{}", w.v_star);
    assert!(w.zero_dynamics.contains("at −2 1/s (×6)") && w.zero_dynamics.contains("minimum phase"));
    assert!(w.quotient.contains("A4 = 2.64 ± 29.58j 1/s, unstable"), "{}", w.quotient);
    assert!(w.quotient.contains("with paper K_pr it moves to −2.48 ± 29.60j 1/s, stable"), "{}", w.quotient);
    assert!(w.index.starts_with("Index 5 ") && w.index.contains(", 3 with the stabilized"), "{}", w.index);
    assert!(w.horizon.contains("U_k from k = 3 on, so k = 3 is already enough"), "{}", w.horizon);
    assert!(w.horizon.contains("U₂ reacts to θ(tₙ) with 3.45e4 N m/rad (∝ 1/ε²)"), "{}", w.horizon);
    assert!(w.horizon.contains("k = 3 (m = 2, kε = 1.5δ): no gain on θ, θ̇, ρ = 0.9808"), "{}", w.horizon);
    assert!(w.horizon.contains("k = 1 (m = 1, kε = 1δ)"), "k = 1 cannot reach 1.5δ with ε ≤ δ: {}", w.horizon);
    // The zeros are the law's: the arm with its links as output has none of its own.
    assert_eq!(s.arm_zeros, 0);
    assert!(w.zero_dynamics.contains("no finite zeros of its own"), "{}", w.zero_dynamics);
    // Other settings, other numbers: unequal α, no feedback, the heavier motor.
    let heavier = arm("heavier").unwrap().plant();
    let s = Structure::of(&config(heavier, [0.5, 2.0], PreliminaryFeedbackChoice::Off), Some(0.0)).unwrap();
    let w = flexarm::words::structure::structure(&s, PreliminaryFeedbackChoice::Off);
    assert!(w.zero_dynamics.contains("at −2 1/s (×3) and −0.5 1/s (×3)"), "{}", w.zero_dynamics);
    let a4 = closed_form_a4(&heavier, [0.5, 2.0], 0.0, &FeedbackGain::zeros()).complex_eigenvalues();
    let upper = if a4[0].im > 0.0 { a4[0] } else { a4[1] };
    let pair = format!("{:.2} ± {:.2}j 1/s", upper.re, upper.im).replace('-', "−");
    assert!(w.quotient.contains(&format!("A4 = {pair}")), "{} vs {pair}", w.quotient);
    assert!(!w.quotient.contains("K_pr it moves to"), "no feedback, no move: {}", w.quotient);
    assert!(w.horizon.contains(&format!("{:.2e}", heavier.ir1 / (0.01f64 / (4.0 / 3.0)).powi(2))), "{}", w.horizon);
}

#[test]
fn analyze_prints_the_structure_and_exports_it() {
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm")).args(["analyze"]).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(out.status.success());
    let block: Vec<&str> = text.lines().skip_while(|l| !l.starts_with("section 3's structure")).take(6).collect();
    assert_eq!(block.len(), 6, "{text}");
    assert!(block[1].contains("6-dimensional") && block[2].contains("Ā1") && block[3].contains("A4 = 2.64 ± 29.58j"));
    assert!(block[4].starts_with("  Index 5 ") && block[5].contains("k = 3 is already enough"), "{block:?}");
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm")).args(["analyze", "--json", "--pf", "off"]).output().unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let s = &v["structure"];
    assert_eq!(s["v_star_dim"], 6);
    assert_eq!((s["index_path"].as_u64(), s["index_stabilized"].as_u64()), (Some(5), Some(3)));
    assert_eq!(s["zero_dynamics"][0]["multiplicity"], 6);
    assert!((s["quotient_open"][0]["value"][0].as_f64().unwrap() - 2.639).abs() < 1e-3);
    assert_eq!(s["torque_forgets_from"], 3);
    assert_eq!(s["sentences"].as_array().unwrap().len(), 5);
    assert_eq!(s["feedback"], false);
}

/// "Try k below it": the schema lets k go below the DAE's index, and the simulation shows what the
/// structure says — with k = 2 the applied torque is the impulsive U₂ and the arm is thrown off
/// course at once; with k = 3, the index, it is as stable as with the paper's k = 12.
#[test]
fn below_the_index_the_simulated_arm_is_thrown_off_at_the_index_it_is_not() {
    let run = |k: &str, m: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_flexarm"))
            .args(["simulate", "--k", k, "--eps-ratio", m, "--duration", "2"])
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8(out.stdout).unwrap()
    };
    let below = run("2", "1.33");
    assert!(below.contains("Diverged") && below.contains("a tracking error passed π rad"), "{below}");
    for (k, m) in [("3", "2"), ("12", "8")] {
        let at = run(k, m);
        assert!(at.contains("verdict                     Stable"), "k = {k}: {at}");
    }
}

/// k and m fit only each other (k/2 ≤ m ≤ k): a link or a Try button giving both, in either
/// order, is read whole — not refused key by key against the other's old value.
#[test]
fn a_link_with_k_below_the_index_and_its_m_is_read_whole() {
    for state in ["k=2&eps_ratio=1.33", "eps_ratio=1.33&k=2", "k=20&eps_ratio=14"] {
        let (s, notices) = flexarm::session::Session::open(state);
        assert!(notices.is_empty(), "{state}: {notices:?}");
        let c = s.run(0).unwrap().closed_loop().config().controller;
        assert!(c.horizon_steps == 2 || c.horizon_steps == 20, "{state}: {c:?}");
    }
    // A k that fits no m given is still refused, with its notice.
    let (_, notices) = flexarm::session::Session::open("k=2");
    assert!(notices.iter().any(|n| n.key == "k"), "{notices:?}");
}
