//! The command line under random arguments (proptest): bad flags, hostile values and unwritable
//! paths never panic or hang. Every invocation ends within 20 s; one that fails prints exactly
//! one `error: ...` line on stderr and exits with status 2 (1 only for a failed analysis).

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::test_runner::{Config as ProptestConfig, RngSeed, TestCaseError, TestRunner};

/// No invocation may take longer.
const TIME_LIMIT: Duration = Duration::from_secs(20);

const COMMANDS: &[&str] = &["simulate", "analyze", "sweep", "map", "data", "help", "", "simulat", "--help", "-h"];

/// Every flag of every command, some misspelt, some of other commands.
const FLAGS: &[&str] = &[
    "--delta",
    "--alpha",
    "--alpha1",
    "--alpha2",
    "--pf",
    "--friction",
    "--inner",
    "--repeat",
    "--k",
    "--eps-ratio",
    "--duration",
    "--output-interval",
    "--csv",
    "--svg",
    "--json",
    "--state",
    "--q2",
    "--simulate",
    "--delta-range",
    "--alpha-range",
    "--n-delta",
    "--n-alpha",
    "--mark",
    "--help",
    "--force",
    "--no-maps",
    "--output",
    "--deltaa",
    "-d",
    "--",
    "---",
    "--speed",
    "--compare",
];

/// Values meant to break things: non-numbers, extremes, injections, paths that cannot be written.
const VALUES: &[&str] = &[
    "",
    " ",
    "0",
    "-0",
    "-1",
    "1e-300",
    "1e-9",
    "1e-5",
    "0.01",
    "0.04",
    "2",
    "10",
    "11",
    "1e6",
    "1e308",
    "1e309",
    "-1e308",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "infinity",
    "0x10",
    "1,2",
    "1:2",
    "1:2:3",
    "1e-5:10:10000",
    "0.1:10:10000",
    "2000",
    "2001",
    "abc",
    "off",
    "paper",
    "lq",
    "both",
    "held",
    "sampled",
    "continuous",
    "1",
    "true",
    "٣",
    "１",
    "δ",
    "'; rm -rf /",
    "$(touch /tmp/flexarm-pwned)",
    "<script>alert(1)</script>",
    "%s%n%x",
    "delta=1e-300",
    "delta=0.01&pf=lq&k=999999",
    "a=b&&&=",
    "/nonexistent-dir/x/y.csv",
    "/proc/version",
    "/",
    "/dev/full",
    ".",
    "..",
];

fn arguments() -> impl Strategy<Value = Vec<String>> {
    let value = prop_oneof![
        4 => proptest::sample::select(VALUES).prop_map(String::from),
        1 => "[ -~]{0,40}",
        1 => Just("9".repeat(10_000)),
    ];
    let flag_and_value = (proptest::sample::select(FLAGS), proptest::option::of(value));
    (proptest::sample::select(COMMANDS), proptest::collection::vec(flag_and_value, 0..5)).prop_map(|(c, flags)| {
        let mut args = vec![c.to_string()];
        for (f, v) in flags {
            args.push(f.to_string());
            args.extend(v);
        }
        args
    })
}

/// Runs flexarm with `args`, killing it after [`TIME_LIMIT`]. Returns (status, stdout, stderr,
/// seconds) or an error if it had to be killed.
fn run(args: &[String]) -> Result<(Option<i32>, String, String, f64), String> {
    let started = Instant::now();
    // Files named by random values ("--csv 2") land in a scratch folder, not in the checkout.
    let scratch = std::env::temp_dir().join(format!("flexarm-cli-arguments-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).map_err(|e| e.to_string())?;
    let mut child = Command::new(env!("CARGO_BIN_EXE_flexarm"))
        .args(args)
        .current_dir(&scratch)
        // The test's own limit on work (the default is a minute): nothing valid runs long here.
        .env("FLEXARM_WORK_LIMIT", "5")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let (mut out, mut err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let reader = std::thread::spawn(move || {
        let (mut o, mut e) = (Vec::new(), Vec::new());
        let _ = out.read_to_end(&mut o);
        let _ = err.read_to_end(&mut e);
        (o, e)
    });
    loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            let (o, e) = reader.join().unwrap();
            let text = |b: Vec<u8>| String::from_utf8_lossy(&b).into_owned();
            return Ok((status.code(), text(o), text(e), started.elapsed().as_secs_f64()));
        }
        if started.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("flexarm {args:?} did not finish within {TIME_LIMIT:?}"));
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// 400 random argument lists; prints how many succeeded, were refused, and the slowest.
#[test]
fn random_arguments_fail_in_one_line_or_succeed_never_panic_nor_hang() {
    let config = ProptestConfig {
        cases: 400,
        rng_seed: RngSeed::Fixed(1994),
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    let tally = std::cell::RefCell::new((0u32, 0u32, 0.0f64));
    let result = TestRunner::new(config).run(&arguments(), |args| {
        let (status, stdout, stderr, seconds) = run(&args).map_err(TestCaseError::fail)?;
        prop_assert!(!stderr.contains("panicked") && !stderr.contains("RUST_BACKTRACE"), "{args:?}: {stderr}");
        let mut t = tally.borrow_mut();
        t.2 = t.2.max(seconds);
        match status {
            Some(0) => {
                // Success: output, and on stderr at most progress lines.
                t.0 += 1;
                prop_assert!(!stdout.is_empty(), "{args:?}: no output");
                prop_assert!(stderr.lines().all(|l| l.contains(" %, ")), "{args:?}: {stderr}");
            }
            Some(code @ (1 | 2)) => {
                t.1 += 1;
                let lines: Vec<&str> = stderr.lines().filter(|l| !l.contains(" %, ")).collect();
                prop_assert_eq!(lines.len(), 1, "{:?}: one line expected, got {}", args, stderr);
                prop_assert!(lines[0].starts_with("error: "), "{args:?}: {stderr}");
                // 1 is kept for an analysis that fails on valid input: never a usage mistake.
                prop_assert!(code == 2 || lines[0].contains("analysis"), "{args:?} exited {code}: {stderr}");
            }
            other => prop_assert!(false, "{args:?}: exit status {other:?} (a crash?): {stderr}"),
        }
        Ok(())
    });
    let (ok, refused, slowest) = *tally.borrow();
    println!(
        "cli arguments: {} cases, {ok} succeeded, {refused} refused in one line, slowest {slowest:.2} s",
        ok + refused
    );
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// The hostile values the issue names, one by one: each a one-line error with status 2.
#[test]
fn named_hostile_inputs_are_refused_in_one_line() {
    let cases: &[&[&str]] = &[
        &["simulate", "--delta", "1e-300"],
        &["sweep", "--delta", "1e-9", "--alpha", "0.002", "--simulate", "--pf", "lq"],
        &["simulate", "--duration", "1e309"],
        &["simulate", "--csv", "/nonexistent-dir/x.csv"],
        &["simulate", "--svg", "/proc/version"],
        &["map", "--csv", "/", "--n-delta", "2", "--n-alpha", "2"],
        &["simulate", "--state", "delta=0.01&pf=lq&k=999999"],
        &["simulat"],
        &["simulate", "--deltaa", "0.01"],
    ];
    for args in cases {
        let args: Vec<String> = args.iter().map(|s| s.to_string()).collect();
        let (status, _, stderr, _) = run(&args).unwrap();
        assert_eq!(status, Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    }
}
