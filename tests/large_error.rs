//! Issue 34, item 5: a verdict on stability beside a tracking error that misses the course by a
//! tenth of a link's travel or more says so — in the CLI's verdict and in the page's status, one
//! wording. The slew's travel is the paper's (q1: π/2, q2: 3π/2); the run's errors are its own
//! measurements, and the threshold is the fraction stated in `control::metrics`.

use flexarm::control::metrics::LARGE_ERROR_FRACTION;
use std::f64::consts::PI;
use std::process::Command;

fn simulate(args: &[&str]) -> serde_json::Value {
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm"))
        .args(["simulate", "--duration", "4", "--json"])
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn worst_share(run: &serde_json::Value) -> (usize, f64, f64) {
    let travel = [0.5 * PI, 1.5 * PI];
    let err = |i: usize| run["max_error_slew"][i].as_f64().unwrap().max(run["max_error_after"][i].as_f64().unwrap());
    let (i, e) =
        (0..2).map(|i| (i, err(i))).max_by(|a, b| (a.1 / travel[a.0]).total_cmp(&(b.1 / travel[b.0]))).unwrap();
    (i, e, e / travel[i])
}

#[test]
fn a_stable_run_far_off_course_says_so_and_one_on_course_does_not() {
    for (args, large) in [
        (&["--ir1", "20", "--model", "paper"][..], true),
        (&["--delta", "0.2", "--pf", "off"][..], true),
        (&["--delta", "0.01"][..], false),
        (&["--delta", "0.05"][..], false),
    ] {
        let run = simulate(args);
        assert_eq!(run["verdict"], "stable", "{args:?}: {}", run["detail"]);
        let (link, error, share) = worst_share(&run);
        assert_eq!(share > LARGE_ERROR_FRACTION, large, "{args:?}: {share}");
        let detail = run["detail"].as_str().unwrap();
        assert_eq!(detail.contains("but the tracking error reaches"), large, "{args:?}: {detail}");
        if large {
            let said = format!(
                "reaches {} rad on link {}, {:.0} % of its",
                flexarm::plot::format::significant_trimmed(error, 2),
                link + 1,
                100.0 * share
            );
            assert!(detail.contains(&said), "{args:?}: {detail} should say {said}");
            // The page's status, from the same state, says the same.
            let state = run["state"].as_str().unwrap();
            let (mut s, _) = flexarm::session::Session::open(state);
            while s.run(0).unwrap().closed_loop().time() < 4.0 - 1e-9 {
                s.advance(0.05).unwrap();
            }
            let status = s.status();
            assert!(status.runs[0].detail.contains(&said), "page: {}", status.runs[0].detail);
        }
    }
}
