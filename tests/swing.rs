//! The flexible pair as a mode (`flexarm::analysis::swing`, issue 19): in a simulated run, the
//! swing's share of the errors — the pair's coordinate c = uᵀζ at each sampling instant while the
//! reference rests — grows or shrinks by |λ| per period, as the linear analysis says, on several
//! arms, α and preliminary feedbacks; and in the unstable loop it is what is left of the errors.

use flexarm::control::{ClosedLoop, SimulationConfig};
use flexarm::*;

/// The swing's amplitude in e1 and the rest of e1 at the sampling instants of the first rest
/// after a poke of the motor at t = 1.3 s (t from 1.4 to 2.4 s; the slew ends at 1 s), and the
/// report. The poke (the page's Poke button) lifts the swing well above what the friction
/// observer's small residual keeps stirring (about 1e-4 rad with K_pr).
fn split(config: SimulationConfig) -> (Vec<(f64, f64, f64, f64)>, flexarm::analysis::StabilityReport) {
    let mut sim = ClosedLoop::new(config).unwrap();
    sim.keep_history(5.0);
    sim.advance(1.3).unwrap();
    let (torque, duration) = flexarm::session::POKE;
    sim.apply_disturbance(torque, duration).unwrap();
    sim.advance(1.15).unwrap();
    let report = flexarm::analysis::analyze(&config, None).unwrap();
    let mode = report.swing_mode.expect("the pair's mode");
    let rest = config.reference.end;
    let rows = sim
        .history()
        .between(1.4, 2.4)
        .map(|s| {
            let zeta = s.deviation(rest);
            let c = mode.coordinate(&zeta);
            let (share, amplitude) = mode.part(c, 0);
            (s.time, amplitude, (zeta[0] - share).abs(), zeta[0].abs())
        })
        .collect();
    (rows, report)
}

#[test]
fn the_swing_in_a_run_grows_by_its_eigenvalue_per_period() {
    let cases: [(&str, f64, f64, f64, PreliminaryFeedbackChoice); 6] = [
        ("paper's arm, δ = 0.01 s", 1.0, 1.0, 0.01, PreliminaryFeedbackChoice::Off),
        ("paper's arm, δ = 0.05 s", 1.0, 1.0, 0.05, PreliminaryFeedbackChoice::Off),
        ("paper's arm, δ = 0.01 s, paper's K_pr", 1.0, 1.0, 0.01, PreliminaryFeedbackChoice::Paper),
        ("stiffer spring, δ = 0.01 s", 4.0, 1.0, 0.01, PreliminaryFeedbackChoice::Off),
        ("heavier motor, δ = 0.02 s", 1.0, 4.0, 0.02, PreliminaryFeedbackChoice::Off),
        ("softer spring, δ = 0.1 s", 0.25, 1.0, 0.1, PreliminaryFeedbackChoice::Off),
    ];
    let mut worst: f64 = 0.0;
    let mut first = None;
    for (name, k1, ir1, delta, pf) in cases {
        let mut c = SimulationConfig::default();
        c.plant.k1 *= k1;
        c.plant.ir1 *= ir1;
        c.controller.sampling_period = delta;
        c.preliminary_feedback = pf;
        let (rows, report) = split(c);
        let [re, im] = report.swing_mode.unwrap().eigenvalue;
        let per_period = re.hypot(im);
        // The observed rate: a least-squares line through ln amplitude against t.
        let n = rows.len() as f64;
        let (st, sy) = rows.iter().fold((0.0, 0.0), |(a, b), r| (a + r.0, b + r.1.ln()));
        let (mt, my) = (st / n, sy / n);
        let (num, den) =
            rows.iter().fold((0.0, 0.0), |(a, b), r| (a + (r.0 - mt) * (r.1.ln() - my), b + (r.0 - mt).powi(2)));
        let observed = num / den;
        let predicted = per_period.ln() / delta;
        println!(
            "{name}: |λ| = {per_period:.4}, ln|λ|/δ = {predicted:.3} 1/s, observed {observed:.3} 1/s over {} instants",
            rows.len()
        );
        assert!(rows.len() >= 10, "{name}");
        let off = (observed - predicted).abs() / predicted.abs().max(1.0);
        assert!(off <= 0.02, "{name}: the swing changes at {observed} 1/s, the pair's eigenvalue says {predicted}");
        worst = worst.max(off);
        first.get_or_insert((observed, predicted));
        if report.spectral_radius > 1.0 && rows.last().unwrap().1 > 0.0 {
            // Unstable: by the end of the rest the swing is most of e1.
            let (_, amp, rest, _) = *rows.last().unwrap();
            assert!(rest < 0.5 * amp, "{name}: the rest {rest} against the swing {amp}");
        }
    }
    println!("worst relative difference {worst:.4}");
    let (observed, predicted) = first.unwrap();
    let readme = include_str!("../README.md").split_whitespace().collect::<Vec<_>>().join(" ");
    let said = format!(
        "changes at ln |λ|/δ to within 2 % ({observed:.3} 1/s measured against {predicted:.3} 1/s at Fig. 5.3's δ = 0.01 s"
    );
    assert!(readme.contains(&said), "README should say {said:?}");
}

mod common;

/// The page's log |e| view draws the split (the swing in its colour) from run A's kept states,
/// and only while the view is log |e|; drawing more frames allocates nothing new.
#[test]
fn the_log_view_draws_the_swing_and_the_rest() {
    use flexarm::plot::palette;
    use flexarm::view::{Scene, ViewOptions};
    for (query, drawn) in [("preset=fig5.3&log=1", true), ("preset=fig5.3", false)] {
        let mut s = common::session(query);
        common::play(&mut s, 2.4);
        s.refresh();
        let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
        let count = |scene: &Scene| scene_vertices_of(scene, palette::SWING.0);
        scene.draw_session(&s);
        let first = count(&scene);
        assert_eq!(first > 0, drawn, "{query}: {first} swing vertices");
        scene.draw_session(&s);
        assert_eq!(count(&scene), first, "{query}: the same frame draws the same split");
    }
}

fn scene_vertices_of(scene: &flexarm::view::Scene, color: [f32; 4]) -> usize {
    scene.vertices().iter().filter(|v| v.color == color).count()
}

/// The swing's shape that the arm panel animates (the scene's `swing_shape`, from the flexible
/// pair's eigenvector) is the joint's resonance as the controller leaves it. Without K_pr, over
/// arms (K1 and I_r1 from a quarter to four times the paper's, A3 from a quarter to three times),
/// α = 1 … 3 1/s and δ = 0.002 … 0.05 s, what holds (the tolerances found: 4.9 %, 57°, 5.6 %, 22°):
/// - link 2 turns against link 1 by the coupling of the links, q2 ≈ −(A2 + A3)/A2 · q1 at q2 = 0
///   (within 5 % and 5°): free at its joint, it is flung the other way;
/// - for δ ≤ 0.01 s the motor and link 1 move against each other (at least 120° apart);
/// - where the controller's feed is small against the swing (3β/2 ≤ ω/10) and the swing turns
///   little per period (ωδ ≤ 0.3), the shape is the arm's own, a two-mass oscillator
///   (I_r1 θ̈ = −K1 (θ − q1), J_eff q̈1 = K1 (θ − q1)): link 1 moves I_r1/J_eff of the motor's
///   angle, in opposition (within 10 % and 25°).
/// Elsewhere (a heavy motor, large α, large δ, or K_pr) the loop reshapes it: the panel draws the
/// loop's own eigenvector, not the estimate.
#[test]
fn the_swing_drawn_on_the_arm_is_the_motor_against_link_1() {
    use flexarm::view::scene::Scene;
    use flexarm::view::ViewOptions;
    let (mut in_domain, mut worst) = (0, [0.0f64; 4]);
    let mut cases = 0;
    for (name, key, factor) in [
        ("paper", "k1", 1.0),
        ("K1×¼", "k1", 0.25),
        ("K1×4", "k1", 4.0),
        ("Ir1×¼", "ir1", 0.25),
        ("Ir1×4", "ir1", 4.0),
        ("A3×¼", "a3", 0.25),
        ("A3×3", "a3", 3.0),
    ] {
        for delta in [0.002, 0.01, 0.05] {
            for alpha in [1.0, 2.0, 3.0] {
                let mut c = SimulationConfig::default();
                let v = c.plant.get(key).unwrap();
                assert!(c.plant.set(key, v * factor));
                c.controller.sampling_period = delta;
                c.controller.alpha = [alpha; 2];
                c.preliminary_feedback = PreliminaryFeedbackChoice::Off;
                let case = format!("{name} δ={delta} α={alpha}");
                let report = flexarm::analysis::analyze(&c, Some(0.0)).unwrap();
                let sim = ClosedLoop::new(c).unwrap();
                let options = ViewOptions { show_swing: true, ..ViewOptions::default() };
                let mut scene = Scene::new(options, 800.0, 600.0, 1.0);
                scene.draw_loops(&sim, Some(&report), None);
                let shape = scene.swing_shape().expect("a shape");
                let [q1, q2, theta] = shape.motion.map(|p| nalgebra::Complex::new(p[0], p[1]));
                let (ratio, q2_q1) = (q1 / theta, q2 / q1);
                let opposite = |z: nalgebra::Complex<f64>| 180.0 - z.arg().to_degrees().abs();
                let p = c.plant;
                let j_eff = p.a1 + 2.0 * p.a3 - (p.a2 + p.a3).powi(2) / p.a2;
                let coupling = (p.a2 + p.a3) / p.a2;
                assert!(
                    (q2_q1.norm() / coupling - 1.0).abs() < 0.05 && opposite(q2_q1) < 5.0,
                    "{case}: q2/q1 = {q2_q1}"
                );
                worst[0] = worst[0].max((q2_q1.norm() / coupling - 1.0).abs());
                if delta <= 0.01 {
                    assert!(opposite(ratio) < 60.0, "{case}: q1/θ = {ratio}");
                    worst[1] = worst[1].max(opposite(ratio));
                    if 1.5 * alpha <= shape.omega / 10.0 && shape.omega * delta <= 0.3 {
                        let off = ratio.norm() / (p.ir1 / j_eff) - 1.0;
                        assert!(
                            off.abs() < 0.10 && opposite(ratio) < 25.0,
                            "{case}: q1/θ = {ratio}, two-mass {}",
                            p.ir1 / j_eff
                        );
                        worst[2] = worst[2].max(off.abs());
                        worst[3] = worst[3].max(opposite(ratio));
                        in_domain += 1;
                    }
                }
                // The picture turns at the pair's frequency in this loop (arg λ / δ).
                let lambda = report.swing_mode.unwrap().eigenvalue;
                assert!((shape.omega - lambda[1].atan2(lambda[0]).abs() / delta).abs() < 1e-9);
                cases += 1;
            }
        }
    }
    println!("{cases} cases, {in_domain} in the two-mass domain; worst: |q2/q1| {:.1} %, q1 against θ {:.0}°, two-mass ratio {:.1} % and {:.0}°", 100.0 * worst[0], worst[1], 100.0 * worst[2], worst[3]);
    assert_eq!(cases, 63);
    assert!(in_domain >= 12, "{in_domain}");
}
