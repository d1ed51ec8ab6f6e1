//! Presentation mode and the figure's text size (issue 23 item 2): on a projector the smallest
//! figure text is at least 18 px at 1920 × 1080 and 14 px at 1024 × 768; at every text size no
//! label overlaps another or the data, and the page's pointer still finds what it points at; each
//! text size is larger than the last there too (issue 35).

mod common;
use common::{play, session};

use flexarm::view::text_size::{page_text_factor, text_scale, TextSize};
use flexarm::view::{Label, PanelKind, Rect, Scene, ViewOptions};

/// The presentation bar's height, CSS px (the canvas fills the screen above it).
const BAR: f64 = 56.0;

fn drawn(query: &str, w: f64, h: f64, screen: f64) -> Scene {
    drawn_at(&format!("preset=fig5.3&{query}"), w, h, screen, 1.5)
}

/// The scene of the whole `query` after `seconds` of the run (a time window that has scrolled).
fn drawn_at(query: &str, w: f64, h: f64, screen: f64, seconds: f64) -> Scene {
    let mut s = session(query);
    play(&mut s, seconds);
    s.refresh();
    let mut scene = Scene::new(ViewOptions::default(), w, h, 1.0);
    scene.set_screen_height(screen);
    scene.draw_session(&s);
    scene
}

fn smallest(labels: &[Label]) -> f64 {
    labels.iter().map(|l| l.size).fold(f64::INFINITY, f64::min)
}

#[test]
fn presented_text_is_readable_from_the_back_of_a_room() {
    for (w, h, need) in [(1920.0, 1080.0, 18.0), (1024.0, 768.0, 14.0)] {
        for view in ["mode=full", "mode=full&plane=z&torque=1", "mode=intro", "mode=full&compare=1"] {
            for text in ["normal", "large", "larger", "largest"] {
                let q = format!("{view}&present=1&text={text}");
                let scene = drawn(&q, w, h - BAR, h);
                let labels = scene.page_labels();
                assert!(!labels.is_empty(), "{q}");
                let min = smallest(&labels);
                assert!(min >= need - 1e-9, "{q} at {w}×{h}: smallest text {min:.1} px < {need} px");
            }
        }
        // The same screen without presentation mode keeps the laptop's 12 px: the floor is
        // presentation mode's doing, not the screen's.
        let plain = drawn("mode=full", w, h - BAR, h);
        assert!(smallest(&plain.page_labels()) < need, "{w}×{h} without present=1");
    }
}

#[test]
fn text_sizes_grow_in_order_and_apply_outside_presentation_mode_too() {
    let mut last = 0.0;
    for text in ["normal", "large", "larger", "largest"] {
        let scene = drawn(&format!("mode=full&text={text}"), 1920.0, 1080.0, 1080.0);
        let min = smallest(&scene.page_labels());
        assert!(min > last + 1.0, "text={text}: {min} after {last}");
        last = min;
    }
}

fn overlap(a: &Rect, b: &Rect) -> bool {
    a.x < b.right() - 0.5 && b.x < a.right() - 0.5 && a.y < b.bottom() - 0.5 && b.y < a.bottom() - 0.5
}

fn touch(a: &Rect, b: &Rect) -> bool {
    let g = 2.0;
    a.x < b.right() + g && b.x < a.right() + g && a.y < b.bottom() + g && b.y < a.bottom() + g
}

/// The no-overlap guarantee of tests/labels.rs, in the page's pixels, at every text size.
#[test]
fn no_text_overlaps_at_any_text_size() {
    let mut checked = 0;
    for text in ["large", "larger", "largest"] {
        for view in ["mode=full", "mode=full&plane=z&log=1", "mode=full&compare=1&torque=1", "mode=intro", "embed=1"] {
            for (w, h) in [(1920.0, 1024.0), (1280.0, 744.0), (1024.0, 712.0), (760.0, 480.0), (390.0, 600.0)] {
                for present in ["0", "1"] {
                    let q = format!("{view}&text={text}&present={present}");
                    let scene = drawn(&q, w, h, h + BAR);
                    let labels = scene.page_labels();
                    let panels: Vec<(&str, Rect)> = scene
                        .page_panel_info()
                        .iter()
                        .map(|p| (p.id, Rect::new(p.x, p.y, p.width, p.height)))
                        .collect();
                    let canvas = Rect::new(-0.5, -0.5, w + 1.0, h + 1.0);
                    for (i, a) in labels.iter().enumerate() {
                        let ba = a.bounds();
                        assert!(canvas.contains_rect(&ba), "{q} {w}×{h}: '{}' off the canvas", a.text);
                        for (id, r) in &panels {
                            if *id != a.panel || a.class != flexarm::view::LabelClass::Mark {
                                assert!(!overlap(&ba, r), "{q} {w}×{h}: '{}' covers {id}", a.text);
                            }
                        }
                        for b in &labels[i + 1..] {
                            assert!(!touch(&ba, &b.bounds()), "{q} {w}×{h}: '{}' touches '{}'", a.text, b.text);
                        }
                    }
                    checked += labels.len();
                }
            }
        }
    }
    println!("{checked} labels checked");
}

/// The page speaks CSS pixels of the screen: a pole reported at (x, y) is found by the pointer
/// there, and a time plot's time under the pointer is the same at any text size.
#[test]
fn the_pointer_finds_what_the_page_was_told_at_any_text_size() {
    for text in ["normal", "largest"] {
        let scene = drawn(&format!("mode=full&present=1&text={text}"), 1920.0, 1024.0, 1080.0);
        let poles = scene.page_pole_info();
        let shown: Vec<_> = poles.iter().filter(|p| p.in_view).collect();
        assert!(!shown.is_empty(), "text={text}: no pole in view");
        for p in shown {
            let (x, y) = (p.x.expect("in view"), p.y.expect("in view"));
            let probe = scene
                .page_probe(x, y, 2.0)
                .unwrap_or_else(|| panic!("text={text}: no pole under the pointer at {p:?}"));
            assert!((probe.x - x).abs() < 1.0 && (probe.y - y).abs() < 1.0, "text={text}: {probe:?} vs ({x}, {y})");
        }
        let e1 = scene.page_panel_info().into_iter().find(|p| p.id == PanelKind::Error1.id()).expect("e1 shown");
        let t = scene.page_time_at(e1.x + e1.width - 1.0, e1.y + e1.height / 2.0).expect("a time at e1's right edge");
        let end = scene.time_window().end;
        assert!((t - end).abs() < 0.05, "text={text}: t = {t} at the right edge, the window ends at {end} s");
    }
}

/// Issue 35, item 3: in presentation mode each text size is larger than the last on both
/// projectors (the floor applies to Normal), the page's own text (bar, verdict, key) with it.
const SIZES_PRESENTED: [&str; 4] = ["normal", "large", "larger", "largest"];
/// The projectors' heights, CSS px.
const SCREENS: [f64; 2] = [1080.0, 768.0];

#[test]
fn each_text_size_is_larger_than_the_last_on_both_projectors() {
    for h in SCREENS {
        let scales: Vec<f64> = SIZES_PRESENTED.iter().map(|s| text_scale(TextSize::from_name(s), true, h)).collect();
        let page: Vec<f64> =
            SIZES_PRESENTED.iter().map(|s| page_text_factor(TextSize::from_name(s), true, h)).collect();
        for (figure, bar) in scales.windows(2).zip(page.windows(2)) {
            // Visibly: at least 10 % larger each time, the figure's labels and the bar alike.
            assert!(figure[1] >= figure[0] * 1.1, "{h} lines: {scales:?}");
            assert!(bar[1] >= bar[0] * 1.1, "{h} lines: the bar {page:?}");
        }
        assert_eq!(page[0], 1.0, "Normal is the bar as designed");
        // Normal meets the floor (18 px ticks at 1080 lines, 14 px at 768).
        let floor = flexarm::view::text_size::presentation_min_text(h);
        assert!(scales[0] * 12.0 >= floor - 1e-9, "{h} lines: {scales:?}");
    }
}

/// Issue 35, item 3: on both projectors and at every text size, every axis with ticks keeps at
/// least three labels (a short axis gets a few more ticks rather than one or two labels).
#[test]
fn every_axis_keeps_three_tick_labels_at_every_presented_size() {
    let mut short = Vec::new();
    // The time axes after 13 s of Fig. 5.2 too (stable: it runs on): a window that has scrolled.
    for (view, seconds) in [
        ("preset=fig5.3&mode=full&plane=z", 1.5),
        ("preset=fig5.3&mode=full&predict=1", 1.5),
        ("preset=fig5.3&mode=full&compare=1", 1.5),
        ("preset=fig5.3&mode=intro", 1.5),
        ("preset=fig5.2&mode=full", 13.0),
    ] {
        for (w, h) in [(1920.0, 1080.0), (1024.0, 768.0)] {
            for text in SIZES_PRESENTED {
                let q = format!("{view}&present=1&text={text}");
                let scene = drawn_at(&q, w, h - BAR, h, seconds);
                for p in scene.page_panel_info() {
                    for (axis, ticks, labels) in [("x", &p.x_ticks, &p.x_labels), ("y", &p.y_ticks, &p.y_labels)] {
                        if !ticks.is_empty() && labels.len() < 3 {
                            short.push(format!("{q} at {w}×{h}: {} {axis} has {} labels", p.id, labels.len()));
                        }
                    }
                }
            }
        }
    }
    assert!(short.is_empty(), "{}", short.join("\n"));
}
