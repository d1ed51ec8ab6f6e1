//! What the page shows, as settings: the schema's view parameters ([`crate::schema::MODE`] …),
//! read from and written to the state string with the rest.

use crate::error::{Error, ParseError};
use crate::plot::color::Measure;
use crate::schema::{self, Param, Value};

/// What the page shows: the schema's view parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewSettings {
    /// The full view (every control and figure) rather than the intro.
    pub full: bool,
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
    /// The time plots zoomed on one sampling instant (Fig. 2.1).
    pub predict: bool,
    /// The flexible pair's shape animated on the arm.
    pub swing: bool,
    /// The view a narrow canvas shows ("run", "poles", "maps").
    pub tab: &'static str,
    /// Embedded in another page: the canvas and a strip of controls.
    pub embed: bool,
    /// The time plots' window, s.
    pub window: f64,
    /// Student mode (`answers=hidden`): what gives the answer away waits for the student's answer.
    pub answers_hidden: bool,
}

/// The view parameters, in the order the state string writes them.
pub(super) const VIEW_PARAMS: [&Param; 14] = [
    &schema::MODE,
    &schema::EMBED,
    &schema::WINDOW,
    &schema::TAB,
    &schema::POLES,
    &schema::PLANE,
    &schema::RHO,
    &schema::MAP,
    &schema::MEASURE,
    &schema::TORQUE,
    &schema::LOG,
    &schema::PREDICT,
    &schema::SWING,
    &schema::ANSWERS,
];

impl Default for ViewSettings {
    fn default() -> Self {
        let mut v = Self {
            full: false,
            poles: false,
            z_plane: false,
            rho: false,
            map: false,
            measure: Measure::Rho,
            torque: false,
            log: false,
            predict: false,
            swing: false,
            tab: "run",
            embed: false,
            window: 10.0,
            answers_hidden: false,
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
            "plane" => Value::Choice(if self.z_plane { "z" } else { "s" }),
            "tab" => Value::Choice(self.tab),
            "embed" => Value::Switch(self.embed),
            "window" => Value::Number(self.window),
            "poles" => Value::Switch(self.poles),
            "rho" => Value::Switch(self.rho),
            "map" => Value::Switch(self.map),
            "measure" => Value::Choice(self.measure.name()),
            "torque" => Value::Switch(self.torque),
            "log" => Value::Switch(self.log),
            "predict" => Value::Switch(self.predict),
            "swing" => Value::Switch(self.swing),
            "answers" => Value::Choice(if self.answers_hidden { "hidden" } else { "shown" }),
            _ => return None,
        })
    }

    /// Sets a view parameter; false if `key` is not one.
    pub(super) fn set(&mut self, key: &str, v: Value) -> bool {
        match (key, v) {
            ("mode", Value::Choice(m)) => self.full = m == "full",
            ("plane", Value::Choice(p)) => self.z_plane = p == "z",
            ("tab", Value::Choice(t)) => self.tab = t,
            ("embed", Value::Switch(b)) => self.embed = b,
            ("window", Value::Number(w)) => self.window = w,
            ("poles", Value::Switch(b)) => self.poles = b,
            ("rho", Value::Switch(b)) => self.rho = b,
            ("map", Value::Switch(b)) => self.map = b,
            ("measure", Value::Choice(m)) => self.measure = Measure::from_name(m).unwrap_or_default(),
            ("torque", Value::Switch(b)) => self.torque = b,
            ("log", Value::Switch(b)) => self.log = b,
            ("predict", Value::Switch(b)) => self.predict = b,
            ("swing", Value::Switch(b)) => self.swing = b,
            ("answers", Value::Choice(a)) => self.answers_hidden = a == "hidden",
            _ => return false,
        }
        true
    }

    /// The figures named in a list (`views=arm,traces,zplane`): the arm and the errors are always
    /// drawn; `poles` or `zplane`, `rho`, `map` and `torque` add theirs, and only those.
    pub fn read_views(&mut self, list: &str) -> Result<(), Error> {
        const KNOWN: [&str; 7] = ["arm", "traces", "poles", "zplane", "rho", "map", "torque"];
        let names: Vec<&str> = list.split(',').map(str::trim).filter(|n| !n.is_empty()).collect();
        if let Some(bad) = names.iter().find(|n| !KNOWN.contains(n)) {
            return Err(Error::Parse(ParseError {
                key: "views".into(),
                text: (*bad).into(),
                expected: format!("a list of {}", KNOWN.join(", ")),
            }));
        }
        let has = |n: &str| names.contains(&n);
        self.full = true;
        self.poles = has("poles") || has("zplane");
        self.z_plane = has("zplane");
        self.rho = has("rho");
        self.map = has("map");
        self.torque = has("torque");
        Ok(())
    }

    /// What is drawn: the intro shows the arm and the errors only, whatever the figures' switches
    /// say; an embedded page what they say.
    pub fn shown(&self) -> Self {
        if self.full || self.embed {
            *self
        } else {
            Self { poles: false, rho: false, map: false, torque: false, predict: false, swing: false, ..*self }
        }
    }
}
