//! `flexarm`: the command-line front end of the flexible-joint arm simulator.
//!
//! * `flexarm simulate` runs one closed-loop slew and prints a summary (or one JSON object, or
//!   writes the traces as CSV),
//! * `flexarm analyze` prints the linear stability analysis at rest (ρ, eigenvalues, the δ → 0
//!   pair A4),
//! * `flexarm sweep` tabulates ρ (and optionally simulation verdicts) over lists of δ and α,
//! * `flexarm map` computes ρ on a logarithmic (δ, α) grid without and/or with preliminary
//!   feedback, summarizes it, and writes it as CSV, JSON or an SVG figure.
//!
//! Arguments are parsed by hand. Every configuration starts from `SimulationConfig::default()`
//! (the paper's parameters) and is validated by the library. Bad input prints one `error: ...`
//! line to stderr and exits with status 2; a failed file write or analysis exits with status 1.

use std::io::{IsTerminal, Write};
use std::time::Instant;

use flexarm::analysis::{self, StabilityMap, StabilityReport};
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
  flexarm simulate [CONFIG] [--friction MODE] [--duration S] [--output-interval S] [--csv FILE]
                   [--svg FILE] [--json]
  flexarm analyze  [CONFIG] [--q2 RAD] [--json]
  flexarm sweep    --delta LIST --alpha LIST [--k N] [--eps-ratio M] [--pf P] [--inner I]
                   [--simulate] [--friction MODE] [--duration S] [--json]
  flexarm map      [--delta-range A:B] [--alpha-range A:B] [--n-delta N] [--n-alpha N]
                   [--pf off|paper|lq|both] [--inner I] [--k N] [--eps-ratio M]
                   [--mark D:A] [--csv FILE] [--svg FILE] [--json]
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
  --svg FILE          write a figure of the tracking errors e1, e2 over time to FILE (SVG)
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

map (ρ on a grid, logarithmic in both δ and α; prints a summary with the stable δ intervals
     in the grid row of α nearest 2 1/s):
  --delta-range A:B   sampling periods from A to B s, 0 < A < B ≤ 10 (default 0.002:0.25)
  --alpha-range A:B   α = α1 = α2 from A to B 1/s, 0 < A < B ≤ 1000 (default 0.1:5)
  --n-delta N         number of δ values, 2 to 2000 (default 100)
  --n-alpha N         number of α values, 2 to 2000 (default 60)
  --pf P              off | paper | lq | both (default both: off and the paper's K_pr)
  --mark D:A          mark the point δ = D s, α = A 1/s in the figure
  --csv FILE          write ρ to FILE, one row per PF and cell:
                      preliminary_feedback,delta [s],alpha [1/s],rho,stable
  --svg FILE          write the map as a figure to FILE (SVG); with --pf both the two maps
                      are side by side in that one file
  --json              print one JSON object {PF: {sampling_periods, alphas, spectral_radius
                      (row-major by α), ...}} instead of the summary
  Progress goes to stderr when it is a terminal.

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
    let (mut duration, mut json_out, mut csv, mut svg) = (DEFAULT_DURATION, false, None::<String>, None::<String>);
    while let Some(flag) = args.0.next() {
        if controller_flag(&mut config, &flag, &mut args)? {
            continue;
        }
        match flag.as_str() {
            "--friction" => config.friction_compensation = friction_flag(&mut args)?,
            "--duration" => duration = args.number(&flag, "a duration in s (≥ 0)")?,
            "--output-interval" => config.output_interval = args.number(&flag, "a trace spacing in s (> 0)")?,
            "--csv" => csv = Some(args.value(&flag, "a file name")?),
            "--svg" => svg = Some(args.value(&flag, "a file name")?),
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
    if let Some(path) = svg {
        let title = format!(
            "Tracking errors: {}, PF {} — {}",
            delta_alpha_text(&config),
            name(config.preliminary_feedback),
            verdict_text(report.metrics.verdict, config.divergence_bound)
        );
        write_file("--svg", &path, &flexarm::svg::error_traces_svg(&report.traces, &title))?;
        if !json_out {
            out += &format!("figure of the tracking errors written to {path}\n");
        }
    }
    Ok(out)
}

/// "δ = 0.01 s, α = 2 1/s" (or α1, α2 when they differ).
fn delta_alpha_text(c: &SimulationConfig) -> String {
    let k = &c.controller;
    if k.alpha[0] == k.alpha[1] {
        format!("δ = {} s, α = {} 1/s", k.sampling_period, k.alpha[0])
    } else {
        format!("δ = {} s, α1 = {} 1/s, α2 = {} 1/s", k.sampling_period, k.alpha[0], k.alpha[1])
    }
}

/// Writes an output file; a failure is reported with the flag that named the file (status 1).
fn write_file(flag: &str, path: &str, contents: &str) -> Res<()> {
    std::fs::write(path, contents).map_err(|e| Failure(format!("could not write {flag} file '{path}': {e}"), 1))
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

// --------------------------------------------------------------------------------------------- map

/// The default grid of `flexarm map`: δ [s] and α [1/s] ranges and sizes.
const MAP_DELTA_RANGE: (f64, f64) = (0.002, 0.25);
const MAP_ALPHA_RANGE: (f64, f64) = (0.1, 5.0);
const MAP_N_DELTA: usize = 100;
const MAP_N_ALPHA: usize = 60;
/// The largest number of grid points per axis.
const MAP_MAX_POINTS: usize = 2000;
/// The summary lists the stable δ intervals in the grid row with α nearest this (the paper's α).
const MAP_SUMMARY_ALPHA: f64 = 2.0;
/// Maps with at least this many cells report progress (when stderr is a terminal).
const MAP_PROGRESS_CELLS: usize = 2000;

/// `A:B` with 0 < A < B.
fn parse_range(flag: &str, text: &str, unit: &str) -> Res<(f64, f64)> {
    let bad = |why: &str| usage_error(format!("{flag} expects A:B with 0 < A < B in {unit} ({why}), got '{text}'"));
    let (a, b) = text.split_once(':').ok_or_else(|| bad("two numbers separated by ':'"))?;
    let a = parse_number(a).ok_or_else(|| bad("A is not a number"))?;
    let b = parse_number(b).ok_or_else(|| bad("B is not a number"))?;
    if a <= 0.0 {
        return Err(bad("A must be > 0"));
    }
    if b <= a {
        return Err(bad("A must be less than B"));
    }
    Ok((a, b))
}

fn parse_count(flag: &str, text: &str) -> Res<usize> {
    text.trim().parse::<usize>().ok().filter(|n| (2..=MAP_MAX_POINTS).contains(n)).ok_or_else(|| {
        usage_error(format!("{flag} expects a whole number of grid points from 2 to {MAP_MAX_POINTS}, got '{text}'"))
    })
}

/// The figure's caption for one map.
fn pf_caption(pf: PreliminaryFeedbackChoice) -> &'static str {
    match pf {
        PreliminaryFeedbackChoice::Off => "without preliminary feedback (PF off)",
        PreliminaryFeedbackChoice::Paper => "with the paper's preliminary feedback K_pr",
        PreliminaryFeedbackChoice::Lq => "with the LQ preliminary feedback",
    }
}

/// Percentages on stderr, every 10 %, when enabled.
struct Progress {
    enabled: bool,
    total: usize,
    done: usize,
    next: usize,
    shown: bool,
}

impl Progress {
    fn step(&mut self) {
        self.done += 1;
        let percent = self.done * 100 / self.total.max(1);
        if self.enabled && percent >= self.next {
            eprint!("\rmap: {percent:>3} % of {} rows", self.total);
            self.next = (percent / 10 + 1) * 10;
            self.shown = true;
        }
    }

    fn finish(&self) {
        if self.shown {
            eprint!("\r{:40}\r", "");
        }
    }
}

/// One computed map and what the summary says about it.
struct MapResult {
    pf: PreliminaryFeedbackChoice,
    map: StabilityMap,
    seconds: f64,
    /// Cells whose analysis failed (ρ = NaN).
    failed: usize,
}

impl MapResult {
    fn stable_fraction(&self) -> f64 {
        let n = self.map.spectral_radius.len().max(1);
        self.map.spectral_radius.iter().filter(|r| **r < 1.0).count() as f64 / n as f64
    }
}

/// The index of the α nearest `MAP_SUMMARY_ALPHA` (in log α).
fn summary_row(alphas: &[f64]) -> usize {
    let d = |a: f64| (a.ln() - MAP_SUMMARY_ALPHA.ln()).abs();
    (0..alphas.len()).min_by(|&i, &j| d(alphas[i]).total_cmp(&d(alphas[j]))).unwrap_or(0)
}

/// The δ intervals of one grid row where ρ < 1: runs of stable cells whose ends are moved to the
/// crossing of ρ = 1, interpolated linearly in log δ (a run that reaches the end of the grid, or
/// a NaN cell, ends at that grid point).
fn stable_intervals(deltas: &[f64], rho: &[f64]) -> Vec<[f64; 2]> {
    let crossing = |a: usize, b: usize| {
        let (ra, rb) = (rho[a], rho[b]);
        if !(ra.is_finite() && rb.is_finite()) || ra == rb {
            return None;
        }
        let t = (1.0 - ra) / (rb - ra);
        Some((deltas[a].ln() + t * (deltas[b].ln() - deltas[a].ln())).exp())
    };
    let n = deltas.len().min(rho.len());
    let mut out = Vec::new();
    let mut j = 0;
    while j < n {
        if rho[j] < 1.0 {
            let start = j;
            while j + 1 < n && rho[j + 1] < 1.0 {
                j += 1;
            }
            let lo = if start > 0 { crossing(start - 1, start).unwrap_or(deltas[start]) } else { deltas[start] };
            let hi = if j + 1 < n { crossing(j, j + 1).unwrap_or(deltas[j]) } else { deltas[j] };
            out.push([lo, hi]);
        }
        j += 1;
    }
    out
}

/// Three significant digits, trailing zeros trimmed.
fn sig3(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = (2 - v.abs().log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn map(mut args: Args) -> Res<String> {
    use PreliminaryFeedbackChoice as P;
    let mut config = SimulationConfig::default();
    let (mut delta_range, mut alpha_range) = (MAP_DELTA_RANGE, MAP_ALPHA_RANGE);
    let (mut delta_text, mut alpha_text) = (None::<String>, None::<String>);
    let (mut n_delta, mut n_alpha) = (MAP_N_DELTA, MAP_N_ALPHA);
    let mut pfs = vec![P::Off, P::Paper];
    let (mut csv, mut svg, mut json_out, mut mark) = (None::<String>, None::<String>, false, None);
    while let Some(flag) = args.0.next() {
        match flag.as_str() {
            "--delta-range" => {
                let v = args.value(&flag, "a range A:B of sampling periods in s")?;
                delta_range = parse_range(&flag, &v, "s")?;
                delta_text = Some(v);
            }
            "--alpha-range" => {
                let v = args.value(&flag, "a range A:B of α values in 1/s")?;
                alpha_range = parse_range(&flag, &v, "1/s")?;
                alpha_text = Some(v);
            }
            "--n-delta" => n_delta = parse_count(&flag, &args.value(&flag, "a number of δ values")?)?,
            "--n-alpha" => n_alpha = parse_count(&flag, &args.value(&flag, "a number of α values")?)?,
            "--pf" => {
                pfs = args
                    .choice(
                        &flag,
                        &[
                            ("off", &[P::Off][..]),
                            ("paper", &[P::Paper]),
                            ("lq", &[P::Lq]),
                            ("both", &[P::Off, P::Paper]),
                        ],
                    )?
                    .to_vec()
            }
            "--mark" => {
                let what = "a point D:A (δ in s, α in 1/s, both > 0)";
                let v = args.value(&flag, what)?;
                let point = v
                    .split_once(':')
                    .and_then(|(d, a)| Some((parse_number(d)?, parse_number(a)?)))
                    .filter(|(d, a)| *d > 0.0 && *a > 0.0);
                mark = Some(point.ok_or_else(|| usage_error(format!("--mark expects {what}, got '{v}'")))?);
            }
            "--csv" => csv = Some(args.value(&flag, "a file name")?),
            "--svg" => svg = Some(args.value(&flag, "a file name")?),
            "--json" => json_out = true,
            "--delta" => return Err(usage_error("--delta is not available in 'map': use --delta-range A:B")),
            "--alpha" | "--alpha1" | "--alpha2" => {
                return Err(usage_error(format!("{flag} is not available in 'map': use --alpha-range A:B (α1 = α2)")))
            }
            _ if controller_flag(&mut config, &flag, &mut args)? => {}
            _ => return Err(unknown_flag("map", &flag)),
        }
    }
    // k and m first (their own flags), then the ends of the ranges against the library's limits.
    config.validate().map_err(|e| lib_error(e.into()))?;
    for (flag, text, (lo, hi), is_delta) in
        [("--delta-range", &delta_text, delta_range, true), ("--alpha-range", &alpha_text, alpha_range, false)]
    {
        for end in [lo, hi] {
            let mut c = config.controller;
            if is_delta {
                c.sampling_period = end;
            } else {
                c.alpha = [end; 2];
            }
            if let Err(e) = c.validate() {
                let given = text.as_deref().map(|t| format!(" '{t}'")).unwrap_or_default();
                return Err(usage_error(format!("{flag}{given}: {e}")));
            }
        }
    }

    let deltas = analysis::log_space(delta_range.0, delta_range.1, n_delta);
    let alphas = analysis::log_space(alpha_range.0, alpha_range.1, n_alpha);
    let mut progress = Progress {
        enabled: std::io::stderr().is_terminal() && n_delta * n_alpha * pfs.len() >= MAP_PROGRESS_CELLS,
        total: n_alpha * pfs.len(),
        done: 0,
        next: 10,
        shown: false,
    };
    let started = Instant::now();
    let mut results = Vec::new();
    for &pf in &pfs {
        let pf_started = Instant::now();
        let mut c = config;
        c.preliminary_feedback = pf;
        let mut rho = Vec::with_capacity(n_delta * n_alpha);
        let mut failed = 0;
        for &alpha in &alphas {
            let before = rho.len();
            match analysis::stability_map_row(&c, alpha, &deltas, &mut rho) {
                Ok(()) => {}
                // A singular step or a failed design at some cells: analyse the row cell by cell.
                Err(Error::Analysis(_)) => {
                    rho.truncate(before);
                    for &delta in &deltas {
                        let mut cell = c;
                        cell.controller.sampling_period = delta;
                        cell.controller.alpha = [alpha; 2];
                        let r = analysis::spectral_radius(&cell, None).unwrap_or(f64::NAN);
                        failed += usize::from(r.is_nan());
                        rho.push(r);
                    }
                }
                Err(e) => {
                    progress.finish();
                    return Err(lib_error(e));
                }
            }
            progress.step();
        }
        let map = StabilityMap { sampling_periods: deltas.clone(), alphas: alphas.clone(), spectral_radius: rho };
        results.push(MapResult { pf, map, seconds: pf_started.elapsed().as_secs_f64(), failed });
    }
    progress.finish();
    let seconds = started.elapsed().as_secs_f64();

    let row = summary_row(&alphas);
    let row_rho = |r: &MapResult| r.map.spectral_radius[row * n_delta..(row + 1) * n_delta].to_vec();
    let mut written = Vec::new();
    if let Some(path) = &csv {
        let mut text = String::from("preliminary_feedback,delta [s],alpha [1/s],rho,stable\n");
        for r in &results {
            let pf = name(r.pf);
            for (i, alpha) in alphas.iter().enumerate() {
                for (j, delta) in deltas.iter().enumerate() {
                    let rho = r.map.at(i, j);
                    text += &format!("{pf},{delta},{alpha},{rho},{}\n", rho < 1.0);
                }
            }
        }
        write_file("--csv", path, &text)?;
        written.push(format!("ρ written to {path} ({} rows)", results.len() * n_delta * n_alpha));
    }
    if let Some(path) = &svg {
        let title = format!(
            "Spectral radius ρ of the sampled loop (k = {}, m = {}, inner loop {})",
            config.controller.horizon_steps,
            config.controller.eps_ratio,
            name(config.inner_loop)
        );
        let panels: Vec<(&StabilityMap, &str)> = results.iter().map(|r| (&r.map, pf_caption(r.pf))).collect();
        write_file("--svg", path, &flexarm::svg::stability_maps_svg(&panels, &title, mark))?;
        written.push(format!("figure written to {path}"));
    }

    if json_out {
        let mut out = serde_json::Map::new();
        for r in &results {
            let mut v = serde_json::to_value(&r.map).map_err(|e| Failure(format!("JSON encoding failed: {e}"), 1))?;
            v["preliminary_feedback"] = json!(name(r.pf));
            v["inner_loop"] = json!(name(config.inner_loop));
            v["k"] = json!(config.controller.horizon_steps);
            v["eps_ratio"] = json!(config.controller.eps_ratio);
            v["stable_fraction"] = json!(r.stable_fraction());
            v["summary_alpha"] = json!(alphas[row]);
            v["stable_delta_intervals"] = json!(stable_intervals(&deltas, &row_rho(r)));
            v["failed_cells"] = json!(r.failed);
            v["seconds"] = json!(r.seconds);
            out.insert(name(r.pf), v);
        }
        return Ok(Value::Object(out).to_string() + "\n");
    }

    let cells = n_delta * n_alpha;
    let mut s = format!(
        "flexarm map: ρ of the sampled loop linearized at rest on {n_delta} δ × {n_alpha} α (logarithmic grid)\n  \
         δ from {} to {} s, α = α1 = α2 from {} to {} 1/s, k = {}, m = {}, inner loop {}\n  \
         {} × {cells} cells in {seconds:.2} s\n",
        delta_range.0,
        delta_range.1,
        alpha_range.0,
        alpha_range.1,
        config.controller.horizon_steps,
        config.controller.eps_ratio,
        name(config.inner_loop),
        results.len(),
    );
    let width = results.iter().map(|r| name(r.pf).len()).max().unwrap_or(0);
    for r in &results {
        let finite = r.map.spectral_radius.iter().copied().filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        let label = format!("PF {}:", name(r.pf));
        s += &format!(
            "{label:<w$} {:5.1} % of the cells stable (ρ < 1), ρ from {} to {}",
            100.0 * r.stable_fraction(),
            sig3(lo),
            sig3(hi),
            w = width + 4
        );
        if r.failed > 0 {
            s += &format!(", {} cells could not be analysed", r.failed);
        }
        s += "\n";
    }
    for r in &results {
        let intervals = stable_intervals(&deltas, &row_rho(r));
        s += &format!("PF {}, α = {} 1/s: ", name(r.pf), sig3(alphas[row]));
        if intervals.is_empty() {
            s += "unstable for every δ in the grid\n";
            continue;
        }
        let list: Vec<String> = intervals.iter().map(|[a, b]| format!("[{}, {}]", sig3(*a), sig3(*b))).collect();
        s += &format!("stable for δ in {} s", list.join(", "));
        let edges: Vec<String> = [deltas[0], deltas[n_delta - 1]]
            .into_iter()
            .filter(|e| intervals.iter().flatten().any(|v| v == e))
            .map(|e| format!("{} s", sig3(e)))
            .collect();
        if !edges.is_empty() {
            s += &format!(" ({} = end of the grid)", edges.join(" and "));
        }
        s += "\n";
    }
    for line in written {
        s += &line;
        s += "\n";
    }
    Ok(s)
}

// -------------------------------------------------------------------------------------------- main

fn run(mut args: Args) -> Res<String> {
    let Some(command) = args.0.next() else {
        return Err(usage_error("no command given: use simulate, analyze, sweep, map or help (see 'flexarm --help')"));
    };
    if args.0.as_slice().iter().any(|a| a == "--help" || a == "-h") {
        return Ok(USAGE.to_string());
    }
    match command.as_str() {
        "help" | "--help" | "-h" => Ok(USAGE.to_string()),
        "simulate" => simulate(args),
        "analyze" => analyze(args),
        "sweep" => sweep(args),
        "map" => map(args),
        other => Err(usage_error(format!("unknown command '{other}': use simulate, analyze, sweep, map or help"))),
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
