//! Issue 34's fuzz of the command line over the whole accepted range of every setting: each
//! number at its ends (just inside an exclusive one) and log-spaced (or evenly spaced) inside,
//! every choice and switch, and seeded pairs of settings at their corners. Each run must end
//! within 20 s with status 0 and finite numbers, or with status 2 and one `error:` line — never a
//! panic (status 101), a crash, a NaN or an infinity in what it prints.

use std::io::Read;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use flexarm::schema::{Kind, Param, Scope, PARAMS};

/// The wall-clock limit of one run: a setting the command accepts must not hang it.
const LIMIT: Duration = Duration::from_secs(20);

struct Outcome {
    status: Option<i32>,
    stdout: String,
    stderr: String,
    seconds: f64,
}

fn run(args: &[String]) -> Outcome {
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_flexarm"))
        .args(args)
        .env_remove("FLEXARM_WORK_LIMIT")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the flexarm binary starts");
    let (mut out, mut err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let reader = std::thread::spawn(move || {
        let (mut o, mut e) = (String::new(), String::new());
        out.read_to_string(&mut o).ok();
        err.read_to_string(&mut e).ok();
        (o, e)
    });
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s.code();
        }
        if start.elapsed() > LIMIT {
            child.kill().ok();
            child.wait().ok();
            break Some(-1);
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let (stdout, stderr) = reader.join().unwrap();
    Outcome { status, stdout, stderr, seconds: start.elapsed().as_secs_f64() }
}

/// The values to try for one number setting: its ends and points inside.
fn numbers(p: &Param) -> Vec<f64> {
    let Kind::Number(spec) = p.kind else { return vec![] };
    let low = if spec.min_inclusive {
        spec.min
    } else if spec.min > 0.0 {
        spec.min * (1.0 + 1e-9)
    } else if spec.min == 0.0 {
        f64::MIN_POSITIVE
    } else {
        spec.min + spec.min.abs() * 1e-9
    };
    let high = if spec.max.is_finite() { spec.max } else { 1e12 };
    let mut v = vec![low, high, spec.default];
    for i in 1..4 {
        let f = f64::from(i) / 4.0;
        v.push(if low > 0.0 { (low.ln() + (high.ln() - low.ln()) * f).exp() } else { low + (high - low) * f });
    }
    if spec.integer {
        v = v.into_iter().map(f64::round).collect();
    }
    v
}

fn values(p: &Param) -> Vec<String> {
    match p.kind {
        Kind::Number(_) => numbers(p).into_iter().map(|v| format!("{v:e}")).collect(),
        Kind::Choice { options, .. } => options.iter().map(|c| c.value.to_string()).collect(),
        Kind::Switch { .. } => vec!["1".into(), "0".into()],
    }
}

/// The arguments that set `p` to `value` for `command`: the state string for a run's settings,
/// the flag for a command-line option.
fn setting(p: &Param, value: &str) -> Vec<String> {
    match p.scope {
        Scope::Cli => vec![format!("--{}", p.key.replace('_', "-")), value.to_string()],
        _ => vec!["--state".into(), format!("{}={value}", p.key)],
    }
}

/// What a run may print: no NaN or infinity anywhere; a refusal is one `error:` line.
fn check(args: &[String], o: &Outcome) -> Result<(), String> {
    let text = format!("{}\n{}", o.stdout, o.stderr);
    // A refusal may quote what was typed ('NaN'): only what the program computed is checked.
    let computed: String = text.split('\'').step_by(2).collect::<Vec<_>>().join(" ");
    let lower = computed.to_lowercase();
    let bad_number = ["nan", "inf ", "inf\n", "inf,", "infinity", "null"]
        .iter()
        .find(|w| lower.split(|c: char| !c.is_alphanumeric()).any(|t| t == w.trim_end_matches([' ', '\n', ','])));
    match o.status {
        Some(0) if bad_number.is_none() => Ok(()),
        Some(0) => Err(format!("{args:?}: prints {bad_number:?}:\n{text}")),
        Some(2) => {
            let lines: Vec<&str> = o.stderr.lines().collect();
            if lines.len() == 1 && lines[0].starts_with("error: ") && o.stdout.is_empty() && bad_number.is_none() {
                Ok(())
            } else {
                Err(format!("{args:?}: a refusal must be one error line:\n{text}"))
            }
        }
        Some(-1) => Err(format!("{args:?}: still running after {} s", LIMIT.as_secs())),
        s => Err(format!("{args:?}: status {s:?}:\n{text}")),
    }
}

/// Runs every argument list on two threads (the machine's cores) and collects what failed.
fn fuzz(cases: Vec<Vec<String>>) -> (usize, usize, Vec<String>) {
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(Vec::new());
    let refused = AtomicUsize::new(0);
    let slowest = Mutex::new((0.0, Vec::new()));
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(args) = cases.get(i) else { break };
                let o = run(args);
                if o.status == Some(2) {
                    refused.fetch_add(1, Ordering::Relaxed);
                }
                if let Err(e) = check(args, &o) {
                    failures.lock().unwrap().push(e);
                }
                let mut s = slowest.lock().unwrap();
                if o.seconds > s.0 {
                    *s = (o.seconds, args.clone());
                }
            });
        }
    });
    let (t, args) = slowest.into_inner().unwrap();
    eprintln!("slowest run: {t:.2} s for {args:?}");
    (cases.len(), refused.into_inner(), failures.into_inner().unwrap())
}

fn command(name: &str, rest: &[&str]) -> Vec<String> {
    std::iter::once(name).chain(rest.iter().copied()).map(String::from).collect()
}

/// A small deterministic generator for the pairs (no dependency, the same cases every run).
struct Lcg(u64);

impl Lcg {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((self.0 >> 33) % n as u64) as usize
    }
}

#[test]
fn every_setting_over_its_range_ends_in_a_result_or_one_error_line() {
    let runs: Vec<&Param> = PARAMS.iter().copied().filter(|p| p.scope == Scope::Run).collect();
    let options: Vec<&Param> = PARAMS.iter().copied().filter(|p| p.scope == Scope::Cli).collect();
    let mut cases = Vec::new();
    for p in &runs {
        for v in values(p) {
            let mut analyze = command("analyze", &[]);
            analyze.extend(setting(p, &v));
            cases.push(analyze);
            let mut simulate = command("simulate", &["--duration", "1.5"]);
            simulate.extend(setting(p, &v));
            cases.push(simulate);
        }
    }
    for p in &options {
        for v in values(p) {
            let mut simulate = command("simulate", &[]);
            simulate.extend(setting(p, &v));
            cases.push(simulate);
        }
    }
    // Pairs of a run's number settings, each at one of its ends.
    let numeric: Vec<&Param> = runs.iter().copied().filter(|p| matches!(p.kind, Kind::Number(_))).collect();
    let mut rng = Lcg(34);
    for _ in 0..60 {
        let (a, b) = (numeric[rng.below(numeric.len())], numeric[rng.below(numeric.len())]);
        if a.key == b.key {
            continue;
        }
        let (va, vb) = (numbers(a)[rng.below(2)], numbers(b)[rng.below(2)]);
        let state = format!("{}={va:e}&{}={vb:e}", a.key, b.key);
        cases.push(command("analyze", &["--state", &state]));
        cases.push(command("simulate", &["--duration", "1.5", "--state", &state]));
    }
    // State strings as a hand or a broken link writes them.
    for state in [
        "",
        "&",
        "&&&",
        "=",
        "delta",
        "delta=",
        "=0.01",
        "delta==0.01",
        "delta=0.01&delta=0.02",
        "delta=%zz",
        "delta=0x10",
        "delta=1e",
        "delta=.",
        "DELTA=0.01",
        "delta=0.01&&alpha=2",
        "alpha=2,3",
        "pf=PAPER",
        "pf=",
        "arm=nosuch",
        "delta=1e-5&alpha=1000&k=1000",
        "k=2.5",
        "k=-1",
        "eps_ratio=1e-300",
        "δ=0.01",
        "delta=0.01#x",
        "delta=0.01 ",
        " delta=0.01",
        "delta=+0.01",
        "delta=NaN",
        "delta=-inf",
        "rest=nowhere",
    ] {
        cases.push(command("analyze", &["--state", state]));
        cases.push(command("simulate", &["--duration", "1", "--state", state]));
    }
    // The sweep over lists at the range's ends.
    cases.push(command("sweep", &["--delta", "1e-5,10", "--alpha", "0.001,1000"]));
    cases.push(command("sweep", &["--delta", "0.002:0.25:4", "--alpha", "0.1,5", "--simulate"]));
    let (total, refused, failures) = fuzz(cases);
    eprintln!("{total} runs: {} ended with a result, {refused} refused with one line", total - refused);
    assert!(failures.is_empty(), "{} of {total} runs failed:\n{}", failures.len(), failures.join("\n---\n"));
}
