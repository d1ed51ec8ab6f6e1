//! One judgement, said once (issue 20): over a grid of δ, α, K_pr, friction, repeat and run
//! lengths, the page's headline, its "observed" line, its readouts and the CLI's JSON never
//! disagree — the same verdict word everywhere, and every reason the observation gives is one the
//! data support.

mod common;

use std::process::Command;

use flexarm::control::metrics::GROWTH_FIT_SPAN;

/// The number after `prefix` in `text` ("observed growth rate −0.52 1/s" → −0.52).
fn number_after(text: &str, prefix: &str) -> Option<f64> {
    let rest = &text[text.find(prefix)? + prefix.len()..];
    let word: String = rest.chars().take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '−' | '-' | 'e')).collect();
    word.replace('−', "-").parse().ok()
}

#[test]
fn the_page_and_the_cli_judge_every_run_alike_for_the_reasons_they_give() {
    let mut checked = 0;
    for delta in ["0.01", "0.035", "0.05", "0.15"] {
        for alpha in ["0.5", "2"] {
            for pf in ["off", "paper"] {
                for friction in ["continuous", "held", "off"] {
                    for repeat in ["0", "1"] {
                        let state = format!("delta={delta}&alpha={alpha}&pf={pf}&friction={friction}&repeat={repeat}");
                        for duration in [3.0, 8.0] {
                            check(&state, duration);
                            checked += 1;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(checked, 192);
}

fn check(state: &str, duration: f64) {
    let mut s = common::session(state);
    common::play(&mut s, duration);
    let t = s.run(0).unwrap().closed_loop().time();
    let st = &s.status().runs[0];
    let at = format!("{state} at t = {t:.2} s: {} — {} — {}", st.headline, st.detail, st.observed);

    // The CLI, over the same simulated time, says the same word.
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm"))
        .args(["simulate", "--state", state, "--duration", &format!("{t}"), "--json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{at}: {}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["verdict"].as_str(), Some(st.verdict), "{at}\nCLI: {v}");
    assert_eq!(v["headline"].as_str(), Some(st.headline), "{at}");
    assert_eq!(v["observed"].as_str(), Some(st.observed.as_str()), "{at}");

    // The headline's word is the verdict's.
    assert_eq!(st.headline.to_lowercase(), st.verdict, "{at}");
    // The readouts' observed rate is the observation line's.
    if let Some(g) = number_after(&st.observed, "observed growth rate ") {
        let readout = st.readouts.growth.replace('−', "-");
        assert!(readout.starts_with(&format!("{g:.2}")), "{at}: readout {}", st.readouts.growth);
    }
    // A reason is one the data support.
    let e = s.run(0).unwrap().closed_loop().snapshot().error;
    let far = e[0].abs().max(e[1].abs());
    if st.observed.contains("far from rest the arm is nonlinear") {
        assert!(far > 0.05, "{at}: blamed the nonlinearity at errors of {far} rad");
    }
    if st.observed.contains("matches ln ρ/δ") {
        let g = number_after(&st.observed, "observed growth rate ").unwrap();
        let p = number_after(&st.observed, "matches ln ρ/δ = ").unwrap();
        assert!((g - p).abs() <= 0.25 * p.abs().max(0.2) + 0.01, "{at}");
    }
    if st.observed.contains("too early to see it") {
        let p = st.growth_rate.unwrap();
        assert!(p.abs() * GROWTH_FIT_SPAN < 1.0, "{at}: a rate of {p} 1/s shows within the span fitted");
    }
    if st.observed.contains("dies out by e only") {
        assert!(st.spectral_radius.unwrap() < 1.0, "{at}: 'dies out' with ρ ≥ 1");
    }
    if st.verdict == "stable" {
        assert!(st.spectral_radius.is_none_or(|r| r < 1.0) || st.rho.contains("not this run's friction"), "{at}");
    }
    if st.rho.contains("not this run's friction") {
        assert!(!st.observed.contains("as ρ > 1 predicted") && !st.observed.contains("matches"), "{at}");
    }
}
