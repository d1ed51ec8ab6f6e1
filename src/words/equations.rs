//! The explanation's equations with today's numbers, as MathML (native in today's browsers and
//! read by screen readers; no script to typeset them): the law the predictor imposes (4.3), Re A4,
//! ρ, the growth ln ρ/δ and the lag law. Built from the same numbers as the story's sentences,
//! so an equation and the sentence beside it cannot disagree (`tests/equations.rs`).

use serde::Serialize;

use crate::analysis::lag::LagLaw;
use crate::analysis::StabilityReport;
use crate::plot::format::significant_trimmed;

/// Each equation as one `<math>` element.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Equations {
    /// (d/dt + α_i)³ e_i = 0 written out: ë_i + 3α_i ė_i + 3α_i² e_i + w_i = 0, ẇ_i = α_i³ e_i.
    pub constraint: String,
    /// Re A4 = 3β/2 − B_v1/(2 I_r1) = … = … 1/s.
    pub re_a4: String,
    /// ρ = max |λ| = ….
    pub rho: String,
    /// ln ρ/δ = ln … / … s = … 1/s.
    pub growth: String,
    /// φ = 1.5 ωδ = … rad; σ ≈ (3β/2) cos φ − B_v1/(2 I_r1) = … 1/s.
    pub lag: String,
    /// The swing's energy over one period: |λ|² − 1 = W_v (+ W_K) − D = … (empty without a
    /// flexible pair).
    pub energy: String,
}

fn mi(x: &str) -> String {
    format!("<mi>{x}</mi>")
}

fn mo(x: &str) -> String {
    format!("<mo>{x}</mo>")
}

/// A number, with U+2212 for its minus sign (as every number the page prints).
fn mn(v: &str) -> String {
    match v.strip_prefix(['-', '−']) {
        Some(rest) => format!("<mo>−</mo><mn>{rest}</mn>"),
        None => format!("<mn>{v}</mn>"),
    }
}

fn sub(base: &str, index: &str) -> String {
    format!("<msub>{base}{index}</msub>")
}

fn frac(num: &str, den: &str) -> String {
    format!("<mfrac><mrow>{num}</mrow><mrow>{den}</mrow></mfrac>")
}

/// e, ė or ë (`dots` = 0, 1, 2) with index `i` (precomposed letters: every font has them, where
/// a MathML accent over e can come out too small to see).
fn error(dots: usize, i: &str) -> String {
    sub(&mi(["e", "ė", "ë"][dots.min(2)]), &mi(i))
}

fn math(body: &str) -> String {
    format!("<math display=\"block\"><mrow>{body}</mrow></math>")
}

/// "2.64" with two decimals and the page's minus.
fn fixed2(v: f64) -> String {
    crate::plot::format::minus(&format!("{v:.2}"))
}

/// The motor's damping term B_v1/(2 I_r1).
fn motor_term() -> String {
    frac(&sub(&mi("B"), &mi("v1")), &[mn("2"), sub(&mi("I"), &mi("r1"))].concat())
}

/// The controller's feed 3β/2.
fn feed_term() -> String {
    frac(&[mn("3"), mi("β")].concat(), &mn("2"))
}

/// A number with its unit after a thin space.
fn quantity(v: &str, unit: &str) -> String {
    [mn(v), mi(&format!("&#8201;{unit}"))].concat()
}

/// The equations of run A's analysis (`report`, its lag law `law`) at sampling period `delta`
/// under α.
pub fn equations(report: &StabilityReport, law: &LagLaw, alpha: [f64; 2], delta: f64) -> Equations {
    let r = &report.resonance;
    let n = |v: f64| mn(&significant_trimmed(v, 4));
    // (4.3) written out per link; one line for both where α1 = α2.
    let line = |i: &str, a: f64| {
        [
            error(2, i),
            mo("+"),
            n(3.0 * a),
            error(1, i),
            mo("+"),
            n(3.0 * a * a),
            error(0, i),
            mo("+"),
            sub(&mi("w"), &mi(i)),
            mo("="),
            mn("0"),
            mo(",&#8195;"),
            sub(&mi("ẇ"), &mi(i)),
            mo("="),
            n(a * a * a),
            error(0, i),
        ]
        .concat()
    };
    let constraint = if alpha[0] == alpha[1] {
        math(&line("i", alpha[0]))
    } else {
        [math(&line("1", alpha[0])), math(&line("2", alpha[1]))].concat()
    };
    let re_a4 = math(
        &[
            mi("Re"),
            sub(&mi("A"), &mn("4")),
            mo("="),
            feed_term(),
            mo("−"),
            motor_term(),
            mo("="),
            mn(&fixed2(r.controller_feed)),
            mo("−"),
            mn(&fixed2(r.motor_damping)),
            mo("="),
            quantity(&fixed2(r.real_part), "1/s"),
        ]
        .concat(),
    );
    let rho_text = super::numbers::rho(report.spectral_radius);
    let rho = math(&[mi("ρ"), mo("="), mi("max"), mo("|"), mi("λ"), mo("|"), mo("="), mn(&rho_text)].concat());
    let growth = math(
        &[
            frac(&[mi("ln"), mi("ρ")].concat(), &mi("δ")),
            mo("="),
            frac(&[mi("ln"), mn(&rho_text)].concat(), &quantity(&significant_trimmed(delta, 3), "s")),
            mo("="),
            quantity(&fixed2(report.growth_rate), "1/s"),
        ]
        .concat(),
    );
    // Two short lines, so that a narrow column shows them whole: the turn per period, the lag.
    let turn = [
        mi("ω"),
        mi("δ"),
        mo("="),
        quantity(&fixed2(law.omega), "rad/s"),
        mo("×"),
        quantity(&significant_trimmed(delta, 3), "s"),
        mo("="),
        quantity(&fixed2(law.turn(delta)), "rad"),
    ]
    .concat();
    let phase =
        [mi("φ"), mo("="), mn("1.5"), mi("ω"), mi("δ"), mo("="), quantity(&fixed2(law.lag(delta)), "rad")].concat();
    // The growth on a line of its own (a narrow column does not have to scroll); beyond ωδ = π the
    // law has nothing to say.
    let growth_by_law = if law.turn(delta) >= core::f64::consts::PI {
        mi("beyond ωδ = π the swing is aliased: the law says nothing")
    } else {
        [
            mi("σ"),
            mo("≈"),
            feed_term(),
            mi("cos"),
            mi("φ"),
            mo("−"),
            motor_term(),
            mo("="),
            quantity(&fixed2(law.growth(delta)), "1/s"),
        ]
        .concat()
    };
    let energy = report.swing_energy.map_or(String::new(), |e| {
        let percent = |v: f64| mn(&format!("{}&#8201;%", crate::plot::format::minus(&format!("{:.1}", 100.0 * v))));
        let signed = |v: f64| if v < 0.0 { [mo("−"), percent(-v)].concat() } else { [mo("+"), percent(v)].concat() };
        let with_feedback = e.preliminary_feedback != 0.0;
        // The shares as the sentence prints them: rounded so that the balance adds up.
        let [held, preliminary, damping, net] = super::numbers::energy_shares(&e);
        let mut terms = vec![sub(&mi("W"), &mi("v"))];
        let mut values = vec![percent(held)];
        if with_feedback {
            terms.extend([mo("+"), sub(&mi("W"), &mi("K"))]);
            values.push(signed(preliminary));
        }
        terms.extend([mo("−"), mi("D")]);
        values.push([mo("−"), percent(damping)].concat());
        // Two short lines, so that a narrow column shows them whole: the balance, its numbers.
        let balance = [frac(&[mi("ΔE"), mo("/"), mi("E")].concat(), &mi("period")), mo("="), terms.concat()];
        let numbers = [mo("="), values.concat(), mo("="), percent(net)];
        [math(&balance.concat()), math(&numbers.concat())].concat()
    });
    Equations {
        constraint,
        re_a4,
        rho,
        growth,
        lag: [math(&turn), math(&phase), math(&growth_by_law)].concat(),
        energy,
    }
}
