//! Why some larger δ work without a preliminary feedback (issue 19; the paper: "not clear"): the
//! lag law of `flexarm::analysis::lag`, checked against ρ over arms and α — the stiffness K1 and
//! the motor inertia I_r1 each from a quarter to four times the paper's, α from 0.5 to 3 1/s.
//!
//! The law: the held torque reaches the swing 1.5 δ late on average; the controller's feed 3β/2
//! then pushes the swing only by cos(1.5 ωδ) of itself (ω = |Im A4|), and the swing is damped
//! from ωδ = arccos(B_v1/(3β I_r1))/1.5 up to about π (half a turn per period, the Nyquist
//! frequency). The tolerance it has, found over this grid and asserted where the swing turns fast
//! against its growth (3β/2 ≤ ω/4, the paper's arm at α = 2: 0.10 ω): the true lower edge within
//! −2 … +16 % of the law's, the true upper edge between 0.94 π and π (or the window goes on past π
//! where it merges with the next) — while in δ the same windows move by a factor of more than 50.
//! Beyond that domain the law's edge stays a lower bound (up to 38 % low on this grid).

use flexarm::analysis::lag::LagLaw;
use flexarm::analysis::{analyze, stable_windows, LinearSettings};
use flexarm::*;

/// The paper's arm with K1 and I_r1 scaled, α1 = α2 = `alpha`, no preliminary feedback.
fn config(k1: f64, ir1: f64, alpha: f64) -> SimulationConfig {
    common::lag::config(k1, ir1, 1.0, alpha)
}

#[test]
fn the_controller_alone_works_where_the_lagged_feed_brakes_the_swing_below_half_a_turn_per_period() {
    let pi = core::f64::consts::PI;
    let mut rows = Vec::new();
    let (mut low_ratio, mut high_turn) = ([f64::INFINITY, 0.0f64], f64::INFINITY);
    let mut first_windows = Vec::new();
    for k1 in [0.25, 0.5, 1.0, 2.0, 4.0] {
        for ir1 in [0.25, 1.0, 4.0] {
            for alpha in [0.5, 1.0, 2.0, 3.0] {
                let case = format!("K1×{k1} Ir1×{ir1} α={alpha}");
                let c = config(k1, ir1, alpha);
                let law = LagLaw::of(&analyze(&c, None).unwrap());
                let windows = stable_windows(&LinearSettings::of(&c, None), [5e-4, 1.0]).unwrap();
                let Some([lo, hi]) = law.window() else {
                    // The motor damps the swing at every small δ: stable from the smallest δ on.
                    assert!(windows.windows.first().is_some_and(|w| w[0] <= windows.range[0]), "{case}");
                    continue;
                };
                // The true window the law describes: the first one reaching past its lower edge.
                let w = windows
                    .windows
                    .iter()
                    .find(|w| w[1] > lo)
                    .unwrap_or_else(|| panic!("{case}: no window above {lo} s"));
                let (ratio, upper) = (w[0] / lo, law.turn(w[1]));
                let merged = w[1] > 1.1 * hi;
                rows.push(format!(
                    "{case}: ω = {:.1} rad/s, 3β/2 = {:.2} 1/s ({:.3} ω); law ωδ from {:.3}, true {:.3} to {}; δ from {:.4} to {:.4} s",
                    law.omega,
                    law.feed,
                    law.feed / law.omega,
                    law.turn(lo),
                    law.turn(w[0]),
                    if merged { "past π (merged)".to_string() } else { format!("{upper:.3}") },
                    w[0],
                    w[1]
                ));
                // Always a lower bound: below the law's edge the lagged feed still pushes.
                assert!(ratio >= 0.98, "{case}: lower edge {} below the law's {lo}", w[0]);
                // Its domain: the swing turns fast against its growth, 3β/2 ≤ ω/4.
                if law.feed > 0.25 * law.omega {
                    continue;
                }
                assert!(ratio <= 1.16, "{case}: lower edge {} against the law's {lo} (×{ratio:.3})", w[0]);
                assert!(merged || (0.94 * pi..=1.001 * pi).contains(&upper), "{case}: ends at ωδ = {upper:.3}");
                low_ratio = [low_ratio[0].min(ratio), low_ratio[1].max(ratio)];
                if !merged {
                    high_turn = high_turn.min(upper);
                }
                first_windows.push(w[0]);
            }
        }
    }
    println!("{}", rows.join("\n"));
    println!(
        "where 3β/2 ≤ ω/4: lower edge / the law's {:.3}–{:.3}; upper edge ≥ {high_turn:.3} rad ({:.3} π)",
        low_ratio[0],
        low_ratio[1],
        high_turn / pi
    );
    // The law is worth stating: in δ the same windows spread far wider than in ωδ.
    let spread =
        first_windows.iter().cloned().fold(0.0, f64::max) / first_windows.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!(
        first_windows.len() >= 40 && spread > 50.0,
        "{} cases, lower edges in δ spread ×{spread:.1}",
        first_windows.len()
    );
}

/// The law's growth σ ≈ (3β/2) cos(1.5 ωδ) − B_v1/(2 I_r1) has the sign of ln ρ/δ for the paper's
/// arm at α = 2 wherever both are clear of zero below the Nyquist frequency (|σ| > 0.5 1/s).
#[test]
fn the_lag_laws_growth_has_the_sign_of_the_loops() {
    let c = config(1.0, 1.0, 2.0);
    let law = LagLaw::of(&analyze(&c, None).unwrap());
    let mut checked = 0;
    for i in 0..60 {
        let delta = 0.003 * (0.1 / 0.003f64).powf(i as f64 / 59.0);
        if law.turn(delta) >= 0.95 * core::f64::consts::PI {
            continue;
        }
        let mut c = c;
        c.controller.sampling_period = delta;
        let rate = analyze(&c, None).unwrap().growth_rate;
        let sigma = law.growth(delta);
        if sigma.abs() > 0.5 && rate.abs() > 0.05 {
            assert_eq!(sigma > 0.0, rate > 0.0, "δ = {delta}: law {sigma}, loop {rate}");
            checked += 1;
        }
    }
    assert!(checked > 30, "{checked}");
}

/// The page states the law with the tolerances asserted above.
#[test]
fn the_page_states_the_law_with_the_tested_tolerances() {
    let page = include_str!("../www/index.html").split_whitespace().collect::<Vec<_>>().join(" ");
    for said in [
        "within −2 … +16 % of the law's",
        "between 0.94 π and π",
        "3β/2 ≤ ω/4",
        "by a factor of more than 50",
        "on some arms (the lighter motor), the window runs on past π",
    ] {
        assert!(page.contains(said), "the page should say {said:?}");
    }
    // The lighter motor (I_r1 ÷ 4) at α = 2: its first window runs on past ωδ = π.
    let c = config(1.0, 0.25, 2.0);
    let law = LagLaw::of(&analyze(&c, None).unwrap());
    let [lo, hi] = law.window().unwrap();
    let windows = stable_windows(&LinearSettings::of(&c, None), [5e-4, 1.0]).unwrap();
    let first = windows.windows.iter().find(|w| w[1] > lo).unwrap();
    assert!(first[1] > 1.1 * hi, "the lighter motor's window {first:?} ends near π/ω = {hi}");
}

/// The lesson's step "Why some larger δ work" quotes the law's numbers for the paper's arm at
/// δ = 0.05 s and α = 2, and the loop's own first window.
#[test]
fn the_lesson_quotes_the_laws_numbers() {
    let lesson = include_str!("../www/lessons/paper.md");
    let mut c = config(1.0, 1.0, 2.0);
    c.controller.sampling_period = 0.05;
    let report = analyze(&c, None).unwrap();
    let law = LagLaw::of(&report);
    let [lo, hi] = law.window().unwrap();
    let windows = stable_windows(&LinearSettings::of(&c, None), [0.002, 0.25]).unwrap();
    let first = windows.windows[0];
    for said in [
        format!("ω = |Im A4| = {:.2} rad/s", law.omega),
        format!("ωδ = {:.2} rad in one period", law.turn(0.05)),
        format!("φ = 1.5 ωδ = {:.2} rad ({:.0}°)", law.lag(0.05), law.lag(0.05).to_degrees()),
        format!("Lagged by {:.0}°", law.lag(0.05).to_degrees()),
        format!("for ωδ from {:.2} to π, that is δ from {:.3} to {:.3} s", law.turn(lo), lo, hi),
        format!("the loop's own window is {:.3} s to {:.3} s", first[0], first[1]),
    ] {
        assert!(lesson.contains(&said), "the lesson should say {said:?}");
    }
    // The next step's softer spring (K1 ÷ 4) at the same δ: too little lag.
    let mut soft = config(0.25, 1.0, 2.0);
    soft.controller.sampling_period = 0.05;
    let soft_report = analyze(&soft, None).unwrap();
    let soft_law = LagLaw::of(&soft_report);
    let [soft_lo, _] = soft_law.window().unwrap();
    let said = format!(
        "at {:.2} rad/s the softer arm's swing turns only ωδ = {:.2} rad per period at δ = 0.05 s, short of the {:.2}",
        soft_law.omega,
        soft_law.turn(0.05),
        soft_law.turn(soft_lo)
    );
    assert!(lesson.contains(&said), "the lesson should say {said:?}");
    assert!(soft_law.turn(0.05) < soft_law.turn(soft_lo) && soft_report.spectral_radius > 1.0);
    // At that δ the law and the loop agree: the swing is braked.
    assert!(law.growth(0.05) < 0.0 && report.spectral_radius < 1.0);
}

/// The README quotes the law on the paper's arm at α = 2 with the numbers of this module.
#[test]
fn the_readme_quotes_the_law() {
    let readme = include_str!("../README.md").split_whitespace().collect::<Vec<_>>().join(" ");
    let c = config(1.0, 1.0, 2.0);
    let law = LagLaw::of(&analyze(&c, None).unwrap());
    let [lo, hi] = law.window().unwrap();
    let first = stable_windows(&LinearSettings::of(&c, None), [0.002, 0.25]).unwrap().windows[0];
    let said = format!(
        "{:.2} to π on the paper's arm at α = 2, δ from {lo:.3} to {hi:.3} s against the true {:.3}–{:.3} s",
        law.turn(lo),
        first[0],
        first[1]
    );
    assert!(readme.contains(&said), "README should say {said:?}");
    assert!(readme.contains("within −2 … +16 % of the law's and the upper between 0.94 π and π wherever 3β/2 ≤ ω/4"));
}

mod common;

/// The ρ(δ) panel's second axis: ωδ along the top, π where δ = π/|Im A4| (half a swing per
/// period), labelled at a laptop's size with its title.
#[test]
fn the_rho_curve_has_an_axis_in_turns_per_period() {
    use flexarm::view::{Scene, ViewOptions};
    let s = common::session("preset=fig5.3&mode=full&tab=poles");
    let report = s.run(0).unwrap().analysis().report().unwrap().clone();
    let omega = LagLaw::of(&report).omega;
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let rho = panels.iter().find(|p| p.id == "rho-curve").expect("the ρ(δ) panel");
    let pi = rho.x2_labels.iter().find(|t| t.text == "π").expect("a tick at π");
    assert!((pi.value - core::f64::consts::PI / omega).abs() < 1e-12, "{} vs π/ω", pi.value);
    assert!(rho.x2_label.starts_with("ωδ [rad/period]") && rho.x2_label.contains("2π = one swing"));
    let labels = scene.labels();
    let shown = |text: &str| labels.iter().any(|l| l.panel == "rho-curve" && l.text == text);
    assert!(shown("π") && shown("π/2"), "{:?}", labels.iter().filter(|l| l.panel == "rho-curve").collect::<Vec<_>>());
    // Short of room the title is the symbol alone, with the whole title as the label's `full`.
    let title = labels.iter().find(|l| l.panel == "rho-curve" && l.text.starts_with("ωδ")).expect("the axis title");
    assert!(title.text == "ωδ" && title.full == rho.x2_label, "{title:?}");
    // On a large screen the title says its unit.
    let mut scene = Scene::new(ViewOptions::default(), 1920.0, 1080.0, 1.0);
    scene.draw_session(&s);
    let labels = scene.labels();
    assert!(labels.iter().any(|l| l.panel == "rho-curve" && l.text.starts_with("ωδ [rad/period]")));
    assert!(labels.iter().any(|l| l.panel == "rho-curve" && l.text == "2π"));
}
