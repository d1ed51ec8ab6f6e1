//! Peak memory of a long run: `cargo bench --bench memory` runs 20 000 s of the paper's loop
//! (δ = 0.01 s, K_pr) in chunks, as `flexarm simulate --duration 20000` does, and prints the
//! process's peak resident memory (Linux: VmHWM) before and after. The goal is ≤ 50 MB, whatever
//! the duration: the metrics are online and each chunk's traces are dropped once handed on.

use flexarm::control::simulate_in_chunks;
use flexarm::{Error, PreliminaryFeedbackChoice, SimulationConfig};

/// The peak resident memory of this process so far, MiB (None off Linux).
fn peak_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn main() {
    let mut config = SimulationConfig::default();
    config.preliminary_feedback = PreliminaryFeedbackChoice::Paper;
    let before = peak_mib();
    for duration in [200.0, 2000.0, 20_000.0] {
        let started = std::time::Instant::now();
        let mut rows = 0usize;
        let metrics = simulate_in_chunks(&config, duration, 5.0, |t, _| -> Result<(), Error> {
            rows += t.len();
            Ok(())
        })
        .expect("the paper's loop runs");
        let show = |v: Option<f64>| v.map_or("n/a".to_string(), |m| format!("{m:.1} MiB"));
        println!(
            "memory: {duration:>7} s run ({rows} trace rows, the simulation: {}): peak {} (before any run {}), {:.2} s",
            flexarm::words::verdict::verdict_short(&metrics.verdict),
            show(peak_mib()),
            show(before),
            started.elapsed().as_secs_f64()
        );
    }
}
