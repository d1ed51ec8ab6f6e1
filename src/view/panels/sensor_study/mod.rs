//! What bounds δ from below with run A's sensors (issue 36), drawn beside ρ(δ): the slew's error
//! and the error at rest against δ ([`PanelKind::StudyError`]), T1's noise at rest and its peak
//! with the torque limit ([`PanelKind::StudyTorque`]) — each simulated with the settings' sensors
//! and with perfect ones, and the linear prediction of the noise ([`drawing::SERIES`]). The
//! study itself is the session's ([`crate::session::Session::study_facts`]); the panel keeps a
//! copy, taken when the study moves, and draws it in the static layer.

pub mod drawing;

use drawing::{draw_study, series_of, study_ticks, value_range, StudyFrame};

use crate::analysis::sensor_study::{Best, SensorStudy, StudyRow};
use crate::plot::{format, palette};
use crate::schema::PanelKind;
use crate::view::delta_axis::DeltaAxis;
use crate::view::layout::Panel;
use crate::view::legend::{item, Glyph, LegendGroup};
use crate::view::painter::Painter;
use crate::view::panel_info::{PanelInfo, Probe, Region, TipLine};
use crate::view::panels::contract::{Frame, PanelView, Runs};
use crate::view::tick_labels::log_labels;

/// Least distance between labels along a log axis, CSS px.
const LOG_LABEL_SPACING: f64 = 38.0;
/// The value axes before any run is in: rad, N m.
const ERROR_FALLBACK: [f64; 2] = [1e-4, 1e-1];
const TORQUE_FALLBACK: [f64; 2] = [1e-1, 1e3];

/// The study's two panels, with the copy of the study they draw.
#[derive(Clone, Debug, Default)]
pub struct StudyPanels {
    /// The session study's generation copied (0: none yet).
    generation: u64,
    rows: Vec<StudyRow>,
    /// The row ringed: the least error of the stable δ, once every run is in.
    best: Option<usize>,
    /// The motors' torque limit, N m, if any.
    limit: Option<f64>,
    /// The share of the runs done, 0 … 1.
    progress: f64,
}

impl StudyPanels {
    /// Takes the session's study (`generation`, its facts, the torque limit) unless it has it
    /// already; true if it took it (the static layer is then drawn again).
    pub fn follow(&mut self, generation: u64, study: Option<&SensorStudy>, limit: Option<f64>) -> bool {
        if generation == self.generation && limit == self.limit {
            return false;
        }
        self.generation = generation;
        self.limit = limit;
        self.rows.clear();
        self.best = None;
        self.progress = 0.0;
        if let Some(s) = study {
            self.rows.extend_from_slice(&s.rows);
            self.best = match s.best {
                Best::Inside { index } | Best::Smallest { index } => Some(index),
                _ => None,
            };
            self.progress = s.progress;
        }
        true
    }

    /// The session study's generation copied.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// The torque limit drawn, N m.
    pub fn limit(&self) -> Option<f64> {
        self.limit
    }

    /// The rows drawn.
    pub fn rows(&self) -> &[StudyRow] {
        &self.rows
    }

    fn frame(&self, frame: &Frame, panel: &Panel, physical: bool) -> StudyFrame {
        let rect = if physical { frame.layout.to_physical(panel.rect) } else { panel.rect };
        let x_range = frame.windows.as_ref().map_or(crate::schema::DELTA_SPEC.control, |w| w.range);
        let fallback = if panel.kind == PanelKind::StudyTorque { TORQUE_FALLBACK } else { ERROR_FALLBACK };
        let axis = DeltaAxis { rect, range: x_range };
        StudyFrame { axis, y_range: value_range(panel.kind, &self.rows, self.limit, fallback) }
    }

    /// The row nearest δ (in log scale).
    fn row_near(&self, delta: f64) -> Option<&StudyRow> {
        self.rows
            .iter()
            .min_by(|a, b| (a.sampling_period / delta).ln().abs().total_cmp(&(b.sampling_period / delta).ln().abs()))
    }
}

impl PanelView for StudyPanels {
    fn figure_size(&self, _kind: PanelKind) -> (f64, f64) {
        (600.0, 300.0)
    }

    fn vertex_budget(&self, frame: &Frame, _panel: &Panel) -> usize {
        // The runs' δ: a line and a dot each (the curves are in the static layer).
        frame.run_count() * (3 * 6 + 2 * 128 * 3) + 24
    }

    fn draw_static(&self, frame: &Frame, panel: &Panel, painter: &mut Painter) {
        let study = self.frame(frame, panel, true);
        let (x_ticks, y_ticks) = study_ticks(panel.rect, &study);
        let dpr = frame.layout.device_pixel_ratio;
        draw_study(painter, panel.kind, &study, &self.rows, self.best, self.limit, (&x_ticks, &y_ticks), dpr);
    }

    /// The runs' δ, as on ρ(δ): a vertical line (the curves are in the static layer).
    fn draw(&mut self, frame: &Frame, _runs: &Runs<'_>, panel: &Panel, painter: &mut Painter) {
        let dpr = frame.layout.device_pixel_ratio;
        let study = self.frame(frame, panel, true);
        let r = study.axis.rect;
        for run in (0..frame.run_count()).rev() {
            let Some(config) = &frame.runs[run].config else { continue };
            let color = if run == 0 { palette::MAP_MARKER } else { palette::RUN_B };
            let x = study.axis.x(config.controller.sampling_period).clamp(r.x, r.right());
            painter.line([x, r.y], [x, r.bottom()], 1.5 * dpr, color.with_alpha(0.6));
        }
        painter.rect_outline(r, dpr.max(1.0), palette::FRAME);
    }

    fn describe(&self, frame: &Frame, panel: &Panel) -> PanelInfo {
        let r = panel.rect;
        let mut info = PanelInfo::new(panel.kind.id(), r.x, r.y, r.w, r.h);
        let study = self.frame(frame, panel, false);
        let (x_ticks, y_ticks) = study_ticks(r, &study);
        let torque = panel.kind == PanelKind::StudyTorque;
        info.x_label = "δ [s]".into();
        info.y_label = if torque { "T1 [N m]" } else { "error [rad]" };
        info.x_range = study.axis.range;
        info.y_range = study.y_range;
        info.x_labels = log_labels(&x_ticks, info.x_range, r.w, LOG_LABEL_SPACING);
        info.y_labels = log_labels(&y_ticks, info.y_range, r.h, 16.0);
        info.x_ticks = x_ticks;
        info.y_ticks = y_ticks;
        info.x_scale = "log";
        info.y_scale = "log";
        let done = if self.progress < 1.0 && !self.rows.is_empty() {
            format!(": {} % simulated", (100.0 * self.progress).round())
        } else if self.rows.is_empty() {
            ": waiting to start".to_string()
        } else {
            String::new()
        };
        // Short: on a laptop six analysis panels share a row.
        info.note = if torque { format!("T1 against δ{done}") } else { format!("error against δ{done}") };
        info.region = Some(Region {
            label: "The study against δ. Left and right arrow keys change δ.",
            keys: "delta",
            map: None,
        });
        info
    }

    /// The row of the study nearest the pointer's δ, its values read out.
    fn probe(&self, frame: &Frame, panel: &Panel, x: f64, y: f64, _reach: f64) -> Option<Probe> {
        if !panel.contains(x, y) {
            return None;
        }
        let study = self.frame(frame, panel, false);
        let delta = study.axis.delta_at(x);
        let mut lines = Vec::new();
        let row = self.row_near(delta);
        match row {
            Some(row) => {
                lines.push(TipLine::plain(format!("δ = {} s (studied)", format::significant(row.sampling_period, 3))));
                if let Some(rho) = row.spectral_radius {
                    let unstable = if row.unstable() { " ≥ 1: unstable in the long run" } else { "" };
                    lines.push(TipLine::plain(format!("ρ = {}{unstable}", crate::words::numbers::rho(rho))));
                }
                let unit = if panel.kind == PanelKind::StudyTorque { "N m" } else { "rad" };
                for s in series_of(panel.kind) {
                    let value = (s.value)(row)
                        .map_or("—".to_string(), |v| format!("{} {unit}", format::significant(v, s.digits)));
                    lines.push(TipLine::plain(format!("{}: {value}", s.label)));
                }
                if row.diverged() {
                    lines.push(TipLine::plain("the run with these sensors diverged: no slew, no rest to read"));
                }
                if let (Some(limit), Some(share)) = (self.limit, row.saturated()) {
                    lines.push(TipLine::plain(format!(
                        "time at the {} N m limit: {}",
                        format::significant_trimmed(limit, 3),
                        crate::words::sensors::percent(share)
                    )));
                }
            }
            None => lines.push(TipLine::plain("the study has not started: open “A real robot” or wait")),
        }
        lines.push(TipLine::plain("click to run at this δ"));
        let title = if panel.kind == PanelKind::StudyTorque { "T1 against δ" } else { "the error against δ" };
        let delta = row.map_or(delta, |r| r.sampling_period);
        Some(Probe { kind: "study", title: title.into(), lines, x, y, map: None, delta: Some(delta), alpha: None })
    }

    fn legend(&self, _frame: &Frame, kinds: &[PanelKind]) -> Vec<LegendGroup> {
        let mut groups = Vec::new();
        for kind in [PanelKind::StudyError, PanelKind::StudyTorque] {
            if !kinds.contains(&kind) {
                continue;
            }
            let mut items: Vec<_> = series_of(kind)
                .map(|s| {
                    let glyph = if s.stroke == drawing::Stroke::Solid { Glyph::Line } else { Glyph::Dashed };
                    item(glyph, s.color, s.label)
                })
                .collect();
            if kind == PanelKind::StudyError {
                items.push(item(Glyph::Ring, palette::WINDOW_MARK, "the best δ: least slew error among the stable δ"));
                items.push(item(Glyph::Cross, palette::POLE_UNSTABLE, "ρ ≥ 1 or the run diverged: no δ to choose"));
            } else {
                items.push(item(Glyph::Dashed, palette::TORQUE_LIMIT, "the motors' torque limit"));
            }
            groups.push(LegendGroup {
                title: if kind == PanelKind::StudyTorque { "T1 against δ" } else { "the error against δ" },
                items,
                scale: None,
            });
        }
        groups
    }

    fn figure_title(&self, _frame: &Frame, kinds: &[PanelKind]) -> String {
        match kinds {
            [PanelKind::StudyTorque] => "T1's noise and peak against δ".into(),
            [PanelKind::StudyError] => "The tracking error against δ".into(),
            _ => "The tracking error and T1 against δ, with these sensors and with perfect ones".into(),
        }
    }
}
