//! The command line's figures (`flexarm simulate --svg`, `flexarm map --svg`), written by the one
//! figure writer (`view::figure`) as every figure is: well-formed standalone SVG with axes and
//! their units, a key, the ρ = 1 contour and the colour bar on the maps, the whole state string in
//! the caption, nothing non-finite even for a diverging run, and text escaped.

#[path = "figure/reading.rs"]
mod reading;

use flexarm::analysis::{log_space, StabilityMap};
use flexarm::control::{Column, Traces};
use flexarm::plot::color::Measure;
use flexarm::plot::palette;
use flexarm::view::figure::{errors_figure, maps_figure};
use flexarm::{PreliminaryFeedbackChoice as Pf, SimulationConfig};
use reading::{assert_wellformed, centroid, texts, triangles, triangles_in, Axes};

/// A state string with characters that must be escaped.
const STATE: &str = "delta=0.01&pf=off&x=<1>";

/// The centre of the synthetic map's ring, (ln δ, ln α).
fn centre() -> (f64, f64) {
    ((0.002f64.ln() + 0.25f64.ln()) / 2.0, (0.1f64.ln() + 5.0f64.ln()) / 2.0)
}

/// A synthetic map: ρ = 1 on the circle of radius 1 around the grid's centre in log space.
fn synthetic_map() -> StabilityMap {
    let deltas = log_space(0.002, 0.25, 30);
    let alphas = log_space(0.1, 5.0, 20);
    let (cx, cy) = centre();
    let mut rho = Vec::new();
    for a in &alphas {
        for d in &deltas {
            let r2 = (d.ln() - cx).powi(2) + (a.ln() - cy).powi(2);
            rho.push(0.8 + 0.2 * r2);
        }
    }
    StabilityMap { sampling_periods: deltas, alphas, spectral_radius: rho }
}

/// n samples 2 ms apart from t = 0 of a growing oscillation (e1) and a slower one (e2).
fn traces(n: usize, amplitude: f64) -> Traces {
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.002).collect();
    let e1 = t.iter().map(|t| amplitude * (30.0 * t).sin() * (0.03 * t).exp()).collect();
    let e2 = t.iter().map(|t| -0.5 * amplitude * (7.0 * t).cos()).collect();
    Traces::from_columns([(Column::T, t), (Column::E1, e1), (Column::E2, e2)])
}

fn errors(tr: &Traces) -> String {
    errors_figure(tr, &SimulationConfig::default(), "a run", STATE).svg
}

fn maps(list: &[(Pf, &StabilityMap)], measure: Measure, mark: Option<(f64, f64)>) -> String {
    maps_figure(list, &SimulationConfig::default(), measure, mark, "maps", STATE).unwrap().svg
}

/// The state string is the caption's, whole, and the figure's description.
fn assert_states(svg: &str, what: &str) {
    assert_eq!(texts(svg, "state").concat(), STATE, "{what}");
    assert!(svg.contains("<desc>flexarm state: delta=0.01&amp;pf=off&amp;x=&lt;1&gt;</desc>"), "{what}");
}

#[test]
fn the_errors_figure_shows_both_errors_over_the_whole_run_with_units_a_key_and_the_state() {
    let tr = traces(30_000, 2e-3);
    let svg = errors(&tr);
    assert_wellformed(&svg, "errors");
    assert!(!texts(&svg, "figure-title").is_empty(), "a title");
    let axes = texts(&svg, "axis");
    for label in ["e1 [rad]", "e2 [rad]", "t [s]"] {
        assert!(axes.iter().any(|a| a == label), "{label} among {axes:?}");
    }
    // The time axis is the run's, from its first sample to its last.
    let end = *tr.t().last().unwrap();
    for id in ["e1", "e2"] {
        let x = Axes::of(&svg, id).x;
        assert!(x[0] == 0.0 && (x[1] - end).abs() < 1e-9, "{id}: {x:?} for a run to {end} s");
    }
    // A key naming each curve, drawn in the plots' colours.
    assert!(!texts(&svg, "key-title").is_empty(), "a key");
    let key = texts(&svg, "key");
    for name in ["e1", "e2"] {
        assert!(key.iter().any(|k| k.starts_with(name)), "{name} in {key:?}");
    }
    assert!(!triangles(&svg, palette::ERROR1).is_empty() && !triangles(&svg, palette::ERROR2).is_empty());
    assert_states(&svg, "errors");
}

#[test]
fn a_long_run_costs_no_more_than_the_plot_is_wide_and_keeps_its_extremes() {
    let tr = traces(30_000, 2e-3);
    let svg = errors(&tr);
    let axes = Axes::of(&svg, "e1");
    let drawn = triangles(&svg, palette::ERROR1);
    // At most two points a pixel column, a segment two triangles.
    let columns = axes.rect[2].ceil() as usize;
    assert!(drawn.len() <= 2 * (2 * columns + 1), "{} triangles for {columns} columns", drawn.len());
    // The largest |e1| drawn is the run's, to within the line's width.
    let largest = tr.e1().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let per_px = (axes.y[1] - axes.y[0]) / axes.rect[3];
    let reach = drawn.iter().flatten().map(|p| axes.value(*p)[1].abs()).fold(0.0, f64::max);
    assert!((reach - largest).abs() < 2.0 * per_px, "drawn to {reach}, the run reached {largest}");
}

#[test]
fn the_maps_figure_has_log_axes_the_rho_1_contour_the_colour_bar_the_mark_and_the_state() {
    let map = synthetic_map();
    let svg = maps(&[(Pf::Off, &map), (Pf::Paper, &map)], Measure::Rho, Some((0.01, 2.0)));
    assert_wellformed(&svg, "maps");
    let shown: Vec<String> = ["axis", "title", "note"].iter().flat_map(|c| texts(&svg, c)).collect();
    for label in ["δ [s]", "α [1/s]", "ρ, no Kₚᵣ", "ρ, paper Kₚᵣ"] {
        assert!(shown.iter().any(|t| t == label), "{label} among {shown:?}");
    }
    // Decades and their 2s and 5s on both log axes.
    let ticks = texts(&svg, "tick");
    for t in ["0.005", "0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1", "2"] {
        assert!(ticks.iter().any(|k| k == t), "tick {t} in {ticks:?}");
    }
    // The ρ = 1 contour on each map: the ring at distance 1 from the centre in (ln δ, ln α).
    let contour = triangles_in(&svg, "static", palette::CONTOUR);
    let (cx, cy) = centre();
    for id in ["map-off", "map-on"] {
        let axes = Axes::of(&svg, id);
        let [x, y, w, h] = [axes.rect[0], axes.rect[1], axes.rect[2], axes.rect[3]];
        let on = |p: &[f64; 2]| p[0] >= x && p[0] <= x + w && p[1] >= y && p[1] <= y + h;
        let ring: Vec<[f64; 2]> = contour.iter().map(centroid).filter(on).collect();
        assert!(ring.len() > 20, "{id}: a contour of {} triangles", ring.len());
        for p in ring {
            let [d, a] = axes.log_value(p);
            let r = (d.ln() - cx).hypot(a.ln() - cy);
            // Linear interpolation of a quadratic on a coarse grid, and the line's width.
            assert!((r - 1.0).abs() < 0.06, "{id}: the contour at radius {r}");
        }
    }
    // The cells in the canvas's ramp: the smallest ρ (near the centre) and the largest (a corner).
    let rho = &map.spectral_radius;
    for extreme in [rho.iter().copied().fold(f64::INFINITY, f64::min), rho.iter().copied().fold(0.0, f64::max)] {
        let fill = format!("fill=\"{}\"", flexarm::plot::rho_color(extreme).css());
        assert!(svg.contains(&fill), "ρ = {extreme}: {fill}");
    }
    // The colour bar: the ramp's neutral colour in the middle; its ends and ρ = 1 labelled.
    assert!(svg.contains(&format!("offset=\"0.5\" stop-color=\"{}\"", palette::MAP_NEUTRAL.css())));
    let key = texts(&svg, "key");
    for t in ["≤ 0.8", "1", "≥ 1.2"] {
        assert!(key.iter().any(|k| k == t), "{t} in {key:?}");
    }
    assert!(key.iter().any(|k| k.starts_with("ρ = 1")), "the contour in the key: {key:?}");
    // The point marked, on the maps and in the key; none without a mark.
    assert!(!triangles(&svg, palette::MAP_MARKER).is_empty(), "the marker");
    assert!(key.iter().any(|k| k.contains("δ = 0.01 s, α = 2 1/s")), "the mark in the key: {key:?}");
    let plain = maps(&[(Pf::Off, &map)], Measure::Rho, None);
    assert!(triangles(&plain, palette::MAP_MARKER).is_empty(), "no marker");
    assert!(!texts(&plain, "key").iter().any(|k| k.contains("δ =")), "no mark in the key");
    assert_states(&svg, "maps");
    assert_states(&plain, "one map");
}

#[test]
fn nothing_non_finite_gets_into_a_figure_and_a_grid_that_is_no_grid_is_refused() {
    // A diverging run's traces: a stretch without numbers, an infinity, a huge value.
    let tr = traces(500, 1.5);
    let mut e1 = tr.e1().to_vec();
    let mut e2 = tr.e2().to_vec();
    e1[100..150].fill(f64::NAN);
    e2[200] = f64::INFINITY;
    e2[300] = 1e300;
    let tr = Traces::from_columns([(Column::T, tr.t().to_vec()), (Column::E1, e1), (Column::E2, e2)]);
    let svg = errors(&tr);
    assert_wellformed(&svg, "diverged");
    // No e1 where the run had no number (t from 0.2 to 0.298 s).
    let axes = Axes::of(&svg, "e1");
    let (from, to) = (axes.rect[0] + axes.rect[2] * 0.2 / axes.x[1], axes.rect[0] + axes.rect[2] * 0.298 / axes.x[1]);
    let inside =
        triangles(&svg, palette::ERROR1).iter().flatten().filter(|p| p[0] > from + 2.0 && p[0] < to - 2.0).count();
    assert_eq!(inside, 0, "the gap is left empty");
    assert_wellformed(&errors(&Traces::default()), "no samples");
    assert_wellformed(&errors(&traces(1, 0.0)), "one sample");

    // Maps with cells not computed or infinite, a mark that is no point.
    let mut map = synthetic_map();
    map.spectral_radius[5] = f64::NAN;
    map.spectral_radius[77] = f64::INFINITY;
    assert_wellformed(&maps(&[(Pf::Off, &map)], Measure::Rho, Some((f64::NAN, 2.0))), "holes");
    assert_wellformed(&maps(&[(Pf::Off, &map), (Pf::Lq, &map)], Measure::Rate, None), "rate");
    // Fewer than two values along an axis, or two maps for one side, are refused.
    let single = StabilityMap { sampling_periods: vec![0.01], alphas: vec![2.0], spectral_radius: vec![0.9] };
    let empty = StabilityMap { sampling_periods: vec![], alphas: vec![], spectral_radius: vec![] };
    let config = SimulationConfig::default();
    for list in [&[(Pf::Off, &single)][..], &[(Pf::Off, &empty)], &[(Pf::Paper, &map), (Pf::Lq, &map)], &[]] {
        assert!(maps_figure(list, &config, Measure::Rho, None, "t", STATE).is_err(), "{} maps", list.len());
    }
}

#[test]
fn text_is_escaped_and_a_long_caption_wraps_without_losing_a_word() {
    let about = "δ = 0.01 s & PF <off> — diverged at t = 4.138 s (a tracking error exceeded 3.1416 rad), with words \
                 enough for two lines in any figure";
    let svg = errors_figure(&traces(10, 1e-3), &SimulationConfig::default(), about, STATE).svg;
    assert_wellformed(&svg, "escaped");
    assert!(svg.contains("δ = 0.01 s &amp; PF &lt;off&gt;") && !svg.contains("<off>"));
    let lines = texts(&svg, "caption");
    assert!(lines.len() >= 2, "{lines:?}");
    let caption = lines.join(" ");
    assert!(caption.starts_with("flexarm at t = ") && caption.ends_with(about), "{caption}");
    let map = synthetic_map();
    let svg =
        maps_figure(&[(Pf::Off, &map)], &SimulationConfig::default(), Measure::Rho, None, "a <map> & more", STATE)
            .unwrap()
            .svg;
    assert!(svg.contains("a &lt;map&gt; &amp; more") && !svg.contains("<map>"));
}

#[test]
fn a_diverging_run_from_the_command_line_is_drawn_to_where_it_stopped() {
    let path = std::env::temp_dir().join(format!("flexarm-svg-{}.svg", std::process::id()));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_flexarm"))
        .args(["simulate", "--pf", "off", "--duration", "6", "--json", "--svg", path.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let svg = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).ok();
    assert_eq!(json["verdict"], "diverged", "Fig. 5.3 diverges within 6 s");
    assert_wellformed(&svg, "diverged run");
    assert_eq!(texts(&svg, "state").concat(), json["state"].as_str().unwrap(), "the run's state string");
    // Its time axis ends where the run stopped.
    let stopped = json["simulated_time"].as_f64().unwrap();
    let x = Axes::of(&svg, "e2").x;
    assert!(stopped < 6.0 && (x[1] - stopped).abs() < 0.01, "{x:?}, stopped at {stopped} s");
    assert!(texts(&svg, "caption").concat().contains("diverged"));
}
