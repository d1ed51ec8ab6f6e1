//! `flexarm sweep`: ρ (and optionally simulation verdicts) over lists of δ and α.

use clap::{ArgMatches, Command};
use flexarm::analysis;
use flexarm::control::Work;
use flexarm::schema;
use serde_json::{json, Value};

use crate::cli::{self, lib_error, parse_number, usage_error, Res};
use crate::long_work::{self, Progress, TraceSinks};
use crate::output::settings_json;
use crate::simulate::{simulation_json, Linear};
use flexarm::analysis::judgement::{judge, Prediction};
use flexarm::words::judgement::{judgement as in_words, prediction_word};

/// The run settings `sweep` takes besides its lists of δ and α.
pub const KEYS: &[&str] = &["pf", "friction", "inner", "repeat", "k", "eps_ratio"];

/// Flags of other commands, and what `sweep` has instead.
const REDIRECTS: &[(&str, &str)] = &[("alpha1", "--alpha LIST (α1 = α2)"), ("alpha2", "--alpha LIST (α1 = α2)")];

pub fn command() -> Command {
    cli::command("sweep", "Tabulate ρ (and, with --simulate, simulation verdicts) over lists of δ and α")
        .arg(
            cli::option(
                "delta_list",
                "LIST",
                "Sampling periods, s: a comma list 0.005,0.01,0.02 or START:STOP:N (N points, logarithmically spaced \
             when both ends are > 0)",
            )
            .long("delta"),
        )
        .arg(cli::option("alpha_list", "LIST", "Values of α = α1 = α2, 1/s, same syntax").long("alpha"))
        .args(cli::run_args(KEYS))
        .arg(cli::flag("simulate", "Also run each point for --duration s"))
        .arg(cli::param_arg(&schema::DURATION))
        .arg(cli::flag("json", "Print an array of JSON objects"))
        .arg(long_work::force_arg())
        .args(cli::redirects(REDIRECTS))
}

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

pub fn run(m: &ArgMatches) -> Res<String> {
    cli::check_redirects(m, "sweep", REDIRECTS)?;
    let settings = cli::read_settings(m, KEYS)?;
    let list = |name: &str, flag: &str, what: &str| -> Res<Vec<f64>> {
        let text = m.get_one::<String>(name).ok_or_else(|| usage_error(format!("sweep needs {flag} LIST ({what})")))?;
        parse_list(flag, text)
    };
    let deltas = list("delta_list", "--delta", "sampling periods in s")?;
    let alphas = list("alpha_list", "--alpha", "α = α1 = α2 in 1/s")?;
    let run = m.get_flag("simulate");
    let duration = cli::number(m, &schema::DURATION)?;
    // Every value is checked before any work starts (and before the estimate, which needs them);
    // δ and α are limited independently of each other.
    for (i, &delta) in deltas.iter().enumerate() {
        let alpha = alphas[i.min(alphas.len() - 1)];
        let mut point = settings;
        (point.a.delta, point.a.alpha) = (delta, [alpha, alpha]);
        point.a.config().validate().map_err(|e| lib_error(e.into()))?;
    }
    for &alpha in &alphas {
        let mut point = settings;
        (point.a.delta, point.a.alpha) = (deltas[0], [alpha, alpha]);
        point.a.config().validate().map_err(|e| lib_error(e.into()))?;
    }
    let points = (deltas.len() * alphas.len()) as f64;
    let mut work = Work::of_units(points, analysis::stability_map::SECONDS_PER_CELL);
    if run {
        for &delta in &deltas {
            let mut point = settings;
            point.a.delta = delta;
            work = work.plus(Work::of_run(&point.a.config(), duration).times(alphas.len() as f64));
        }
    }
    long_work::check(m, "this sweep", work, "sweep fewer or longer δ, or a shorter --duration")?;
    let mut progress = Progress::new("sweep", work);
    let mut quiet = Progress::new("sweep", Work::NONE);
    let mut done = 0.0;
    let mut rows = Vec::new();
    let mut text = format!("{:>10} {:>8} {:>12} {:>10}", "δ [s]", "α [1/s]", "ρ", "linear");
    // With sensors on: their noise floor at each δ, predicted, and with --simulate as simulated.
    let sensors = settings.a.sensors.is_digital();
    if sensors {
        text += &format!("  {:>18} {:>18}", "pred. RMS e1 [rad]", "pred. RMS T1 [N m]");
    }
    if run {
        text += &format!("  {:>28}  {:>21}  {:>21}", "simulation", "max |e| slew [rad]", "max |e| after [rad]");
        if sensors {
            text += &format!("  {:>18} {:>19} {:>10}", "RMS e1 rest [rad]", "T1 fluct. [N m]", "at limit");
        }
    }
    text += "\n";
    for &alpha in &alphas {
        for &delta in &deltas {
            let mut point = settings;
            point.a.delta = delta;
            point.a.alpha = [alpha, alpha];
            let c = point.a.config();
            let rho = analysis::spectral_radius(&c, None).map_err(lib_error)?;
            // ρ's verdict by the rule every command and the page use (borderline by the rate).
            let linear = Prediction::of_rho(rho, delta).map_or("—", prediction_word);
            let mut row = Value::Object(settings_json(&point.a, |_| true));
            row["spectral_radius"] = json!(rho);
            row["verdict"] = json!(linear);
            row["state"] = json!(point.run_query());
            text += &format!("{delta:>10.5} {alpha:>8.3} {rho:>12.6} {linear:>10}");
            if sensors {
                let floor = crate::output::noise_floor(&c).and_then(Result::ok);
                let cell = |v: Option<f64>| v.map_or("—".to_string(), |v| format!("{v:.3e}"));
                text += &format!(
                    "  {:>18} {:>18}",
                    cell(floor.map(|f| f.rms_error[0])),
                    cell(floor.map(|f| f.rms_torque[0]))
                );
                row["noise_floor"] = json!(floor);
            }
            if run {
                let sinks = TraceSinks { csv: None, envelope: None };
                let (m, _) = long_work::run(&c, duration, sinks, &mut quiet)?;
                let q2 = c.reference.end[1];
                let report = analysis::analyze(&c, Some(q2)).map_err(lib_error)?;
                let judgement = in_words(&judge(&m, Some(&report), None, &c, m.error));
                let verdict = judgement.verdict;
                let linear =
                    Linear { rho: Some(rho), q2, describes: analysis::describes(&c), judgement, processor: None };
                row["simulation"] = simulation_json(&point, &c, duration, &m, &linear);
                let [s1, s2] = m.max_error_slew;
                let [a1, a2] = m.max_error_after;
                text += &format!("  {verdict:>28}  {s1:>10.3e} {s2:>10.3e}  {a1:>10.3e} {a2:>10.3e}");
                if sensors {
                    let share = 100.0 * m.saturated[0].max(m.saturated[1]);
                    text += &format!(
                        "  {:>18.3e} {:>19.3e} {:>9.1}%",
                        m.rms_error_rest[0], m.torque_fluctuation_rest[0], share
                    );
                }
            }
            text += "\n";
            rows.push(row);
            done += 1.0;
            progress.update(done / points);
        }
    }
    progress.finish();
    Ok(if m.get_flag("json") { Value::Array(rows).to_string() + "\n" } else { text })
}
