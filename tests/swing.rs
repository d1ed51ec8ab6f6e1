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
