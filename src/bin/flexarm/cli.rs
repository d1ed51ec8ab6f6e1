//! The command line built from the schema: every run parameter becomes a flag with its label,
//! unit, range and default as help; values are read by the schema, so the CLI, the page and the
//! URL accept and refuse the same things with the same words.

use std::sync::OnceLock;

use clap::parser::ValueSource;
use clap::{Arg, ArgAction, ArgMatches, Command};
use flexarm::error::Error;
use flexarm::schema::{self, Kind, Param};
use flexarm::session::query::split_query;
use flexarm::session::{Settings, Source};

/// A failure to report: the message (without `error: `) and the exit status.
pub struct Failure(pub String, pub i32);

pub type Res<T> = Result<T, Failure>;

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        lib_error(e)
    }
}

/// A mistake in the command line (status 2).
pub fn usage_error(msg: impl Into<String>) -> Failure {
    Failure(msg.into(), 2)
}

/// The visible long flags of the command being run, so that a hint names only flags it has.
static FLAGS: OnceLock<Vec<String>> = OnceLock::new();

/// Remembers the flags of the command about to run (called once, before it runs).
pub fn set_command(c: &Command) {
    let flags = c.get_arguments().filter(|a| !a.is_hide_set()).filter_map(|a| a.get_long()).map(|l| format!("--{l}"));
    let _ = FLAGS.set(flags.collect());
}

/// True if the command being run has `flag` (every flag before one is known).
pub fn has_flag(flag: &str) -> bool {
    FLAGS.get().is_none_or(|flags| flags.iter().any(|f| f == flag))
}

/// " (set with --X)": the flags of the command being run that set parameter `key`, or nothing
/// when it has none.
fn hint(key: &str) -> String {
    let (flags, join): (Vec<String>, &str) = match key {
        "eps_ratio" => (vec!["--eps-ratio".into(), "--k".into()], " and "),
        "alpha1" | "alpha2" => (vec![format!("--{}", key), "--alpha".into()], " or "),
        // A moment of the page is the figure's --time.
        "t" => (vec!["--time".into()], ""),
        "duration" => (vec!["--duration".into(), "--time".into()], " or "),
        _ => (vec![format!("--{}", key.replace('_', "-"))], ""),
    };
    let flags: Vec<String> = flags.into_iter().filter(|f| has_flag(f)).collect();
    if flags.is_empty() {
        String::new()
    } else {
        format!(" (set with {})", flags.join(join))
    }
}

/// A library error: the user's input (status 2), naming the flag that sets the parameter (if this
/// command has one); a failed analysis is a failure of the run (status 1).
pub fn lib_error(e: Error) -> Failure {
    match &e {
        Error::Config(c) => {
            let key = schema::PARAMS.iter().find(|p| p.name == c.parameter).map_or("", |p| p.key);
            usage_error(format!("{e}{}", hint(key)))
        }
        Error::Parse(p) => usage_error(format!("{e}{}", hint(&p.key))),
        Error::InvalidDuration(_) => usage_error(format!("{e}{}", hint("duration"))),
        Error::Refused(_) => usage_error(e.to_string()),
        Error::Analysis(_) | Error::Lesson { .. } | Error::NotReady(_) => Failure(e.to_string(), 1),
    }
}

/// The value name in usage lines: `S` for seconds, `A` for 1/s, `N` for counts, the choices.
fn value_name(p: &Param) -> String {
    match (&p.kind, p.unit) {
        (Kind::Choice { options, .. }, _) => options.iter().map(|o| o.value).collect::<Vec<_>>().join("|"),
        (Kind::Number(n), _) if n.integer => "N".into(),
        (_, "s") => "S".into(),
        (_, "1/s") => "A".into(),
        (_, "rad") => "RAD".into(),
        _ => "X".into(),
    }
}

/// What both help forms add to a parameter's label: "; default 0.01" (nothing for a switch that
/// is off) and ", s".
fn default_and_unit(p: &Param) -> (String, String) {
    let default = match p.default_value() {
        schema::Value::Switch(false) => String::new(),
        v => format!("; default {}", v.text()),
    };
    let unit = if p.unit.is_empty() { String::new() } else { format!(", {}", p.unit) };
    (default, unit)
}

/// The short help line of a parameter (`-h`): label, unit, range, default.
fn short_help(p: &Param) -> String {
    let (default, unit) = default_and_unit(p);
    let range = match &p.kind {
        Kind::Number(n) if n.min_inclusive => {
            format!(" ({}–{}{default})", schema::format_number(n.min), schema::format_number(n.max))
        }
        Kind::Number(n) => {
            format!(" (> {}, ≤ {}{default})", schema::format_number(n.min), schema::format_number(n.max))
        }
        Kind::Choice { .. } => format!(" ({}{default})", p.allowed(false)),
        Kind::Switch { .. } => String::new(),
    };
    format!("{}{unit}{range}", p.label)
}

/// The help of a parameter (`--help`): label, unit, range in words, default, what it does.
fn help(p: &Param) -> String {
    let (default, unit) = default_and_unit(p);
    let range = match &p.kind {
        Kind::Number(n) => format!(" ({}{default})", n.allowed_text(p.unit)),
        Kind::Choice { .. } => format!(" ({}{default})", p.allowed(false)),
        Kind::Switch { .. } => String::new(),
    };
    format!("{}{unit}{range}. {}", p.label, p.help)
}

/// A flag for a schema parameter.
pub fn param_arg(p: &'static Param) -> Arg {
    let long = p.flag().trim_start_matches("--").to_string();
    let arg = Arg::new(p.key).long(long).help(short_help(p)).long_help(help(p));
    match p.kind {
        Kind::Switch { .. } => arg.action(ArgAction::SetTrue),
        _ => arg.value_name(value_name(p)).allow_negative_numbers(true).action(ArgAction::Set),
    }
}

/// The flags of these run parameters, `--arm`, the arm's own and `--model` (every command that runs or
/// analyses the loop takes them), and `--state`.
/// The settings of the preliminary feedback's own design (the twist gains, the LQ weights): a
/// command that takes `pf` takes them too, so a new one is added here once.
const FEEDBACK_DESIGN: &[&str] = &["twist_stiffness", "twist_damping", "lq_q_twist", "lq_q_rate", "lq_r"];

/// `keys` with the feedback's design settings after `pf`.
fn with_design(keys: &[&str]) -> Vec<&'static str> {
    let mut out = Vec::new();
    for k in keys {
        if let Some(p) = schema::param(k) {
            out.push(p.key);
            if p.key == schema::PF.key {
                out.extend_from_slice(FEEDBACK_DESIGN);
            }
        }
    }
    out
}

pub fn run_args(keys: &[&str]) -> Vec<Arg> {
    let mut args: Vec<Arg> = with_design(keys).into_iter().filter_map(schema::param).map(param_arg).collect();
    let arms: Vec<&str> = flexarm::session::ARMS.iter().map(|a| a.id).collect();
    args.push(option(
        "arm",
        "ID",
        format!(
            "Start from one of these arms: {} (the paper's arm with one part changed; the arm's own flags change it further)",
            arms.join(" | ")
        ),
    ));
    args.extend(schema::ARM_PARAMS.iter().copied().chain([&schema::MODEL]).map(param_arg));
    args.extend(schema::SENSOR_PARAMS.iter().copied().map(param_arg));
    args.push(
        Arg::new("state")
            .long("state")
            .value_name("STATE")
            .help(
                "Settings as a state string, e.g. 'delta=0.01&alpha=2&pf=off' (the page's URL query, its \
                 'copy as command line' and the CSV/SVG headers give one); flags given as well override it",
            )
            .action(ArgAction::Set),
    );
    args
}

/// The settings of a command: the CLI's defaults, then `--state`, then each flag (in the schema's
/// order, so `--alpha` comes before `--alpha1`/`--alpha2`).
pub fn read_settings(m: &ArgMatches, keys: &[&str]) -> Res<Settings> {
    read_settings_of(m, keys, false)
}

/// [`read_settings`] for a command that draws the page (`figure`): the page's own keys in
/// `--state` are its to read, not ignored.
pub fn read_settings_of(m: &ArgMatches, keys: &[&str], uses_page_keys: bool) -> Res<Settings> {
    let keys = &with_design(keys)[..];
    let mut settings = Settings::default();
    let state = m.get_one::<String>("state").map_or("", String::as_str);
    if !state.is_empty() {
        let notices = settings
            .read(state, Source::CommandLine)
            .map_err(|e| usage_error(format!("--state: {}", lib_error(e).0)))?;
        // What the command sets aside is said, not silently dropped (`figure` reads the view's
        // keys itself).
        let ignored: Vec<&str> =
            notices.iter().map(|n| n.key.as_str()).filter(|k| !(uses_page_keys && page_key_drawn(k))).collect();
        if !ignored.is_empty() {
            eprintln!(
                "note: --state: this command ignores {} (the page's own: how it plays, what it shows, run B, its \
                 lesson)",
                ignored.join(", ")
            );
        }
    }
    if let Some(id) = m.get_one::<String>("arm") {
        settings.set_arm(id).map_err(lib_error)?;
    }
    for p in schema::PARAMS.iter().filter(|p| {
        keys.contains(&p.key) || schema::is_arm(p.key) || schema::is_sensor(p.key) || p.key == schema::MODEL.key
    }) {
        let text = match p.kind {
            Kind::Switch { .. } => m.get_flag(p.key).then(|| "1".to_string()),
            _ => m.get_one::<String>(p.key).cloned(),
        };
        if let Some(text) = text {
            settings.set_text(p.key, &text, Source::CommandLine).map_err(lib_error)?;
        }
    }
    // The one check across A1, A2, A3 blames what the user gave (flags first, then the state
    // string), not A3 whatever was changed.
    let given = |key: &&str| {
        m.value_source(key) == Some(ValueSource::CommandLine) || split_query(state).iter().any(|(k, _)| k == key)
    };
    let arm_keys = [&schema::A1, &schema::A2, &schema::A3];
    let flagged = arm_keys.iter().find(|p| m.value_source(p.key) == Some(ValueSource::CommandLine));
    let blamed = flagged.or_else(|| arm_keys.iter().find(|p| given(&p.key))).copied().unwrap_or(&schema::A3);
    settings.a.plant.check_mass_matrix(blamed).map_err(|e| lib_error(e.into()))?;
    settings.a.config().validate().map_err(|e| lib_error(e.into()))?;
    Ok(settings)
}

/// A page key that `figure` draws from (the view, run B, a moment), rather than ignores.
fn page_key_drawn(key: &str) -> bool {
    key != schema::SPEED.key && !matches!(key, "lesson" | "lesson_src")
}

/// A number of a CLI-only schema parameter (duration, output interval, q2), or its default.
pub fn number(m: &ArgMatches, p: &'static Param) -> Res<f64> {
    match m.get_one::<String>(p.key) {
        None => Ok(p.number().map_or(0.0, |n| n.default)),
        Some(text) => p.parse(text, false).map(|v| v.number().unwrap_or(f64::NAN)).map_err(lib_error),
    }
}

/// A finite decimal number (Rust would also accept "inf" and "NaN").
pub fn parse_number(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// A boolean flag.
pub fn flag(name: &'static str, help: &'static str) -> Arg {
    Arg::new(name).long(name).help(help).action(ArgAction::SetTrue)
}

/// An option with a value. A list or a pair (`LIST`, `A:B`, `RE,IM`) may start with a minus sign
/// (`--alpha -1,2`): it is read as the value, and its numbers are then checked against their
/// ranges, rather than taken for an unknown flag.
pub fn option(name: &'static str, value: &'static str, help: impl Into<String>) -> Arg {
    let listed = value == "LIST" || value.contains([':', ',']);
    Arg::new(name)
        .long(name)
        .value_name(value)
        .help(help.into())
        .allow_negative_numbers(true)
        .allow_hyphen_values(listed)
        .action(ArgAction::Set)
}

/// A subcommand with the common settings.
pub fn command(name: &'static str, about: &'static str) -> Command {
    Command::new(name).bin_name(format!("flexarm {name}")).about(about).disable_version_flag(true)
}

/// A file named on the command line could not be written: bad input, like any other argument
/// (status 2), named with its flag.
pub fn write_error(flag: &str, path: &str, e: std::io::Error) -> Failure {
    usage_error(format!("could not write {flag} file '{path}': {e}"))
}

/// Writes an output file; a failure is reported with the flag that named the file.
pub fn write_file(flag: &str, path: &str, contents: &str) -> Res<()> {
    std::fs::write(path, contents).map_err(|e| write_error(flag, path, e))
}

/// Flags that other commands have but this one does not, with the flag to use instead: hidden,
/// so that using one explains itself instead of a "did you mean" guess.
pub fn redirects(pairs: &[(&'static str, &'static str)]) -> Vec<Arg> {
    pairs
        .iter()
        .map(|(name, _)| Arg::new(*name).long(*name).hide(true).allow_negative_numbers(true).action(ArgAction::Set))
        .collect()
}

/// The error for the first redirected flag given.
pub fn check_redirects(m: &ArgMatches, command: &str, pairs: &[(&'static str, &'static str)]) -> Res<()> {
    match pairs.iter().find(|(name, _)| m.contains_id(name) && m.value_source(name).is_some()) {
        Some((name, instead)) => Err(usage_error(format!("--{name} is not available in '{command}': use {instead}"))),
        None => Ok(()),
    }
}
