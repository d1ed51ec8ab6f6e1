//! Stability outcomes computed by the wasm build, in headless Chromium.
//! Run: `wasm-pack test --headless --chrome wasm-tests` (scripts/test.sh does).

use flexarm::web::{spectral_radius, Simulation};
use js_sys::Reflect;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

include!(concat!(env!("OUT_DIR"), "/native_rho.rs"));

fn config(delta: f64, alpha: f64, pf: &str) -> JsValue {
    let js = js_sys::eval(&format!(
        "({{ controller: {{ sampling_period: {delta}, alpha: [{alpha}, {alpha}] }}, preliminary_feedback: '{pf}' }})"
    ));
    js.expect("a literal object")
}

fn get(obj: &JsValue, key: &str) -> JsValue {
    Reflect::get(obj, &key.into()).unwrap_or(JsValue::UNDEFINED)
}

fn number(obj: &JsValue, key: &str) -> f64 {
    get(obj, key).as_f64().unwrap_or(f64::NAN)
}

fn pair(obj: &JsValue, key: &str) -> [f64; 2] {
    let a = get(obj, key);
    [number(&a, "0"), number(&a, "1")]
}

/// Runs `seconds` of simulated time in browser-sized frames and returns the metrics object.
fn run(delta: f64, pf: &str, seconds: f64) -> JsValue {
    let mut sim = Simulation::new(config(delta, 2.0, pf)).map_err(JsValue::from).unwrap();
    while sim.time() < seconds - 1e-9 && !sim.is_finished() {
        sim.advance(0.1, 1.0).map_err(JsValue::from).unwrap();
    }
    sim.metrics().map_err(JsValue::from).unwrap()
}

fn verdict(m: &JsValue) -> String {
    get(m, "verdict").as_string().unwrap_or_default()
}

/// Paper, Fig. 5.3: without preliminary feedback δ = 0.01 s is unstable; with it, stable (Fig. 5.2).
#[wasm_bindgen_test]
fn small_delta_needs_the_preliminary_feedback() {
    let without = run(0.01, "off", 6.0);
    assert!(matches!(verdict(&without).as_str(), "unstable" | "diverged"), "without PF: {}", verdict(&without));
    let with = run(0.01, "paper", 6.0);
    assert_eq!(verdict(&with), "stable");
}

/// Section 4: without preliminary feedback the controller works for larger δ.
#[wasm_bindgen_test]
fn larger_delta_is_stable_without_feedback() {
    assert_eq!(verdict(&run(0.04, "off", 6.0)), "stable");
}

/// Figs. 5.1–5.2: with preliminary feedback the errors at δ = 0.01 s are smaller than at 0.04 s.
#[wasm_bindgen_test]
fn errors_shrink_with_delta() {
    let fine = pair(&run(0.01, "paper", 3.0), "max_error_slew");
    let coarse = pair(&run(0.04, "paper", 3.0), "max_error_slew");
    assert!(fine[0] < coarse[0] && fine[1] < coarse[1], "{fine:?} vs {coarse:?}");
}

/// The wasm build's ρ equals the native core's (computed by build.rs on the host).
#[wasm_bindgen_test]
fn spectral_radius_matches_the_native_core() {
    for &(delta, alpha, pf, native) in NATIVE_RHO {
        let wasm = spectral_radius(config(delta, alpha, pf)).map_err(JsValue::from).unwrap();
        assert!(
            (wasm - native).abs() <= 1e-9 * native,
            "δ = {delta}, α = {alpha}, {pf}: wasm {wasm} vs native {native}"
        );
        // The handle's analysis reports the same ρ.
        let mut sim = Simulation::new(config(delta, alpha, pf)).map_err(JsValue::from).unwrap();
        let report = sim.analysis().map_err(JsValue::from).unwrap();
        assert!((number(&report, "spectral_radius") - native).abs() <= 1e-9 * native);
    }
}

fn error_message(e: wasm_bindgen::JsError) -> String {
    let v = JsValue::from(e);
    let err = v.dyn_ref::<js_sys::Error>().expect("a JS Error object");
    String::from(err.message())
}

/// A bad configuration throws a JS `Error` with a readable message instead of panicking.
#[wasm_bindgen_test]
fn bad_configuration_throws_a_readable_error() {
    let msg = error_message(Simulation::new(config(-0.01, 2.0, "off")).err().expect("δ < 0 is rejected"));
    assert!(msg.contains("sampling_period") && msg.contains("> 0"), "{msg}");
    let msg = error_message(Simulation::new(config(0.01, 2.0, "maybe")).err().expect("unknown PF is rejected"));
    assert!(msg.contains("invalid configuration") && msg.contains("maybe"), "{msg}");
    let bad_k = js_sys::eval("({ controller: { horizon_steps: 2, eps_ratio: 2 } })").unwrap();
    let msg = error_message(Simulation::new(bad_k).err().expect("k ≤ 3 is rejected"));
    assert!(msg.contains("DAE index"), "{msg}");
    // A live change to an invalid value is rejected and the simulation goes on.
    let mut sim = Simulation::new(config(0.01, 2.0, "paper")).map_err(JsValue::from).unwrap();
    let msg = error_message(sim.set_config(config(0.01, -2.0, "paper")).err().expect("α < 0 is rejected"));
    assert!(msg.contains("alpha1"), "{msg}");
    sim.advance(0.1, 1.0).map_err(JsValue::from).unwrap();
    assert!(sim.time() > 0.09);
    assert!(sim.advance(f64::NAN, 1.0).is_err());
    assert!(sim.trace("nope").is_err());
}

/// Traces come out as typed arrays of equal length.
#[wasm_bindgen_test]
fn traces_are_typed_arrays() {
    let mut sim = Simulation::new(JsValue::UNDEFINED).map_err(JsValue::from).unwrap();
    sim.advance(0.2, 1.0).map_err(JsValue::from).unwrap();
    let t = sim.trace("t").map_err(JsValue::from).unwrap();
    let e1 = sim.trace("e1").map_err(JsValue::from).unwrap();
    assert_eq!(t.length(), e1.length());
    assert!(t.length() > 50);
    assert!(sim.traces_csv().starts_with("t [s],"));
}

/// The map computed in chunks by the wasm build: ρ agrees with single-point evaluations, and
/// without preliminary feedback the stable window of δ (section 4) shows at α = 2.
#[wasm_bindgen_test]
fn stability_map_in_chunks() {
    use flexarm::web::StabilityMapJob;
    let mut job =
        StabilityMapJob::new(config(0.01, 2.0, "off"), 0.005, 0.15, 12, 1.0, 2.0, 3).map_err(JsValue::from).unwrap();
    let mut steps = 0;
    while !job.is_done() {
        let progress = job.step(0.0).map_err(JsValue::from).unwrap();
        steps += 1;
        assert!(progress > 0.0 && progress <= 1.0);
    }
    assert_eq!(steps, 3, "a zero budget computes one row per step");
    let values = job.values().to_vec();
    let deltas = job.sampling_periods().to_vec();
    let alphas = job.alphas().to_vec();
    assert_eq!((values.len(), deltas.len(), alphas.len()), (36, 12, 3));
    for (i, a) in alphas.iter().enumerate() {
        for (j, d) in deltas.iter().enumerate() {
            let single = spectral_radius(config(*d, *a, "off")).map_err(JsValue::from).unwrap();
            assert!((values[i * 12 + j] - single).abs() < 1e-12);
        }
    }
    // α = 2 row: unstable at the smallest δ, stable somewhere in between, unstable at the largest.
    let row = &values[24..36];
    assert!(row[0] > 1.0 && row[11] > 1.0, "{row:?}");
    assert!(row.iter().any(|r| *r < 1.0), "{row:?}");
    assert!(StabilityMapJob::new(config(0.01, 2.0, "off"), 0.1, 0.01, 10, 1.0, 2.0, 3).is_err());
}
