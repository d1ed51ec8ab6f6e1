//! End-to-end tests of the `flexarm` command-line program: JSON output, CSV traces, the paper's
//! stability findings through the CLI, and clean failures on bad input.

use std::process::{Command, Output};

use serde_json::Value;

fn flexarm(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().expect("the flexarm binary runs")
}

/// Runs a command that must succeed and returns its stdout.
fn stdout_of(args: &[&str]) -> String {
    let out = flexarm(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "flexarm {args:?} failed with {:?}: {stderr}", out.status);
    String::from_utf8(out.stdout).expect("stdout is UTF-8")
}

/// Runs a command that must print exactly one JSON value.
fn json_of(args: &[&str]) -> Value {
    let text = stdout_of(args);
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("flexarm {args:?} printed invalid JSON ({e}): {text}"))
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("'{key}' is not a number in {v}"))
}

#[test]
fn simulate_without_preliminary_feedback_is_unstable_at_10_ms() {
    let v = json_of(&["simulate", "--delta", "0.01", "--pf", "off", "--duration", "6", "--json"]);
    let verdict = v["verdict"].as_str().unwrap();
    assert!(verdict == "unstable" || verdict == "diverged", "verdict {verdict}");
    assert!(num(&v, "spectral_radius") > 1.0, "{v}");
    assert_eq!(v["preliminary_feedback"], "off");
    assert_eq!(num(&v, "delta"), 0.01);
    if verdict == "diverged" {
        assert!(num(&v, "diverged_at") > 0.0);
        assert!(v["divergence_reason"].is_string());
    }
}

#[test]
fn simulate_with_paper_feedback_is_stable_at_10_ms() {
    let v = json_of(&["simulate", "--delta", "0.01", "--pf", "paper", "--duration", "6", "--json"]);
    assert_eq!(v["verdict"], "stable", "{v}");
    assert!(num(&v, "spectral_radius") < 1.0, "{v}");
    assert!(v["diverged_at"].is_null() && v["divergence_reason"].is_null());
    for key in ["alpha1", "alpha2", "k", "eps_ratio", "duration"] {
        num(&v, key);
    }
    for key in ["max_error_slew", "max_error_after", "rms_error", "max_torque"] {
        let pair = v[key].as_array().unwrap_or_else(|| panic!("'{key}' is not an array"));
        assert_eq!(pair.len(), 2);
        assert!(pair.iter().all(|x| x.as_f64().is_some_and(|x| x.is_finite() && x >= 0.0)), "{key}: {pair:?}");
    }
    // Tracking within a few milliradians, as in the paper's plots.
    assert!(v["max_error_slew"].as_array().unwrap().iter().all(|x| x.as_f64().unwrap() < 1e-2));
}

#[test]
fn simulate_text_summary_names_the_verdict_and_rho() {
    let text = stdout_of(&["simulate", "--duration", "2"]);
    assert!(text.contains("stable"), "{text}");
    assert!(text.contains("ρ"), "{text}");
    assert!(text.contains("rad"), "{text}");
}

#[test]
fn csv_has_a_header_with_units_and_numeric_rows() {
    let path = std::env::temp_dir().join(format!("flexarm-cli-test-{}.csv", std::process::id()));
    let path_str = path.to_str().unwrap();
    let text = stdout_of(&["simulate", "--duration", "1.5", "--csv", path_str]);
    assert!(text.contains(path_str), "the summary says where the CSV went: {text}");
    let csv = std::fs::read_to_string(&path).expect("CSV written");
    std::fs::remove_file(&path).ok();
    let mut lines = csv.lines();
    let header = lines.next().expect("header line");
    assert!(header.contains("t [s]") && header.contains("e1 [rad]"), "header: {header}");
    let width = header.split(',').count();
    let mut rows = 0;
    for line in lines {
        let fields: Vec<f64> =
            line.split(',').map(|f| f.parse().unwrap_or_else(|_| panic!("bad field in {line}"))).collect();
        assert_eq!(fields.len(), width);
        rows += 1;
    }
    // 1.5 s at the default 2 ms spacing, plus the initial sample.
    assert!(rows >= 700, "{rows} rows");
}

#[test]
fn csv_write_failure_exits_with_1() {
    let out = flexarm(&["simulate", "--duration", "0.1", "--csv", "/nonexistent-dir/flexarm/x.csv"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("error:"));
}

#[test]
fn analyze_reports_the_paper_limit_pair() {
    let v = json_of(&["analyze", "--json"]);
    let open = &v["limit_pair_open"][0];
    let (re, im) = (open[0].as_f64().unwrap(), open[1].as_f64().unwrap().abs());
    // Paper: 2.63 ± 29.58j.
    assert!((re - 2.64).abs() / 2.64 < 0.01, "Re = {re}");
    assert!((im - 29.58).abs() / 29.58 < 0.01, "Im = {im}");
    assert!(num(&v, "spectral_radius") < 1.0);
    assert_eq!(v["verdict"], "stable");
    assert_eq!(v["poles"].as_array().unwrap().len(), 10);
    // With the paper's K_pr the pair is reflected into the left half-plane.
    assert!(v["limit_pair"][0][0].as_f64().unwrap() < 0.0);
}

#[test]
fn analyze_text_lists_the_eigenvalues() {
    let text = stdout_of(&["analyze", "--pf", "off"]);
    assert!(text.contains("unstable"), "{text}");
    assert!(text.contains("A4"), "{text}");
    assert!(text.contains("29.58"), "{text}");
}

#[test]
fn sweep_shows_large_delta_stable_and_small_delta_unstable_without_pf() {
    let v = json_of(&["sweep", "--delta", "0.01,0.04", "--alpha", "2", "--pf", "off", "--json"]);
    let rows = v.as_array().expect("an array");
    assert_eq!(rows.len(), 2);
    assert_eq!(num(&rows[0], "delta"), 0.01);
    assert_eq!(rows[0]["verdict"], "unstable");
    assert!(num(&rows[0], "spectral_radius") > 1.0);
    assert_eq!(num(&rows[1], "delta"), 0.04);
    assert_eq!(rows[1]["verdict"], "stable");
    assert!(num(&rows[1], "spectral_radius") < 1.0);
}

#[test]
fn sweep_range_is_log_spaced() {
    let v = json_of(&["sweep", "--delta", "0.001:0.1:3", "--alpha", "1,2", "--json"]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 6);
    let deltas: Vec<f64> = rows[..3].iter().map(|r| num(r, "delta")).collect();
    for (got, want) in deltas.iter().zip([0.001, 0.01, 0.1]) {
        assert!((got - want).abs() < 1e-12 * want.max(1.0), "{deltas:?}");
    }
    assert_eq!(num(&rows[3], "alpha"), 2.0);
}

#[test]
fn help_lists_every_command_and_flag() {
    for args in [&["--help"][..], &["help"][..]] {
        let text = stdout_of(args);
        for word in [
            "simulate",
            "analyze",
            "sweep",
            "--delta",
            "--alpha1",
            "--k",
            "--eps-ratio",
            "--pf",
            "--inner",
            "--friction",
            "--duration",
            "--output-interval",
            "--csv",
            "--json",
            "--q2",
            "--simulate",
        ] {
            assert!(text.contains(word), "help lacks {word}");
        }
    }
}

#[test]
fn bad_input_fails_cleanly_with_status_2() {
    let cases: [(&[&str], &[&str]); 9] = [
        (&["simulate", "--delta", "-1"], &["δ", "sampling_period", "--delta"]),
        (&["simulate", "--pf", "maybe"], &["--pf"]),
        (&["simulate", "--k", "2"], &["k (horizon", "--k"]),
        (&["simulate", "--bogus"], &["--bogus"]),
        (&["frobnicate"], &["frobnicate"]),
        (&["simulate", "--delta"], &["--delta"]),
        (&["simulate", "--delta", "abc"], &["--delta"]),
        (&["simulate", "--duration", "-2"], &["duration"]),
        (&["sweep", "--delta", "0.01,x", "--alpha", "2"], &["--delta"]),
    ];
    for (args, mentions) in cases {
        let out = flexarm(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "flexarm {args:?}: {stderr}");
        assert!(stderr.starts_with("error:"), "flexarm {args:?}: {stderr}");
        assert_eq!(stderr.trim_end().lines().count(), 1, "one line: {stderr}");
        assert!(mentions.iter().all(|m| stderr.contains(m)), "flexarm {args:?} should mention {mentions:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(out.stdout.is_empty(), "nothing on stdout for {args:?}");
    }
    // The allowed values are named.
    let out = flexarm(&["simulate", "--pf", "maybe"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("off") && stderr.contains("paper") && stderr.contains("lq"), "{stderr}");
}
