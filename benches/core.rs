//! Benchmarks of the core, as a plain bench binary (no timed tests):
//!
//! `cargo bench --bench core` times one controller sample (k = 12 Newton-solved backward-Euler
//! steps), the same from the middle of the slew as `flexarm simulate` times it (issue 36, "the
//! processor": k = 12 and k = 4, as a share of δ = 10 ms and 2 ms), a 10-s closed-loop run at δ = 0.01 s (and as the page runs it), one spectral-radius evaluation, an arm change
//! to ρ, A4 and the windows, and both maps after it, a real robot's sensors in that run, the
//! sensor study's prediction and the whole study (issue 36), and prints medians over repeated batches. `cargo bench --bench core -- --python` also runs the
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

    // Issue 36, "the processor": the sampling instant's prediction as `flexarm simulate` times it
    // (`control::timing`, from the reference's middle), at k = 12 (m = 8) and k = 4 (m = 4), at
    // δ = 0.01 and 0.002 s (ε = δ/m changes Newton's work a little).
    let processor = |k: usize, m: f64, delta: f64| {
        let mut c = config;
        c.controller.horizon_steps = k;
        c.controller.eps_ratio = m;
        c.controller.sampling_period = delta;
        let mut w = flexarm::control::ControllerWorkload::new(&c).unwrap();
        let start = Instant::now();
        let plan = flexarm::control::TimingPlan { batches: 21, per_batch: 5_000, budget: 10.0 };
        (w.measure(&mut || start.elapsed().as_secs_f64(), plan).unwrap(), k, w.newton_iterations())
    };
    let processors =
        [processor(12, 8.0, 0.01), processor(12, 8.0, 0.002), processor(4, 4.0, 0.01), processor(4, 4.0, 0.002)];

    let (run_med, run_min) = time_it(11, 3, || {
        black_box(simulate(&config, 10.0).unwrap());
    });

    // The page's run keeps 30 s of history (every sampling instant): what does that cost?
    let (history_med, history_min) = time_it(11, 3, || {
        let mut sim = ClosedLoop::new(config).unwrap();
        sim.keep_history(flexarm::session::HISTORY_SECONDS);
        sim.keep_sweep(true);
        sim.advance(10.0).unwrap();
        black_box(sim.snapshot());
    });

    // Issue 36: the sensor model's cost in a 10-s run (a 1024-count encoder, velocities
    // differenced, seeded angle noise, a 150-N m limit: the controller digital) against the same
    // run with the paper's perfect sensors, timed right after it; the study's linear
    // prediction at its 11 δ (what a change of a sensor setting recomputes); the whole simulated
    // study (11 δ × the slew with these sensors and with perfect ones).
    let sensed = {
        let mut c = config;
        let mut s = flexarm::session::Settings::default();
        s.read("encoder=1024&velocity=difference&noise=1e-5&torque_limit=150", flexarm::session::Source::CommandLine)
            .unwrap();
        c.sensors = s.a.config().sensors;
        c
    };
    let (plain_med, _) = time_it(11, 3, || {
        black_box(simulate(&config, 10.0).unwrap());
    });
    let (sensed_med, sensed_min) = time_it(11, 3, || {
        black_box(simulate(&sensed, 10.0).unwrap());
    });
    let deltas = flexarm::analysis::sensor_study::STUDY_DELTAS;
    let (linear_med, linear_min) = time_it(11, 3, || {
        black_box(flexarm::analysis::sensor_study::SensorStudy::linear(&sensed, &deltas));
    });
    let (study_med, study_min) = time_it(5, 1, || {
        let (mut s, _) = flexarm::session::Session::open("preset=real-encoder");
        black_box(s.sensor_study_step(1000).unwrap());
    });

    let (rho_med, rho_min) = time_it(21, 200, || {
        black_box(spectral_radius(black_box(&config), None).unwrap());
    });

    // Dragging an arm slider (issue 18): one change of K1 to ρ, A4 (the story) and the windows of
    // δ recomputed, as the page's session does it; then both maps of the new arm to the end.
    let (mut session, _) = flexarm::session::Session::open("preset=fig5.3&mode=full");
    let mut k1 = 1000.0;
    let (arm_med, arm_min) = time_it(15, 5, || {
        k1 = if k1 > 1800.0 { 1000.0 } else { k1 + 37.0 };
        session.set("k1", &k1.to_string()).unwrap();
        session.windows().unwrap();
        black_box(session.status().story.unwrap());
    });
    let clock = Instant::now();
    let (maps_med, maps_min) = time_it(5, 1, || {
        k1 = if k1 > 1800.0 { 1000.0 } else { k1 + 37.0 };
        session.set("k1", &k1.to_string()).unwrap();
        let a = flexarm::analysis::LinearSettings::of(&session.settings().a.config(), None);
        session.maps_mut().show(&a);
        while session.maps_mut().work(&mut || clock.elapsed().as_secs_f64() * 1e3, 1e9) {}
    });

    // Issue 32: dragging the pair — one placement to A4, ρ, the windows analog and sampled and
    // δ_max (the status a pointer move asks for); the torque price once the drag rests; and the
    // design map ρ(δ, k_d) to the end after a change of α.
    let (mut design, _) = flexarm::session::Session::open("pf=twist&twist_damping=16&mode=full");
    let mut re = -2.0;
    let (place_med, place_min) = time_it(15, 5, || {
        re = if re < -6.0 { -2.0 } else { re - 0.13 };
        design.place_pair(re, 29.0).unwrap();
        design.refresh();
        black_box(design.design_status());
    });
    let twist = {
        let mut c = config;
        c.preliminary_feedback = PreliminaryFeedbackChoice::Twist;
        c
    };
    let (torque_med, torque_min) = time_it(11, 3, || {
        black_box(flexarm::control::torque_price(&twist).unwrap());
    });
    let mut alpha = 2.0;
    let (design_map_med, design_map_min) = time_it(5, 1, || {
        alpha = if alpha > 4.0 { 1.0 } else { alpha + 0.37 };
        design.set("alpha", &alpha.to_string()).unwrap();
        let a = flexarm::analysis::LinearSettings::of(&design.settings().a.config(), None);
        design.maps_mut().show(&a);
        while design.maps_mut().work(&mut || clock.elapsed().as_secs_f64() * 1e3, 1e9) {}
    });

    // Issue 19: a frame of log |e| with the swing split out (δ = 0.002 s: 5000 kept instants in
    // the 10-s window, the most the page draws) against the same frame without the log view, and
    // the swing's energy over one period (once per analysis).
    let frame_cost = |query: &str| {
        let (mut s, _) = flexarm::session::Session::open(query);
        while s.run(0).unwrap().closed_loop().time() < 10.0 {
            s.advance(0.05).unwrap();
        }
        s.refresh();
        let mut scene = flexarm::view::Scene::new(flexarm::view::ViewOptions::default(), 1280.0, 800.0, 1.0);
        scene.draw_session(&s);
        time_it(21, 50, || {
            scene.draw_session(&s);
            black_box(scene.vertices().len());
        })
    };
    // Fig. 2.1 live: a frame zoomed on t_n with the swing's shape on, live (the controller's own
    // sweep, copied) and looking back (the sweep computed again every frame from the kept state),
    // against the same frame unzoomed.
    let zoom_cost = |query: &str, back: usize, k: usize| {
        let (mut s, _) = flexarm::session::Session::open(query);
        while s.run(0).unwrap().closed_loop().time() < 2.0 {
            s.advance(0.05).unwrap();
        }
        for _ in 0..back {
            s.step_back();
        }
        let mut scene = flexarm::view::Scene::new(flexarm::view::ViewOptions::default(), 1280.0, 800.0, 1.0);
        scene.draw_session(&s);
        time_it(21, k, || {
            scene.draw_session(&s);
            black_box(scene.vertices().len());
        })
    };
    let (zoom_live, _) = zoom_cost("preset=fig5.3&mode=full&predict=1&swing=1", 0, 200);
    let (zoom_back, zoom_back_min) = zoom_cost("preset=fig5.3&mode=full&predict=1&swing=1", 5, 200);
    let (unzoomed, _) = zoom_cost("preset=fig5.3&mode=full", 5, 200);
    let (log_med, log_min) = frame_cost("preset=fig5.2&delta=0.002&mode=full&log=1");
    let (lin_med, _) = frame_cost("preset=fig5.2&delta=0.002&mode=full");
    let model = flexarm::analysis::LoopModel::new(&flexarm::analysis::LinearSettings::of(&config, None)).unwrap();
    let mode = model.report().unwrap().swing_mode.unwrap();
    let delta = config.controller.sampling_period;
    let (energy_med, energy_min) = time_it(21, 200, || {
        black_box(model.swing_energy(delta, &mode).unwrap());
    });

    println!("flexarm core benchmarks (median of batches; min in parentheses)");
    println!("| what | median | min |");
    println!("|---|---|---|");
    println!(
        "| controller sample (k = 12 steps, {iterations} Newton iterations) | {:.2} µs | {:.2} µs |",
        sample_med * 1e6,
        sample_min * 1e6
    );
    for (t, k, newton) in processors {
        println!(
            "| the processor: one sampling instant's prediction from mid-slew (k = {k}, {newton} Newton iterations), as `simulate` times it | {:.2} µs ({:.3} % of δ = {} ms) | |",
            t.seconds_per_sample * 1e6,
            100.0 * t.share(),
            t.sampling_period * 1e3
        );
    }
    println!(
        "| 10-s closed-loop run, δ = 0.01 s, PF paper | {:.2} ms ({:.0}× real time) | {:.2} ms |",
        run_med * 1e3,
        10.0 / run_med,
        run_min * 1e3
    );
    println!(
        "| the same run keeping 30 s of history and the newest sweep (the page's timeline and Fig. 2.1) | {:.2} ms ({:+.1} % against without) | {:.2} ms |",
        history_med * 1e3,
        100.0 * (history_med / run_med - 1.0),
        history_min * 1e3
    );
    println!(
        "| the same 10-s run with a real robot's sensors (1024 counts, differenced, noise, 150 N m) | {:.2} ms ({:+.1} % against {:.2} ms without, timed just before it; goal ≤ +10 %) | {:.2} ms |",
        sensed_med * 1e3,
        100.0 * (sensed_med / plain_med - 1.0),
        plain_med * 1e3,
        sensed_min * 1e3
    );
    println!(
        "| the sensor study's linear prediction at its 11 δ (ρ and the noise floor of the 16-state loop; per change of a sensor setting) | {:.2} ms (goal ≤ 16 ms) | {:.2} ms |",
        linear_med * 1e3,
        linear_min * 1e3
    );
    println!(
        "| the whole sensor study (11 δ × the slew with the sensors and with perfect ones, 3 s each) | {:.0} ms (the page's goal ≤ 2 s) | {:.0} ms |",
        study_med * 1e3,
        study_min * 1e3
    );
    println!(
        "| one spectral radius ρ (10×10 loop, k-step pencil sweep, expm, eig) | {:.1} µs | {:.1} µs |",
        rho_med * 1e6,
        rho_min * 1e6
    );

    println!(
        "| an arm change (K1) to ρ, A4 and the windows of δ (the page's goal: ≤ 16 ms in wasm) | {:.2} ms | {:.2} ms |",
        arm_med * 1e3,
        arm_min * 1e3
    );
    println!(
        "| both maps (ρ over δ × α, no K_pr and paper K_pr) after an arm change (goal: ≤ 0.5 s in wasm) | {:.0} ms | {:.0} ms |",
        maps_med * 1e3,
        maps_min * 1e3
    );

    println!(
        "| placing the pair (issue 32): the twist gains, ρ, A4, run A's windows of δ and δ_max (the other inner loop's wait for the drag to rest; goal: ≤ 16 ms in wasm) | {:.2} ms | {:.2} ms |",
        place_med * 1e3,
        place_min * 1e3
    );
    println!(
        "| the design's torque price: one slew and a poke simulated (once the drag rests) | {:.2} ms | {:.2} ms |",
        torque_med * 1e3,
        torque_min * 1e3
    );
    println!(
        "| the design map ρ(δ, k_d) after a change of α (the map without K_pr, over α, is kept; goal: ≤ 0.5 s in wasm) | {:.0} ms | {:.0} ms |",
        design_map_med * 1e3,
        design_map_min * 1e3
    );
    println!(
        "| a frame of log |e| with the swing split out, δ = 0.002 s (5000 instants; the goal: split ≤ 1 ms) | {:.3} ms ({:+.3} ms against the linear view) | {:.3} ms |",
        log_med * 1e3,
        (log_med - lin_med) * 1e3,
        log_min * 1e3
    );
    println!(
        "| the swing's energy over one period (once per analysis; goal ≤ 1 ms) | {:.1} µs | {:.1} µs |",
        energy_med * 1e6,
        energy_min * 1e6
    );

    println!(
        "| a frame zoomed on t_n (Fig. 2.1) with the swing's shape, live: the controller's own sweep (goal ≤ 1 ms more) | {:.3} ms ({:+.3} ms against unzoomed) | |",
        zoom_live * 1e3,
        (zoom_live - unzoomed) * 1e3
    );
    println!(
        "| the same looking back: the sweep computed again from the kept state every frame | {:.3} ms ({:+.3} ms) | {:.3} ms |",
        zoom_back * 1e3,
        (zoom_back - unzoomed) * 1e3,
        zoom_back_min * 1e3
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
