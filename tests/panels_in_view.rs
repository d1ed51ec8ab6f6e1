//! Every panel the text talks about is on screen (issue 23 item 3): on a canvas that shows one tab
//! at a time (a phone, the page at 1024 × 768), a lesson step, a "Try:" button or a link that
//! names a panel selects the tab that holds it — the z-plane of "Why: a resonance the controller
//! feeds" is drawn, not hidden behind "Arm and errors".

mod common;
use common::session;

use flexarm::lesson::builtin;
use flexarm::session::Session;
use flexarm::view::{PanelKind, Scene, ViewOptions};

/// Canvases that may show one tab at a time: a phone, and the page's canvas at 1024 × 768.
const TABBED: [(f64, f64); 2] = [(374.0, 520.0), (640.0, 560.0)];

fn panels(s: &Session, w: f64, h: f64) -> Vec<PanelKind> {
    let mut scene = Scene::new(ViewOptions::default(), w, h, 1.0);
    scene.draw_session(s);
    // A phone always shows one tab at a time when there are analysis panels.
    assert!(w >= 600.0 || scene.layout().panels.len() <= 4, "{w}×{h}: everything at once on a phone?");
    scene.layout().panels.iter().map(|p| p.kind).collect()
}

/// The panel a lesson step's `state:` turns on first (the one its text is about), if any.
fn named_panel(state: &str) -> Option<PanelKind> {
    // A step that names its tab itself (log |e| before the pole plot) is about that tab's panels.
    if state.split('&').any(|kv| kv == "tab=run") {
        return Some(PanelKind::Error1);
    }
    let on = |key: &str| state.split('&').any(|kv| kv == format!("{key}=1"));
    let z = state.split('&').any(|kv| kv == "plane=z");
    state.split('&').find_map(|kv| match kv {
        "poles=1" => Some(if z { PanelKind::ZPlane } else { PanelKind::Poles }),
        "rho=1" if !on("poles") => Some(PanelKind::RhoCurve),
        "map=1" if !on("poles") && !on("rho") => Some(PanelKind::MapOff),
        _ => None,
    })
}

#[test]
fn every_lesson_step_shows_the_panel_it_is_about() {
    let lesson = builtin().expect("the built-in lesson");
    let mut s = common::visit("");
    let mut checked = 0;
    for (i, step) in lesson.steps.iter().enumerate() {
        s.lesson_open(i).expect("the step opens");
        s.refresh();
        let Some(kind) = named_panel(&step.state) else { continue };
        for (w, h) in TABBED {
            let shown = panels(&s, w, h);
            assert!(shown.contains(&kind), "step {} '{}' at {w}×{h}: {kind:?} not in {shown:?}", i + 1, step.title);
        }
        checked += 1;
    }
    // The lesson's z-plane, s-plane, ρ(δ) and map steps at least.
    assert!(checked >= 5, "only {checked} steps name a panel");
}

#[test]
fn a_link_or_a_try_button_naming_a_panel_shows_it() {
    // A link naming the z-plane opens on its tab; one naming nothing opens on the arm.
    let s = session("preset=fig5.3&mode=full&plane=z");
    assert!(panels(&s, 374.0, 520.0).contains(&PanelKind::ZPlane));
    let s = session("preset=fig5.3&mode=full");
    assert!(panels(&s, 374.0, 520.0).contains(&PanelKind::Arm));
    // A tab the link gives wins.
    let s = session("preset=fig5.3&mode=full&plane=z&tab=maps");
    assert!(panels(&s, 374.0, 520.0).contains(&PanelKind::MapOff));
    // A "Try:" button (a setting) turning the maps on brings them; turning log |e| on, the errors.
    let mut s = session("preset=fig5.3&mode=full&map=0&tab=poles");
    s.set("map", "1").unwrap();
    assert!(panels(&s, 374.0, 520.0).contains(&PanelKind::MapOff));
    s.set("log", "1").unwrap();
    assert!(panels(&s, 374.0, 520.0).contains(&PanelKind::Error1));
    // Switching to the full view names no panel: the tab stays.
    let mut s = session("preset=fig5.3");
    s.set("mode", "full").unwrap();
    assert!(panels(&s, 374.0, 520.0).contains(&PanelKind::Arm));
}
