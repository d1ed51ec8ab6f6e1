//! The sensors, the torque limit and what they do to δ's lower bound, in words: rendered from the
//! facts of [`crate::analysis::sensor_study`] and [`crate::analysis::noise`], never canned.

use crate::analysis::noise::NoiseFloor;
use crate::analysis::sensor_study::{tracking_error, Best, SensorStudy, StudyRow, MARKEDLY_WORSE};
use crate::control::sensing::{SensorModel, VelocitySource};
use crate::control::sensor_sweep::SWEEP_SECONDS;
use crate::plot::format::{number, significant};

/// The sensors in a few words: "a 1024-count encoder, velocities differenced over δ, torque at
/// most 150 N m", or the paper's "perfect sensors, unlimited torque".
pub fn sensors_text(s: &SensorModel) -> String {
    let mut parts = Vec::new();
    if s.encoder_counts > 0.0 {
        parts.push(format!("a {}-count encoder", number(s.encoder_counts)));
    }
    if s.noise > 0.0 {
        parts.push(format!("angle noise σ = {} rad", significant(s.noise, 2)));
    }
    if s.velocity == VelocitySource::Difference {
        parts.push("velocities differenced over δ".to_string());
    }
    if s.velocity_filter > 0.0 {
        parts.push(format!("filtered with τᵥ = {} s", number(s.velocity_filter)));
    }
    if let Some(limit) = s.limit() {
        parts.push(format!("torque at most {} N m", number(limit)));
    }
    if parts.is_empty() {
        "perfect sensors, unlimited torque (the paper's)".to_string()
    } else {
        parts.join(", ")
    }
}

/// The study's table: a header row (with units) and one row per δ, every cell text; cells not yet
/// simulated are "…", predictions that do not exist "—".
pub fn study_table(study: &SensorStudy, sensors: &SensorModel) -> Vec<Vec<String>> {
    let limited = sensors.limit().is_some();
    let mut header = vec![
        "δ [s]".to_string(),
        "ρ".to_string(),
        "max |e|, slew [rad]".to_string(),
        "perfect sensors [rad]".to_string(),
        "RMS e, rest [rad]".to_string(),
        "T1 noise, rest [N m]".to_string(),
        "peak T1 [N m]".to_string(),
    ];
    if limited {
        header.push("time at the limit".to_string());
    }
    header.push("predicted T1 noise [N m]".to_string());
    let mut table = vec![header];
    for r in &study.rows {
        // A cell: "…" until the run is in, "—" where it diverged (the slew's columns say so).
        let cell = |v: Option<f64>, digits: usize| match v {
            Some(v) => significant(v, digits),
            None if r.real.is_none() => "…".to_string(),
            None => "—".to_string(),
        };
        let slew = |v: Option<f64>, ran: bool, diverged: bool| match v {
            Some(v) => significant(v, 2),
            None if diverged => "diverged".to_string(),
            None if ran => "—".to_string(),
            None => "…".to_string(),
        };
        let ideal_diverged = r.ideal.is_some_and(|p| p.diverged);
        let mut row = vec![
            number(r.sampling_period),
            r.spectral_radius.map_or("—".to_string(), crate::words::numbers::rho),
            slew(r.slew_error(), r.real.is_some(), r.diverged()),
            slew(r.ideal_slew_error(), r.ideal.is_some(), ideal_diverged),
            cell(r.rest_error(), 2),
            cell(r.torque_noise(), 2),
            cell(r.peak_torque(), 3),
        ];
        if limited {
            row.push(r.saturated().map_or_else(|| cell(None, 0), percent));
        }
        row.push(r.predicted_torque().map_or("—".to_string(), |v| significant(v, 2)));
        table.push(row);
    }
    table
}

/// What the table's columns are, in one paragraph under it.
pub fn table_note(sensors: &SensorModel) -> String {
    let mut s = "ρ: the linear analysis of this loop at each δ (≥ 1: unstable — its errors grow in the long run, \
                 even where the short run has not diverged; such a row is never the best); max |e|, slew: the \
                 largest error of either link while the arm slews (each δ's run is one slew from rest; the page's run \
                 repeats it, and a later slew starts from where the last one left the arm); perfect sensors: the same \
                 slew in the paper's loop — exact readings, the preliminary feedback and the friction observer acting \
                 continuously, no torque limit; RMS e and T1 noise at rest: over the 2 s \
                 after the slew (T1 noise is the motor torque's RMS about its mean); peak T1: the largest motor \
                 torque"
        .to_string();
    if let Some(limit) = sensors.limit() {
        s += &format!("; time at the limit: the share of the time a motor sits at its {} N m", number(limit));
    }
    s + "; predicted T1 noise: the linear prediction with each reading's error as white noise, valid while the \
         arm moves (— where the digital loop is unstable or reads exactly). The highlighted row has the least \
         error of the stable δ; ▸ marks the δ of the run shown; choose a δ to run the arm at it."
}

fn error_cell(e: f64) -> String {
    if e.is_finite() {
        significant(e, 2)
    } else {
        "diverged".to_string()
    }
}

/// A share of the time as the table and the figure's readout both print it: "0 %", "< 1 %", "3 %".
pub fn percent(share: f64) -> String {
    if share == 0.0 {
        "0 %".to_string()
    } else if share < 0.01 {
        "< 1 %".to_string()
    } else {
        format!("{:.0} %", 100.0 * share)
    }
}

/// The study's findings in sentences, each from the numbers of the rows it names.
pub fn study_summary(study: &SensorStudy, sensors: &SensorModel) -> Vec<String> {
    let mut out = vec![if *sensors == SensorModel::default() {
        format!(
            "Each row is the paper's 1-s slew and {} s at rest, simulated with the paper's perfect sensors and \
             unlimited torque.",
            number(SWEEP_SECONDS - 1.0)
        )
    } else {
        format!(
            "Each row is the paper's 1-s slew and {} s at rest, simulated with {} and again with perfect sensors.",
            number(SWEEP_SECONDS - 1.0),
            sensors_text(sensors)
        )
    }];
    let real = |r: &StudyRow| r.real.as_ref().map_or(f64::INFINITY, tracking_error);
    let ideal = |r: &StudyRow| r.ideal.as_ref().map_or(f64::INFINITY, tracking_error);
    let (Some(first), Some(last)) = (study.rows.first(), study.rows.last()) else {
        return out;
    };
    let best = match study.best {
        Best::Pending => {
            out.push(format!("Simulating: {:.0} % done.", 100.0 * study.progress));
            return out;
        }
        Best::Inside { index } | Best::Smallest { index } => &study.rows[index],
        Best::Largest => last,
        Best::Nowhere => {
            out.push(
                "No δ studied tracks: at every one the loop is unstable by ρ (ρ ≥ 1) or the run diverges.".to_string(),
            );
            return out;
        }
    };
    if let Some(s) = unstable_rows(study, sensors) {
        out.push(s);
    }
    let at = |r: &StudyRow| format!("{} s", number(r.sampling_period));
    out.push(match study.best {
        // Below the best the noise-free loop itself is unstable: ρ, not the sensors' noise, bounds δ.
        Best::Inside { .. } if first.unstable() => format!(
            "A best δ exists among the δ studied: the error during the slew is smallest at δ = {} ({} rad); at {} \
             {} — there ρ of the noise-free loop, not the sensors' noise, rules δ out.",
            at(best),
            significant(real(best), 2),
            at(first),
            if first.real.is_some_and(|p| p.diverged) { "the run diverges" } else { "the loop is unstable by ρ" }
        ),
        Best::Inside { .. } => format!(
            "A best δ exists with these sensors: the error during the slew is smallest at δ = {} ({} rad), and \
             both faster and slower sampling track worse — at {}, {}.",
            at(best),
            significant(real(best), 2),
            at(first),
            match study.smallest_excess {
                Some(x) => format!("{}× worse", significant(x, 2)),
                None if first.real.is_some_and(|p| p.diverged) => "the run diverges".to_string(),
                None => "the loop is unstable by ρ".to_string(),
            }
        ),
        Best::Smallest { index: 0 } => format!(
            "The error during the slew is smallest at the smallest δ studied, {} ({} rad): with these sensors, \
             sampling faster still helps down to it.",
            at(best),
            significant(real(best), 2)
        ),
        Best::Smallest { .. } => format!(
            "The error during the slew is smallest at δ = {} ({} rad) and stays within {} % of that down to the \
             smallest δ studied, {}: no best δ above it — sampling faster neither helps nor hurts much there.",
            at(best),
            significant(real(best), 2),
            number(100.0 * (MARKEDLY_WORSE - 1.0)),
            at(first)
        ),
        _ => format!(
            "The error during the slew is smallest at the largest δ studied, {} ({} rad).",
            at(best),
            significant(real(best), 2)
        ),
    });
    if let (Best::Inside { .. }, false) = (study.best, first.unstable()) {
        out.push(below_best(first, best, sensors));
    }
    if let Some(s) = above_best(study, best, &real, &ideal) {
        out.push(s);
    }
    if let Some(s) = at_rest(study, best) {
        out.push(s);
    }
    out
}

/// The best δ is judged by the slew; the columns at rest may point elsewhere: say where, from
/// the rows' own numbers (None when no row at rest was simulated).
fn at_rest(study: &SensorStudy, best: &StudyRow) -> Option<String> {
    let least = |f: &dyn Fn(&crate::control::sensor_sweep::SweepPoint) -> f64| {
        study
            .rows
            .iter()
            .filter(|r| !r.unstable())
            .filter_map(|r| r.real.filter(|p| !p.diverged).map(|p| (r.sampling_period, f(&p))))
            .filter(|(_, v)| v.is_finite())
            .min_by(|a, b| a.1.total_cmp(&b.1))
    };
    let (error_at, error) = least(&|p| p.rms_error_rest[0].max(p.rms_error_rest[1]))?;
    let (torque_at, torque) = least(&|p| p.torque_fluctuation_rest[0])?;
    let here = best.sampling_period;
    if error_at == here && torque_at == here {
        return Some(format!(
            "That δ is judged by the slew; at rest, too, the error and T1's noise are least at {} s.",
            number(here)
        ));
    }
    if error_at == torque_at {
        return Some(format!(
            "That δ is judged by the error during the slew. At rest both the error ({} rad RMS) and T1's noise ({} N \
             m RMS) are least at δ = {} s: a δ chosen for holding still or for a quiet motor differs.",
            significant(error, 2),
            significant(torque, 2),
            number(error_at)
        ));
    }
    let (mut parts, mut purposes) = (Vec::new(), Vec::new());
    if error_at != here {
        parts.push(format!("the error is least at δ = {} s ({} rad RMS)", number(error_at), significant(error, 2)));
        purposes.push("for holding still");
    }
    if torque_at != here {
        parts.push(format!("T1's noise at δ = {} s ({} N m RMS)", number(torque_at), significant(torque, 2)));
        purposes.push("for a quiet motor");
    }
    Some(format!(
        "That δ is judged by the error during the slew. At rest {}: a δ chosen {} differs.",
        parts.join(", and "),
        purposes.join(" or ")
    ))
}

/// Why the smallest δ tracks worse than the best: how far it is from perfect sensors, and the
/// torque's noise and time at the limit there.
fn below_best(first: &StudyRow, best: &StudyRow, sensors: &SensorModel) -> String {
    let (Some(f), Some(b), Some(fi), Some(bi)) = (first.real, best.real, first.ideal, best.ideal) else {
        return String::new();
    };
    let (e, ei) = (tracking_error(&f), tracking_error(&fi));
    if !e.is_finite() {
        return format!(
            "At δ = {} s the run with these sensors diverges, while perfect sensors track within {} rad.",
            number(first.sampling_period),
            error_cell(ei)
        );
    }
    let mut s = format!("At δ = {} s the error is {} rad", number(first.sampling_period), error_cell(e));
    if e.is_finite() && ei > 0.0 {
        s += &format!(", {}× what perfect sensors give ({} rad)", significant(e / ei, 2), significant(ei, 2));
        // Faster sampling helps the perfect robot and hurts this one: what differs, the sensors,
        // is what grows.
        if ei < tracking_error(&bi) {
            s += ": the sensors' error, not the sampling, sets it there";
        }
    }
    let (tf, tb) = (f.torque_fluctuation_rest[0], b.torque_fluctuation_rest[0]);
    if tf > 1.2 * tb {
        s += &format!(
            "; T1 fluctuates by {} N m RMS at rest there, against {} N m at {} s",
            significant(tf, 2),
            significant(tb, 2),
            number(best.sampling_period)
        );
    }
    if let Some(limit) = sensors.limit() {
        let sat = f.saturated[0].max(f.saturated[1]);
        if sat > 0.0 {
            s += &format!(", and a motor sits at its {} N m limit {} of the time", number(limit), percent(sat));
        }
    }
    s + "."
}

/// What happens above the best δ: the largest δ that did not diverge, against perfect sensors.
fn above_best(
    study: &SensorStudy,
    best: &StudyRow,
    real: &dyn Fn(&StudyRow) -> f64,
    ideal: &dyn Fn(&StudyRow) -> f64,
) -> Option<String> {
    // The largest δ that tracks: its run did not diverge and ρ < 1 (an unstable row's short run
    // says nothing of the long run, and the sentence on unstable rows covers it).
    let top = study
        .rows
        .iter()
        .rev()
        .find(|r| r.sampling_period > best.sampling_period && real(r).is_finite() && !r.unstable())?;
    let (e, ei) = (real(top), ideal(top));
    let mut s = format!(
        "At δ = {} s the error is {} rad, and {} rad with perfect sensors",
        number(top.sampling_period),
        significant(e, 2),
        error_cell(ei)
    );
    if ei.is_finite() && ei > 0.3 * e {
        s += ": there the sampling itself sets it";
    }
    let diverged =
        study.rows.iter().find(|r| r.sampling_period > top.sampling_period && r.real.is_some_and(|p| p.diverged));
    if let Some(d) = diverged {
        s += &format!("; from δ = {} s the run with these sensors diverges", number(d.sampling_period));
    }
    Some(s + ".")
}

/// What limits the error with these sensors, for the status under the verdict: the noise floor
/// the linear prediction gives (`floor`, None where the digital loop is unstable), from which
/// source and through which velocity estimate; ρ is the loop without that error.
pub fn limits_text(floor: Option<&NoiseFloor>, sensors: &SensorModel) -> String {
    let Some(f) = floor else {
        return "With these sensors the noise-free digital loop is unstable (ρ ≥ 1): no error floor to speak of."
            .to_string();
    };
    let quantizer = sensors.count() * sensors.count() / 12.0;
    let source = match (sensors.encoder_counts > 0.0, sensors.noise > 0.0) {
        (false, false) => {
            return "The controller is digital but reads exact angles: the sensors add no error, and ρ says the rest."
                .to_string();
        }
        (true, false) => format!("the {}-count encoder", number(sensors.encoder_counts)),
        (false, true) => format!("the angle noise σ = {} rad", significant(sensors.noise, 2)),
        (true, true) if quantizer >= sensors.noise * sensors.noise => {
            format!("the {}-count encoder (more than the angle noise)", number(sensors.encoder_counts))
        }
        (true, true) => format!("the angle noise σ = {} rad (more than the encoder)", significant(sensors.noise, 2)),
    };
    let path = match (sensors.velocity, sensors.velocity_filter > 0.0) {
        (VelocitySource::Difference, false) => " through the velocities differenced over δ".to_string(),
        (VelocitySource::Difference, true) => format!(
            " through the velocities differenced over δ and filtered (τᵥ = {} s)",
            number(sensors.velocity_filter)
        ),
        (VelocitySource::Exact, _) => String::new(),
    };
    format!(
        "The sensors' noise: {source}{path} — by the linear prediction, about {} rad RMS of error on link 1 and \
         {} N m RMS of noise on T1 while the arm moves. The quantizer at rest, the friction's stick and slip and \
         the torque limit add what only the simulation shows: the table in A real robot compares each δ with \
         perfect sensors. ρ is the loop without the sensors' error.",
        significant(f.rms_error[0], 2),
        significant(f.rms_torque[0], 2)
    )
}

/// The linear prediction at the current δ, and where it stops applying.
pub fn prediction_text(delta: f64, floor: Option<&NoiseFloor>, sensors: &SensorModel) -> String {
    if !sensors.is_digital() {
        return "With perfect sensors there is no noise to predict: turn on an encoder, noise or differenced \
                velocities."
            .to_string();
    }
    let Some(f) = floor else {
        return format!(
            "At δ = {} s the noise-free digital loop is unstable (ρ ≥ 1): there is no noise floor to predict.",
            number(delta)
        );
    };
    let mut s = format!(
        "Linear prediction at δ = {} s (each angle's error as white noise of variance Δ²/12 + σ², the friction \
         taken as cancelled): RMS e1 {} rad, \
         e2 {} rad, T1 {} N m, T2 {} N m; ρ of the noise-free digital loop {}.",
        number(delta),
        significant(f.rms_error[0], 2),
        significant(f.rms_error[1], 2),
        significant(f.rms_torque[0], 2),
        significant(f.rms_torque[1], 2),
        crate::words::numbers::rho(f.spectral_radius)
    );
    if sensors.encoder_counts > 0.0 {
        s += &format!(
            " One count is Δ = 2π/{} = {} rad. The prediction counts on the arm crossing many counts between \
             samples, as in the slew; at rest the reading barely changes and it no longer applies — the error at \
             rest in the table comes from the quantizer and the friction's stick and slip, the torque there is \
             quieter.",
            number(sensors.encoder_counts),
            significant(sensors.count(), 2)
        );
    }
    s
}

/// The rows ρ calls unstable, as ranges of δ: "By ρ the loop is unstable at δ = 0.002–0.03 s …"
/// (None when every row is stable).
fn unstable_rows(study: &SensorStudy, sensors: &SensorModel) -> Option<String> {
    let mut ranges: Vec<(f64, f64)> = Vec::new();
    let mut open = false;
    for r in &study.rows {
        match (r.unstable(), open, ranges.last_mut()) {
            (true, true, Some(last)) => last.1 = r.sampling_period,
            (true, _, _) => ranges.push((r.sampling_period, r.sampling_period)),
            _ => {}
        }
        open = r.unstable();
    }
    if ranges.is_empty() {
        return None;
    }
    let text: Vec<String> = ranges
        .iter()
        .map(|&(a, b)| if a == b { format!("{} s", number(a)) } else { format!("{}–{} s", number(a), number(b)) })
        .collect();
    let mut s = format!(
        "By ρ the loop is unstable at δ = {}: its errors grow in the long run, even where the {}-s run has not \
         diverged yet, so those rows are never the best.",
        text.join(" and "),
        number(SWEEP_SECONDS)
    );
    // ρ is the noise-free loop's: where the paper's loop is stable at every one of those δ, what
    // differs is how this controller reads and acts, not the sensors' noise.
    let unstable: Vec<&StudyRow> = study.rows.iter().filter(|r| r.unstable()).collect();
    if unstable.iter().all(|r| r.ideal_spectral_radius.is_some_and(|p| p < 1.0)) {
        let first = unstable[0];
        let reads = match (sensors.velocity, sensors.velocity_filter > 0.0) {
            (VelocitySource::Difference, true) => Some("the velocities differenced over δ and filtered"),
            (VelocitySource::Difference, false) => Some("the velocities differenced over δ (half a period late)"),
            (_, true) => Some("the velocities filtered"),
            _ => None,
        };
        let held = "the preliminary feedback and the friction observer held over δ";
        let cause = match reads {
            Some(r) => format!("{r}, with {held}, make the difference"),
            None => format!("{held} make the difference"),
        };
        s += &format!(
            " The same loop with perfect sensors as in the paper — exact readings, the preliminary feedback and the friction observer acting \
             continuously (the perfect-sensors column) — is stable there (ρ = {} at {} s): {cause}, not the noise \
             (ρ has none).",
            first.ideal_spectral_radius.map_or("—".to_string(), crate::words::numbers::rho),
            number(first.sampling_period),
        );
    }
    Some(s)
}
