//! The data behind every figure (issue 21, `session::data`, `flexarm data`, the page's "Download
//! the data"), checked against the physics rather than against a copy of the output: the
//! eigenvalues listed are those of the Φ listed and the largest is the ρ `flexarm analyze`
//! prints; Φ is the arm over one period (e^{(A + B K_pr) δ}) for the A, B and K_pr listed; C, D
//! are the law (4.3) on A, B; A alone has the arm's own flexible pair; K_pr is the paper's; the
//! ρ(δ) curve and the maps are ρ at their δ and α; the JSON is the CSV's numbers with a unit on
//! every one; and the trace CSV names the reference and the velocities unmistakably, the
//! velocities integrating to the angles.

use std::collections::HashMap;
use std::process::{Command, Output};

use flexarm::analysis::{spectral_radius, LinearSettings, LoopModel};
use flexarm::control::{simulate, Column};
use flexarm::session::Session;
use flexarm::{PreliminaryFeedbackChoice, SimulationConfig};
use nalgebra::{Complex, DMatrix};
use serde_json::Value;

fn flexarm(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().expect("the flexarm binary runs")
}

fn stdout_of(args: &[&str]) -> String {
    let out = flexarm(args);
    assert!(out.status.success(), "flexarm {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("UTF-8")
}

fn json_of(args: &[&str]) -> Value {
    let text = stdout_of(args);
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("flexarm {args:?}: invalid JSON ({e})"))
}

/// The rows of the long table: (quantity, i, j) → (row, column, value, unit).
type Rows = HashMap<(String, usize, usize), (String, String, f64, String)>;

/// The `# ` lines (without the `# `) and the rows of a data CSV; every row has seven cells and a
/// unit, and no (quantity, i, j) comes twice.
fn parse_csv(csv: &str) -> (Vec<&str>, Rows) {
    let head: Vec<&str> = csv.lines().take_while(|l| l.starts_with('#')).map(|l| &l[2..]).collect();
    let mut lines = csv.lines().skip(head.len());
    assert_eq!(lines.next(), Some("quantity,i,j,row,column,value,unit"));
    let mut rows = Rows::new();
    for line in lines {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 7, "{line}");
        assert!(!f[6].is_empty(), "a row without its unit: {line}");
        let value: f64 = f[5].parse().unwrap_or_else(|_| panic!("{line}"));
        let key = (f[0].to_string(), f[1].parse().unwrap(), f[2].parse().unwrap());
        let old = rows.insert(key, (f[3].to_string(), f[4].to_string(), value, f[6].to_string()));
        assert!(old.is_none(), "a repeated row: {line}");
    }
    (head, rows)
}

/// One quantity of the table: its values, names and units.
struct Table {
    rows: Vec<String>,
    columns: Vec<String>,
    values: DMatrix<f64>,
    units: Vec<Vec<String>>,
}

fn table(rows: &Rows, quantity: &str) -> Table {
    let keys: Vec<(usize, usize)> = rows.keys().filter(|k| k.0 == quantity).map(|k| (k.1, k.2)).collect();
    assert!(!keys.is_empty(), "no {quantity} in the table");
    let n = keys.iter().map(|k| k.0).max().unwrap() + 1;
    let m = keys.iter().map(|k| k.1).max().unwrap() + 1;
    assert_eq!(keys.len(), n * m, "{quantity} is not a full {n} × {m} table");
    let at = |i: usize, j: usize| &rows[&(quantity.to_string(), i, j)];
    Table {
        rows: (0..n).map(|i| at(i, 0).0.clone()).collect(),
        columns: (0..m).map(|j| at(0, j).1.clone()).collect(),
        values: DMatrix::from_fn(n, m, |i, j| at(i, j).2),
        units: (0..n).map(|i| (0..m).map(|j| at(i, j).3.clone()).collect()).collect(),
    }
}

/// A named entry of a one-column table (`controller`, `loop`, `arm`).
fn named(rows: &Rows, quantity: &str, name: &str) -> (f64, String) {
    let (_, (_, _, v, u)) =
        rows.iter().find(|(k, r)| k.0 == quantity && r.0 == name).unwrap_or_else(|| panic!("no {quantity} {name}"));
    (*v, u.clone())
}

/// The data the page gives for `query` (no maps computed yet): the session, the head, the rows.
fn page_data(query: &str) -> (Session, String) {
    let (session, notices) = Session::open(query);
    assert!(notices.is_empty(), "{notices:?}");
    let csv = session.figure_data_csv().unwrap();
    (session, csv)
}

fn eigenvalues(m: &DMatrix<f64>) -> Vec<Complex<f64>> {
    m.clone().complex_eigenvalues().iter().copied().collect()
}

fn config(delta: f64, alpha: f64, pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    let mut c = SimulationConfig { preliminary_feedback: pf, ..Default::default() };
    c.controller.sampling_period = delta;
    c.controller.alpha = [alpha, alpha];
    c
}

const STATES: [&str; 4] = [
    "delta=0.01&alpha=2&pf=off",
    "delta=0.01&alpha=2&pf=paper",
    "delta=0.05&alpha=1&pf=lq&inner=sampled",
    "delta=0.02&alpha=2&pf=off&ir1=3&model=paper",
];

#[test]
fn the_eigenvalues_listed_are_those_of_phi_and_the_largest_is_the_rho_analyze_prints() {
    for state in STATES {
        let (_, csv) = page_data(state);
        let (head, rows) = parse_csv(&csv);
        let phi = table(&rows, "Phi");
        let delta = named(&rows, "controller", "delta").0;
        let ours = eigenvalues(&phi.values);
        let listed = table(&rows, "eigenvalues");
        assert_eq!(listed.values.nrows(), 10, "{state}");
        assert_eq!(listed.columns, ["re", "im", "abs", "s_re", "s_im"]);
        assert_eq!(listed.units[0], ["1", "1", "1", "1/s", "1/s"]);
        for e in listed.values.row_iter() {
            let (re, im, abs, s_re, s_im) = (e[0], e[1], e[2], e[3], e[4]);
            let nearest = ours.iter().map(|l| (l - Complex::new(re, im)).norm()).fold(f64::INFINITY, f64::min);
            assert!(nearest < 1e-9, "{state}: λ = {re} + {im}j is no eigenvalue of the Φ listed ({nearest:e})");
            assert!((abs - re.hypot(im)).abs() < 1e-15);
            // s = ln λ / δ: e^{sδ} gives λ back (no s for λ = 0).
            if abs > 0.0 {
                let back = (Complex::new(s_re, s_im) * delta).exp();
                assert!((back - Complex::new(re, im)).norm() < 1e-12, "{state}");
            } else {
                assert!(s_re.is_nan() && s_im.is_nan());
            }
        }
        let rho = ours.iter().map(|l| l.norm()).fold(0.0, f64::max);
        let (listed_rho, unit) = named(&rows, "loop", "spectral_radius");
        assert!((rho - listed_rho).abs() < 1e-9 * rho, "{state}: {rho} vs {listed_rho}");
        assert_eq!(unit, "1");
        assert!((named(&rows, "loop", "growth_rate").0 - rho.ln() / delta).abs() < 1e-6);

        // The ρ `flexarm analyze` prints for the state the data names.
        let full_state = head[1].strip_prefix("flexarm state: ").expect("the state string");
        let analyzed = json_of(&["analyze", "--json", "--state", full_state]);
        let printed = analyzed["spectral_radius"].as_f64().unwrap();
        assert!((printed - listed_rho).abs() < 1e-12, "{state}: analyze says {printed}");
        assert_eq!(analyzed["state"].as_str().unwrap(), full_state);
    }
}

#[test]
fn phi_is_the_arm_over_one_period_for_the_a_b_and_k_pr_listed() {
    for state in STATES {
        let (session, csv) = page_data(state);
        let (_, rows) = parse_csv(&csv);
        let (a, b, k) = (table(&rows, "A").values, table(&rows, "B").values, table(&rows, "K_pr").values);
        let delta = named(&rows, "controller", "delta").0;
        let sampled = session.settings().a.inner.name() == "sampled";
        // [[A + B K, B], [0, 0]] δ, exponentiated: the arm and the held v over one period.
        let mut aug = DMatrix::zeros(10, 10);
        let a_plant = if sampled { a.clone() } else { &a + &b * &k };
        aug.view_mut((0, 0), (8, 8)).copy_from(&(a_plant * delta));
        aug.view_mut((0, 8), (8, 2)).copy_from(&(&b * delta));
        let t = aug.exp();
        let phi = table(&rows, "Phi");
        assert_eq!(&phi.rows[8..], ["v1", "v2"]);
        let phi = phi.values;
        let mut expected = t.view((0, 0), (8, 10)).into_owned();
        if sampled {
            // K_pr x(t_n) held over the period, like v.
            let held = t.view((0, 8), (8, 2)) * &k;
            let mut block = expected.view_mut((0, 0), (8, 8));
            block += held;
        }
        let scale = expected.amax();
        let gap = (phi.view((0, 0), (8, 10)) - &expected).amax();
        assert!(gap < 1e-9 * scale, "{state}: Φ differs from e^((A + B K_pr) δ) by {gap:e} of {scale:e}");
        // The predictor sees only the links: no gain on θ, θ̇ and none on the held v.
        for r in 8..10 {
            for c in [2, 5, 8, 9] {
                assert!(phi[(r, c)].abs() < 1e-8 * phi.row(r).amax(), "{state}: Φ[{r}][{c}] = {}", phi[(r, c)]);
            }
        }
    }
}

#[test]
fn c_and_d_are_the_stabilized_law_on_a_and_b_and_every_entry_has_its_unit() {
    let (_, csv) = page_data("delta=0.01&alpha1=1.5&alpha2=3&pf=off");
    let (_, rows) = parse_csv(&csv);
    let (a, b, c, d) = (table(&rows, "A"), table(&rows, "B"), table(&rows, "C"), table(&rows, "D"));
    for (i, alpha) in [1.5_f64, 3.0].into_iter().enumerate() {
        // y_i = q̈_i + 3α_i q̇_i + 3α_i² q_i + w_i, with q̈_i the row 3 + i of (A, B).
        for j in 0..8 {
            let law = match j {
                _ if j == i => 3.0 * alpha * alpha,
                _ if j == 3 + i => 3.0 * alpha,
                _ if j == 6 + i => 1.0,
                _ => 0.0,
            };
            assert!((c.values[(i, j)] - a.values[(3 + i, j)] - law).abs() < 1e-12, "C[{i}][{j}]");
        }
        assert_eq!(d.values.row(i), b.values.row(3 + i));
        // The integrators: dw_i/dt = α_i³ q_i.
        assert!((a.values[(6 + i, i)] - alpha.powi(3)).abs() < 1e-12);
    }
    assert_eq!(a.rows, ["q1", "q2", "theta", "q1_dot", "q2_dot", "theta_dot", "w1", "w2"]);
    assert_eq!((a.units[3][0].as_str(), a.units[0][3].as_str(), a.units[6][0].as_str()), ("1/s²", "1", "1/s³"));
    assert_eq!(b.units[3][0], "rad/(N m s²)");
    assert_eq!(c.units[0][6], "1");
    let phi = table(&rows, "Phi");
    assert_eq!(
        (phi.units[8][0].as_str(), phi.units[0][8].as_str(), phi.units[8][8].as_str()),
        ("N m/rad", "rad/(N m)", "1")
    );
}

#[test]
fn a_alone_has_the_arms_own_flexible_pair_and_the_integrators_zeros() {
    let (_, csv) = page_data("delta=0.01&alpha=2&pf=off");
    let (_, rows) = parse_csv(&csv);
    let ev = eigenvalues(&table(&rows, "A").values);
    // The paper's arm, without torque and with the friction cancelled: −0.29 ± 29.36j 1/s.
    let pair = ev.iter().find(|l| l.im > 1.0).expect("a swinging pair");
    assert!((pair.re - -0.29).abs() < 0.01 && (pair.im - 29.36).abs() < 0.01, "{pair}");
    assert!(ev.iter().any(|l| (l - pair.conj()).norm() < 1e-9));
    // Four zeros (defective: a solver finds them ≈ 1e-7 apart): the integrators w1, w2 and the
    // free rotations of link 2 and of link 1 with the motor; their speeds decay.
    assert_eq!(ev.iter().filter(|l| l.norm() < 1e-5).count(), 4, "{ev:?}");
    assert_eq!(ev.iter().filter(|l| l.im == 0.0 && l.re < -0.1).count(), 2, "{ev:?}");
}

#[test]
fn k_pr_is_the_papers_gain_and_zero_without_it() {
    let (_, csv) = page_data("delta=0.01&alpha=2&pf=paper");
    let (head, rows) = parse_csv(&csv);
    // Section 4 of the paper: u = K_pr x on x = (q1, q2, θ, q̇1, q̇2, θ̇, w1, w2).
    let printed = DMatrix::from_row_slice(
        2,
        8,
        &[
            102.3, -0.07, -103.0, 15.97, -0.10, -17.0, 0.0, 0.0, //
            16.17, -0.01, -16.3, 2.55, -0.02, -2.71, 0.0, 0.0,
        ],
    );
    let k = table(&rows, "K_pr");
    assert_eq!(k.values, printed);
    assert_eq!(k.rows, ["T1", "T2"]);
    assert_eq!(k.columns, ["q1", "q2", "theta", "q1_dot", "q2_dot", "theta_dot", "w1", "w2"]);
    assert_eq!(
        (k.units[0][0].as_str(), k.units[0][3].as_str(), k.units[1][7].as_str()),
        ("N m/rad", "N m s/rad", "N m s²/rad")
    );
    assert!(head[2].starts_with("preliminary feedback paper, inner loop continuous"), "{}", head[2]);
    let (_, csv) = page_data("delta=0.01&alpha=2&pf=off");
    assert!(table(&parse_csv(&csv).1, "K_pr").values.iter().all(|v| *v == 0.0));
    // The model: the arm's table with units, α, δ, k, ε.
    assert_eq!(named(&rows, "controller", "delta"), (0.01, "s".into()));
    assert_eq!(named(&rows, "controller", "alpha1"), (2.0, "1/s".into()));
    assert_eq!(named(&rows, "controller", "k").0, 12.0);
    assert_eq!(named(&rows, "controller", "eps"), (0.01 / 8.0, "s".into()));
    assert_eq!(named(&rows, "arm", "k1"), (1152.6, "N m/rad".into()));
    assert!(!rows.keys().any(|k| k.0 == "controller_arm"));
    // With a model error, the arm the controller assumes too.
    let (_, csv) = page_data("delta=0.01&alpha=2&pf=off&ir1=3&model=paper");
    let (head, rows) = parse_csv(&csv);
    assert_eq!(named(&rows, "arm", "ir1").0, 3.0);
    assert_eq!(named(&rows, "controller_arm", "ir1"), (1.939, "kg m²".into()));
    assert!(head[2].contains("the controller assumes the paper's arm"), "{}", head[2]);
}

#[test]
fn the_rho_curve_and_the_maps_are_rho_at_their_delta_and_alpha() {
    let (mut session, csv) = page_data("delta=0.01&alpha=2&pf=off&mode=full");
    let c = session.settings().a.config();
    let at = |delta: f64| {
        let mut c = c;
        c.controller.sampling_period = delta;
        c
    };
    let (head, rows) = parse_csv(&csv);
    let curve = table(&rows, "rho_curve");
    assert_eq!(curve.columns, ["delta", "rho"]);
    assert_eq!(curve.units[0], ["s", "1"]);
    assert!(curve.values.nrows() >= 100);
    for (i, p) in curve.values.row_iter().enumerate().step_by(7) {
        let direct = spectral_radius(&at(p[0]), None).unwrap();
        assert!((direct - p[1]).abs() < 1e-12 * direct, "ρ(δ = {}) = {direct} but the curve has {} at {i}", p[0], p[1]);
    }
    // Without K_pr at α = 2 the loop is stable only in windows of larger δ (section 4).
    let windows = table(&rows, "stable_windows").values;
    assert!(windows[(0, 0)] > 0.02, "{windows}");
    for w in windows.row_iter() {
        assert!(spectral_radius(&at((w[0] * w[1]).sqrt()), None).unwrap() < 1.0);
    }

    // The page's maps before any work: the grid, no cells, and said to be unfinished.
    assert_eq!(table(&rows, "map_delta").values.nrows(), 100);
    assert_eq!(table(&rows, "map_alpha").values.nrows(), 60);
    assert!(!rows.keys().any(|k| k.0.starts_with("map_o")));
    assert!(head.iter().any(|l| l.starts_with("omitted: ") && l.contains("0 of 60 rows")), "{head:?}");
    // Some rows computed: as far as computed, each cell ρ at its (δ, α), the right map with the
    // paper's K_pr.
    let mut clock = 0.0;
    session.maps_mut().work(
        &mut || {
            clock += 1.0;
            clock
        },
        2.5,
    );
    let (_, rows) = parse_csv(&session.figure_data_csv().unwrap());
    let map = table(&rows, "map_off");
    let (deltas, alphas) = (table(&rows, "map_delta").values, table(&rows, "map_alpha").values);
    assert!(map.values.nrows() >= 1 && map.values.ncols() == 100);
    assert!(!rows.keys().any(|k| k.0 == "map_on"), "the right map waits for the left");
    let settings = LinearSettings::of(&c, None).with_feedback(PreliminaryFeedbackChoice::Off);
    for i in 0..map.values.nrows() {
        let alpha = alphas[(i, 0)];
        assert_eq!(map.rows[i].parse::<f64>().unwrap(), alpha);
        let model = LoopModel::new(&settings.at(0.01, [alpha, alpha])).unwrap();
        for j in [0, 37, 99] {
            assert_eq!(map.columns[j].parse::<f64>().unwrap(), deltas[(j, 0)]);
            let direct = model.spectral_radius(deltas[(j, 0)]).unwrap();
            assert!((map.values[(i, j)] - direct).abs() < 1e-12, "map at α = {alpha}, δ = {}", deltas[(j, 0)]);
        }
    }
}

/// JSON's number (null for a non-finite one). Both are written in the shortest form that reads
/// back exactly; serde_json's reader (without its `float_roundtrip` feature) may miss by an ulp.
fn same(csv: f64, json: &Value, what: &str) {
    match json.as_f64() {
        Some(v) => assert!(csv.to_bits().abs_diff(v.to_bits()) <= 1, "{what}: CSV {csv:e}, JSON {v:e}"),
        None => assert!(json.is_null() && !csv.is_finite(), "{what}: CSV {csv}, JSON {json}"),
    }
}

#[test]
fn the_json_is_the_csvs_numbers_with_their_names_and_units() {
    let state = "delta=0.01&alpha=2&pf=paper";
    let json = json_of(&["data", "--state", state]);
    let csv = stdout_of(&["data", "--csv", "--state", state]);
    let (head, rows) = parse_csv(&csv);
    let full_state = json["state"].as_str().unwrap();
    assert!(full_state.starts_with(state), "{full_state}");
    assert_eq!(json["head"].as_array().unwrap().iter().map(|l| l.as_str().unwrap()).collect::<Vec<_>>(), head);
    assert_eq!(head[1], format!("flexarm state: {full_state}"));
    let mut counted = 0;
    for (quantity, t) in json["quantities"].as_object().unwrap() {
        let (names, columns) = (t["rows"].as_array().unwrap(), t["columns"].as_array().unwrap());
        for (i, values) in t["values"].as_array().unwrap().iter().enumerate() {
            let values = values.as_array().unwrap();
            assert_eq!(values.len(), columns.len(), "{quantity}: a full table");
            for (j, v) in values.iter().enumerate() {
                let (row, column, value, unit) =
                    rows.get(&(quantity.clone(), i, j)).unwrap_or_else(|| panic!("the CSV lacks {quantity}[{i}][{j}]"));
                same(*value, v, &format!("{quantity}[{i}][{j}]"));
                assert_eq!((row.as_str(), column.as_str()), (names[i].as_str().unwrap(), columns[j].as_str().unwrap()));
                assert_eq!(unit, t["units"][i][j].as_str().unwrap(), "{quantity}[{i}][{j}]");
                counted += 1;
            }
        }
    }
    assert_eq!(counted, rows.len(), "every row of the CSV is in the JSON");
    // The CLI computes both maps on the page's grid, and leaves nothing out.
    for name in ["map_off", "map_on"] {
        assert_eq!(json["quantities"][name]["values"].as_array().unwrap().len(), 60);
        assert_eq!(json["quantities"][name]["columns"].as_array().unwrap().len(), 100);
    }
    assert!(!head.iter().any(|l| l.starts_with("omitted")));
    let phi = &json["quantities"]["Phi"];
    assert_eq!(phi["rows"][9], "v2");
    assert_eq!(phi["units"][0][8], "rad/(N m)");
}

#[test]
fn every_csv_header_has_the_state_string_and_units() {
    let (mut session, csv) = page_data("delta=0.02&alpha=1.5&pf=lq");
    let run_query = session.settings().run_query();
    // The data's CSV.
    let (head, rows) = parse_csv(&csv);
    assert_eq!(head[1], format!("flexarm state: {run_query}"));
    for unit in ["[rad]", "[rad/s]", "[rad/s^2]", "[N m]", "[1/s]"] {
        assert!(head.iter().any(|l| l.contains(unit)), "the head names no {unit}: {head:?}");
    }
    assert!(rows.values().all(|(_, _, _, unit)| !unit.is_empty()));
    // The trace CSV: the state string, what the columns are, each header cell with its unit.
    session.advance(0.2).unwrap();
    let traces = session.csv();
    let mut lines = traces.lines();
    assert!(lines.next().unwrap().starts_with(&format!("# flexarm state: {run_query}")));
    assert!(lines.next().unwrap().starts_with("# columns: t time;"));
    let header = lines.next().unwrap();
    for cell in header.split(',') {
        assert!(cell.ends_with(']') && cell.contains(" ["), "a header cell without its unit: {cell}");
    }
}

#[test]
fn the_trace_csv_names_the_reference_and_has_velocities_that_integrate_to_the_angles() {
    let (mut session, _) = page_data("delta=0.01&alpha=2&pf=paper");
    session.advance(0.1).unwrap();
    let csv = session.csv();
    let header = csv.lines().find(|l| !l.starts_with('#')).unwrap();
    let cells: Vec<&str> = header.split(',').collect();
    let expected = [
        "t [s]",
        "q1 [rad]",
        "q2 [rad]",
        "theta [rad]",
        "q1_dot [rad/s]",
        "q2_dot [rad/s]",
        "theta_dot [rad/s]",
        "q1_ref [rad]",
        "q2_ref [rad]",
        "e1 [rad]",
    ];
    assert_eq!(&cells[..10], expected);
    assert!(!header.contains("qd1") && !header.contains("qd2"), "{header}");
    let comment = csv.lines().nth(1).unwrap();
    for words in
        ["q1_ref, q2_ref the reference slew", "e = q - q_ref", "T1, T2 the applied torques", "v1, v2", "xf1_hat"]
    {
        assert!(comment.contains(words), "the columns' line lacks {words:?}: {comment}");
    }
    assert_eq!(Column::from_key("q1_dot"), Some(Column::Q1Dot));
    assert_eq!(Column::from_key("qd1"), None);

    // During the slew the velocities, integrated (trapezoid), give the angles' change.
    let report = simulate(&config(0.01, 2.0, PreliminaryFeedbackChoice::Paper), 2.0).unwrap();
    let tr = &report.traces;
    let t = tr.t();
    for (q, qdot) in [(tr.q1(), tr.q1_dot()), (tr.q2(), tr.q2_dot()), (tr.theta(), tr.theta_dot())] {
        let travel = q.iter().map(|v| (v - q[0]).abs()).fold(0.0, f64::max);
        assert!(travel > 0.1, "the arm moves: {travel}");
        let mut integral = 0.0;
        let mut worst: f64 = 0.0;
        for i in 1..t.len() {
            integral += 0.5 * (qdot[i] + qdot[i - 1]) * (t[i] - t[i - 1]);
            worst = worst.max((integral - (q[i] - q[0])).abs());
        }
        assert!(worst < 1e-3 * travel, "∫ q̇ dt strays {worst:e} rad from q (travel {travel})");
    }
    // And the reference columns are the reference: e = q − q_ref.
    for i in (0..t.len()).step_by(50) {
        assert!((tr.e1()[i] - (tr.q1()[i] - tr.q1_ref()[i])).abs() < 1e-12);
    }
}

#[test]
fn the_data_command_writes_files_leaves_maps_out_when_asked_and_refuses_two_formats() {
    let path = std::env::temp_dir().join(format!("flexarm-data-{}.json", std::process::id()));
    let p = path.to_str().unwrap();
    let said = stdout_of(&["data", "--no-maps", "--delta", "0.02", "--pf", "off", "--output", p]);
    assert!(said.contains(p), "{said}");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    std::fs::remove_file(&path).ok();
    let q = &v["quantities"];
    assert!(q.get("map_off").is_none() && q.get("map_delta").is_none());
    assert!(v["head"].as_array().unwrap().iter().any(|l| l.as_str().unwrap().contains("--no-maps")));
    assert_eq!(q["controller"]["rows"][2], "delta");
    assert_eq!(q["controller"]["values"][2][0], 0.02);
    // --q2 moves the rest point as in `analyze`.
    let moved = json_of(&["data", "--no-maps", "--q2", "1"]);
    assert_eq!(moved["quantities"]["controller"]["values"][8][0], 1.0);
    let analyzed = json_of(&["analyze", "--json", "--q2", "1"]);
    assert_eq!(moved["quantities"]["loop"]["values"][0][0], analyzed["spectral_radius"]);

    let out = flexarm(&["data", "--json", "--csv"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("error: --json and --csv"));
    let out = flexarm(&["data", "--no-maps", "--output", "/nonexistent-dir/x.json"]);
    assert_eq!(out.status.code(), Some(2));
}
