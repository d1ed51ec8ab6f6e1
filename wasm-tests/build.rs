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
    // Issue 34: the page's judgement at the start of a run, as the native session gives it
    // (tests/one_judgement.rs checks the CLI's commands against the same session): ρ just above
    // 1 inside the borderline band, just outside it, and clearly on either side.
    out.push_str("/// (state, the native session's verdict word, headline and detail at t = 0).\n");
    out.push_str("pub const NATIVE_JUDGEMENT: &[(&str, &str, &str, &str)] = &[\n");
    for state in [
        "delta=0.002&alpha=0.25&pf=off&repeat=0",
        "delta=0.002&alpha=0.22&pf=off&repeat=0",
        "delta=0.002&alpha=0.28&pf=off&repeat=0",
        "delta=0.01&alpha=2&pf=off&repeat=0",
        "delta=0.01&alpha=2&pf=paper&repeat=0",
    ] {
        let (session, notices) = flexarm::session::Session::open(state);
        assert!(notices.is_empty(), "{state}: {notices:?}");
        let run = &session.status().runs[0];
        writeln!(out, "    ({state:?}, {:?}, {:?}, {:?}),", run.verdict, run.headline, run.detail).unwrap();
    }
    out.push_str("];\n");
    let path = std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("native_rho.rs");
    std::fs::write(path, out).unwrap();
}
