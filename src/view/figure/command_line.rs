//! The command line's figures, drawn and written as every other figure is (a [`Sheet`]): `flexarm
//! simulate --svg` draws a run's errors over its whole duration from what the run kept of them
//! (an envelope: a run of any length in bounded memory), `flexarm map --svg` the maps computed on
//! the user's grid. Each takes what the command has — traces and the configuration, or maps —
//! rather than a page session.

use super::key::curve_key;
use super::sheet::{at_time, Figure, Sheet, Words};
use super::svg::Background;
use crate::analysis::StabilityMap;
use crate::control::config::{PreliminaryFeedbackChoice, SimulationConfig};
use crate::control::{Snapshot, Traces};
use crate::error::{Error, ParseError};
use crate::model::reference::Reference;
use crate::plot::color::Measure;
use crate::plot::{format, palette};
use crate::schema::PanelKind;
use crate::session::MapSide;
use crate::view::legend::LegendGroup;
use crate::view::panels::contract::RunState;
use crate::view::panels::time_plots::figure_curves;
use crate::view::scene::{Scene, ViewOptions};

/// Rows an envelope keeps for [`errors_figure`]: about 24 a pixel column of its plots, so that
/// each column's extremes are the run's own, whatever its length.
pub const ENVELOPE_ROWS: usize = 16_000;

/// The sheet of the panels `kinds` as a scene with `options` shows them (their title says what
/// the options show: ρ or ln ρ/δ, …), and that scene laid out on it, drawn from nothing yet.
/// A command line figure's words: captioned with the whole state string, on the page's paper.
fn page_words<'a>(head: &'a str, state: &'a str) -> Words<'a> {
    Words { caption: Some((head, state)), state, dark: false, background: Background::Page }
}

fn sheet_and_scene(kinds: &[PanelKind], options: ViewOptions) -> (Sheet, Scene) {
    let mut scene = Scene::new(options, 800.0, 600.0, 1.0);
    let (sheet, layout) = Sheet::new(&scene, kinds, 1.0);
    scene.set_layout(layout);
    (sheet, scene)
}

/// A state at simulated time `t` that only says the time: the time plots read nothing else of it,
/// and the figures of the command line draw no arm.
fn at(t: f64) -> Snapshot {
    Snapshot {
        time: t,
        q: [0.0; 3],
        qdot: [0.0; 3],
        qd: [0.0; 2],
        error: [0.0; 2],
        torque: [0.0; 2],
        v: [0.0; 2],
        xf_hat: [0.0; 2],
        w: [0.0; 2],
        error_meas: [0.0; 2],
        qdot_est: [0.0; 3],
    }
}

/// The errors e1 and e2 of a run of `config` over its whole duration (the time plots' window is
/// the run's), the slews shaded: `traces` are what the run kept of them (a [`TraceEnvelope`]'s,
/// or the whole run). `about` says what ran (the settings, the verdict), after the simulated
/// time, in the caption above the `state` string.
///
/// [`TraceEnvelope`]: crate::control::TraceEnvelope
pub fn errors_figure(traces: &Traces, config: &SimulationConfig, about: &str, state: &str) -> Figure {
    let kinds = &[PanelKind::Error1, PanelKind::Error2];
    let end = traces.t().iter().copied().filter(|t| t.is_finite()).fold(0.0, f64::max);
    // A run that has not left t = 0 still gets an axis.
    let options = ViewOptions { time_window: if end > 0.0 { end } else { 1.0 }, ..ViewOptions::default() };
    let (sheet, mut scene) = sheet_and_scene(kinds, options);
    let reference = Reference::new(config.reference);
    let snapshot = at(end);
    scene.draw_runs(
        RunState { reference: Some(&reference), config: Some(config), ..RunState::bare(&snapshot, traces) },
        None,
    );
    let mut groups: Vec<LegendGroup> = curve_key(figure_curves(kinds), None, None).into_iter().collect();
    groups.extend(scene.legend());
    sheet.write(&scene, &groups, page_words(&at_time(end, about), state))
}

/// The stability maps `maps` (each with the preliminary feedback it was computed with: none, and
/// the paper's or the LQ design's, one map each) side by side, coloured by `measure`, on the grid
/// they were computed on, with `mark` (δ, α) marked if given. `config` is the rest of their
/// settings (k, m, the inner loop). `about` says what was computed, in the caption above the
/// `state` string.
pub fn maps_figure(
    maps: &[(PreliminaryFeedbackChoice, &StabilityMap)],
    config: &SimulationConfig,
    measure: Measure,
    mark: Option<(f64, f64)>,
    about: &str,
    state: &str,
) -> Result<Figure, Error> {
    let bad = |expected: &str| {
        let names: Vec<&str> = maps.iter().map(|(pf, _)| pf.name()).collect();
        Error::Parse(ParseError { key: "maps".into(), text: names.join(", "), expected: expected.into() })
    };
    let sides: Vec<MapSide> = maps.iter().map(|(pf, _)| MapSide::for_feedback(*pf)).collect();
    let kinds: &[PanelKind] = match sides[..] {
        [MapSide::Off] => &[PanelKind::MapOff],
        [MapSide::On] => &[PanelKind::MapOn],
        [MapSide::Off, MapSide::On] => &[PanelKind::MapOff, PanelKind::MapOn],
        _ => return Err(bad("one map, or the map without preliminary feedback and one with it")),
    };
    // The run the maps are drawn for: its feedback names the map with it, its (δ, α) is the mark
    // (none: not a finite point, which the maps do not mark).
    let (delta, alpha) = mark.unwrap_or((f64::NAN, f64::NAN));
    let mut run = *config;
    run.preliminary_feedback = maps.last().map_or(run.preliminary_feedback, |(pf, _)| *pf);
    run.controller.sampling_period = delta;
    run.controller.alpha = [alpha; 2];

    let options = ViewOptions { measure, ..ViewOptions::default() };
    let (sheet, mut scene) = sheet_and_scene(kinds, options);
    for (side, (_, map)) in sides.iter().zip(maps) {
        scene.set_map(*side, &map.sampling_periods, &map.alphas, &map.spectral_radius).map_err(|e| bad(&e))?;
    }
    let (snapshot, traces) = (at(0.0), Traces::default());
    scene.draw_runs(RunState { config: Some(&run), ..RunState::bare(&snapshot, &traces) }, None);

    // The page's key, but for a point marked rather than run, and no stable windows (a run's).
    let mut groups = scene.legend();
    for g in &mut groups {
        g.items.retain_mut(|item| {
            if item.color == palette::WINDOW_MARK.css() {
                return false;
            }
            if item.color == palette::MAP_MARKER.css() {
                let Some((d, a)) = mark else { return false };
                item.text = format!("marked: δ = {} s, α = {} 1/s", format::number(d), format::number(a));
            }
            true
        });
    }
    Ok(sheet.write(&scene, &groups, page_words(about, state)))
}
