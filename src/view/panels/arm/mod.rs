//! The arm, seen from above (run A's, and run B's beside it when two runs are compared): links,
//! motor, the flexible joint's spring with its twist magnified, and the reference arm
//! ([`drawing`]); zoomed on one sampling instant, the arm the controller predicts for tₙ + kε; and
//! on demand the flexible pair's shape, animated ([`swing`]).

pub mod drawing;
pub mod swing;

use drawing::{draw_arm_outline, draw_arm_panel, ArmFrame, ArmPose, VERTEX_BUDGET};
use swing::{swing_legend, swing_pose, swing_shape, SWING_SLOWDOWN};

use crate::plot::palette;
use crate::schema::PanelKind;
use crate::view::layout::Panel;
use crate::view::legend::{item, Glyph, LegendGroup};
use crate::view::painter::Painter;
use crate::view::panel_info::PanelInfo;
use crate::view::panels::contract::{Frame, PanelView, Runs};

/// The arm panels ([`PanelKind::Arm`], [`PanelKind::ArmB`]).
#[derive(Clone, Debug, Default)]
pub struct Arm;

impl PanelView for Arm {
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (480.0, 440.0)
    }

    fn vertex_budget(&self, _frame: &Frame, _panel: &Panel) -> usize {
        VERTEX_BUDGET
    }

    fn draw(&mut self, frame: &Frame, runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let snapshot = match panel.kind {
            PanelKind::ArmB => match &runs.b {
                Some(b) => b.snapshot,
                None => return,
            },
            _ => runs.a.snapshot,
        };
        let [q1, q2, theta] = snapshot.q;
        let actual = ArmPose { q1, q2, theta };
        let [qd1, qd2] = snapshot.qd;
        let reference = ArmPose { q1: qd1, q2: qd2, theta: qd1 };
        let rect = frame.layout.to_physical(panel.rect);
        let dpr = frame.layout.device_pixel_ratio;
        let magnification = frame.options.spring_magnification;
        draw_arm_panel(painter, rect, dpr, &actual, &reference, magnification);
        // The flexible pair's shape, turning (slowed down) about the rest point of the analysis.
        if panel.kind == PanelKind::Arm {
            if let Some(pose) = swing_pose(frame) {
                draw_arm_outline(painter, rect, dpr, &pose, 1.0, palette::SWING);
            }
        }
        // Zoomed on t_n: where the controller predicts the arm at t_n + kε (X_k).
        if panel.kind == PanelKind::Arm && frame.zoomed() && frame.cycle.sweep.complete {
            if let Some(x) = frame.cycle.sweep.states.last() {
                let predicted = ArmPose { q1: x[0], q2: x[1], theta: x[2] };
                draw_arm_outline(painter, rect, dpr, &predicted, magnification, palette::PREDICTED_ARM);
            }
        }
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        let rect_px = frame.layout.to_physical(r);
        let (x_range, y_range) = ArmFrame::fit(rect_px, frame.layout.device_pixel_ratio).world_range(rect_px);
        info.x_range = x_range;
        info.y_range = y_range;
        let zoom = frame.zoomed();
        info.title = match (panel.kind, frame.pair) {
            (PanelKind::Arm, _) if zoom => "arm at tₙ".into(),
            (PanelKind::Arm, false) => "arm, top view".into(),
            (PanelKind::Arm, true) => "A: arm, top view".into(),
            _ => "B: arm, top view".into(),
        };
        if panel.kind == PanelKind::Arm {
            if zoom {
                info.title += "; violet: as predicted for tₙ + kε";
            }
            if frame.options.show_swing && swing_shape(frame).is_some() {
                info.title += &format!("; amber: the swing's shape, {SWING_SLOWDOWN}× slower");
            }
        }
        info
    }

    fn legend(&self, _frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        if !kinds.contains(&PanelKind::Arm) {
            return Vec::new();
        }
        vec![LegendGroup {
            title: "arm",
            items: vec![
                item(Glyph::Line, palette::GHOST, "the reference arm: where the arm should be"),
                item(
                    Glyph::Line,
                    palette::AXIS,
                    "the thin line from the base: 0 rad, where the angles are measured from",
                ),
                item(
                    Glyph::Line,
                    palette::SPRING_STRETCHED,
                    "the spring between motor and link 1: its twist θ − q1 drawn magnified (orange relaxed, red wound)",
                ),
                item(Glyph::Line, palette::MOTOR_MARKER, "the motor's angle θ on its disc (grey: the reference's)"),
            ],
            scale: None,
        }]
    }

    fn readings(&self, frame: &Frame) -> Vec<LegendGroup> {
        swing_legend(frame).into_iter().collect()
    }

    fn figure_title(&self, _frame: &Frame, kinds: &[PanelKind]) -> String {
        if kinds.contains(&PanelKind::ArmB) {
            "Run B's arm, top view".into()
        } else {
            "The arm, top view".into()
        }
    }
}
