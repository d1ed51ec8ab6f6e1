//! `flexarm figure`: one panel of the page as a standalone SVG figure — the same figure as the
//! page's "Figure" download ([`flexarm::view::figure`]): the session runs to a time (`--time` or
//! the state's `t=`), so that the traces exist, and the panel is drawn from the view's geometry
//! with its title, axes, key and the state string as its caption.

use clap::{ArgMatches, Command};
use flexarm::control::Work;
use flexarm::schema;
use flexarm::session::{Session, Source};
use flexarm::view::figure::{figure_svg_with, FigureOptions, FigurePanel};

use crate::cli::{self, lib_error, usage_error, write_file, Res};
use crate::long_work;
use crate::simulate::KEYS;

/// Seconds run when neither `--time` nor the state's `t=` says.
const DEFAULT_TIME: f64 = 5.0;

const REDIRECTS: &[(&str, &str)] = &[(
    "png",
    "--svg (flexarm writes SVG only: rasterize it with a browser or an SVG converter, or save a PNG at 1×, 2× or 4× \
     from the page's Figure row)",
)];

pub fn command() -> Command {
    cli::command(
        "figure",
        "One panel as an SVG figure (the page's Figure download): its title, axes, key and the state string as its \
         caption, after running the session to --time",
    )
    .args(cli::run_args(KEYS))
    .arg(cli::option("panel", "NAME", format!("The panel to draw: {}", FigurePanel::names())).required(true))
    .arg(cli::option("svg", "FILE", "Write the figure to FILE (default: standard output)"))
    .arg(cli::option(
        "time",
        "S",
        format!(
            "Run the session to t = S seconds first, as a link's moment t= does: {} (default: the state's t=, else \
             {DEFAULT_TIME} s)",
            schema::START_TIME.number().map_or(String::new(), |n| n.allowed_text(schema::START_TIME.unit))
        ),
    ))
    .arg(long_work::force_arg())
    .arg(cli::flag("dark", "Draw on a dark background (the page's dark scheme) instead of the light one"))
    .arg(cli::option(
        "background",
        "page|white|transparent",
        "The paper: the page's (default), white, or none (a slide's own shows)",
    ))
    .arg(cli::option(
        "text",
        "normal|large|larger|largest",
        "The text size (default: the state's text=, else normal): larger text on a figure of about the same size",
    ))
    .arg(cli::option(
        "caption",
        "full|settings|none",
        "The caption: what it shows and the whole state string (full, the default), the settings of the runs \
         only (without the view's keys), or none",
    ))
    .arg(cli::flag("wide", "A 16:9 figure, a slide's shape: the panels grow to fill it"))
    .args(cli::redirects(REDIRECTS))
}

pub fn run(m: &ArgMatches) -> Res<String> {
    cli::check_redirects(m, "figure", REDIRECTS)?;
    let name = m.get_one::<String>("panel").map(String::as_str).unwrap_or("");
    let panel = FigurePanel::parse(name).map_err(|e| usage_error(format!("--panel: {e}")))?;
    let mut settings = cli::read_settings_of(m, KEYS, true)?;
    // The page's own keys, which other commands ignore, say what the figure shows (plane=z,
    // log=1, predict=1, measure=rate, compare=1 and run B) and when (t=): read as strictly.
    if let Some(state) = m.get_one::<String>("state") {
        let mut page = settings;
        page.read(state, Source::Lesson).map_err(|e| usage_error(format!("--state: {}", lib_error(e).0)))?;
        settings.view = page.view;
        settings.b = page.b;
        settings.start = page.start;
    }
    // --time is the page's moment t=, with its limit and the reason for it.
    let time = match m.get_one::<String>("time") {
        Some(text) => schema::START_TIME.parse(text, false).map_err(lib_error)?.number().unwrap_or(DEFAULT_TIME),
        None if settings.start.time > 0.0 => settings.start.time,
        None => DEFAULT_TIME,
    };
    let runs = if settings.b.is_some() { 2.0 } else { 1.0 };
    let work = Work::of_run(&settings.a.config(), time).times(runs);
    long_work::check(m, "running to this moment", work, "choose an earlier --time or a longer --delta")?;
    let mut session = Session::new(settings).map_err(lib_error)?;
    // In steps, so that a run of more than a few seconds shows its progress on stderr.
    let mut progress = long_work::Progress::new("figure", work);
    const STEPS: u32 = 50;
    for i in 1..=STEPS {
        let fraction = f64::from(i) / f64::from(STEPS);
        session.run_to(time * fraction).map_err(lib_error)?;
        progress.update(fraction);
    }
    progress.finish();
    // ρ(δ) and the marks on the maps need the stable windows; the maps, every row.
    session.refresh();
    if panel.kinds().iter().any(|k| k.is_map()) && !session.answers_hidden() {
        session.maps_mut().enabled = true;
        let mut clock = 0.0;
        let mut now = || {
            clock += 1.0;
            clock
        };
        while session.maps_mut().work(&mut now, 1e9) {}
    }
    // The study against δ (asked for by name, whatever the page's switch says), run to its end:
    // one simulated slew per δ with the sensors and one with perfect ones.
    if panel == FigurePanel::Study && session.reads_sensors() {
        while !session.sensor_study_step(1).map_err(lib_error)?.done {}
    }
    let figure =
        figure_svg_with(&session, &session.state_string(), panel.id(), &figure_options(m)?).map_err(lib_error)?;
    match m.get_one::<String>("svg") {
        Some(path) => {
            write_file("--svg", path, &figure.svg)?;
            Ok(format!(
                "wrote the figure '{}' ({} × {} px) at t = {} s to {path}\n",
                panel.id(),
                figure.width,
                figure.height,
                flexarm::plot::format::significant_trimmed(session.run(0).map_or(0.0, |r| r.closed_loop().time()), 4)
            ))
        }
        None => Ok(figure.svg),
    }
}

/// The figure's options from the command line, read by the page's reader (one set of names).
fn figure_options(m: &ArgMatches) -> Res<FigureOptions> {
    let mut pairs = vec![format!("dark={}", u8::from(m.get_flag("dark")))];
    if m.get_flag("wide") {
        pairs.push("shape=wide".into());
    }
    for key in ["background", "text", "caption"] {
        if let Some(v) = m.get_one::<String>(key) {
            pairs.push(format!("{key}={}", v.replace('&', "")));
        }
    }
    FigureOptions::parse(&pairs.join("&")).map_err(|e| usage_error(lib_error(e).0))
}
