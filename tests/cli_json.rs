//! The commands' JSON (issue 34): one key per setting, the schema's, in every command's JSON
//! (`analyze`, `simulate`, `sweep`, `map`); and `analyze --json` exports the δ → 0 pair's block A4
//! and its input matrix B4, so that a design can target the pair.

use std::process::Command;

use flexarm::schema;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().unwrap();
    assert!(out.status.success(), "flexarm {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("flexarm {args:?}: not JSON ({e})"))
}

/// Names earlier versions wrote for a setting beside (or instead of) its schema key.
const ALIASES: [&str; 6] =
    ["sampling_period", "preliminary_feedback", "inner_loop", "friction_compensation", "analysis_rest_q2", "alpha"];

/// Settings away from their defaults, as flags, and what the JSON must say of each.
const SET: [(&str, &str); 6] =
    [("delta", "0.02"), ("alpha1", "1"), ("alpha2", "1.5"), ("pf", "off"), ("k", "14"), ("eps_ratio", "10")];

/// Each setting in `keys` is in `v` under its schema key with the value set (numbers compared as
/// numbers); none under an alias; the arm's parameters under the schema's keys, in `arm` and
/// only there.
fn check(v: &Value, keys: &[&str], what: &str) {
    let object = v.as_object().unwrap_or_else(|| panic!("{what}: not an object: {v}"));
    for alias in ALIASES {
        assert!(!object.contains_key(alias), "{what}: '{alias}' is not the schema's key: {v}");
    }
    for (key, value) in SET.iter().filter(|(k, _)| keys.contains(k)) {
        let written = &object.get(*key).unwrap_or_else(|| panic!("{what}: no '{key}' in {v}"));
        match written.as_f64() {
            Some(x) => assert_eq!(x, value.parse::<f64>().unwrap(), "{what}: {key}"),
            None => assert_eq!(written.as_str(), Some(*value), "{what}: {key}"),
        }
    }
    let arm = object.get("arm").and_then(Value::as_object).unwrap_or_else(|| panic!("{what}: no arm: {v}"));
    let arm_keys: Vec<&str> = schema::ARM_PARAMS.iter().map(|p| p.key).collect();
    assert_eq!(arm.keys().map(String::as_str).collect::<Vec<_>>().len(), arm_keys.len(), "{what}");
    for key in arm.keys() {
        assert!(arm_keys.contains(&key.as_str()), "{what}: arm's '{key}'");
        assert!(!object.contains_key(key), "{what}: '{key}' twice, at the top and in arm");
    }
}

#[test]
fn every_commands_json_writes_each_setting_once_under_the_schema_key() {
    let flags: Vec<String> =
        SET.iter().flat_map(|(k, v)| [format!("--{}", k.replace('_', "-")), v.to_string()]).collect();
    let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
    let all: Vec<&str> = SET.iter().map(|(k, _)| *k).collect();

    let analyze = json(&[&["analyze", "--json"][..], &flags].concat());
    check(&analyze, &all, "analyze");
    assert_eq!(analyze["q2"], 0.0, "the analysis's rest angle under the schema's key q2");

    let simulate = json(&[&["simulate", "--json", "--duration", "0.5"][..], &flags].concat());
    check(&simulate, &all, "simulate");
    // Every run setting, each once: a run's JSON says all it was run with.
    for p in schema::PARAMS.iter().filter(|p| p.scope == schema::Scope::Run && !schema::is_arm(p.key)) {
        assert!(p.key == "alpha" || simulate.get(p.key).is_some(), "simulate: no '{}'", p.key);
    }
    assert_eq!(simulate["duration"], 0.5);

    let rows = json(&[
        "sweep",
        "--delta",
        "0.02",
        "--alpha",
        "1",
        "--pf",
        "off",
        "--k",
        "14",
        "--eps-ratio",
        "10",
        "--simulate",
        "--duration",
        "0.5",
        "--json",
    ]);
    let row = &rows[0];
    check(row, &["delta", "pf", "k", "eps_ratio"], "sweep");
    assert_eq!((row["alpha1"].as_f64(), row["alpha2"].as_f64()), (Some(1.0), Some(1.0)), "sweep: α = α1 = α2");
    check(&row["simulation"], &["delta", "pf", "k", "eps_ratio"], "sweep --simulate");

    let maps =
        json(&["map", "--n-delta", "2", "--n-alpha", "2", "--pf", "off", "--k", "14", "--eps-ratio", "10", "--json"]);
    check(&maps["off"], &["pf", "k", "eps_ratio"], "map");
}

/// The two roots of λ² − tr λ + det of a 2×2 matrix's rows, the upper one first (re, im).
fn eigenvalues(m: &Value) -> [[f64; 2]; 2] {
    let a = |i: usize, j: usize| m[i][j].as_f64().unwrap();
    let (tr, det) = (a(0, 0) + a(1, 1), a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0));
    let disc = tr * tr / 4.0 - det;
    if disc < 0.0 {
        [[tr / 2.0, (-disc).sqrt()], [tr / 2.0, -(-disc).sqrt()]]
    } else {
        [[tr / 2.0 + disc.sqrt(), 0.0], [tr / 2.0 - disc.sqrt(), 0.0]]
    }
}

fn pair(v: &Value) -> [f64; 2] {
    [v[0][0].as_f64().unwrap(), v[0][1].as_f64().unwrap().abs()]
}

fn near(a: [f64; 2], b: [f64; 2], what: &str) {
    let scale = a[0].hypot(a[1]);
    assert!((a[0] - b[0]).abs() < 1e-6 * scale && (a[1] - b[1]).abs() < 1e-6 * scale, "{what}: {a:?} vs {b:?}");
}

/// A4's eigenvalues are the pair `analyze` prints (without and with the preliminary feedback), and
/// B4 is the closed form of `analysis::resonance` written out here from the arm's parameters:
/// B4 = [[0, κ], [1/Ir1, λ]], κ = 3 M11 M12 (α2 − α1)/(A2 J_eff K1), λ = M12/(A2 J_eff) −
/// 6 M11 M12 (α2² − α1²)/(A2 J_eff K1), M11 = A1 + 2 A3 cos q2, M12 = A2 + A3 cos q2, J_eff = A1 −
/// A2 − (A3²/A2) cos² q2. A twist damper (ΔT1 = −k_p z − k_d y) makes the pair A4 + B4 K.
#[test]
fn analyze_exports_a4_and_its_input_matrix() {
    let cases: [&[&str]; 5] = [
        &["--pf", "off"],
        &["--pf", "paper"],
        &["--pf", "paper", "--alpha1", "2", "--alpha2", "1", "--q2", "0.7"],
        &["--pf", "twist", "--twist-stiffness", "50", "--twist-damping", "20", "--alpha1", "0.5", "--alpha2", "3"],
        &["--pf", "off", "--ir1", "1", "--k1", "3000", "--q2", "2"],
    ];
    for case in cases {
        let v = json(&[&["analyze", "--json"][..], case].concat());
        let r = &v["resonance"];
        near(eigenvalues(&r["a4"])[0], pair(&v["limit_pair_open"]), &format!("{case:?}: A4 without feedback"));
        near(eigenvalues(&r["a4_with_feedback"])[0], pair(&v["limit_pair"]), &format!("{case:?}: A4 with feedback"));

        let n = |key: &str| v[key].as_f64().unwrap();
        let arm = |key: &str| v["arm"][key].as_f64().unwrap();
        let (a1, a2, a3, ir1, k1) = (arm("a1"), arm("a2"), arm("a3"), arm("ir1"), arm("k1"));
        let (al1, al2, c) = (n("alpha1"), n("alpha2"), n("q2").cos());
        let (m11, m12) = (a1 + 2.0 * a3 * c, a2 + a3 * c);
        let j_eff = a1 - a2 - a3 * a3 / a2 * c * c;
        let kappa = 3.0 * m11 * m12 * (al2 - al1) / (a2 * j_eff * k1);
        let lambda = m12 / (a2 * j_eff) - 6.0 * m11 * m12 * (al2 * al2 - al1 * al1) / (a2 * j_eff * k1);
        let b = &r["a4_input"];
        let b = |i: usize, j: usize| b[i][j].as_f64().unwrap();
        for (got, want) in [(b(0, 0), 0.0), (b(0, 1), kappa), (b(1, 0), 1.0 / ir1), (b(1, 1), lambda)] {
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1e-3), "{case:?}: B4 {got} vs {want}");
        }
        if v["pf"] == "twist" {
            let (kp, kd) = (n("twist_stiffness"), n("twist_damping"));
            let a = |i: usize, j: usize| r["a4"][i][j].as_f64().unwrap();
            let made =
                [[a(0, 0) - b(0, 0) * kp, a(0, 1) - b(0, 0) * kd], [a(1, 0) - b(1, 0) * kp, a(1, 1) - b(1, 0) * kd]];
            for (i, row) in made.iter().enumerate() {
                for (j, x) in row.iter().enumerate() {
                    let got = r["a4_with_feedback"][i][j].as_f64().unwrap();
                    assert!((got - x).abs() < 1e-9 * x.abs().max(1.0), "{case:?}: A4 + B4 K [{i}][{j}] {got} vs {x}");
                }
            }
        }
    }
}
