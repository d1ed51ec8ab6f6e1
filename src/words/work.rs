//! What a run will cost, in words: its work estimate, and a duration in sensible units.

use crate::control::work::Work;

/// A work estimate in words, e.g. "2.0e6 sampling periods, about 9 s".
pub fn estimate(work: &Work) -> String {
    let mut parts = Vec::new();
    if work.sampling_periods > 0.0 {
        parts.push(format!("{:.1e} sampling periods", work.sampling_periods));
    }
    parts.push(format!("about {}", duration(work.seconds)));
    parts.join(", ")
}

/// Seconds in words: "9 s", "4 min", "3.2 h", "12 days", "10^14 years".
pub fn duration(seconds: f64) -> String {
    const MINUTE: f64 = 60.0;
    const HOUR: f64 = 3600.0;
    const DAY: f64 = 86400.0;
    const YEAR: f64 = 365.25 * DAY;
    if !seconds.is_finite() {
        "for ever".into()
    } else if seconds < 1.0 {
        "under a second".into()
    } else if seconds < 2.0 * MINUTE {
        format!("{seconds:.0} s")
    } else if seconds < 2.0 * HOUR {
        format!("{:.0} min", seconds / MINUTE)
    } else if seconds < 2.0 * DAY {
        format!("{:.1} h", seconds / HOUR)
    } else if seconds < YEAR {
        format!("{:.0} days", seconds / DAY)
    } else {
        format!("{:.1e} years", seconds / YEAR)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_read_in_sensible_units() {
        assert_eq!(duration(9.4), "9 s");
        assert_eq!(duration(600.0), "10 min");
        assert_eq!(duration(f64::INFINITY), "for ever");
        assert!(duration(1e12).ends_with("years"));
    }
}
