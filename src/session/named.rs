//! Every panel the text talks about is on screen (issue 23 item 3): a lesson step, a "Try:" button
//! or a link that names a panel — turns it on, or changes what it shows — selects the tab that
//! holds it, so a phone or a 1024-px projector, which show one tab at a time, show that panel. A
//! `tab=` given with the change wins; where a change names several panels, the first named wins
//! (a lesson's `state:` line lists the one its text is about first). On a wide canvas, where every
//! panel is shown at once, the tab changes nothing.

use super::query::split_query;
use super::view::ViewSettings;

/// The tab holding the panel that the setting `key` names, if that panel is shown in `view`.
pub fn tab_of(key: &str, view: &ViewSettings) -> Option<&'static str> {
    let v = view.shown();
    let shown = match key {
        "poles" | "plane" => v.poles,
        "rho" => v.rho,
        "map" => v.map,
        "torque" => v.torque,
        "log" => v.log,
        "predict" => v.predict,
        "swing" => v.swing,
        // An embed's list: its first analysis panel.
        "views" => return tab_of("poles", view).or_else(|| tab_of("rho", view)).or_else(|| tab_of("map", view)),
        _ => false,
    };
    shown.then_some(match key {
        "poles" | "plane" | "rho" => "poles",
        "map" => "maps",
        _ => "run",
    })
}

/// The tab a state string (a link, a lesson step's `state:`) brings into view with `view` its
/// result: that of the first key naming a shown panel; none if it says `tab=` itself.
pub fn tab_named_in(state: &str, view: &ViewSettings) -> Option<&'static str> {
    let pairs = split_query(state);
    if pairs.iter().any(|(k, _)| k == "tab") {
        return None;
    }
    pairs.iter().find_map(|(k, _)| tab_of(k, view))
}

/// The tab a lesson step opens on, `view` being the settings its `state:` made (with the tab it
/// says, if it says one) and `shown` the tab shown before: the panel the step names; else the tab
/// it says; else the tab shown stays, if it still has panels.
pub fn step_tab(state: &str, view: &ViewSettings, shown: &'static str) -> &'static str {
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

/// True if `view` shows a panel on the tab `tab` ("run" always has the arm and the errors).
pub fn tab_has_panels(tab: &str, view: &ViewSettings) -> bool {
    let v = view.shown();
    match tab {
        "poles" => v.poles || v.rho,
        "maps" => v.map,
        _ => true,
    }
}
