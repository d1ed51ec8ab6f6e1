//! The README's table "What it reproduces" says what flexarm computes; each figure there is
//! formatted here from the code and must appear in its row, so the README cannot drift from the
//! program (a changed model fails this test, and the message gives the number to write).

use flexarm::analysis::analyze;
use flexarm::session::Session;
use flexarm::*;

const README: &str = include_str!("../README.md");

/// The table row whose first cell starts with `paper`.
fn row(paper: &str) -> &'static str {
    README
        .lines()
        .find(|l| l.starts_with(&format!("| {paper}")))
        .unwrap_or_else(|| panic!("README has no row for {paper:?}"))
}

fn assert_says(paper: &str, figure: &str) {
    let r = row(paper);
    assert!(r.contains(figure), "README row {paper:?} should say {figure:?}:\n{r}");
}

fn config(delta: f64, alpha: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
    c.controller.sampling_period = delta;
    c.controller.alpha = [alpha, alpha];
    c
}

/// "−2.478" with the typographic minus the README uses.
fn fixed(v: f64, digits: usize) -> String {
    format!("{v:.digits$}").replace('-', "−")
}

fn pair(p: [[f64; 2]; 2], digits: usize) -> String {
    format!("{} ± {}j", fixed(p[0][0], digits), fixed(p[0][1].abs(), digits))
}

#[test]
fn the_flexible_pair_and_its_feedback_are_as_printed() {
    let off = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Off), None).unwrap();
    assert_says("A4 ≈", &pair(off.limit_pair_open, 4));
    let paper = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Paper), None).unwrap();
    assert_says("K_pr moves A4", &format!("printed (rounded) K_pr: {}", pair(paper.limit_pair, 3)));
    let lq = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Lq), None).unwrap();
    assert_says("K_pr moves A4", &format!("our LQ gain: {}", pair(lq.limit_pair, 3)));
}

#[test]
fn fig_5_3_grows_as_rho_says_and_diverges_when_printed() {
    let c = config(0.01, 2.0, PreliminaryFeedbackChoice::Off);
    let r = analyze(&c, None).unwrap();
    assert!(r.spectral_radius > 1.0);
    assert_says("without K_pr unstable", &format!("ρ = {:.4} > 1", r.spectral_radius));
    assert_says("without K_pr unstable", &format!("e^{{{:.2} t}} (ln ρ/δ)", r.growth_rate));
    let sim = simulate(&c, 6.0).unwrap();
    let fitted = sim.metrics.growth_rate.expect("a growth rate before divergence");
    assert_says("without K_pr unstable", &format!("the simulation fits {fitted:.2} 1/s"));
    let Verdict::Diverged { at, .. } = sim.metrics.verdict else { panic!("{:?}", sim.metrics.verdict) };
    assert_says("without K_pr unstable", &format!("t = {at:.2} s"));
}

#[test]
fn the_stable_windows_are_the_ones_the_page_and_analyze_print() {
    // The same words the page's status and `flexarm analyze` use.
    for (query, paper) in [
        ("delta=0.01&alpha=2&pf=off", "without K_pr stable for larger"),
        ("delta=0.01&alpha=2&pf=paper", "with K_pr stable"),
    ] {
        let (mut s, _) = Session::open(query);
        let words = flexarm::words::settings::windows(s.windows().unwrap());
        assert_says(paper, &format!("at α = 2: {words}"));
    }
}

#[test]
fn the_figures_errors_and_their_ratio_are_as_printed() {
    let max_slew = |delta: f64| {
        let sim = simulate(&config(delta, 2.0, PreliminaryFeedbackChoice::Paper), 3.0).unwrap();
        assert_eq!(sim.metrics.verdict, Verdict::Stable);
        sim.metrics.max_error_slew
    };
    let (fig51, fig52) = (max_slew(0.04), max_slew(0.01));
    let says = |e: [f64; 2]| format!("max \\|e1\\| = {:.2e} rad, \\|e2\\| = {:.2e} rad", e[0], e[1]);
    assert_says("Fig. 5.1", &says(fig51));
    assert_says("Fig. 5.2", &says(fig52));
    let ratio = |i: usize| (fig51[i] / fig52[i]).round();
    assert_says("Fig. 5.2", &format!("({}× and {}× smaller)", ratio(0), ratio(1)));
}

#[test]
fn smaller_alpha_slows_the_growth_as_printed() {
    let growth = |alpha: f64| analyze(&config(0.01, alpha, PreliminaryFeedbackChoice::Off), None).unwrap().growth_rate;
    let (g2, g1, g05) = (growth(2.0), growth(1.0), growth(0.5));
    assert!(g2 > g1 && g1 > g05 && g05 > 0.0);
    assert_says("smaller α", &format!("{g2:.2} (α = 2), {g1:.2} (α = 1), {g05:.2} (α = 0.5)"));
}

#[test]
fn the_verdicts_quoted_in_the_readme_are_the_pages() {
    let web = README.split("## The web demo").nth(1).expect("a web demo section");
    for (preset, headline) in [("fig5.3", "Unstable"), ("fig5.2", "Stable")] {
        let (s, _) = Session::open(&format!("preset={preset}"));
        let status = &s.status().runs[0];
        assert_eq!(status.headline, headline);
        let quoted = format!("**{}**, \"{}\"", status.headline, status.detail);
        let flat = |t: &str| t.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(flat(web).contains(&flat(&quoted)), "README's web demo section should quote {quoted:?}");
    }
}

#[test]
fn held_friction_hunts_as_printed() {
    let mut c = config(0.04, 2.0, PreliminaryFeedbackChoice::Paper);
    let rho = analyze(&c, None).unwrap().spectral_radius;
    let row = "(not in the paper) Fig. 5.1 with the friction compensation held";
    assert_says(row, &format!("ρ = {rho:.4} < 1"));
    c.friction_compensation = FrictionCompensation::Held;
    let m = simulate(&c, 60.0).unwrap().metrics;
    let Verdict::BoundedOscillation { amplitude, period, .. } = m.verdict else { panic!("{:?}", m.verdict) };
    assert_says(row, &format!("amplitude {:.2e}, {:.2e} rad, period {period:.2} s", amplitude[0], amplitude[1]));
}

#[test]
fn the_closed_form_and_the_arm_alone_are_as_printed() {
    use flexarm::analysis::resonance::arm_pair;
    let own = arm_pair(&PlantParameters::default(), 0.0)[0];
    assert_says("A4 ≈", &format!("the arm alone: {}", pair([[own.re, own.im], [own.re, -own.im]], 4)));
    let off = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Off), None).unwrap();
    let [re, im] = off.poles[off.flexible_pair()[0].unwrap()].continuous.unwrap();
    assert_says("without K_pr unstable", &format!("flexible pair at {re:.2} ± {im:.2}j"));
}

#[test]
fn small_alpha_and_the_papers_gains_at_large_alpha_are_as_printed() {
    use flexarm::analysis::resonance::{alpha_limit, alpha_star, feedback_shift};
    use flexarm::control::feedback::paper_gain;
    let p = PlantParameters::default();
    assert_says("\"a change of α", &format!("α* = Bv1/(3 Ir1) = {:.4} 1/s", alpha_star(&p)));
    let (s, _) = Session::open("delta=0.01&alpha=0.2&pf=off");
    let mut s = s;
    assert_says("\"a change of α", &format!("at α = 0.2: {}", flexarm::words::settings::windows(s.windows().unwrap())));
    let shift = feedback_shift(&p, [2.0, 2.0], 0.0, &paper_gain());
    let row = "(not in the paper) the paper's K_pr at larger α";
    assert_says(row, &fixed(shift, 3));
    assert_says(row, &format!("only for α < {:.3} 1/s", alpha_limit(&p, shift)));
    let (mut s, _) = Session::open("delta=0.01&alpha=5&pf=paper");
    assert_says(row, &format!("at α = 5: {}", flexarm::words::settings::windows(s.windows().unwrap())));
    let (mut s, _) = Session::open("delta=0.01&alpha=2&pf=paper&inner=sampled");
    assert_says(
        "with K_pr stable",
        &format!("sampled at δ: {}", flexarm::words::settings::windows(s.windows().unwrap())),
    );
}

/// Issue 34 item 6: where the paper's fixed gains stop working when the controller knows the arm.
#[test]
fn the_papers_gains_on_the_heavier_motor_are_as_printed() {
    use flexarm::analysis::resonance::{closed_form_a4, feedback_shift, AlphaBound};
    use flexarm::control::feedback::paper_gain;
    let p = PlantParameters { ir1: 4.0 * PlantParameters::default().ir1, ..PlantParameters::default() };
    let heading = "(not in the paper) the paper's K_pr on the heavier motor";
    let text = row(heading);
    let row = heading;
    assert_says(row, &fixed(feedback_shift(&p, [2.0, 2.0], 0.0, &paper_gain()), 3));
    assert_says(row, &format!("only for α < {:.3} 1/s", AlphaBound::new(&p, 0.0, &paper_gain()).stable_below()));
    let pair = closed_form_a4(&p, [2.0, 2.0], 0.0, &paper_gain()).complex_eigenvalues();
    let upper = if pair[0].im > 0.0 { pair[0] } else { pair[1] };
    assert_says(row, &format!("A4 with K_pr is {:.2} ± {:.2}j", upper.re, upper.im));
    for (pf, state) in [("paper", "A4 with K_pr"), ("lq", "the LQ design")] {
        let (s, _) = Session::open(&format!("delta=0.01&arm=heavier&pf={pf}"));
        let rho = s.run(0).unwrap().analysis().report().unwrap().spectral_radius;
        let said = format!("ρ(0.01 s) = {rho:.4}");
        assert_says(row, &said);
        assert!(text.find(state).unwrap() < text.find(&said).unwrap(), "{state} before {said}");
        assert_eq!(rho > 1.0, pf == "paper");
    }
}

#[test]
fn the_real_robot_row_is_the_codes() {
    use flexarm::analysis::{noise_floor, LinearSettings, LoopModel};
    use flexarm::control::sensing::{SensorModel, VelocitySource};
    let r = row("\"small δ yields small tracking error");
    let sensors = SensorModel { encoder_counts: 1024.0, velocity: VelocitySource::Difference, ..Default::default() };
    let floors: Vec<_> = [0.002, 0.01, 0.04]
        .iter()
        .map(|&d| {
            let mut c = config(d, 2.0, PreliminaryFeedbackChoice::Paper);
            c.sensors = sensors;
            noise_floor(&LoopModel::new(&LinearSettings::of(&c, None)).unwrap(), d, &sensors).unwrap()
        })
        .collect();
    let rho: Vec<String> = floors.iter().map(|f| format!("{:.4}", f.spectral_radius)).collect();
    assert!(
        r.contains(&format!("{} at δ = 0.002 s, {} at 0.01 s, {} at 0.04 s", rho[0], rho[1], rho[2])),
        "{rho:?}\n{r}"
    );
    let sci = |v: f64| format!("{v:.2e}");
    let e: Vec<String> = floors.iter().map(|f| sci(f.rms_error[0])).collect();
    assert!(r.contains(&format!("RMS e1 {}, {}, {} rad", e[0], e[1], e[2])), "{e:?}");
    let t: Vec<String> = floors.iter().map(|f| flexarm::plot::format::significant(f.rms_torque[0], 3)).collect();
    assert!(r.contains(&format!("RMS T1 {}, {}, {} N m", t[0], t[1], t[2])), "{t:?}");
    // The simulated figures are the study's (tests/sensor_study.rs checks the same in the lesson).
    let mut s = flexarm::session::Settings::default();
    s.read("preset=real-encoder", flexarm::session::Source::CommandLine).unwrap();
    let v = Session::new(s).unwrap().sensor_study_step(1000).unwrap();
    let cell = |d: &str, i: usize| v.table.iter().find(|row| row[0] == d).unwrap()[i].clone();
    assert!(r.contains(&format!(
        "best at δ = 0.005 s (max \\|e\\| {} rad; {} rad at 0.002 s",
        cell("0.005", 2),
        cell("0.002", 2)
    )));
    assert!(r.contains(&format!("limit {} of the time", cell("0.002", 7))));
}
