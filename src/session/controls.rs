//! The controls' values as the page shows them: the value, the slider position, the text with
//! its unit.

use serde::Serialize;

use super::Session;
use crate::schema::{self, Kind, Scope, Value};

impl Session {
    /// The controls' current values, for the page to show.
    pub fn controls(&self) -> Vec<ControlValue> {
        let mut values: Vec<ControlValue> = schema::PARAMS
            .iter()
            .filter(|p| matches!(p.scope, Scope::Run | Scope::Page | Scope::Compare))
            .filter_map(|p| {
                let v = self.settings.get(p.key)?;
                let (position, text) = match (&p.kind, v) {
                    (Kind::Number(n), Value::Number(x)) => (Some(n.position(x)), display(p, x)),
                    _ => (None, v.text()),
                };
                Some(ControlValue { key: p.key, value: v.text(), position, text, shown: self.settings.matters(p.key) })
            })
            .collect();
        // The embed's strip (`strip=`, a list the session reads itself): which controls it shows.
        let strip = self.settings.view.strip.text();
        values.push(ControlValue { key: "strip", value: strip.clone(), position: None, text: strip, shown: true });
        values
    }
}

/// A control's value as the page shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ControlValue {
    pub key: &'static str,
    /// The value as the state string writes it.
    pub value: String,
    /// The slider position in [0, 1] (numbers only).
    pub position: Option<f64>,
    /// The value with its unit, as shown beside the control ("0.0100 s", "2.00 1/s", "1.0×").
    pub text: String,
    /// False while the setting does nothing (the twist feedback's gains under another feedback):
    /// the page hides its control.
    pub shown: bool,
}

/// A number with the precision of its control and its unit ("0.0100 s", "2.00 1/s", "1.0×", "12").
pub fn display(p: &schema::Param, x: f64) -> String {
    if let Some(off) = schema::off_text(p.key).filter(|_| x == 0.0) {
        return off.to_string();
    }
    let spec = p.number();
    let v = if spec.is_some_and(|n| n.integer) {
        format!("{x}")
    } else if p.key == schema::SPEED.key && x >= 1.0 {
        format!("{x:.1}")
    } else {
        precision(x, spec.map_or(3, |n| n.digits as usize))
    };
    match p.unit {
        "" => v,
        "×" => format!("{v}×"),
        u => format!("{v} {u}"),
    }
}

/// `digits` significant digits, keeping trailing zeros ("0.0100", "2.00").
fn precision(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let e = x.abs().log10().floor() as i32;
    let decimals = (digits as i32 - 1 - e).max(0) as usize;
    format!("{x:.decimals$}")
}
