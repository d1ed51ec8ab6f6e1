//! What a user has set, as typed values keyed by the [`crate::schema`] keys, and the *state string*
//! that carries it everywhere: the page's URL query, `flexarm … --state`, the CSV and SVG headers.
//!
//! A state string is `key=value` pairs joined by `&` (`delta=0.01&alpha=2&pf=off&repeat=1`), read
//! over a base (the page's start, or the CLI's defaults). [`Settings::to_query`] writes every run
//! setting so a shared link means the same thing everywhere; [`Settings::command_line`] writes the
//! `flexarm simulate …` that reproduces run A.

use super::presets::{arm, preset, ArmPreset, Preset, ARMS, PRESETS};
use super::query::join_query;
pub use super::query::split_query;
use super::view::Strip;
pub use super::view::ViewSettings;
use crate::control::config::PreliminaryFeedbackChoice;
use crate::error::{Error, ParseError};
use crate::schema::{self, Scope, Value};

/// The preset the page opens with when its URL names none.
pub const PAGE_START_PRESET: &str = "fig5.3";

use super::run_settings::quiet_at_default;
pub use super::run_settings::{CompareSettings, RestPoint, RunSettings, REPEAT_HOLD};

/// Everything the page's URL holds: run A, run B if compared, the playback speed and the view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub a: RunSettings,
    /// Run B, when two runs are compared.
    pub b: Option<CompareSettings>,
    /// Simulated seconds per wall-clock second.
    pub speed: f64,
    pub view: ViewSettings,
    /// Where a link starts (`t=3&paused=1`): read once, then consumed by the session, never
    /// written back into the state string (a moment's link writes it: `Session::moment_query`).
    pub start: Start,
}

/// A link's moment: advance the runs to `time` (s) and, if `paused`, wait there.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Start {
    pub time: f64,
    pub paused: bool,
}

impl Default for Settings {
    /// The schema's defaults (what the CLI starts from).
    fn default() -> Self {
        Self {
            a: RunSettings::default(),
            b: None,
            speed: schema::SPEED.number().map_or(1.0, |n| n.default),
            view: ViewSettings::default(),
            start: Start::default(),
        }
    }
}

/// A value that was not taken, and why (the page shows these as notices).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Notice {
    pub key: String,
    pub text: String,
}

/// Where a state string comes from: the page checks numbers against its controls' spans and skips
/// bad values with a notice; the command line checks the hard limits, refuses bad values and
/// sets the page's own keys aside with a notice; a lesson step is checked like the page and refused like the
/// command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    Page,
    CommandLine,
    Lesson,
}

impl Settings {
    /// What the page opens with when its URL names no settings: the paper's Fig. 5.3 — the
    /// controller without preliminary feedback at δ = 0.01 s, the case the page is about — with
    /// the slew repeating, so there is always something moving, in the intro view.
    pub fn page_start() -> Self {
        let mut s = Self::default();
        s.a.repeat = true;
        if let Err(e) = s.apply_preset(preset(PAGE_START_PRESET).expect("the start preset exists")) {
            panic!("presets are valid: {e}");
        }
        s
    }

    /// The value of any parameter (run A's, run B's `b_*`, `speed`, `compare`).
    pub fn get(&self, key: &str) -> Option<Value> {
        match key {
            "speed" => Some(Value::Number(self.speed)),
            "t" => Some(Value::Number(self.start.time)),
            "paused" => Some(Value::Switch(self.start.paused)),
            "compare" => Some(Value::Switch(self.b.is_some())),
            "b_pf" => self.b.map(|b| Value::Choice(b.pf.name())),
            "b_delta" => self.b.map(|b| Value::Number(b.delta)),
            "b_alpha" => self.b.map(|b| Value::Number(b.alpha[0])),
            "b_arm" => self.b.map(|b| Value::Choice(b.arm.unwrap_or("same"))),
            _ => self.view.get(key).or_else(|| self.a.get(key)),
        }
    }

    /// Sets a parameter from a checked value. Run B's keys switch the comparison on.
    pub fn set(&mut self, key: &str, v: Value) -> Result<(), Error> {
        match (key, v) {
            ("speed", Value::Number(x)) => self.speed = x,
            ("t", Value::Number(x)) => self.start.time = x,
            ("paused", Value::Switch(on)) => self.start.paused = on,
            ("compare", Value::Switch(on)) => {
                self.b = if on { Some(self.b.unwrap_or_else(|| CompareSettings::switched(&self.a))) } else { None }
            }
            ("b_pf", Value::Choice(s)) => self.b_mut().pf = PreliminaryFeedbackChoice::from_name(s).unwrap_or_default(),
            ("b_delta", Value::Number(x)) => self.b_mut().delta = x,
            ("b_alpha", Value::Number(x)) => self.b_mut().alpha = [x, x],
            ("b_arm", Value::Choice(s)) => self.b_mut().arm = (s != "same").then_some(s),
            _ => {
                if !self.view.set(key, v) && !self.a.set(key, v) {
                    return Err(unknown(key));
                }
            }
        }
        Ok(())
    }

    /// False for a setting that does nothing with the others as they are: the twist feedback's
    /// gains while neither run uses `pf = twist`, the LQ weights while neither uses `pf = lq`.
    pub fn matters(&self, key: &str) -> bool {
        let used = |pf: PreliminaryFeedbackChoice| self.a.pf == pf || self.b.is_some_and(|b| b.pf == pf);
        if key == schema::TWIST_STIFFNESS.key || key == schema::TWIST_DAMPING.key {
            return used(PreliminaryFeedbackChoice::Twist);
        }
        if super::run_settings::is_lq_weight(key) {
            return used(PreliminaryFeedbackChoice::Lq);
        }
        if key == schema::SEED.key {
            return self.a.sensors.noise > 0.0;
        }
        true
    }

    fn b_mut(&mut self) -> &mut CompareSettings {
        let a = self.a;
        self.b.get_or_insert_with(|| CompareSettings::switched(&a))
    }

    /// Reads `key=text` as the schema says and sets it.
    pub fn set_text(&mut self, key: &str, text: &str, source: Source) -> Result<(), Error> {
        let p = schema::param(key).ok_or_else(|| unknown(key))?;
        // A lesson stays on the controls' spans, and so does a URL's playback and view; a URL's
        // run settings may hold what the page wrote for a value typed beyond a slider (within
        // the hard limits), so that a reload reproduces it.
        let on_spans = match source {
            Source::Lesson => true,
            Source::Page => p.scope == Scope::Page,
            Source::CommandLine => false,
        };
        let v = p.parse(text, on_spans)?;
        self.set(key, v)
    }

    /// Whether run A (and B) can run with these settings.
    pub fn validate(&self) -> Result<(), Error> {
        self.a.config().validate()?;
        if let Some(b) = self.b {
            b.run(&self.a).config().validate()?;
        }
        Ok(())
    }

    /// Reads a state string over `self`. The page ([`Source::Page`]) is lenient: a bad value is
    /// skipped with a [`Notice`]; the command line is strict: the first bad value is the error.
    /// One rule everywhere: every key is a setting of the state string, given once, with a value
    /// its parameter accepts. `preset=ID` is applied first, `alpha` before `alpha1`/`alpha2`; run
    /// B's keys count only with `compare=1`; the command line checks the page's own keys (speed,
    /// the view, the comparison, a moment) and sets them aside, each with a notice.
    pub fn read(&mut self, state: &str, source: Source) -> Result<Vec<Notice>, Error> {
        let pairs = split_query(state);
        let mut notices = Vec::new();
        // The page's own keys the command line checked and set aside.
        let mut set_aside = Vec::new();
        let mut fail = |key: &str, e: Error| -> Result<(), Error> {
            match source {
                Source::CommandLine | Source::Lesson => Err(e),
                Source::Page => {
                    notices.push(Notice { key: key.to_string(), text: e.to_string() });
                    Ok(())
                }
            }
        };
        if let Some((_, id)) = pairs.iter().rev().find(|(k, _)| k == "preset") {
            match preset(id) {
                Some(p) => self.apply_preset(p)?,
                None => fail("preset", preset_error(id))?,
            }
        }
        // `arm=ID`: the paper's arm with one part changed, before the arm's own keys.
        if let Some((_, id)) = pairs.iter().rev().find(|(k, _)| k == "arm") {
            if let Err(e) = self.set_arm(id) {
                fail("arm", e)?;
            }
        }
        if let Some((_, list)) = pairs.iter().rev().find(|(k, _)| k == "views") {
            if let Err(e) = self.view.read_views(list) {
                fail("views", e)?;
            }
        }
        // `strip=play,reset,delta`: the embed's controls, a list as `views=` is.
        if let Some((_, list)) = pairs.iter().rev().find(|(k, _)| k == "strip") {
            match Strip::read(list) {
                Ok(strip) => self.view.strip = strip,
                Err(e) => fail("strip", e)?,
            }
        }
        let compare = pairs.iter().rev().find(|(k, _)| k == "compare").map(|(_, v)| v.as_str());
        // One value per key, as one flag per option on the command line: a second is refused
        // there; a link (which a hand may have edited) keeps the last, as it always has, and says so.
        for (i, (key, text)) in pairs.iter().enumerate() {
            let earlier: Vec<&str> = pairs[..i].iter().filter(|(k, _)| k == key).map(|(_, v)| v.as_str()).collect();
            if earlier.len() == 1 {
                fail(key, repeated(key, earlier[0], text, source))?;
            }
        }
        let mut listed = false;
        for (key, _) in &pairs {
            // `lesson` is the session's (which step of the lesson is open), not a setting.
            // `lesson_src` is the page's too (where a teacher's lesson file is).
            if !matches!(key.as_str(), "preset" | "arm" | "lesson" | "lesson_src" | "views" | "strip")
                && schema::param(key).is_none()
            {
                // The settings there are are listed once, with the first unknown key.
                let e = if listed { unknown_again(key) } else { unknown(key) };
                listed = true;
                fail(key, e)?;
            } else if source == Source::CommandLine && matches!(key.as_str(), "lesson" | "lesson_src") {
                set_aside.push(ignored(key));
            }
        }
        if source == Source::CommandLine {
            set_aside
                .extend(["views", "strip"].into_iter().filter(|k| pairs.iter().any(|(key, _)| key == k)).map(ignored));
        }
        // Values that parse but do not run with the others as they stand (k without its m): tried
        // again together once every key is read, so a link may give both in any order.
        let mut deferred: Vec<(&'static schema::Param, &String, Error)> = Vec::new();
        for p in schema::PARAMS {
            // The last occurrence of a key wins, as in URLSearchParams.get of a rewritten URL.
            let Some((_, text)) = pairs.iter().rev().find(|(k, _)| k == p.key) else { continue };
            let page_only = matches!(p.scope, Scope::Page | Scope::Compare);
            if source == Source::CommandLine && page_only {
                // Checked like any value (a bad one is a mistake wherever it is), then set aside
                // with a notice: the command line plays nothing and shows no view.
                match p.parse(text, false) {
                    Ok(_) => set_aside.push(ignored(p.key)),
                    Err(e) => fail(p.key, e)?,
                }
                continue;
            }
            if p.scope == Scope::Cli {
                fail(p.key, cli_only(p.key, text))?;
                continue;
            }
            if p.scope == Scope::Compare && !matches!(compare, Some("1" | "true" | "on" | "yes")) {
                continue;
            }
            let before = *self;
            // The page takes a value only if the settings can still run together (an arm whose mass
            // matrix fails, a k that does not fit m); a value that was read but does not fit the
            // others waits for them (`deferred`), any other is that key's notice alone.
            let taken = match self.set_text(p.key, text, source) {
                Ok(()) if source == Source::Page => self.validate().map_err(|e| (e, true)),
                Ok(()) => Ok(()),
                Err(e) => Err((e, false)),
            };
            if let Err((e, read)) = taken {
                *self = before;
                // A link's notice names the key and the text it holds, as for a value it cannot read.
                let e = match e {
                    Error::Config(c) if source == Source::Page => {
                        Error::Parse(ParseError { key: p.key.into(), text: text.clone(), expected: c.allowed })
                    }
                    e => e,
                };
                if read {
                    deferred.push((p, text, e));
                } else {
                    fail(p.key, e)?;
                }
            }
        }
        if !deferred.is_empty() {
            let before = *self;
            let together = deferred.iter().all(|(p, text, _)| self.set_text(p.key, text, source).is_ok());
            if !(together && self.validate().is_ok()) {
                *self = before;
                for (p, _, e) in deferred {
                    fail(p.key, e)?;
                }
            }
        }
        notices.extend(set_aside);
        Ok(notices)
    }

    /// Applies a preset's settings over these.
    pub fn apply_preset(&mut self, p: &Preset) -> Result<(), Error> {
        // A preset is a whole robot: the paper's figures have its perfect sensors, and only a
        // preset that names sensors has them.
        self.a.sensors = crate::control::sensing::SensorModel::default();
        self.read(p.state, Source::CommandLine).map(|_| ())
    }

    /// Makes the arm the arm preset named `id` (an error lists the arms there are).
    pub fn set_arm(&mut self, id: &str) -> Result<(), Error> {
        let p = arm(id).ok_or_else(|| arm_error(id))?;
        self.a.plant = p.plant();
        Ok(())
    }

    /// The arm preset these settings' arm is, if any.
    pub fn arm_preset(&self) -> Option<&'static ArmPreset> {
        ARMS.iter().find(|p| p.plant() == self.a.plant)
    }

    /// True if these settings already have every value `p` sets.
    pub fn matches(&self, p: &Preset) -> bool {
        let mut applied = *self;
        applied.apply_preset(p).is_ok() && applied.a == self.a
    }

    /// The state string of everything set: every run setting of A, then the page's own keys.
    pub fn to_query(&self) -> String {
        join_query(&self.query_pairs(true))
    }

    /// The state string without the view's keys and the playback speed: what decides the runs
    /// (a slide's caption).
    pub fn runs_query(&self) -> String {
        join_query(&self.query_pairs(false))
    }

    fn query_pairs(&self, view: bool) -> Vec<(&'static str, String)> {
        let mut pairs = run_pairs(&self.a, false);
        if view {
            pairs.push(("speed", Value::Number(self.speed).text()));
        }
        if let Some(b) = &self.b {
            pairs.push(("compare", "1".into()));
            pairs.push(("b_pf", b.pf.name().into()));
            pairs.push(("b_delta", Value::Number(b.delta).text()));
            pairs.push(("b_alpha", Value::Number(b.alpha[0]).text()));
            // B's arm only when it is not A's: links to comparisons stay as they were.
            if let Some(arm) = b.arm {
                pairs.push(("b_arm", arm.into()));
            }
        }
        // The view's keys only where they differ from the defaults: links stay short.
        if view {
            pairs.extend(self.view.query_pairs());
        }
        pairs
    }

    /// The state string of run A alone (what the CLI's `--state` reproduces).
    pub fn run_query(&self) -> String {
        join_query(&run_pairs(&self.a, false))
    }

    /// `flexarm simulate …` reproducing run A: every setting that differs from the CLI's
    /// defaults, and δ, α and the preliminary feedback always; `duration` if given (s).
    pub fn command_line(&self, duration: Option<f64>) -> String {
        let mut words = vec!["flexarm".to_string(), "simulate".to_string()];
        for (key, text) in run_pairs(&self.a, true) {
            let p = schema::param(key).expect("run keys are schema keys");
            match p.kind {
                schema::Kind::Switch { .. } => {
                    if text == "1" {
                        words.push(p.flag());
                    }
                }
                _ => {
                    words.push(p.flag());
                    words.push(text);
                }
            }
        }
        if let Some(d) = duration.filter(|d| d.is_finite() && *d > 0.0) {
            words.push("--duration".into());
            words.push(schema::format_number(schema::round_significant(d, 4)));
        }
        words.join(" ")
    }
}

/// Run A's pairs in schema order: `alpha` when α1 = α2, else `alpha1` and `alpha2`. With
/// `changed_only`, settings at their CLI default are left out (except δ, α and K_pr).
pub(super) fn run_pairs(a: &RunSettings, changed_only: bool) -> Vec<(&'static str, String)> {
    let defaults = RunSettings::default();
    let mut out = Vec::new();
    for p in schema::PARAMS.iter().filter(|p| p.scope == Scope::Run) {
        let same_alpha = a.alpha[0] == a.alpha[1];
        let skip = match p.key {
            "alpha" => !same_alpha,
            "alpha1" | "alpha2" => same_alpha,
            _ => false,
        };
        if skip {
            continue;
        }
        let v = a.get(p.key).expect("run keys have values");
        let headline = matches!(p.key, "delta" | "alpha" | "alpha1" | "alpha2" | "pf");
        let quiet = changed_only || quiet_at_default(p.key);
        if quiet && !headline && defaults.get(p.key) == Some(v) {
            continue;
        }
        out.push((p.key, v.text()));
    }
    out
}

/// The notice of a page's own key that the command line reads, checks and sets aside.
fn ignored(key: &str) -> Notice {
    Notice { key: key.to_string(), text: format!("{key} is the page's own (how it plays and what it shows): ignored") }
}

/// A key given a second time: refused by the command line and a lesson; a link keeps the last.
fn repeated(key: &str, first: &str, again: &str, source: Source) -> Error {
    let taken = if source == Source::Page { "the last one is taken" } else { "give it once" };
    Error::Refused(format!("{key} is given twice in the state string ('{first}', then '{again}'): {taken}"))
}

/// A command-line option (`duration`, `output_interval`, `q2`) in a state string, which holds the
/// page's settings only: the flag sets it.
fn cli_only(key: &str, text: &str) -> Error {
    Error::Parse(ParseError {
        key: key.into(),
        text: text.into(),
        expected: "a setting of the state string, which holds the page's settings only: this one is the command \
                   line's"
            .into(),
    })
}

/// A key that names no setting ("invalid setting = 'bogus': expected a known setting: …"): the
/// key is what was given, so it is quoted like any other value (and shortened by the page). The
/// command line's own options are not among them.
fn unknown(key: &str) -> Error {
    let known: Vec<&str> = schema::PARAMS.iter().filter(|p| p.scope != Scope::Cli).map(|p| p.key).collect();
    Error::Parse(ParseError {
        key: "setting".into(),
        text: key.into(),
        expected: format!("a known setting: preset, arm, {}", known.join(", ")),
    })
}

/// A second key that names no setting, in a list of notices that named the known ones already.
fn unknown_again(key: &str) -> Error {
    Error::Parse(ParseError {
        key: "setting".into(),
        text: key.into(),
        expected: "a known setting (listed above)".into(),
    })
}

fn arm_error(id: &str) -> Error {
    let ids: Vec<&str> = ARMS.iter().map(|p| p.id).collect();
    Error::Parse(ParseError { key: "arm".into(), text: id.into(), expected: format!("one of {}", ids.join(" | ")) })
}

fn preset_error(id: &str) -> Error {
    let ids: Vec<&str> = PRESETS.iter().map(|p| p.id).collect();
    Error::Parse(ParseError { key: "preset".into(), text: id.into(), expected: format!("one of {}", ids.join(" | ")) })
}

#[cfg(test)]
mod tests {
    use super::super::query::{decode, encode};
    use super::*;
    use crate::control::config::{FrictionCompensation, SimulationConfig};

    #[test]
    fn defaults_are_the_papers_configuration() {
        assert_eq!(RunSettings::default().config(), SimulationConfig::default());
        // k may go below the index, to be tried; the default is well above it.
        assert_eq!(schema::K.number().unwrap().min, 1.0);
        assert!(schema::K.number().unwrap().default as usize > crate::control::config::DAE_INDEX);
    }

    #[test]
    fn settings_and_configurations_convert_both_ways() {
        let mut s = Settings::page_start();
        s.read("delta=0.04&alpha1=1&alpha2=3&pf=lq&friction=held&inner=sampled&k=10&eps_ratio=6", Source::Page)
            .unwrap();
        assert_eq!(RunSettings::of_config(&s.a.config()), s.a);
        assert_eq!(RunSettings::of_config(&Settings::default().a.config()), Settings::default().a);
    }

    #[test]
    fn a_query_round_trips() {
        let mut s = Settings::page_start();
        s.read("delta=0.04&alpha1=1&alpha2=3&pf=off&friction=held&inner=sampled&k=10&eps_ratio=6", Source::Page)
            .unwrap();
        s.b = Some(CompareSettings {
            pf: PreliminaryFeedbackChoice::Lq,
            delta: 0.02,
            alpha: [0.5, 0.5],
            arm: Some("damped"),
        });
        let q = s.to_query();
        let mut back = Settings::default();
        assert!(back.read(&q, Source::Page).unwrap().is_empty(), "{q}");
        assert_eq!(back, s, "{q}");
    }

    #[test]
    fn the_page_skips_bad_values_with_notices_the_cli_refuses_them() {
        let mut s = Settings::page_start();
        let notices = s.read("?delta=abc&pf=maybe&alpha=0.5&bogus=1&junk=2", Source::Page).unwrap();
        let keys: Vec<&str> = notices.iter().map(|n| n.key.as_str()).collect();
        assert_eq!(keys, ["bogus", "junk", "delta", "pf"]);
        assert!(notices[0].text.starts_with("invalid setting = 'bogus': expected a known setting: preset, arm, delta"));
        // The list of settings is said once, not on every line.
        assert_eq!(notices[1].text, "invalid setting = 'junk': expected a known setting (listed above)");
        assert_eq!(s.a.alpha, [0.5, 0.5]);
        assert_eq!(s.a.delta, 0.01);
        assert!(Settings::default().read("delta=abc", Source::CommandLine).is_err());
        assert!(
            Settings::default().read("delta=5", Source::Page).unwrap().is_empty(),
            "outside the slider, as the page writes a typed δ"
        );
        assert!(Settings::default().read("delta=50", Source::Page).unwrap().len() == 1, "beyond the hard limits");
        // A value that cannot run with the others is skipped alone; the rest of the link holds.
        let mut s = Settings::page_start();
        let notices = s.read("delta=0.05&a3=2&k1=4610.4", Source::Page).unwrap();
        assert_eq!(notices.iter().map(|n| n.key.as_str()).collect::<Vec<_>>(), ["a3"]);
        assert!(notices[0].text.contains("positive definite"), "{}", notices[0].text);
        assert_eq!((s.a.delta, s.a.plant.k1, s.a.plant.a3), (0.05, 4610.4, 0.328));
        assert!(Settings::default().read("delta=5", Source::CommandLine).unwrap().is_empty(), "inside the limits");
        // The page's own keys mean nothing to the CLI: checked, set aside, and said.
        let mut c = Settings::default();
        let notices = c.read("speed=2&compare=1&b_pf=off", Source::CommandLine).unwrap();
        assert_eq!(notices.iter().map(|n| n.key.as_str()).collect::<Vec<_>>(), ["speed", "compare", "b_pf"]);
        assert_eq!(c, Settings::default());
    }

    #[test]
    fn presets_apply_first_and_run_b_needs_compare() {
        let mut s = Settings::page_start();
        s.read("preset=fig5.3&delta=0.02&b_pf=lq", Source::Page).unwrap();
        assert_eq!((s.a.delta, s.a.pf, s.b), (0.02, PreliminaryFeedbackChoice::Off, None));
        s.read("compare=1&b_pf=lq", Source::Page).unwrap();
        assert_eq!(s.b.unwrap().pf, PreliminaryFeedbackChoice::Lq);
    }

    #[test]
    fn every_preset_applies_and_matches_afterwards() {
        for p in &PRESETS {
            let mut s = Settings::page_start();
            s.apply_preset(p).unwrap();
            assert!(s.matches(p), "{}", p.id);
            assert!(s.a.repeat, "{}: a preset leaves the slew as it was", p.id);
        }
        let mut s = Settings::default();
        s.apply_preset(preset("fig5.3").unwrap()).unwrap();
        s.a.delta = 0.02;
        assert!(!s.matches(preset("fig5.3").unwrap()));
    }

    #[test]
    fn the_command_line_names_what_differs() {
        let mut s = Settings::page_start();
        s.read("delta=0.01&pf=off", Source::Page).unwrap();
        assert_eq!(
            s.command_line(Some(4.25)),
            "flexarm simulate --delta 0.01 --alpha 2 --pf off --repeat --duration 4.25"
        );
        s.a.alpha = [1.0, 2.0];
        s.a.friction = FrictionCompensation::Held;
        s.a.repeat = false;
        assert_eq!(
            s.command_line(None),
            "flexarm simulate --delta 0.01 --alpha1 1 --alpha2 2 --pf off --friction held"
        );
    }

    #[test]
    fn queries_decode_and_encode() {
        assert_eq!(
            split_query("?a=1+2&b=%3Cx%3E&c"),
            [("a".into(), "1 2".into()), ("b".into(), "<x>".into()), ("c".into(), "".into())]
        );
        assert_eq!(encode("<script>"), "%3Cscript%3E");
        assert_eq!(decode("%zz%4"), "%zz%4");
    }
}
