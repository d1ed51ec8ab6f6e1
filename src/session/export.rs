//! What the page exports besides the CSV: the same SVG figures as `flexarm simulate --svg` and
//! `flexarm map --svg` (written by [`crate::svg`]).

use super::maps::MapSide;
use super::{status, Session};
use crate::analysis::StabilityMap;
use crate::error::Error;

impl Session {
    /// Run A's tracking errors as an SVG figure headed by the settings and the verdict, the
    /// state string in its description.
    pub fn svg_traces(&self) -> String {
        let s = status::run_status("A", &self.a);
        let title = format!(
            "Tracking errors e1, e2: {} — {}",
            crate::words::settings::run(&self.a.settings().config()),
            s.headline
        );
        crate::svg::error_traces_svg(self.a.closed_loop().traces(), &title, Some(&self.settings.run_query()))
    }

    /// The two stability maps shown, side by side with their colour bar and the current (δ, α),
    /// coloured by the view's measure (ρ or ln ρ/δ), once they are computed.
    pub fn svg_maps(&self) -> Result<String, Error> {
        if self.answers_hidden() {
            return Err(Error::NotReady("student mode hides the stability maps until you answer"));
        }
        let pf = self.settings.a.pf;
        let measure = self.settings.view.measure;
        let mut maps: Vec<(StabilityMap, String)> = Vec::new();
        for side in MapSide::BOTH {
            let entry = self.maps.shown(side).filter(|e| e.is_done()).ok_or(Error::NotReady(
                "the stability maps are still being computed: show them and wait for the progress bar to fill",
            ))?;
            maps.push((entry.job().clone().finish()?, self.maps.caption(side, pf, measure)));
        }
        let panels: Vec<(&StabilityMap, &str)> = maps.iter().map(|(m, c)| (m, c.as_str())).collect();
        let a = &self.settings.a;
        let title = format!(
            "{} of the sampled loop (k = {}, m = {}, inner loop {})",
            measure.quantity(),
            a.k,
            a.eps_ratio,
            a.inner.name()
        );
        let mark = (a.alpha[0] == a.alpha[1]).then_some((a.delta, a.alpha[0]));
        Ok(crate::svg::stability_maps_svg(&panels, &title, mark, Some(&self.settings.run_query()), measure))
    }
}
