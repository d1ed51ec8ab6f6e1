//! `flexarm map`: ρ on a logarithmic (δ, α) grid without and/or with preliminary feedback, its
//! summary (the stable δ intervals near α = 2), and the map as CSV, JSON or an SVG figure.

use std::time::Instant;

use clap::{ArgMatches, Command};
use flexarm::analysis::judgement::Prediction;
use flexarm::analysis::stability_map::SECONDS_PER_CELL;
use flexarm::analysis::{stable_intervals, LinearSettings, MapGrid, MapJob, StabilityMap};
use flexarm::control::Work;
use flexarm::plot::color::Measure;
use flexarm::plot::format::significant_trimmed;
use flexarm::schema;
use flexarm::view::figure::maps_figure;
use flexarm::words::judgement::prediction_word;
use flexarm::PreliminaryFeedbackChoice;
use serde_json::{json, Value};

use crate::cli::{self, lib_error, parse_number, usage_error, write_file, Failure, Res};
use crate::long_work::{self, Progress};
use crate::output::settings_json;

/// The run settings a map takes besides its grid.
pub const KEYS: &[&str] = &["inner", "k", "eps_ratio"];
/// Flags of other commands, and what `map` has instead.
const REDIRECTS: &[(&str, &str)] = &[
    ("delta", "--delta-range A:B"),
    ("alpha", "--alpha-range A:B (α1 = α2)"),
    ("alpha1", "--alpha-range A:B (α1 = α2)"),
    ("alpha2", "--alpha-range A:B (α1 = α2)"),
    ("duration", "'flexarm simulate' (a map does not simulate)"),
    ("friction", "'flexarm simulate' (ρ does not depend on it)"),
];
/// The summary lists the stable δ intervals in the grid row with α nearest this (the paper's α).
const SUMMARY_ALPHA: f64 = 2.0;

pub fn command() -> Command {
    let g = MapGrid::DEFAULT;
    cli::command(
        "map",
        "ρ on a logarithmic (δ, α) grid; prints a summary with the stable δ intervals in the grid row of α \
         nearest 2 1/s (progress goes to stderr when it takes more than a few seconds)",
    )
    .arg(cli::option(
        "delta-range",
        "A:B",
        format!("Sampling periods from A to B s, 0 < A < B ≤ 10 (default {}:{})", g.delta[0], g.delta[1]),
    ))
    .arg(cli::option(
        "alpha-range",
        "A:B",
        format!("α = α1 = α2 from A to B 1/s, 0 < A < B ≤ 1000 (default {}:{})", g.alpha[0], g.alpha[1]),
    ))
    .arg(cli::option(
        "n-delta",
        "N",
        format!("Number of δ values, 2 to {} (default {})", MapGrid::MAX_POINTS, g.n_delta),
    ))
    .arg(cli::option(
        "n-alpha",
        "N",
        format!("Number of α values, 2 to {} (default {})", MapGrid::MAX_POINTS, g.n_alpha),
    ))
    .arg(
        cli::option(
            "map_pf",
            "P",
            "Preliminary feedback: off | paper | lq | both (default both: off and the paper's K_pr)",
        )
        .long("pf"),
    )
    .args(cli::run_args(KEYS))
    .args(cli::redirects(REDIRECTS))
    .arg(cli::option("mark", "D:A", "Mark the point δ = D s, α = A 1/s in the figure"))
    .arg(cli::option(
        "measure",
        "rho|rate",
        "What the figure's cells are coloured by: ρ per sampling period (rho, default) or the rate ln ρ/δ in \
         1/s (rate), which compares across δ; the ρ = 1 contour is ln ρ/δ = 0, the same line",
    ))
    .arg(cli::option(
        "csv",
        "FILE",
        "Write ρ to FILE, one row per PF and cell: pf,delta [s],alpha [1/s],rho,verdict (stable, borderline or unstable)",
    ))
    .arg(cli::option(
        "svg",
        "FILE",
        "Write the map as a figure to FILE (SVG); with --pf both the two maps side by side",
    ))
    .arg(cli::flag(
        "json",
        "Print one JSON object {PF: {sampling_periods, alphas, spectral_radius (row-major by α), ...}} instead of \
         the summary",
    ))
    .arg(long_work::force_arg())
}

/// `A:B` with 0 < A < B.
fn parse_range(flag: &str, text: &str, unit: &str) -> Res<[f64; 2]> {
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
    Ok([a, b])
}

fn parse_count(flag: &str, text: &str) -> Res<usize> {
    text.trim().parse::<usize>().ok().filter(|n| (2..=MapGrid::MAX_POINTS).contains(n)).ok_or_else(|| {
        usage_error(format!(
            "{flag} expects a whole number of grid points from 2 to {}, got '{text}'",
            MapGrid::MAX_POINTS
        ))
    })
}

/// One computed map and how long it took.
struct MapResult {
    pf: PreliminaryFeedbackChoice,
    map: StabilityMap,
    seconds: f64,
    /// Cells whose analysis failed (ρ = NaN).
    failed: usize,
}

/// The index of the α nearest [`SUMMARY_ALPHA`] (in log α).
fn summary_row(alphas: &[f64]) -> usize {
    let d = |a: f64| (a.ln() - SUMMARY_ALPHA.ln()).abs();
    (0..alphas.len()).min_by(|&i, &j| d(alphas[i]).total_cmp(&d(alphas[j]))).unwrap_or(0)
}

pub fn run(m: &ArgMatches) -> Res<String> {
    use PreliminaryFeedbackChoice as P;
    cli::check_redirects(m, "map", REDIRECTS)?;
    let settings = cli::read_settings(m, KEYS)?;
    let config = settings.a.config();
    let mut grid = MapGrid::DEFAULT;
    let text = |name: &str| m.get_one::<String>(name).map(String::as_str);
    if let Some(t) = text("delta-range") {
        grid.delta = parse_range("--delta-range", t, "s")?;
    }
    if let Some(t) = text("alpha-range") {
        grid.alpha = parse_range("--alpha-range", t, "1/s")?;
    }
    if let Some(t) = text("n-delta") {
        grid.n_delta = parse_count("--n-delta", t)?;
    }
    if let Some(t) = text("n-alpha") {
        grid.n_alpha = parse_count("--n-alpha", t)?;
    }
    let pfs: Vec<P> = match text("map_pf") {
        None | Some("both") => vec![P::Off, P::Paper],
        Some(t) => vec![P::from_name(t)
            .ok_or_else(|| usage_error(format!("--pf must be one of off | paper | lq | both, got '{t}'")))?],
    };
    // Read by the schema's view parameter, so the CLI and the page accept the same words.
    let measure = match text("measure") {
        None => Measure::Rho,
        Some(t) => schema::MEASURE
            .parse(t, false)
            .map_err(lib_error)?
            .choice()
            .and_then(Measure::from_name)
            .unwrap_or_default(),
    };
    let mark = match text("mark") {
        None => None,
        Some(v) => {
            let what = "a point D:A (δ in s, α in 1/s, both > 0)";
            let point = v
                .split_once(':')
                .and_then(|(d, a)| Some((parse_number(d)?, parse_number(a)?)))
                .filter(|(d, a)| *d > 0.0 && *a > 0.0);
            Some(point.ok_or_else(|| usage_error(format!("--mark expects {what}, got '{v}'")))?)
        }
    };
    // The ends of the ranges against the controller's limits.
    for (flag, [lo, hi], is_delta) in [("--delta-range", grid.delta, true), ("--alpha-range", grid.alpha, false)] {
        for end in [lo, hi] {
            let mut c = config.controller;
            if is_delta {
                c.sampling_period = end;
            } else {
                c.alpha = [end; 2];
            }
            if let Err(e) = c.validate() {
                let given = text(&flag[2..]).map(|t| format!(" '{t}'")).unwrap_or_default();
                return Err(usage_error(format!("{flag}{given}: {e}")));
            }
        }
    }

    let cells = (grid.n_delta * grid.n_alpha * pfs.len()) as f64;
    let work = Work::of_units(cells, SECONDS_PER_CELL);
    long_work::check(m, "this map", work, "use fewer --n-delta or --n-alpha")?;
    let mut progress = Progress::new("map", work);
    let (rows_total, mut rows_done) = ((grid.n_alpha * pfs.len()) as f64, 0.0);
    let started = Instant::now();
    let mut results = Vec::new();
    for &pf in &pfs {
        let pf_started = Instant::now();
        let settings = LinearSettings::of(&config, None).with_feedback(pf);
        let mut job = MapJob::on_grid(&settings, &grid).map_err(lib_error)?;
        while !job.is_done() {
            if let Err(e) = job.step_row() {
                progress.finish();
                return Err(lib_error(e));
            }
            rows_done += 1.0;
            progress.update(rows_done / rows_total);
        }
        let failed = job.failed_cells();
        let map = job.finish().map_err(lib_error)?;
        results.push(MapResult { pf, map, seconds: pf_started.elapsed().as_secs_f64(), failed });
    }
    progress.finish();
    let seconds = started.elapsed().as_secs_f64();

    let deltas = grid.deltas();
    let alphas = grid.alphas();
    let row = summary_row(&alphas);
    let state = settings.run_query();
    let mut written = Vec::new();
    if let Some(path) = text("csv") {
        let mut out = String::from("pf,delta [s],alpha [1/s],rho,verdict\n");
        for r in &results {
            for (i, alpha) in alphas.iter().enumerate() {
                for (j, delta) in deltas.iter().enumerate() {
                    let rho = r.map.at(i, j);
                    // ρ's verdict by the rule every command and the page use (borderline by the rate).
                    let verdict = Prediction::of_rho(rho, *delta).map_or("", prediction_word);
                    out += &format!("{},{delta},{alpha},{rho},{verdict}\n", r.pf.name());
                }
            }
        }
        write_file("--csv", path, &out)?;
        written.push(format!("ρ written to {path} ({} rows)", results.len() * grid.n_delta * grid.n_alpha));
    }
    if let Some(path) = text("svg") {
        // What the title (the measure) does not say: the grid and the loop's settings.
        let about = format!(
            "flexarm map: the sampled loop linearized at rest on {} δ × {} α (logarithmic grid); k = {}, m = {}, \
             inner loop {}",
            grid.n_delta,
            grid.n_alpha,
            config.controller.horizon_steps,
            config.controller.eps_ratio,
            config.inner_loop.name()
        );
        let maps: Vec<(PreliminaryFeedbackChoice, &StabilityMap)> = results.iter().map(|r| (r.pf, &r.map)).collect();
        let figure = maps_figure(&maps, &config, measure, mark, &about, &state).map_err(lib_error)?;
        write_file("--svg", path, &figure.svg)?;
        written.push(format!("figure written to {path}"));
    }

    if m.get_flag("json") {
        let mut out = serde_json::Map::new();
        for r in &results {
            let mut v = serde_json::to_value(&r.map).map_err(|e| Failure(format!("JSON encoding failed: {e}"), 1))?;
            // The settings ρ depends on under the schema's keys (the grid varies δ and α, each map
            // its own K_pr; the rest does not change ρ).
            let object = v.as_object_mut().ok_or_else(|| Failure("JSON encoding failed: not an object".into(), 1))?;
            object.extend(settings_json(&settings.a, |key| {
                !matches!(key, "delta" | "alpha1" | "alpha2" | "pf" | "friction" | "repeat" | "rest")
            }));
            v["pf"] = json!(r.pf.name());
            v["state"] = json!(state);
            v["stable_fraction"] = json!(r.map.stable_fraction());
            v["summary_alpha"] = json!(alphas[row]);
            v["stable_delta_intervals"] = json!(stable_intervals(&deltas, r.map.row(row)));
            v["failed_cells"] = json!(r.failed);
            v["seconds"] = json!(r.seconds);
            out.insert(r.pf.name().to_string(), v);
        }
        return Ok(Value::Object(out).to_string() + "\n");
    }

    let cells = grid.n_delta * grid.n_alpha;
    let mut s = format!(
        "flexarm map: ρ of the sampled loop linearized at rest on {} δ × {} α (logarithmic grid)\n  \
         δ from {} to {} s, α = α1 = α2 from {} to {} 1/s, k = {}, m = {}, inner loop {}\n  \
         {} × {cells} cells in {seconds:.2} s\n",
        grid.n_delta,
        grid.n_alpha,
        grid.delta[0],
        grid.delta[1],
        grid.alpha[0],
        grid.alpha[1],
        config.controller.horizon_steps,
        config.controller.eps_ratio,
        config.inner_loop.name(),
        results.len(),
    );
    let width = results.iter().map(|r| r.pf.name().len()).max().unwrap_or(0);
    for r in &results {
        let finite = r.map.spectral_radius.iter().copied().filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        let label = format!("PF {}:", r.pf.name());
        s += &format!(
            "{label:<w$} {:5.1} % of the cells stable (ρ < 1), ρ from {} to {}",
            100.0 * r.map.stable_fraction(),
            significant_trimmed(lo, 3),
            significant_trimmed(hi, 3),
            w = width + 4
        );
        if r.failed > 0 {
            s += &format!(", {} cells could not be analysed", r.failed);
        }
        s += "\n";
    }
    for r in &results {
        let intervals = stable_intervals(&deltas, r.map.row(row));
        s += &format!("PF {}, α = {} 1/s: ", r.pf.name(), significant_trimmed(alphas[row], 3));
        if intervals.is_empty() {
            s += "unstable for every δ in the grid\n";
            continue;
        }
        let list: Vec<String> = intervals
            .iter()
            .map(|[a, b]| format!("[{}, {}]", significant_trimmed(*a, 3), significant_trimmed(*b, 3)))
            .collect();
        s += &format!("stable for δ in {} s", list.join(", "));
        let edges: Vec<String> = [deltas[0], deltas[grid.n_delta - 1]]
            .into_iter()
            .filter(|e| intervals.iter().flatten().any(|v| v == e))
            .map(|e| format!("{} s", significant_trimmed(e, 3)))
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
