//! The figure in words, for screen readers (the canvas' description): what it shows, at which
//! instant, and each run's verdict and newest numbers.

use super::status::{hide_answers, run_status};
use super::Session;
use crate::schema::PanelKind;
use crate::words::panels::{figure_contents, figure_run};

impl Session {
    /// The figure in words, for screen readers (the canvas' description): what it shows, at
    /// which instant, the verdict and the newest numbers of each run.
    pub fn figure_text(&self) -> String {
        let v = self.drawn_view();
        let hidden = self.answers_hidden();
        // Only what is drawn: an embed may show the arm or the errors alone, or neither.
        let mut kinds = Vec::new();
        if v.picture {
            kinds.push(PanelKind::Arm);
        }
        if v.errors {
            kinds.push(PanelKind::Error1);
        }
        if v.torque {
            kinds.push(PanelKind::Torque);
        }
        if v.measured && !v.predict && self.reads_sensors() {
            kinds.push(PanelKind::Velocity);
        }
        if v.poles {
            kinds.push(if v.z_plane { PanelKind::ZPlane } else { PanelKind::Poles });
        }
        if v.rho {
            kinds.push(PanelKind::RhoCurve);
        }
        if v.map {
            kinds.push(PanelKind::MapOff);
        }
        if v.study && self.reads_sensors() {
            kinds.push(PanelKind::StudyError);
        }
        let mut text = figure_contents(&kinds, v.measure == crate::plot::color::Measure::Rate);
        for (i, run) in self.runs().enumerate() {
            let name = if i == 0 { "A" } else { "B" };
            let mut s = run_status(name, run);
            if hidden {
                hide_answers(&mut s);
            }
            let at = self.shown_snapshot(i).map_or(f64::NAN, |snap| snap.time);
            let settings = self.run(1).is_some().then_some(s.settings.as_str());
            let looking_back = self.viewing().is_some();
            let errors = v.errors.then_some(s.readouts.error.as_str());
            text += &figure_run(name, settings, s.headline, &s.detail, at, looking_back, errors, &s.observed);
        }
        text
    }
}
