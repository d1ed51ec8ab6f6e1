//! Benchmarks of the core, as a plain bench binary (no timed tests):
//!
//! `cargo bench --bench core` times one controller sample (k = 12 Newton-solved backward-Euler
//! steps), a 10-s closed-loop run at δ = 0.01 s and one spectral-radius evaluation, and prints
//! medians over repeated batches. `cargo bench --bench core -- --python` also runs the
//! Python/NumPy/SciPy baseline of the same loop (bench/run_python.sh) and reports the ratio.

use std::hint::black_box;
use std::process::Command;
use std::time::Instant;

use flexarm::analysis::spectral_radius;
use flexarm::control::predictive::{Predictor, StateVector};
use flexarm::model::reference::Reference;
use flexarm::*;
use nalgebra::Vector2;

/// Median and minimum of `batches` timings of `f`, each the mean over `per_batch` calls, in seconds.
fn time_it(batches: usize, per_batch: usize, mut f: impl FnMut()) -> (f64, f64) {
    let mut samples: Vec<f64> = (0..batches)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..per_batch {
                f();
            }
            start.elapsed().as_secs_f64() / per_batch as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    (samples[samples.len() / 2], samples[0])
}

fn main() {
    let python = std::env::args().any(|a| a == "--python");
    let config = SimulationConfig::default();

    // A state in the middle of the slew, as the controller sees it.
    let mut sim = ClosedLoop::new(config).unwrap();
    sim.advance(0.5).unwrap();
    let s = sim.snapshot();
    let x = StateVector::from_column_slice(&[s.q[0], s.q[1], s.q[2], s.qdot[0], s.qdot[1], s.qdot[2], s.w[0], s.w[1]]);
    let predictor = Predictor::new(&config.plant, &config.controller);
    let reference = Reference::new(config.reference);
    let guess = Vector2::new(s.torque[0], s.torque[1]);
    let iterations = predictor.predict(&reference, s.time, &x, &guess).unwrap().newton_iterations;
    let (sample_med, sample_min) = time_it(21, 20_000, || {
        black_box(predictor.predict(&reference, black_box(s.time), black_box(&x), &guess).unwrap());
    });

    let (run_med, run_min) = time_it(11, 3, || {
        black_box(simulate(&config, 10.0).unwrap());
    });

    // The page's run keeps 30 s of history (every sampling instant): what does that cost?
    let (history_med, history_min) = time_it(11, 3, || {
        let mut sim = ClosedLoop::new(config).unwrap();
        sim.keep_history(flexarm::session::HISTORY_SECONDS);
        sim.advance(10.0).unwrap();
        black_box(sim.snapshot());
    });

    let (rho_med, rho_min) = time_it(21, 200, || {
        black_box(spectral_radius(black_box(&config), None).unwrap());
    });

    println!("flexarm core benchmarks (median of batches; min in parentheses)");
    println!("| what | median | min |");
    println!("|---|---|---|");
    println!(
        "| controller sample (k = 12 steps, {iterations} Newton iterations) | {:.2} µs | {:.2} µs |",
        sample_med * 1e6,
        sample_min * 1e6
    );
    println!(
        "| 10-s closed-loop run, δ = 0.01 s, PF paper | {:.2} ms ({:.0}× real time) | {:.2} ms |",
        run_med * 1e3,
        10.0 / run_med,
        run_min * 1e3
    );
    println!(
        "| the same run keeping 30 s of history (the page's timeline) | {:.2} ms ({:+.1} % against without) | {:.2} ms |",
        history_med * 1e3,
        100.0 * (history_med / run_med - 1.0),
        history_min * 1e3
    );
    println!(
        "| one spectral radius ρ (10×10 loop, k-step pencil sweep, expm, eig) | {:.1} µs | {:.1} µs |",
        rho_med * 1e6,
        rho_min * 1e6
    );

    if python {
        let root = concat!(env!("CARGO_MANIFEST_DIR"));
        let out = Command::new("bash")
            .arg(format!("{root}/bench/run_python.sh"))
            .args(["--delta", "0.01", "--duration", "10", "--pf", "paper", "--repeats", "3"])
            .output();
        match out {
            Ok(o) if o.status.success() => {
                let text = String::from_utf8_lossy(&o.stdout);
                let wall = text
                    .split("\"wall_seconds\":")
                    .nth(1)
                    .and_then(|r| r.split(',').next())
                    .and_then(|v| v.trim().parse::<f64>().ok());
                match wall {
                    Some(w) => println!(
                        "| Python/NumPy/SciPy solve_ivp baseline, same 10-s run (median of 3) | {:.2} s ({:.1}× real time) | flexarm is {:.0}× faster |",
                        w,
                        10.0 / w,
                        w / run_med
                    ),
                    None => println!("Python baseline printed no wall time: {text}"),
                }
            }
            Ok(o) => println!("Python baseline failed: {}", String::from_utf8_lossy(&o.stderr)),
            Err(e) => println!("Python baseline could not start: {e}"),
        }
    }
}
