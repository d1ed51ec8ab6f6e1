//! The command line's inputs and interface (issue 34, items 7, 8, 9): one parser and one rule for
//! the state string, a limit with its reason on long work, every "set with --X" a flag the
//! command has, the work limit's variable checked, a list that starts with a minus sign read as
//! a list, the cross-parameter check blaming what was given, `--version`, and a short `--help`.

use std::io::Read;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use flexarm::schema::{self, Kind, PARAMS};
use flexarm::session::{Settings, Source};

/// No invocation here may take longer (a refusal is immediate; the runs are short).
const TIME_LIMIT: Duration = Duration::from_secs(20);

fn flexarm_env(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_flexarm"));
    c.args(args).env_remove("FLEXARM_WORK_LIMIT").stdout(Stdio::piped()).stderr(Stdio::piped());
    for (k, v) in env {
        c.env(k, v);
    }
    let mut child = c.spawn().expect("the flexarm binary runs");
    // Read both pipes while waiting, so that a long help never blocks on a full pipe.
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            let _ = pipe.read_to_end(&mut bytes);
            bytes
        })
    };
    let stdout = drain(Box::new(child.stdout.take().expect("piped")));
    let stderr = drain(Box::new(child.stderr.take().expect("piped")));
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("waits") {
            break status;
        }
        if started.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            panic!("flexarm {args:?} ran past {TIME_LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    Output { status, stdout: stdout.join().expect("read"), stderr: stderr.join().expect("read") }
}

fn flexarm(args: &[&str]) -> Output {
    flexarm_env(args, &[])
}

fn stdout_of(args: &[&str]) -> String {
    let out = flexarm(args);
    assert!(out.status.success(), "flexarm {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// A refusal: status 2, nothing on stdout, one `error:` line on stderr; returns that line.
fn refusal(args: &[&str], env: &[(&str, &str)]) -> String {
    let out = flexarm_env(args, env);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "flexarm {args:?} should be refused: {err}");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("error: "), "{err}");
    err
}

/// The commands that take `--state`, with what each needs besides.
const COMMANDS: &[(&str, &[&str])] = &[
    ("simulate", &["--duration", "0.1"]),
    ("analyze", &[]),
    ("sweep", &["--delta", "0.01", "--alpha", "2"]),
    ("map", &["--n-delta", "2", "--n-alpha", "2"]),
    ("export-python", &[]),
    ("data", &[]),
    ("figure", &["--panel", "errors", "--time", "0.1"]),
];

/// The long flags a command's help lists.
fn flags_in_help(command: &str) -> Vec<String> {
    stdout_of(&[command, "--help"])
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| w.starts_with("--") && w.len() > 2)
        .map(str::to_string)
        .collect()
}

/// The flags a refusal's "(set with --x or --y)" names.
fn hinted(err: &str) -> Vec<String> {
    let Some((_, rest)) = err.rsplit_once("(set with ") else { return Vec::new() };
    rest.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| w.starts_with("--"))
        .map(str::to_string)
        .collect()
}

/// A value every parameter refuses: beyond the hard limits, or not a choice.
fn bad_value(p: &schema::Param) -> String {
    match &p.kind {
        Kind::Number(n) => format!("{}", n.max * 10.0 + 1e9),
        _ => "bogus".into(),
    }
}

#[test]
fn every_hint_names_a_flag_the_command_has() {
    for (command, extra) in COMMANDS {
        let flags = flags_in_help(command);
        for p in PARAMS {
            let state = format!("{}={}", p.key, bad_value(p));
            let mut args = vec![*command, "--state", &state];
            args.extend_from_slice(extra);
            let err = refusal(&args, &[]);
            for flag in hinted(&err) {
                assert!(
                    flags.contains(&flag),
                    "flexarm {command} --state '{state}': {err} names {flag}, not a flag of it"
                );
            }
        }
    }
}

#[test]
fn a_moment_and_a_figures_time_have_the_schemas_limit_with_its_reason() {
    // The page's moment t= is limited to 120 s (schema::START_TIME), and so is --time.
    let max = schema::START_TIME.number().unwrap().max;
    assert_eq!(max, 120.0);
    for args in [
        &["figure", "--panel", "errors", "--time", "1e9"][..],
        &["figure", "--panel", "errors", "--state", "t=1e9"][..],
    ] {
        let err = refusal(args, &[]);
        assert!(err.contains("120 s") && err.contains("replayed from rest"), "{err}");
        assert!(err.contains("(set with --time)"), "{err}");
    }
    // Within the limit, a run that would take too long is estimated and refused, like any other.
    let err =
        refusal(&["figure", "--panel", "errors", "--delta", "1e-5", "--time", "10"], &[("FLEXARM_WORK_LIMIT", "0.5")]);
    assert!(err.contains("would take too long") && err.contains("--force"), "{err}");
}

#[test]
fn the_state_string_has_one_rule_on_the_command_line() {
    // A command-line option is not among the settings a state string lists as known…
    let err = refusal(&["analyze", "--state", "bogus=1"], &[]);
    for key in ["duration", "output_interval", "q2"] {
        assert!(!err.contains(&format!(" {key},")) && !err.ends_with(key), "{key} listed as known: {err}");
    }
    // …and is refused as the command line's, with its flag where the command has one.
    let err = refusal(&["simulate", "--state", "duration=10"], &[]);
    assert!(err.contains("command line's") && err.contains("(set with --duration)"), "{err}");
    let err = refusal(&["analyze", "--state", "duration=10"], &[]);
    assert!(!err.contains("--duration"), "analyze has no --duration: {err}");
    // The page's own keys are checked like any value…
    for bad in ["speed=abc", "zsize=-5", "t=-1", "compare=maybe", "views=nonsense"] {
        refusal(&["analyze", "--state", bad], &[]);
    }
    // …and, when good, set aside with a note that names them.
    let out = flexarm(&["analyze", "--state", "delta=0.02&speed=2&zsize=0.5", "--json"]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.starts_with("note: ") && err.contains("speed") && err.contains("zsize"), "{err}");
    // A key given twice is refused, as a flag given twice is.
    let err = refusal(&["analyze", "--state", "delta=0.01&alpha=2&delta=0.02"], &[]);
    assert!(err.contains("delta") && err.contains("twice"), "{err}");
    assert!(flexarm(&["analyze", "--delta", "0.01", "--delta", "0.02"]).status.code() == Some(2));
}

#[test]
fn the_page_keeps_reading_its_links_and_says_what_a_repeat_does() {
    // A link the page writes (run B, the view, a moment) reads back on the page without a
    // notice, and on the command line with only the set-aside notes.
    let mut s = Settings::page_start();
    s.read("compare=1&b_pf=lq&zsize=0.5&log=1&plane=z&t=3&paused=1&speed=2", Source::Page).unwrap();
    let link = format!("{}&t=3&paused=1", s.to_query());
    let mut back = Settings::page_start();
    assert!(back.read(&link, Source::Page).unwrap().is_empty(), "{link}");
    let mut cli = Settings::default();
    let notes = cli.read(&link, Source::CommandLine).unwrap();
    assert!(notes.iter().all(|n| n.text.contains("ignored")), "{notes:?}");
    assert_eq!(cli.a, s.a);
    // A repeat in a hand-edited link: the last value, with a notice saying so.
    let mut p = Settings::page_start();
    let notices = p.read("delta=0.01&delta=0.02", Source::Page).unwrap();
    assert_eq!(p.a.delta, 0.02);
    assert_eq!(notices.len(), 1);
    assert!(notices[0].text.contains("twice") && notices[0].text.contains("last"), "{}", notices[0].text);
    assert!(Settings::default().read("delta=0.01&delta=0.02", Source::Lesson).is_err());
}

#[test]
fn the_work_limits_variable_is_checked() {
    for bad in ["abc", "-5", "0", "inf"] {
        let err = refusal(&["analyze"], &[("FLEXARM_WORK_LIMIT", bad)]);
        assert!(err.contains("FLEXARM_WORK_LIMIT"), "{err}");
    }
    assert!(flexarm_env(&["analyze"], &[("FLEXARM_WORK_LIMIT", "30")]).status.success());
}

#[test]
fn a_list_may_start_with_a_minus_sign_and_is_refused_by_the_range() {
    let err = refusal(&["sweep", "--delta", "0.01", "--alpha", "-1,2"], &[]);
    assert!(err.contains("α1") && err.contains("must be from 0.001") && err.contains("--alpha"), "{err}");
    let err = refusal(&["sweep", "--delta", "-0.01:0.1:3", "--alpha", "2"], &[]);
    assert!(err.contains("δ") && err.contains("--delta"), "{err}");
    // So do the other pairs: a range, a mark, a pole to place.
    for (args, flag) in
        [(&["map", "--delta-range", "-0.01:0.1"][..], "--delta-range"), (&["map", "--mark", "-0.01:2"][..], "--mark")]
    {
        let err = refusal(args, &[]);
        assert!(err.contains(flag) && !err.contains("unexpected argument"), "{err}");
    }
    // A4 at −2.6 ± 29.6j: a pole in the left half-plane is written with a minus sign.
    let out = flexarm(&["analyze", "--place", "-2.6,29.6"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn the_mass_matrix_check_blames_the_setting_given() {
    // A1 A2 − A2² < 0 for A1 = 0.01 < A2 = 0.247: no A3 makes the mass matrix positive definite.
    for args in [&["analyze", "--a1", "0.01"][..], &["analyze", "--state", "a1=0.01"][..]] {
        let err = refusal(args, &[]);
        assert!(err.contains("invalid a1 (A1) = 0.01") && err.contains("(set with --a1)"), "{err}");
        assert!(err.contains("A3² < A1·A2 − A2²"), "{err}");
    }
    let err = refusal(&["analyze", "--a3", "3"], &[]);
    assert!(err.contains("invalid a3 (A3) = 3") && err.contains("(set with --a3)"), "{err}");
}

#[test]
fn version_and_a_short_help() {
    for flag in ["--version", "-V"] {
        assert_eq!(stdout_of(&[flag]).trim(), format!("flexarm {}", env!("CARGO_PKG_VERSION")));
    }
    let short = stdout_of(&["--help"]);
    assert_eq!(short, stdout_of(&["help"]));
    assert!(short.lines().count() < 60, "{} lines", short.lines().count());
    for command in ["simulate", "analyze", "sweep", "map", "export-python", "data", "figure", "bundle"] {
        assert!(short.contains(command), "{command}");
        // `--help` and `help COMMAND` are the long form; `-h` lists the same flags in short.
        let long = stdout_of(&[command, "--help"]);
        assert_eq!(long, stdout_of(&["help", command]), "{command}");
        let brief = stdout_of(&[command, "-h"]);
        assert!(brief.len() <= long.len(), "{command}");
        for flag in flags_in_help(command) {
            assert!(brief.contains(&flag), "{command} -h lacks {flag}");
        }
    }
    let all = stdout_of(&["help", "all"]);
    for flag in ["--delta-range", "--q2", "--panel", "--output-interval"] {
        assert!(all.contains(flag), "help all lacks {flag}");
    }
}
