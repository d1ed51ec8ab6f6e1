//! Long work on the command line: estimated before it starts (refused over the limit unless
//! `--force`), run in bounded memory, with progress on stderr.

use std::io::{IsTerminal, Write};
use std::time::Instant;

use clap::{Arg, ArgMatches};
use flexarm::control::work::WORK_LIMIT_SECONDS;
use flexarm::control::{simulate_in_chunks, Metrics, TraceEnvelope, Work};
use flexarm::words::work::{duration as duration_text, estimate};
use flexarm::SimulationConfig;

use crate::cli::{self, usage_error, Failure, Res};

/// Simulated seconds per chunk of a run: the traces of one chunk are all that is held at once.
const CHUNK_SECONDS: f64 = 5.0;

/// The `--force` flag.
pub fn force_arg() -> Arg {
    cli::flag(
        "force",
        "Run even when the work is estimated to take longer than a minute (or FLEXARM_WORK_LIMIT seconds); \
         without it such work is refused with the estimate",
    )
}

/// The environment variable that sets the work limit in seconds (default [`WORK_LIMIT_SECONDS`]):
/// a faster machine may allow more, a test harness less.
pub const LIMIT_VARIABLE: &str = "FLEXARM_WORK_LIMIT";

/// The work limit in force, s: [`LIMIT_VARIABLE`] if set (empty counts as unset), else
/// [`WORK_LIMIT_SECONDS`]. A value that is not a number of seconds > 0 is refused, not ignored
/// (by every command, before it starts: a bad setting is said where it is made).
pub fn limit() -> Res<f64> {
    match std::env::var(LIMIT_VARIABLE) {
        Ok(text) if !text.trim().is_empty() => cli::parse_number(&text).filter(|v| *v > 0.0).ok_or_else(|| {
            usage_error(format!(
                "invalid {LIMIT_VARIABLE} = '{}': expected the work limit in seconds, a number > 0 (unset, it is {})",
                text.chars().map(|c| if c.is_control() { ' ' } else { c }).collect::<String>(),
                duration_text(WORK_LIMIT_SECONDS)
            ))
        }),
        _ => Ok(WORK_LIMIT_SECONDS),
    }
}

/// Refuses `work` over the limit unless `--force` was given (status 2, with the estimate and
/// what to change).
pub fn check(m: &ArgMatches, what: &str, work: Work, shorter: &str) -> Res<()> {
    let limit = limit()?;
    if work.is_over(limit) && !m.get_flag("force") {
        return Err(usage_error(format!(
            "{what} would take too long: {} (the limit is {}, set by {LIMIT_VARIABLE}); {shorter}, or add --force \
             to run it anyway",
            estimate(&work),
            duration_text(limit)
        )));
    }
    Ok(())
}

/// Progress on stderr for work estimated over a few seconds: a line rewritten in place on a
/// terminal, one line per 10 % otherwise.
pub struct Progress {
    label: &'static str,
    enabled: bool,
    terminal: bool,
    next_percent: u32,
    started: Instant,
    shown: bool,
}

impl Progress {
    pub fn new(label: &'static str, work: Work) -> Self {
        Progress {
            label,
            enabled: work.wants_progress(),
            terminal: std::io::stderr().is_terminal(),
            next_percent: 10,
            started: Instant::now(),
            shown: false,
        }
    }

    /// `fraction` (0 to 1) of the work is done.
    pub fn update(&mut self, fraction: f64) {
        let percent = (fraction.clamp(0.0, 1.0) * 100.0) as u32;
        if !self.enabled || percent < self.next_percent || percent >= 100 {
            return;
        }
        self.next_percent = (percent / 10 + 1) * 10;
        let elapsed = self.started.elapsed().as_secs_f64();
        let left = elapsed * (1.0 - fraction) / fraction.max(1e-9);
        let left = if left < 1.0 { "less than a second".to_string() } else { format!("about {}", duration_text(left)) };
        let line = format!("{}: {percent:>3} %, {left} left", self.label);
        let mut err = std::io::stderr().lock();
        let _ = if self.terminal { write!(err, "\r{line:<60}") } else { writeln!(err, "{line}") };
        self.shown = true;
    }

    /// Clears the progress line on a terminal.
    pub fn finish(&mut self) {
        if self.shown && self.terminal {
            eprint!("\r{:60}\r", "");
        }
        self.shown = false;
    }
}

/// Where a run's traces go while it runs: nowhere, a CSV file (streamed), an envelope for a
/// figure, or both.
pub struct TraceSinks<'a> {
    pub csv: Option<(&'a mut dyn Write, &'a str)>,
    pub envelope: Option<&'a mut TraceEnvelope>,
}

/// Runs `config` from rest for `duration` s, chunk by chunk, passing each chunk's traces to the
/// sinks: the memory does not grow with the duration. Returns the metrics and the rows seen.
pub fn run(
    config: &SimulationConfig,
    duration: f64,
    mut sinks: TraceSinks,
    progress: &mut Progress,
) -> Res<(Metrics, u64)> {
    let mut rows = 0u64;
    let metrics = simulate_in_chunks(config, duration, CHUNK_SECONDS, |traces, done| -> Result<(), Failure> {
        rows += traces.len() as u64;
        if let Some((out, path)) = sinks.csv.as_mut() {
            traces.write_csv_rows(out).map_err(|e| cli::write_error("--csv", path, e))?;
        }
        if let Some(env) = sinks.envelope.as_mut() {
            env.extend(traces);
        }
        progress.update(done);
        Ok(())
    });
    progress.finish();
    Ok((metrics?, rows))
}
