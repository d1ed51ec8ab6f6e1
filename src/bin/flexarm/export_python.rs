//! `flexarm export-python`: the model as a self-contained Python script (NumPy and SciPy) that
//! rebuilds the linearized loop for these settings and prints ρ, the eigenvalues and A4 — the
//! same script as the page's "Export as Python".

use clap::{ArgMatches, Command};
use flexarm::schema;
use flexarm::session::python::{python_script, TEMPLATE};

use crate::analyze::KEYS;
use crate::cli::{self, lib_error, Res};

pub fn command() -> Command {
    cli::command(
        "export-python",
        "The model as a Python script (NumPy, SciPy): the linearized loop for these settings, ρ, its eigenvalues \
         and A4; run it with --simulate for the nonlinear loop too (and --plot FILE.png to save its plot; without a \
         display it is saved to flexarm_errors.png)",
    )
    .args(cli::run_args(KEYS))
    .arg(cli::param_arg(&schema::Q2))
    .arg(cli::option("output", "FILE", "Write the script to FILE instead of standard output"))
}

pub fn run(m: &ArgMatches) -> Res<String> {
    let settings = cli::read_settings(m, KEYS)?;
    let config = settings.a.config();
    let q2 = m.get_one::<String>(schema::Q2.key).map(|_| cli::number(m, &schema::Q2)).transpose()?;
    let rest = [config.reference.end[0], q2.unwrap_or(config.reference.end[1])];
    let script = python_script(&config, rest, &settings.run_query(), TEMPLATE).map_err(lib_error)?;
    match m.get_one::<String>("output") {
        Some(path) => {
            cli::write_file("--output", path, &script)?;
            Ok(format!("wrote the script to {path} (run it: python3 {path})\n"))
        }
        None => Ok(script),
    }
}
