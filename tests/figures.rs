//! The figures that make the analysis visible (issue 9): the z-plane with the unit circle, ρ(δ)
//! with the stable windows, log |e| with the slope ρ predicts, the ghost of the previous run, the
//! Nyquist frequency in the s-plane. All drawn from a session, as the page draws them.

mod common;
use common::play;

use flexarm::session::Session;
use flexarm::view::{PanelInfo, PanelKind, PoleKind, Scene, ViewOptions};

/// A session in the full view (every figure), as the page opens `?mode=full&…`.
fn session(query: &str) -> Session {
    common::session(&format!("mode=full&{query}"))
}

fn info<'a>(panels: &'a [PanelInfo], id: &str) -> &'a PanelInfo {
    panels.iter().find(|p| p.id == id).unwrap_or_else(|| panic!("no panel {id}"))
}

fn all_finite(scene: &Scene) -> bool {
    scene
        .vertices()
        .iter()
        .chain(scene.static_vertices())
        .all(|v| v.position.iter().chain(&v.color).all(|x| x.is_finite()))
}

#[test]
fn the_z_plane_shows_the_flexible_pair_outside_the_unit_circle_without_feedback() {
    for (pf, outside) in [("off", true), ("paper", false)] {
        // The whole circle (the default view zooms on the pair: tests/zplane.rs).
        let s = session(&format!("delta=0.01&pf={pf}&plane=z&zsize=1.2"));
        let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
        scene.draw_session(&s);
        let panels = scene.panel_info();
        let z = info(&panels, "z-plane");
        assert_eq!((z.x_label.as_str(), z.y_label), ("Re λ", "Im λ"));
        assert!(z.x_range[0] < -1.0 && z.x_range[1] > 1.0 && z.y_range[0] < -1.0 && z.y_range[1] > 1.0, "{z:?}");
        assert!(panels.iter().all(|p| p.id != "poles"), "one pole plot at a time");
        let poles = scene.pole_info();
        let flexible: Vec<_> = poles.iter().filter(|p| p.kind == PoleKind::Loop && p.flexible).collect();
        assert_eq!(flexible.len(), 2);
        for p in &flexible {
            assert_eq!(p.modulus > 1.0, outside, "{pf}: |λ| = {}", p.modulus);
            assert_eq!(p.unstable, p.modulus > 1.0);
            // The marker sits at λ in the panel: |λ| = 1 is one "unit" from the centre.
            let (x, y) = (p.x.unwrap(), p.y.unwrap());
            assert!(x >= z.x && x <= z.x + z.width && y >= z.y && y <= z.y + z.height);
        }
        // ρ is the largest |λ|.
        let rho = s.run(0).unwrap().analysis().report().unwrap().spectral_radius;
        let largest = poles.iter().filter(|p| p.kind == PoleKind::Loop).map(|p| p.modulus).fold(0.0, f64::max);
        assert!((largest - rho).abs() < 1e-12);
        assert!(z.marks.iter().any(|m| m.text.contains("flexible pair")), "{:?}", z.marks);
        // Pointing at the flexible pair names the loop's pole, not the δ → 0 marker beside it,
        // even a little nearer the marker.
        let a4 = poles.iter().find(|q| q.kind == PoleKind::A4Open && q.im > 0.0).unwrap();
        let p = *flexible.iter().find(|q| q.im > 0.0).unwrap();
        let (ax, ay, px, py) = (a4.x.unwrap(), a4.y.unwrap(), p.x.unwrap(), p.y.unwrap());
        let gap = (ax - px).hypot(ay - py);
        assert!(gap < 40.0, "{pf}: the marker is beside the pole ({gap} px)");
        let probe = scene.probe(px + 0.6 * (ax - px), py + 0.6 * (ay - py), 22.0).unwrap();
        assert!(probe.title.starts_with("loop pole"), "{pf}: {}", probe.title);
        assert!(probe
            .lines
            .iter()
            .any(|l| l.text.contains(&format!("|λ| = {}", flexarm::plot::format::significant(p.modulus, 4)))));
        assert!(all_finite(&scene));
    }
}

#[test]
fn moving_delta_across_a_window_edge_moves_the_pair_across_the_circle() {
    // The window without feedback opens at δ ≈ 0.0350 s.
    let modulus = |delta: f64| {
        let s = session(&format!("delta={delta}&pf=off&plane=z"));
        let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
        scene.draw_session(&s);
        scene.pole_info().iter().filter(|p| p.kind == PoleKind::Loop).map(|p| p.modulus).fold(0.0, f64::max)
    };
    assert!(modulus(0.0345) > 1.0 && modulus(0.0355) < 1.0);
}

#[test]
fn the_s_plane_marks_the_nyquist_frequency_and_the_aliased_pair() {
    let s = session("delta=0.15&pf=off");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let poles_panel = info(&panels, "poles");
    assert!(
        poles_panel.note.contains("π/δ = 20.9 rad/s") && poles_panel.note.contains("aliased"),
        "{}",
        poles_panel.note
    );
    let flexible: Vec<_> = scene.pole_info().into_iter().filter(|p| p.kind == PoleKind::Loop && p.flexible).collect();
    assert!(flexible.iter().all(|p| p.aliased && p.im.abs() < 20.95), "{flexible:?}");
    // The tooltip says so.
    let p = &flexible[0];
    let probe = scene.probe(p.x.unwrap(), p.y.unwrap(), 5.0).unwrap();
    assert!(probe.lines.iter().any(|l| l.text.starts_with("aliased")), "{:?}", probe.lines);
    assert!(probe.lines.iter().any(|l| l.text.contains("|λ| =")), "{:?}", probe.lines);
    // At δ = 0.01 s the Nyquist frequency (314 rad/s) is off the plot and nothing is aliased.
    let s = session("delta=0.01&pf=off");
    scene.draw_session(&s);
    let panels = scene.panel_info();
    assert!(!info(&panels, "poles").note.contains("π/δ"), "no Nyquist line to explain");
    assert!(scene.pole_info().iter().all(|p| !p.aliased));
}

#[test]
fn rho_of_delta_shows_the_windows_and_picks_delta() {
    let mut s = session("delta=0.05&pf=off");
    s.refresh();
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let rho = info(&panels, "rho-curve");
    assert_eq!((rho.x_label.as_str(), rho.y_label, rho.x_scale), ("δ [s]", "ρ", "log"));
    assert_eq!(rho.x_range, [0.002, 0.25]);
    assert!(rho.y_range[0] <= 0.9 && rho.y_range[1] >= 1.1);
    assert!(rho.note.contains("α = 2"), "{}", rho.note);
    assert!(!scene.static_vertices().is_empty());
    // A probe at δ = 0.05 s reads ρ < 1 there and offers to run there.
    let f = (0.05f64 / 0.002).ln() / (0.25f64 / 0.002).ln();
    let (x, y) = (rho.x + f * rho.width, rho.y + rho.height / 2.0);
    let probe = scene.probe(x, y, 0.0).unwrap();
    assert_eq!(probe.kind, "rho");
    assert!((probe.delta.unwrap() / 0.05 - 1.0).abs() < 0.01);
    assert!(probe.lines[1].text.contains("stable") && probe.lines[1].tone == "good", "{:?}", probe.lines);
    assert!(all_finite(&scene));
}

#[test]
fn log_errors_show_decades_and_the_predicted_slope_and_the_ghost() {
    let mut s = session("preset=fig5.3");
    play(&mut s, 5.0);
    s.set("pf", "paper").unwrap();
    play(&mut s, 0.5);
    assert!(s.ghost().is_some());
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let linear = scene.vertices().len();
    // The view is a setting of the session, like any other.
    s.set("log", "1").unwrap();
    scene.draw_session(&s);
    let panels = scene.panel_info();
    let e1 = info(&panels, "e1");
    assert_eq!(e1.y_scale, "log");
    assert!(e1.y_label.starts_with("|e1|"), "{}", e1.y_label);
    assert!((e1.y_range[1] / e1.y_range[0] - 1e6).abs() < 1.0, "six decades: {:?}", e1.y_range);
    assert!(e1.y_ticks.len() >= 6 && e1.y_labels.iter().any(|l| l.text.contains('e')), "{:?}", e1.y_labels);
    assert!(e1.note.contains("ln ρ/δ"), "{}", e1.note);
    assert!(panels.iter().filter(|p| p.id == "torque").all(|p| p.y_scale == "linear"), "torques stay linear");
    assert!(scene.vertices().len() != linear);
    assert!(all_finite(&scene));
    // The ghost does not drive the scale: the new, stable run's errors do.
    let max_now = s.run(0).unwrap().closed_loop().traces().e1().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(e1.y_range[1] < 100.0 * max_now.max(1e-6), "{:?} vs {max_now}", e1.y_range);
}

#[test]
fn the_windows_are_marked_on_the_map_of_the_current_feedback() {
    let mut s = session("delta=0.05&pf=off");
    s.refresh();
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let with_marks = scene.vertices().len();
    let mut s2 = session("delta=0.05&pf=off");
    let mut scene2 = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene2.draw_session(&s2);
    assert!(with_marks > scene2.vertices().len(), "three windows, each a bar with a halo");
    s2.refresh();
    scene2.draw_session(&s2);
    assert_eq!(scene2.vertices().len(), with_marks);
    let panels = scene2.panel_info();
    assert!(panels.iter().any(|p| p.id == "rho-curve"));
    let _ = PanelKind::RhoCurve;
}

#[test]
fn the_key_names_every_marker_shown_and_the_maps_colour_bar() {
    use flexarm::view::legend::Glyph;
    let s = session("preset=fig5.3&plane=z");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&s);
    let key = scene.legend();
    let titles: Vec<&str> = key.iter().map(|g| g.title).collect();
    assert_eq!(titles, ["arm", "z-plane", "ρ(δ)", "stability maps"]);
    // The arm's picture: the reference arm, the 0-rad line, the spring, the motor's mark.
    assert!(key[0].items.iter().any(|i| i.text.contains("0 rad")));
    let z = &key[1];
    for glyph in [Glyph::Cross, Glyph::Halo, Glyph::Ring, Glyph::Diamond, Glyph::Swatch, Glyph::Chevron] {
        assert!(z.items.iter().any(|i| i.glyph == glyph), "{glyph:?} explained");
    }
    assert!(z.items.iter().any(|i| i.text.contains("unit circle")));
    let scale = key[3].scale.as_ref().unwrap();
    let one = scale.ticks.iter().find(|(_, t)| t == "1").unwrap();
    assert!((one.0 - 0.5).abs() < 1e-12, "ρ = 1 in the middle of the bar");
    assert_eq!(scale.stops.first().unwrap().1, flexarm::plot::color::ramp_color(0.0).css());
    // The intro shows no analysis panels: only the arm to key.
    let intro = common::session("preset=fig5.3");
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
    scene.draw_session(&intro);
    let titles: Vec<&str> = scene.legend().iter().map(|g| g.title).collect();
    assert_eq!(titles, ["arm"]);
}
