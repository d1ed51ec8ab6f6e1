//! The 9th-order slew of section 5 (with the sign of the τ⁵ term corrected, ERRATA.md).

use flexarm::model::reference::{profile, Reference};
use flexarm::SlewParameters;
use std::f64::consts::PI;

#[test]
fn profile_goes_from_zero_to_one_with_flat_ends() {
    let (s0, ds0, dds0) = profile(0.0);
    let (s1, ds1, dds1) = profile(1.0);
    assert_eq!((s0, ds0, dds0), (0.0, 0.0, 0.0));
    assert_eq!((s1, ds1, dds1), (1.0, 0.0, 0.0));
    // Approaching the ends from inside, velocity and acceleration vanish too (5th-order contact).
    let (s, ds, dds) = profile(1.0 - 1e-3);
    assert!((s - 1.0).abs() < 1e-12 && ds.abs() < 1e-9 && dds.abs() < 1e-5);
    // Symmetric: s(1 − τ) = 1 − s(τ); midpoint 1/2; monotone.
    for i in 0..=100 {
        let t = i as f64 / 100.0;
        assert!((profile(1.0 - t).0 - (1.0 - profile(t).0)).abs() < 1e-12);
        assert!(profile(t).1 >= -1e-12);
    }
    assert!((profile(0.5).0 - 0.5).abs() < 1e-12);
}

#[test]
fn derivatives_match_finite_differences() {
    let h = 1e-6;
    for i in 1..50 {
        let t = i as f64 / 50.0;
        let (_, ds, dds) = profile(t);
        let fd1 = (profile(t + h).0 - profile(t - h).0) / (2.0 * h);
        let fd2 = (profile(t + h).1 - profile(t - h).1) / (2.0 * h);
        assert!((ds - fd1).abs() < 1e-6, "s' at {t}");
        assert!((dds - fd2).abs() < 1e-5, "s'' at {t}");
    }
}

#[test]
fn paper_reference_moves_both_links_in_one_second() {
    let r = Reference::new(SlewParameters::default());
    let start = r.sample(0.0);
    let end = r.sample(1.0);
    assert!((start.q[0] - 0.0).abs() < 1e-15 && (start.q[1] - 1.5 * PI).abs() < 1e-15);
    assert!((end.q[0] - 0.5 * PI).abs() < 1e-12 && end.q[1].abs() < 1e-12);
    assert_eq!(r.sample(5.0).q, end.q);
    // Derivatives scale with the endpoints and the slew time.
    let mid = r.sample(0.5);
    assert!((mid.qdot[0] - 0.5 * PI * profile(0.5).1).abs() < 1e-12);
    assert!((mid.qdot[1] + 1.5 * PI * profile(0.5).1).abs() < 1e-12);
    assert!(r.is_moving(0.5) && !r.is_moving(1.5));
}

#[test]
fn configurable_slew_time_and_repeating_maneuver() {
    let p = SlewParameters { start: [0.0, 0.0], end: [1.0, -1.0], slew_time: 2.0, repeat_hold: Some(1.0) };
    let r = Reference::new(p);
    assert!((r.sample(1.0).q[0] - 0.5).abs() < 1e-12);
    assert!((r.sample(2.5).q[0] - 1.0).abs() < 1e-12 && !r.is_moving(2.5));
    // Back again after the hold: period 2 (t_f + hold) = 6 s.
    assert!((r.sample(4.0).q[0] - 0.5).abs() < 1e-12 && r.is_moving(4.0));
    assert!((r.sample(4.0).qdot[0] + 0.5 * profile(0.5).1).abs() < 1e-12);
    assert!(r.sample(5.5).q[0].abs() < 1e-12);
    assert!((r.sample(7.0).q[0] - 0.5).abs() < 1e-12);
}
