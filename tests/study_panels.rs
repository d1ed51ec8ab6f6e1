//! The sensor study drawn beside ρ(δ) (issue 36, the `study` switch): the two panels come with
//! a real robot's sensors and only then, they read out what the study's table prints for the
//! same δ (two outputs of the same facts cannot disagree), every value lies on its axis, and the
//! torque noise they draw grows as δ shrinks, as the differenced velocity's 1/δ says.

mod common;

use flexarm::schema::PanelKind;
use flexarm::session::Session;
use flexarm::view::{Scene, ViewOptions};

fn scene_of(session: &Session) -> Scene {
    let mut scene = Scene::new(ViewOptions::default(), 1920.0, 1080.0, 1.0);
    scene.draw_session(session);
    scene.draw_session(session);
    scene
}

fn kinds(scene: &Scene) -> Vec<PanelKind> {
    scene.layout().panels.iter().map(|p| p.kind).collect()
}

#[test]
fn the_study_panels_come_with_sensors_and_the_switch_only() {
    let with = common::session("preset=real-encoder&mode=full&study=1");
    let k = kinds(&scene_of(&with));
    assert!(k.contains(&PanelKind::StudyError) && k.contains(&PanelKind::StudyTorque), "{k:?}");
    assert!(with.study_drawn());
    // The paper's perfect robot: nothing to study, the switch changes nothing.
    let perfect = common::session("mode=full&study=1");
    let plain = common::session("mode=full");
    assert_eq!(kinds(&scene_of(&perfect)), kinds(&scene_of(&plain)));
    assert!(!perfect.study_drawn());
    // Sensors without the switch: the layout of before.
    let off = common::session("preset=real-encoder&mode=full");
    assert!(!kinds(&scene_of(&off)).iter().any(|k| k.is_study()));
    // The intro shows the arm and its errors only.
    let intro = common::session("preset=real-encoder&study=1");
    assert!(!kinds(&scene_of(&intro)).iter().any(|k| k.is_study()));
}

#[test]
fn the_panels_read_out_what_the_table_prints_and_the_torque_noise_grows_as_delta_shrinks() {
    let mut session = common::session("preset=real-encoder&mode=full&study=1");
    let before = scene_of(&session);
    let info = before.panel_info();
    let error = info.iter().find(|p| p.id == "study-error").expect("the error panel");
    assert!(error.note.contains("waiting to start"), "{}", error.note);
    let view = session.sensor_study_step(1000).unwrap();
    assert!(view.done);
    let scene = scene_of(&session);
    let info = scene.panel_info();
    let [header, rows @ ..] = &view.table[..] else { panic!("a table") };
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("{name}: {header:?}"));
    for (kind, id) in [(PanelKind::StudyError, "study-error"), (PanelKind::StudyTorque, "study-torque")] {
        let p = info.iter().find(|p| p.id == id).unwrap();
        assert!(!p.note.contains('%'), "done: {}", p.note);
        assert_eq!((p.x_scale, p.y_scale), ("log", "log"));
        let panel = scene.layout().panel(kind).unwrap();
        for (i, row) in rows.iter().enumerate() {
            let delta = view.deltas[i];
            // The pointer over the row's δ: its values, as the table prints them.
            let x = panel.rect.x + panel.rect.w * (delta / p.x_range[0]).ln() / (p.x_range[1] / p.x_range[0]).ln();
            let probe = scene.probe(x, panel.rect.y + panel.rect.h / 2.0, 0.0).expect("a readout");
            assert_eq!(probe.delta, Some(delta));
            let text: Vec<&str> = probe.lines.iter().map(|l| l.text.as_str()).collect();
            let said = |label: &str| {
                text.iter()
                    .find_map(|t| t.strip_prefix(label).and_then(|r| r.strip_prefix(": ")))
                    .map(|v| v.split(' ').next().unwrap().to_string())
                    .unwrap_or_else(|| panic!("{label} in {text:?}"))
            };
            let pairs: &[(&str, &str)] = if kind == PanelKind::StudyError {
                &[
                    ("max |e| during the slew, these sensors", "max |e|, slew [rad]"),
                    ("max |e| during the slew, perfect sensors", "perfect sensors [rad]"),
                    ("RMS e at rest, these sensors", "RMS e, rest [rad]"),
                ]
            } else {
                &[
                    ("T1 noise at rest (RMS about its mean), these sensors", "T1 noise, rest [N m]"),
                    ("peak |T1|, these sensors", "peak T1 [N m]"),
                    (
                        "the sensors' noise in T1, predicted (RMS; the linear model with white noise, valid while the \
                         arm moves)",
                        "predicted T1 noise [N m]",
                    ),
                ]
            };
            for (label, col) in pairs {
                let cell = &row[column(col)];
                if cell != "diverged" {
                    assert_eq!(&said(label), cell, "δ = {delta}: {label}");
                }
            }
        }
        // Every value read out lies within the axis (at most four decades deep).
        for row in &view.study.rows {
            let values: Vec<f64> = match kind {
                PanelKind::StudyError => {
                    row.real.iter().map(|r| r.max_error_slew[0].max(r.max_error_slew[1])).collect()
                }
                _ => row
                    .real
                    .iter()
                    .map(|r| r.torque_fluctuation_rest[0])
                    .chain(row.real.iter().map(|r| r.max_torque[0]))
                    .collect(),
            };
            for v in values {
                assert!(
                    v <= p.y_range[1] && v >= p.y_range[0].min(p.y_range[1] * 1e-4),
                    "{id}: {v} in {:?}",
                    p.y_range
                );
            }
        }
    }
    // The torque's noise the panel draws: the linear prediction grows like 1/δ (the velocity
    // differenced over δ divides a count by δ), about 10× from δ = 0.02 s to 0.002 s.
    let predicted = |d: f64| {
        view.study
            .rows
            .iter()
            .find(|r| (r.sampling_period - d).abs() < 1e-12)
            .and_then(|r| r.predicted)
            .unwrap()
            .rms_torque[0]
    };
    let ratio = predicted(0.002) / predicted(0.02);
    assert!((6.0..14.0).contains(&ratio), "T1 noise 0.002 s / 0.02 s = {ratio}");
    // The key names every curve of both panels, the limit and the best δ.
    let legend = scene.legend();
    let texts: Vec<&str> = legend.iter().flat_map(|g| g.items.iter().map(|i| i.text.as_str())).collect();
    for needle in ["these sensors", "perfect sensors", "predicted", "torque limit", "best δ"] {
        assert!(texts.iter().any(|t| t.contains(needle)), "{needle}: {texts:?}");
    }
    // The figure for a slide: both panels, their key and the study's settings; refused, with its
    // reason, for the paper's perfect robot.
    let figure = flexarm::view::figure::figure_svg(&session, "study", false).unwrap();
    for needle in ["δ [s]", "T1 [N m]", "error [rad]", "perfect sensors", "encoder=1024"] {
        assert!(figure.svg.contains(needle), "{needle}");
    }
    let perfect = common::session("mode=full&study=1");
    let refused = flexarm::view::figure::figure_svg(&perfect, "study", false).unwrap_err().to_string();
    assert!(refused.contains("a real robot's sensors"), "{refused}");
}
