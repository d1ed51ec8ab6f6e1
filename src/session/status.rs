//! What the page says about a run, in words. The headline is the linear analysis — ρ of the
//! settings on screen, known from the first frame — stated plainly; the simulation's own
//! observation confirms it (or says why it cannot) as soon as it can. Written here so that every
//! number shown for one setting comes from one place and cannot contradict another.

use serde::Serialize;

use super::run::Run;
use crate::analysis::judgement::judge;
use crate::control::metrics::Verdict;
use crate::plot::format::{minus, scientific, significant};
use crate::words::judgement::{judgement, JudgementText};

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

/// One run's status, in words and flags.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RunStatus {
    /// "A" or "B".
    pub run: &'static str,
    /// "stable", "unstable", "borderline" (from ρ), or what the run has shown beyond it:
    /// "diverged", "bounded oscillation", "solver failed" (a numerical failure stopped it).
    pub verdict: &'static str,
    /// The verdict as the headline says it: "Unstable", "Stable", "Borderline", "Diverged",
    /// "Bounded oscillation", "Solver failed".
    pub headline: &'static str,
    /// The prediction in a sentence: "ρ = 1.0239 > 1 — in the long run the errors grow e-fold every
    /// 0.42 s".
    pub detail: String,
    /// The headline and the detail's first clause, for a narrow strip (an embed's):
    /// "Unstable: ρ = 1.0239 > 1" — derived from them, so it never says otherwise.
    pub short: String,
    /// The detail's first clause alone, "ρ = 1.0239 > 1": after the headline on a short screen
    /// (presentation mode on a 768-line projector).
    pub detail_short: String,
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
    /// With sensors on, what limits the error, from the linear noise floor (empty without them).
    pub limits: String,
}

/// The status of `run`, named `name`.
pub fn run_status(name: &'static str, run: &Run) -> RunStatus {
    let sim = run.closed_loop();
    let m = sim.metrics();
    let s = sim.snapshot();
    let report = run.analysis().report();
    let JudgementText { verdict, headline, detail, observed, measured, rho } =
        judgement(&judge(&m, report, run.analysis().error(), sim.config(), s.error));
    let pair = |v: [f64; 2], unit: &str| format!("{}, {} {unit}", scientific(v[0], 3), scientific(v[1], 3));
    let readouts = Readouts {
        time: format!("{:.2} s", m.time),
        error: crate::words::settings::errors(s.error),
        max_slew: pair(m.max_error_slew, "rad"),
        // Nothing to show until the reference has rested once.
        max_after: if m.time <= sim.config().reference.slew_time {
            "— (the slew is under way)".into()
        } else {
            pair(m.max_error_after, "rad")
        },
        torque: format!("{}, {} N m", significant(m.max_torque[0], 3), significant(m.max_torque[1], 3)),
        growth: match (m.verdict, m.growth_rate) {
            // The last fit before a divergence is no rate of the run's.
            (Verdict::Diverged { .. }, _) => "— (diverged)".into(),
            (_, None) if !m.errors_at_floor => "measuring…".into(),
            (_, g) => minus(&crate::words::verdict::growth(g, m.errors_at_floor)),
        },
        a4: report.map_or("—".into(), |r| {
            let [[re, im], [re2, im2]] = r.limit_pair;
            let pair = if im == 0.0 && im2 == 0.0 {
                // Two real eigenvalues (a motor damped past its swing): never "± 0j".
                format!("{} and {} 1/s", significant(re.max(re2), 3), significant(re.min(re2), 3))
            } else {
                format!("{} ± {}j 1/s", significant(re, 3), significant(im.abs(), 4))
            };
            format!("{pair} {}", limit_is(sim.config()))
        }),
    };
    RunStatus {
        run: name,
        verdict,
        headline,
        announce: format!("Run {name}: {headline}. {detail}."),
        short: short_verdict(headline, &detail),
        detail_short: first_clause(&detail).to_owned(),
        detail,
        observed,
        measured,
        finished: sim.is_finished(),
        rho,
        spectral_radius: report.map(|r| r.spectral_radius),
        growth_rate: report.map(|r| r.growth_rate),
        readouts,
        settings: crate::words::settings::run(&run.settings().config()),
        limits: limits(run),
    }
}

/// What limits the error of a run with sensors: their noise floor, scaled from the analysis's.
fn limits(run: &Run) -> String {
    let sensors = run.closed_loop().config().sensors;
    if !sensors.is_digital() {
        return String::new();
    }
    let floor = run.analysis().unit_floor().map(|f| f.scaled(sensors.angle_variance().sqrt()));
    crate::words::sensors::limits_text(floor.as_ref(), &sensors)
}

/// What the flexible pair's δ → 0 limit is for `config`: A4 (with its K_pr) when the controller
/// knows the arm; under a model error the loop's limit, which the closed forms of A4 do not give.
fn limit_is(config: &crate::control::SimulationConfig) -> &'static str {
    use crate::control::config::PreliminaryFeedbackChoice::Off;
    match (config.has_model_error(), config.preliminary_feedback == Off) {
        (true, _) => "(the loop's limit, not A4: the controller assumes the paper's arm)",
        (false, true) => "(A4)",
        (false, false) => "(A4 with Kₚᵣ)",
    }
}

/// "Unstable: ρ = 1.0239 > 1" from the headline and the detail (up to its first " — " or ";").
pub fn short_verdict(headline: &str, detail: &str) -> String {
    format!("{headline}: {}", first_clause(detail))
}

/// A detail up to its first " — " or ";".
fn first_clause(detail: &str) -> &str {
    let first = detail.split(" — ").next().unwrap_or(detail);
    first.split("; ").next().unwrap_or(first)
}

/// What a student in student mode (`answers=hidden`) may not see yet: the verdict and ρ, the
/// observation (it says whether the simulation agrees with ρ), the growth rates and A4. What the
/// figure shows (the errors, the torques, the time) stays; the words say what is hidden, for the
/// eye and the screen reader alike.
pub fn hide_answers(r: &mut RunStatus) {
    const HIDDEN: &str = "hidden until you answer";
    r.verdict = "hidden";
    r.headline = "Verdict hidden";
    r.detail = "student mode: the verdict and ρ wait for your answer".into();
    r.short = short_verdict(r.headline, &r.detail);
    r.detail_short = first_clause(&r.detail).to_owned();
    r.observed = if r.finished {
        // What the run did is on screen: say why it stopped, not what ρ says.
        "The run stopped: the errors passed π rad. Restart to watch it again.".into()
    } else {
        "Watch the errors: do they grow or die out?".into()
    };
    r.measured = false;
    r.rho = format!("linear analysis: {HIDDEN}");
    r.spectral_radius = None;
    r.growth_rate = None;
    r.announce = format!("Run {}: the verdict is hidden until you answer.", r.run);
    r.readouts.growth = HIDDEN.into();
    r.readouts.a4 = HIDDEN.into();
}
