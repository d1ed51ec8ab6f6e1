//! Numbers as people read them: tick labels, readouts and figures all format through here, with
//! a real minus sign (−) and no trailing zeros; and any text as markup carries it ([`escape`]: the
//! SVG figures and the embed's HTML, which sit in layers that cannot share a module above this).

/// Replaces a leading ASCII hyphen (and the one of an exponent) by the minus sign −.
pub fn minus(s: &str) -> String {
    s.replace('-', "−")
}

/// Trims trailing zeros of a decimal (and the point if nothing follows it).
fn trim(s: &str) -> &str {
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// A number alone: up to six significant digits, trailing zeros trimmed, exponent notation
/// below 1e-4 and from 1e6 on ("0.002", "−1.5", "2e−7", "250").
pub fn number(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if !v.is_finite() {
        return if v.is_nan() {
            "—".into()
        } else if v > 0.0 {
            "∞".into()
        } else {
            "−∞".into()
        };
    }
    let e = v.abs().log10().floor() as i32;
    if (-4..=5).contains(&e) {
        let s = format!("{:.*}", (5 - e).clamp(0, 12) as usize, v);
        minus(trim(&s))
    } else {
        let m = v / 10f64.powi(e);
        let m = format!("{m:.3}");
        minus(&format!("{}e{e}", trim(&m)))
    }
}

/// `digits` significant digits without an exponent for ordinary magnitudes (1e-3 ≤ |v| < 1e6),
/// else in exponent notation: "2.64", "29.6", "3.34e−4". "—" for a missing value.
pub fn significant(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    let a = v.abs();
    if a != 0.0 && !(1e-3..1e6).contains(&a) {
        return scientific(v, digits);
    }
    if v == 0.0 {
        return "0".into();
    }
    let e = a.log10().floor() as i32;
    let decimals = (digits as i32 - 1 - e).max(0) as usize;
    minus(&format!("{v:.decimals$}"))
}

/// `digits` significant digits in exponent notation: "3.34e−4". "—" for a missing value.
pub fn scientific(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let s = format!("{:.*e}", digits.saturating_sub(1), v);
    minus(&s.replace("e+", "e"))
}

/// Rounds `parts` to multiples of `step` so that they add up to their sum rounded to `step`
/// (largest-remainder rounding): every part is rounded down, then the parts with the largest
/// remainders go up one step each until the sum is right. Each stays within one step of its
/// value; an equation that prints the parts and their total then adds up as printed.
pub fn rounded_summands<const N: usize>(parts: [f64; N], step: f64) -> [f64; N] {
    let scaled = parts.map(|p| p / step);
    let total = scaled.iter().sum::<f64>().round();
    let mut out = scaled.map(f64::floor);
    let mut missing = (total - out.iter().sum::<f64>()).round().max(0.0) as usize;
    let mut order: [usize; N] = core::array::from_fn(|i| i);
    crate::sort::sort_by_key(&mut order, |&i| -((scaled[i] - out[i]) * 1e6).round() as i64);
    for &i in order.iter() {
        if missing == 0 {
            break;
        }
        out[i] += 1.0;
        missing -= 1;
    }
    out.map(|v| v * step)
}

/// `digits` significant digits, trailing zeros trimmed ("0.0349", "0.1", "2.09").
pub fn significant_trimmed(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return number(v);
    }
    let decimals = (digits as i32 - 1 - v.abs().log10().floor() as i32).max(0) as usize;
    minus(trim(&format!("{v:.decimals$}")))
}

/// A whole number with its thousands set apart by narrow no-break spaces (U+202F), rounded:
/// "48 200", "1 153", "−5".
pub fn grouped(v: f64) -> String {
    if !v.is_finite() {
        return number(v);
    }
    let digits = format!("{:.0}", v.abs().round());
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push('\u{202f}');
        }
        out.push(c);
    }
    if v.round() < 0.0 {
        out.insert(0, '−');
    }
    out
}

/// Labels for a set of ticks of a linear axis: fixed decimals enough to tell neighbours apart,
/// or the fewest exponent digits that name each tick exactly when the values are tiny or huge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TickFormat {
    exponent: bool,
    decimals: usize,
    /// A tick this close to zero reads "0".
    zero: f64,
}

impl TickFormat {
    /// The format for these ticks (evenly spaced, as [`super::ticks::Ticks`] makes them).
    pub fn for_ticks(ticks: &[f64]) -> TickFormat {
        let max_abs = ticks.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut step = ticks.windows(2).map(|w| (w[1] - w[0]).abs()).fold(f64::INFINITY, f64::min);
        if !step.is_finite() || step == 0.0 {
            step = if max_abs > 0.0 { max_abs } else { 1.0 };
        }
        let exponent = max_abs != 0.0 && !(1e-2..1e5).contains(&max_abs);
        let decimals = (-(step.log10() + 1e-9).floor()).clamp(0.0, 6.0) as usize;
        TickFormat { exponent, decimals, zero: step * 1e-6 }
    }

    /// One tick's label.
    pub fn format(&self, v: f64) -> String {
        if v.abs() < self.zero {
            return "0".into();
        }
        if self.exponent {
            // The fewest mantissa digits that still name the tick: 5e−4, 1e−3, 2.5e−4.
            for d in 0..=6 {
                let text = format!("{v:.d$e}");
                if text.parse::<f64>().is_ok_and(|back| (back - v).abs() <= self.zero) {
                    return minus(&text);
                }
            }
            return minus(&format!("{v:.6e}"));
        }
        let s = format!("{v:.*}", self.decimals);
        if s.parse::<f64>() == Ok(0.0) {
            "0".into()
        } else {
            minus(&s)
        }
    }
}

/// A log-axis label: three significant digits, no trailing zeros ("0.002", "5"); exponent
/// notation for tiny or huge values ("1e−6", "5e−4").
pub fn log_tick(v: f64) -> String {
    if v != 0.0 && !(1e-3..1e5).contains(&v.abs()) {
        for d in 0..=2 {
            let text = format!("{v:.d$e}");
            if text.parse::<f64>().is_ok_and(|back| (back / v - 1.0).abs() < 1e-9) {
                return minus(&text);
            }
        }
        return scientific(v, 3);
    }
    significant_trimmed(v, 3)
}

/// Text escaped for XML and HTML element content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            // Characters that XML 1.0 does not allow at all.
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_is_escaped_and_control_characters_dropped() {
        assert_eq!(escape("a<b> & \"c\" 'd'\u{1}"), "a&lt;b&gt; &amp; &quot;c&quot; &#39;d&#39; ");
        assert_eq!(escape("δ = 0.01\n"), "δ = 0.01\n");
    }

    #[test]
    fn numbers_read_cleanly() {
        assert_eq!(number(0.002), "0.002");
        assert_eq!(number(-1.5), "−1.5");
        assert_eq!(number(2e-7), "2e−7");
        assert_eq!(number(250.0), "250");
        assert_eq!(significant(2.639, 3), "2.64");
        assert_eq!(significant(-29.58, 4), "−29.58");
        assert_eq!(significant(3.34e-4, 3), "3.34e−4");
        assert_eq!(scientific(0.000334, 3), "3.34e−4");
        assert_eq!(significant_trimmed(0.034912, 3), "0.0349");
        assert_eq!(significant_trimmed(0.1, 3), "0.1");
        assert_eq!(log_tick(0.002), "0.002");
        assert_eq!(log_tick(5.0), "5");
        assert_eq!(log_tick(1e-9), "1e−9");
        assert_eq!(log_tick(5e-4), "5e−4");
        assert_eq!(log_tick(0.001), "0.001");
    }

    #[test]
    fn tick_labels_tell_neighbours_apart() {
        let f = TickFormat::for_ticks(&[-0.2, 0.0, 0.2, 0.4]);
        assert_eq!(f.format(0.4), "0.4");
        assert_eq!(f.format(-0.2), "−0.2");
        assert_eq!(f.format(1e-17), "0");
        let f = TickFormat::for_ticks(&[0.0, 0.5, 1.0, 1.5]);
        assert_eq!(f.format(1.0), "1.0");
        let f = TickFormat::for_ticks(&[-5e-4, 0.0, 5e-4]);
        assert_eq!(f.format(5e-4), "5e−4");
        let f = TickFormat::for_ticks(&[0.0, 2.5e-4, 5e-4]);
        assert_eq!(f.format(2.5e-4), "2.5e−4");
        let f = TickFormat::for_ticks(&[10.0, 20.0, 30.0]);
        assert_eq!(f.format(20.0), "20");
    }
}
