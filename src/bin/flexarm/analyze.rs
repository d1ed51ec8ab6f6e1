//! `flexarm analyze`: the sampled loop linearized at rest — ρ, the eigenvalues, the δ → 0 pair A4.

use clap::{ArgMatches, Command};
use flexarm::analysis::resonance::ResonanceReport;
use flexarm::analysis::{self, StabilityReport};
use flexarm::plot::format::minus;
use flexarm::schema;
use flexarm::{words, SimulationConfig};
use serde_json::json;

use crate::cli::{self, lib_error, Failure, Res};
use crate::output::{describe_config, processor, processor_json, processor_text, settings_json};
use flexarm::analysis::judgement::judge_analysis;

/// The run settings the analysis depends on (friction compensation and the slew do not change ρ).
pub const KEYS: &[&str] = &["delta", "alpha", "alpha1", "alpha2", "pf", "inner", "k", "eps_ratio"];

pub fn command() -> Command {
    cli::command("analyze", "The sampled loop linearized at rest: ρ, its eigenvalues, and the δ → 0 pair A4")
        .args(cli::run_args(KEYS))
        .arg(cli::param_arg(&schema::Q2))
        .arg(cli::flag("json", "Print the stability report as one JSON object"))
        .arg(cli::option(
            "place",
            "RE,IM",
            "Place the δ → 0 pair A4 at RE ± IM j (1/s) with the twist feedback: finds k_p, k_d in closed form \
             and analyzes the loop with them (pf = twist)",
        ))
}

/// `--place RE,IM`: the twist gains that put A4 there, or why none in the settings' ranges does.
fn placed(m: &ArgMatches, config: &mut SimulationConfig, q2: Option<f64>) -> Res<Option<[f64; 4]>> {
    let Some(text) = m.get_one::<String>("place") else { return Ok(None) };
    let parts: Vec<Option<f64>> = text.split(',').map(cli::parse_number).collect();
    let [Some(re), Some(im)] = parts[..] else {
        return Err(cli::usage_error(format!("--place {text}: give the pair as RE,IM in 1/s, e.g. --place=-2.6,29.6")));
    };
    let target = nalgebra::Complex::new(re, im.abs());
    let q2 = q2.unwrap_or(config.reference.end[1]);
    // Designed on the arm the controller assumes, as the LQ design is.
    let [kp, kd] = flexarm::analysis::design::place_twist(&config.model_plant(), config.controller.alpha, q2, target)
        .map_err(|u| {
        cli::usage_error(format!(
            "--place {re},{im}: no twist feedback reaches it — {}",
            words::design::unplaceable(&u)
        ))
    })?;
    config.preliminary_feedback = flexarm::PreliminaryFeedbackChoice::Twist;
    config.twist = flexarm::control::config::TwistFeedback { stiffness: kp, damping: kd };
    Ok(Some([re, im.abs(), kp, kd]))
}

pub fn run(m: &ArgMatches) -> Res<String> {
    let mut settings = cli::read_settings(m, KEYS)?;
    let mut config = settings.a.config();
    let q2 = m.get_one::<String>(schema::Q2.key).map(|_| cli::number(m, &schema::Q2)).transpose()?;
    let placement = placed(m, &mut config, q2)?;
    if placement.is_some() {
        settings.a.pf = config.preliminary_feedback;
        settings.a.twist = config.twist;
    }
    let report = analysis::analyze(&config, q2).map_err(lib_error)?;
    // The stable windows of δ for these settings (δ itself aside), over the page's δ range.
    let range = schema::DELTA.number().expect("δ is a number").control;
    let windows = analysis::stable_windows(&analysis::LinearSettings::of(&config, q2), range).map_err(lib_error)?;
    // The design's price: the windows with the feedback analog and sampled, the torque it takes.
    let linear = analysis::LinearSettings::of(&config, q2);
    let price = analysis::design::DigitalPrice::of(&linear, range).map_err(lib_error)?;
    let torque = flexarm::control::torque_price(&config).map_err(lib_error)?;
    let gain = flexarm::control::feedback::resolve_gain(&config).map_err(lib_error)?;
    let design = words::design::status(
        config.preliminary_feedback,
        config.inner_loop,
        config.sensors.is_digital(),
        report.limit_pair,
        [Some(&price.analog), Some(&price.sampled)],
        Some(&torque),
        &flexarm::control::feedback::twist_parts(&gain),
    );
    // The verdict every command and the page give these settings, in the same words.
    let (headline, detail) = judge_analysis(&report, config.sensors.angle_variance() > 0.0)
        .ok_or_else(|| Failure(format!("the linear analysis gave ρ = {}, not a number", report.spectral_radius), 2))?;
    let verdict = words::judgement::verdict(headline, &detail);
    // Section 3's structure for the arm shown: V*, Ā1, A4, the index, k at and below it.
    // (An arm whose linearized DAE is not regular has no such structure; the rest still stands.)
    let structure = analysis::structure::Structure::of(&config, q2);
    let structure_words = structure.as_ref().ok().map(|s| words::structure::structure(s, config.preliminary_feedback));
    // "To be implementable, the numerical integration of the DAE has to be faster than real-time."
    let processor = processor(&config);
    // With sensors on: the noise their white error leaves at this δ (the linear prediction).
    let floor = crate::output::noise_floor(&config);
    if m.get_flag("json") {
        // Non-finite floats (e.g. ln 0) become null in serde_json's Value.
        let mut v = serde_json::to_value(&report).map_err(|e| Failure(format!("JSON encoding failed: {e}"), 1))?;
        // The settings under the schema's keys (δ is `delta`, not the report's field name).
        let object = v.as_object_mut().ok_or_else(|| Failure("JSON encoding failed: not an object".into(), 1))?;
        object.remove("sampling_period");
        // The rest point is the setting `rest` elsewhere; here it is q2 (the analysis does not depend on q1).
        object.remove("rest");
        // Not the friction, the slew's repetition or the run's rest point: ρ does not depend on them.
        object.extend(settings_json(&settings.a, |key| !matches!(key, "friction" | "repeat" | "rest")));
        v[schema::Q2.key] = json!(report.rest[1]);
        v["state"] = json!(settings.run_query());
        v["verdict"] = json!(verdict.verdict);
        v["headline"] = json!(verdict.headline);
        v["detail"] = json!(verdict.detail);
        v["stable_windows"] =
            json!({ "range": windows.range, "windows": windows.windows, "tolerance": windows.tolerance });
        let windows_json = |w: &analysis::StableWindows| json!({ "range": w.range, "windows": w.windows });
        v["design"] = json!({
            "analog": windows_json(&price.analog),
            "sampled": windows_json(&price.sampled),
            "delta_max": { "analog": design.delta_max[0], "sampled": design.delta_max[1] },
            "torque": torque,
            "twist_parts": flexarm::control::feedback::twist_parts(&gain),
        });
        v["structure"] = match (&structure, &structure_words) {
            (Ok(s), Some(w)) => {
                let mut object =
                    serde_json::to_value(s).map_err(|e| Failure(format!("JSON encoding failed: {e}"), 1))?;
                object["sentences"] = json!(w.lines());
                object
            }
            (Err(e), _) => json!({ "error": e.to_string() }),
            _ => serde_json::Value::Null,
        };
        v["controller_seconds_per_sample"] = processor_json(&processor);
        v["noise_floor"] = match &floor {
            Some(Ok(f)) => json!(f),
            Some(Err(e)) => json!({ "error": e.to_string() }),
            None => serde_json::Value::Null,
        };
        if let Some([re, im, kp, kd]) = placement {
            v["placement"] = json!({ "target": [re, im], "twist_stiffness": kp, "twist_damping": kd });
        }
        return Ok(v.to_string() + "\n");
    }
    let mut text = String::new();
    if let Some([re, im, kp, kd]) = placement {
        text += &format!(
            "placing A4 at {re} ± {im}j 1/s: --pf twist --twist-stiffness {kp:.4} --twist-damping {kd:.4} \
             (k_p in N m/rad, k_d in N m s/rad)\n"
        );
    }
    text += &analysis_text(&config, &report, &verdict.line());
    if config.has_model_error() {
        text += "(the closed form below is for a controller that knows this arm; the pairs above include the model error)\n";
    }
    text += &resonance_text(&report.resonance, &config);
    text += "section 3's structure at this rest point (the predictor as δ → 0, knowing the arm; k at δ):\n";
    match (&structure, &structure_words) {
        (Ok(_), Some(w)) => {
            for line in w.lines() {
                text += &format!("  {line}\n");
            }
        }
        (Err(e), _) => text += &format!("  not computed: {e}\n"),
        _ => {}
    }
    text += &format!(
        "stable windows of δ at these α (edges within {:.0e} s): {}\n",
        windows.tolerance,
        flexarm::words::settings::windows(&windows)
    );
    text += &format!(
        "the price of the preliminary feedback ({}):\n",
        words::settings::feedback_short(config.preliminary_feedback)
    );
    for line in [design.analog, design.sampled, design.torque, design.parts].iter().filter(|l| !l.is_empty()) {
        text += &format!("  {line}\n");
    }
    text += &format!("processor: {}\n", processor_text(&processor));
    if config.sensors.is_digital() {
        let f = floor.as_ref().and_then(|r| r.as_ref().ok());
        text += &format!(
            "noise floor: {}\n",
            words::sensors::prediction_text(config.controller.sampling_period, f, &config.sensors)
        );
    }
    Ok(text)
}

fn analysis_text(c: &SimulationConfig, r: &StabilityReport, verdict: &str) -> String {
    let mut s = format!(
        "flexarm analyze: sampled loop linearized at rest at q1 = {:.4} rad, q2 = {:.4} rad, friction cancelled\n\
         configuration\n{}",
        r.rest[0],
        r.rest[1],
        describe_config(c)
    );
    s += &format!(
        "verdict: {verdict}\nspectral radius ρ = {:.6}, growth rate ln ρ/δ = {:.4} 1/s\n",
        r.spectral_radius, r.growth_rate
    );
    s += "eigenvalues of the one-period map (s = ln λ/δ, ζ = −Re s/|s|):\n";
    s += &format!(
        "  {:>2}  {:>10} {:>11} {:>11}  {:>11} {:>11}  {:>8} {:>11}\n",
        "#", "|λ|", "Re λ", "Im λ", "Re s [1/s]", "Im s [1/s]", "ζ", "|s| [rad/s]"
    );
    for (i, p) in r.poles.iter().enumerate() {
        let [re, im] = p.discrete;
        s += &format!("  {:>2}  {:>10.6} {:>11.6} {:>11.6}", i + 1, re.hypot(im), re, im);
        s += &match p.continuous {
            Some([sr, si]) => {
                let w = sr.hypot(si);
                let zeta = if w > 0.0 { format!("{:>8.4}", -sr / w) } else { format!("{:>8}", "—") };
                format!("  {sr:>11.4} {si:>11.4}  {zeta} {w:>11.4}\n")
            }
            None => "  (λ = 0: no continuous equivalent)\n".into(),
        };
    }
    let pair = |p: [[f64; 2]; 2]| flexarm::words::numbers::eigen_pair(p, 4);
    // With a model error the limit pair is no longer A4 (the controller's model is not the arm).
    let name = if c.has_model_error() { "pair (with the model error)" } else { "pair A4" };
    s += &format!("δ → 0 {name} without preliminary feedback: {}\n", pair(r.limit_pair_open));
    // With the feedback off the two lines would repeat one pair under a misleading label.
    if r.limit_pair != r.limit_pair_open {
        s += &format!(
            "δ → 0 {name} with preliminary feedback ({}): {}\n",
            c.preliminary_feedback.name(),
            pair(r.limit_pair)
        );
    }
    s
}

/// The joint's resonance in closed form at the rest point, from the report (see
/// `flexarm::analysis::resonance`).
fn resonance_text(r: &ResonanceReport, config: &SimulationConfig) -> String {
    let a = r.a4;
    let mut s =
        "the joint's resonance in closed form (δ → 0; z = θ − θ*, the gap to the motor angle the links' law needs):\n"
            .to_string();
    s += &format!(
        "  J_eff = A1 − A2 − (A3²/A2) cos² q2 = {:.4} kg m²; motor against link 1: √(K1 (1/Ir1 + 1/J_eff)) = {:.2} rad/s \
         (against a clamped link: {:.2})\n",
        r.j_eff, r.omega_joint, r.omega_clamped
    );
    s += &format!(
        "  A4 = [[3β, 1], [−(K1/Ir1 + K1/J_eff + 6γ), −Bv1/Ir1]] = [[{:.4}, {:.0}], [{:.3}, {:.4}]]: trace {:.4} 1/s, \
         det {:.3} 1/s²\n",
        a[0][0], a[0][1], a[1][0], a[1][1], r.trace, r.determinant
    );
    let input = r.a4_input;
    s += &format!(
        "  how the torques enter (ż, ẏ): B4 = [[0, κ], [1/Ir1, λ]] = [[{:.0}, {:.4e}], [{:.4}, {:.4e}]] per N m of (T1, T2); \
         a feedback ΔT = K (z, y) makes the pair A4 + B4 K\n",
        input[0][0], input[0][1], input[1][0], input[1][1]
    );
    // Re A4 is the pair's growth rate only while the pair swings (tr² < 4 det); two real
    // eigenvalues have tr/2 as their mean and the larger one decides.
    let parts =
        format!("3β/2 − Bv1/(2 Ir1) = {:.4} − {:.4} = {:.4} 1/s", r.controller_feed, r.motor_damping, r.real_part);
    let beta = format!("β = α1 + μ (α1 − α2) = {:.4} 1/s (μ = {:.4})", r.beta, r.mu);
    s += &match r.real_eigenvalues() {
        None => format!("  Re A4 = {parts}, with {beta}\n"),
        Some([larger, smaller]) => minus(&format!(
            "  A4 has two real eigenvalues here (tr² ≥ 4 det: the motor no longer swings), {larger:.4} and {smaller:.4} \
             1/s: {parts} is their mean, not a growth rate; with {beta}\n"
        )),
    };
    s += &if r.arm_pair[1] != 0.0 {
        format!(
            "  the arm alone (no torque, friction cancelled): {:.4} ± {:.4}j 1/s\n",
            r.arm_pair[0],
            r.arm_pair[1].abs()
        )
    } else {
        "  the arm alone (no torque, friction cancelled) does not swing: its motor is damped past the swing\n".into()
    };
    let b = r.open_bound;
    s += &if b.lost_to_det() {
        let at = b.det_zero.unwrap_or(0.0);
        format!(
            "  α* = Bv1/(3 Ir1) = {:.4} 1/s, where tr A4 = 0; but det A4 = 6α² − 3α Bv1/Ir1 + K1/Ir1 + K1/J_eff reaches 0 \
             first, at α = {at:.4} 1/s: without preliminary feedback the pair (α1 = α2) is stable only for α < {at:.4} 1/s \
             (above it a real eigenvalue is positive: a slow real mode grows)\n",
            r.alpha_star
        )
    } else {
        format!(
            "  α* = Bv1/(3 Ir1) = {:.4} 1/s: below it (α1 = α2) the pair is stable without preliminary feedback\n",
            r.alpha_star
        )
    };
    if r.feedback_shift != 0.0 {
        s +=
            &format!("  the preliminary feedback shifts Re A4 by {:.4} 1/s (through its gains on θ̇)", r.feedback_shift);
        s += &match r.feedback_alpha_limit {
            Some(limit) => format!(", whatever α1 = α2: the pair stays stable for α < {limit:.3} 1/s\n"),
            None => "\n".into(),
        };
        // The paper's gains are fixed (designed for the paper's arm at α = 2): where this arm and α
        // leave the pair unstable with them, say so and why.
        let [a1, a2] = config.controller.alpha;
        if let (Some(bound), true) = (r.feedback_bound, a1 == a2) {
            if a1 >= bound.stable_below() {
                let why = if bound.lost_to_det() {
                    flexarm::words::story::gains_fail_because(&bound).to_string()
                } else {
                    format!(
                        "the feed 3α/2 − Bv1/(2 Ir1) = {} 1/s outweighs the shift's {} 1/s",
                        minus(&format!("{:.4}", r.real_part)),
                        minus(&format!("{:.4}", r.feedback_shift))
                    )
                };
                s += &format!(
                    "  so at α = {} 1/s it does not damp the pair on this arm: {why}, and small δ fail{}\n",
                    flexarm::plot::format::significant_trimmed(a1, 3),
                    if config.preliminary_feedback == flexarm::control::config::PreliminaryFeedbackChoice::Paper {
                        " (the paper's gains are fixed, designed for the paper's arm at α = 2 1/s; --pf lq is redone for \
                         each arm and α)"
                    } else {
                        ""
                    }
                );
            }
        }
    }
    s
}
