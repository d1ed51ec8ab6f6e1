//! `flexarm`: the command-line front end of the flexible-joint arm simulator.
//!
//! * `flexarm simulate` runs one closed-loop slew and prints a summary (or one JSON object, or
//!   writes the traces as CSV and the errors as SVG),
//! * `flexarm analyze` prints the linear stability analysis at rest (ρ, eigenvalues, the δ → 0
//!   pair A4),
//! * `flexarm sweep` tabulates ρ (and optionally simulation verdicts) over lists of δ and α,
//! * `flexarm map` computes ρ on a logarithmic (δ, α) grid without and/or with preliminary
//!   feedback, summarizes it, and writes it as CSV, JSON or an SVG figure,
//! * `flexarm export-python` writes the model as a Python script (NumPy, SciPy),
//! * `flexarm data` writes the numbers behind every figure (model, A, B, C, D, Φ, eigenvalues, ρ(δ),
//!   the maps) as JSON or one long CSV,
//! * `flexarm figure` draws one panel of the page (arm, errors, pole plot, z-plane, ρ(δ), a map, …)
//!   as an SVG figure with its key and the state string as its caption,
//! * `flexarm bundle` writes the page as one HTML file that opens from disk with no server or
//!   network, starting at a state string and carrying a teacher's lesson.
//!
//! The flags of the run settings come from the schema ([`flexarm::schema`]), as do their ranges
//! and error messages. Bad input — including an output path that cannot be written — prints one
//! `error: ...` line to stderr and exits with status 2; a failed analysis exits with status 1.

mod analyze;
mod answers;
mod bundle;
mod cli;
mod data;
mod export_python;
mod figure;
mod lesson_link;
mod long_work;
mod map;
mod output;
mod simulate;
mod sweep;

use std::io::Write;

use clap::error::ErrorKind;
use clap::Command;

use cli::{Failure, Res};

const ABOUT: &str =
    "flexarm — predictive control of a flexible-joint robot arm (von Wissel, Nikoukhah & Campbell 1994)";

const AFTER: &str = "ρ is the spectral radius of the one-period map linearized at rest with the friction cancelled: \
                     ρ < 1 ⇒ that rest point is stable for small motions (errors behave like ρⁿ over many periods).\n\
                     'flexarm help COMMAND' or 'flexarm COMMAND --help' describes one command with all its flags \
                     ('-h' in short); 'flexarm help all' describes every command.";

fn commands() -> Vec<Command> {
    vec![
        simulate::command(),
        analyze::command(),
        sweep::command(),
        map::command(),
        export_python::command(),
        data::command(),
        figure::command(),
        bundle::command(),
        lesson_link::command(),
        answers::command(),
    ]
}

fn root() -> Command {
    Command::new("flexarm")
        .about(ABOUT)
        .version(env!("CARGO_PKG_VERSION"))
        .disable_help_subcommand(true)
        .subcommand_required(true)
        .subcommands(commands())
        .subcommand(
            Command::new("help")
                .about("Print this overview, one command's help with all its flags, or 'all' of them")
                .arg(clap::Arg::new("command").value_name("COMMAND|all").action(clap::ArgAction::Set)),
        )
        .after_help(AFTER)
}

/// The short overview (`flexarm --help`): the commands, one line each, and where to read more.
fn overview() -> String {
    root().render_help().to_string()
}

/// Every command with all its flags (`flexarm help all`: one place to read them all).
fn reference() -> String {
    let mut s = format!("{ABOUT}\n\n");
    for mut c in commands() {
        let name = c.get_name().to_string();
        s += &format!("──── flexarm {name} ────\n");
        s += &c.render_long_help().to_string();
        s += "\n";
    }
    s += AFTER;
    s += "\n";
    s
}

/// A clap error on one line: the message, its tips, and where to read more.
fn one_line(e: &clap::Error, command: Option<&str>) -> String {
    let rendered = e.render().to_string();
    let mut parts: Vec<String> = Vec::new();
    for line in rendered.lines().map(str::trim) {
        if line.is_empty() || line.starts_with("Usage:") || line.starts_with("For more information") {
            continue;
        }
        parts.push(line.trim_start_matches("error: ").to_string());
    }
    let see = match command {
        Some(c) => format!("see 'flexarm {c} --help'"),
        None => "see 'flexarm --help'".into(),
    };
    // A line that ends in ':' introduces the next ("not provided: --out <FILE>"), not a new clause.
    let mut text = String::new();
    for part in &parts {
        if !text.is_empty() {
            text.push_str(if text.ends_with(':') { " " } else { "; " });
        }
        text.push_str(part);
    }
    format!("{text} ({see})")
}

fn run(args: Vec<String>) -> Res<String> {
    let command = args.iter().find(|a| commands().iter().any(|c| c.get_name() == a.as_str())).cloned();
    let matches = match root().try_get_matches_from(std::iter::once("flexarm".to_string()).chain(args.iter().cloned()))
    {
        Ok(m) => m,
        Err(e) => {
            return match e.kind() {
                // `flexarm --help` is the overview of every command; `flexarm map --help` map's own.
                ErrorKind::DisplayHelp if command.is_none() => Ok(overview()),
                // `-h` the flags in short, `--help` with what each does (clap's help and long help).
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => Ok(e.render().to_string()),
                ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
                    if args.iter().any(|a| a == "-h" || a == "--help") =>
                {
                    Ok(overview())
                }
                ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
                    Err(cli::usage_error(
                        "no command given: use simulate, analyze, sweep, map, export-python, data, figure, bundle, lesson-link, answers or help (see 'flexarm --help')",
                    ))
                }
                _ => Err(cli::usage_error(one_line(&e, command.as_deref()))),
            };
        }
    };
    if let Some(c) = matches.subcommand_name().and_then(|name| commands().into_iter().find(|c| c.get_name() == name)) {
        cli::set_command(&c);
        long_work::limit()?;
    }
    match matches.subcommand() {
        Some(("simulate", m)) => simulate::run(m),
        Some(("analyze", m)) => analyze::run(m),
        Some(("sweep", m)) => sweep::run(m),
        Some(("map", m)) => map::run(m),
        Some(("export-python", m)) => export_python::run(m),
        Some(("data", m)) => data::run(m),
        Some(("figure", m)) => figure::run(m),
        Some(("bundle", m)) => bundle::run(m),
        Some(("lesson-link", m)) => lesson_link::run(m),
        Some(("answers", m)) => answers::run(m),
        Some(("help", m)) => match m.get_one::<String>("command") {
            None => Ok(overview()),
            Some(all) if all == "all" => Ok(reference()),
            Some(name) => match commands().into_iter().find(|c| c.get_name() == name) {
                // Exactly what `flexarm COMMAND --help` prints.
                Some(c) => run(vec![c.get_name().to_string(), "--help".into()]),
                None => Err(cli::usage_error(format!(
                    "unknown command '{name}': use simulate, analyze, sweep, map, export-python, data, figure, bundle, \
                     lesson-link, answers or all"
                ))),
            },
        },
        _ => Ok(overview()),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(args) {
        Ok(out) => {
            // Ignore a closed pipe (e.g. `flexarm analyze | head`) rather than panicking.
            let _ = std::io::stdout().lock().write_all(out.as_bytes());
        }
        Err(Failure(msg, code)) => {
            eprintln!("error: {}", msg.replace('\n', " "));
            std::process::exit(code);
        }
    }
}
