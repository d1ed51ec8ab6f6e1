//! Issue 36, "the processor": the paper says "to be implementable, the numerical integration of the
//! DAE has to be faster than real-time". One sampling instant's prediction against δ, in words —
//! from made-up timings (nothing here is timed) — and its arithmetic.

use flexarm::control::timing::{median, ControllerTime};
use flexarm::words::processor::{period, processor, short_duration};

fn time(seconds_per_sample: f64, sampling_period: f64, horizon_steps: usize) -> ControllerTime {
    ControllerTime { seconds_per_sample, sampling_period, horizon_steps }
}

#[test]
fn a_fast_prediction_is_faster_than_real_time() {
    let t = time(6.2e-6, 0.002, 12);
    assert!((t.share() - 0.0031).abs() < 1e-12);
    assert!(t.fits());
    assert_eq!(
        processor(&t),
        "the controller's prediction (k = 12 backward-Euler steps) takes 6.2 µs per sample here: 0.31 % of δ = 2 ms \
         — faster than real time"
    );
}

#[test]
fn a_prediction_longer_than_delta_cannot_be_implemented() {
    let t = time(140e-6, 1e-4, 12);
    assert!((t.share() - 1.4).abs() < 1e-12);
    assert!(!t.fits());
    assert_eq!(
        processor(&t),
        "the controller's prediction (k = 12 backward-Euler steps) takes 140 µs per sample here: 140 % of δ = 0.1 ms: \
         slower than real time, this δ cannot be implemented on this computer"
    );
    // Exactly δ is not faster than real time.
    assert!(!time(0.01, 0.01, 4).fits());
}

#[test]
fn units_follow_the_size() {
    assert_eq!(short_duration(85e-9), "85 ns");
    assert_eq!(short_duration(3.55e-6), "3.5 µs");
    assert_eq!(short_duration(1.4e-3), "1.4 ms");
    assert_eq!(short_duration(2.5), "2.5 s");
    assert_eq!(period(0.01), "10 ms");
    assert_eq!(period(1e-5), "0.01 ms");
    assert_eq!(period(1.5), "1.5 s");
    let one = processor(&time(3.0e-3, 1.0, 1));
    assert!(
        one.contains("(k = 1 backward-Euler step)") && one.contains("3 ms") && one.contains("0.3 % of δ = 1 s"),
        "{one}"
    );
}

#[test]
fn a_clock_that_saw_nothing_is_said_so() {
    for s in [0.0, f64::NAN, f64::INFINITY] {
        let t = time(s, 0.01, 12);
        assert!(!t.is_measured());
        assert!(processor(&t).contains("could not be timed"), "{s}");
    }
    assert!(!time(f64::NAN, 0.01, 12).fits());
}

#[test]
fn the_median_is_the_middle_sample() {
    assert_eq!(median(&mut [5.0, 1.0, 4.0, 2.0, 3.0]), 3.0);
    assert_eq!(median(&mut [2.0, 1.0]), 1.5);
    assert!(median(&mut []).is_nan());
}

/// `simulate` and `analyze` say the native figure: a `processor` line, and
/// `controller_seconds_per_sample` in the JSON (its size is the computer's, not checked here).
#[test]
fn simulate_and_analyze_time_the_controller_here() {
    let run = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().expect("flexarm runs");
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let text = run(&["simulate", "--duration", "0.2", "--delta", "0.002"]);
    let line = text.lines().find(|l| l.trim_start().starts_with("processor")).unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains("(k = 12 backward-Euler steps) takes") && line.contains("of δ = 2 ms"), "{line}");
    let analyze = run(&["analyze", "--k", "4", "--eps-ratio", "4"]);
    assert!(analyze.contains("processor: the controller's prediction (k = 4 backward-Euler steps)"), "{analyze}");
    for args in [&["simulate", "--duration", "0.2", "--json"][..], &["analyze", "--json"]] {
        let v: serde_json::Value = serde_json::from_str(&run(args)).expect("JSON");
        let seconds = v["controller_seconds_per_sample"].as_f64().unwrap_or_else(|| panic!("{args:?}: {v}"));
        assert!(seconds > 0.0 && seconds < 1.0, "{args:?}: {seconds}");
    }
}
