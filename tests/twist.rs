//! The cure as a design (issue 32, the core): a feedback of the joint's twist alone on the motor
//! torque, T1 += k_p (q1 − θ) + k_d (q̇1 − θ̇), is a damper between motor and link 1. Checked
//! against the numerical δ → 0 limit over arms, α and q2: Re A4 = 3α/2 − (Bv1 + k_d)/(2 Ir1);
//! a pair placed by (k_p, k_d) reads back as the target; no twist is no feedback; and its price on
//! a sampled inner loop: the largest stable δ falls as the damping grows.

use flexarm::analysis::resonance::*;
use flexarm::analysis::*;
use flexarm::control::config::{ControllerParameters, InnerLoop};
use flexarm::control::feedback::*;
use flexarm::*;
use nalgebra::Complex;
use std::f64::consts::PI;

fn numerical(plant: &PlantParameters, alpha: [f64; 2], q2: f64, gain: &FeedbackGain) -> LimitPair {
    limit_pair(&linearize_at_rest(plant, alpha, [0.5 * PI, q2]), gain).unwrap()
}

/// A small deterministic generator (no dependency): xorshift64*.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let u = (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * u
    }
}

/// Arms around the paper's: the joint's stiffness, the motor's inertia and damping, link 2's
/// coupling each scaled by up to 3× either way.
fn random_arm(rng: &mut Rng) -> PlantParameters {
    let p = PlantParameters::default();
    let scale = |rng: &mut Rng| 3f64.powf(rng.uniform(-1.0, 1.0));
    PlantParameters {
        k1: p.k1 * scale(rng),
        ir1: p.ir1 * scale(rng),
        bv1: p.bv1 * scale(rng),
        a3: p.a3 * rng.uniform(0.3, 1.0),
        ..p
    }
}

#[test]
fn the_twist_is_a_damper_re_a4_is_three_alpha_halves_minus_motor_and_twist_damping() {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    for _ in 0..40 {
        let plant = random_arm(&mut rng);
        let alpha = rng.uniform(0.3, 6.0);
        let q2 = rng.uniform(-PI, PI);
        let [kp, kd] = [rng.uniform(0.0, 300.0), rng.uniform(0.0, 60.0)];
        let n = numerical(&plant, [alpha, alpha], q2, &twist_gain(kp, kd));
        let re = 1.5 * alpha - (plant.bv1 + kd) / (2.0 * plant.ir1);
        assert!(
            (n.eigenvalues[0].re - re).abs() < 1e-6 * (1.0 + re.abs()),
            "{plant:?} α = {alpha} q2 = {q2} k_p = {kp} k_d = {kd}: Re A4 {} vs {re}",
            n.eigenvalues[0]
        );
        // The stiffness moves the frequency, not the real part.
        let stiff = numerical(&plant, [alpha, alpha], q2, &twist_gain(kp + 100.0, kd));
        assert!((stiff.eigenvalues[0].re - re).abs() < 1e-6 * (1.0 + re.abs()));
        assert!(stiff.eigenvalues[0].im > n.eigenvalues[0].im, "a stiffer joint swings faster");
    }
}

#[test]
fn a_pair_placed_by_the_twist_reads_back_as_the_target() {
    let mut rng = Rng(0x5eed_1234_abcd_0002);
    for _ in 0..30 {
        let plant = random_arm(&mut rng);
        let alpha = [rng.uniform(0.3, 6.0), rng.uniform(0.3, 6.0)];
        let q2 = rng.uniform(-PI, PI);
        let open = JointResonance::new(&plant, alpha, q2).eigenvalues[0];
        let target = Complex::new(rng.uniform(-8.0, 1.0), open.im * rng.uniform(0.7, 1.3));
        let [kp, kd] = twist_placing(&plant, alpha, q2, target);
        let placed = numerical(&plant, alpha, q2, &twist_gain(kp, kd)).eigenvalues[0];
        assert!(
            (placed - target).norm() < 1e-6 * target.norm(),
            "{plant:?} α = {alpha:?} q2 = {q2}: target {target}, placed {placed} with k_p = {kp}, k_d = {kd}"
        );
    }
}

#[test]
fn the_issues_example_the_papers_pair_mirrored_on_the_papers_arm() {
    // Issue 32, from an independent SciPy model at α = 2, q2 = 0: −2.6 ± 29.6j ⇒ k_p ≈ 123.6,
    // k_d ≈ 20.32.
    let [kp, kd] = twist_placing(&PlantParameters::default(), [2.0, 2.0], 0.0, Complex::new(-2.6, 29.6));
    assert!((kp - 123.6).abs() < 0.5, "k_p = {kp}");
    assert!((kd - 20.32).abs() < 0.05, "k_d = {kd}");
}

#[test]
fn no_twist_is_no_preliminary_feedback() {
    assert_eq!(twist_gain(0.0, 0.0), FeedbackGain::zeros());
    let plant = PlantParameters::default();
    let off = numerical(&plant, [2.0, 2.0], 0.0, &FeedbackGain::zeros());
    let zero = numerical(&plant, [2.0, 2.0], 0.0, &twist_gain(0.0, 0.0));
    assert_eq!(off.a4, zero.a4);
}

/// ρ of the sampled loop at δ with the twist feedback sampled at δ too (a digital inner loop).
fn rho_sampled(plant: &PlantParameters, gain: &FeedbackGain, delta: f64) -> f64 {
    let model = linearize_at_rest(plant, [2.0, 2.0], [0.5 * PI, 0.0]);
    let controller = ControllerParameters { sampling_period: delta, alpha: [2.0, 2.0], ..Default::default() };
    let m = sampled_loop_matrix(&model, &model, gain, &controller, InnerLoop::Sampled).unwrap();
    loop_eigenvalues(&m).first().map_or(0.0, |c| c.norm())
}

/// The upper edge of the lowest stable window of δ in [0.002, 0.25] s, on a fine log grid: where
/// the loop first fails as δ grows past the δ that work (NaN if none works).
fn largest_stable_delta(plant: &PlantParameters, gain: &FeedbackGain) -> f64 {
    let mut last = f64::NAN;
    for i in 0..=1200 {
        let delta = 0.002 * (0.25f64 / 0.002).powf(i as f64 / 1200.0);
        let stable = rho_sampled(plant, gain, delta) < 1.0;
        if stable {
            last = delta;
        } else if last.is_finite() {
            break;
        }
    }
    last
}

#[test]
fn the_price_a_digital_damper_shrinks_the_largest_stable_delta() {
    let plant = PlantParameters::default();
    let mut previous = f64::INFINITY;
    let mut seen = Vec::new();
    // Issue 32's independent SciPy model (linear sampled loop, α = 2, q2 = 0) found these δ_max.
    let scipy = [0.095, 0.084, 0.064, 0.042, 0.023];
    for (kd, expected) in [5.0, 16.0, 40.0, 80.0, 160.0].into_iter().zip(scipy) {
        let gain = twist_gain(0.0, kd);
        let first = rho_sampled(&plant, &gain, 0.002);
        let dmax = largest_stable_delta(&plant, &gain);
        seen.push((kd, first, dmax));
        // Damping past 3α Ir1 − Bv1 puts the pair in the left half-plane: the smallest δ works.
        let cures = kd > 3.0 * 2.0 * plant.ir1 - plant.bv1;
        assert_eq!(first < 1.0, cures, "k_d = {kd}: ρ(0.002 s) = {first}");
        assert!(dmax < previous, "δ_max must fall as k_d grows: {seen:?}");
        assert!((dmax / expected - 1.0).abs() < 0.02, "k_d = {kd}: δ_max {dmax} s, SciPy {expected} s");
        previous = dmax;
    }
    println!("k_d, ρ(0.002 s), top of the lowest stable window of δ (sampled inner loop, α = 2, q2 = 0): {seen:?}");
}

#[test]
fn at_alpha_five_the_papers_gain_fails_and_a_designed_damper_cures_it() {
    // Issue 32: at α = 5, 3α/2 outruns the paper's fixed damping (ρ(0.01 s) ≈ 1.014); a twist
    // damper past 3α Ir1 − Bv1 (here k_d = 40) puts the pair back in the left half-plane.
    let plant = PlantParameters::default();
    let rho = |gain: &FeedbackGain| {
        let model = linearize_at_rest(&plant, [5.0, 5.0], [0.5 * PI, 0.0]);
        let controller = ControllerParameters { sampling_period: 0.01, alpha: [5.0, 5.0], ..Default::default() };
        let m = sampled_loop_matrix(&model, &model, gain, &controller, InnerLoop::Continuous).unwrap();
        loop_eigenvalues(&m).first().map_or(0.0, |c| c.norm())
    };
    let paper = rho(&paper_gain());
    assert!(paper > 1.0 && (paper - 1.014).abs() < 0.002, "paper K_pr at α = 5: ρ = {paper}");
    let bound = 3.0 * 5.0 * plant.ir1 - plant.bv1;
    assert!(40.0 > bound, "k_d = 40 is past 3α Ir1 − Bv1 = {bound}");
    assert!(rho(&twist_gain(0.0, 40.0)) < 1.0);
    assert!(rho(&twist_gain(0.0, 0.5 * bound)) > 1.0, "half the damping it takes is not enough");
}

/// The setting (issue 32, part 2): `pf=twist` with `twist_stiffness` and `twist_damping` through
/// the one schema; the gains reach the loop, the state string keeps them only when they are not
/// the defaults, the page shows their controls only under `pf=twist`, and the sentence beside
/// the feedback's selector gives the damping the pair needs, which the numerical limit confirms
/// on either side of it, over arms and α.
mod setting {
    use super::*;
    use flexarm::session::Session;

    fn session(query: &str) -> Session {
        let (s, notices) = Session::open(query);
        assert!(notices.is_empty(), "{query}: {notices:?}");
        s
    }

    #[test]
    fn the_gains_reach_the_loop_and_the_link_keeps_them() {
        let s = session("pf=twist&twist_stiffness=120&twist_damping=40&alpha=2&delta=0.01");
        let c = s.settings().a.config();
        assert_eq!(resolve_gain(&c).unwrap(), twist_gain(120.0, 40.0));
        let state = s.state_string();
        assert!(
            state.contains("pf=twist") && state.contains("twist_stiffness=120") && state.contains("twist_damping=40"),
            "{state}"
        );
        // At their defaults the gains stay out of links, as the arm's parameters do.
        let plain = session("pf=off").state_string();
        assert!(!plain.contains("twist"), "{plain}");
    }

    #[test]
    fn their_controls_show_only_under_the_twist_feedback() {
        let shown = |q: &str| {
            session(q)
                .controls()
                .into_iter()
                .filter(|c| c.key.starts_with("twist_"))
                .map(|c| c.shown)
                .collect::<Vec<_>>()
        };
        assert_eq!(shown("pf=paper"), [false, false]);
        assert_eq!(shown("pf=twist"), [true, true]);
        assert_eq!(shown("pf=off&compare=1&b_pf=twist"), [true, true]);
    }

    #[test]
    fn the_damping_the_note_asks_for_is_where_the_pair_crosses_the_axis() {
        let mut rng = Rng(0x5eed_1234_abcd_0003);
        let mut checked = 0;
        for _ in 0..12 {
            let plant = random_arm(&mut rng);
            let alpha = rng.uniform(0.5, 6.0);
            let needed = 3.0 * alpha * plant.ir1 - plant.bv1;
            if needed <= 1.0 {
                continue;
            }
            let arm = flexarm::schema::ARM_PARAMS
                .iter()
                .zip(plant.values())
                .map(|(p, v)| format!("{}={v}", p.key))
                .collect::<Vec<_>>()
                .join("&");
            let c = session(&format!("pf=twist&alpha={alpha}&{arm}")).settings().a.config();
            let report = analyze(&c, None).unwrap();
            let note = flexarm::words::story::story(&c, &report).kpr_note;
            let printed = format!("{} N m s/rad", flexarm::plot::format::significant_trimmed(needed, 3));
            assert!(note.contains(&printed), "{note} should ask for {printed}");
            for (kd, stable) in [(needed * 1.05, true), (needed * 0.95, false)] {
                let re = numerical(&plant, [alpha, alpha], 0.0, &twist_gain(0.0, kd)).eigenvalues[0].re;
                assert_eq!(re < 0.0, stable, "α = {alpha}, k_d = {kd}: Re A4 = {re}");
            }
            checked += 1;
        }
        assert!(checked >= 8, "only {checked} arms needed damping");
    }
}

#[test]
fn the_readme_says_what_k_d_16_does() {
    let pair = numerical(&PlantParameters::default(), [2.0, 2.0], 0.0, &twist_gain(0.0, 16.0)).eigenvalues[0];
    let said = format!("A4 = −{:.2} ± {:.2}j", -pair.re, pair.im);
    let readme = include_str!("../README.md");
    assert!(readme.contains(&said), "README should say {said:?}");
}

#[test]
fn the_readme_says_what_placing_the_papers_pair_takes() {
    let [kp, kd] = twist_placing(&PlantParameters::default(), [2.0, 2.0], 0.0, Complex::new(-2.6, 29.6));
    let said = format!("{kp:.2} N m/rad and {kd:.2} N m s/rad");
    assert!(include_str!("../README.md").contains(&said), "README should say {said:?}");
}
