//! `flexarm data`: the numbers behind every figure — the model (arm, α, δ, k, ε, K_pr), the
//! linearized A, B, C, D, the one-period map Φ, its eigenvalues, ρ, A4, the ρ(δ) curve and both
//! stability maps on the page's grid — as JSON (default) or as one long CSV, the same as the
//! page's "Download the data" ([`flexarm::session::data`]).
//!
//! The JSON is the long table reshaped, one object per quantity (the page builds the same from
//! the CSV, `www/js/export.js`): `{"head": [lines], "state": "...", "quantities": {"A": {"rows":
//! [...], "columns": [...], "values": [[...]], "units": [[...]]}, ...}}`, non-finite numbers null.

use core::fmt::Display;

use clap::{ArgMatches, Command};
use flexarm::analysis;
use flexarm::schema;
use flexarm::session::data::{computed_maps, rho_curve, FigureData, Sink};
use serde_json::{json, Map, Value};

use crate::analyze::KEYS;
use crate::cli::{self, lib_error, usage_error, Res};

pub fn command() -> Command {
    cli::command(
        "data",
        "The numbers behind every figure: the model (arm, α, δ, k, ε, K_pr), the linearized A, B, C, D, the \
         one-period map Φ, its eigenvalues, ρ, A4, the ρ(δ) curve and both stability maps on the page's grid \
         (≈ 0.2 s), with units and the state string; JSON by default",
    )
    .args(cli::run_args(KEYS))
    .arg(cli::param_arg(&schema::Q2))
    .arg(cli::flag(
        "json",
        "Write JSON (the default): {head, state, quantities: {NAME: {rows, columns, values, units}}}",
    ))
    .arg(cli::flag(
        "csv",
        "Write one long CSV instead: quantity,i,j,row,column,value,unit, headed by # lines with the state string \
         and the units",
    ))
    .arg(cli::flag("no-maps", "Leave the two stability maps out (the rest takes a few milliseconds)"))
    .arg(cli::option("output", "FILE", "Write to FILE instead of standard output"))
}

/// The long table reshaped: one object per quantity, its rows and columns in the order written.
#[derive(Default)]
struct Tables(Map<String, Value>);

impl Sink for Tables {
    fn row(
        &mut self,
        quantity: &str,
        i: usize,
        j: usize,
        row: &dyn Display,
        column: &dyn Display,
        value: f64,
        unit: &str,
    ) {
        let table =
            self.0.entry(quantity).or_insert_with(|| json!({"rows": [], "columns": [], "values": [], "units": []}));
        let push = |key: &str, index: usize, item: Value, table: &mut Value| {
            let list = table[key].as_array_mut().expect("a list");
            if list.len() == index {
                list.push(item);
            }
        };
        push("rows", i, json!(row.to_string()), table);
        push("columns", j, json!(column.to_string()), table);
        push("values", i, json!([]), table);
        push("units", i, json!([]), table);
        // Non-finite numbers (ρ where an analysis failed, s of λ = 0) become null.
        let v = if value.is_finite() { json!(value) } else { Value::Null };
        table["values"][i].as_array_mut().expect("a row").push(v);
        table["units"][i].as_array_mut().expect("a row").push(json!(unit));
    }
}

pub fn run(m: &ArgMatches) -> Res<String> {
    if m.get_flag("json") && m.get_flag("csv") {
        return Err(usage_error("--json and --csv exclude each other: choose one (JSON is the default)"));
    }
    let settings = cli::read_settings(m, KEYS)?;
    let config = settings.a.config();
    let q2 = m.get_one::<String>(schema::Q2.key).map(|_| cli::number(m, &schema::Q2)).transpose()?;
    let report = analysis::analyze(&config, q2).map_err(lib_error)?;
    let windows = rho_curve(&config, q2).map_err(lib_error)?;
    let (jobs, omitted) = if m.get_flag("no-maps") {
        (Vec::new(), "the stability maps: left out (--no-maps)".to_string())
    } else {
        (computed_maps(&config, q2).map_err(lib_error)?, String::new())
    };
    let maps = jobs.iter().map(|(side, job)| (*side, job)).collect();
    let data =
        FigureData::new(&config, settings.run_query(), &report, Some(&windows), maps, omitted).map_err(lib_error)?;
    let (text, what) = if m.get_flag("csv") {
        (data.to_csv(), "CSV")
    } else {
        let mut tables = Tables::default();
        data.write(&mut tables);
        let value = json!({"head": data.head(), "state": data.state, "quantities": Value::Object(tables.0)});
        (format!("{value:#}\n"), "JSON")
    };
    match m.get_one::<String>("output") {
        Some(path) => {
            cli::write_file("--output", path, &text)?;
            Ok(format!("wrote the data ({what}) to {path}\n"))
        }
        None => Ok(text),
    }
}
