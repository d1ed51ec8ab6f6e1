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
    assert_eq!(v["pf"], "off");
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
    // The first line names the settings as a state string (issue 8); the data follow.
    let mut lines = csv.lines().skip_while(|l| l.starts_with('#'));
    assert!(csv.starts_with("# flexarm state: delta=0.01&"), "{}", &csv[..80.min(csv.len())]);
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
fn an_unwritable_output_path_is_bad_input() {
    let out = flexarm(&["simulate", "--duration", "0.1", "--csv", "/nonexistent-dir/flexarm/x.csv"]);
    assert_eq!(out.status.code(), Some(2));
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
    assert_eq!(num(&rows[3], "alpha1"), 2.0);
}

#[test]
fn help_lists_every_command_and_flag() {
    // `flexarm help all` is the reference of every command; `--help` is the short overview.
    for args in [&["help", "all"][..]] {
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
        (&["simulate", "--k", "0"], &["k (horizon", "--k"]),
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

// --------------------------------------------------------------------------------------- map, svg

/// A temporary file name for this test process.
fn temp_file(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("flexarm-cli-test-{}-{name}", std::process::id()))
}

/// Runs a command that must fail with status 2 and one `error:` line mentioning `mentions`.
fn assert_usage_error(args: &[&str], mentions: &[&str]) {
    let out = flexarm(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "flexarm {args:?}: {stderr}");
    assert!(stderr.starts_with("error:"), "flexarm {args:?}: {stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "one line: {stderr}");
    assert!(mentions.iter().all(|m| stderr.contains(m)), "flexarm {args:?} should mention {mentions:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(out.stdout.is_empty(), "nothing on stdout for {args:?}");
}

#[test]
fn map_json_has_one_grid_per_preliminary_feedback() {
    let v = json_of(&["map", "--n-delta", "12", "--n-alpha", "4", "--json"]);
    let object = v.as_object().expect("one JSON object");
    assert_eq!(object.keys().collect::<Vec<_>>(), ["off", "paper"], "--pf both is the default");
    for (pf, m) in object {
        assert_eq!(m["pf"], pf.as_str());
        let deltas = m["sampling_periods"].as_array().unwrap();
        let alphas = m["alphas"].as_array().unwrap();
        let rho = m["spectral_radius"].as_array().unwrap();
        assert_eq!((deltas.len(), alphas.len(), rho.len()), (12, 4, 48), "{pf}");
        assert!(rho.iter().all(|r| r.as_f64().is_some_and(|r| r.is_finite() && r > 0.0)), "{pf}: {rho:?}");
        // The default grid: δ 2 ms – 0.25 s and α 0.1 – 5 1/s, logarithmic.
        let d: Vec<f64> = deltas.iter().map(|x| x.as_f64().unwrap()).collect();
        assert!((d[0] - 0.002).abs() < 1e-15 && (d[11] - 0.25).abs() < 1e-12, "{d:?}");
        assert!(((d[1] / d[0]) - (d[11] / d[10])).abs() < 1e-9, "log-spaced: {d:?}");
        assert!((alphas[0].as_f64().unwrap() - 0.1).abs() < 1e-15 && (alphas[3].as_f64().unwrap() - 5.0).abs() < 1e-12);
        let fraction = num(m, "stable_fraction");
        let stable = rho.iter().filter(|r| r.as_f64().unwrap() < 1.0).count();
        assert!((fraction - stable as f64 / 48.0).abs() < 1e-12, "{pf}: {fraction}");
        assert!(m["stable_delta_intervals"].is_array());
    }
    // The paper's feedback stabilizes more of the grid.
    assert!(num(&v["paper"], "stable_fraction") > num(&v["off"], "stable_fraction"), "{v}");
    let single = json_of(&["map", "--n-delta", "3", "--n-alpha", "2", "--pf", "lq", "--json"]);
    assert_eq!(single.as_object().unwrap().keys().collect::<Vec<_>>(), ["lq"]);
}

#[test]
fn map_summary_names_the_stable_window_at_alpha_2() {
    let text = stdout_of(&["map", "--n-delta", "60", "--n-alpha", "10"]);
    assert!(text.contains("PF off") && text.contains("PF paper") && text.contains("% of the cells stable"), "{text}");
    // "PF off, α = 2.09 1/s: stable for δ in [0.0349, 0.1], ... s": the window opens near 35 ms.
    let line = text.lines().find(|l| l.starts_with("PF off, α = ")).unwrap_or_else(|| panic!("{text}"));
    let first = line.split("stable for δ in [").nth(1).unwrap_or_else(|| panic!("{line}"));
    let (lo, rest) = first.split_once(", ").unwrap();
    let hi = rest.split(']').next().unwrap();
    let (lo, hi): (f64, f64) = (lo.parse().unwrap(), hi.parse().unwrap());
    assert!((0.025..0.05).contains(&lo) && (0.08..0.13).contains(&hi), "{line}");
    let paper = text.lines().find(|l| l.starts_with("PF paper, α = ")).unwrap();
    assert!(paper.contains("stable for δ in [0.002, "), "with K_pr stable from the smallest δ: {paper}");
}

#[test]
fn map_csv_is_long_format_with_units() {
    let path = temp_file("map.csv");
    let path_str = path.to_str().unwrap();
    let text = stdout_of(&["map", "--n-delta", "12", "--n-alpha", "4", "--pf", "both", "--csv", path_str]);
    assert!(text.contains(path_str), "{text}");
    let csv = std::fs::read_to_string(&path).expect("CSV written");
    std::fs::remove_file(&path).ok();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("pf,delta [s],alpha [1/s],rho,verdict"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2 * 48);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row.len(), 5, "{row:?}");
        assert_eq!(row[0], if k < 48 { "off" } else { "paper" });
        let [delta, alpha, rho]: [f64; 3] = [1, 2, 3].map(|i| row[i].parse().unwrap_or_else(|_| panic!("{row:?}")));
        assert!((0.002 - 1e-12..=0.25 + 1e-12).contains(&delta) && (0.1 - 1e-12..=5.0 + 1e-12).contains(&alpha));
        // ρ's verdict by its rate ln ρ/δ: borderline within ±0.05 1/s.
        let rate = rho.ln() / delta;
        let verdict = if rate > 0.05 {
            "unstable"
        } else if rate < -0.05 {
            "stable"
        } else {
            "borderline"
        };
        assert_eq!(row[4], verdict, "{row:?}");
    }
}

#[test]
fn map_and_simulate_write_svg_figures() {
    let path = temp_file("map.svg");
    let path_str = path.to_str().unwrap();
    let text = stdout_of(&["map", "--n-delta", "12", "--n-alpha", "4", "--svg", path_str, "--mark", "0.01:2"]);
    assert!(text.contains(path_str), "{text}");
    let svg = std::fs::read_to_string(&path).expect("SVG written");
    std::fs::remove_file(&path).ok();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // The axes with their units, the colour bar, which map is which, the point marked.
    for needle in ["δ [s]", "α [1/s]", "<linearGradient", "no Kₚᵣ", "paper Kₚᵣ", "marked: δ = 0.01 s, α = 2 1/s"]
    {
        assert!(svg.contains(needle), "the map figure lacks {needle}");
    }
    assert!(!svg.contains("NaN") && !svg.contains("inf"));

    let path = temp_file("traces.svg");
    let path_str = path.to_str().unwrap();
    let text = stdout_of(&["simulate", "--pf", "off", "--duration", "2", "--svg", path_str]);
    assert!(text.contains(path_str), "{text}");
    let svg = std::fs::read_to_string(&path).expect("SVG written");
    std::fs::remove_file(&path).ok();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    for needle in ["t [s]", "e1 [", "e2 [", "δ = 0.01 s", "PF off"] {
        assert!(svg.contains(needle), "the traces figure lacks {needle}");
    }
    // With --json stdout stays one JSON object.
    let path = temp_file("traces-json.svg");
    json_of(&["simulate", "--duration", "0.5", "--json", "--svg", path.to_str().unwrap()]);
    assert!(std::fs::read_to_string(&path).unwrap().starts_with("<svg"));
    std::fs::remove_file(&path).ok();

    // A path that cannot be written is bad input, like any other argument.
    let out = flexarm(&["map", "--n-delta", "2", "--n-alpha", "2", "--svg", "/nonexistent-dir/flexarm/x.svg"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("error:"));
}

#[test]
fn map_bad_input_fails_cleanly_with_status_2() {
    assert_usage_error(&["map", "--delta-range", "0.1:0.01"], &["--delta-range", "0.1:0.01"]);
    assert_usage_error(&["map", "--delta-range", "0:0.1"], &["--delta-range"]);
    assert_usage_error(&["map", "--delta-range", "0.01"], &["--delta-range"]);
    assert_usage_error(&["map", "--delta-range", "0.01:20"], &["--delta-range", "10 s"]);
    assert_usage_error(&["map", "--alpha-range", "1:x"], &["--alpha-range"]);
    assert_usage_error(&["map", "--n-delta", "1"], &["--n-delta"]);
    assert_usage_error(&["map", "--n-alpha", "abc"], &["--n-alpha", "abc"]);
    assert_usage_error(&["map", "--n-alpha"], &["--n-alpha"]);
    assert_usage_error(&["map", "--pf", "maybe"], &["--pf", "both"]);
    assert_usage_error(&["map", "--delta", "0.01"], &["--delta-range"]);
    assert_usage_error(&["map", "--alpha", "2"], &["--alpha-range"]);
    assert_usage_error(&["map", "--mark", "0.01"], &["--mark"]);
    assert_usage_error(&["map", "--k", "2"], &["--k"]);
    assert_usage_error(&["map", "--duration", "2"], &["--duration", "map"]);
}

#[test]
fn help_describes_map_and_svg() {
    let text = stdout_of(&["help", "all"]);
    for word in ["map", "--delta-range", "--alpha-range", "--n-delta", "--n-alpha", "both", "--svg", "--mark"] {
        assert!(text.contains(word), "help lacks {word}");
    }
    // Each command has its own help (issue 8): map's lists map's flags.
    let map_help = stdout_of(&["map", "--help"]);
    for word in ["--delta-range", "--n-alpha", "--svg", "--mark", "both"] {
        assert!(map_help.contains(word), "map --help lacks {word}");
    }
    assert!(!map_help.contains("--output-interval"), "map --help is map's alone");
}

// ------------------------------------------------------------------ the page's state string

#[test]
fn the_pages_command_line_and_state_string_run_the_same_settings() {
    use flexarm::session::{Settings, Source};
    let mut settings = Settings::page_start();
    settings
        .read("delta=0.04&alpha1=1&alpha2=1.5&pf=lq&friction=held&inner=sampled&k=10&eps_ratio=6", Source::Page)
        .unwrap();
    // "Copy as command line" gives these words; the CLI runs exactly these settings.
    let command = settings.command_line(Some(1.0));
    let words: Vec<&str> = command.split(' ').skip(1).chain(["--json"]).collect();
    let v = json_of(&words);
    assert_eq!(v["state"], settings.run_query(), "{command}");
    assert_eq!((num(&v, "delta"), num(&v, "alpha1"), num(&v, "alpha2"), num(&v, "duration")), (0.04, 1.0, 1.5, 1.0));
    assert_eq!(
        (v["pf"].as_str(), v["friction"].as_str(), v["inner"].as_str()),
        (Some("lq"), Some("held"), Some("sampled"))
    );
    assert_eq!(v["repeat"], true);
    // The page's URL query works as --state; flags given as well override it.
    let query = settings.to_query();
    let v = json_of(&["simulate", "--state", &query, "--duration", "1", "--json"]);
    assert_eq!(v["state"], settings.run_query());
    let v = json_of(&["simulate", "--state", &query, "--delta", "0.02", "--duration", "0.5", "--json"]);
    assert_eq!(num(&v, "delta"), 0.02);
    // A bad state string is one line naming the problem, status 2.
    assert_usage_error(&["simulate", "--state", "delta=oops"], &["--state", "delta", "oops"]);
    assert_usage_error(&["analyze", "--state", "bogus=1"], &["--state", "bogus"]);
}

/// Issue 32: `analyze --place RE,IM` finds the twist gains that put A4 there (read back from the
/// analysis of the loop with them), and refuses a pair no damper in range reaches, saying why.
#[test]
fn analyze_places_the_pair_with_the_twist_feedback() {
    for (alpha, target) in [("2", [-2.6, 29.6]), ("5", [-2.0, 29.0])] {
        let place = format!("--place={},{}", target[0], target[1]);
        let v = json_of(&["analyze", "--alpha", alpha, &place, "--json"]);
        let pair = &v["limit_pair"][0];
        for (got, want) in [(pair[0].as_f64().unwrap(), target[0]), (pair[1].as_f64().unwrap(), target[1])] {
            assert!((got - want).abs() < 1e-6 * 30.0, "α = {alpha}: A4 {pair} vs {target:?}");
        }
        assert_eq!(v["pf"], "twist");
        let state = v["state"].as_str().unwrap();
        assert!(state.contains("pf=twist") && state.contains("twist_damping="), "{state}");
    }
    // A pair to the right of where the controller puts it needs negative damping.
    assert_usage_error(&["analyze", "--place=8,29.6"], &["k_d", "≥ 0"]);
    assert_usage_error(&["analyze", "--place=abc"], &["RE,IM"]);
}
