//! Issue 34, items 3 and 6: the pair A4 is not always a swing, and the paper's fixed K_pr does not
//! damp it on every arm. Where the motor is damped past its swing, A4 is two real eigenvalues (det
//! A4 can even turn negative: a slow real mode grows though tr A4 < 0), and where a heavier motor
//! takes the gains' damping shift down (it scales with 1/Ir1), 3α/2 outweighs it. Checked against
//! the numerical δ → 0 limit of the linearized loop, which knows nothing of the closed forms.

use flexarm::analysis::resonance::*;
use flexarm::analysis::*;
use flexarm::control::feedback::*;
use flexarm::*;
use std::f64::consts::PI;
use std::process::Command;

fn numerical(plant: &PlantParameters, alpha: f64, gain: &FeedbackGain) -> LimitPair {
    limit_pair(&linearize_at_rest(plant, [alpha, alpha], [0.5 * PI, 0.0]), gain).unwrap()
}

/// The larger real part of the numerical limit pair: the pair is stable where it is < 0.
fn growth(plant: &PlantParameters, alpha: f64, gain: &FeedbackGain) -> f64 {
    let e = numerical(plant, alpha, gain).eigenvalues;
    e[0].re.max(e[1].re)
}

fn analyze(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm")).arg("analyze").args(args).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap()
}

/// The α below which the pair is stable is where tr A4 or det A4 first reaches zero, whichever is
/// first — on a lightly damped motor α* = Bv1/(3 Ir1), on a heavily damped one the det root.
#[test]
fn the_pair_is_stable_exactly_below_its_alpha_bound_on_light_and_heavy_damping() {
    let paper = PlantParameters::default();
    let arms = [
        paper,
        PlantParameters { bv1: 290.0, ..paper },
        PlantParameters { bv1: 120.0, ..paper },
        PlantParameters { bv1: 400.0, ir1: 4.0, ..paper },
        PlantParameters { k1: paper.k1 / 4.0, bv1: 60.0, ..paper },
    ];
    let mut by_det = 0;
    for plant in arms {
        for gain in [FeedbackGain::zeros(), paper_gain()] {
            let b = AlphaBound::new(&plant, 0.0, &gain);
            let edge = b.stable_below();
            assert!(edge > 0.0, "{plant:?}");
            assert!(growth(&plant, 0.97 * edge, &gain) < 0.0, "{plant:?}: stable just below {edge}");
            assert!(growth(&plant, 1.03 * edge, &gain) > 0.0, "{plant:?}: unstable just above {edge}");
            by_det += usize::from(b.lost_to_det());
        }
    }
    // The heavily damped motors lose the pair to det A4 first: α* alone would be wrong there.
    assert!(by_det >= 3, "{by_det}");
    // α* is the trace's bound without feedback.
    assert!((AlphaBound::new(&paper, 0.0, &FeedbackGain::zeros()).trace_zero - alpha_star(&paper)).abs() < 1e-12);
}

#[test]
fn analyze_prints_a_real_pair_as_two_real_eigenvalues_and_the_true_alpha_bound() {
    let text = analyze(&["--bv1", "290", "--pf", "off"]);
    assert!(!text.contains("± 0.0000j"), "{text}");
    let plant = PlantParameters { bv1: 290.0, ..PlantParameters::default() };
    let n = numerical(&plant, 2.0, &FeedbackGain::zeros()).eigenvalues;
    assert!(n[0].im == 0.0 && n[1].im == 0.0, "a real pair: {n:?}");
    let (hi, lo) = (n[0].re.max(n[1].re), n[0].re.min(n[1].re));
    assert!(text.contains(&format!("{hi:.4} and {lo:.4} 1/s (two real eigenvalues)")), "{text}");
    // The trace formula is a mean there, not a growth rate, and α* is not where it turns unstable.
    assert!(!text.contains("Re A4 = 3β/2"), "{text}");
    assert!(text.contains("is their mean, not a growth rate"), "{text}");
    assert!(!text.contains("below it (α1 = α2) the pair is stable"), "{text}");
    let edge = AlphaBound::new(&plant, 0.0, &FeedbackGain::zeros()).stable_below();
    assert!(edge < 2.0 && growth(&plant, 2.0, &FeedbackGain::zeros()) > 0.0);
    assert!(text.contains(&format!("stable only for α < {edge:.4} 1/s")), "{text}");
    // The paper's arm keeps its swing and its α*.
    let text = analyze(&["--pf", "off"]);
    assert!(text.contains("Re A4 = 3β/2 − Bv1/(2 Ir1)") && text.contains("below it (α1 = α2) the pair is stable"));
}

/// Item 6: the heavier motor (I_r1 × 4) quarters what the paper's gains add to the motor's
/// damping through T1; at α = 2 the feed 3α/2 outweighs it and small δ fail — analyze says so.
#[test]
fn analyze_says_where_the_papers_gains_stop_working_on_the_heavier_motor() {
    let heavier = PlantParameters { ir1: 4.0 * PlantParameters::default().ir1, ..PlantParameters::default() };
    assert!(growth(&heavier, 2.0, &paper_gain()) > 0.0, "the paper's K_pr leaves the pair unstable");
    let text = analyze(&["--arm", "heavier", "--delta", "0.01"]);
    assert!(text.contains("at α = 2 1/s it does not damp the pair on this arm"), "{text}");
    assert!(text.contains("redone for each arm and α"), "{text}");
    // Where the gains do damp the pair, nothing of the kind is said.
    assert!(growth(&PlantParameters::default(), 2.0, &paper_gain()) < 0.0);
    assert!(!analyze(&["--delta", "0.01"]).contains("does not damp the pair"));
}

/// Item 14: "In short" says where "every small δ" holds with the paper's K_pr, for the arm and α
/// shown — not the paper's arm at α = 2 everywhere.
#[test]
fn the_pages_cure_sentence_holds_on_the_arm_and_alpha_shown() {
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/www/index.html")).unwrap();
    assert!(page.contains(r#"<span data-live="kpr_cure">"#), "In short's cure is live");
    let cure = |state: &str| {
        let (s, notices) = flexarm::session::Session::open(state);
        assert!(notices.is_empty(), "{notices:?}");
        s.status().story.unwrap().kpr_cure
    };
    let paper = PlantParameters::default();
    for (state, plant, alpha) in [
        ("pf=paper", paper, 2.0),
        ("alpha=5&pf=paper", paper, 5.0),
        ("arm=heavier&pf=paper", PlantParameters { ir1: 4.0 * paper.ir1, ..paper }, 2.0),
        ("alpha=1&arm=heavier", PlantParameters { ir1: 4.0 * paper.ir1, ..paper }, 1.0),
    ] {
        let text = cure(state);
        let works = growth(&plant, alpha, &paper_gain()) < 0.0;
        assert_eq!(text.contains("then every small δ works"), works, "{state}: {text}");
        assert_eq!(text.contains("small δ still fail"), !works, "{state}: {text}");
        let edge = AlphaBound::new(&plant, 0.0, &paper_gain()).stable_below();
        assert!(text.contains(&format!("{edge:.2} 1/s")), "{state}: the bound for this arm: {text}");
    }
}

/// Item 3 on the page: where the motor is damped past its swing, no number the explanation
/// quotes writes a real pair as "± 0.00j" (the loop's pair, A4, what K_pr and the LQ design make).
#[test]
fn the_page_never_writes_a_real_pair_as_a_complex_one() {
    for state in ["bv1=290&pf=off", "bv1=290&pf=paper", "bv1=290&pf=lq&delta=0.002"] {
        let (s, notices) = flexarm::session::Session::open(state);
        assert!(notices.is_empty(), "{notices:?}");
        let status = s.status();
        let story = serde_json::to_string(&status.story.unwrap()).unwrap();
        assert!(!story.contains("± 0.00j") && !story.contains("± −0.00j"), "{state}: {story}");
        assert!(story.contains("two real eigenvalues") || story.contains(" and "), "{state}");
        assert!(!status.runs[0].readouts.a4.contains("± 0"), "{state}: {}", status.runs[0].readouts.a4);
    }
}

/// Items 6 and 14 on every arm preset and α: the page's cure sentence, the CLI's line on the
/// paper's gains and the pair's stability under them (the numerical δ → 0 limit, which knows
/// nothing of the words) agree.
#[test]
fn the_cure_is_said_truly_on_every_arm_preset_and_alpha() {
    let mut failing = 0;
    for preset in flexarm::session::presets::ARMS {
        for alpha in [0.3, 1.0, 2.0, 5.0] {
            let state = format!("arm={}&alpha={alpha}&pf=paper", preset.id);
            let (s, notices) = flexarm::session::Session::open(&state);
            assert!(notices.is_empty(), "{notices:?}");
            let plant = s.run(0).unwrap().closed_loop().config().plant;
            let works = growth(&plant, alpha, &paper_gain()) < 0.0;
            let cure = s.status().story.unwrap().kpr_cure;
            assert_eq!(cure.contains("then every small δ works"), works, "{state}: {cure}");
            assert_eq!(cure.contains("small δ still fail"), !works, "{state}: {cure}");
            let cli = analyze(&["--arm", preset.id, "--alpha", &alpha.to_string()]);
            assert_eq!(cli.contains("does not damp the pair on this arm"), !works, "{state}:\n{cli}");
            failing += usize::from(!works);
        }
    }
    // Not a vacuous check: the paper's gains fail somewhere (α = 5, the heavier motor).
    assert!(failing >= 2, "{failing}");
}

/// Where the paper's gains fail because the motor is damped past its swing (det A4 < 0 first),
/// the reason given is that, not the feed outweighing their damping — which is false there.
#[test]
fn a_motor_damped_past_its_swing_is_given_its_own_reason() {
    let plant = PlantParameters { bv1: 290.0, ..PlantParameters::default() };
    let bound = AlphaBound::new(&plant, 0.0, &paper_gain());
    assert!(bound.lost_to_det() && growth(&plant, 2.0, &paper_gain()) > 0.0);
    let (s, _) = flexarm::session::Session::open("bv1=290&pf=paper");
    let cure = s.status().story.unwrap().kpr_cure;
    let cli = analyze(&["--bv1", "290"]);
    for text in [&cure, &cli] {
        assert!(text.contains("one real eigenvalue of the pair crosses zero (det A4 < 0)"), "{text}");
        assert!(!text.contains("outweighs"), "{text}");
    }
    // On the heavier motor the trace decides, and the feed is the reason.
    let heavier = PlantParameters { ir1: 4.0 * PlantParameters::default().ir1, ..PlantParameters::default() };
    assert!(!AlphaBound::new(&heavier, 0.0, &paper_gain()).lost_to_det());
    assert!(analyze(&["--arm", "heavier"]).contains("outweighs the shift's"));
}
