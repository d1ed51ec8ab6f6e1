//! What the linear analysis and the simulation say about a run, as facts: ρ's prediction, what
//! the simulation has observed and whether they agree, why they may not, and the verdict decided
//! from both. The headline is the linear analysis — ρ of the settings, known from the first frame —
//! where it describes the run; what the simulation has seen beyond it (a divergence, a limit cycle)
//! overrides it. The page's status and the CLI's summary both say this ([`crate::words::judgement`]
//! renders it), so they cannot disagree.

use serde::Serialize;

use super::sampled::{describes, StabilityReport};
use crate::control::config::{FrictionCompensation, SimulationConfig};
use crate::control::metrics::{DivergenceReason, Metrics, Verdict, GROWTH_FIT_SPAN, UNSTABLE_GROWTH_RATE};

/// Errors above this (rad) are far enough from rest for the arm's nonlinearity (Coriolis terms,
/// the mass matrix's change with q2) to be a reason the simulation departs from ρ; below it the
/// linearization holds and another reason is given.
pub const NONLINEAR_ERROR: f64 = 0.05;

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
    /// ρ's prediction for a loop and its rate ln ρ/δ, where the analysis gave finite numbers: the
    /// one rule every command and the page judge ρ by (a rate within the borderline band is
    /// borderline whichever side of 1 ρ is).
    pub fn of_report(report: &StabilityReport) -> Option<(Prediction, f64)> {
        let (rho, rate) = (report.spectral_radius, report.growth_rate);
        (rho.is_finite() && rate.is_finite()).then(|| (Prediction::of_rate(rate), rate))
    }

    /// The prediction for ρ per sampling period δ (s): by its rate ln ρ/δ.
    pub fn of_rho(rho: f64, delta: f64) -> Option<Prediction> {
        let rate = rho.ln() / delta;
        (rho.is_finite() && rate.is_finite()).then(|| Prediction::of_rate(rate))
    }

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

/// Why the simulation may not follow the linear analysis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Caveat {
    /// The analysis is linearized at rest; far from rest the arm is nonlinear.
    Nonlinear,
    /// The analysis takes the friction as cancelled; held over δ, the compensation leaves the
    /// friction's change within each period.
    HeldFriction,
    /// The analysis takes the friction as cancelled; uncompensated, the motor's Dahl friction is a
    /// spring at rest (of `spring` = F_c1/ε1 N m/rad, rounded to 3 figures, beside the joint's
    /// K1) and a torque of up to F_c1 beyond ε1.
    NoFriction { spring: f64, eps1: f64, k1: f64, fc1: f64 },
    /// ρ is the noise-free loop's: the run also carries its sensors' error and its torque limit
    /// (`config.sensors`), which the linear analysis does not see.
    Sensors(crate::control::sensing::SensorModel),
}

impl Caveat {
    /// The caveat of a configuration's friction compensation.
    pub fn of(config: &SimulationConfig) -> Caveat {
        let p = config.plant;
        if config.sensors != crate::control::sensing::SensorModel::default() {
            return Caveat::Sensors(config.sensors);
        }
        match config.friction_compensation {
            FrictionCompensation::Continuous => Caveat::Nonlinear,
            FrictionCompensation::Held => Caveat::HeldFriction,
            FrictionCompensation::Off => Caveat::NoFriction {
                spring: crate::schema::round_significant(p.fc1 / p.eps1, 3),
                eps1: p.eps1,
                k1: p.k1,
                fc1: p.fc1,
            },
        }
    }
}

/// A divergence against what ρ said.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DivergenceReading {
    /// As ρ > 1 predicted.
    AsPredicted,
    /// ρ > 1, computed with the friction cancelled, points the same way, but does not describe
    /// this run.
    SameWayWithoutFriction,
    /// Not what ρ, computed with the friction cancelled, predicts.
    NotPredictedWithoutFriction(Caveat),
    /// Not what ρ predicts.
    NotPredicted(Caveat),
}

/// An oscillation of steady size against what ρ said.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OscillationReading {
    /// Too early to tell: ρ > 1 predicts growth at `rate`, which the slew's dying transient can
    /// hide for a while.
    TooEarlyForGrowth { rate: f64 },
    /// ρ > 1 predicts growth, and the nonlinearity bounds it.
    Bounded,
    /// As ρ ≈ 1 predicts: a mode that hardly grows or decays.
    AsBorderline,
    /// Too early to tell: near rest the loop is linear, and ρ predicts `rate`.
    TooEarlyNearRest { rate: f64 },
    /// A nonlinear effect ρ cannot show.
    Nonlinear(Caveat),
}

/// Errors that come back as large after every slew, against what ρ said.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SlewReading {
    /// The slowest mode dies out by e only every 1/|rate| s, longer than the `period` between slews.
    SlowerThanTheSlews { rate: f64, period: f64 },
    /// Each slew's transient dies out, as ρ < 1 predicts.
    TransientDies,
    /// As ρ ≈ 1 predicts: the slowest mode hardly moves at `rate`, and every slew excites it again.
    AsBorderline { rate: f64 },
    /// Too early to tell: ρ > 1 predicts growth at `rate` from slew to slew.
    TooEarlyForGrowth { rate: f64 },
    /// No prediction to compare with.
    Caveat(Caveat),
}

/// Errors settled at their floor, against what ρ said.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FloorReading {
    NotPredicted(Caveat),
    /// Nothing left to grow or decay, as ρ < 1 predicts.
    AsPredicted,
    /// No prediction to compare with.
    Alone,
}

/// A measured growth rate against ρ's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GrowthReading {
    /// ρ does not describe the run: the rate, the errors now and why.
    Alone { error: [f64; 2], caveat: Caveat },
    /// No prediction.
    Unpredicted,
    /// Within a quarter of ln ρ/δ (`predicted`).
    Matches { predicted: f64 },
    /// The sign ρ predicts, at another rate; `faster`: above ln ρ/δ.
    SameSign { prediction: Prediction, predicted: f64, faster: bool },
    /// The other sign.
    OtherSign { prediction: Prediction, predicted: f64, why: OtherSignWhy },
}

/// Why a measured rate can have another sign than ln ρ/δ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OtherSignWhy {
    /// Too slow to show in the seconds fitted (`span`), where the slew's (`repeating`: slews')
    /// transient still shows.
    TooSlow {
        span: f64,
        repeating: bool,
    },
    Caveat(Caveat),
    /// ln ρ/δ is the rate in the long run; over a few seconds the modes' sum can move otherwise.
    LongRun,
}

/// What the simulation has observed, and how it stands against ρ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Observation {
    /// The run stopped at `at` s because the predictor's Newton iteration did not converge: a
    /// numerical failure of the solver, which says nothing of the arm's dynamics or of ρ; the
    /// errors were `error` (rad) then.
    SolverFailed {
        at: f64,
        error: [f64; 2],
    },
    /// Diverged at `at` s; `bound`: the error bound it passed (rad), if that was the reason.
    Diverged {
        at: f64,
        reason: DivergenceReason,
        bound: f64,
        reading: DivergenceReading,
    },
    /// A bounded oscillation (limit cycle); `steady_so_far`: near rest, with a prediction to
    /// compare, called an oscillation of steady size so far.
    Oscillation {
        amplitude: [f64; 2],
        period: f64,
        steady_so_far: bool,
        reading: OscillationReading,
    },
    /// The errors come back about as large after every slew; `across`: the rate from slew to slew.
    SlewLocked {
        amplitude: [f64; 2],
        period: f64,
        across: Option<f64>,
        reading: SlewReading,
    },
    AtFloor(FloorReading),
    /// Still measuring, between slews (`repeating`) or since the slew; alone: only the simulation
    /// can judge.
    Measuring {
        repeating: bool,
        alone: Option<Caveat>,
    },
    /// A growth rate measured, 1/s.
    Growth {
        rate: f64,
        reading: GrowthReading,
    },
}

impl Observation {
    /// True once the simulation has measured something (a rate, a divergence, a cycle, the floor).
    pub fn measured(&self) -> bool {
        !matches!(self, Observation::Measuring { .. })
    }
}

/// The verdict as the headline says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Headline {
    Stable,
    Unstable,
    Borderline,
    Diverged,
    /// The predictor's solver failed (a numerical failure): the run stopped, nothing diverged.
    SolverFailed,
    BoundedOscillation,
    Bounded,
    TooEarly,
}

impl Headline {
    /// The verdict's one name, shared by the page's status, the CLI and the JSON: "stable",
    /// "unstable", "borderline", "diverged", "solver failed", "bounded oscillation", "bounded",
    /// "too early to tell".
    pub fn id(self) -> &'static str {
        match self {
            Headline::Stable => "stable",
            Headline::Unstable => "unstable",
            Headline::Borderline => "borderline",
            Headline::Diverged => "diverged",
            Headline::SolverFailed => "solver failed",
            Headline::BoundedOscillation => "bounded oscillation",
            Headline::Bounded => "bounded",
            Headline::TooEarly => "too early to tell",
        }
    }
}

impl From<Prediction> for Headline {
    /// ρ's prediction as the headline says it where nothing the simulation saw overrides it.
    fn from(p: Prediction) -> Headline {
        match p {
            Prediction::Stable => Headline::Stable,
            Prediction::Borderline => Headline::Borderline,
            Prediction::Unstable => Headline::Unstable,
        }
    }
}

/// The prediction under the headline.
#[derive(Clone, Debug, PartialEq)]
pub enum Detail {
    /// ρ's own verdict, at `rate` = ln ρ/δ; `noisy`: the controller reads its angles with an
    /// error (an encoder, noise), so the errors settle at that error's floor, not at rest.
    Prediction { rho: f64, rate: f64, prediction: Prediction, noisy: bool },
    /// Under a headline the simulation decided against ρ: what the linear analysis predicts.
    Predicted { rho: f64, rate: f64, prediction: Prediction },
    /// ρ holds with the friction cancelled, not for this run: the simulation decides.
    SimulationDecides { rho: f64 },
    /// The linear analysis failed, and why.
    AnalysisFailed(String),
}

/// The analysis line: ρ, where it holds, and its verdict.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RhoLine {
    /// No analysis.
    Missing,
    /// ρ at the rest point q2 (rad), its rate ln ρ/δ (not always finite), and whether it
    /// describes the run; `digital`: the loop is the digital controller of the sensors (its ρ
    /// is that of the noise-free loop).
    Analysis { q2: f64, rho: f64, rate: f64, describes: bool, digital: bool },
}

/// What a run's status says about it, decided once from the simulation's metrics, the linear
/// analysis of its settings (or why it failed), its configuration and the errors now.
#[derive(Clone, Debug, PartialEq)]
pub struct Judgement {
    pub headline: Headline,
    pub detail: Detail,
    pub observation: Observation,
    pub rho: RhoLine,
    /// Under a headline that is not a failure (stable, borderline, bounded, too early), a
    /// tracking error large against the slew: stable is not the same as useful.
    pub large_error: Option<crate::control::metrics::LargeError>,
}

/// The judgement of the linear analysis alone (no run: `analyze`, `sweep` without `--simulate`):
/// ρ's prediction as the headline, and the sentence under it — the headline and detail [`judge`]
/// gives a run where nothing the simulation saw overrides ρ. None where ρ is not finite.
pub fn judge_analysis(report: &StabilityReport, noisy: bool) -> Option<(Headline, Detail)> {
    let (prediction, rate) = Prediction::of_report(report)?;
    Some((prediction.into(), Detail::Prediction { rho: report.spectral_radius, rate, prediction, noisy }))
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

/// The observation, against the prediction (ρ's, and its rate).
fn observe(
    m: &Metrics,
    prediction: Option<(Prediction, f64)>,
    config: &SimulationConfig,
    error: [f64; 2],
) -> Observation {
    // Where ρ does not describe the run, it is never cited as the cause of what is seen.
    let raw_prediction = prediction;
    let applies = describes(config);
    let prediction = prediction.filter(|_| applies);
    let repeating = config.reference.repeat_hold.is_some();
    let alone = !applies;
    let caveat = Caveat::of(config);
    if let Verdict::Diverged { at, reason: DivergenceReason::NewtonFailure } = m.verdict {
        return Observation::SolverFailed { at, error };
    }
    if let Verdict::Diverged { at, reason } = m.verdict {
        let reading = match prediction {
            Some((Prediction::Unstable, _)) => DivergenceReading::AsPredicted,
            // ρ with the friction cancelled, where it is not: it may still point the same way
            // (far from rest the friction only saturates), but it is not the verdict.
            _ if alone => match raw_prediction {
                Some((Prediction::Unstable, _)) => DivergenceReading::SameWayWithoutFriction,
                _ => DivergenceReading::NotPredictedWithoutFriction(caveat),
            },
            _ => DivergenceReading::NotPredicted(caveat),
        };
        return Observation::Diverged { at, reason, bound: config.divergence_bound, reading };
    }
    if let Verdict::BoundedOscillation { amplitude, period } = m.verdict {
        // Near rest the arm is linear: a flat envelope there is not the nonlinearity at work.
        let near_rest = amplitude[0].max(amplitude[1]) < NONLINEAR_ERROR;
        let reading = match prediction {
            Some((Prediction::Unstable, rate)) if near_rest => OscillationReading::TooEarlyForGrowth { rate },
            Some((Prediction::Unstable, _)) => OscillationReading::Bounded,
            Some((Prediction::Borderline, _)) if near_rest => OscillationReading::AsBorderline,
            Some((_, rate)) if near_rest => OscillationReading::TooEarlyNearRest { rate },
            _ => OscillationReading::Nonlinear(caveat),
        };
        let steady_so_far = near_rest && prediction.is_some();
        return Observation::Oscillation { amplitude, period, steady_so_far, reading };
    }
    if let Verdict::SlewLocked { amplitude, period } = m.verdict {
        let reading = match prediction {
            Some((Prediction::Stable, rate)) if 1.0 / rate.abs() > period => {
                SlewReading::SlowerThanTheSlews { rate, period }
            }
            Some((Prediction::Stable, _)) => SlewReading::TransientDies,
            Some((Prediction::Borderline, rate)) => SlewReading::AsBorderline { rate },
            Some((Prediction::Unstable, rate)) => SlewReading::TooEarlyForGrowth { rate },
            None => SlewReading::Caveat(caveat),
        };
        return Observation::SlewLocked { amplitude, period, across: m.growth_rate, reading };
    }
    let Some(g) = m.growth_rate else {
        if m.errors_at_floor {
            return Observation::AtFloor(match prediction {
                Some((Prediction::Unstable, _)) => FloorReading::NotPredicted(caveat),
                Some(_) => FloorReading::AsPredicted,
                None => FloorReading::Alone,
            });
        }
        return Observation::Measuring { repeating, alone: alone.then_some(caveat) };
    };
    if alone {
        return Observation::Growth { rate: g, reading: GrowthReading::Alone { error, caveat } };
    }
    let Some((p, predicted)) = prediction else {
        return Observation::Growth { rate: g, reading: GrowthReading::Unpredicted };
    };
    let reading = if Prediction::of_rate(g) == p {
        if (g - predicted).abs() <= 0.25 * predicted.abs().max(0.2) {
            GrowthReading::Matches { predicted }
        } else {
            GrowthReading::SameSign { prediction: p, predicted, faster: g > predicted }
        }
    } else {
        let why = if predicted.abs() * GROWTH_FIT_SPAN < 1.0 {
            // Too slow to show in the seconds fitted: never blame the nonlinearity for that.
            OtherSignWhy::TooSlow { span: GROWTH_FIT_SPAN, repeating }
        } else if error[0].abs().max(error[1].abs()) > NONLINEAR_ERROR {
            OtherSignWhy::Caveat(caveat)
        } else {
            OtherSignWhy::LongRun
        };
        GrowthReading::OtherSign { prediction: p, predicted, why }
    };
    Observation::Growth { rate: g, reading }
}

/// The judgement of a run (see [`Judgement`]).
pub fn judge(
    m: &Metrics,
    report: Option<&StabilityReport>,
    analysis_error: Option<&str>,
    config: &SimulationConfig,
    error: [f64; 2],
) -> Judgement {
    let prediction = report.and_then(Prediction::of_report);
    let predicted = report.zip(prediction).map(|(r, (_, rate))| (r.spectral_radius, rate));
    let observation = observe(m, prediction, config, error);
    let measured = observation.measured();
    let applies = describes(config);
    let near_rest = error[0].abs().max(error[1].abs()) < NONLINEAR_ERROR;
    // A rate that changes the errors by e or more over the span fitted: growth (sign 1) or decay
    // (−1) the simulation has clearly seen.
    let clear = |sign: f64| m.growth_rate.is_some_and(|g| sign * g * GROWTH_FIT_SPAN >= 1.0);
    // ρ decides the headline only where it describes the run (the friction cancelled); what the
    // simulation has seen beyond the linear analysis overrides it: a divergence, or a limit
    // cycle (named as the CLI and the JSON name it).
    let judged = prediction.filter(|_| applies).map(|p| p.0);
    let headline = match (m.verdict, judged) {
        (Verdict::Diverged { reason: DivergenceReason::NewtonFailure, .. }, _) => Headline::SolverFailed,
        (Verdict::Diverged { .. }, _) => Headline::Diverged,
        (Verdict::BoundedOscillation { .. }, _) if credible_cycle(m, applies) => Headline::BoundedOscillation,
        (_, Some(p)) => p.into(),
        // Without an analysis that holds, only the simulation can say, once it has seen enough: a
        // growth that has carried the errors far from rest, or a decay that has brought them near
        // it. Near rest the friction's hunting can grow for a while and then settle into a cycle.
        (_, None) if m.errors_at_floor => Headline::Stable,
        (Verdict::Unstable { .. }, None) if !near_rest && clear(1.0) => Headline::Unstable,
        // Near rest the friction can hold the errors, let them creep, or hunt: bounded so far,
        // and said no more firmly than that.
        (_, None) if measured && near_rest => Headline::Bounded,
        (_, None) => Headline::TooEarly,
    };
    // Under a headline the simulation decided against ρ, ρ's sentence is the prediction.
    let overridden = match m.verdict {
        Verdict::BoundedOscillation { .. } => credible_cycle(m, applies),
        // A solver failure overrides every headline: ρ's is only what it predicts.
        Verdict::Diverged { reason: DivergenceReason::NewtonFailure, .. } => true,
        Verdict::Diverged { .. } => !matches!(judged, Some(Prediction::Unstable)),
        _ => false,
    };
    let detail = match predicted {
        Some((rho, _)) if !applies => Detail::SimulationDecides { rho },
        Some((rho, rate)) if overridden => Detail::Predicted { rho, rate, prediction: Prediction::of_rate(rate) },
        Some((rho, rate)) => Detail::Prediction {
            rho,
            rate,
            prediction: Prediction::of_rate(rate),
            noisy: config.sensors.angle_variance() > 0.0,
        },
        None => Detail::AnalysisFailed(analysis_error.unwrap_or("no report").to_string()),
    };
    let rho = match report {
        None => RhoLine::Missing,
        Some(r) => RhoLine::Analysis {
            q2: r.rest[1],
            rho: r.spectral_radius,
            rate: r.growth_rate,
            describes: applies,
            digital: config.sensors.is_digital(),
        },
    };
    let failed = matches!(headline, Headline::Unstable | Headline::Diverged);
    let large_error = if failed { None } else { m.large_error(&config.reference) };
    Judgement { headline, detail, observation, rho, large_error }
}
