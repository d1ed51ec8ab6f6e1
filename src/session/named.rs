//! Every panel the text talks about is on screen: a lesson step, a "Try:" button
//! or a link that names a panel — turns it on, or changes what it shows — selects the tab that
//! holds it, so a phone or a 1024-px projector, which show one tab at a time, show that panel. A
//! `tab=` given with the change wins; where a change names several panels, the first named wins
//! (a lesson's `state:` line lists the one its text is about first). On a wide canvas, where every
//! panel is shown at once, the tab changes nothing.

use super::query::split_query;
use super::view::ViewSettings;
use crate::schema::{PanelKind, Tab};

/// The panel the setting `key` turns on or changes, if that panel is shown in `view`.
fn panel_of(key: &str, view: &ViewSettings) -> Option<PanelKind> {
    let v = view.shown();
    let (shown, panel) = match key {
        "poles" | "plane" => (v.poles, if v.z_plane { PanelKind::ZPlane } else { PanelKind::Poles }),
        "rho" => (v.rho, PanelKind::RhoCurve),
        "map" => (v.map, PanelKind::MapOff),
        "torque" => (v.torque, PanelKind::Torque),
        "log" => (v.log, PanelKind::Error1),
        "predict" => (v.predict, PanelKind::Error1),
        "swing" => (v.swing, PanelKind::Arm),
        "study" => (v.study, PanelKind::StudyError),
        // An embed's list: its first analysis panel.
        "views" => return panel_of("poles", view).or_else(|| panel_of("rho", view)).or_else(|| panel_of("map", view)),
        _ => return None,
    };
    shown.then_some(panel)
}

/// The tab holding the panel that the setting `key` names, if that panel is shown in `view`.
pub fn tab_of(key: &str, view: &ViewSettings) -> Option<Tab> {
    panel_of(key, view).map(PanelKind::tab)
}

/// The tab a state string (a link, a lesson step's `state:`) brings into view with `view` its
/// result: that of the first key naming a shown panel; none if it says `tab=` itself.
pub fn tab_named_in(state: &str, view: &ViewSettings) -> Option<Tab> {
    let pairs = split_query(state);
    if pairs.iter().any(|(k, _)| k == "tab") {
        return None;
    }
    pairs.iter().find_map(|(k, _)| tab_of(k, view))
}

/// The tab a lesson step opens on, `view` being the settings its `state:` made (with the tab it
/// says, if it says one) and `shown` the tab shown before: the panel the step names; else the tab
/// it says; else the tab shown stays, if it still has panels.
pub fn step_tab(state: &str, view: &ViewSettings, shown: Tab) -> Tab {
    let pairs = split_query(state);
    if pairs.iter().any(|(k, _)| k == "tab") {
        return view.tab;
    }
    match pairs.iter().find_map(|(k, _)| tab_of(k, view)) {
        Some(tab) => tab,
        None if tab_has_panels(shown, view) => shown,
        None => view.tab,
    }
}

/// True if `view` shows a panel on the tab `tab` (the run's always has the arm and the errors).
pub fn tab_has_panels(tab: Tab, view: &ViewSettings) -> bool {
    let v = view.shown();
    match tab {
        Tab::Poles => v.poles || v.rho,
        Tab::Maps => v.map,
        Tab::Study => v.study,
        Tab::Run => true,
    }
}
