//! The z-plane one can look into (issue 23, item 4): zoom about the pointer, pan, limits, the
//! default view that shows how far Fig. 5.3's flexible pair (|λ| = 1.024, the paper's unstable
//! case) is outside the unit circle, the shading of |λ| > 1 at any zoom, readable ticks, and the
//! zoom in the state string.

mod common;
use common::session;

use flexarm::plot::{palette, Ticks};
use flexarm::session::Session;
use flexarm::view::painter::Painter;
use flexarm::view::panels::z_plane::drawing::{draw_zplane_background, ZFrame, BACKGROUND_VERTEX_BUDGET};
use flexarm::view::panels::z_plane::view::ZView;
use flexarm::view::panels::z_plane::view::{CENTER_LIMIT, MIN_HALF, WHOLE_HALF};
use flexarm::view::{PanelInfo, PoleKind, Rect, Scene, ViewOptions};

/// Canvas sizes: a wide desktop, a laptop, a phone.
const SIZES: [(f64, f64); 3] = [(1920.0, 1080.0), (1280.0, 800.0), (390.0, 700.0)];

fn scene_of(s: &Session, w: f64, h: f64) -> Scene {
    let mut scene = Scene::new(ViewOptions::default(), w, h, 1.0);
    scene.draw_session(s);
    scene
}

fn z_info(scene: &Scene) -> PanelInfo {
    scene.panel_info().into_iter().find(|p| p.id == "z-plane").expect("the z-plane is shown")
}

/// Fig. 5.3 with the z-plane (on a phone, its tab).
const FIG53: &str = "preset=fig5.3&mode=full&plane=z&tab=poles";

#[test]
fn zooming_keeps_the_pointed_at_lambda_under_the_pointer() {
    let s = session(FIG53);
    let scene = scene_of(&s, 1280.0, 800.0);
    let rect = scene.z_panel().unwrap();
    let before = ZFrame::new(rect, scene.z_view());
    for (fx, fy) in [(0.2, 0.3), (0.5, 0.5), (0.9, 0.85)] {
        let p = [rect.x + fx * rect.w, rect.y + fy * rect.h];
        let lambda = before.value_at(p);
        for factor in [1.25, 0.8, 40.0] {
            let view = scene.zoom_z(p[0], p[1], factor).unwrap();
            let after = ZFrame::new(rect, view).value_at(p);
            let tol = 1e-9 * view.half;
            assert!(
                (after[0] - lambda[0]).abs() < tol && (after[1] - lambda[1]).abs() < tol,
                "{factor}: {lambda:?} → {after:?}"
            );
        }
    }
    // Off the panel nothing zooms.
    assert!(scene.zoom_z(rect.x - 5.0, rect.y + 5.0, 2.0).is_none());
}

#[test]
fn zoom_and_pan_stay_within_their_limits() {
    let v = ZView::WHOLE;
    assert_eq!(v.zoomed_about([0.3, 0.2], 1e-6).half, WHOLE_HALF, "never wider than the whole circle");
    let deep = v.zoomed_about([0.99, 0.1], 1e12);
    assert_eq!(deep.half, MIN_HALF, "never closer than 1e-4");
    // At the limit the point still stays put: the centre moved by the allowed ratio only.
    let f0 = ZFrame::new(Rect::new(0.0, 0.0, 400.0, 300.0), v);
    let p = f0.point([0.99, 0.1]);
    let f1 = ZFrame::new(f0.rect, deep);
    let q = f1.value_at(p);
    assert!((q[0] - 0.99).abs() < 1e-12 && (q[1] - 0.1).abs() < 1e-12, "{q:?}");
    // The view's shorter side stays within ±1.5: at the widest, the whole circle give or take 0.3.
    let far = v.panned([100.0, -100.0]);
    assert_eq!(far.center, [CENTER_LIMIT - WHOLE_HALF, WHOLE_HALF - CENTER_LIMIT]);
    let close = ZView { center: [1.0, 0.0], half: 0.01 }.panned([100.0, -100.0]);
    assert_eq!(close.center, [CENTER_LIMIT - 0.01, 0.01 - CENTER_LIMIT]);
    assert_eq!(ZView { center: [f64::NAN, 0.0], half: 0.1 }.clamped(), ZView::WHOLE);
    // The same limits through the session's setting, with typed errors for what is out of them.
    let mut s = session(FIG53);
    for (key, bad) in [("zsize", "-0.1"), ("zsize", "1.5"), ("zsize", "lots"), ("zre", "3"), ("zim", "-2.5")] {
        let e = s.set(key, bad).unwrap_err();
        assert!(matches!(e, flexarm::error::Error::Config(_) | flexarm::error::Error::Parse(_)), "{key}={bad}: {e}");
    }
    let (_, notices) = Session::open("plane=z&zsize=7");
    assert_eq!(notices.len(), 1, "a link's bad zoom is a notice");
}

#[test]
fn at_fig_5_3_the_flexible_pair_is_in_view_and_visibly_outside_the_circle() {
    for (w, h) in SIZES {
        let s = session(FIG53);
        let scene = scene_of(&s, w, h);
        let rect = scene.z_panel().unwrap();
        let pair: Vec<_> =
            scene.pole_info().into_iter().filter(|p| p.kind == PoleKind::Loop && p.flexible && p.im > 0.0).collect();
        assert_eq!(pair.len(), 1);
        let p = &pair[0];
        // The paper's unstable case: |λ| = 1.024 > 1.
        assert!((p.modulus - 1.024).abs() < 5e-4, "{}", p.modulus);
        assert!(p.in_view, "{w}×{h}: the pair is in the default view");
        // Its distance from the circle, in CSS px: at least 24 (the old ±1.3 square gave 2–4).
        let frame = ZFrame::new(rect, scene.z_view());
        let gap_px = (p.modulus - 1.0) * frame.scale();
        assert!(gap_px >= 24.0, "{w}×{h}: {gap_px} px");
        let whole = (p.modulus - 1.0) * ZFrame::new(rect, ZView::WHOLE).scale();
        assert!(whole < 24.0, "{w}×{h}: the whole circle shows only {whole} px (this test would fail there)");
        // |λ| − 1 is written beside it.
        let z = z_info(&scene);
        let said = |t: &str| {
            t.split("|λ| − 1 = +").nth(1).and_then(|v| v.parse::<f64>().ok()).is_some_and(|v| (v - 0.024).abs() < 5e-4)
        };
        assert!(z.marks.iter().any(|m| said(&m.text)), "{:?}", z.marks);
        assert!(scene.labels().iter().any(|l| l.panel == "z-plane" && said(&l.text)), "the label is placed");
        // Hovering it in the zoomed view names the loop's pole.
        let probe = scene.probe(p.x.unwrap(), p.y.unwrap(), 22.0).unwrap();
        assert!(probe.title.starts_with("loop pole"), "{}", probe.title);
        // The panel uses its width: equal scales, the longer side shows more.
        let (xr, yr) = (z.x_range[1] - z.x_range[0], z.y_range[1] - z.y_range[0]);
        assert!((xr / yr - rect.w / rect.h).abs() < 1e-9, "{xr} / {yr} against {} / {}", rect.w, rect.h);
    }
    // A pair far inside the circle leaves the whole circle in view; one near it is zoomed on,
    // the nearer the closer.
    assert_eq!(ZView::around(Some([0.3, 0.2]), 300.0), ZView::WHOLE);
    assert_eq!(ZView::around(None, 300.0), ZView::WHOLE);
    let near = ZView::around(Some([0.99, 0.0]), 300.0).half;
    let nearer = ZView::around(Some([0.999, 0.0]), 300.0).half;
    assert!(nearer < near && near < WHOLE_HALF, "{near} {nearer}");
}

/// The colour on top at pixel `p` of a triangle list (the last triangle covering it).
fn color_at(painter: &Painter, p: [f64; 2]) -> Option<[f32; 4]> {
    let v = painter.vertices();
    let mut top = None;
    for t in v.chunks_exact(3) {
        let q = |i: usize| [t[i].position[0] as f64, t[i].position[1] as f64];
        let (a, b, c) = (q(0), q(1), q(2));
        let cross =
            |o: [f64; 2], u: [f64; 2], w: [f64; 2]| (u[0] - o[0]) * (w[1] - o[1]) - (u[1] - o[1]) * (w[0] - o[0]);
        let (d1, d2, d3) = (cross(a, b, p), cross(b, c, p), cross(c, a, p));
        let neg = d1 < 0.0 || d2 < 0.0 || d3 < 0.0;
        let pos = d1 > 0.0 || d2 > 0.0 || d3 > 0.0;
        if !(neg && pos) {
            top = Some(t[0].color);
        }
    }
    top
}

#[test]
fn everything_outside_the_circle_in_view_is_shaded_and_nothing_inside() {
    let rect = Rect::new(30.0, 20.0, 640.0, 300.0);
    let views = [
        ZView::WHOLE,
        ZView::around(Some([0.983, 0.287]), 300.0),
        ZView { center: [0.0, 0.0], half: 0.5 },
        ZView { center: [0.96, 0.28], half: 0.01 },
        ZView { center: [std::f64::consts::FRAC_1_SQRT_2; 2], half: 1e-3 },
        ZView { center: [1.0, 0.0], half: 1e-4 },
        ZView { center: [-0.6, -0.8], half: 1e-4 },
        ZView { center: [0.3, 0.2], half: 0.05 },
        ZView { center: [1.4, 1.4], half: 0.05 },
    ];
    let empty = || (Ticks::new(0.0, 0.0, 1), Ticks::new(0.0, 0.0, 1));
    for view in views {
        let frame = ZFrame::new(rect, view);
        let mut painter = Painter::new();
        draw_zplane_background(&mut painter, &frame, empty(), 1.0);
        assert!(painter.len() <= BACKGROUND_VERTEX_BUDGET, "{view:?}: {} vertices", painter.len());
        let o = frame.point([0.0, 0.0]);
        let (mut inside, mut outside) = (0, 0);
        for i in 0..=64 {
            for j in 0..=32 {
                let p = [rect.x + rect.w * (i as f64 + 0.5) / 65.5, rect.y + rect.h * (j as f64 + 0.5) / 33.5];
                let r_px = (p[0] - o[0]).hypot(p[1] - o[1]);
                let from_circle = r_px - frame.scale();
                // Away from the ring (2.5 px wide) and the axes.
                if from_circle.abs() < 3.0 || (p[0] - o[0]).abs() < 2.0 || (p[1] - o[1]).abs() < 2.0 {
                    continue;
                }
                let want = if from_circle > 0.0 { palette::UNSTABLE_REGION } else { palette::PANEL };
                let got = color_at(&painter, p);
                assert_eq!(got, Some(want.0), "{view:?} at {p:?}, {from_circle} px from the circle");
                if from_circle > 0.0 {
                    outside += 1;
                } else {
                    inside += 1;
                }
            }
        }
        assert!(inside + outside > 1000, "{view:?}");
    }
}

/// The base and unit of offset tick labels, from a title's "… 0.70710 + n × 1e−5" (or "n·1e−5").
fn offset_of(note: &str) -> Option<(f64, f64)> {
    let clause = note.split("; ").find(|c| c.contains(" + n"))?;
    let num = |t: &str| t.trim().replace('−', "-").parse::<f64>().ok();
    let (left, right) = clause.split_once(" + n")?;
    let base = num(left.rsplit(' ').next()?)?;
    let unit = num(right.trim_start_matches(" × ").trim_start_matches('·'))?;
    Some((base, unit))
}

#[test]
fn ticks_stay_readable_from_the_whole_circle_to_a_ten_thousandth() {
    for (w, h) in SIZES {
        let mut s = session(FIG53);
        for half in [WHOLE_HALF, 0.3, 0.05, 1e-2, 1e-3, 1e-4] {
            for center in [[0.983, 0.287], [1.0, 0.0], [0.0, 0.0], [-0.5, 0.5]] {
                s.set_z_view(center, half).unwrap();
                let scene = scene_of(&s, w, h);
                let z = z_info(&scene);
                for (axis, labels, range) in [("x", &z.x_labels, z.x_range), ("y", &z.y_labels, z.y_range)] {
                    let what = format!("{w}×{h} half {half} at {center:?}, {axis}");
                    assert!(labels.len() >= 2, "{what}: {labels:?}");
                    let texts: Vec<&str> = labels.iter().map(|l| l.text.as_str()).collect();
                    for (i, t) in texts.iter().enumerate() {
                        assert!(!texts[i + 1..].contains(t), "{what}: '{t}' twice in {texts:?}");
                    }
                    // Each label reads back as its tick, closer than half the step.
                    let step = (labels[1].value - labels[0].value).abs();
                    // Offset labels (steps from a base the title names) where plain ones are too wide.
                    let offset = (axis == "y").then(|| offset_of(&z.note)).flatten();
                    for l in labels.iter() {
                        let mut read: f64 = l.text.replace('−', "-").parse().unwrap_or(f64::NAN);
                        if let Some((base, unit)) = offset {
                            read = base + read * unit;
                        }
                        assert!((read - l.value).abs() < step / 2.0, "{what}: '{}' for {}", l.text, l.value);
                        let slack = 1e-6 * step;
                        assert!(l.value >= range[0] - slack && l.value <= range[1] + slack, "{what}: {}", l.value);
                    }
                }
            }
        }
    }
}

#[test]
fn the_zoom_goes_into_the_state_string_and_back() {
    let mut s = session(FIG53);
    assert!(!s.state_string().contains("zsize"), "the default view writes nothing");
    let scene = scene_of(&s, 1280.0, 800.0);
    let rect = scene.z_panel().unwrap();
    let v = scene.zoom_z(rect.x + rect.w / 2.0, rect.y + rect.h / 2.0, 4.0).unwrap().rounded();
    s.set_z_view(v.center, v.half).unwrap();
    let q = s.state_string();
    assert!(q.contains("zsize=") && q.contains("zre=") && q.contains("zim="), "{q}");
    let back = session(&q);
    let scene2 = scene_of(&back, 1280.0, 800.0);
    assert_eq!(scene2.z_view(), v, "{q}");
    // Drawing at any zoom stays within the room reserved at layout (no allocation per frame).
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    scene.draw_session(&s);
    let capacity = scene.painter().capacity();
    for half in [WHOLE_HALF, 0.1, 1e-3, 1e-4] {
        for center in [[0.0, 0.0], [1.0, 0.0], [0.983, 0.287]] {
            s.set_z_view(center, half).unwrap();
            scene.draw_session(&s);
            assert_eq!(scene.painter().capacity(), capacity, "half {half} at {center:?}");
        }
    }
}

/// Every control admits its own ends, negative ones too (`zre=-2` was refused: the slack was
/// relative with the wrong sign below zero).
#[test]
fn every_control_admits_its_own_ends() {
    for p in flexarm::schema::PARAMS {
        if let Some(n) = p.number() {
            let [lo, hi] = n.control;
            assert!(n.in_control(lo) && n.in_control(hi), "{}: [{lo}, {hi}]", p.key);
            assert!(!n.in_control(lo - 1e-3 * (hi - lo)), "{}: below its span", p.key);
        }
    }
}
