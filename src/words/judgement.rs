//! The judgement of a run in sentences ([`crate::analysis::judgement`] decides it): the headline,
//! ρ's prediction stated plainly, what the simulation observed and whether it agrees, and the
//! analysis line. One wording per fact, for the page's status and the CLI's summary alike.

use serde::Serialize;

use super::numbers::{e_folding, two_decimals};
use super::verdict::{divergence_reason, solver_failure};
use crate::analysis::judgement::{
    Caveat, Detail, DivergenceReading, FloorReading, GrowthReading, Headline, Judgement, Observation,
    OscillationReading, OtherSignWhy, Prediction, RhoLine, SlewReading,
};
use crate::control::metrics::UNSTABLE_GROWTH_RATE;
use crate::plot::format::{grouped, scientific, significant_trimmed};

/// A judgement in words: what the page's status and the CLI's summary both say.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JudgementText {
    /// The verdict's one name: "stable", "unstable", "borderline", "diverged", "bounded
    /// oscillation", "bounded" or "too early to tell".
    pub verdict: &'static str,
    /// The verdict as the headline says it.
    pub headline: &'static str,
    pub detail: String,
    pub observed: String,
    /// True once the simulation has measured a growth rate (or diverged, or settled).
    pub measured: bool,
    pub rho: String,
}

impl JudgementText {
    /// The verdict in one line, as the CLI prints it: "Unstable: ρ = 1.0239 > 1 — …".
    pub fn line(&self) -> String {
        format!("{}: {}", self.headline, self.detail)
    }
}

/// The linear analysis's judgement alone in words (no run): what [`JudgementText`] says of a run
/// where nothing the simulation saw overrides ρ.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VerdictText {
    /// The verdict's one name: "stable", "borderline" or "unstable".
    pub verdict: &'static str,
    /// The verdict as the headline says it.
    pub headline: &'static str,
    pub detail: String,
}

impl VerdictText {
    /// The verdict in one line: "Unstable: ρ = 1.0239 > 1 — …".
    pub fn line(&self) -> String {
        format!("{}: {}", self.headline, self.detail)
    }
}

/// The linear analysis's judgement in words ([`crate::analysis::judgement::judge_analysis`]).
pub fn verdict(h: Headline, d: &Detail) -> VerdictText {
    VerdictText { verdict: h.id(), headline: headline(h), detail: detail(d) }
}

/// The judgement in words.
pub fn judgement(j: &Judgement) -> JudgementText {
    JudgementText {
        verdict: j.headline.id(),
        headline: headline(j.headline),
        detail: detail(&j.detail) + &j.large_error.map_or(String::new(), |l| large_error(&l)),
        observed: observation(&j.observation),
        measured: j.observation.measured(),
        rho: rho_line(&j.rho),
    }
}

/// The verdict as the headline says it: "Unstable", "Stable", "Borderline", "Diverged", "Solver
/// failed", "Bounded oscillation", "Bounded", "Too early to tell".
pub fn headline(h: Headline) -> &'static str {
    match h {
        Headline::Stable => "Stable",
        Headline::Unstable => "Unstable",
        Headline::Borderline => "Borderline",
        Headline::Diverged => "Diverged",
        Headline::SolverFailed => "Solver failed",
        Headline::BoundedOscillation => "Bounded oscillation",
        Headline::Bounded => "Bounded",
        Headline::TooEarly => "Too early to tell",
    }
}

/// What ρ predicts, in one word: "stable", "borderline", "unstable" (the verdict's own words, so
/// a tooltip and the status never judge one ρ differently).
pub fn prediction_word(p: Prediction) -> &'static str {
    Headline::from(p).id()
}

/// The sentence under the headline: "ρ = 1.0239 > 1 — in the long run the errors grow e-fold
/// every 0.42 s".
pub fn detail(d: &Detail) -> String {
    match d {
        // ρ with four decimals, as the analysis line prints it (five where it is nearly 1). ρ is a
        // rate in the long run, not a bound per period: say so.
        Detail::Prediction { rho, rate, prediction, noisy } => match prediction {
            Prediction::Unstable => format!("ρ = {rho:.4} > 1 — in the long run the errors grow {}", e_folding(*rate)),
            // The sensors' error keeps feeding the loop: what shrinks is the error above its floor.
            Prediction::Stable if *noisy => format!(
                "ρ = {rho:.4} < 1 — in the long run the errors shrink {} down to the floor the sensors' error leaves",
                e_folding(*rate)
            ),
            Prediction::Stable => format!("ρ = {rho:.4} < 1 — in the long run the errors shrink {}", e_folding(*rate)),
            Prediction::Borderline => format!(
                "ρ = {rho:.5} ≈ 1, just {} 1 — the errors change too slowly to see ({})",
                if *rho < 1.0 { "below" } else { "above" },
                e_folding(*rate)
            ),
        },
        // Said as what the linear analysis predicts, so that the line under "Bounded oscillation"
        // does not read as a second verdict.
        Detail::Predicted { rho, rate, prediction } => match prediction {
            Prediction::Unstable => {
                format!("the linear analysis predicts growth {} (ρ = {rho:.4} > 1)", e_folding(*rate))
            }
            Prediction::Stable => format!("the linear analysis predicts decay {} (ρ = {rho:.4} < 1)", e_folding(*rate)),
            Prediction::Borderline => format!(
                "the linear analysis predicts errors changing only slowly: {} {} (ρ = {rho:.5} ≈ 1)",
                if *rate > 0.0 { "growth" } else { "decay" },
                e_folding(*rate)
            ),
        },
        Detail::SimulationDecides { rho } => {
            format!("the simulation decides: ρ = {rho:.4} holds with the friction cancelled, not for this run")
        }
        Detail::AnalysisFailed(why) => format!("the linear analysis failed: {why}"),
    }
}

/// What a verdict that is no failure adds when the tracking error is large against the slew:
/// "; but the tracking error reaches 0.66 rad on link 1, 42 % of its 1.57-rad travel — stable,
/// not on course".
pub fn large_error(l: &crate::control::metrics::LargeError) -> String {
    format!(
        "; but the tracking error reaches {} rad on link {}, {:.0} % of its {}-rad travel — not on course",
        significant_trimmed(l.error, 2),
        l.link + 1,
        100.0 * l.error / l.travel,
        significant_trimmed(l.travel, 3)
    )
}

/// Why the simulation may not follow the linear analysis.
#[inline(never)]
pub fn caveat(c: &Caveat) -> String {
    match *c {
        Caveat::Nonlinear => "the analysis is linearized at rest; far from rest the arm is nonlinear".into(),
        // With an error in the readings the errors settle at a floor, not at rest: a rate fitted
        // there is the floor's wandering, which a reader must not take for the loop's growth.
        Caveat::Sensors(sensors) if sensors.angle_variance() > 0.0 => format!(
            "ρ is the noise-free loop's; the run also carries {}, whose error keeps the errors at a floor instead of \
             letting them die out — the linear analysis does not see it, and a rate observed at that floor is the \
             floor's wandering (the status's line on the sensors gives its size)",
            crate::words::sensors::sensors_text(&sensors)
        ),
        Caveat::Sensors(sensors) => format!(
            "ρ is the noise-free loop's; the run also carries {}, which the linear analysis does not see",
            crate::words::sensors::sensors_text(&sensors)
        ),
        Caveat::HeldFriction => "the analysis takes the friction as cancelled; held over δ, the compensation leaves \
                                 the friction's change within each period"
            .into(),
        Caveat::NoFriction { spring, eps1, k1, fc1 } => format!(
            "the analysis takes the friction as cancelled; uncompensated, the motor's Dahl friction is a spring of \
             F_c1/ε1 = {} N m/rad at rest (up to twice that after a reversal) for motions well below ε1 = {} rad — \
             the joint's K1 is {} N m/rad — and a torque of up to F_c1 = {} N m beyond; joint 2's likewise",
            grouped(spring),
            significant_trimmed(eps1, 3),
            grouped(k1),
            significant_trimmed(fc1, 3)
        ),
    }
}

/// "growth" or "decay" for a rate's sign.
fn growth_or_decay(rate: f64) -> &'static str {
    if rate > 0.0 {
        "growth"
    } else {
        "decay"
    }
}

/// What the simulation observed, against ρ.
pub fn observation(o: &Observation) -> String {
    match o {
        // What happened, and that it is the solver's, not the arm's: no reading against ρ.
        Observation::SolverFailed { at, error } => format!(
            "observed: the run stopped at t = {at:.2} s with the errors at {}, {} rad: {}",
            scientific(error[0], 2),
            scientific(error[1], 2),
            solver_failure()
        ),
        Observation::Diverged { at, reason, bound, reading } => {
            let agrees = match reading {
                DivergenceReading::AsPredicted => "as ρ > 1 predicted".to_string(),
                DivergenceReading::SameWayWithoutFriction => {
                    "ρ > 1, computed with the friction cancelled, points the same way (far from rest the friction is a \
                     bounded torque), but it does not describe this run"
                        .to_string()
                }
                DivergenceReading::NotPredictedWithoutFriction(c) => {
                    format!("not what ρ, computed with the friction cancelled, predicts: {}", caveat(c))
                }
                DivergenceReading::NotPredicted(c) => format!("not what ρ predicts: {}", caveat(c)),
            };
            format!("observed: diverged at t = {at:.2} s ({}) — {agrees}", divergence_reason(*reason, *bound))
        }
        Observation::Oscillation { amplitude, period, steady_so_far, reading } => {
            let amplitude = format!("amplitude {}, {} rad", scientific(amplitude[0], 2), scientific(amplitude[1], 2));
            let what = if *steady_so_far {
                format!(
                    "observed: an oscillation of steady size so far — {amplitude}, period {} s",
                    significant_trimmed(*period, 3)
                )
            } else {
                format!(
                    "observed: a bounded oscillation (limit cycle) — {amplitude}, period {} s",
                    significant_trimmed(*period, 3)
                )
            };
            let why = match reading {
                OscillationReading::TooEarlyForGrowth { rate } => format!(
                    "too early to tell: ρ > 1 predicts growth e-fold every {} s, which the slew's dying transient can \
                     hide for a while",
                    significant_trimmed(1.0 / rate.abs(), 2)
                ),
                OscillationReading::Bounded => "ρ > 1 predicts growth, and the nonlinearity bounds it".to_string(),
                OscillationReading::AsBorderline => {
                    "as ρ ≈ 1 predicts: a mode of the loop that hardly grows or decays".to_string()
                }
                OscillationReading::TooEarlyNearRest { rate } => format!(
                    "too early to tell: near rest the loop is linear, and ρ predicts {} e-fold every {} s",
                    growth_or_decay(*rate),
                    significant_trimmed(1.0 / rate.abs(), 2)
                ),
                OscillationReading::Nonlinear(c) => format!("a nonlinear effect ρ cannot show: {}", caveat(c)),
            };
            format!("{what}; {why}")
        }
        Observation::SlewLocked { amplitude, period, across, reading } => {
            let across = across.map_or(String::new(), |g| format!(", {} 1/s from slew to slew", two_decimals(g)));
            let what = format!(
                "observed: the errors come back about as large after every slew (up to {}, {} rad, every {} s{across})",
                scientific(amplitude[0], 2),
                scientific(amplitude[1], 2),
                significant_trimmed(*period, 3)
            );
            let why = match reading {
                SlewReading::SlowerThanTheSlews { rate, period } => format!(
                    "the slowest mode dies out by e only every {} s (ln ρ/δ = {} 1/s), longer than the {} s between \
                     slews",
                    significant_trimmed(1.0 / rate.abs(), 2),
                    two_decimals(*rate),
                    significant_trimmed(*period, 3)
                ),
                SlewReading::TransientDies => "each slew's transient dies out, as ρ < 1 predicts".into(),
                SlewReading::AsBorderline { rate } => format!(
                    "as ρ ≈ 1 predicts: the slowest mode hardly {} ({} e-fold every {} s), and every slew excites it \
                     again",
                    if *rate > 0.0 { "grows" } else { "decays" },
                    if *rate > 0.0 { "growing" } else { "decaying" },
                    significant_trimmed(1.0 / rate.abs(), 2)
                ),
                SlewReading::TooEarlyForGrowth { rate } => format!(
                    "too early to tell: ρ > 1 predicts growth e-fold every {} s from slew to slew",
                    significant_trimmed(1.0 / rate.abs(), 2)
                ),
                SlewReading::Caveat(c) => caveat(c),
            };
            format!("{what}; {why}")
        }
        Observation::AtFloor(reading) => {
            let agrees = match reading {
                FloorReading::NotPredicted(c) => format!(" — not what ρ predicts: {}", caveat(c)),
                FloorReading::AsPredicted => " — nothing left to grow or decay, as ρ < 1 predicts".into(),
                FloorReading::Alone => String::new(),
            };
            format!("observed: the errors have settled at their floor{agrees}")
        }
        Observation::Measuring { repeating, alone } => {
            let when = if *repeating { "between slews" } else { "since the slew" };
            match alone {
                Some(c) => format!(
                    "observed: measuring how the errors move {when}… (only the simulation can judge: {})",
                    caveat(c)
                ),
                None => format!("observed: measuring how the errors move {when}…"),
            }
        }
        Observation::Growth { rate: g, reading } => growth(*g, reading),
    }
}

/// A measured growth rate `g` (1/s) against ln ρ/δ.
fn growth(g: f64, reading: &GrowthReading) -> String {
    let rate = format!("observed growth rate {} 1/s", two_decimals(g));
    match *reading {
        GrowthReading::Alone { error: e, caveat: c } => {
            format!("{rate}, errors now {}, {} rad — {}", scientific(e[0], 2), scientific(e[1], 2), caveat(&c))
        }
        GrowthReading::Unpredicted => rate,
        GrowthReading::Matches { predicted } => format!("{rate} — matches ln ρ/δ = {} 1/s", two_decimals(predicted)),
        // The sign agrees but not the rate: say so, and why that can be. ln ρ/δ is the rate of the
        // slowest (or the growing) mode; until the others have died out their sum can move faster
        // or slower.
        GrowthReading::SameSign { prediction, predicted, faster } => {
            let predicted = two_decimals(predicted);
            match (prediction, faster) {
                (Prediction::Unstable, false) => format!(
                    "{rate} — it grows, as ρ > 1 predicts; ln ρ/δ = {predicted} 1/s is the rate once the growing mode \
                     dominates"
                ),
                (Prediction::Unstable, true) => format!(
                    "{rate} — it grows, as ρ > 1 predicts, faster than ln ρ/δ = {predicted} 1/s for now: that is the \
                     rate in the long run, and the modes' sum can grow faster for a while"
                ),
                (Prediction::Stable, false) => format!(
                    "{rate} — it decays, as ρ < 1 predicts; ln ρ/δ = {predicted} 1/s is the slowest mode's rate, \
                     which takes over later"
                ),
                (Prediction::Stable, true) => format!(
                    "{rate} — it decays, as ρ < 1 predicts, slower than ln ρ/δ = {predicted} 1/s: that is the rate in \
                     the long run, and over a few seconds the modes' sum can decay slower"
                ),
                (Prediction::Borderline, _) => format!("{rate} — about flat, as ln ρ/δ = {predicted} 1/s predicts"),
            }
        }
        GrowthReading::OtherSign { prediction, predicted, why } => {
            let expected = match prediction {
                Prediction::Unstable => "growth",
                Prediction::Stable => "decay",
                // A rate within the borderline band is a slow growth or decay, not none.
                Prediction::Borderline if predicted < 0.0 => "a decay too slow to tell in a run",
                Prediction::Borderline => "a growth too slow to tell in a run",
            };
            let why = match why {
                OtherSignWhy::TooSlow { span, repeating } => format!(
                    "too early to see it: at that rate the errors change by e only every {} s, longer than the {} s \
                     fitted, where the {} transient still shows",
                    significant_trimmed(1.0 / predicted.abs(), 2),
                    significant_trimmed(span, 2),
                    if repeating { "slews'" } else { "slew's" }
                ),
                OtherSignWhy::Caveat(c) => caveat(&c),
                OtherSignWhy::LongRun => {
                    "ln ρ/δ is the rate in the long run; over a few seconds the modes' sum can move otherwise".into()
                }
            };
            format!("{rate} — but ln ρ/δ = {} 1/s predicts {expected}: {why}", two_decimals(predicted))
        }
    }
}

/// Where the analysis holds, in words: "at rest at q2 = 0 rad, friction cancelled".
pub fn scope(q2: f64) -> String {
    let q2 = if q2.abs() < 5e-13 { "0".to_string() } else { significant_trimmed(q2, 3) };
    format!("at rest at q2 = {q2} rad, friction cancelled")
}

/// The analysis line: "linear analysis (at rest at q2 = 0 rad, friction cancelled): ρ = 1.0239 >
/// 1 ⇒ unstable (ln ρ/δ = 2.36 1/s)".
pub fn rho_line(line: &RhoLine) -> String {
    match *line {
        RhoLine::Missing => "linear analysis: ρ = —".into(),
        RhoLine::Analysis { q2, rho, rate, describes, digital } => {
            let growth =
                if rate.is_finite() { format!(" (ln ρ/δ = {} 1/s)", two_decimals(rate)) } else { String::new() };
            let mut scope = scope(q2);
            if digital {
                scope += ", the digital loop without its sensors' error";
            }
            if describes {
                // The same judgement as the headline's, in the same words.
                let (digits, verdict) = match Prediction::of_rate(rate) {
                    Prediction::Stable => (4, "< 1 ⇒ stable".to_string()),
                    Prediction::Unstable => (4, "> 1 ⇒ unstable".to_string()),
                    // Borderline is decided by the rate, not by how near ρ is to 1: say so.
                    Prediction::Borderline => (
                        5,
                        format!(
                            "≈ 1 ⇒ borderline: |ln ρ/δ| < {} 1/s, the errors would change by e only every {} s or more",
                            UNSTABLE_GROWTH_RATE,
                            significant_trimmed(1.0 / UNSTABLE_GROWTH_RATE, 2)
                        ),
                    ),
                };
                format!("linear analysis ({scope}): ρ = {rho:.digits$} {verdict}{growth}")
            } else {
                format!("linear analysis ({scope}, not this run's friction): ρ = {rho:.4}{growth}")
            }
        }
    }
}
