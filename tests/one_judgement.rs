//! One ρ, one judgement, one wording (issue 34): `analyze` (text and JSON), `simulate` (text and
//! JSON), `sweep` (with and without `--simulate`) and the page's status give a state the same
//! verdict word — the one ρ states by its rate ln ρ/δ: borderline within
//! ±[`UNSTABLE_GROWTH_RATE`] 1/s, where the errors change by e only every 20 s or more; unstable
//! above, stable below. Also: every command's JSON writes each setting once, under the schema's
//! key; and `analyze --json` exports A4 and how the torque enters it.

mod common;

use std::process::Command;

use flexarm::control::metrics::UNSTABLE_GROWTH_RATE;
use serde_json::Value;

fn flexarm(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().unwrap();
    assert!(out.status.success(), "flexarm {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap()
}

fn json(args: &[&str]) -> Value {
    let text = flexarm(args);
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("flexarm {args:?}: not JSON ({e}): {text}"))
}

/// The word after `label` up to the next ':' on the line that starts with it (trimmed), lowercase.
fn word_after(text: &str, label: &str) -> String {
    let line = text.lines().map(str::trim_start).find(|l| l.starts_with(label)).unwrap_or_else(|| {
        panic!("no line starting '{label}' in\n{text}");
    });
    let rest = line[label.len()..].trim_start();
    rest.split(':').next().unwrap().trim().to_lowercase()
}

/// States around ρ = 1 at δ = 2 ms without K_pr (α moves Re A4 by 3/2 per 1/s), and three far from it.
const STATES: [(&str, &str, &str); 7] = [
    ("0.002", "0.25", "off"), // ρ = 1.000026 > 1 inside the band (the case)
    ("0.002", "0.18", "off"), // ln ρ/δ ≈ −0.09: stable, just outside the band
    ("0.002", "0.22", "off"), // ρ < 1 inside the band
    ("0.002", "0.28", "off"), // ln ρ/δ ≈ 0.058: unstable, just outside
    ("0.01", "2", "off"),     // ρ = 1.0239: clearly unstable
    ("0.01", "2", "paper"),   // clearly stable
    ("0.05", "2", "paper"),   // the paper's K_pr at 50 ms: stable
];

/// The verdict ρ states, computed here from ρ and δ by the rule (not by the program's function).
fn expected(rho: f64, delta: f64) -> &'static str {
    let rate = rho.ln() / delta;
    if rate > UNSTABLE_GROWTH_RATE {
        "unstable"
    } else if rate < -UNSTABLE_GROWTH_RATE {
        "stable"
    } else {
        "borderline"
    }
}

#[test]
fn analyze_simulate_sweep_and_the_page_judge_one_rho_alike() {
    let mut words = Vec::new();
    for (delta, alpha, pf) in STATES {
        let at = format!("δ = {delta}, α = {alpha}, pf = {pf}");
        let flags = ["--delta", delta, "--alpha", alpha, "--pf", pf];
        let analyze = json(&[&["analyze", "--json"][..], &flags].concat());
        let rho = analyze["spectral_radius"].as_f64().unwrap();
        let word = expected(rho, delta.parse().unwrap());
        words.push(word);
        assert_eq!(analyze["verdict"], word, "{at}: analyze --json (ρ = {rho})");
        assert_eq!(analyze["headline"].as_str().map(str::to_lowercase).as_deref(), Some(word), "{at}");
        let text = flexarm(&[&["analyze"][..], &flags].concat());
        assert_eq!(word_after(&text, "verdict:"), word, "{at}: analyze\n{text}");

        let run = [&["simulate", "--duration", "2"][..], &flags].concat();
        let sim = json(&[&run[..], &["--json"]].concat());
        assert_eq!(sim["verdict"], word, "{at}: simulate --json: {}", sim["detail"]);
        let text = flexarm(&run);
        assert_eq!(word_after(&text, "verdict"), word, "{at}: simulate\n{text}");

        let sweep =
            [&["sweep", "--delta", delta, "--alpha", alpha, "--pf", pf, "--simulate", "--duration", "2"][..]].concat();
        let rows = json(&[&sweep[..], &["--json"]].concat());
        assert_eq!(rows[0]["verdict"], word, "{at}: sweep's linear verdict");
        assert_eq!(rows[0]["simulation"]["verdict"], word, "{at}: sweep --simulate");
        let text = flexarm(&sweep);
        let cells: Vec<&str> = text.lines().nth(1).unwrap().split_whitespace().collect();
        assert_eq!((cells[3], cells[4]), (word, word), "{at}: sweep's table\n{text}");
        let text = flexarm(&["sweep", "--delta", delta, "--alpha", alpha, "--pf", pf]);
        assert_eq!(text.lines().nth(1).unwrap().split_whitespace().nth(3), Some(word), "{at}\n{text}");

        // The page: the session's status after the same 2 s.
        let mut s = common::session(&format!("delta={delta}&alpha={alpha}&pf={pf}"));
        common::play(&mut s, 2.0);
        assert_eq!(s.status().runs[0].verdict, word, "{at}: the page");
    }
    assert_eq!(words, ["borderline", "stable", "borderline", "unstable", "unstable", "stable", "stable"]);
}

/// The ρ line reads as one statement: ρ against 1 in the direction of the verdict, and the e-fold
/// time 1/|ln ρ/δ| it implies (never "→ unstable (ρ < 1 ⇒ linearly stable)").
#[test]
fn analyze_says_rho_against_one_the_way_the_verdict_goes() {
    for (delta, alpha, pf) in STATES {
        let text = flexarm(&["analyze", "--delta", delta, "--alpha", alpha, "--pf", pf]);
        let line = text.lines().find(|l| l.starts_with("verdict: ")).unwrap();
        let v = json(&["analyze", "--delta", delta, "--alpha", alpha, "--pf", pf, "--json"]);
        let rate = v["growth_rate"].as_f64().unwrap();
        let (relation, grows) = match v["verdict"].as_str().unwrap() {
            "unstable" => ("> 1", "grow"),
            "stable" => ("< 1", "shrink"),
            _ => ("≈ 1", "change too slowly to see"),
        };
        assert!(line.contains(relation) && line.contains(grows), "{line}");
        let e_fold = 1.0 / rate.abs();
        let digits = if e_fold >= 10.0 { format!("{e_fold:.0}") } else { format!("{e_fold:.2}") };
        let shown: f64 = line.split("e-fold every ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
        assert!((shown - e_fold).abs() <= 0.05 * e_fold, "{line}: 1/|ln ρ/δ| = {digits} s");
        assert!(!text.contains("⇒ linearly stable"), "{text}");
    }
    // The README quotes the line as `analyze --pf off` prints it.
    let text = flexarm(&["analyze", "--pf", "off"]);
    let line = text.lines().find(|l| l.starts_with("verdict: ")).unwrap();
    let readme = include_str!("../README.md").split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(readme.contains(&format!("`--pf off`: `{line}`")), "README should quote {line:?}");
}
