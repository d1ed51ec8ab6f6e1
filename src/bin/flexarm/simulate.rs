//! `flexarm simulate`: one closed-loop run, its summary, and the traces as CSV or SVG.

use clap::{ArgMatches, Command};
use flexarm::analysis;
use flexarm::analysis::judgement::judge;
use flexarm::control::{Metrics, TraceEnvelope, Traces, Work};
use flexarm::schema;
use flexarm::session::Settings;
use flexarm::view::figure;
use flexarm::words::judgement::{judgement as in_words, JudgementText as Judgement};
use flexarm::words::verdict::growth as growth_text;
use flexarm::{SimulationConfig, Verdict};
use serde_json::{json, Value};
use std::io::{BufWriter, Write};

use crate::cli::{self, lib_error, write_file, Res};
use crate::long_work::{self, Progress, TraceSinks};
use crate::output::{delta_alpha_text, describe_config, processor, processor_json, processor_text, settings_json};

/// The run settings `simulate` takes.
pub const KEYS: &[&str] =
    &["delta", "alpha", "alpha1", "alpha2", "pf", "friction", "inner", "rest", "repeat", "k", "eps_ratio"];

pub fn command() -> Command {
    cli::command("simulate", "Run the closed loop from rest along the slew and summarize it")
        .args(cli::run_args(KEYS))
        .arg(cli::param_arg(&schema::DURATION))
        .arg(cli::param_arg(&schema::OUTPUT_INTERVAL))
        .arg(cli::option(
            "csv",
            "FILE",
            "Write the traces (t [s], q [rad], e [rad], T [N m], ...) to FILE, headed by the state string",
        ))
        .arg(cli::option("svg", "FILE", "Write a figure of the tracking errors e1, e2 over time to FILE (SVG)"))
        .arg(cli::flag("json", "Print one JSON object instead of the text summary"))
        .arg(long_work::force_arg())
}

pub fn run(m: &ArgMatches) -> Res<String> {
    let settings = cli::read_settings(m, KEYS)?;
    let duration = cli::number(m, &schema::DURATION)?;
    let mut config = settings.a.config();
    config.output_interval = cli::number(m, &schema::OUTPUT_INTERVAL)?;
    config.validate().map_err(|e| lib_error(e.into()))?;
    let work = Work::of_run(&config, duration);
    long_work::check(m, "this run", work, "choose a shorter --duration or a longer --delta")?;
    let json_out = m.get_flag("json");
    let state = settings.run_query();

    // The CSV is streamed to its file as the run goes; the figure keeps only an envelope.
    let csv_path = m.get_one::<String>("csv");
    let mut csv_file = match csv_path {
        Some(path) => {
            let file = std::fs::File::create(path).map_err(|e| cli::write_error("--csv", path, e))?;
            let mut out = BufWriter::new(file);
            let comment = format!("flexarm state: {state} | {}", settings.command_line(Some(duration)));
            Traces::write_csv_head(&mut out, Some(&comment)).map_err(|e| cli::write_error("--csv", path, e))?;
            Some((out, path.as_str()))
        }
        None => None,
    };
    let svg_path = m.get_one::<String>("svg");
    // A figure that cannot be written is known before the run, not after it.
    if let Some(path) = svg_path {
        std::fs::File::create(path).map_err(|e| cli::write_error("--svg", path, e))?;
    }
    let mut envelope = svg_path.map(|_| TraceEnvelope::new(figure::ENVELOPE_ROWS));
    let sinks = TraceSinks {
        csv: csv_file.as_mut().map(|(out, path)| (out as &mut dyn std::io::Write, *path)),
        envelope: envelope.as_mut(),
    };
    let mut progress = Progress::new("simulate", work);
    let (metrics, rows) = long_work::run(&config, duration, sinks, &mut progress)?;
    if let Some((mut out, path)) = csv_file {
        out.flush().map_err(|e| cli::write_error("--csv", path, e))?;
    }

    // The analysis at the rest point the settings choose, at the end of the run, and the verdict
    // decided from it and the run as the page decides it.
    let q2 = settings.a.rest.angles(&config, metrics.time)[1];
    let report = analysis::analyze(&config, Some(q2));
    let rho = report.as_ref().ok().map(|r| r.spectral_radius);
    let failed = report.as_ref().err().map(|e| e.to_string());
    let judgement = in_words(&judge(&metrics, report.as_ref().ok(), failed.as_deref(), &config, metrics.error));
    let linear =
        Linear { rho, q2, describes: analysis::describes(&config), judgement, processor: Some(processor(&config)) };
    let mut out = if json_out {
        simulation_json(&settings, &config, duration, &metrics, &linear).to_string() + "\n"
    } else {
        simulation_text(&config, duration, &metrics, &linear)
    };
    if let (Some(path), false) = (csv_path, json_out) {
        out += &format!("traces ({rows} rows) written to {path}\n");
    }
    if let (Some(path), Some(envelope)) = (svg_path, envelope) {
        let about = format!(
            "{}, PF {} — {}",
            delta_alpha_text(&config),
            config.preliminary_feedback.name(),
            linear.judgement.verdict
        );
        let figure = figure::errors_figure(&envelope.traces(), &config, &about, &state);
        write_file("--svg", path, &figure.svg)?;
        if !json_out {
            out += &format!("figure of the tracking errors written to {path}\n");
        }
    }
    Ok(out)
}

/// The linear analysis beside a run: ρ, where it was linearized, whether it describes the run,
/// and the verdict decided from both (the page's words).
pub struct Linear {
    pub rho: Option<f64>,
    /// q2 of the rest point, rad.
    pub q2: f64,
    /// False where the run's friction is not cancelled ([`analysis::describes`]).
    pub describes: bool,
    pub judgement: Judgement,
    /// The controller's prediction timed on this computer (issue 36); None where not asked
    /// (`sweep --simulate`: its rows are the settings', not the computer's).
    pub processor: Option<Result<flexarm::control::ControllerTime, flexarm::Error>>,
}

/// The run as one JSON object: the settings under their schema keys, the state string, the
/// metrics, ρ and the verdict.
pub fn simulation_json(
    settings: &Settings,
    c: &SimulationConfig,
    duration: f64,
    m: &Metrics,
    linear: &Linear,
) -> Value {
    let (at, reason) = match m.verdict {
        Verdict::Diverged { at, reason } => (Some(at), serde_json::to_value(reason).ok()),
        _ => (None, None),
    };
    let (amplitude, period) = match m.verdict {
        Verdict::BoundedOscillation { amplitude, period } => (Some(amplitude), Some(period)),
        _ => (None, None),
    };
    let (slew_amplitude, slew_period) = match m.verdict {
        Verdict::SlewLocked { amplitude, period } => (Some(amplitude), Some(period)),
        _ => (None, None),
    };
    // The settings under the schema's keys, once each; then what the run and ρ say.
    let mut v = Value::Object(settings_json(&settings.a, |_| true));
    let result = json!({
        "state": settings.run_query(),
        "output_interval": c.output_interval,
        "duration": duration,
        "simulated_time": m.time,
        "verdict": linear.judgement.verdict,
        "headline": linear.judgement.headline,
        "detail": linear.judgement.detail,
        "observed": linear.judgement.observed,
        "diverged_at": at,
        "divergence_reason": reason,
        "max_error_slew": m.max_error_slew,
        "max_error_after": m.max_error_after,
        "rms_error": m.rms_error,
        "growth_rate": m.growth_rate,
        "growth": growth_text(m.growth_rate, m.errors_at_floor),
        "errors_at_floor": m.errors_at_floor,
        "oscillation_amplitude": amplitude,
        "oscillation_period": period,
        "slew_response_amplitude": slew_amplitude,
        "slew_response_period": slew_period,
        "max_torque": m.max_torque,
        "rms_error_rest": m.rms_error_rest,
        "torque_fluctuation_rest": m.torque_fluctuation_rest,
        "saturated": m.saturated,
        "spectral_radius": linear.rho,
        "q2": linear.q2,
        "analysis_describes_run": linear.describes,
    });
    if let (Value::Object(v), Value::Object(result)) = (&mut v, result) {
        v.extend(result);
    }
    if let Some(time) = &linear.processor {
        v["controller_seconds_per_sample"] = processor_json(time);
    }
    v
}

fn simulation_text(c: &SimulationConfig, duration: f64, m: &Metrics, linear: &Linear) -> String {
    let j = &linear.judgement;
    let pair = |v: [f64; 2], unit: &str| format!("{:.3e}, {:.3e} {unit}", v[0], v[1]);
    let growth = growth_text(m.growth_rate, m.errors_at_floor);
    let slew = if c.reference.repeat_hold.is_some() { "the repeating slew" } else { "the 1-s slew" };
    let mut s = format!("flexarm simulate: {duration} s of {slew}\nconfiguration\n{}", describe_config(c));
    s += &format!("result (simulated {:.3} s)\n", m.time);
    s += &format!("  verdict                     {}\n", j.line());
    // What the simulation saw, in the words that go with the verdict (its own label alone could
    // read as a second verdict: "a limit cycle" while the transient hides a growth ρ predicts).
    s += &format!("  simulation                  {}\n", j.observed);
    s += &format!("  max |e1|, |e2| during slew  {}\n", pair(m.max_error_slew, "rad"));
    s += &format!("  max |e1|, |e2| after slew   {}\n", pair(m.max_error_after, "rad"));
    s += &format!("  RMS e1, e2                  {}\n", pair(m.rms_error, "rad"));
    s += &format!("  growth rate                 {growth}\n");
    s += &format!("  max |T1|, |T2|              {:.3}, {:.3} N m\n", m.max_torque[0], m.max_torque[1]);
    if c.sensors != flexarm::control::sensing::SensorModel::default() {
        s += &format!("  RMS e1, e2 at rest          {}\n", pair(m.rms_error_rest, "rad"));
        s +=
            &format!("  T1, T2 fluctuation at rest  {} (standard deviation)\n", pair(m.torque_fluctuation_rest, "N m"));
        if c.sensors.limit().is_some() {
            s += &format!(
                "  time at the torque limit    {:.1} %, {:.1} % (T1, T2)\n",
                100.0 * m.saturated[0],
                100.0 * m.saturated[1]
            );
        }
    }
    // The analysis line in the page's words (the same judgement as the verdict's).
    let rho = linear.rho.map_or("n/a (the analysis failed)".into(), |r| format!("{r:.6}"));
    s += &format!("  spectral radius ρ           {rho}\n  {}\n", j.rho);
    if let Some(time) = &linear.processor {
        s += &format!("  processor                   {}\n", processor_text(time));
    }
    s
}
