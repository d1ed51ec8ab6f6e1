//! What the page shows, as settings: the schema's view parameters ([`crate::schema::MODE`] …),
//! read from and written to the state string with the rest.

use crate::error::{Error, ParseError};
use crate::plot::color::Measure;
use crate::schema::{self, Param, Tab, Value};

/// What the page shows: the schema's view parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewSettings {
    /// The full view (every control and figure) rather than the intro.
    pub full: bool,
    /// The arm picture (off: an embed of plots alone).
    pub picture: bool,
    /// The error plots e1, e2.
    pub errors: bool,
    /// The controls an embed's strip shows (`strip=play,reset,delta,alpha,pf`).
    pub strip: Strip,
    pub poles: bool,
    /// The pole plot draws λ with the unit circle instead of s = ln λ / δ.
    pub z_plane: bool,
    pub rho: bool,
    pub map: bool,
    /// What the maps and ρ(δ) show: ρ per period or ln ρ/δ per second.
    pub measure: Measure,
    pub torque: bool,
    /// log |e| with the predicted slope.
    pub log: bool,
    /// The errors as the controller read them, beside the true ones.
    pub measured: bool,
    /// The sensor study's curves over δ beside ρ(δ).
    pub study: bool,
    /// The time plots zoomed on one sampling instant (Fig. 2.1).
    pub predict: bool,
    /// The flexible pair's shape animated on the arm.
    pub swing: bool,
    /// The view a narrow canvas shows.
    pub tab: Tab,
    /// Embedded in another page: the canvas and a strip of controls.
    pub embed: bool,
    /// The time plots' window, s.
    pub window: f64,
    /// Student mode (`answers=hidden`): what gives the answer away waits for the student's answer.
    pub answers_hidden: bool,
    /// Presentation mode: the figure over the whole screen.
    pub present: bool,
    /// The figure's text size ("normal", "large", "larger", "largest").
    pub text: &'static str,
    /// The z-plane's view: half its shorter side in units of λ, 0 for the default (around the
    /// flexible pair); and its centre (Re λ, Im λ).
    pub z_size: f64,
    pub z_center: [f64; 2],
}

/// The view parameters, in the order the state string writes them.
pub(super) const VIEW_PARAMS: [&Param; 23] = [
    &schema::MODE,
    &schema::EMBED,
    &schema::WINDOW,
    &schema::TAB,
    &schema::PICTURE,
    &schema::ERRORS,
    &schema::POLES,
    &schema::PLANE,
    &schema::RHO,
    &schema::MAP,
    &schema::MEASURE,
    &schema::TORQUE,
    &schema::LOG,
    &schema::MEASURED,
    &schema::STUDY,
    &schema::PREDICT,
    &schema::SWING,
    &schema::ANSWERS,
    &schema::PRESENT,
    &schema::TEXT,
    &schema::ZSIZE,
    &schema::ZRE,
    &schema::ZIM,
];

impl Default for ViewSettings {
    fn default() -> Self {
        let mut v = Self {
            full: false,
            picture: true,
            errors: true,
            strip: Strip::DEFAULT,
            poles: false,
            z_plane: false,
            rho: false,
            map: false,
            measure: Measure::Rho,
            torque: false,
            log: false,
            measured: false,
            study: false,
            predict: false,
            swing: false,
            tab: Tab::Run,
            embed: false,
            window: 10.0,
            answers_hidden: false,
            present: false,
            text: "normal",
            z_size: 0.0,
            z_center: [0.0, 0.0],
        };
        for p in VIEW_PARAMS {
            v.set(p.key, p.default_value());
        }
        v
    }
}

impl ViewSettings {
    /// The value of a view parameter.
    pub fn get(&self, key: &str) -> Option<Value> {
        Some(match key {
            "mode" => Value::Choice(if self.full { "full" } else { "intro" }),
            "picture" => Value::Switch(self.picture),
            "errors" => Value::Switch(self.errors),
            "plane" => Value::Choice(if self.z_plane { "z" } else { "s" }),
            "tab" => Value::Choice(self.tab.id()),
            "embed" => Value::Switch(self.embed),
            "window" => Value::Number(self.window),
            "poles" => Value::Switch(self.poles),
            "rho" => Value::Switch(self.rho),
            "map" => Value::Switch(self.map),
            "measure" => Value::Choice(self.measure.name()),
            "torque" => Value::Switch(self.torque),
            "log" => Value::Switch(self.log),
            "measured" => Value::Switch(self.measured),
            "study" => Value::Switch(self.study),
            "predict" => Value::Switch(self.predict),
            "swing" => Value::Switch(self.swing),
            "answers" => Value::Choice(if self.answers_hidden { "hidden" } else { "shown" }),
            "present" => Value::Switch(self.present),
            "text" => Value::Choice(self.text),
            "zsize" => Value::Number(self.z_size),
            "zre" => Value::Number(self.z_center[0]),
            "zim" => Value::Number(self.z_center[1]),
            _ => return None,
        })
    }

    /// Sets a view parameter; false if `key` is not one.
    pub(super) fn set(&mut self, key: &str, v: Value) -> bool {
        match (key, v) {
            ("mode", Value::Choice(m)) => self.full = m == "full",
            ("picture", Value::Switch(b)) => self.picture = b,
            ("errors", Value::Switch(b)) => self.errors = b,
            ("plane", Value::Choice(p)) => self.z_plane = p == "z",
            ("tab", Value::Choice(t)) => self.tab = Tab::from_id(t).unwrap_or_default(),
            ("embed", Value::Switch(b)) => self.embed = b,
            ("window", Value::Number(w)) => self.window = w,
            ("poles", Value::Switch(b)) => self.poles = b,
            ("rho", Value::Switch(b)) => self.rho = b,
            ("map", Value::Switch(b)) => self.map = b,
            ("measure", Value::Choice(m)) => self.measure = Measure::from_name(m).unwrap_or_default(),
            ("torque", Value::Switch(b)) => self.torque = b,
            ("log", Value::Switch(b)) => self.log = b,
            ("measured", Value::Switch(b)) => self.measured = b,
            ("study", Value::Switch(b)) => self.study = b,
            ("predict", Value::Switch(b)) => self.predict = b,
            ("swing", Value::Switch(b)) => self.swing = b,
            ("answers", Value::Choice(a)) => self.answers_hidden = a == "hidden",
            ("present", Value::Switch(b)) => self.present = b,
            ("text", Value::Choice(t)) => self.text = t,
            // Between 0 (the default view) and the closest zoom: the closest zoom.
            ("zsize", Value::Number(v)) => self.z_size = if v > 0.0 { v.max(1e-4) } else { 0.0 },
            ("zre", Value::Number(v)) => self.z_center[0] = v,
            ("zim", Value::Number(v)) => self.z_center[1] = v,
            _ => return false,
        }
        true
    }

    /// The figures named in a list (`views=zplane,rho`): exactly those, the arm (`arm`) and the
    /// errors (`traces`) included: `poles` or `zplane` (the z-plane if both), `rho`, `map`,
    /// `torque`. A name that is no figure, or a list that names none, is an error.
    pub fn read_views(&mut self, list: &str) -> Result<(), Error> {
        let names = read_list("views", list, &VIEWS)?;
        if names.is_empty() {
            return Err(list_error("views", list, &VIEWS, "a list naming at least one figure"));
        }
        let has = |n: &str| names.contains(&n);
        self.full = true;
        self.picture = has("arm");
        self.errors = has("traces");
        self.poles = has("poles") || has("zplane");
        self.z_plane = has("zplane");
        self.rho = has("rho");
        self.map = has("map");
        self.torque = has("torque");
        Ok(())
    }

    /// The figures drawn, as `views=` names them (`arm,traces,zplane,rho`): the list that gives
    /// this view back.
    pub fn views_list(&self) -> String {
        let v = self.shown();
        let pole = if v.z_plane { "zplane" } else { "poles" };
        let named = [
            ("arm", v.picture),
            ("traces", v.errors),
            // The zoom on one sampling instant shows the torques held.
            ("torque", v.torque || v.predict),
            (pole, v.poles),
            ("rho", v.rho),
            ("map", v.map),
        ];
        let names: Vec<&str> = named.iter().filter(|(_, on)| *on).map(|(n, _)| *n).collect();
        names.join(",")
    }

    /// What is drawn: the intro shows the arm and the errors only, whatever the figures' switches
    /// say — but in presentation mode the zoom on one sampling instant too, when a link asks for
    /// it (`present=1&predict=1`: a lecturer's Fig. 2.1); the full view what they say, with the
    /// arm and the errors always (it has no control to bring them back); an embedded page exactly
    /// what they say.
    pub fn shown(&self) -> Self {
        if self.embed {
            *self
        } else if self.full {
            Self { picture: true, errors: true, ..*self }
        } else {
            Self {
                picture: true,
                errors: true,
                poles: false,
                rho: false,
                map: false,
                torque: false,
                study: false,
                predict: self.predict && self.present,
                swing: false,
                ..*self
            }
        }
    }

    /// The view's keys that differ from the defaults (the view's part of a state string; links
    /// stay short), the embed's strip among them.
    pub fn query_pairs(&self) -> Vec<(&'static str, String)> {
        let defaults = ViewSettings::default();
        let mut pairs = Vec::new();
        for p in VIEW_PARAMS {
            let v = self.get(p.key).expect("view keys have values");
            if defaults.get(p.key) != Some(v) {
                pairs.push((p.key, v.text()));
            }
        }
        if self.strip != defaults.strip {
            pairs.push(("strip", self.strip.text()));
        }
        pairs
    }
}

/// The figures `views=` can name.
pub const VIEWS: [&str; 7] = ["arm", "traces", "poles", "zplane", "rho", "map", "torque"];

/// The controls an embed's strip can show: Play/Pause (Restart after divergence), Reset, the δ
/// and α sliders, and the K_pr switch, in the order the strip shows them.
pub const STRIP_CONTROLS: [&str; 5] = ["play", "reset", "delta", "alpha", "pf"];

/// The controls an embedded page's strip shows (`strip=play,reset,delta`), one bit each in the
/// order of [`STRIP_CONTROLS`]; the verdict and "Open flexarm ↗" are always there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Strip(u8);

impl Strip {
    /// Play and the K_pr switch: what the strip always had.
    pub const DEFAULT: Strip = Strip(0b1_0001);

    /// Reads a list of [`STRIP_CONTROLS`] names (empty: the verdict and the link alone).
    pub fn read(list: &str) -> Result<Strip, Error> {
        let names = read_list("strip", list, &STRIP_CONTROLS)?;
        Ok(Strip(STRIP_CONTROLS.iter().enumerate().filter(|(_, c)| names.contains(c)).fold(0, |b, (i, _)| b | 1 << i)))
    }

    /// True if the strip shows the control named `name`.
    pub fn has(self, name: &str) -> bool {
        STRIP_CONTROLS.iter().position(|c| *c == name).is_some_and(|i| self.0 & (1 << i) != 0)
    }

    /// The list as the state string writes it (`play,reset,delta`).
    pub fn text(self) -> String {
        let names: Vec<&str> = STRIP_CONTROLS.into_iter().filter(|c| self.has(c)).collect();
        names.join(",")
    }
}

/// The names of a comma-separated list, each checked against `known`.
fn read_list<'a>(key: &str, list: &'a str, known: &[&str]) -> Result<Vec<&'a str>, Error> {
    let names: Vec<&str> = list.split(',').map(str::trim).filter(|n| !n.is_empty()).collect();
    match names.iter().find(|n| !known.contains(n)) {
        Some(bad) => Err(list_error(key, bad, known, "")),
        None => Ok(names),
    }
}

/// "expected a list of a, b, c" (with what more is expected, if anything).
fn list_error(key: &str, text: &str, known: &[&str], more: &str) -> Error {
    let expected = if more.is_empty() {
        format!("a list of {}", known.join(", "))
    } else {
        format!("{more}: a list of {}", known.join(", "))
    };
    Error::Parse(ParseError { key: key.into(), text: text.into(), expected })
}
