//! What the page can change about the picture: which panels, the time window, the spring's
//! magnification.

use serde::{Deserialize, Serialize};

use super::layout::{LayoutOptions, Tab};
use super::panels::arm::drawing::DEFAULT_SPRING_MAGNIFICATION;
use super::text_size::TextSize;
use super::time_window::DEFAULT_TIME_WINDOW;
use crate::plot::color::Measure;

/// Longest time window accepted, s.
pub const MAX_TIME_WINDOW: f64 = 3600.0;
/// Largest spring magnification accepted.
pub const MAX_SPRING_MAGNIFICATION: f64 = 1000.0;

/// What the page can change about the picture.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ViewOptions {
    /// Show the arm picture (the stage); an embed may leave it out.
    pub show_arm: bool,
    /// Show the error plots e1, e2; an embed may leave them out.
    pub show_errors: bool,
    /// Exactly the panels asked for (an embed): the zoom on one sampling instant does not add
    /// the torque panel by itself.
    pub exact_panels: bool,
    /// Show the torque panel (T1, T2) below the error panels.
    pub show_torque: bool,
    /// Width W of the scrolling time window, s.
    pub time_window: f64,
    /// Magnification M of the spring twist θ − q1 in the arm picture.
    pub spring_magnification: f64,
    /// Show the pole plot.
    pub show_poles: bool,
    /// The pole plot shows λ with the unit circle (z-plane) instead of s = ln λ / δ.
    pub z_plane: bool,
    /// Show ρ(δ) at the current α with the stable windows.
    pub show_rho: bool,
    /// Show the two stability maps.
    pub show_map: bool,
    /// What the maps and ρ(δ) show (the session's view decides; not a page option).
    pub measure: Measure,
    /// The error plots show log |e|, with the slope ln ρ / δ the analysis predicts.
    pub log_errors: bool,
    /// The error plots add the errors as the controller read them (with the sensors on).
    pub show_measured: bool,
    /// The sensor study's curves over δ beside ρ(δ) (with the sensors on).
    pub show_study: bool,
    /// The time plots zoomed on one sampling instant: the prediction of Fig. 2.1.
    pub show_cycle: bool,
    /// The flexible pair's mode animated on the arm.
    pub show_swing: bool,
    /// The view a narrow canvas shows.
    pub tab: Tab,
    /// Student mode: what the analysis predicts (the slope ln ρ/δ on log |e|) is not drawn.
    pub hide_prediction: bool,
    /// The z-plane's view as the page set it (`zsize` …), or None: around the flexible pair.
    pub z_view: Option<super::panels::z_plane::view::ZView>,
    /// The figure's text size (the session's view decides; not a page option).
    pub text: TextSize,
    /// Presentation mode: the text never smaller than the screen needs.
    pub present: bool,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            show_arm: true,
            show_errors: true,
            exact_panels: false,
            show_torque: false,
            time_window: DEFAULT_TIME_WINDOW,
            spring_magnification: DEFAULT_SPRING_MAGNIFICATION,
            show_poles: true,
            z_plane: false,
            show_rho: true,
            show_map: true,
            measure: Measure::Rho,
            log_errors: false,
            show_measured: false,
            show_study: false,
            show_cycle: false,
            show_swing: false,
            tab: Tab::Run,
            hide_prediction: false,
            z_view: None,
            text: TextSize::Normal,
            present: false,
        }
    }
}

/// A partial update of [`ViewOptions`] as the page sends it; missing fields stay unchanged.
/// Unknown fields are rejected so that a misspelt option does not silently do nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OptionsUpdate {
    pub show_torque: Option<bool>,
    pub time_window: Option<f64>,
    pub spring_magnification: Option<f64>,
    pub show_poles: Option<bool>,
    pub z_plane: Option<bool>,
    pub show_rho: Option<bool>,
    pub show_map: Option<bool>,
    pub log_errors: Option<bool>,
}

impl OptionsUpdate {
    /// The accepted field names (for checking objects whose deserializer ignores unknown keys).
    pub const FIELDS: [&'static str; 8] = [
        "show_torque",
        "time_window",
        "spring_magnification",
        "show_poles",
        "z_plane",
        "show_rho",
        "show_map",
        "log_errors",
    ];

    /// An error message if `name` is not one of [`OptionsUpdate::FIELDS`].
    pub fn check_field(name: &str) -> Result<(), String> {
        if Self::FIELDS.contains(&name) {
            Ok(())
        } else {
            Err(format!("unknown option '{name}' (known: {})", Self::FIELDS.join(", ")))
        }
    }
}

impl ViewOptions {
    /// Applies `update` if every given field is valid; otherwise changes nothing and explains.
    pub fn apply(&mut self, update: &OptionsUpdate) -> Result<(), String> {
        let mut next = *self;
        if let Some(v) = update.show_torque {
            next.show_torque = v;
        }
        if let Some(w) = update.time_window {
            if !(w.is_finite() && w > 0.0 && w <= MAX_TIME_WINDOW) {
                return Err(format!("time_window = {w}: must be a number of seconds in (0, {MAX_TIME_WINDOW}]"));
            }
            next.time_window = w;
        }
        if let Some(m) = update.spring_magnification {
            if !(m.is_finite() && m > 0.0 && m <= MAX_SPRING_MAGNIFICATION) {
                return Err(format!("spring_magnification = {m}: must be a number in (0, {MAX_SPRING_MAGNIFICATION}]"));
            }
            next.spring_magnification = m;
        }
        if let Some(v) = update.show_poles {
            next.show_poles = v;
        }
        if let Some(v) = update.show_map {
            next.show_map = v;
        }
        for (field, value) in [
            (&mut next.z_plane, update.z_plane),
            (&mut next.show_rho, update.show_rho),
            (&mut next.log_errors, update.log_errors),
        ] {
            if let Some(v) = value {
                *field = v;
            }
        }
        *self = next;
        Ok(())
    }

    /// The panels these options ask for; `digital`: run A's controller reads sensors (the
    /// `measured` switch then adds the velocity panel, except zoomed on one instant; the `study`
    /// switch the study's two panels).
    pub(crate) fn layout_options(&self, pair: bool, digital: bool) -> LayoutOptions {
        LayoutOptions {
            show_arm: self.show_arm,
            show_errors: self.show_errors,
            show_torque: self.show_torque || (self.show_cycle && !self.exact_panels),
            show_velocity: self.show_measured && digital && !self.show_cycle,
            show_study: self.show_study && digital,
            show_poles: self.show_poles,
            z_plane: self.z_plane,
            show_rho: self.show_rho,
            show_map: self.show_map,
            pair,
            tab: self.tab,
        }
    }
}
