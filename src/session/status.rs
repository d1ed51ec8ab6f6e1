//! What the page says about a run, in words. The headline is the linear analysis — ρ of the
//! settings on screen, known from the first frame — stated plainly; the simulation's own
//! observation confirms it (or says why it cannot) as soon as it can. Written here so that every
//! number shown for one setting comes from one place and cannot contradict another.

use serde::Serialize;

use super::maps::feedback_short;
use super::run::Run;
use crate::control::config::{FrictionCompensation, SimulationConfig};
use crate::control::metrics::{growth_text, DivergenceReason, Metrics, Verdict, GROWTH_FIT_SPAN, UNSTABLE_GROWTH_RATE};

/// Errors above this (rad) are far enough from rest for the arm's nonlinearity (Coriolis terms,
/// the mass matrix's change with q2) to be a reason the simulation departs from ρ; below it the
/// linearization holds and another reason is given.
const NONLINEAR_ERROR: f64 = 0.05;
use crate::plot::format::{grouped, minus, sci, sig, sig_trim};
use crate::schema;

/// The readouts under the canvas.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Readouts {
    pub time: String,
    pub error: String,
    pub max_slew: String,
    pub max_after: String,
    pub torque: String,
    /// The observed growth rate of the errors' free motion.
    pub growth: String,
    /// The δ → 0 pair A4 with the run's preliminary feedback.
    pub a4: String,
}

/// What the linear analysis says about a loop: ρ against 1, with a borderline band where the
/// errors would change too slowly to tell (|ln ρ|/δ below the rate the simulation can resolve).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Prediction {
    Stable,
    Borderline,
    Unstable,
}

impl Prediction {
    /// The prediction for a growth rate ln ρ/δ (1/s).
    pub fn of_rate(rate: f64) -> Prediction {
        if rate > UNSTABLE_GROWTH_RATE {
            Prediction::Unstable
        } else if rate < -UNSTABLE_GROWTH_RATE {
            Prediction::Stable
        } else {
            Prediction::Borderline
        }
    }
}

/// One run's status, in words and flags.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RunStatus {
    /// "A" or "B".
    pub run: &'static str,
    /// "stable", "unstable", "borderline" (from ρ), or what the run has shown beyond it:
    /// "diverged", "bounded oscillation".
    pub verdict: &'static str,
    /// The verdict as the headline says it: "Unstable", "Stable", "Borderline", "Diverged",
    /// "Bounded oscillation".
    pub headline: &'static str,
    /// The prediction in a sentence: "ρ = 1.0239 > 1 — in the long run the errors grow e-fold every
    /// 0.42 s".
    pub detail: String,
    /// What the simulation has observed, and whether it agrees.
    pub observed: String,
    /// True once the simulation has measured a growth rate (or diverged).
    pub measured: bool,
    /// The run has diverged and does not advance until a reset or a change.
    pub finished: bool,
    /// "linear analysis: ρ = 1.0239 ≥ 1 ⇒ unstable (ln ρ/δ = 2.36 1/s)".
    pub rho: String,
    /// The spectral radius and ln ρ/δ (null if the analysis failed).
    pub spectral_radius: Option<f64>,
    pub growth_rate: Option<f64>,
    /// What a screen reader hears when the verdict changes.
    pub announce: String,
    pub readouts: Readouts,
    /// "no K_pr, δ = 0.01 s, α = 2 1/s": which settings this run has.
    pub settings: String,
}

/// A rate with two decimals and a real minus sign, never "−0.00".
fn two(v: f64) -> String {
    if v.abs() < 0.005 {
        "0.00".into()
    } else {
        minus(&format!("{v:.2}"))
    }
}

/// "e-fold every 0.42 s" for a rate (1/s).
fn e_folding(rate: f64) -> String {
    format!("e-fold every {} s", sig_trim(1.0 / rate.abs(), 2))
}

/// The prediction's sentence.
fn prediction_text(rho: f64, rate: f64) -> (Prediction, String) {
    let p = Prediction::of_rate(rate);
    let text = match p {
        // ρ with four decimals, as the analysis line prints it (five where it is nearly 1).
        // ρ is a rate in the long run, not a bound per period: say so.
        Prediction::Unstable => format!("ρ = {rho:.4} > 1 — in the long run the errors grow {}", e_folding(rate)),
        Prediction::Stable => format!("ρ = {rho:.4} < 1 — in the long run the errors shrink {}", e_folding(rate)),
        Prediction::Borderline => format!(
            "ρ = {rho:.5} ≈ 1, just {} 1 — the errors change too slowly to see ({})",
            if rho < 1.0 { "below" } else { "above" },
            e_folding(rate)
        ),
    };
    (p, text)
}

/// The prediction's sentence under a headline the simulation has overridden (a limit cycle, or
/// a divergence ρ did not predict): said as what the linear analysis predicts, so that the line
/// under "Bounded oscillation" does not read as a second verdict.
fn predicted_text(rho: f64, rate: f64) -> String {
    match Prediction::of_rate(rate) {
        Prediction::Unstable => format!("the linear analysis predicts growth {} (ρ = {rho:.4} > 1)", e_folding(rate)),
        Prediction::Stable => format!("the linear analysis predicts decay {} (ρ = {rho:.4} < 1)", e_folding(rate)),
        Prediction::Borderline => format!(
            "the linear analysis predicts errors changing only slowly: {} {} (ρ = {rho:.5} ≈ 1)",
            if rate > 0.0 { "growth" } else { "decay" },
            e_folding(rate)
        ),
    }
}

/// Why the simulation may not follow the linear analysis.
fn caveat(config: &SimulationConfig) -> String {
    let p = config.plant;
    match config.friction_compensation {
        FrictionCompensation::Continuous => {
            "the analysis is linearized at rest; far from rest the arm is nonlinear".into()
        }
        FrictionCompensation::Held => "the analysis takes the friction as cancelled; held over δ, the \
                                        compensation leaves the friction's change within each period"
            .into(),
        FrictionCompensation::Off => format!(
            "the analysis takes the friction as cancelled; uncompensated, the motor's Dahl friction is a spring of \
             F_c1/ε1 = {} N m/rad at rest (up to twice that after a reversal) for motions well below ε1 = {} rad — \
             the joint's K1 is {} N m/rad — and a torque of up to F_c1 = {} N m beyond; joint 2's likewise",
            grouped(schema::round_significant(p.fc1 / p.eps1, 3)),
            sig_trim(p.eps1, 3),
            grouped(p.k1),
            sig_trim(p.fc1, 3)
        ),
    }
}

/// Whether a limit cycle the simulation sees can stand against ρ: always where ρ does not describe
/// the run; where it does, only far from rest — near rest the loop is linear, and a steady
/// envelope there is a transient's, too early to judge.
fn credible_cycle(m: &Metrics, applies: bool) -> bool {
    match m.verdict {
        Verdict::BoundedOscillation { amplitude, .. } => !applies || amplitude[0].max(amplitude[1]) >= NONLINEAR_ERROR,
        _ => false,
    }
}

/// Where the analysis holds, in words: "at rest at q2 = 0 rad, friction cancelled".
fn scope_text(report: &crate::analysis::StabilityReport) -> String {
    let q2 = report.rest[1];
    let q2 = if q2.abs() < 5e-13 { "0".to_string() } else { sig_trim(q2, 3) };
    format!("at rest at q2 = {q2} rad, friction cancelled")
}

/// The observation, compared with the prediction.
fn observation(
    m: &Metrics,
    prediction: Option<(Prediction, f64)>,
    config: &SimulationConfig,
    error: [f64; 2],
) -> (String, bool) {
    // Where ρ does not describe the run, it is never cited as the cause of what is seen.
    let raw_prediction = prediction;
    let applies = crate::analysis::describes(config);
    let prediction = prediction.filter(|_| applies);
    let repeating = config.reference.repeat_hold.is_some();
    let alone = !applies;
    if let Verdict::Diverged { at, reason } = m.verdict {
        let why = match reason {
            DivergenceReason::ErrorBound => "an error passed π rad",
            DivergenceReason::NonFinite => "the state became non-finite",
            DivergenceReason::NewtonFailure => "the predictor's Newton iteration failed",
        };
        let agrees = match prediction {
            Some((Prediction::Unstable, _)) => "as ρ > 1 predicted".to_string(),
            // ρ with the friction cancelled, where it is not: it may still point the same way
            // (far from rest the friction only saturates), but it is not the verdict.
            _ if alone => match raw_prediction {
                Some((Prediction::Unstable, _)) => {
                    "ρ > 1, computed with the friction cancelled, points the same way (far from rest the friction \
                     is a bounded torque), but it does not describe this run"
                        .to_string()
                }
                _ => format!("not what ρ, computed with the friction cancelled, predicts: {}", caveat(config)),
            },
            _ => format!("not what ρ predicts: {}", caveat(config)),
        };
        return (format!("observed: diverged at t = {at:.2} s ({why}) — {agrees}"), true);
    }
    if let Verdict::BoundedOscillation { amplitude, period } = m.verdict {
        let amplitude_max = amplitude[0].max(amplitude[1]);
        let amplitude = format!("amplitude {}, {} rad", sci(amplitude[0], 2), sci(amplitude[1], 2));
        // Near rest the arm is linear: a flat envelope there is not the nonlinearity at work.
        let near_rest = amplitude_max < NONLINEAR_ERROR;
        let what = if near_rest && prediction.is_some() {
            format!("observed: an oscillation of steady size so far — {amplitude}, period {} s", sig_trim(period, 3))
        } else {
            format!("observed: a bounded oscillation (limit cycle) — {amplitude}, period {} s", sig_trim(period, 3))
        };
        let why = match prediction {
            Some((Prediction::Unstable, rate)) if near_rest => format!(
                "too early to tell: ρ > 1 predicts growth e-fold every {} s, which the slew's dying transient can hide \
                 for a while",
                sig_trim(1.0 / rate.abs(), 2)
            ),
            Some((Prediction::Unstable, _)) => "ρ > 1 predicts growth, and the nonlinearity bounds it".to_string(),
            Some((Prediction::Borderline, _)) if near_rest => {
                "as ρ ≈ 1 predicts: a mode of the loop that hardly grows or decays".to_string()
            }
            Some((_, rate)) if near_rest => format!(
                "too early to tell: near rest the loop is linear, and ρ predicts {} e-fold every {} s",
                if rate > 0.0 { "growth" } else { "decay" },
                sig_trim(1.0 / rate.abs(), 2)
            ),
            _ => format!("a nonlinear effect ρ cannot show: {}", caveat(config)),
        };
        return (format!("{what}; {why}"), true);
    }
    if let Verdict::SlewLocked { amplitude, period } = m.verdict {
        let across = m.growth_rate.map_or(String::new(), |g| format!(", {} 1/s from slew to slew", two(g)));
        let what = format!(
            "observed: the errors come back about as large after every slew (up to {}, {} rad, every {} s{across})",
            sci(amplitude[0], 2),
            sci(amplitude[1], 2),
            sig_trim(period, 3)
        );
        let why = match prediction {
            Some((Prediction::Stable, rate)) if 1.0 / rate.abs() > period => format!(
                "the slowest mode dies out by e only every {} s (ln ρ/δ = {} 1/s), longer than the {} s between slews",
                sig_trim(1.0 / rate.abs(), 2),
                two(rate),
                sig_trim(period, 3)
            ),
            Some((Prediction::Stable, _)) => "each slew's transient dies out, as ρ < 1 predicts".into(),
            Some((Prediction::Borderline, rate)) => format!(
                "as ρ ≈ 1 predicts: the slowest mode hardly {} ({} e-fold every {} s), and every slew excites it again",
                if rate > 0.0 { "grows" } else { "decays" },
                if rate > 0.0 { "growing" } else { "decaying" },
                sig_trim(1.0 / rate.abs(), 2)
            ),
            Some((Prediction::Unstable, rate)) => format!(
                "too early to tell: ρ > 1 predicts growth e-fold every {} s from slew to slew",
                sig_trim(1.0 / rate.abs(), 2)
            ),
            None => caveat(config),
        };
        return (format!("{what}; {why}"), true);
    }
    let Some(g) = m.growth_rate else {
        if m.errors_at_floor {
            let agrees = match prediction {
                Some((Prediction::Unstable, _)) => format!(" — not what ρ predicts: {}", caveat(config)),
                Some(_) => " — nothing left to grow or decay, as ρ < 1 predicts".into(),
                None => String::new(),
            };
            return (format!("observed: the errors have settled at their floor{agrees}"), true);
        }
        let when = if repeating { "between slews" } else { "since the slew" };
        let text = if alone {
            format!(
                "observed: measuring how the errors move {when}… (only the simulation can judge: {})",
                caveat(config)
            )
        } else {
            format!("observed: measuring how the errors move {when}…")
        };
        return (text, false);
    };
    let rate = format!("observed growth rate {} 1/s", two(g));
    if alone {
        let e = error;
        let now = format!(", errors now {}, {} rad", sci(e[0], 2), sci(e[1], 2));
        return (format!("{rate}{now} — {}", caveat(config)), true);
    }
    let Some((p, predicted)) = prediction else { return (rate, true) };
    let seen = Prediction::of_rate(g);
    let text = if seen == p {
        let close = (g - predicted).abs() <= 0.25 * predicted.abs().max(0.2);
        let slower = g > predicted;
        let predicted = two(predicted);
        match (close, p, slower) {
            (true, _, _) => format!("{rate} — matches ln ρ/δ = {predicted} 1/s"),
            // The sign agrees but not the rate: say so, and why that can be. ln ρ/δ is the rate of
            // the slowest (or the growing) mode; until the others have died out their sum can
            // move faster or slower.
            (false, Prediction::Unstable, false) => format!(
                "{rate} — it grows, as ρ > 1 predicts; ln ρ/δ = {predicted} 1/s is the rate once the growing mode dominates"
            ),
            (false, Prediction::Unstable, true) => format!(
                "{rate} — it grows, as ρ > 1 predicts, faster than ln ρ/δ = {predicted} 1/s for now: that is the rate in \
                 the long run, and the modes' sum can grow faster for a while"
            ),
            (false, Prediction::Stable, false) => format!(
                "{rate} — it decays, as ρ < 1 predicts; ln ρ/δ = {predicted} 1/s is the slowest mode's rate, which takes over later"
            ),
            (false, Prediction::Stable, true) => format!(
                "{rate} — it decays, as ρ < 1 predicts, slower than ln ρ/δ = {predicted} 1/s: that is the rate in the \
                 long run, and over a few seconds the modes' sum can decay slower"
            ),
            (false, Prediction::Borderline, _) => format!("{rate} — about flat, as ln ρ/δ = {predicted} 1/s predicts"),
        }
    } else {
        let expected = match p {
            Prediction::Unstable => "growth",
            Prediction::Stable => "decay",
            // A rate within the borderline band is a slow growth or decay, not none.
            Prediction::Borderline if predicted < 0.0 => "a decay too slow to tell in a run",
            Prediction::Borderline => "a growth too slow to tell in a run",
        };
        let e = error;
        let why = if predicted.abs() * GROWTH_FIT_SPAN < 1.0 {
            // Too slow to show in the seconds fitted: never blame the nonlinearity for that.
            format!(
                "too early to see it: at that rate the errors change by e only every {} s, longer than the {} s fitted, \
                 where the {} transient still shows",
                sig_trim(1.0 / predicted.abs(), 2),
                sig_trim(GROWTH_FIT_SPAN, 2),
                if repeating { "slews'" } else { "slew's" }
            )
        } else if e[0].abs().max(e[1].abs()) > NONLINEAR_ERROR {
            caveat(config)
        } else {
            "ln ρ/δ is the rate in the long run; over a few seconds the modes' sum can move otherwise".into()
        };
        format!("{rate} — but ln ρ/δ = {} 1/s predicts {expected}: {why}", two(predicted))
    };
    (text, true)
}

/// What a run's status says about it, decided once — the verdict word and headline, the
/// prediction's sentence, the observation and the analysis line — from the simulation's
/// metrics, the linear analysis of its settings (or why it failed), its configuration and the
/// errors now. The page's status and the CLI's summary both say this, so they cannot disagree.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Judgement {
    /// "stable", "unstable", "borderline", "diverged", "bounded oscillation" or "too early to tell".
    pub verdict: &'static str,
    /// The verdict as the headline says it.
    pub headline: &'static str,
    pub detail: String,
    pub observed: String,
    pub measured: bool,
    pub rho: String,
}

/// The judgement of a run (see [`Judgement`]).
pub fn judge(
    m: &Metrics,
    report: Option<&crate::analysis::StabilityReport>,
    analysis_error: Option<&str>,
    config: &SimulationConfig,
    error: [f64; 2],
) -> Judgement {
    let predicted = report.map(|r| (r.spectral_radius, r.growth_rate)).filter(|(r, g)| r.is_finite() && g.is_finite());
    let (prediction, detail) = match predicted {
        Some((rho, rate)) => {
            let (p, text) = prediction_text(rho, rate);
            (Some((p, rate)), text)
        }
        None => (None, format!("the linear analysis failed: {}", analysis_error.unwrap_or("no report"))),
    };
    let (observed, measured) = observation(m, prediction, config, error);
    let applies = crate::analysis::describes(config);
    let near_rest = error[0].abs().max(error[1].abs()) < NONLINEAR_ERROR;
    // A rate that changes the errors by e or more over the span fitted: growth (sign 1) or decay
    // (−1) the simulation has clearly seen.
    let clear = |sign: f64| m.growth_rate.is_some_and(|g| sign * g * GROWTH_FIT_SPAN >= 1.0);
    // ρ decides the headline only where it describes the run (the friction cancelled); what the
    // simulation has seen beyond the linear analysis overrides it: a divergence, or a limit
    // cycle (named as the CLI and the JSON name it).
    let judged = prediction.filter(|_| applies).map(|p| p.0);
    let (verdict, headline) = match (m.verdict, judged) {
        (Verdict::Diverged { .. }, _) => ("diverged", "Diverged"),
        (v @ Verdict::BoundedOscillation { .. }, _) if credible_cycle(m, applies) => (v.label(), "Bounded oscillation"),
        (_, Some(Prediction::Unstable)) => ("unstable", "Unstable"),
        (_, Some(Prediction::Stable)) => ("stable", "Stable"),
        (_, Some(Prediction::Borderline)) => ("borderline", "Borderline"),
        // Without an analysis that holds, only the simulation can say, once it has seen enough: a
        // growth that has carried the errors far from rest, or a decay that has brought them near
        // it. Near rest the friction's hunting can grow for a while and then settle into a cycle.
        (_, None) if m.errors_at_floor => ("stable", "Stable"),
        (Verdict::Unstable { .. }, None) if !near_rest && clear(1.0) => ("unstable", "Unstable"),
        // Near rest the friction can hold the errors, let them creep, or hunt: bounded so far,
        // and said no more firmly than that.
        (_, None) if measured && near_rest => ("bounded", "Bounded"),
        (_, None) => ("too early to tell", "Too early to tell"),
    };
    // Under a headline the simulation decided against ρ, ρ's sentence is the prediction.
    let overridden = match m.verdict {
        Verdict::BoundedOscillation { .. } => credible_cycle(m, applies),
        Verdict::Diverged { .. } => !matches!(judged, Some(Prediction::Unstable)),
        _ => false,
    };
    let detail = match predicted {
        Some((rho, _)) if !applies => {
            format!("the simulation decides: ρ = {rho:.4} holds with the friction cancelled, not for this run")
        }
        Some((rho, rate)) if overridden => predicted_text(rho, rate),
        _ => detail,
    };
    let rho_line = match report {
        None => "linear analysis: ρ = —".into(),
        Some(r) => {
            let growth = if r.growth_rate.is_finite() {
                format!(" (ln ρ/δ = {} 1/s)", two(r.growth_rate))
            } else {
                String::new()
            };
            let scope = scope_text(r);
            if applies {
                // The same judgement as the headline's, in the same words.
                let (digits, verdict) = match Prediction::of_rate(r.growth_rate) {
                    Prediction::Stable => (4, "< 1 ⇒ stable".to_string()),
                    Prediction::Unstable => (4, "> 1 ⇒ unstable".to_string()),
                    // Borderline is decided by the rate, not by how near ρ is to 1: say so.
                    Prediction::Borderline => (
                        5,
                        format!(
                            "≈ 1 ⇒ borderline: |ln ρ/δ| < {} 1/s, the errors would change by e only every {} s or more",
                            UNSTABLE_GROWTH_RATE,
                            sig_trim(1.0 / UNSTABLE_GROWTH_RATE, 2)
                        ),
                    ),
                };
                format!("linear analysis ({scope}): ρ = {:.digits$} {verdict}{growth}", r.spectral_radius)
            } else {
                format!("linear analysis ({scope}, not this run's friction): ρ = {:.4}{growth}", r.spectral_radius)
            }
        }
    };
    Judgement { verdict, headline, detail, observed, measured, rho: rho_line }
}

/// The status of `run`, named `name`.
pub fn run_status(name: &'static str, run: &Run) -> RunStatus {
    let sim = run.closed_loop();
    let m = sim.metrics();
    let s = sim.snapshot();
    let report = run.analysis().report();
    let Judgement { verdict, headline, detail, observed, measured, rho } =
        judge(&m, report, run.analysis().error(), sim.config(), s.error);
    let pair = |v: [f64; 2], unit: &str| format!("{}, {} {unit}", sci(v[0], 3), sci(v[1], 3));
    let readouts = Readouts {
        time: format!("{:.2} s", m.time),
        error: error_pair(s.error),
        max_slew: pair(m.max_error_slew, "rad"),
        // Nothing to show until the reference has rested once.
        max_after: if m.time <= sim.config().reference.slew_time {
            "— (the slew is under way)".into()
        } else {
            pair(m.max_error_after, "rad")
        },
        torque: format!("{}, {} N m", sig(m.max_torque[0], 3), sig(m.max_torque[1], 3)),
        growth: match (m.verdict, m.growth_rate) {
            // The last fit before a divergence is no rate of the run's.
            (Verdict::Diverged { .. }, _) => "— (diverged)".into(),
            (_, None) if !m.errors_at_floor => "measuring…".into(),
            (_, g) => minus(&growth_text(g, m.errors_at_floor)),
        },
        a4: report.map_or("—".into(), |r| {
            let [re, im] = r.limit_pair[0];
            format!("{} ± {}j 1/s", sig(re, 3), sig(im.abs(), 4))
        }),
    };
    RunStatus {
        run: name,
        verdict,
        headline,
        announce: format!("Run {name}: {headline}. {detail}."),
        detail,
        observed,
        measured,
        finished: sim.is_finished(),
        rho,
        spectral_radius: report.map(|r| r.spectral_radius),
        growth_rate: report.map(|r| r.growth_rate),
        readouts,
        settings: describe(run),
    }
}

/// "1.23e−3, −4.56e−4 rad".
pub(super) fn error_pair(e: [f64; 2]) -> String {
    // Exponents where errors are small (comparable at a glance), plain numbers near a radian.
    let f = |v: f64| if v.abs() >= 0.1 { sig(v, 3) } else { sci(v, 3) };
    format!("{}, {} rad", f(e[0]), f(e[1]))
}

/// "no K_pr, δ = 0.01 s, α = 2 1/s", and what departs from the paper's model ("…, friction
/// compensation held").
pub fn describe(run: &Run) -> String {
    let s = run.settings();
    let alpha = if s.alpha[0] == s.alpha[1] {
        format!("α = {}", sig_trim(s.alpha[0], 3))
    } else {
        format!("α = {}, {}", sig_trim(s.alpha[0], 3), sig_trim(s.alpha[1], 3))
    };
    let mut text = format!("{}, δ = {} s, {alpha} 1/s", feedback_short(s.pf), sig_trim(s.delta, 3));
    // What departs from the paper's model, so "your settings" never hide it.
    let paper = super::settings::RunSettings::default();
    if s.friction != paper.friction {
        text += &format!(", friction compensation {}", s.friction.name());
    }
    if s.inner != paper.inner {
        text += &format!(", inner loop {}", s.inner.name());
    }
    if s.k != paper.k || s.eps_ratio != paper.eps_ratio {
        text += &format!(", k = {}, m = {}", s.k, sig_trim(s.eps_ratio, 3));
    }
    if s.plant != paper.plant {
        text += &format!(", arm: {}", crate::schema::arm_text(&s.plant.values()));
    }
    if s.repeat {
        text += ", slew repeating";
    }
    text
}

impl super::Session {
    /// The figure in words, for screen readers (the canvas' description): what it shows, at
    /// which instant, the verdict and the newest numbers of each run.
    pub fn figure_text(&self) -> String {
        let v = self.drawn_view();
        let hidden = self.answers_hidden();
        let mut shown = vec!["the arm (top view)", "the tracking errors e1, e2 over time"];
        if v.torque {
            shown.push("the torques");
        }
        if v.poles {
            shown.push(if v.z_plane {
                "the loop's eigenvalues λ with the unit circle"
            } else {
                "the pole plot s = ln λ / δ"
            });
        }
        let rate = v.measure == crate::plot::color::Measure::Rate;
        if v.rho {
            shown.push(if rate { "the rate ln ρ/δ along δ" } else { "ρ along δ" });
        }
        if v.map {
            shown.push(if rate { "the stability maps coloured by ln ρ/δ" } else { "the stability maps ρ(δ, α)" });
        }
        let mut text = format!("The figure shows {}.", shown.join(", "));
        for (i, run) in self.runs().enumerate() {
            let name = if i == 0 { "A" } else { "B" };
            let mut s = run_status(name, run);
            if hidden {
                super::student::hide_answers(&mut s);
            }
            let at = self.shown_snapshot(i).map_or(f64::NAN, |snap| snap.time);
            let when = if self.viewing().is_some() { "looking back at" } else { "at" };
            let who = if self.run(1).is_some() { format!("Run {name} ({}): ", s.settings) } else { String::new() };
            text += &format!(
                " {who}{} — {}; {when} t = {at:.2} s the errors are {}; {}.",
                s.headline, s.detail, s.readouts.error, s.observed
            );
        }
        text
    }
}
