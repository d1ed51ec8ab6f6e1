//! What the maps and ρ(δ) measure (`measure=rho|rate`): ρ per sampling period, or the rate
//! ln ρ/δ per second, which compares across δ. The rate's colour ramp, the cells and the contour
//! under both, ρ(δ) as a rate, the tooltips, the state string, the SVG figure and the CLI flag.

mod common;

use flexarm::analysis::{log_space, stability_map, StabilityMap};
use flexarm::plot::color::{ramp_color, rate_color, rate_position, Measure, RATE_SHOWN};
use flexarm::plot::palette;
use flexarm::session::{Session, Settings, Source};
use flexarm::view::figure::{figure_svg, maps_figure};
use flexarm::view::panels::stability_maps::grid::{draw_map_static, LogFrame, StabilityGrid};
use flexarm::view::{Color, Painter, PanelInfo, PanelKind, Rect, Scene, Vertex, ViewOptions};
use flexarm::{PreliminaryFeedbackChoice, SimulationConfig};

fn lum(c: Color) -> f32 {
    c.0[..3].iter().sum()
}

// ------------------------------------------------------------------------------- the rate ramp

#[test]
fn the_rate_ramp_is_neutral_exactly_at_zero_and_monotone() {
    assert_eq!(rate_position(0.0), 0.5);
    assert_eq!(rate_color(0.0), palette::MAP_NEUTRAL);
    assert_eq!(rate_color(-0.0), palette::MAP_NEUTRAL);
    // The position rises strictly inside ± RATE_SHOWN and saturates outside.
    let rates: Vec<f64> = (-1000..=1000).map(|k| k as f64 * 0.01).collect();
    for w in rates.windows(2) {
        let (a, b) = (rate_position(w[0]), rate_position(w[1]));
        if w[1] <= -RATE_SHOWN || w[0] >= RATE_SHOWN {
            assert_eq!(a, b, "saturated between {} and {}", w[0], w[1]);
        } else {
            assert!(a < b, "rising between {} and {}: {a} vs {b}", w[0], w[1]);
        }
    }
    assert_eq!(rate_position(-RATE_SHOWN), 0.0);
    assert_eq!(rate_position(RATE_SHOWN), 1.0);
    assert_eq!(rate_color(f64::NEG_INFINITY), rate_color(-RATE_SHOWN));
    assert_eq!(rate_color(f64::INFINITY), rate_color(RATE_SHOWN));
    assert_eq!(rate_color(f64::NAN), palette::MAP_PENDING, "not computed: grey");
    // Darker the further from 0 on both sides: blue below (stable), red above.
    for w in rates.windows(2).filter(|w| w[0] >= 0.0 && w[1] <= RATE_SHOWN) {
        assert!(lum(rate_color(w[1])) < lum(rate_color(w[0])), "darker from {} to {}", w[0], w[1]);
        assert!(lum(rate_color(-w[1])) < lum(rate_color(-w[0])), "darker from −{} to −{}", w[0], w[1]);
    }
    let (stable, unstable) = (rate_color(-1.0).0, rate_color(1.0).0);
    assert!(stable[2] > stable[0] && unstable[0] > unstable[2], "{stable:?} {unstable:?}");
    // ±0.2 1/s is visibly coloured, as ρ = 1 ± 0.02 is on the ρ ramp.
    assert!(lum(rate_color(0.2)) < lum(palette::MAP_NEUTRAL) - 0.1);
    assert!(lum(rate_color(-0.2)) < lum(palette::MAP_NEUTRAL) - 0.1);
    // The same ramp as ρ's, at the rate's position.
    assert_eq!(rate_color(1.3), ramp_color(rate_position(1.3)));
}

#[test]
fn a_measure_colours_rho_or_its_rate() {
    for (rho, delta) in [(0.98, 0.01), (1.02, 0.2), (1.0, 0.05), (0.5, 0.002), (0.0, 0.1), (f64::INFINITY, 0.1)] {
        assert_eq!(Measure::Rho.color(rho, delta), flexarm::plot::rho_color(rho));
        assert_eq!(Measure::Rate.color(rho, delta), rate_color(rho.ln() / delta), "ρ = {rho}, δ = {delta}");
    }
    assert_eq!(Measure::Rate.color(f64::NAN, 0.01), palette::MAP_PENDING);
    // ρ = 0.99 is the same colour per period at every δ, but not per second.
    assert_eq!(Measure::Rho.color(0.99, 0.002), Measure::Rho.color(0.99, 0.2));
    assert!(lum(Measure::Rate.color(0.99, 0.002)) < lum(Measure::Rate.color(0.99, 0.2)) - 0.2);
    assert_eq!(Measure::from_name("rate"), Some(Measure::Rate));
    assert_eq!(Measure::from_name("ln"), None);
    assert_eq!(Measure::default(), Measure::Rho);
}

// ------------------------------------------------------------------------------ map cells

fn frame(grid: &StabilityGrid) -> LogFrame {
    LogFrame { rect: Rect::new(10.0, 20.0, 300.0, 200.0), x_range: grid.delta_range(), y_range: grid.alpha_range() }
}

fn painted(grid: &StabilityGrid, measure: Measure) -> Vec<Vertex> {
    let mut painter = Painter::new();
    draw_map_static(&mut painter, &frame(grid), grid, (&[], &[]), measure, 1.0);
    painter.vertices().to_vec()
}

/// The colour of the last triangle drawn under the point `p` (the cell there, unless a line
/// crosses it).
fn colour_at(vertices: &[Vertex], p: [f64; 2]) -> Option<[f32; 4]> {
    let inside = |t: &[Vertex]| {
        let [a, b, c] = [0, 1, 2].map(|i| [t[i].position[0] as f64, t[i].position[1] as f64]);
        let side = |u: [f64; 2], v: [f64; 2]| (v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]);
        let (d1, d2, d3) = (side(a, b), side(b, c), side(c, a));
        !((d1 < 0.0 || d2 < 0.0 || d3 < 0.0) && (d1 > 0.0 || d2 > 0.0 || d3 > 0.0))
    };
    vertices.chunks(3).rev().find(|t| inside(t)).map(|t| t[0].color)
}

#[test]
fn a_map_cell_under_rate_is_the_ramp_at_ln_rho_over_delta() {
    // One value not computed yet; the contour crosses between the rows, away from the points read.
    let deltas = [0.004, 0.016, 0.064];
    let alphas = [0.5, 2.0];
    let rho = [0.5, 0.9, 0.97, 1.3, 1.6, f64::NAN];
    let mut grid = StabilityGrid::default();
    grid.set(&deltas, &alphas, &rho).unwrap();
    let f = frame(&grid);
    for measure in [Measure::Rho, Measure::Rate] {
        let vertices = painted(&grid, measure);
        for (i, alpha) in alphas.iter().enumerate() {
            for (j, delta) in deltas.iter().enumerate() {
                let r = rho[i * deltas.len() + j];
                // Inside the cell, a little off its centre (the panel shows the grid's range: the
                // edge cells are half cells).
                let mut p = f.point(*delta, *alpha);
                p[0] += if j == 0 { 3.0 } else { -3.0 };
                p[1] += if i == 0 { -3.0 } else { 3.0 };
                let want = match measure {
                    Measure::Rho => flexarm::plot::rho_color(r),
                    Measure::Rate if r.is_nan() => palette::MAP_PENDING,
                    Measure::Rate => rate_color(r.ln() / delta),
                };
                assert_eq!(colour_at(&vertices, p), Some(want.0), "{measure:?} cell δ = {delta}, α = {alpha}");
            }
        }
    }
}

/// The vertices of the contour and its halo.
fn contour(vertices: &[Vertex]) -> Vec<Vertex> {
    let ink = [palette::CONTOUR.0, palette::CONTOUR_HALO.0];
    vertices.iter().filter(|v| ink.contains(&v.color)).copied().collect()
}

fn real_map(pf: PreliminaryFeedbackChoice) -> StabilityMap {
    let config = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
    stability_map(&config, &log_space(0.002, 0.25, 30), &log_space(0.1, 5.0, 8)).unwrap()
}

#[test]
fn the_contour_is_the_same_line_under_both_measures() {
    let map = real_map(PreliminaryFeedbackChoice::Off);
    let mut grid = StabilityGrid::default();
    grid.set(&map.sampling_periods, &map.alphas, &map.spectral_radius).unwrap();
    let (rho, rate) = (painted(&grid, Measure::Rho), painted(&grid, Measure::Rate));
    let line = contour(&rho);
    assert!(line.len() > 100, "the map without K_pr has a contour: {} vertices", line.len());
    assert!(line == contour(&rate), "the same contour");
    assert!(rho != rate, "but the cells differ");
    // The same in the SVG figure (`flexarm map --svg`): the contour's paths, in its colour.
    let paths = |svg: &str| -> Vec<String> {
        let fill = format!("fill=\"{}\"", palette::CONTOUR.css());
        svg.split("<path ").filter(|p| p.split('>').next().unwrap().contains(&fill)).map(str::to_owned).collect()
    };
    let svg_rho = map_svg(&map, Measure::Rho, None);
    let svg_rate = map_svg(&map, Measure::Rate, None);
    assert!(!paths(&svg_rho).is_empty(), "a contour");
    assert_eq!(paths(&svg_rho), paths(&svg_rate));
    assert_ne!(svg_rho, svg_rate);
}

/// The figure `flexarm map --svg` writes of one map without preliminary feedback.
fn map_svg(map: &StabilityMap, measure: Measure, mark: Option<(f64, f64)>) -> String {
    let config = SimulationConfig::default();
    maps_figure(&[(PreliminaryFeedbackChoice::Off, map)], &config, measure, mark, "t", "").unwrap().svg
}

#[test]
fn the_svg_figure_follows_the_measure() {
    let map = real_map(PreliminaryFeedbackChoice::Paper);
    let config = SimulationConfig::default();
    let svg =
        maps_figure(&[(PreliminaryFeedbackChoice::Paper, &map)], &config, Measure::Rate, Some((0.01, 2.0)), "t", "")
            .unwrap()
            .svg;
    let key = |class: &str| -> Vec<String> {
        svg.split(&format!("<text class=\"{class}\""))
            .skip(1)
            .map(|t| t.split_once('>').unwrap().1.split('<').next().unwrap().to_owned())
            .collect()
    };
    assert!(key("key").iter().any(|t| t == "ln ρ/δ (1/s)"), "the colour bar's title: {:?}", key("key"));
    assert!(!key("key").iter().any(|t| t == "ρ"), "not ρ's");
    assert!(key("key").iter().any(|t| t.starts_with("ln ρ/δ = 0 (ρ = 1)")), "the boundary in the key");
    for tick in [">≤ −5<", ">−1<", ">0<", ">1<", ">≥ 5<"] {
        assert!(svg.contains(tick), "colour-bar tick {tick}");
    }
    // Every cell's fill is the rate ramp at that cell.
    let nd = map.sampling_periods.len();
    let some = [(0, 0), (3, 7), (7, 29)]
        .map(|(i, j)| rate_color(map.spectral_radius[i * nd + j].ln() / map.sampling_periods[j]));
    for c in some {
        assert!(svg.contains(&format!("fill=\"{}\"", c.css())), "{}", c.css());
    }
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
}

// ------------------------------------------------------------------------ the page's figures

fn info<'a>(panels: &'a [PanelInfo], id: &str) -> &'a PanelInfo {
    panels.iter().find(|p| p.id == id).unwrap_or_else(|| panic!("no panel {id}"))
}

/// A full-view session with its stable windows and both maps computed.
fn computed(query: &str) -> Session {
    let mut s = common::session(&format!("mode=full&{query}"));
    common::play(&mut s, 0.2);
    s.refresh();
    let mut tick = 0.0;
    let mut clock = || {
        tick += 1.0;
        tick
    };
    while s.maps_mut().work(&mut clock, 50.0) {}
    s
}

#[test]
fn rho_of_delta_becomes_the_rate_with_zero_as_the_border() {
    let s = computed("delta=0.05&pf=off&measure=rate");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let curve = info(&panels, "rho-curve");
    assert_eq!((curve.x_label.as_str(), curve.y_label, curve.x_scale), ("δ [s]", "ln ρ/δ [1/s]", "log"));
    assert!(curve.y_range[0] <= -1.0 && curve.y_range[1] >= 1.0, "{:?}", curve.y_range);
    assert!(curve.y_range.iter().all(|v| v.fract() == 0.0), "whole 1/s: {:?}", curve.y_range);
    assert!(curve.note.starts_with("rate at α = 2 1/s"), "{}", curve.note);
    // Without K_pr at α = 2 the smallest δ grows at about the δ → 0 pair's rate, 2.4 1/s: it is
    // on the axis (ρ = 1.005 would sit on the line ρ = 1).
    assert!(curve.y_range[1] >= 3.0, "{:?}", curve.y_range);
    // Picking δ still works, and the tooltip gives both numbers.
    let f = (0.05f64 / 0.002).ln() / (0.25f64 / 0.002).ln();
    let (x, y) = (curve.x + f * curve.width, curve.y + curve.height / 2.0);
    let probe = scene.probe(x, y, 0.0).unwrap();
    assert_eq!((probe.kind, probe.title.as_str()), ("rho", "ln ρ/δ at this α"));
    assert!((probe.delta.unwrap() / 0.05 - 1.0).abs() < 0.01);
    assert!(probe.lines[1].text.starts_with("ρ = 0.") && probe.lines[1].tone == "good", "{:?}", probe.lines);
    assert!(probe.lines[2].text.starts_with("ln ρ/δ = −") && probe.lines[2].text.ends_with("1/s (per second)"));
    assert_eq!(info(&panels, "map-off").note, "rate, no Kₚᵣ");
    assert_eq!(info(&panels, "map-on").note, "rate, paper Kₚᵣ");
    // The key and the figure's words say which.
    let key = scene.legend();
    assert_eq!(
        key.iter().map(|g| g.title).collect::<Vec<_>>(),
        ["arm", "pole plot", "ln ρ/δ along δ", "stability maps"]
    );
    let scale = key[3].scale.as_ref().unwrap();
    assert_eq!(scale.name, "ln ρ/δ (1/s)");
    let zero = scale.ticks.iter().find(|(_, t)| t == "0").unwrap();
    assert_eq!(zero.0, 0.5, "0 in the middle of the bar");
    assert_eq!(scale.ticks.first().unwrap().1, "≤ −5");
    assert!(scale.label.contains("below 0 (stable)"), "{}", scale.label);
    assert!(key[3].items[0].text.starts_with("ln ρ/δ = 0"));
    assert!(s.figure_text().contains("coloured by ln ρ/δ"), "{}", s.figure_text());
}

#[test]
fn the_map_tooltip_gives_rho_and_the_rate_whatever_the_switch() {
    for measure in ["rho", "rate"] {
        let s = computed(&format!("delta=0.05&pf=off&measure={measure}"));
        let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
        scene.draw_session(&s);
        let panels = scene.panel_info();
        let map = info(&panels, "map-off");
        let probe = scene.probe(map.x + map.width / 2.0, map.y + map.height / 2.0, 0.0).unwrap();
        assert_eq!(probe.kind, "map");
        let (delta, alpha) = (probe.delta.unwrap(), probe.alpha.unwrap());
        let (cell_delta, rho) = scene.map(flexarm::session::MapSide::Off).near(delta, alpha);
        assert!(rho.is_finite());
        assert_eq!(
            probe.lines[1].text,
            format!("ρ = {rho:.3} per period: {}", if rho < 1.0 { "stable" } else { "unstable" })
        );
        let rate = flexarm::plot::format::significant(rho.ln() / cell_delta, 3);
        assert_eq!(probe.lines[2].text, format!("ln ρ/δ = {rate} 1/s (per second)"), "{measure}");
        let bar = &scene.legend().last().unwrap().scale.clone().unwrap();
        assert_eq!(bar.name, if measure == "rho" { "ρ" } else { "ln ρ/δ (1/s)" });
    }
}

#[test]
fn switching_the_measure_redraws_the_maps_and_the_curve() {
    let mut s = computed("delta=0.05&pf=off");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let (g0, rho_layer) = (scene.static_generation(), scene.static_vertices().to_vec());
    s.set("measure", "rate").unwrap();
    scene.draw_session(&s);
    assert!(scene.static_generation() > g0, "the static layer is rebuilt");
    assert!(scene.static_vertices() != &rho_layer[..]);
    // The maps' contours stay (ρ(δ)'s border line moves from ρ = 1 to ln ρ/δ = 0).
    let curve = scene.layout().to_physical(scene.layout().panel(PanelKind::RhoCurve).unwrap().rect);
    let maps = |v: &[Vertex]| -> Vec<Vertex> {
        let off_curve =
            |v: &Vertex| !curve.contains_rect(&Rect::new(v.position[0] as f64, v.position[1] as f64, 0.0, 0.0));
        contour(v).into_iter().filter(off_curve).collect()
    };
    let (now, before) = (maps(scene.static_vertices()), maps(&rho_layer));
    assert!(now.len() > 100 && now == before, "the contours stay: {} vs {} vertices", now.len(), before.len());
    let g1 = scene.static_generation();
    scene.draw_session(&s);
    assert_eq!(scene.static_generation(), g1, "and only once");
    s.set("measure", "rho").unwrap();
    scene.draw_session(&s);
    assert!(scene.static_vertices() == &rho_layer[..], "back to ρ");
    // The page's "Maps as a figure" follows the switch too.
    s.set("measure", "rate").unwrap();
    let svg = figure_svg(&s, "maps", false).unwrap().svg;
    assert!(svg.contains("Rate ln ρ/δ") && svg.contains(">ln ρ/δ (1/s)<"), "{}", &svg[..300]);
    assert!(svg.contains(">rate, no Kₚᵣ<") && svg.contains(">rate, paper Kₚᵣ<"), "the panels' captions");
}

// ----------------------------------------------------------------------- the state string

#[test]
fn the_state_string_carries_measure_rate_and_only_when_set() {
    for query in ["", "preset=fig5.3", "mode=full&plane=z"] {
        let (s, _) = Session::open(query);
        assert!(!s.state_string().contains("measure"), "default: {}", s.state_string());
    }
    assert!(!Settings::default().to_query().contains("measure"));
    assert!(!Settings::page_start().to_query().contains("measure"));
    let s = common::session("preset=fig5.3&mode=full&measure=rate");
    let q = s.state_string();
    assert!(q.contains("measure=rate"), "{q}");
    let again = common::session(&q);
    assert_eq!(again.settings().view.measure, Measure::Rate);
    assert_eq!(again.state_string(), q);
    // Written back to ρ, the key goes away again.
    let mut s = s;
    s.set("measure", "rho").unwrap();
    assert!(!s.state_string().contains("measure"), "{}", s.state_string());
    // A lesson step may set it; a bad value is refused there and skipped with a notice in a URL.
    let mut lesson = Settings::default();
    lesson.read("preset=fig5.3&measure=rate", Source::Lesson).unwrap();
    assert_eq!(lesson.view.measure, Measure::Rate);
    assert!(Settings::default().read("measure=ln", Source::Lesson).is_err());
    let (page, notices) = Session::open("measure=ln");
    assert_eq!(page.settings().view.measure, Measure::Rho);
    assert!(notices.iter().any(|n| n.key == "measure" && n.text.contains("rho | rate")), "{notices:?}");
    // The page builds its selector from the schema.
    let control = s.controls().into_iter().find(|c| c.key == "measure").expect("a control");
    assert_eq!(control.value, "rho");
}

// ------------------------------------------------------------------------------------ the CLI

fn flexarm(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().expect("flexarm runs")
}

#[test]
fn flexarm_map_measure_rate_writes_the_rate_figure_and_refuses_other_words() {
    let path = std::env::temp_dir().join(format!("flexarm-measure-test-{}.svg", std::process::id()));
    let p = path.to_str().unwrap();
    let out = flexarm(&["map", "--n-delta", "8", "--n-alpha", "3", "--measure", "rate", "--svg", p]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).ok();
    assert!(svg.contains("Rate ln ρ/δ (1/s) of the sampled loop"), "{}", &svg[..400]);
    // The colour bar's title (in the key).
    assert!(svg.contains(">ln ρ/δ (1/s)</text>"));
    let out = flexarm(&["map", "--n-delta", "8", "--n-alpha", "3", "--measure", "rho", "--svg", p]);
    assert!(out.status.success());
    assert!(std::fs::read_to_string(&path).unwrap().contains(">ρ</text>"));
    std::fs::remove_file(&path).ok();
    let out = flexarm(&["map", "--measure", "ln", "--svg", p]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.starts_with("error:") && stderr.trim_end().lines().count() == 1, "{stderr}");
    assert!(stderr.contains("--measure") && stderr.contains("rho | rate") && stderr.contains("'ln'"), "{stderr}");
    assert!(out.stdout.is_empty() && !path.exists());
    let help = String::from_utf8_lossy(&flexarm(&["map", "--help"]).stdout).into_owned();
    assert!(help.contains("--measure"), "{help}");
}

/// Where the map with the paper's K_pr turns red at large α, its tooltip says why (issue 22): the
/// gains' shift of Re A4 is fixed while the controller's feed grows; below the limit it says
/// nothing of the kind.
#[test]
fn the_kpr_map_says_why_it_turns_red_above_the_gains_alpha_limit() {
    let s = computed("delta=0.05&pf=paper");
    let limit = s.run(0).unwrap().analysis().report().unwrap().resonance.paper_alpha_limit;
    assert!((limit - 3.65).abs() < 0.01, "{limit}");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let map = info(&panels, "map-on");
    let said = |alpha: f64| {
        // α runs up the map logarithmically from 0.1 to 5 1/s.
        let f = (alpha / 0.1).ln() / (5.0f64 / 0.1).ln();
        let probe = scene.probe(map.x + map.width / 2.0, map.y + map.height * (1.0 - f), 0.0).unwrap();
        probe.lines.iter().any(|l| {
            l.text.starts_with(
                "above α = 3.65 1/s the paper's K_pr leaves the δ → 0 pair unstable: at this α the smallest δ fail",
            )
        })
    };
    assert!(said(4.5));
    assert!(!said(2.0));
}

/// A map's tooltip says what a click runs: the point rounded as the session rounds it (issue 20).
#[test]
fn the_map_tooltip_names_the_point_a_click_runs() {
    let mut s = computed("delta=0.05&pf=off");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let map = info(&panels, "map-off");
    let (x, y) = (map.x + map.width * 0.37, map.y + map.height * 0.61);
    let probe = scene.probe(x, y, 0.0).unwrap();
    let (delta, alpha) = (probe.delta.unwrap(), probe.alpha.unwrap());
    let said = probe.lines.last().unwrap().text.clone();
    s.set_from_map(flexarm::session::MapSide::Off, delta, alpha).unwrap();
    let a = s.settings().a;
    let fmt = flexarm::schema::format_number;
    assert_eq!(said, format!("click to run at δ = {} s, α = {} 1/s", fmt(a.delta), fmt(a.alpha[0])));
}
