//! The SVG figures: well-formed standalone documents with axes, units, the ρ colour bar, the
//! ρ = 1 contour, legends and the state string, and nothing non-finite in them.

use flexarm::analysis::{log_space, StabilityMap};
use flexarm::control::{Column, Traces};
use flexarm::plot::color::Measure;
use flexarm::plot::palette;
use flexarm::svg::{error_traces_svg, stability_map_svg, stability_maps_svg, MAX_TRACE_POINTS};

/// A synthetic map: ρ = 1 on the circle of radius 1 around the grid's centre in log space.
fn synthetic_map() -> StabilityMap {
    let deltas = log_space(0.002, 0.25, 30);
    let alphas = log_space(0.1, 5.0, 20);
    let (cx, cy) = ((0.002f64.ln() + 0.25f64.ln()) / 2.0, (0.1f64.ln() + 5.0f64.ln()) / 2.0);
    let mut rho = Vec::new();
    for a in &alphas {
        for d in &deltas {
            let r2 = (d.ln() - cx).powi(2) + (a.ln() - cy).powi(2);
            rho.push(0.8 + 0.2 * r2);
        }
    }
    StabilityMap { sampling_periods: deltas, alphas, spectral_radius: rho }
}

fn count(s: &str, pat: &str) -> usize {
    s.matches(pat).count()
}

fn assert_wellformed(svg: &str) {
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""), "{}", &svg[..80.min(svg.len())]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert_eq!(count(svg, "<svg"), 1);
    assert!(svg.contains("viewBox=\"0 0 ") && svg.contains("width=\"") && svg.contains("height=\""));
    // Paired elements open and close equally often; the others are self-closing.
    for tag in ["text", "g", "title", "desc", "defs", "linearGradient"] {
        assert_eq!(
            count(svg, &format!("<{tag}>")) + count(svg, &format!("<{tag} ")),
            count(svg, &format!("</{tag}>")),
            "<{tag}>"
        );
    }
    for tag in ["path", "rect", "circle", "stop"] {
        let opened = count(svg, &format!("<{tag} "));
        let closed = svg
            .split(&format!("<{tag} "))
            .skip(1)
            .filter(|rest| rest.split('>').next().unwrap().ends_with('/'))
            .count();
        assert_eq!(opened, closed, "every <{tag}> is self-closing");
    }
    assert_eq!(count(svg, "<"), count(svg, ">"), "angle brackets balance (text is escaped)");
    for bad in ["NaN", "inf", "Infinity"] {
        assert!(!svg.contains(bad), "{bad} in the output");
    }
}

#[test]
fn map_figure_is_wellformed_with_axes_colour_bar_contour_and_marker() {
    let map = synthetic_map();
    let svg = stability_map_svg(&map, "ρ <map> & more", Some((0.01, 2.0)));
    assert_wellformed(&svg);
    assert!(svg.contains("sampling period δ [s]"));
    assert!(svg.contains("stabilizing constant α [1/s]"));
    assert!(svg.contains("ρ (spectral radius)"));
    assert!(svg.contains("ρ &lt;map&gt; &amp; more"), "title escaped");
    assert!(!svg.contains("<map>"));
    let contour = svg.split("id=\"rho-contour-0\" d=\"").nth(1).expect("a contour path");
    let d = contour.split('"').next().unwrap();
    // A closed ring: one subpath, many vertices, closed.
    assert_eq!(count(d, "M"), 1, "{d}");
    assert!(count(d, "L") > 20 && d.ends_with('Z'), "{d}");
    assert!(svg.contains("<circle"), "the marker");
    // 1-2-5 tick labels per decade.
    for label in [">0.002<", ">0.005<", ">0.01<", ">0.02<", ">0.05<", ">0.1<", ">0.2<", ">0.5<", ">1<", ">2<", ">5<"] {
        assert!(svg.contains(label), "tick {label}");
    }
}

#[test]
fn the_map_figure_uses_the_canvas_colour_ramp() {
    let map = synthetic_map();
    let svg = stability_map_svg(&map, "ramp", None);
    // The cells near ρ = 0.8 are the canvas's darkest stable blue, the contour its contour colour.
    assert!(svg.contains(&palette::MAP_STABLE_FAR.css()), "the saturated stable colour");
    assert!(svg.contains(&format!("stroke=\"{}\"", palette::CONTOUR.css())));
    // The colour bar's middle stop is the ramp's neutral ρ = 1 colour.
    assert!(svg.contains(&format!("offset=\"0.5\" stop-color=\"{}\"", palette::MAP_NEUTRAL.css())));
}

#[test]
fn figures_carry_the_state_string() {
    let map = synthetic_map();
    let svg = stability_maps_svg(&[(&map, "off")], "t", None, Some("delta=0.01&pf=off&x=<1>"), Measure::Rho);
    assert_wellformed(&svg);
    assert!(svg.contains("<desc>flexarm state: delta=0.01&amp;pf=off&amp;x=&lt;1&gt;</desc>"));
    let svg = error_traces_svg(&traces(100, 1e-3), "t", Some("delta=0.04&pf=paper"));
    assert!(svg.contains("<desc>flexarm state: delta=0.04&amp;pf=paper</desc>"));
}

#[test]
fn nan_cells_and_points_are_skipped() {
    let mut map = synthetic_map();
    map.spectral_radius[5] = f64::NAN;
    map.spectral_radius[77] = f64::INFINITY;
    let svg = stability_map_svg(&map, "t", Some((f64::NAN, 2.0)));
    assert_wellformed(&svg);
    let svg = stability_maps_svg(&[(&map, "a"), (&map, "b")], "two", None, None, Measure::Rate);
    assert_wellformed(&svg);
    assert!(svg.contains("rho-contour-1"));
    // Degenerate grids still give a valid document.
    let single = StabilityMap { sampling_periods: vec![0.01], alphas: vec![2.0], spectral_radius: vec![0.9] };
    assert_wellformed(&stability_map_svg(&single, "one cell", None));
    let empty = StabilityMap { sampling_periods: vec![], alphas: vec![], spectral_radius: vec![] };
    assert_wellformed(&stability_map_svg(&empty, "empty", None));
}

fn traces(n: usize, amplitude: f64) -> Traces {
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.002).collect();
    let e1 = t.iter().map(|t| amplitude * (30.0 * t).sin() * (0.03 * t).exp()).collect();
    let e2 = t.iter().map(|t| -0.5 * amplitude * (7.0 * t).cos()).collect();
    Traces::from_columns([(Column::T, t), (Column::E1, e1), (Column::E2, e2)])
}

#[test]
fn traces_figure_is_wellformed_with_units_legend_and_decimation() {
    let tr = traces(30_000, 2e-3);
    let svg = error_traces_svg(&tr, "δ = 0.01 s & PF <off>", None);
    assert_wellformed(&svg);
    assert!(svg.contains("time t [s]"));
    assert!(svg.contains("e1 [mrad]") && svg.contains("e2 [mrad]"), "errors in mrad for mrad-sized traces");
    assert!(svg.contains("link 1 error e1") && svg.contains("link 2 error e2"), "legend");
    assert!(svg.contains("δ = 0.01 s &amp; PF &lt;off&gt;"));
    for name in ["e1", "e2"] {
        let d = svg.split(&format!("id=\"trace-{name}\" d=\"")).nth(1).unwrap().split('"').next().unwrap();
        let points = count(d, "M") + count(d, "L");
        assert!((1000..=MAX_TRACE_POINTS).contains(&points), "{name}: {points} points");
    }
    // The traces have the canvas's colours.
    assert!(svg.contains(&format!("stroke=\"{}\"", palette::ERROR1.css())));
    assert!(svg.contains(&format!("stroke=\"{}\"", palette::ERROR2.css())));
}

#[test]
fn traces_with_gaps_large_values_or_nothing_are_valid() {
    let tr = traces(500, 1.5);
    let mut e1 = tr.e1().to_vec();
    let mut e2 = tr.e2().to_vec();
    e1[100] = f64::NAN;
    e2[200] = f64::INFINITY;
    let tr = Traces::from_columns([(Column::T, tr.t().to_vec()), (Column::E1, e1), (Column::E2, e2)]);
    let svg = error_traces_svg(&tr, "diverged", None);
    assert_wellformed(&svg);
    assert!(svg.contains("e1 [rad]"));
    let d = svg.split("id=\"trace-e1\" d=\"").nth(1).unwrap().split('"').next().unwrap();
    assert_eq!(count(d, "M"), 2, "the NaN splits the line");
    assert_wellformed(&error_traces_svg(&Traces::default(), "empty", None));
    assert_wellformed(&error_traces_svg(&traces(1, 0.0), "one sample", None));
}

#[test]
fn long_titles_wrap_into_two_lines() {
    let long = "Tracking errors: δ = 0.01 s, α = 2 1/s, PF off — diverged at t = 4.138 s (a tracking error \
                exceeded 3.1416 rad)";
    let svg = error_traces_svg(&traces(10, 1e-3), long, None);
    assert_wellformed(&svg);
    let headings: Vec<&str> =
        svg.split("font-weight=\"bold\">").skip(1).map(|rest| rest.split("</text>").next().unwrap()).collect();
    assert_eq!(headings.len(), 2, "{headings:?}");
    assert!(headings[0].ends_with('—'), "{headings:?}");
    assert_eq!(headings[1], "diverged at t = 4.138 s (a tracking error exceeded 3.1416 rad)");
    let short = error_traces_svg(&traces(10, 1e-3), "ρ over (δ, α)", None);
    assert_eq!(short.matches("font-weight=\"bold\"").count(), 1);
}
