//! Every invalid input gives a typed error that names the parameter and the allowed range.

use flexarm::analysis::{analyze, spectral_radius};
use flexarm::*;

fn expect_config_error(config: SimulationConfig, parameter: &str, allowed: &str) {
    let check = |e: Error, what: &str| match e {
        Error::Config(ConfigError { parameter: p, allowed: a, .. }) => {
            assert!(p.contains(parameter), "{what}: parameter {p:?} should name {parameter:?}");
            assert!(a.contains(allowed), "{what}: allowed range {a:?} should mention {allowed:?}");
        }
        other => panic!("{what}: expected a config error for {parameter}, got {other:?}"),
    };
    check(config.validate().map_err(Error::from).unwrap_err(), "validate");
    check(ClosedLoop::new(config).unwrap_err(), "ClosedLoop::new");
    check(simulate(&config, 1.0).unwrap_err(), "simulate");
    check(analyze(&config, None).unwrap_err(), "analyze");
    check(spectral_radius(&config, None).unwrap_err(), "spectral_radius");
    // A running loop rejects it too and keeps its configuration.
    let mut sim = ClosedLoop::new(SimulationConfig::default()).unwrap();
    check(sim.set_config(config).unwrap_err(), "set_config");
}

fn with(f: impl FnOnce(&mut SimulationConfig)) -> SimulationConfig {
    let mut c = SimulationConfig::default();
    f(&mut c);
    c
}

#[test]
fn sampling_period_must_be_positive_and_finite() {
    // Below 1e-5 s only the δ → 0 limit remains, at over 10⁵ predictions per simulated second.
    for bad in [0.0, -0.01, 9e-6, 1e-300, f64::NAN, f64::INFINITY, 11.0] {
        let c = with(|c| c.controller.sampling_period = bad);
        let allowed = if bad.is_finite() { "from 1e-5 s to 10 s" } else { "finite" };
        expect_config_error(c, "sampling_period", allowed);
    }
}

#[test]
fn alphas_must_be_positive() {
    expect_config_error(with(|c| c.controller.alpha = [0.0, 2.0]), "alpha1", "from 0.001");
    expect_config_error(with(|c| c.controller.alpha = [2.0, -1.0]), "alpha2", "from 0.001");
    expect_config_error(with(|c| c.controller.alpha = [f64::NAN, 2.0]), "alpha1", "finite");
}

#[test]
fn horizon_must_be_at_least_one_step() {
    for k in [0] {
        expect_config_error(
            with(|c| {
                c.controller.horizon_steps = k;
                c.controller.eps_ratio = (k as f64).max(1.0);
            }),
            "k (horizon",
            "an integer from 1 to 1000",
        );
    }
}

#[test]
fn horizon_must_lie_between_one_and_two_sampling_periods() {
    // k = 12: δ ≤ kε ≤ 2δ ⇔ 6 ≤ m ≤ 12.
    for m in [5.9, 12.5, 30.0] {
        expect_config_error(with(|c| c.controller.eps_ratio = m), "eps_ratio", "δ ≤ kε ≤ 2δ");
    }
    expect_config_error(with(|c| c.controller.eps_ratio = -8.0), "eps_ratio", "> 0");
    for m in [6.0, 12.0] {
        assert!(with(|c| c.controller.eps_ratio = m).validate().is_ok());
    }
}

#[test]
fn plant_parameters_are_checked() {
    // A thousandth to a thousand times the paper's inertias and stiffness (tests/arm_range.rs).
    for bad in [0.0, 1e-12, 1e-300, 2e6] {
        expect_config_error(with(|c| c.plant.k1 = bad), "K1", "from 1.1526 to 1152600 N m/rad");
    }
    expect_config_error(with(|c| c.plant.ir1 = -1.0), "I_r1", "from 0.001939 to 1939 kg m²");
    expect_config_error(with(|c| c.plant.ir1 = 1e-300), "I_r1", "from 0.001939 to 1939 kg m²");
    expect_config_error(with(|c| c.plant.bv1 = -0.1), "B_v1", "≥ 0");
    expect_config_error(with(|c| c.plant.fc2 = f64::NAN), "F_c2", "finite");
    expect_config_error(with(|c| c.plant.eps1 = 0.0), "ε1", "> 0");
    expect_config_error(with(|c| c.plant.a3 = 2.0), "A3", "positive definite");
}

#[test]
fn reference_and_run_settings_are_checked() {
    expect_config_error(with(|c| c.reference.slew_time = 0.0), "slew_time", "> 0");
    expect_config_error(with(|c| c.reference.end[1] = f64::INFINITY), "reference.end[1]", "finite");
    expect_config_error(with(|c| c.reference.repeat_hold = Some(-1.0)), "repeat_hold", "≥ 0");
    expect_config_error(with(|c| c.plant_step_max = 0.0), "plant_step_max", "> 0");
    expect_config_error(with(|c| c.output_interval = -1.0), "output_interval", "> 0");
    expect_config_error(with(|c| c.divergence_bound = f64::NAN), "divergence_bound", "finite");
}

#[test]
fn durations_are_checked() {
    let c = SimulationConfig::default();
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(simulate(&c, bad), Err(Error::InvalidDuration(_))));
        let mut sim = ClosedLoop::new(c).unwrap();
        let e = sim.advance(bad).unwrap_err();
        assert!(e.to_string().contains("duration"), "{e}");
        assert!(sim.apply_disturbance([1.0, 0.0], bad).is_err());
    }
}

#[test]
fn messages_name_the_parameter_and_the_range() {
    let e = ClosedLoop::new(with(|c| c.controller.sampling_period = -0.5)).unwrap_err();
    assert!(e.to_string().starts_with("invalid sampling_period (δ) = -0.5: must be from 1e-5 s to 10 s (below"), "{e}");
}
