//! A figure per panel (issue 23, item 6): every panel's SVG is a well-formed standalone document
//! on a light background with its title, axes, key and the whole state string as its caption; the
//! physics read back from the figure through its axes (the flexible pair right of the imaginary
//! axis at Fig. 5.3, left of it at Fig. 5.2, outside the unit circle in the z-plane); a diverging
//! run's errors rise to the plot's edge; student mode refuses the analysis' figures.

mod common;
#[path = "figure/reading.rs"]
mod reading;

use flexarm::plot::palette;
use flexarm::session::{MapSide, Session};
use flexarm::view::figure::{figure_choices, figure_svg, FigurePanel};
use reading::{assert_wellformed, attr, background, centroid, count, luminance, texts, triangles, Axes};

/// The page's session for `query` in the full view (what its classroom hides, hidden), run to `t`
/// seconds, with ρ(δ)'s windows and (if `maps`) both maps computed.
fn session(query: &str, t: f64, maps: bool) -> Session {
    let mut s = common::visit(&format!("mode=full&{query}")).session;
    s.run_to(t).unwrap();
    s.refresh();
    if maps {
        let mut clock = 0.0;
        let mut now = || {
            clock += 1.0;
            clock
        };
        while s.maps_mut().work(&mut now, 1e9) {}
        assert!(MapSide::BOTH.iter().all(|&m| s.maps().shown(m).unwrap().is_done()));
    }
    s
}

fn svg(s: &Session, panel: &str) -> String {
    figure_svg(s, panel, false).unwrap_or_else(|e| panic!("{panel}: {e}")).svg
}

#[test]
fn every_panel_is_a_light_wellformed_figure_with_title_axes_key_and_the_whole_state() {
    let s = session("preset=fig5.3&torque=1", 3.0, true);
    let z = session("preset=fig5.3&plane=z", 3.0, false);
    let axes: [(&str, &Session, &[&str]); 12] = [
        ("arm", &s, &["arm, top view"]),
        ("errors", &s, &["e1 [rad]", "e2 [rad]", "t [s]"]),
        ("e1", &s, &["e1 [rad]", "t [s]"]),
        ("e2", &s, &["e2 [rad]", "t [s]"]),
        ("torque", &s, &["T1, T2 [N m]", "t [s]"]),
        ("poles", &s, &["Re s [1/s]", "Im s [rad/s]"]),
        ("zplane", &z, &["Re λ", "Im λ"]),
        ("rho", &s, &["δ [s]", "ρ"]),
        ("map-off", &s, &["δ [s]", "α [1/s]", "ρ, no Kₚᵣ"]),
        ("map-on", &s, &["δ [s]", "α [1/s]", "ρ, paper Kₚᵣ"]),
        ("maps", &s, &["ρ, no Kₚᵣ", "ρ, paper Kₚᵣ"]),
        ("z-plane", &z, &["Re λ"]),
    ];
    for (panel, s, labels) in axes {
        let figure = figure_svg(s, panel, false).unwrap();
        let svg = &figure.svg;
        assert_wellformed(svg, panel);
        assert!(luminance(&background(svg)) > 0.85, "{panel}: a light background, not {}", background(svg));
        assert!(!texts(svg, "figure-title").is_empty(), "{panel}: a title");
        let shown: Vec<String> = ["axis", "title", "note"].iter().flat_map(|c| texts(svg, c)).collect();
        for l in labels {
            assert!(shown.iter().any(|t| t == l), "{panel}: {l} among {shown:?}");
        }
        assert!(!texts(svg, "key-title").is_empty(), "{panel}: a key");
        assert_eq!(texts(svg, "state").concat(), s.state_string(), "{panel}: the whole state in the caption");
        assert!(svg.contains(&format!("width=\"{}\"", figure.width)), "{panel}");
        // Every triangle and text inside the figure.
        for t in triangles(svg, palette::ERROR1).iter().chain(&triangles(svg, palette::FRAME)) {
            for p in t {
                assert!(p[0] >= 0.0 && p[0] <= figure.width && p[1] >= 0.0 && p[1] <= figure.height, "{panel}: {p:?}");
            }
        }
    }
    // Only the errors, torques and arm figures carry curves in the errors' colour.
    assert!(!triangles(&svg(&s, "e1"), palette::ERROR1).is_empty());
    assert!(triangles(&svg(&s, "e2"), palette::ERROR1).is_empty());
    // The dark scheme on request only.
    let dark = figure_svg(&s, "poles", true).unwrap().svg;
    assert!(luminance(&background(&dark)) < 0.15, "{}", background(&dark));
    assert!(FigurePanel::parse("nothing").unwrap_err().to_string().contains("zplane"), "the names are listed");
}

#[test]
fn a_long_state_string_is_never_cut_but_wraps_within_the_figure() {
    let arm = flexarm::session::ARMS.iter().find(|a| a.id == "softer").unwrap().id;
    let s = session(&format!("preset=fig5.3&arm={arm}&bv1=12.5&ir1=2.5&alpha1=1.5&alpha2=2.5&log=1"), 1.0, false);
    let state = s.state_string();
    assert!(state.len() > 150, "{state}");
    for panel in ["e1", "poles", "arm"] {
        let figure = figure_svg(&s, panel, false).unwrap();
        let lines = texts(&figure.svg, "state");
        assert!(lines.len() >= 2, "{panel}: {lines:?}");
        assert_eq!(lines.concat(), state, "{panel}");
        // A monospace line of n characters at 11 px is at most 0.62 em a character.
        for (tag, line) in figure.svg.split("<text class=\"state\"").skip(1).zip(&lines) {
            let x: f64 = attr(tag, "x").parse().unwrap();
            assert!(x + line.chars().count() as f64 * 0.62 * 11.0 <= figure.width, "{panel}: {line}");
        }
    }
}

/// Re s of the flexible pair's marker (its halo's centre) in the pole-plot figure.
fn flexible_re_s(query: &str) -> f64 {
    let s = session(query, 0.5, false);
    let svg = svg(&s, "poles");
    let axes = Axes::of(&svg, "poles");
    let halo = triangles(&svg, palette::POLE_HALO);
    assert!(!halo.is_empty(), "{query}: the flexible pair is marked");
    let xs: Vec<f64> = halo.iter().map(|t| axes.value(centroid(t))[0]).collect();
    xs.iter().sum::<f64>() / xs.len() as f64
}

#[test]
fn the_pole_figure_puts_the_flexible_pair_right_of_the_axis_at_fig_5_3_and_left_at_fig_5_2() {
    let unstable = flexible_re_s("preset=fig5.3");
    assert!(unstable > 1.5 && unstable < 3.2, "Fig. 5.3: Re s ≈ +2.36, read {unstable}");
    let stable = flexible_re_s("preset=fig5.2");
    assert!(stable < 0.0, "Fig. 5.2: left of the imaginary axis, read {stable}");
}

#[test]
fn the_z_plane_figure_puts_the_pair_outside_the_unit_circle_at_fig_5_3() {
    let s = session("preset=fig5.3&plane=z", 0.5, false);
    let svg = svg(&s, "zplane");
    let axes = Axes::of(&svg, "z-plane");
    let halo = triangles(&svg, palette::POLE_HALO);
    assert!(!halo.is_empty());
    // The upper pole's halo (Im λ > 0): its centre's distance from 0.
    let upper: Vec<[f64; 2]> = halo.iter().map(|t| axes.value(centroid(t))).filter(|v| v[1] > 0.0).collect();
    let n = upper.len() as f64;
    let (re, im) = (upper.iter().map(|v| v[0]).sum::<f64>() / n, upper.iter().map(|v| v[1]).sum::<f64>() / n);
    let modulus = re.hypot(im);
    assert!(modulus > 1.005 && modulus < 1.05, "|λ| ≈ 1.024 read {modulus}");
}

#[test]
fn a_diverging_runs_errors_rise_to_the_plots_edge() {
    // Fig. 5.3 diverges about 4 s in: the figure shows the growth up to where the run stopped.
    let s = session("preset=fig5.3", 12.0, false);
    assert!(s.run(0).unwrap().closed_loop().is_finished());
    let svg = svg(&s, "e2");
    let axes = Axes::of(&svg, "e2");
    let points: Vec<[f64; 2]> = triangles(&svg, palette::ERROR2).iter().flat_map(|t| t.to_vec()).collect();
    let [x, y, w, h] = [axes.rect[0], axes.rect[1], axes.rect[2], axes.rect[3]];
    assert!(points.iter().all(|p| p[0] >= x - 2.0 && p[0] <= x + w + 2.0 && p[1] >= y - 2.0 && p[1] <= y + h + 2.0));
    let mid = y + h / 2.0;
    let reach = points.iter().map(|p| (p[1] - mid).abs()).fold(0.0, f64::max) / (h / 2.0);
    // The autoscale's 1-2-5 ceiling over 1.1 × the largest error: at least 45 % of the half-height.
    assert!(reach > 0.45, "the curve reaches {reach} of the way to the edge");
    // On log |e| the growth reaches the top decade.
    let mut s = s;
    s.set("log", "1").unwrap();
    let svg = figure_svg(&s, "e2", false).unwrap().svg;
    let axes = Axes::of(&svg, "e2");
    let top =
        triangles(&svg, palette::ERROR2).iter().flat_map(|t| t.to_vec()).map(|p| p[1]).fold(f64::INFINITY, f64::min);
    assert!(top - axes.rect[1] < 0.1 * axes.rect[3], "log |e2| rises to {} px below the top", top - axes.rect[1]);
}

#[test]
fn student_mode_refuses_the_analysis_figures_and_lists_what_is_shown() {
    let s = session("preset=fig5.3&answers=hidden", 1.0, false);
    for panel in ["poles", "zplane", "rho", "map-off", "maps"] {
        let e = figure_svg(&s, panel, false).unwrap_err().to_string();
        assert!(e.contains("student mode"), "{panel}: {e}");
    }
    assert!(figure_svg(&s, "errors", false).is_ok());
    let ids: Vec<&str> = figure_choices(&s).iter().map(|c| c.id).collect();
    assert_eq!(ids, ["arm", "errors", "e1", "e2"], "only the run's figures are offered");
    let full = session("preset=fig5.3&torque=1&plane=z", 0.1, false);
    let ids: Vec<&str> = figure_choices(&full).iter().map(|c| c.id).collect();
    assert_eq!(ids, ["arm", "errors", "e1", "e2", "torque", "zplane", "rho", "map-off", "map-on", "maps"]);
    // The maps wait for their computation.
    assert!(figure_svg(&full, "maps", false).unwrap_err().to_string().contains("computed"));
}

#[test]
fn the_maps_figure_has_the_canvas_ramp_the_contour_the_marker_and_log_ticks() {
    let s = session("preset=fig5.3", 0.1, true);
    let svg = svg(&s, "maps");
    // Both maps' cells in the canvas's ramp, the ρ = 1 contour, the (δ, α) running now.
    for c in [palette::MAP_STABLE_FAR, palette::CONTOUR, palette::MAP_MARKER] {
        assert!(svg.contains(&format!("fill=\"{}\"", c.css())), "{}", c.css());
    }
    assert_eq!(count(&svg, "data-panel=\"map-"), 2);
    // The key's colour bar: the ramp's neutral ρ = 1 colour in the middle, its ticks.
    assert!(svg.contains(&format!("offset=\"0.5\" stop-color=\"{}\"", palette::MAP_NEUTRAL.css())));
    let key = texts(&svg, "key");
    for t in ["≤ 0.8", "1", "≥ 1.2"] {
        assert!(key.iter().any(|k| k == t), "{t} in {key:?}");
    }
    // Decades and their 2s and 5s on both log axes.
    let ticks = texts(&svg, "tick");
    for t in ["0.005", "0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1", "2"] {
        assert!(ticks.iter().any(|k| k == t), "tick {t} in {ticks:?}");
    }
}

#[test]
fn the_cli_writes_the_same_figure_after_running_to_the_time_and_names_the_panels_it_knows() {
    let exe = env!("CARGO_BIN_EXE_flexarm");
    let dir = std::env::temp_dir().join(format!("flexarm-figure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("z.svg");
    let state = "preset=fig5.3&plane=z&t=2";
    let out = std::process::Command::new(exe)
        .args(["figure", "--panel", "zplane", "--state", state, "--svg", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains("t = 2 s"), "{}", String::from_utf8_lossy(&out.stdout));
    let svg = std::fs::read_to_string(&file).unwrap();
    assert_wellformed(&svg, "cli zplane");
    assert!(texts(&svg, "axis").iter().any(|t| t == "Re λ"));
    let caption = texts(&svg, "state").concat();
    assert!(caption.contains("delta=0.01") && caption.contains("pf=off"), "{caption}");
    // The errors exist: the run went to t = 2 s.
    let out = std::process::Command::new(exe).args(["figure", "--panel", "e1", "--state", state]).output().unwrap();
    let svg = String::from_utf8(out.stdout).unwrap();
    assert!(!triangles(&svg, palette::ERROR1).is_empty(), "e1's curve");
    // An unknown panel: status 2, every name listed.
    let out = std::process::Command::new(exe).args(["figure", "--panel", "bode"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    for name in FigurePanel::ALL.map(FigurePanel::id) {
        assert!(err.contains(name), "{name} in {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn comparing_two_runs_gives_run_bs_arm_and_both_runs_in_one_panel() {
    // Fig. 5.3 beside Fig. 5.2 (a decade apart: the page may turn the errors to log |e|).
    let s = session("preset=fig5.3&compare=1&b_delta=0.04", 3.0, false);
    let ids: Vec<&str> = figure_choices(&s).iter().map(|c| c.id).collect();
    assert!(ids.contains(&"arm-b"), "{ids:?}");
    for (panel, kinds) in [("arm-b", 1), ("e1", 1), ("errors", 2), ("poles", 1)] {
        let svg = svg(&s, panel);
        assert_wellformed(&svg, panel);
        assert_eq!(count(&svg, "<g class=\"panel\""), kinds, "{panel}: only its own panels");
        assert_eq!(texts(&svg, "state").concat(), s.state_string());
    }
    assert!(!triangles(&svg(&s, "e1"), palette::RUN_B).is_empty(), "run B's curve");
    let single = session("preset=fig5.3", 0.5, false);
    assert!(figure_svg(&single, "arm-b", false).unwrap_err().to_string().contains("run B"));
}
