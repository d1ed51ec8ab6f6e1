//! The physical story the page and the lesson tell (issue 22): every number they quote as text is
//! the program's, and the live numbers of the explanation come from the same analysis as the
//! verdict and the pole plot.

mod common;

use flexarm::analysis::resonance::*;
use flexarm::analysis::*;
use flexarm::control::feedback::*;
use flexarm::lesson::LESSON_TEXT;
use flexarm::*;
use std::f64::consts::PI;

const PAGE: &str = include_str!("../www/index.html");

/// The page's text with its markup's entities and line breaks as a reader sees them.
fn page_text() -> String {
    let flat = PAGE.split_whitespace().collect::<Vec<_>>().join(" ");
    flat.replace("&lt;", "<").replace("&#8239;", "\u{202f}").replace("&nbsp;", " ")
}

fn says(what: &str, text: &str, name: &str) {
    assert!(text.contains(what), "the {name} should say {what:?}");
}

fn config(delta: f64, alpha: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
    c.controller.sampling_period = delta;
    c.controller.alpha = [alpha, alpha];
    c
}

fn minus(s: String) -> String {
    s.replace('-', "−")
}

fn windows(c: &SimulationConfig) -> Vec<[f64; 2]> {
    stable_windows(&LinearSettings::of(c, None), [0.002, 0.25]).unwrap().windows
}

#[test]
fn the_mode_shape_quoted_is_the_unstable_eigenvector() {
    let c = config(0.01, 2.0, PreliminaryFeedbackChoice::Off);
    let [_, q2, theta] = LoopModel::new(&LinearSettings::of(&c, None)).unwrap().mode_shape(0.01).unwrap().unwrap();
    let page = page_text();
    for text in [LESSON_TEXT, page.as_str()] {
        says(&minus(format!("θ ≈ {:.1} q1", theta.re)), text, "story");
        says(&minus(format!("q2 ≈ {:.1} q1", q2.re)), text, "story");
    }
}

#[test]
fn the_lessons_resonance_numbers_are_the_programs() {
    let plant = PlantParameters::default();
    let own = arm_pair(&plant, 0.0)[0];
    says(&minus(format!("({:.2} ± {:.2}j 1/s)", own.re, own.im)), LESSON_TEXT, "lesson");
    let r = JointResonance::new(&plant, [2.0, 2.0], 0.0);
    says(&format!("feeding the resonance {} 1/s", r.controller_feed), LESSON_TEXT, "lesson");
    says(&format!("taking back {:.2} 1/s", r.motor_damping), LESSON_TEXT, "lesson");
    let off = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Off), None).unwrap();
    let [re, im] = off.poles[off.flexible_pair()[0].unwrap()].continuous.unwrap();
    says(&format!("the loop's pair is at {re:.2} ± {im:.2}j 1/s"), LESSON_TEXT, "lesson");
    // One name per frequency: the loop's pole at this δ, its limit A4, the arm alone.
    let tau = core::f64::consts::TAU;
    says(&format!("the loop's pole at this δ swings at {im:.2} rad/s ({:.2} Hz)", im / tau), LESSON_TEXT, "lesson");
    let a4 = off.limit_pair_open[0][1];
    says(&format!("it tends to A4, the ring, at {a4:.2} rad/s ({:.2} Hz)", a4 / tau), LESSON_TEXT, "lesson");
    says(&format!("would ring at {:.2} rad/s", own.im), LESSON_TEXT, "lesson");
    says(&format!("α* = B_v1/(3 I_r1) ≈ {:.2} 1/s", alpha_star(&plant)), LESSON_TEXT, "lesson");
    says(&format!("rings near this frequency ({:.1} rad/s)", r.omega_joint), LESSON_TEXT, "lesson");
    let slow = analyze(&config(0.01, 0.5, PreliminaryFeedbackChoice::Off), None).unwrap();
    says(&format!("(ln ρ/δ = {:.2} 1/s, below its limit Re A4)", slow.growth_rate), LESSON_TEXT, "lesson");
    assert!(slow.growth_rate < slow.limit_pair_open[0][0]);
    assert_eq!(windows(&config(0.01, 0.2, PreliminaryFeedbackChoice::Off)), vec![[0.002, 0.25]]);
    says("at α = 0.2 1/s every δ of the slider is stable", LESSON_TEXT, "lesson");
}

/// K_pr's motor torque as the lesson and the page read it, its shift and where it stops working,
/// and the sampled inner loop's windows.
#[test]
fn what_is_said_of_the_preliminary_feedback_is_the_programs() {
    let plant = PlantParameters::default();
    let k = paper_gain();
    let page = page_text();
    let twist = format!("nearly {:.0} (q1 − θ) + {:.0} (q̇1 − θ̇)", k[(0, 0)], k[(0, 3)]);
    let motor = minus(format!("{:.0} N m s/rad", k[(0, 5)]));
    let times = (k[(0, 5)].abs() / plant.bv1).round();
    assert_eq!(times, 12.0, "the page says twelve times");
    for text in [LESSON_TEXT, page.as_str()] {
        says(&twist, text, "story");
        says(&motor, text, "story");
        says("twelve times", text, "story");
        says(&format!("= {} N m s/rad", plant.bv1), &text.replace("<sub>v1</sub>", "_v1"), "story");
    }
    let shift = feedback_shift(&plant, [2.0, 2.0], 0.0, &k);
    says(&minus(format!("{shift:.2} 1/s")), LESSON_TEXT, "lesson");
    // Its two parts: T1's and T2's gains on θ̇.
    let t1 = FeedbackGain::from_fn(|r, c| if r == 0 { k[(r, c)] } else { 0.0 });
    let t2 = FeedbackGain::from_fn(|r, c| if r == 1 { k[(r, c)] } else { 0.0 });
    let (p1, p2) = (feedback_shift(&plant, [2.0, 2.0], 0.0, &t1), feedback_shift(&plant, [2.0, 2.0], 0.0, &t2));
    assert!((p1 + p2 - shift).abs() < 1e-12);
    // Live on the page: the story's parts are these at the paper's settings.
    let st = common::session("preset=fig5.3").status().story.unwrap();
    assert_eq!((st.kpr_shift_t1, st.kpr_shift_t2), (minus(format!("{p1:.2} 1/s")), minus(format!("{p2:.2} 1/s"))));
    says(
        "through T1, twelve times the paper's motor damping B_v1 = 1.4 N m s/rad, gives",
        &page.replace("<sub>v1</sub>", "_v1"),
        "page",
    );
    says(
        &format!("{:.2} N m s/rad through T2 and the links' coupling gives", k[(1, 5)]).replace('-', "−"),
        &page,
        "page",
    );
    let at_pi = feedback_shift(&plant, [2.0, 2.0], PI, &k);
    // Live now, for the arm shown (issue 37): the story's on the paper's arm.
    let live = common::session("preset=fig5.3&pf=paper").status().story.unwrap().kpr_shift_rest;
    assert_eq!(live, minus(format!("on this arm {shift:.2} 1/s at q2 = 0, {at_pi:.2} 1/s at q2 = π")));
    says(&format!("above α = {:.2} 1/s", alpha_limit(&plant, shift)), LESSON_TEXT, "lesson");
    // At α = 5 only a window is left.
    let w = windows(&config(0.01, 5.0, PreliminaryFeedbackChoice::Paper));
    assert_eq!(w.len(), 1);
    says(&format!("at q2 = 0 and α = 5 1/s only δ from {:.3} to {:.3} s is stable", w[0][0], w[0][1]), &page, "page");
    // Sampled at δ: two windows, the first from the smallest δ.
    let mut c = config(0.01, 2.0, PreliminaryFeedbackChoice::Paper);
    c.inner_loop = InnerLoop::Sampled;
    let w = windows(&c);
    assert_eq!(w.len(), 2, "{w:?}");
    assert_eq!(w[0][0], 0.002);
    let sampled = format!("δ < {:.3} s (and {:.3}–{:.3} s)", w[0][1], w[1][0], w[1][1]);
    says(&sampled, LESSON_TEXT, "lesson");
    says(&sampled, &page, "page");
}

/// ρ is an asymptotic rate: in Fig. 5.2's loop (ρ < 1) the link errors from a link turned off at
/// rest first grow, in the same unit, before they die out — "the modes' sum can … even grow for a
/// while".
#[test]
fn the_transient_growth_said_is_the_loops() {
    let c = config(0.01, 2.0, PreliminaryFeedbackChoice::Paper);
    let model = LoopModel::new(&LinearSettings::of(&c, None)).unwrap();
    let phi = model.loop_matrix(0.01).unwrap();
    assert!(model.spectral_radius(0.01).unwrap() < 1.0);
    let mut x = nalgebra::SVector::<f64, 10>::zeros();
    x[0] = 1e-3; // q1, rad
    let mut peak: f64 = 0.0;
    for _ in 1..400 {
        x = phi * x;
        peak = peak.max(x[0].abs().max(x[1].abs()));
    }
    assert!(peak > 1e-3 && x[0].abs().max(x[1].abs()) < 1e-4, "peak {peak}");
    says("until then the modes' sum can move otherwise, even grow for a while", &page_text(), "page");
}

/// Outside the windows (no K_pr, α = 2) the growing mode below 0.224 s oscillates — the resonance,
/// aliased above about 0.1 s — and above 0.224 s it is a slow real mode, with the flexible pair
/// itself stable there.
#[test]
fn what_grows_outside_the_windows_is_as_said() {
    let c = config(0.01, 2.0, PreliminaryFeedbackChoice::Off);
    let model = LoopModel::new(&LinearSettings::of(&c, None)).unwrap();
    let w = windows(&c);
    let edge = w.last().unwrap()[1];
    assert!((edge - 0.2236).abs() < 2e-4, "{w:?}");
    for i in 0..120 {
        let d = 0.002 * (0.25f64 / 0.002).powf(i as f64 / 119.0);
        if w.iter().any(|[a, b]| d >= *a && d <= *b) {
            continue;
        }
        let top = loop_eigenvalues(&model.loop_matrix(d).unwrap())[0];
        assert!(top.norm() > 1.0);
        let oscillates = top.im.abs() > 1e-9 * top.norm() || top.re < 0.0;
        assert_eq!(oscillates, d < edge, "δ = {d}: top eigenvalue {top}");
        // Sampled slower than the resonance swings (π/δ below ≈ 29.4 rad/s), it shows up aliased.
        if d > 1.02 * PI / 29.4 && d < edge {
            let s = top.ln() / d;
            assert!(s.im.abs() <= PI / d + 1e-9 && (s.im.abs() - 29.4).abs() > 1.0, "aliased at δ = {d}: {s}");
        }
        if d > edge {
            let r = LoopModel::new(&LinearSettings::of(&config(d, 2.0, PreliminaryFeedbackChoice::Off), None))
                .unwrap()
                .report()
                .unwrap();
            let flexible = r.poles[r.flexible_pair()[0].unwrap()].discrete;
            assert!(flexible[0].hypot(flexible[1]) < 1.0, "δ = {d}: the flexible pair is stable");
        }
    }
    let page = page_text();
    says("below 0.224 s it is the resonance that grows", &page, "page");
    says("above 0.224 s a slow mode that does not oscillate drifts away", &page, "page");
    says("above 0.224 s a slow mode that does not oscillate drifts away", LESSON_TEXT, "lesson");
}

/// With α1 ≠ α2 the controller can drain the resonance: for α2 > α1 (1 + μ)/μ its part 3β/2 of
/// Re A4 is negative, and α1 = 1, α2 = 5 (within the sliders) is stable at δ = 0.01 s without K_pr.
#[test]
fn a_fast_law_for_link_two_drains_the_resonance() {
    let plant = PlantParameters::default();
    let r = JointResonance::new(&plant, [1.0, 5.0], 0.0);
    assert!(5.0 > (1.0 + r.mu) / r.mu && r.beta < 0.0 && r.real_part() < 0.0, "{r:?}");
    let mut c = config(0.01, 1.0, PreliminaryFeedbackChoice::Off);
    c.controller.alpha = [1.0, 5.0];
    assert!(analyze(&c, None).unwrap().spectral_radius < 1.0);
    let s = common::session("delta=0.01&alpha1=1&alpha2=5&pf=off");
    let story = s.status().story.unwrap();
    assert_eq!(story.feed_says, "the controller drains the resonance");
    assert_eq!(story.alpha2_drain, format!("{:.2} α1", (1.0 + r.mu) / r.mu));
    assert_eq!(story.six_poles, "−1 1/s and −5 1/s, three of each");
    // The paper's K_pr's shift with α1 ≠ α2 is the closed form's, its parts add up, and the pair
    // they make is the numerical limit's.
    let mut with = c;
    with.preliminary_feedback = PreliminaryFeedbackChoice::Paper;
    let [pre, pim] = analyze(&with, None).unwrap().limit_pair[0];
    assert_eq!(story.kpr_pair, minus(format!("{pre:.2} ± {:.2}j 1/s", pim.abs())));
    let open = analyze(&c, None).unwrap().limit_pair_open[0][0];
    let value = |t: &str| t.trim_end_matches(" 1/s").replace('−', "-").parse::<f64>().unwrap();
    assert!((value(&story.kpr_shift) - (pre - open)).abs() < 0.006, "{} vs {}", story.kpr_shift, pre - open);
    assert!((value(&story.kpr_shift_t1) + value(&story.kpr_shift_t2) - value(&story.kpr_shift)).abs() < 0.011);
    assert!(story.lq_says.starts_with("leaves a stable pair"), "{}", story.lq_says);
}

#[test]
fn what_rho_certifies_is_said_with_the_programs_numbers() {
    let plant = PlantParameters::default();
    let page = page_text();
    let spring = flexarm::plot::format::grouped(flexarm::schema::round_significant(plant.fc1 / plant.eps1, 3));
    says(
        &format!("= {spring} N m/rad at rest, about forty times its K1"),
        &page.replace("<sub>c1</sub>/ε<sub>1</sub>", "_c1/ε1"),
        "page",
    );
    assert_eq!((plant.fc1 / plant.eps1 / plant.k1 / 10.0).round(), 4.0);
    // The windows move with the rest point by up to 0.004 s between q2 = 0 and q2 = π.
    let at = |q2: f64| {
        let c = config(0.01, 2.0, PreliminaryFeedbackChoice::Off);
        stable_windows(&LinearSettings::of(&c, Some(q2)), [0.002, 0.25]).unwrap().windows
    };
    let base = at(0.0);
    let mut largest: f64 = 0.0;
    for i in 1..=12 {
        let w = at(PI * i as f64 / 12.0);
        assert_eq!(w.len(), base.len());
        for (a, b) in w.iter().zip(&base) {
            largest = largest.max((a[0] - b[0]).abs()).max((a[1] - b[1]).abs());
        }
    }
    assert!(largest > 0.003 && largest < 0.0045, "{largest}");
    says("by up to 0.004 s as q2 goes from 0 to π (on the paper's arm)", &page, "page");
}

/// The explanation's live numbers are the report's: the same A4, the same loop pole, and the
/// paper's K_pr and the LQ design as the numerical limit gives them.
#[test]
fn the_live_numbers_are_the_analysis_numbers() {
    let s = common::session("preset=fig5.3");
    let story = s.status().story.unwrap();
    let report = s.run(0).unwrap().analysis().report().unwrap().clone();
    let pair = |re: f64, im: f64| minus(format!("{re:.2} ± {:.2}j 1/s", im.abs()));
    let [re, im] = report.limit_pair_open[0];
    assert_eq!(story.a4, pair(re, im));
    let [lre, lim] = report.poles[report.flexible_pair()[0].unwrap()].continuous.unwrap();
    assert_eq!(story.loop_pair, format!("s = {}", pair(lre, lim)));
    assert_eq!(story.rho, format!("{:.4}", report.spectral_radius));
    assert_eq!(story.rest, "q2 = 0 rad");
    let paper = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Paper), None).unwrap();
    let [pre, pim] = paper.limit_pair[0];
    assert_eq!(story.kpr_pair, pair(pre, pim));
    let lq = analyze(&config(0.01, 2.0, PreliminaryFeedbackChoice::Lq), None).unwrap();
    let [qre, qim] = lq.limit_pair[0];
    assert!(story.lq_says.ends_with(&format!("(here {})", pair(qre, qim))), "{}", story.lq_says);
    assert!(story.lq_says.starts_with("reflects the unstable pair"));
    assert_eq!(story.loop_limit, "A4 — the ring in the pole plot");
    assert_eq!(story.rho_set_by, "the flexible pair");
    // With K_pr on, the loop's pair tends to A4 with K_pr, and ρ is set by another, slower mode.
    let s = common::session("preset=fig5.2");
    let story = s.status().story.unwrap();
    let report = s.run(0).unwrap().analysis().report().unwrap().clone();
    let [kre, kim] = report.limit_pair[0];
    assert_eq!(story.loop_limit, format!("A4 with K_pr, {} — the diamond in the pole plot", pair(kre, kim)));
    assert!(!report.flexible_pair().contains(&Some(0)));
    assert!(story.rho_set_by.starts_with("another mode, at s = −1.9"), "{}", story.rho_set_by);
    assert_eq!(
        (story.feed_says.as_str(), story.re_a4_says.as_str()),
        ("the controller feeds the resonance", "Re A4 > 0: in the limit the pair grows")
    );
    assert_eq!(story.six_poles, "−2 1/s, all six");
    // Below α* the sign of Re A4 turns, though the controller still feeds the resonance.
    let s = common::session("preset=fig5.3&alpha=0.2");
    let story = s.status().story.unwrap();
    assert!(story.re_a4.starts_with('−') && story.re_a4_says.starts_with("Re A4 < 0"), "{story:?}");
    assert_eq!(story.feed_says, "the controller feeds the resonance");
    // Every live element of the page names a field of the story.
    let fields = serde_json::to_value(&story).unwrap();
    for part in PAGE.split("data-live=\"").skip(1) {
        let key = &part[..part.find('"').unwrap()];
        assert!(fields.get(key).is_some(), "data-live=\"{key}\" is not a story field");
    }
}

/// The third cold trial's cases: at δ = 0.103 s (no K_pr) the resonance sits at the Nyquist
/// frequency as two real negative eigenvalues — the growing one among them — and is named so;
/// at α = 5 the paper's K_pr does not make every small δ work, and the text says so.
#[test]
fn the_resonance_at_the_nyquist_frequency_and_kpr_beyond_its_limit_are_named_right() {
    let s = common::session("delta=0.103&pf=off");
    let report = s.run(0).unwrap().analysis().report().unwrap().clone();
    let [a, b] = report.flexible_pair();
    let (a, b) = (report.poles[a.unwrap()].discrete, report.poles[b.unwrap()].discrete);
    assert!(a[0] < 0.0 && a[1].abs() < 1e-9 && b[0] < 0.0 && b[1].abs() < 1e-9, "{a:?} {b:?}");
    assert!(report.flexible_pair().contains(&Some(0)), "the growing eigenvalue is the resonance's");
    let story = s.status().story.unwrap();
    assert!(story.loop_pair.starts_with("the Nyquist frequency π/δ = 30.5 rad/s"), "{}", story.loop_pair);
    assert_eq!(story.rho_set_by, "the flexible pair");
    let s = common::session("alpha=5&pf=paper");
    let story = s.status().story.unwrap();
    assert!(story.kpr_works.starts_with("still the smallest δ fail here"), "{}", story.kpr_works);
    let s = common::session("alpha=2&pf=paper");
    assert!(s.status().story.unwrap().kpr_works.starts_with("every small δ works"));
}

/// The paper's K_pr as the page and the lesson quote it: the T1 row's four gains, as the code has
/// them (trial 4 found "≈ 16 (q̇1 − θ̇)" beside "−17 N m s/rad" without the exact row).
#[test]
fn the_quoted_kpr_row_is_the_papers() {
    let k = flexarm::control::feedback::paper_gain();
    let row = format!(
        "{} q1 − {} θ + {} q̇1 − {} θ̇",
        k[(0, 0)],
        format!("{:.1}", -k[(0, 2)]),
        k[(0, 3)],
        format!("{:.1}", -k[(0, 5)])
    );
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/www/index.html"))
        .unwrap()
        .replace("\n              ", " ");
    assert!(page.contains(&row), "the page should quote {row:?}");
    assert!(LESSON_TEXT.contains(&row), "the lesson should quote {row:?}");
}

/// With a model error (`model = paper` on a stiffer arm) the texts keep A4 for what the closed
/// form describes (a controller that knows the arm: eigenvalues from its trace and determinant)
/// and name the pair the loop does tend to, the ring in the pole plot.
#[test]
fn a_model_error_is_named_with_both_pairs() {
    let pair = |re: f64, im: f64| minus(format!("{re:.2} ± {:.2}j 1/s", im.abs()));
    let s = common::session("preset=fig5.3&arm=stiffer&model=paper");
    let story = s.status().story.unwrap();
    let report = s.run(0).unwrap().analysis().report().unwrap().clone();
    let r = &report.resonance;
    let (mean, im) = (r.trace / 2.0, (r.determinant - r.trace * r.trace / 4.0).sqrt());
    assert_eq!(story.a4, pair(mean, im));
    let [re, lim] = report.limit_pair_open[0];
    let moved = pair(re, lim);
    assert_ne!(moved, story.a4, "a stiffer arm the controller does not know moves the pair");
    assert!(story.model_note.contains(&moved) && story.model_note.contains(&story.a4), "{}", story.model_note);
    assert!(story.loop_limit.starts_with(&moved), "{}", story.loop_limit);
    assert!(story.lq_says.contains("paper's arm"), "{}", story.lq_says);
    // Without the error there is no note.
    let s = common::session("preset=fig5.3&arm=stiffer");
    assert_eq!(s.status().story.unwrap().model_note, "");
}

/// The mechanism's balance as printed adds up (issue 19's trial: "−14.4 % − 2.3 % = −16.8 %"): the
/// shares are rounded so that W_v (+ W_K) − D, printed, is the printed net, and the net is
/// |λ|² − 1 of the flexible pair rounded to 0.1 %. Over arms, α, δ and the preliminary feedbacks.
#[test]
fn the_printed_energy_balance_adds_up() {
    let mut checked = 0;
    for arm in ["", "&k1=4610.4", "&ir1=0.48475", "&arm=damped"] {
        for pf in ["off", "paper", "lq"] {
            for delta in ["0.005", "0.01", "0.03", "0.05", "0.08", "0.15", "0.2"] {
                for alpha in ["1", "2", "3"] {
                    let (s, notices) =
                        flexarm::session::Session::open(&format!("delta={delta}&pf={pf}&alpha={alpha}{arm}"));
                    assert!(notices.is_empty(), "{notices:?}");
                    let Some(story) = s.status().story else { continue };
                    if story.energy.is_empty() {
                        continue;
                    }
                    // "… it puts 5.4 % of the swing's energy in[, Kₚᵣ takes 8.9 % out], and the arm's
                    // damping takes 0.6 % out: the swing's energy changes by +4.8 % a period …":
                    // each "N %" signed by the verb before it.
                    let words: Vec<&str> = story.energy.split(' ').collect();
                    let mut terms = Vec::new();
                    let mut sign = 1.0;
                    for (i, w) in words.iter().enumerate() {
                        match *w {
                            "puts" | "by" => sign = 1.0,
                            "takes" => sign = -1.0,
                            _ => {}
                        }
                        if words.get(i + 1).is_some_and(|n| n.starts_with('%')) {
                            if let Ok(v) = w.replace('−', "-").parse::<f64>() {
                                terms.push(sign * v);
                            }
                        }
                    }
                    let case = format!("δ={delta} {pf} α={alpha}{arm}: {}", story.energy);
                    let (net, shares) = terms.split_last().unwrap_or_else(|| panic!("{case}"));
                    assert!((2..=3).contains(&shares.len()), "{case}");
                    assert!((shares.iter().sum::<f64>() - net).abs() < 1e-9, "{case}");
                    // The net is |λ|² − 1 of the flexible pair, rounded.
                    let report = s.run(0).unwrap().analysis().report().unwrap();
                    let [Some(i), _] = report.flexible_pair() else { panic!("{case}") };
                    let lambda = report.poles[i].discrete;
                    let exact = 100.0 * (lambda[0] * lambda[0] + lambda[1] * lambda[1] - 1.0);
                    assert!((net - exact).abs() <= 0.05 + 1e-9, "{case}: |λ|² − 1 = {exact} %");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 150, "{checked}");
}
