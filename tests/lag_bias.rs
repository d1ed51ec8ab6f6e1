//! The lag law's bias, measured (issue 37): over the grid of `flexarm::analysis::lag`
//! (`GRID_STIFFNESS` × `GRID_MOTOR_INERTIA` × `GRID_MOTOR_DAMPING` × `GRID_ALPHA`, no preliminary
//! feedback, q2 = 0), the law's lower edge against the true lower edge of the loop's first stable
//! window (where the flexible pair stops setting ρ > 1), the true upper edge in units of π/ω and
//! the true lower edge in ωδ. Every point of the domain (`LagLaw::in_domain`) lies inside the
//! bounds `LOWER_EDGE_RATIO`, `LOWER_EDGE_TURN` and `UPPER_EDGE_TURNS`, which are rounded outward
//! from the measured extremes by at most 2 percentage points — so the page, which quotes them,
//! cannot drift from the measurement. `cargo test --test lag_bias -- --nocapture` prints the
//! figures.

mod common;

use common::lag::{config, measure, End};
use flexarm::analysis::lag::*;
use flexarm::analysis::{LinearSettings, LoopModel};

const PI: f64 = core::f64::consts::PI;
/// The δ range searched, s: the smallest is below every law's lower edge on the grid, the largest
/// past every π/ω.
const RANGE: [f64; 2] = [5e-4, 1.0];

/// min and max.
fn extend(band: &mut [f64; 2], x: f64) {
    *band = [band[0].min(x), band[1].max(x)];
}

const EMPTY: [f64; 2] = [f64::INFINITY, f64::NEG_INFINITY];

/// A measured band lies inside its constant, which is no more than `slack` wider on either side.
fn assert_tight(name: &str, constant: [f64; 2], measured: [f64; 2], slack: f64) {
    assert!(
        constant[0] <= measured[0] && measured[0] - constant[0] <= slack,
        "{name}: measured from {:.4}, the constant says {}",
        measured[0],
        constant[0]
    );
    assert!(
        constant[1] >= measured[1] && constant[1] - measured[1] <= slack,
        "{name}: measured to {:.4}, the constant says {}",
        measured[1],
        constant[1]
    );
}

#[test]
fn the_laws_edges_against_the_loops_over_the_grid() {
    let (mut ratio, mut turn, mut upper) = (EMPTY, EMPTY, EMPTY);
    let (mut outside_ratio, mut slow_upper) = (EMPTY, EMPTY);
    let (mut in_domain, mut outside, mut no_window, mut early, mut ends) = (0, 0, 0, 0, [0; 3]);
    // Points the old wording ("within −2 … +16 % of the law's", "between 0.94 π and π") misses.
    let mut old_band_misses = Vec::new();
    let mut motors_at_2 = EMPTY;
    for k1 in GRID_STIFFNESS {
        for ir1 in GRID_MOTOR_INERTIA {
            for bv1 in GRID_MOTOR_DAMPING {
                for alpha in GRID_ALPHA {
                    let case = format!("K1×{k1} I_r1×{ir1} B_v1×{bv1} α={alpha}");
                    let Some(m) = measure(&config(k1, ir1, bv1, alpha), RANGE) else {
                        no_window += 1;
                        continue;
                    };
                    let r = m.lower_ratio();
                    if !m.law.in_domain() {
                        outside += 1;
                        extend(&mut outside_ratio, r);
                        continue;
                    }
                    in_domain += 1;
                    let t = m.law.turn(m.window[0]);
                    let u = m.law.turn(m.window[1]) / PI;
                    eprintln!(
                        "{case}: ω = {:.1} rad/s, 3β/2 = {:.3} ω; lower edge ωδ law {:.3}, true {t:.3} (×{r:.3}); \
                         upper {u:.3} π ({:?})",
                        m.law.omega,
                        m.law.feed / m.law.omega,
                        m.law.turn(m.law_window[0]),
                        m.end
                    );
                    assert!((LOWER_EDGE_RATIO[0]..=LOWER_EDGE_RATIO[1]).contains(&r), "{case}: ×{r}");
                    assert!((LOWER_EDGE_TURN[0]..=LOWER_EDGE_TURN[1]).contains(&t), "{case}: ωδ = {t}");
                    extend(&mut ratio, r);
                    extend(&mut turn, t);
                    early += usize::from(r > 1.0);
                    if (k1, bv1, alpha) == (1.0, 1.0, 2.0) {
                        extend(&mut motors_at_2, t);
                    }
                    let old_ok = (0.98..=1.16).contains(&r) && (m.end != End::Swing || (0.94..=1.0).contains(&u));
                    if !old_ok {
                        old_band_misses.push(case.clone());
                    }
                    match m.end {
                        End::Swing => {
                            assert!((UPPER_EDGE_TURNS[0]..=UPPER_EDGE_TURNS[1]).contains(&u), "{case}: ends at {u} π");
                            extend(&mut upper, u);
                            ends[0] += 1;
                        }
                        End::Slow | End::Range => {
                            // A slow mode (or the range) ends the window, later than the swing would.
                            assert!(u >= UPPER_EDGE_TURNS[0], "{case}: ends at {u} π ({:?})", m.end);
                            if m.end == End::Slow {
                                extend(&mut slow_upper, u);
                                ends[1] += 1;
                            } else {
                                ends[2] += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    eprintln!(
        "grid: {} points; {no_window} without a law window, {outside} outside the domain (3β/2 > ω/4), \
         {in_domain} in it",
        GRID_STIFFNESS.len() * GRID_MOTOR_INERTIA.len() * GRID_MOTOR_DAMPING.len() * GRID_ALPHA.len()
    );
    eprintln!(
        "in the domain: true/law lower edge {:.4}–{:.4} (law early at {early} of {in_domain}); true lower edge \
         ωδ {:.4}–{:.4} rad; upper edge where the swing sets it ({} points) {:.4}–{:.4} π; where a slow mode does \
         ({} points) {:.4}–{:.4} π; {} windows reach δ = {} s",
        ratio[0],
        ratio[1],
        turn[0],
        turn[1],
        ends[0],
        upper[0],
        upper[1],
        ends[1],
        slow_upper[0],
        slow_upper[1],
        ends[2],
        RANGE[1]
    );
    eprintln!("outside the domain: true/law lower edge {:.4}–{:.4}", outside_ratio[0], outside_ratio[1]);
    eprintln!(
        "paper's spring and B_v1 at α = 2, motors ×¼–4: true lower edge ωδ {:.3}–{:.3}",
        motors_at_2[0], motors_at_2[1]
    );
    eprintln!("missed by the old wording: {} points, e.g. {:?}", old_band_misses.len(), old_band_misses.first());

    // The constants are the measurement, rounded outward by at most 2 percentage points.
    assert_tight("LOWER_EDGE_RATIO", LOWER_EDGE_RATIO, ratio, 0.02);
    assert_tight("LOWER_EDGE_TURN", LOWER_EDGE_TURN, turn, 0.02);
    assert_tight("UPPER_EDGE_TURNS", UPPER_EDGE_TURNS, upper, 0.02);
    // The old wording fails on this grid (so this measurement can tell it apart).
    assert!(!old_band_misses.is_empty());
    // The domain covers most of the grid, and the law's lower edge is mostly early.
    assert!(in_domain >= 250 && ends[0] >= 150, "{in_domain} points, {} ended by the swing", ends[0]);
    assert!(early * 10 >= in_domain * 9, "early at {early} of {in_domain}");
    // The true edge in ωδ is not the same on every arm.
    assert!(turn[1] > 5.0 * turn[0] && motors_at_2[1] - motors_at_2[0] > 0.3);
}

/// The grid's words name its arrays.
#[test]
fn the_grid_description_names_the_grid() {
    let frac = |x: f64| match x {
        0.25 => "¼".to_string(),
        0.5 => "½".to_string(),
        x => format!("{x}"),
    };
    let list = |xs: &[f64], f: &dyn Fn(f64) -> String| {
        let s: Vec<String> = xs.iter().map(|&x| f(x)).collect();
        format!("{} and {}", s[..s.len() - 1].join(", "), s[s.len() - 1])
    };
    let d = GRID_DESCRIPTION.split_whitespace().collect::<Vec<_>>().join(" ");
    assert_eq!(GRID_STIFFNESS, GRID_MOTOR_INERTIA);
    for said in [
        format!("K1 and I_r1 each {} times the paper's", list(&GRID_STIFFNESS, &frac)),
        format!("B_v1 {} times", list(&GRID_MOTOR_DAMPING, &frac)),
        format!("α = {} 1/s", list(&GRID_ALPHA, &|x| format!("{x}"))),
        format!("3β/2 ≤ ω/{}", 1.0 / DOMAIN_FEED_PER_OMEGA),
    ] {
        assert!(d.contains(&said), "{d:?} should say {said:?}");
    }
}

/// Just above the law's lower edge its σ is negative but the loop's swing still grows: the law's
/// sign is not to be trusted there (the reviewer's two cases).
#[test]
fn just_above_the_laws_edge_its_sign_is_wrong() {
    for (k1, delta) in [(1.0, 0.034), (0.7, 0.04)] {
        let c = config(k1, 1.0, 1.0, 2.0);
        let model = LoopModel::new(&LinearSettings::of(&c, Some(0.0))).unwrap();
        let report = model.report_at(delta).unwrap();
        let law = LagLaw::of(&report);
        let sigma = law.growth(delta);
        eprintln!("K1×{k1}, δ = {delta} s: law σ = {sigma:.3} 1/s, ρ = {:.4}", report.spectral_radius);
        assert!(
            sigma < -0.1 && report.spectral_radius > 1.004,
            "K1×{k1} δ = {delta}: {sigma} {}",
            report.spectral_radius
        );
    }
}

/// On the paper's arm at α = 2: the law's zero crossing is before a quarter turn, and the computed
/// phase of the held T1 against θ̇ (`SwingEnergy::lag`) is not 1.5 ωδ: it leads as δ → 0.
#[test]
fn on_the_papers_arm_the_computed_phase_is_not_the_laws() {
    let c = config(1.0, 1.0, 1.0, 2.0);
    let model = LoopModel::new(&LinearSettings::of(&c, Some(0.0))).unwrap();
    let law = LagLaw::of(&model.report().unwrap());
    let phi0 = law.zero_crossing_lag().unwrap();
    eprintln!(
        "paper's arm, α = 2: ω = {:.3} rad/s, zero crossing φ₀ = {:.4} rad = {:.1}°, lower edge ωδ = {:.4}, σ = 0 again at \
         ωδ = {:.3}",
        law.omega,
        phi0,
        phi0.to_degrees(),
        phi0 / 1.5,
        (2.0 * PI - phi0) / 1.5
    );
    assert!(phi0 < PI / 2.0 && (phi0 - (0.12f64).acos()).abs() < 1e-2);
    let mut measured = Vec::new();
    for delta in [0.001, 0.01, 0.03, 0.05] {
        let report = model.report_at(delta).unwrap();
        let e = report.swing_energy.expect("the swing's energy");
        // Signed: > 0 lags θ̇, < 0 leads it.
        let lag = (e.lag + PI).rem_euclid(2.0 * PI) - PI;
        eprintln!(
            "δ = {delta} s: held T1 lags θ̇ by {:+.1}° (law 1.5 ωδ = {:.1}°), ρ = {:.4}",
            lag.to_degrees(),
            law.lag(delta).to_degrees(),
            report.spectral_radius
        );
        measured.push(lag);
    }
    // It leads as δ → 0, and lags less than the law says at δ = 0.01 s.
    assert!(measured[0] < 0.0 && measured[1] < law.lag(0.01), "{measured:?}");
}
