//! The explanation's equations (MathML from `flexarm::session::equations`): well-formed, and with
//! the numbers of the sentences beside them and of the analysis — one source for both.

use flexarm::analysis::lag::LagLaw;

mod common;

/// The tags of a MathML string nest and close (a small check: `<x>`, `</x>`, `<x …>`).
fn well_formed(m: &str) {
    let mut open: Vec<&str> = Vec::new();
    let mut rest = m;
    while let Some(start) = rest.find('<') {
        let end = rest[start..].find('>').expect("a tag closes") + start;
        let tag = &rest[start + 1..end];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(open.pop(), Some(name), "in {m}");
        } else {
            open.push(tag.split_whitespace().next().unwrap());
        }
        rest = &rest[end + 1..];
    }
    assert!(open.is_empty(), "unclosed {open:?} in {m}");
}

#[test]
fn the_equations_carry_the_storys_numbers() {
    for query in
        ["preset=fig5.3", "preset=fig5.2", "preset=fig5.3&delta=0.05&arm=softer", "preset=fig5.3&alpha1=1&alpha2=3"]
    {
        let s = common::session(query);
        let story = s.status().story.unwrap();
        let report = s.run(0).unwrap().analysis().report().unwrap().clone();
        for m in [
            &story.math_constraint,
            &story.math_re_a4,
            &story.math_rho,
            &story.math_growth,
            &story.math_lag,
            &story.math_energy,
        ] {
            assert!(m.starts_with("<math"), "{query}: {m}");
            well_formed(m);
        }
        // ρ as the sentence says it.
        assert!(story.math_rho.contains(&format!("<mn>{}</mn>", story.rho)), "{query}: {}", story.math_rho);
        // Re A4's two parts and their difference, as the sentence's.
        let number = |t: &str| t.trim_end_matches(" 1/s").replace('−', "");
        for part in [&story.feed, &story.motor_damping, &story.re_a4] {
            assert!(
                story.math_re_a4.contains(&format!("<mn>{}</mn>", number(part))),
                "{query}: {part} in {}",
                story.math_re_a4
            );
        }
        assert!(story.math_growth.contains(&format!("<mn>{}</mn>", number(&story.growth))), "{query}");
        // The law's lag in radians, from the same law the sentences quote.
        let law = LagLaw::of(&report);
        let delta = s.settings().a.delta;
        assert!(story.math_lag.contains(&format!("<mn>{:.2}</mn>", law.lag(delta))), "{query}: {}", story.math_lag);
        // (4.3) with α: 3α and 3α² as coefficients, α³ on w.
        let a = s.settings().a.alpha[0];
        let significant = |v: f64| flexarm::plot::format::significant_trimmed(v, 4);
        for coefficient in [3.0 * a, 3.0 * a * a, a * a * a] {
            assert!(
                story.math_constraint.contains(&format!("<mn>{}</mn>", significant(coefficient))),
                "{query}: {coefficient}"
            );
        }
    }
}
