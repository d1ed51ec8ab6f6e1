//! What the controller read, recorded beside the truth (issue 36, "in the run"): the measured
//! errors e1_meas, e2_meas = m_n − q_d(t_n), held from the sampling instant t_n over its period,
//! and the velocity estimates ν_n. Checked against the physics of the sensors, not against the
//! program's own output: an encoder reads within half a count of the true angle at t_n; the
//! backward difference is (m_n − m_{n−1})/δ; with the sensors off the controller reads the truth.

use flexarm::control::sensing::{SensorModel, VelocitySource};
use flexarm::control::{simulate, Column, SimulationConfig, Traces};

const DELTA: f64 = 0.01;

fn config(sensors: SensorModel) -> SimulationConfig {
    let mut c = SimulationConfig { sensors, ..Default::default() };
    c.controller.sampling_period = DELTA;
    // A row at every plant step (1 ms): several rows in each period, one at each instant.
    c.output_interval = 1e-3;
    c
}

/// For each row, the index of the row at the sampling instant whose reading the row holds (the
/// last instant before the row's time: a row at an instant was recorded before that instant's
/// reading), and that instant's number n.
fn held_instants(traces: &Traces) -> Vec<Option<(usize, i64)>> {
    let t = traces.t();
    let at_instant = |time: f64| {
        let n = (time / DELTA).round();
        ((time - n * DELTA).abs() < 1e-9).then_some(n as i64)
    };
    let mut row_of_instant = std::collections::HashMap::new();
    for (i, &time) in t.iter().enumerate() {
        if let Some(n) = at_instant(time) {
            row_of_instant.insert(n, i);
        }
    }
    t.iter()
        .map(|&time| {
            let n = match at_instant(time) {
                Some(n) => n - 1,
                None => (time / DELTA).floor() as i64,
            };
            row_of_instant.get(&n).map(|&i| (i, n))
        })
        .collect()
}

#[test]
fn an_encoders_measured_error_is_within_half_a_count_of_the_true_error_at_the_sampling_instant() {
    for counts in [256.0, 2048.0] {
        let sensors = SensorModel { encoder_counts: counts, ..SensorModel::default() };
        let traces = simulate(&config(sensors), 2.0).unwrap().traces;
        let half = 0.5 * std::f64::consts::TAU / counts;
        let held = held_instants(&traces);
        let mut checked = 0;
        let mut differs = 0;
        for (true_error, measured) in [(Column::E1, Column::E1Meas), (Column::E2, Column::E2Meas)] {
            let (e, m) = (traces.column(true_error), traces.column(measured));
            for (i, h) in held.iter().enumerate() {
                let Some((at, _)) = *h else { continue };
                let gap = (m[i] - e[at]).abs();
                assert!(
                    gap <= half * (1.0 + 1e-9),
                    "N = {counts}, t = {}: |e_meas − e(t_n)| = {gap} > {half}",
                    traces.t()[i]
                );
                // Between instants the true error moves on; the measured one stays where it was read.
                if m[i] != e[i] {
                    differs += 1;
                }
                checked += 1;
            }
        }
        assert!(checked > 3000, "{checked}");
        assert!(differs > checked / 2, "the reading is not the truth: {differs} of {checked}");
    }
}

#[test]
fn with_the_sensors_off_the_measured_columns_are_the_true_ones_bit_for_bit() {
    let traces = simulate(&config(SensorModel::default()), 2.0).unwrap().traces;
    assert!(traces.len() > 1000);
    for (truth, read) in [
        (Column::E1, Column::E1Meas),
        (Column::E2, Column::E2Meas),
        (Column::Q1Dot, Column::Q1DotEst),
        (Column::Q2Dot, Column::Q2DotEst),
        (Column::ThetaDot, Column::ThetaDotEst),
    ] {
        let (a, b) = (traces.column(truth), traces.column(read));
        assert!(a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits()), "{read:?} differs from {truth:?}");
    }
    // A torque limit alone leaves the controller reading the truth.
    let limited = SensorModel { torque_limit: 50.0, ..SensorModel::default() };
    let traces = simulate(&config(limited), 1.0).unwrap().traces;
    assert_eq!(traces.e1(), traces.e1_meas());
    assert_eq!(traces.q2_dot(), traces.q2_dot_est());
}

#[test]
fn the_differenced_velocity_is_the_change_of_the_recorded_measured_angles_over_delta() {
    let sensors = SensorModel {
        encoder_counts: 4096.0,
        noise: 2e-4,
        velocity: VelocitySource::Difference,
        ..SensorModel::default()
    };
    let traces = simulate(&config(sensors), 2.0).unwrap().traces;
    let held = held_instants(&traces);
    // The measured angle of each link as read at instant n: m_n = e_meas + q_d(t_n).
    let mut angles = std::collections::BTreeMap::new();
    let refs = [traces.q1_ref(), traces.q2_ref()];
    let meas = [traces.e1_meas(), traces.e2_meas()];
    let est = [traces.q1_dot_est(), traces.q2_dot_est()];
    for (i, h) in held.iter().enumerate() {
        if let Some((at, n)) = *h {
            let m = [meas[0][i] + refs[0][at], meas[1][i] + refs[1][at]];
            angles.insert(n, (m, [est[0][i], est[1][i]]));
        }
    }
    let mut checked = 0;
    let mut moving = 0;
    for (n, (m, nu)) in &angles {
        let Some((m_prev, _)) = angles.get(&(n - 1)) else { continue };
        for link in 0..2 {
            let difference = (m[link] - m_prev[link]) / DELTA;
            let tol = 1e-9 * (1.0 + difference.abs());
            assert!(
                (nu[link] - difference).abs() <= tol,
                "n = {n}, link {}: ν = {} ≠ {difference}",
                link + 1,
                nu[link]
            );
            if difference.abs() > 0.1 {
                moving += 1;
            }
        }
        checked += 1;
    }
    assert!(checked > 150, "{checked}");
    assert!(moving > 20, "the slew moves the arm: {moving}");
    // The estimate is not the true velocity (noise over δ, and a period late).
    let worst = traces.q1_dot_est().iter().zip(traces.q1_dot()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(worst > 1e-3, "{worst}");
}

#[test]
fn the_csv_names_the_measured_columns_at_its_end() {
    let sensors = SensorModel { encoder_counts: 1024.0, ..SensorModel::default() };
    let traces = simulate(&config(sensors), 0.1).unwrap().traces;
    let csv = traces.to_csv(None);
    let mut lines = csv.lines();
    let columns = lines.next().unwrap();
    assert!(columns.contains("e1_meas, e2_meas the errors as the controller read them"), "{columns}");
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        header[header.len() - 5..],
        ["e1_meas [rad]", "e2_meas [rad]", "q1_dot_est [rad/s]", "q2_dot_est [rad/s]", "theta_dot_est [rad/s]"]
    );
    assert_eq!(header[..2], ["t [s]", "q1 [rad]"]);
}

// ---------------------------------------------------------------- in the view

mod common;
use common::{drawn_after, play, session};

use flexarm::plot::{palette, Color};
use flexarm::view::{PanelKind, Scene, ViewOptions};

fn drawn(query: &str) -> Scene {
    drawn_after(query, 1.5)
}

fn paints(scene: &Scene, color: Color) -> bool {
    scene.vertices().iter().any(|v| v.color == color.0)
}

fn note(scene: &Scene, kind: PanelKind) -> String {
    scene.panel_info().into_iter().find(|p| p.id == kind.id()).map(|p| p.note).unwrap_or_default()
}

fn key_texts(scene: &Scene) -> Vec<String> {
    scene.legend().iter().flat_map(|g| g.items.iter().map(move |i| format!("{}: {}", g.title, i.text))).collect()
}

#[test]
fn the_torque_limit_is_drawn_and_keyed_only_when_the_motors_have_one() {
    let limited = drawn("preset=real-encoder&mode=full&torque=1");
    let torque = limited.panel_info().into_iter().find(|p| p.id == PanelKind::Torque.id()).expect("torques shown");
    assert!(torque.note.contains("limit ±150 N m"), "{}", torque.note);
    assert!(
        torque.y_range[1] >= 150.0 && torque.y_range[0] <= -150.0,
        "the scale shows the limit: {:?}",
        torque.y_range
    );
    assert!(paints(&limited, palette::TORQUE_LIMIT));
    assert!(
        key_texts(&limited).iter().any(|t| t.starts_with("Torque limit: limit ±150 N m")),
        "{:?}",
        key_texts(&limited)
    );

    for query in ["encoder=1024&velocity=difference&mode=full&torque=1", "mode=full&torque=1"] {
        let free = drawn(query);
        assert!(!note(&free, PanelKind::Torque).contains("limit"), "{query}");
        assert!(!paints(&free, palette::TORQUE_LIMIT), "{query}");
        assert!(!key_texts(&free).iter().any(|t| t.contains("limit ±")), "{query}");
    }
    // Without the torque panel, no key to it.
    assert!(!key_texts(&drawn("preset=real-encoder&mode=full")).iter().any(|t| t.contains("limit ±")));
}

#[test]
fn the_switch_draws_the_measured_errors_only_where_the_controller_reads_sensors() {
    let on = drawn("preset=real-encoder&measured=1");
    assert!(paints(&on, palette::MEASURED1) && paints(&on, palette::MEASURED2));
    assert!(
        key_texts(&on).iter().any(|t| t.starts_with("What the controller reads: e1 as measured")),
        "{:?}",
        key_texts(&on)
    );
    assert!(note(&on, PanelKind::Error1).contains("as measured"));

    // The switch off: nothing of it.
    let off = drawn("preset=real-encoder");
    assert!(!paints(&off, palette::MEASURED1));
    assert!(!key_texts(&off).iter().any(|t| t.contains("as measured")));

    // The sensors off: the controller reads the true state; said, not drawn twice.
    let perfect = drawn("measured=1");
    assert!(!paints(&perfect, palette::MEASURED1));
    assert!(note(&perfect, PanelKind::Error1).contains("sensors off"));
    assert!(key_texts(&perfect).iter().any(|t| t.contains("reads the true state")));
}

#[test]
fn the_svg_figures_draw_what_the_canvas_draws() {
    use flexarm::view::figure::figure_svg;
    let mut s = session("preset=real-encoder&mode=full&torque=1&measured=1");
    play(&mut s, 1.0);
    let torques = figure_svg(&s, "torque", false).unwrap().svg;
    assert!(torques.contains("limit ±150 N m"), "the torque figure keys the limit");
    let errors = figure_svg(&s, "errors", false).unwrap().svg;
    assert!(errors.contains("e1 as measured"), "the error figure keys the measured errors");
    assert!(errors.contains(&palette::MEASURED1.css()), "and draws them");
    let mut plain = session("mode=full&torque=1");
    play(&mut plain, 1.0);
    assert!(!figure_svg(&plain, "torque", false).unwrap().svg.contains("limit ±"));
}

// ---------------------------------------------------------------- the velocity panel

fn velocity_panel(scene: &Scene) -> Option<flexarm::view::layout::Panel> {
    scene.layout().panel(PanelKind::Velocity).copied()
}

#[test]
fn the_velocity_panel_is_laid_out_only_with_the_switch_on_and_a_digital_controller() {
    let on = drawn("preset=real-encoder&measured=1");
    assert!(velocity_panel(&on).is_some(), "{:?}", on.layout().panels);
    let info = on.panel_info().into_iter().find(|p| p.id == PanelKind::Velocity.id()).expect("described");
    assert_eq!(info.y_label, "q̇1 [rad/s]");
    assert!(info.note.contains("as estimated"), "{}", info.note);
    assert!(paints(&on, palette::VELOCITY1) && paints(&on, palette::VELOCITY1_EST));
    assert!(
        key_texts(&on).iter().any(|t| t.starts_with("What the controller reads: q̇1 as estimated")),
        "{:?}",
        key_texts(&on)
    );
    // The switch off, or the sensors off (the controller reads the true state): the layout of
    // today, no velocity drawn or keyed.
    for query in ["preset=real-encoder", "measured=1", "mode=full&measured=1"] {
        let off = drawn(query);
        assert!(velocity_panel(&off).is_none(), "{query}");
        assert!(!paints(&off, palette::VELOCITY1_EST), "{query}");
        assert!(!key_texts(&off).iter().any(|t| t.contains("q̇1 as estimated")), "{query}");
        let plain = drawn(&query.replace("measured=1", "measured=0"));
        assert_eq!(off.layout().panels, plain.layout().panels, "{query}: the layout as without the switch");
    }
    // A phone stacks it under the errors on the run's tab.
    let mut s = session("preset=real-encoder&measured=1&mode=full");
    play(&mut s, 1.0);
    let mut phone = Scene::new(ViewOptions::default(), 390.0, 700.0, 3.0);
    phone.draw_session(&s);
    let (e2, v) =
        (phone.layout().panel(PanelKind::Error2).unwrap().rect, velocity_panel(&phone).expect("on a phone").rect);
    assert!(v.y > e2.bottom(), "below e2: {e2:?} {v:?}");
}

#[test]
fn the_velocity_estimate_is_clipped_to_its_panel_and_said_to_be() {
    const SECONDS: f64 = 1.5;
    // Differenced over 2 ms, one count of a 256-count encoder is 2π/256/0.002 ≈ 12.3 rad/s: beyond
    // the scale the slew's velocity sets (1.5 × its ≈ 4 rad/s, rounded up to 10).
    let scene = drawn_after("preset=real-encoder&delta=0.002&encoder=256&measured=1", SECONDS);
    let panel = scene.layout().to_physical(velocity_panel(&scene).expect("shown").rect);
    let estimate: Vec<_> = scene.vertices().iter().filter(|v| v.color == palette::VELOCITY1_EST.0).collect();
    assert!(!estimate.is_empty());
    for v in &estimate {
        let [x, y] = [v.position[0] as f64, v.position[1] as f64];
        // Along x the stroke may reach half its width past the window's last sample.
        assert!(x >= panel.x - 2.0 && x <= panel.right() + 2.0, "x {x} outside {panel:?}");
        assert!(y >= panel.y - 1e-3 && y <= panel.bottom() + 1e-3, "y {y} outside {panel:?}");
    }
    let info = scene.panel_info().into_iter().find(|p| p.id == PanelKind::Velocity.id()).unwrap();
    let top = estimate.iter().map(|v| v.position[1]).fold(f32::INFINITY, f32::min);
    assert!(info.note.contains("clipped"), "{} {:?} top {top} {panel:?}", info.note, info.y_range);
    // The scale is the true velocity's, not the estimate's.
    let true_max = drawn_true_max(&scene);
    assert!(info.y_range[1] <= (1.5 * true_max).max(0.2) * 2.0 + 1e-9, "{:?} for |q̇1| ≤ {true_max}", info.y_range);
}

/// The largest |q̇1| the true curve reaches on screen, in rad/s, from its vertices' extent.
fn drawn_true_max(scene: &Scene) -> f64 {
    let info = scene.panel_info().into_iter().find(|p| p.id == PanelKind::Velocity.id()).unwrap();
    let panel = scene.layout().to_physical(scene.layout().panel(PanelKind::Velocity).unwrap().rect);
    let [lo, hi] = info.y_range;
    scene
        .vertices()
        .iter()
        .filter(|v| v.color == palette::VELOCITY1.0)
        .map(|v| (hi - (v.position[1] as f64 - panel.y) / panel.h * (hi - lo)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn a_velocity_filter_bounds_the_differenced_velocitys_noise() {
    let rms = |filter: f64| {
        let sensors = SensorModel {
            encoder_counts: 1024.0,
            velocity: VelocitySource::Difference,
            velocity_filter: filter,
            ..SensorModel::default()
        };
        let mut c = SimulationConfig { sensors, ..Default::default() };
        c.controller.sampling_period = 0.002;
        c.output_interval = 1e-3;
        let traces = simulate(&c, 3.0).unwrap().traces;
        let (t, v, est) = (traces.t(), traces.column(Column::Q1Dot), traces.column(Column::Q1DotEst));
        let (mut sum, mut n) = (0.0, 0usize);
        for i in 0..t.len() {
            if (1.0..=3.0).contains(&t[i]) {
                sum += (est[i] - v[i]).powi(2);
                n += 1;
            }
        }
        assert!(n > 1000, "{n} rows in 1–3 s");
        (sum / n as f64).sqrt()
    };
    let (raw, filtered) = (rms(0.0), rms(0.02));
    // One count over δ is 2π/1024/0.002 ≈ 3.1 rad/s: the raw difference's error is of that order.
    eprintln!("rms of the estimate's error: raw {raw}, filtered {filtered}");
    assert!(raw > 0.05, "raw {raw}");
    assert!(filtered < 0.5 * raw, "filtered {filtered} vs raw {raw}");
}

#[test]
fn the_svg_figure_of_the_velocity() {
    use flexarm::view::figure::{figure_choices, figure_svg};
    let mut s = session("preset=real-encoder&mode=full&measured=1");
    play(&mut s, 1.0);
    assert!(figure_choices(&s).iter().any(|c| c.id == "velocity"));
    let svg = figure_svg(&s, "velocity", false).unwrap().svg;
    assert!(svg.contains("q̇1 as estimated"), "keyed");
    assert!(svg.contains(&palette::VELOCITY1_EST.css()) && svg.contains(&palette::VELOCITY1.css()), "drawn");
    let mut plain = session("preset=real-encoder&mode=full");
    play(&mut plain, 1.0);
    assert!(!figure_choices(&plain).iter().any(|c| c.id == "velocity"));
    assert!(figure_svg(&plain, "velocity", false).is_err());
}
