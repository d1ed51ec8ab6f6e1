//! ρ read out in a tooltip, where the pointer picks a δ (ρ(δ)) or a (δ, α) (a stability map): ρ
//! per period with the verdict's own word for it, and the rate ln ρ/δ per second.

use crate::analysis::judgement::Prediction;
use crate::plot::color::Measure;
use crate::plot::format;
use crate::view::panel_info::TipLine;
use crate::words::judgement::prediction_word;

/// ρ and the rate ln ρ/δ at sampling period `delta` (s), whatever the view colours by: the
/// verdict is read in ρ, the rate compares across δ.
pub fn stability_lines(rho: f64, delta: f64, lines: &mut Vec<TipLine>) {
    if rho.is_finite() {
        // The verdict's own judgement (a rate within the borderline band is borderline here too).
        let verdict = prediction_word(Prediction::of_rate(Measure::Rate.value(rho, delta)));
        lines.push(TipLine::toned(format!("ρ = {rho:.3} per period: {verdict}"), verdict == "stable"));
        let rate = format::significant(Measure::Rate.value(rho, delta), 3);
        lines.push(TipLine::plain(format!("ln ρ/δ = {rate} 1/s (per second)")));
    } else {
        lines.push(TipLine::plain("ρ not computed yet"));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tooltip says the verdict's word for the same ρ and δ (trial 4: δ = 0.114 s, ρ = 0.99498
    /// was "stable" here and "borderline" in the verdict).
    #[test]
    fn a_tooltip_judges_as_the_verdict_does() {
        for (rho, delta, word) in [
            (0.99498, 0.114, "borderline"),
            (0.9977, 0.0355, "stable"),
            (1.0239, 0.01, "unstable"),
            (1.0004, 0.01, "borderline"),
        ] {
            let mut lines = Vec::new();
            stability_lines(rho, delta, &mut lines);
            assert!(lines[0].text.ends_with(word), "{rho} at {delta}: {}", lines[0].text);
            assert_eq!(lines[0].tone == "good", word == "stable");
        }
    }
}
