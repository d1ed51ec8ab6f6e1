//! Every user-settable parameter, once: its key (the same word in the URL, on the command line as
//! `--key` with `-` for `_`, and in JSON), label, symbol, unit, allowed range and why, the span of
//! the page's control and its scale, the default, and a help text.
//!
//! The page builds its controls, URL parsing and notices from [`PARAMS`]; the CLI builds its flags
//! and help from it; the core's validation checks its numbers against the same [`NumberSpec`]s, so
//! a range is written in one place. This module is data and the checks on single values; how the
//! values map onto a configuration lives in [`crate::session::settings`].

use crate::error::{ConfigError, Error, ParseError};

/// How a numeric control moves between its ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Scale {
    Linear,
    /// Logarithmic: equal steps multiply the value (δ, α, speed span decades).
    Log,
}

/// A number: its hard limits, the span of the page's control, scale, precision and default.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NumberSpec {
    /// Smallest value accepted; inclusive only if `min_inclusive`.
    pub min: f64,
    pub min_inclusive: bool,
    /// Largest value accepted (inclusive); `f64::INFINITY` for none.
    pub max: f64,
    /// The allowed range in words, when the plain "must be > 0 and at most …" would not say why.
    pub allowed: Option<&'static str>,
    /// The span of the page's control (a part of the limits).
    pub control: [f64; 2],
    pub scale: Scale,
    /// Significant digits a control position is rounded to (0.0347 s, not 0.034712…).
    pub digits: u32,
    /// Whole numbers only.
    pub integer: bool,
    pub default: f64,
}

impl NumberSpec {
    /// The allowed range in words, as `--help` and notices say it.
    pub fn allowed_text(&self, unit: &str) -> String {
        if let Some(text) = self.allowed {
            return text.to_string();
        }
        if self.max.is_finite() {
            format!("{} and at most {}{}", self.low_text(unit), self.max, unit_suffix(unit))
        } else {
            self.low_text(unit)
        }
    }

    /// What `v` violates, in words: "must be > 0", "must be at most 10 s".
    pub fn violation_text(&self, v: f64, unit: &str) -> String {
        if let Some(text) = self.allowed {
            return text.to_string();
        }
        if !v.is_finite() {
            "must be a finite number".to_string()
        } else if v > self.max {
            format!("must be at most {}{}", self.max, unit_suffix(unit))
        } else if self.integer && v.fract() != 0.0 {
            "must be a whole number".to_string()
        } else {
            self.low_text(unit)
        }
    }

    fn low_text(&self, unit: &str) -> String {
        let op = if self.min_inclusive { "≥" } else { ">" };
        let unit = if self.min == 0.0 { "" } else { unit };
        format!("must be {op} {}{}", self.min, unit_suffix(unit))
    }

    /// True if `v` lies within the hard limits.
    pub fn admits(&self, v: f64) -> bool {
        v.is_finite()
            && (v > self.min || (self.min_inclusive && v == self.min))
            && v <= self.max
            && (!self.integer || v.fract() == 0.0)
    }

    /// True if `v` lies within the control's span (with a little slack for rounded text).
    pub fn in_control(&self, v: f64) -> bool {
        // The slack is relative to each end's size, so that a negative end (the z-plane's centre)
        // admits itself.
        let [lo, hi] = self.control;
        v.is_finite() && v >= lo - 1e-9 * lo.abs() && v <= hi + 1e-9 * hi.abs()
    }

    /// The control position in [0, 1] of `v` (clamped to the control's span).
    pub fn position(&self, v: f64) -> f64 {
        let [lo, hi] = self.control;
        let f = match self.scale {
            Scale::Log => (v / lo).ln() / (hi / lo).ln(),
            Scale::Linear => (v - lo) / (hi - lo),
        };
        if f.is_finite() {
            f.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// The value at control position `f` in [0, 1], rounded to `digits` significant digits (whole
    /// numbers for integer parameters) and kept inside the span.
    pub fn value_at(&self, f: f64) -> f64 {
        let [lo, hi] = self.control;
        let f = if f.is_finite() { f.clamp(0.0, 1.0) } else { 0.0 };
        let raw = match self.scale {
            Scale::Log => lo * (hi / lo).powf(f),
            Scale::Linear => lo + f * (hi - lo),
        };
        let v = if self.integer { raw.round() } else { round_significant(raw, self.digits) };
        v.clamp(lo, hi)
    }

    /// `v` as a click on a figure sets it: rounded to the control's precision and kept inside its
    /// span (what a map's tooltip says will run is what runs).
    pub fn snap(&self, v: f64) -> f64 {
        self.value_at(self.position(round_significant(v, self.digits)))
    }
}

/// The values a logarithmic control steps through with the arrow keys, per decade: 1, 1.2, 1.5,
/// 2, 2.5, 3, 4, 5, 6, 8 — round numbers a user can type and compare, about 20 % apart.
pub const LOG_STEPS: [f64; 10] = [1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

impl NumberSpec {
    /// The value `steps` arrow-key steps from `v` (negative: down), within the control's span: on
    /// a logarithmic control the next round values of [`LOG_STEPS`], on a linear one whole
    /// numbers or a fiftieth of the span; a step from between two round values lands on the next
    /// one, and the span's ends are steps too.
    pub fn step_from(&self, v: f64, steps: i32) -> f64 {
        let [lo, hi] = self.control;
        let mut x = if v.is_finite() { v.clamp(lo, hi) } else { lo };
        for _ in 0..steps.unsigned_abs() {
            let up = steps > 0;
            let next = match self.scale {
                Scale::Log => next_round(x, up),
                Scale::Linear => {
                    let step = if self.integer { 1.0 } else { round_significant((hi - lo) / 50.0, 1) };
                    let k = x / step + if up { 1e-9 } else { -1e-9 };
                    (if up { k.floor() + 1.0 } else { k.ceil() - 1.0 }) * step
                }
            };
            x = next.clamp(lo, hi);
        }
        x
    }
}

/// The next value of the [`LOG_STEPS`] ladder above (or below) `x`.
fn next_round(x: f64, up: bool) -> f64 {
    let decade = 10f64.powf(x.log10().floor());
    let ladder = (-1..=1).flat_map(|d| LOG_STEPS.map(|m| round_significant(m * decade * 10f64.powi(d), 3)));
    let candidates = ladder.filter(|&c| if up { c > x * (1.0 + 1e-9) } else { c < x * (1.0 - 1e-9) });
    if up {
        candidates.fold(f64::INFINITY, f64::min)
    } else {
        candidates.fold(0.0, f64::max)
    }
}

fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

/// `v` rounded to `digits` significant digits.
pub fn round_significant(v: f64, digits: u32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    // Through the decimal text, so 0.0347 is the double nearest to 0.0347.
    format!("{:.*e}", digits.saturating_sub(1) as usize, v).parse().unwrap_or(v)
}

/// One option of a choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Choice {
    /// The word in URLs, on the command line and in JSON.
    pub value: &'static str,
    /// What the page's selector shows.
    pub label: &'static str,
}

/// What kind of value a parameter takes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    Number(NumberSpec),
    Choice {
        options: &'static [Choice],
        default: &'static str,
    },
    /// On or off: `1`/`0` in URLs and state strings, a bare `--flag` on the command line.
    Switch {
        default: bool,
    },
}

/// Where a parameter can be set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Scope {
    /// A setting of a run (run A on the page): page, URL, state string and every CLI command that
    /// runs or analyses the loop.
    Run,
    /// Run B of the page's comparison (URL and page only).
    Compare,
    /// How the page plays (URL and page only).
    Page,
    /// A command-line option of a run (not a control on the page).
    Cli,
}

/// One user-settable parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Param {
    /// URL key, JSON field, and the CLI flag `--key` (with `-` for `_`).
    pub key: &'static str,
    /// Label on the page, e.g. "Sampling period δ".
    pub label: &'static str,
    /// The paper's symbol, e.g. "δ" (empty if none).
    pub symbol: &'static str,
    /// SI unit ("s", "1/s", "" for none).
    pub unit: &'static str,
    /// The name error messages use, e.g. "sampling_period (δ)".
    pub name: &'static str,
    pub kind: Kind,
    pub scope: Scope,
    /// One or two sentences for tooltips and `--help`.
    pub help: &'static str,
}

/// A parsed value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    Number(f64),
    Choice(&'static str),
    Switch(bool),
}

impl Value {
    /// The value as the state string writes it.
    pub fn text(&self) -> String {
        match self {
            Value::Number(v) => format_number(*v),
            Value::Choice(s) => (*s).to_string(),
            Value::Switch(b) => if *b { "1" } else { "0" }.to_string(),
        }
    }

    pub fn number(&self) -> Option<f64> {
        match self {
            Value::Number(v) => Some(*v),
            _ => None,
        }
    }

    pub fn choice(&self) -> Option<&'static str> {
        match self {
            Value::Choice(s) => Some(s),
            _ => None,
        }
    }

    pub fn switch(&self) -> Option<bool> {
        match self {
            Value::Switch(b) => Some(*b),
            _ => None,
        }
    }
}

/// The shortest decimal text that reads back as `v` (0.01, not 0.010000000000000000208).
pub fn format_number(v: f64) -> String {
    let s = format!("{v}");
    if s.len() <= 12 {
        return s;
    }
    for digits in 1..=17 {
        let t = format!("{:.*e}", digits - 1, v);
        if t.parse::<f64>().ok() == Some(v) {
            let short: f64 = t.parse().unwrap_or(v);
            let plain = format!("{short}");
            return if plain.len() <= t.len() + 2 { plain } else { t };
        }
    }
    s
}

impl Param {
    /// The number spec, for numeric parameters.
    pub fn number(&self) -> Option<&NumberSpec> {
        match &self.kind {
            Kind::Number(n) => Some(n),
            _ => None,
        }
    }

    /// The default value.
    pub fn default_value(&self) -> Value {
        match self.kind {
            Kind::Number(n) => Value::Number(n.default),
            Kind::Choice { default, .. } => Value::Choice(default),
            Kind::Switch { default } => Value::Switch(default),
        }
    }

    /// The command-line flag, `--eps-ratio` for `eps_ratio`.
    pub fn flag(&self) -> String {
        format!("--{}", self.key.replace('_', "-"))
    }

    /// The allowed values in words: "0.002–0.25 s (logarithmic)", "off | paper | lq", "1 | 0".
    pub fn allowed(&self, control: bool) -> String {
        match &self.kind {
            Kind::Number(n) if control => {
                let unit = if self.unit.is_empty() { String::new() } else { format!(" {}", self.unit) };
                format!("{}–{}{unit}", format_number(n.control[0]), format_number(n.control[1]))
            }
            Kind::Number(n) => n.allowed_text(self.unit),
            Kind::Choice { options, .. } => options.iter().map(|o| o.value).collect::<Vec<_>>().join(" | "),
            Kind::Switch { .. } => "1 | 0".to_string(),
        }
    }

    /// Checks a number against the hard limits: the error names the parameter and the range.
    pub fn check(&self, v: f64) -> Result<f64, ConfigError> {
        let Kind::Number(n) = &self.kind else {
            return Err(ConfigError::new(self.name, v, "is not a number parameter"));
        };
        if !v.is_finite() {
            return Err(ConfigError::new(self.name, v, "must be a finite number"));
        }
        if n.admits(v) {
            Ok(v)
        } else {
            Err(ConfigError::new(self.name, v, &n.violation_text(v, self.unit)))
        }
    }

    /// Reads `text` as a value of this parameter. With `control` a number must also lie within
    /// the page control's span (URL values); otherwise within the hard limits (command line).
    pub fn parse(&self, text: &str, control: bool) -> Result<Value, Error> {
        let t = text.trim();
        let parse_error = |expected: String| ParseError { key: self.key.into(), text: text.into(), expected };
        match &self.kind {
            Kind::Number(n) => {
                let what = if n.integer { "a whole number" } else { "a number" };
                // Rust would also read "inf" and "NaN"; a user never means those.
                let v: f64 = t
                    .parse()
                    .ok()
                    .filter(|v: &f64| v.is_finite())
                    .ok_or_else(|| parse_error(format!("{what} ({})", self.allowed(control))))?;
                if control && !n.in_control(v) {
                    return Err(parse_error(self.allowed(true)).into());
                }
                if n.integer && v.fract() != 0.0 {
                    return Err(parse_error(format!("a whole number ({})", self.allowed(control))).into());
                }
                Ok(Value::Number(self.check(v)?))
            }
            Kind::Choice { options, .. } => options
                .iter()
                .find(|o| o.value == t)
                .map(|o| Value::Choice(o.value))
                .ok_or_else(|| parse_error(format!("one of {}", self.allowed(control))).into()),
            Kind::Switch { .. } => match t {
                "1" | "true" | "on" | "yes" => Ok(Value::Switch(true)),
                "0" | "false" | "off" | "no" => Ok(Value::Switch(false)),
                _ => Err(parse_error("1 or 0".into()).into()),
            },
        }
    }
}

mod arm;
mod panels;
mod params;
mod sensing;
mod view;

pub use arm::*;
pub use panels::{PanelKind, Tab};
pub use params::*;
pub use sensing::*;
pub use view::*;

/// The parameter with this key.
pub fn param(key: &str) -> Option<&'static Param> {
    PARAMS.iter().copied().find(|p| p.key == key)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_unique_and_flags_are_kebab_case() {
        for (i, p) in PARAMS.iter().enumerate() {
            assert!(PARAMS[..i].iter().all(|q| q.key != p.key), "{} twice", p.key);
            assert!(p.key.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_'));
            assert!(!p.flag().contains('_'));
        }
        assert_eq!(EPS_RATIO.flag(), "--eps-ratio");
    }

    #[test]
    fn defaults_lie_within_the_limits_and_the_controls_within_the_limits() {
        for p in PARAMS {
            if let Kind::Number(n) = p.kind {
                assert!(n.admits(n.default), "{}", p.key);
                assert!(n.admits(n.control[0]) && n.admits(n.control[1]), "{}", p.key);
                assert!(n.control[0] < n.control[1], "{}", p.key);
            }
            if let Kind::Choice { options, default } = p.kind {
                assert!(options.iter().any(|o| o.value == default), "{}", p.key);
            }
        }
    }

    #[test]
    fn positions_and_values_round_trip_on_log_controls() {
        let n = DELTA.number().unwrap();
        assert_eq!(n.value_at(0.0), 0.002);
        assert_eq!(n.value_at(1.0), 0.25);
        for v in [0.002, 0.01, 0.04, 0.1, 0.25] {
            assert!((n.value_at(n.position(v)) / v - 1.0).abs() < 5e-3, "{v}");
        }
        assert_eq!(n.position(1e-9), 0.0);
        assert_eq!(n.position(100.0), 1.0);
    }

    #[test]
    fn parsing_checks_syntax_and_range() {
        assert_eq!(DELTA.parse("0.04", true).unwrap(), Value::Number(0.04));
        assert!(DELTA.parse("abc", true).is_err());
        assert!(DELTA.parse("inf", false).is_err());
        assert!(DELTA.parse("0.5", true).is_err(), "outside the control");
        assert!(DELTA.parse("0.5", false).is_ok(), "inside the limits");
        let e = DELTA.parse("-1", false).unwrap_err().to_string();
        assert!(e.starts_with("invalid sampling_period (δ) = -1: must be from 1e-5 s to 10 s"), "{e}");
        // The lower bound says why: nothing below it but the δ → 0 limit, at great cost.
        let e = DELTA.check(1e-300).unwrap_err().to_string();
        assert!(e.contains("= 1e-300") && e.contains("δ → 0 limit"), "{e}");
        assert!(DELTA.check(1e-5).is_ok() && DELTA.check(10.0).is_ok());
        assert!(DELTA.check(11.0).unwrap_err().to_string().contains("to 10 s"));
        assert!(K.parse("2.5", false).is_err() && K.parse("12", false).is_ok());
        assert_eq!(PF.parse("lq", false).unwrap(), Value::Choice("lq"));
        let e = PF.parse("maybe", false).unwrap_err().to_string();
        assert!(e.contains("off | paper | lq"), "{e}");
        assert_eq!(REPEAT.parse("1", true).unwrap(), Value::Switch(true));
    }

    #[test]
    fn arrow_keys_step_through_round_values() {
        let d = DELTA.number().unwrap();
        let mut v = 0.01;
        let mut seen = vec![v];
        for _ in 0..6 {
            v = d.step_from(v, 1);
            seen.push(v);
        }
        assert_eq!(seen, [0.01, 0.012, 0.015, 0.02, 0.025, 0.03, 0.04]);
        assert_eq!(d.step_from(0.04, -3), 0.02);
        assert_eq!(d.step_from(0.0347, 1), 0.04, "from between two round values: the next one");
        assert_eq!(d.step_from(0.0347, -1), 0.03);
        assert_eq!(d.step_from(0.24, 1), 0.25, "the span's end");
        assert_eq!(d.step_from(0.25, 1), 0.25);
        assert_eq!(d.step_from(0.002, -1), 0.002);
        assert_eq!(K.number().unwrap().step_from(12.0, -2), 10.0);
        assert_eq!(ALPHA.number().unwrap().step_from(2.0, 1), 2.5);
    }

    #[test]
    fn numbers_print_short() {
        assert_eq!(format_number(0.01), "0.01");
        assert_eq!(format_number(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(format_number(2.0), "2");
        assert_eq!(round_significant(0.034712, 3), 0.0347);
    }
}
