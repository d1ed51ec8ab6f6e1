//! Computes the spectral radius ρ of a few configurations with the native build of the core, so
//! the browser tests can check that the wasm build gives the same numbers.

use std::fmt::Write;

use flexarm::analysis::spectral_radius;
use flexarm::{PreliminaryFeedbackChoice, SimulationConfig};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=../src");
    let mut out = String::from("/// (δ [s], α, preliminary feedback, ρ from the native core).\n");
    out.push_str("pub const NATIVE_RHO: &[(f64, f64, &str, f64)] = &[\n");
    for (delta, alpha, pf) in [
        (0.01, 2.0, PreliminaryFeedbackChoice::Off),
        (0.01, 2.0, PreliminaryFeedbackChoice::Paper),
        (0.04, 2.0, PreliminaryFeedbackChoice::Off),
        (0.005, 0.5, PreliminaryFeedbackChoice::Lq),
        (0.12, 3.0, PreliminaryFeedbackChoice::Off),
        (0.01, 2.0, PreliminaryFeedbackChoice::Twist),
    ] {
        let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
        c.controller.sampling_period = delta;
        c.controller.alpha = [alpha, alpha];
        let rho = spectral_radius(&c, None).expect("valid configuration");
        let name = pf.name();
        writeln!(out, "    ({delta:?}, {alpha:?}, {name:?}, {rho:?}),").unwrap();
    }
    out.push_str("];\n");
    let path = std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("native_rho.rs");
    std::fs::write(path, out).unwrap();
}
