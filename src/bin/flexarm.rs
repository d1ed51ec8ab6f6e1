//! `flexarm`: the command-line front end of the flexible-joint arm simulator.
//!
//! * `flexarm simulate` runs one closed-loop slew and prints a summary (or one JSON object, or
//!   writes the traces as CSV),
//! * `flexarm analyze` prints the linear stability analysis at rest (ρ, eigenvalues, the δ → 0
//!   pair A4),
//! * `flexarm sweep` tabulates ρ (and optionally simulation verdicts) over lists of δ and α.
//!
//! Arguments are parsed by hand. Every configuration starts from `SimulationConfig::default()`
//! (the paper's parameters) and is validated by the library. Bad input prints one `error: ...`
//! line to stderr and exits with status 2; a failed file write or analysis exits with status 1.

use std::io::Write;

use flexarm::analysis::{self, StabilityReport};
use flexarm::closed_loop::DivergenceReason;
use flexarm::{
    Error, FrictionCompensation, InnerLoop, PreliminaryFeedbackChoice, RunReport, SimulationConfig, Verdict,
};
use serde::Serialize;
use serde_json::{json, Value};

/// Default simulated time, s: the 1-s slew and 3 s after it (errors of an unstable loop are
/// visible within 2–3 s; without preliminary feedback at δ = 0.01 s they pass π rad at ≈ 4.1 s).
const DEFAULT_DURATION: f64 = 4.0;

const USAGE: &str = "\
flexarm — predictive control of a flexible-joint robot arm (von Wissel, Nikoukhah & Campbell 1994)

USAGE:
  flexarm simulate [CONFIG] [--friction MODE] [--duration S] [--output-interval S] [--csv FILE] [--json]
  flexarm analyze  [CONFIG] [--q2 RAD] [--json]
  flexarm sweep    --delta LIST --alpha LIST [--k N] [--eps-ratio M] [--pf P] [--inner I]
                   [--simulate] [--friction MODE] [--duration S] [--json]
  flexarm help | --help

CONFIG (defaults: the paper's values):
  --delta S           sampling period δ, s (default 0.01)
  --alpha A           stabilizing constant for both links, α1 = α2 = A, 1/s (default 2)
  --alpha1 A          α1 only, 1/s
  --alpha2 A          α2 only, 1/s
  --k N               horizon steps k, an integer > 3 (default 12)
  --eps-ratio M       integration step ε = δ/M, with k/2 ≤ M ≤ k (default 8)
  --pf P              preliminary feedback: off | paper | lq (default paper)
  --inner I           inner loop of the preliminary feedback: continuous | sampled (default continuous)

simulate:
  --friction MODE     friction compensation: continuous | held | off (default continuous)
  --duration S        simulated time, s (default 4: the slew and 3 s after it)
  --output-interval S spacing of the recorded traces, s (default 0.002)
  --csv FILE          write the traces (t [s], q [rad], e [rad], T [N m], ...) to FILE
  --json              print one JSON object instead of the text summary

analyze:
  --q2 RAD            link-2 angle of the rest point, rad (default: the end of the slew, 0)
  --json              print the stability report as JSON

sweep:
  --delta LIST        sampling periods, s: comma list 0.005,0.01,0.02 or START:STOP:N
                      (N points, logarithmically spaced when both ends are > 0)
  --alpha LIST        values of α = α1 = α2, 1/s, same syntax
  --simulate          also run each point for --duration s (default 4: the slew and 3 s after it)
  --json              print an array of JSON objects

ρ is the spectral radius of the one-period map linearized at rest: ρ < 1 ⇒ linearly stable.
";

/// A failure to report: the message (without `error: `) and the exit status.
struct Failure(String, i32);

fn usage_error(msg: impl Into<String>) -> Failure {
    Failure(msg.into(), 2)
}

/// A library error: parameter errors are the user's (status 2), the rest are failures (status 1).
fn lib_error(e: Error) -> Failure {
    match &e {
        Error::Config(c) => {
            let flag = match c.parameter {
                "sampling_period (δ)" => " (set with --delta)",
                "alpha1 (α1)" => " (set with --alpha1 or --alpha)",
                "alpha2 (α2)" => " (set with --alpha2 or --alpha)",
                "k (horizon steps)" => " (set with --k)",
                "eps_ratio (m = δ/ε)" => " (set with --eps-ratio and --k)",
                "output_interval" => " (set with --output-interval)",
                _ => "",
            };
            usage_error(format!("{e}{flag}"))
        }
        Error::InvalidDuration(_) => usage_error(format!("{e} (set with --duration)")),
        Error::Analysis(_) => Failure(e.to_string(), 1),
    }
}

type Res<T> = Result<T, Failure>;

/// The remaining command-line arguments.
struct Args(std::vec::IntoIter<String>);

impl Args {
    /// The value after `flag`; a missing value or another flag counts as missing.
    fn value(&mut self, flag: &str, what: &str) -> Res<String> {
        match self.0.next() {
            Some(v) if !v.starts_with("--") => Ok(v),
            _ => Err(usage_error(format!("{flag} needs a value: {what}"))),
        }
    }

    fn number(&mut self, flag: &str, what: &str) -> Res<f64> {
        let v = self.value(flag, what)?;
        parse_number(&v).ok_or_else(|| usage_error(format!("{flag} expects {what}, got '{v}'")))
    }

    fn choice<T: Copy>(&mut self, flag: &str, options: &[(&str, T)]) -> Res<T> {
        let names: Vec<&str> = options.iter().map(|o| o.0).collect();
        let what = format!("one of {}", names.join(" | "));
        let v = self.value(flag, &what)?;
        options
            .iter()
            .find(|o| o.0 == v)
            .map(|o| o.1)
            .ok_or_else(|| usage_error(format!("{flag} must be {what}, got '{v}'")))
    }
}

/// A finite decimal number (Rust would also accept "inf" and "NaN").
fn parse_number(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

fn unknown_flag(command: &str, flag: &str) -> Failure {
    usage_error(format!("unknown flag '{flag}' for '{command}' (see 'flexarm --help')"))
}

/// Applies a controller flag shared by all commands; `Ok(false)` if `flag` is not one of them.
fn controller_flag(config: &mut SimulationConfig, flag: &str, args: &mut Args) -> Res<bool> {
    let c = &mut config.controller;
    match flag {
        "--delta" => c.sampling_period = args.number(flag, "a sampling period δ in s (> 0)")?,
        "--alpha" => c.alpha = [args.number(flag, "a stabilizing constant α in 1/s (> 0)")?; 2],
        "--alpha1" => c.alpha[0] = args.number(flag, "a stabilizing constant α1 in 1/s (> 0)")?,
        "--alpha2" => c.alpha[1] = args.number(flag, "a stabilizing constant α2 in 1/s (> 0)")?,
        "--eps-ratio" => c.eps_ratio = args.number(flag, "a ratio m = δ/ε with k/2 ≤ m ≤ k")?,
        "--k" => {
            let what = "a whole number of horizon steps k > 3";
            let v = args.value(flag, what)?;
            c.horizon_steps = v.trim().parse().map_err(|_| usage_error(format!("--k expects {what}, got '{v}'")))?;
        }
        "--pf" => {
            use PreliminaryFeedbackChoice as P;
            config.preliminary_feedback = args.choice(flag, &[("off", P::Off), ("paper", P::Paper), ("lq", P::Lq)])?;
        }
        "--inner" => {
            config.inner_loop =
                args.choice(flag, &[("continuous", InnerLoop::Continuous), ("sampled", InnerLoop::Sampled)])?;
        }
        _ => return Ok(false),
    }
    Ok(true)
}

fn friction_flag(args: &mut Args) -> Res<FrictionCompensation> {
    use FrictionCompensation as F;
    args.choice("--friction", &[("continuous", F::Continuous), ("held", F::Held), ("off", F::Off)])
}

/// The lowercase name a settings enum has in JSON (and on the command line).
fn name(value: impl Serialize) -> String {
    serde_json::to_value(value).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}

/// The verdict in words, e.g. "unstable (errors grow at 2.273 1/s)".
fn verdict_text(verdict: Verdict, bound: f64) -> String {
    match verdict {
        Verdict::Stable => "stable".into(),
        Verdict::Unstable { growth_rate } => format!("unstable (errors grow at {growth_rate:.3} 1/s)"),
        Verdict::Diverged { at, reason } => format!(
            "diverged at t = {at:.3} s ({})",
            match reason {
                DivergenceReason::ErrorBound => format!("a tracking error exceeded {bound:.4} rad"),
                DivergenceReason::NonFinite => "the state became NaN or infinite".into(),
                DivergenceReason::NewtonFailure => "Newton's iteration in the predictor failed".into(),
            }
        ),
    }
}

fn linear_verdict(rho: f64) -> &'static str {
    if rho < 1.0 {
        "stable"
    } else {
        "unstable"
    }
}

/// The configuration lines shared by the text outputs.
fn describe_config(c: &SimulationConfig) -> String {
    let k = &c.controller;
    format!(
        "  δ = {} s, α1 = {} 1/s, α2 = {} 1/s, k = {}, m = {} (ε = {:.3e} s, τ = kε = {:.3e} s)\n  \
         preliminary feedback {}, inner loop {}, friction compensation {}\n",
        k.sampling_period,
        k.alpha[0],
        k.alpha[1],
        k.horizon_steps,
        k.eps_ratio,
        k.integration_step(),
        k.horizon(),
        name(c.preliminary_feedback),
        name(c.inner_loop),
        name(c.friction_compensation)
    )
}

// ---------------------------------------------------------------------------------------- simulate

fn simulate(mut args: Args) -> Res<String> {
    let mut config = SimulationConfig::default();
    let (mut duration, mut json_out, mut csv) = (DEFAULT_DURATION, false, None::<String>);
    while let Some(flag) = args.0.next() {
        if controller_flag(&mut config, &flag, &mut args)? {
            continue;
        }
        match flag.as_str() {
            "--friction" => config.friction_compensation = friction_flag(&mut args)?,
            "--duration" => duration = args.number(&flag, "a duration in s (≥ 0)")?,
            "--output-interval" => config.output_interval = args.number(&flag, "a trace spacing in s (> 0)")?,
            "--csv" => csv = Some(args.value(&flag, "a file name")?),
            "--json" => json_out = true,
            _ => return Err(unknown_flag("simulate", &flag)),
        }
    }
    config.validate().map_err(|e| lib_error(e.into()))?;
    let report = flexarm::simulate(&config, duration).map_err(lib_error)?;
    let rho = analysis::spectral_radius(&config, None).ok();
    let mut out = if json_out {
        simulation_json(&config, duration, &report, rho).to_string() + "\n"
    } else {
        simulation_text(&config, duration, &report, rho)
    };
    if let Some(path) = csv {
        std::fs::write(&path, report.traces.to_csv())
            .map_err(|e| Failure(format!("could not write --csv file '{path}': {e}"), 1))?;
        if !json_out {
            out += &format!("traces ({} rows) written to {path}\n", report.traces.len());
        }
    }
    Ok(out)
}

fn simulation_json(c: &SimulationConfig, duration: f64, r: &RunReport, rho: Option<f64>) -> Value {
    let m = &r.metrics;
    let (at, reason) = match m.verdict {
        Verdict::Diverged { at, reason } => (Some(at), Some(name(reason))),
        _ => (None, None),
    };
    json!({
        "delta": c.controller.sampling_period,
        "alpha1": c.controller.alpha[0],
        "alpha2": c.controller.alpha[1],
        "k": c.controller.horizon_steps,
        "eps_ratio": c.controller.eps_ratio,
        "preliminary_feedback": name(c.preliminary_feedback),
        "inner_loop": name(c.inner_loop),
        "friction_compensation": name(c.friction_compensation),
        "duration": duration,
        "simulated_time": m.time,
        "verdict": m.verdict.label(),
        "diverged_at": at,
        "divergence_reason": reason,
        "max_error_slew": m.max_error_slew,
        "max_error_after": m.max_error_after,
        "rms_error": m.rms_error,
        "growth_rate": m.growth_rate,
        "max_torque": m.max_torque,
        "spectral_radius": rho,
    })
}

fn simulation_text(c: &SimulationConfig, duration: f64, r: &RunReport, rho: Option<f64>) -> String {
    let m = &r.metrics;
    let verdict = verdict_text(m.verdict, c.divergence_bound);
    let pair = |v: [f64; 2], unit: &str| format!("{:.3e}, {:.3e} {unit}", v[0], v[1]);
    let growth = m.growth_rate.map_or("n/a (run too short)".into(), |g| format!("{g:.4} 1/s"));
    let rho = rho.map_or("n/a (analysis failed)".into(), |r| {
        format!("{r:.6} → linearly {} (ρ < 1 ⇒ linearly stable)", linear_verdict(r))
    });
    let mut s = format!("flexarm simulate: {duration} s of the 1-s slew\nconfiguration\n{}", describe_config(c));
    s += &format!("result (simulated {:.3} s)\n", m.time);
    s += &format!("  verdict                     {verdict}\n");
    s += &format!("  max |e1|, |e2| during slew  {}\n", pair(m.max_error_slew, "rad"));
    s += &format!("  max |e1|, |e2| after slew   {}\n", pair(m.max_error_after, "rad"));
    s += &format!("  RMS e1, e2                  {}\n", pair(m.rms_error, "rad"));
    s += &format!("  growth rate                 {growth}\n");
    s += &format!("  max |T1|, |T2|              {:.3}, {:.3} N m\n", m.max_torque[0], m.max_torque[1]);
    s += &format!("  spectral radius ρ           {rho}\n");
    s
}

// ----------------------------------------------------------------------------------------- analyze

fn analyze(mut args: Args) -> Res<String> {
    let mut config = SimulationConfig::default();
    let (mut q2, mut json_out) = (None, false);
    while let Some(flag) = args.0.next() {
        if controller_flag(&mut config, &flag, &mut args)? {
            continue;
        }
        match flag.as_str() {
            "--q2" => q2 = Some(args.number(&flag, "a link-2 angle in rad")?),
            "--json" => json_out = true,
            _ => return Err(unknown_flag("analyze", &flag)),
        }
    }
    let report = analysis::analyze(&config, q2).map_err(lib_error)?;
    if json_out {
        // Non-finite floats (e.g. ln 0) become null in serde_json's Value.
        let mut v = serde_json::to_value(&report).map_err(|e| Failure(format!("JSON encoding failed: {e}"), 1))?;
        v["verdict"] = json!(linear_verdict(report.spectral_radius));
        v["alpha"] = json!(config.controller.alpha);
        v["k"] = json!(config.controller.horizon_steps);
        v["eps_ratio"] = json!(config.controller.eps_ratio);
        v["preliminary_feedback"] = json!(name(config.preliminary_feedback));
        v["inner_loop"] = json!(name(config.inner_loop));
        return Ok(v.to_string() + "\n");
    }
    Ok(analysis_text(&config, &report))
}

fn analysis_text(c: &SimulationConfig, r: &StabilityReport) -> String {
    let mut s = format!(
        "flexarm analyze: sampled loop linearized at rest at q1 = {:.4} rad, q2 = {:.4} rad\nconfiguration\n{}",
        r.rest[0],
        r.rest[1],
        describe_config(c)
    );
    s += &format!(
        "spectral radius ρ = {:.6} → {} (ρ < 1 ⇒ linearly stable)\ngrowth rate ln ρ/δ = {:.4} 1/s\n",
        r.spectral_radius,
        linear_verdict(r.spectral_radius),
        r.growth_rate
    );
    s += "eigenvalues of the one-period map (s = ln λ/δ, ζ = −Re s/|s|):\n";
    s += &format!(
        "  {:>2}  {:>10} {:>11} {:>11}  {:>11} {:>11}  {:>8} {:>11}\n",
        "#", "|λ|", "Re λ", "Im λ", "Re s [1/s]", "Im s [1/s]", "ζ", "|s| [rad/s]"
    );
    for (i, p) in r.poles.iter().enumerate() {
        let [re, im] = p.discrete;
        s += &format!("  {:>2}  {:>10.6} {:>11.6} {:>11.6}", i + 1, re.hypot(im), re, im);
        s += &match p.continuous {
            Some([sr, si]) => {
                let w = sr.hypot(si);
                let zeta = if w > 0.0 { format!("{:>8.4}", -sr / w) } else { format!("{:>8}", "—") };
                format!("  {sr:>11.4} {si:>11.4}  {zeta} {w:>11.4}\n")
            }
            None => "  (λ = 0: no continuous equivalent)\n".into(),
        };
    }
    let pair = |p: [[f64; 2]; 2]| format!("{:.4} ± {:.4}j 1/s", p[0][0], p[0][1].abs());
    s += &format!("δ → 0 pair A4 without preliminary feedback: {}\n", pair(r.limit_pair_open));
    s += &format!(
        "δ → 0 pair A4 with preliminary feedback ({}): {}\n",
        name(c.preliminary_feedback),
        pair(r.limit_pair)
    );
    s
}

// ------------------------------------------------------------------------------------------- sweep

/// `0.005,0.01,0.02` or `START:STOP:N` (log-spaced if both ends are > 0, else linear).
fn parse_list(flag: &str, text: &str) -> Res<Vec<f64>> {
    let bad = |why: &str| {
        usage_error(format!("{flag} expects a comma list like 0.005,0.01 or START:STOP:N ({why}), got '{text}'"))
    };
    if let Some((range, n)) = text.rsplit_once(':') {
        let (lo, hi) = range.split_once(':').ok_or_else(|| bad("a range has three parts"))?;
        let (lo, hi) = (
            parse_number(lo).ok_or_else(|| bad("START is not a number"))?,
            parse_number(hi).ok_or_else(|| bad("STOP is not a number"))?,
        );
        let n: usize = n
            .trim()
            .parse()
            .ok()
            .filter(|&n| (1..=10_000).contains(&n))
            .ok_or_else(|| bad("N must be a whole number from 1 to 10000"))?;
        if lo > 0.0 && hi > 0.0 {
            return Ok(analysis::log_space(lo, hi, n));
        }
        return Ok((0..n).map(|i| if n == 1 { lo } else { lo + (hi - lo) * i as f64 / (n - 1) as f64 }).collect());
    }
    text.split(',').map(|v| parse_number(v).ok_or_else(|| bad("not a number"))).collect()
}

fn sweep(mut args: Args) -> Res<String> {
    let mut config = SimulationConfig::default();
    let (mut deltas, mut alphas) = (None, None);
    let (mut run, mut duration, mut json_out) = (false, DEFAULT_DURATION, false);
    while let Some(flag) = args.0.next() {
        match flag.as_str() {
            "--delta" => deltas = Some(parse_list(&flag, &args.value(&flag, "a list of sampling periods in s")?)?),
            "--alpha" => alphas = Some(parse_list(&flag, &args.value(&flag, "a list of α values in 1/s")?)?),
            "--alpha1" | "--alpha2" => {
                return Err(usage_error(format!("{flag} is not available in 'sweep': use --alpha LIST (α1 = α2)")))
            }
            "--friction" => config.friction_compensation = friction_flag(&mut args)?,
            "--duration" => duration = args.number(&flag, "a duration in s (≥ 0)")?,
            "--simulate" => run = true,
            "--json" => json_out = true,
            _ if controller_flag(&mut config, &flag, &mut args)? => {}
            _ => return Err(unknown_flag("sweep", &flag)),
        }
    }
    let deltas = deltas.ok_or_else(|| usage_error("sweep needs --delta LIST (sampling periods in s)"))?;
    let alphas = alphas.ok_or_else(|| usage_error("sweep needs --alpha LIST (α = α1 = α2 in 1/s)"))?;
    let mut rows = Vec::new();
    let mut text = format!("{:>10} {:>8} {:>12} {:>9}", "δ [s]", "α [1/s]", "ρ", "linear");
    if run {
        text += &format!("  {:>28}  {:>21}  {:>21}", "simulation", "max |e| slew [rad]", "max |e| after [rad]");
    }
    text += "\n";
    for &alpha in &alphas {
        for &delta in &deltas {
            let mut c = config;
            c.controller.sampling_period = delta;
            c.controller.alpha = [alpha, alpha];
            let rho = analysis::spectral_radius(&c, None).map_err(lib_error)?;
            let mut row =
                json!({ "delta": delta, "alpha": alpha, "spectral_radius": rho, "verdict": linear_verdict(rho) });
            text += &format!("{delta:>10.5} {alpha:>8.3} {rho:>12.6} {:>9}", linear_verdict(rho));
            if run {
                let r = flexarm::simulate(&c, duration).map_err(lib_error)?;
                row["simulation"] = simulation_json(&c, duration, &r, Some(rho));
                let m = &r.metrics;
                let verdict = match m.verdict {
                    Verdict::Stable => "stable".to_string(),
                    Verdict::Unstable { growth_rate } => format!("unstable ({growth_rate:.2} 1/s)"),
                    Verdict::Diverged { at, .. } => format!("diverged at {at:.2} s"),
                };
                let [s1, s2] = m.max_error_slew;
                let [a1, a2] = m.max_error_after;
                text += &format!("  {verdict:>28}  {s1:>10.3e} {s2:>10.3e}  {a1:>10.3e} {a2:>10.3e}");
            }
            text += "\n";
            rows.push(row);
        }
    }
    Ok(if json_out { Value::Array(rows).to_string() + "\n" } else { text })
}

// -------------------------------------------------------------------------------------------- main

fn run(mut args: Args) -> Res<String> {
    let Some(command) = args.0.next() else {
        return Err(usage_error("no command given: use simulate, analyze, sweep or help (see 'flexarm --help')"));
    };
    if args.0.as_slice().iter().any(|a| a == "--help" || a == "-h") {
        return Ok(USAGE.to_string());
    }
    match command.as_str() {
        "help" | "--help" | "-h" => Ok(USAGE.to_string()),
        "simulate" => simulate(args),
        "analyze" => analyze(args),
        "sweep" => sweep(args),
        other => Err(usage_error(format!("unknown command '{other}': use simulate, analyze, sweep or help"))),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(Args(args.into_iter())) {
        Ok(out) => {
            // Ignore a closed pipe (e.g. `flexarm analyze | head`) rather than panicking.
            let _ = std::io::stdout().lock().write_all(out.as_bytes());
        }
        Err(Failure(msg, code)) => {
            eprintln!("error: {msg}");
            std::process::exit(code);
        }
    }
}
