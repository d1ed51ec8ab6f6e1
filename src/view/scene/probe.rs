//! What lies under the pointer, described for a tooltip: the nearest pole of the pole plot or
//! z-plane, the point of a stability map (and what a click there runs), the δ of ρ(δ).

use serde::Serialize;

use super::info::contains;
use super::Scene;
use crate::plot::color::Measure;
use crate::plot::format;
use crate::session::maps::{feedback_short, point_text, MapSide};
use crate::session::status::Prediction;
use crate::view::layout::PanelKind;
use crate::view::map::side_of;
use crate::view::poles::{PoleInfo, PoleKind};

/// CSS pixels a δ → 0 marker must be nearer than a loop pole to be picked instead of it.
const A4_PICK_PENALTY: f64 = 6.0;
/// Markers of another kind within this many CSS pixels are named in a pole's tooltip.
const A4_BESIDE: f64 = 16.0;

/// What a pole-plot marker is, as its tooltip's title says it.
fn pole_name(kind: PoleKind) -> &'static str {
    match kind {
        PoleKind::Loop => "loop pole (sampled loop, s = ln λ / δ)",
        PoleKind::A4Open => "A4 without K_pr (the flexible pair's δ → 0 limit, not the sampled loop)",
        PoleKind::A4 => "A4 with K_pr (the flexible pair's δ → 0 limit, not the sampled loop)",
    }
}
/// One line of a tooltip, with its tone ("good", "bad" or "").
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TipLine {
    pub text: String,
    pub tone: &'static str,
}

impl TipLine {
    fn plain(text: impl Into<String>) -> Self {
        Self { text: text.into(), tone: "" }
    }

    fn toned(text: impl Into<String>, good: bool) -> Self {
        Self { text: text.into(), tone: if good { "good" } else { "bad" } }
    }
}

/// What lies under the pointer: a pole or a point of a map, described for a tooltip.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Probe {
    /// "pole" or "map".
    pub kind: &'static str,
    pub title: String,
    pub lines: Vec<TipLine>,
    /// Where the tooltip points, CSS pixels in the canvas.
    pub x: f64,
    pub y: f64,
    /// For a map: which one ("off" or "on") and the (δ, α) under the pointer.
    pub map: Option<MapSide>,
    pub delta: Option<f64>,
    pub alpha: Option<f64>,
}

impl Scene {
    /// What lies at (x, y) (CSS pixels in the canvas): the nearest pole within `reach` pixels,
    /// else the point of a map or of ρ(δ) under the pointer; `None` elsewhere.
    pub fn probe(&self, x: f64, y: f64, reach: f64) -> Option<Probe> {
        self.probe_pole(x, y, reach).or_else(|| self.probe_map(x, y)).or_else(|| self.probe_rho(x, y))
    }

    /// The δ under (x, y) on ρ(δ), with ρ and ln ρ/δ there.
    fn probe_rho(&self, x: f64, y: f64) -> Option<Probe> {
        let panel = self.layout.panel(PanelKind::RhoCurve)?;
        if !contains(panel, x, y) {
            return None;
        }
        let frame = self.rho_frame(panel, false);
        let delta = frame.delta_at(x);
        let [scan_delta, rho] = self
            .windows
            .as_ref()
            .and_then(|w| {
                w.scan.iter().min_by(|a, b| (a[0] / delta).ln().abs().total_cmp(&(b[0] / delta).ln().abs())).copied()
            })
            .unwrap_or([delta, f64::NAN]);
        let mut lines = vec![TipLine::plain(format!("δ = {} s", format::sig(delta, 3)))];
        stability_lines(rho, scan_delta, &mut lines);
        // The second reading of δ: how far the joint's swing turns in a period, and how late the
        // torque acts on it (the lag law, analysis::lag).
        if let Some(law) = self.runs[0].report.as_ref().map(crate::analysis::lag::LagLaw::of) {
            lines.push(TipLine::plain(format!(
                "the swing turns ωδ = {:.2} rad per period ({:.2} of a turn); the torque acts 1.5 ωδ = {:.0}° later",
                law.turn(delta),
                law.turn(delta) / core::f64::consts::TAU,
                law.lag(delta).to_degrees()
            )));
        }
        lines.push(TipLine::plain("click or drag to run at this δ"));
        let title = if self.options.measure == Measure::Rate { "ln ρ/δ at this α" } else { "ρ(δ) at this α" };
        Some(Probe { kind: "rho", title: title.into(), lines, x, y, map: None, delta: Some(delta), alpha: None })
    }

    fn probe_pole(&self, x: f64, y: f64, reach: f64) -> Option<Probe> {
        let panel = self.layout.panels.iter().find(|p| p.kind.is_pole_plot())?.rect;
        let near_panel = |px: f64, py: f64, m: f64| {
            px >= panel.x - m && px <= panel.right() + m && py >= panel.y - m && py <= panel.bottom() + m
        };
        if !near_panel(x, y, reach / 2.0) {
            return None;
        }
        let poles = self.pole_info();
        let at = |p: &PoleInfo| Some((p.x?, p.y?)).filter(|(px, py)| near_panel(*px, *py, 12.0));
        // The sampled loop's own poles win over the δ → 0 markers that sit next to them (the
        // question is usually "what is this pole?", and A4 marks a limit, not the loop).
        let penalty = |p: &PoleInfo| if p.kind == PoleKind::Loop { 0.0 } else { A4_PICK_PENALTY };
        let best = poles
            .iter()
            .filter_map(|p| at(p).map(|(px, py)| (p, px, py, (px - x).hypot(py - y))))
            .filter(|(.., d)| *d <= reach)
            .min_by(|a, b| (a.3 + penalty(a.0)).total_cmp(&(b.3 + penalty(b.0))))?;
        let (pole, px, py, _) = best;
        // Other markers of the same kind on the same spot (those of another kind are named below;
        // two poles both held at the plot's edge are not "at the same spot").
        let others = poles
            .iter()
            .filter(|p| !std::ptr::eq(*p, pole) && p.kind == pole.kind && p.in_view == pole.in_view)
            .filter_map(at)
            .filter(|(qx, qy)| (qx - px).hypot(qy - py) < 4.0)
            .count();
        let im = pole.im.abs();
        // A real negative λ is one eigenvalue flipping sign every period, not a ± pair.
        let [lr, li] = pole.lambda;
        let flips = pole.kind == PoleKind::Loop && lr < 0.0 && li.abs() <= 1e-12 * lr.abs();
        let s = if flips {
            format!("s = {} + jπ/δ 1/s: λ real and negative", format::sig(pole.re, 3))
        } else if im > 1e-9 {
            format!("s = {} ± {}j 1/s", format::sig(pole.re, 3), format::sig(im, 4))
        } else {
            format!("s = {} 1/s", format::sig(pole.re, 3))
        };
        let mut lines = vec![TipLine::plain(s)];
        if let Some(zeta) = pole.zeta {
            lines.push(TipLine::plain(format!("damping ratio ζ = {}", format::sig(zeta, 3))));
        }
        // The damped frequency it swings at and the natural one, named apart.
        lines.push(TipLine::plain(if flips {
            format!("it flips sign every period: a swing at the Nyquist frequency π/δ = {} rad/s", format::sig(im, 4))
        } else if im > 1e-9 {
            format!(
                "swings at Im s = {} rad/s = {} Hz (natural frequency |s| = {} rad/s)",
                format::sig(im, 4),
                format::sig(im / core::f64::consts::TAU, 3),
                format::sig(pole.omega, 3)
            )
        } else {
            format!("|s| = {} 1/s (it does not swing)", format::sig(pole.omega, 3))
        }));
        if pole.kind == PoleKind::Loop {
            let [lr, li] = pole.lambda;
            let lambda = if li.abs() > 1e-12 {
                format!("λ = {} ± {}j", format::sig(lr, 3), format::sig(li.abs(), 3))
            } else {
                format!("λ = {}", format::sig(lr, 4))
            };
            lines.push(TipLine::plain(format!(
                "{lambda}: |λ| = {}, angle {} rad per period",
                format::sig(pole.modulus, 4),
                format::sig(pole.angle.abs(), 3)
            )));
            if pole.flexible {
                // One motion, three numbers: say which this is.
                lines.push(TipLine::plain("the flexible pair: the joint's resonance in this loop, at this δ"));
            }
            // Student mode: the numbers to read, not the verdict they give.
            if !self.options.hide_prediction {
                lines.push(if pole.unstable {
                    TipLine::toned("unstable: |λ| > 1 (Re s > 0), it grows", false)
                } else {
                    TipLine::toned("stable: |λ| < 1 (Re s < 0), it decays", true)
                });
            }
        } else if !self.options.hide_prediction {
            // A limit, not an eigenvalue of this loop: its sign says what happens as δ → 0.
            if self.layout.panels.iter().any(|p| p.kind == PanelKind::ZPlane) {
                lines.push(TipLine::plain("drawn at e^(A4 δ): not an eigenvalue of this loop"));
            }
            lines.push(if pole.unstable {
                TipLine::toned("Re s > 0: as δ → 0 the flexible pair grows", false)
            } else {
                TipLine::toned("Re s < 0: as δ → 0 the flexible pair dies out", true)
            });
        }
        if pole.aliased {
            lines.push(TipLine::plain(format!(
                "aliased: the mode itself is faster than the Nyquist frequency π/δ = {} rad/s",
                format::sig(core::f64::consts::PI / self.runs[0].report.as_ref().map_or(1.0, |r| r.sampling_period), 3)
            )));
        }
        if !pole.in_view {
            lines.push(TipLine::plain("outside the shown range (marked at the edge)"));
        }
        if others > 0 {
            let place = if pole.in_view { "at the same spot" } else { "beyond the same edge" };
            lines.push(TipLine::plain(format!("({others} more pole{} {place})", if others > 1 { "s" } else { "" })));
        }
        // A different kind of marker right beside this one is named too, so neither hides the other.
        for q in poles.iter().filter(|q| q.kind != pole.kind && q.run == pole.run) {
            let Some((qx, qy)) = at(q) else { continue };
            if (qx - px).hypot(qy - py) <= A4_BESIDE {
                let s = format!("{} ± {}j", format::sig(q.re, 3), format::sig(q.im.abs(), 4));
                let line = TipLine::plain(format!("beside it: {} at s = {s} 1/s", pole_name(q.kind)));
                // Both halves of a conjugate pair can sit beside a real pole: name it once.
                if !lines.contains(&line) {
                    lines.push(line);
                }
            }
        }
        let mut title = pole_name(pole.kind).to_string();
        if self.pair {
            title += &format!(" — run {}", pole.run);
        }
        Some(Probe { kind: "pole", title, lines, x: px, y: py, map: None, delta: None, alpha: None })
    }

    /// The map and (δ, α) at (x, y), if (x, y) lies on a map.
    pub fn map_point(&self, x: f64, y: f64) -> Option<(MapSide, f64, f64)> {
        let panel = self
            .layout
            .panels
            .iter()
            .find(|p| side_of(p.kind).is_some() && p.rect.w > 0.0 && p.rect.h > 0.0 && contains(p, x, y))?;
        let side = side_of(panel.kind)?;
        let grid = &self.maps[side.index()];
        let r = panel.rect;
        let fx = ((x - r.x) / r.w).clamp(0.0, 1.0);
        let fy = (1.0 - (y - r.y) / r.h).clamp(0.0, 1.0);
        let along = |f: f64, [lo, hi]: [f64; 2]| lo * (hi / lo).powf(f);
        Some((side, along(fx, grid.delta_range()), along(fy, grid.alpha_range())))
    }

    fn probe_map(&self, x: f64, y: f64) -> Option<Probe> {
        let (side, delta, alpha) = self.map_point(x, y)?;
        let (cell_delta, rho) = self.maps[side.index()].near(delta, alpha);
        let mut lines = vec![TipLine::plain(point_text(delta, alpha))];
        stability_lines(rho, cell_delta, &mut lines);
        let pf = self.runs[0].config.map(|c| c.preliminary_feedback).unwrap_or_default();
        // Where the paper's gains stop damping the resonance, the map says why it turns red.
        let limit = self.runs[0].report.as_ref().map(|r| r.resonance.paper_alpha_limit);
        if let (crate::control::config::PreliminaryFeedbackChoice::Paper, Some(limit)) = (side.feedback(pf), limit) {
            if alpha > limit {
                lines.push(TipLine::plain(format!(
                    "above α = {} 1/s the paper's K_pr leaves the δ → 0 pair unstable: at this α the smallest δ fail; its shift of \
                     Re A4 is the same at every α, while the controller's feed 3α/2 grows",
                    format::sig(limit, 3)
                )));
            }
        }
        // What a click runs: the point rounded as the controls round it (the session snaps the
        // same way), beside the map cell's ρ above.
        let spec = |p: &crate::schema::Param| *p.number().expect("δ and α are numbers");
        let (d, a) = (spec(&crate::schema::DELTA).snap(delta), spec(&crate::schema::ALPHA).snap(alpha));
        lines.push(TipLine::plain(format!(
            "click to run at δ = {} s, α = {} 1/s",
            crate::schema::format_number(d),
            crate::schema::format_number(a)
        )));
        let title = match side.feedback(pf) {
            crate::control::config::PreliminaryFeedbackChoice::Off => "without preliminary feedback".to_string(),
            f => format!("with {}", feedback_short(f)),
        };
        Some(Probe { kind: "map", title, lines, x, y, map: Some(side), delta: Some(delta), alpha: Some(alpha) })
    }
}

/// ρ and the rate ln ρ/δ at sampling period `delta` (s), whatever the view colours by: the
/// verdict is read in ρ, the rate compares across δ.
fn stability_lines(rho: f64, delta: f64, lines: &mut Vec<TipLine>) {
    if rho.is_finite() {
        // The verdict's own judgement (a rate within the borderline band is borderline here too).
        let verdict = match Prediction::of_rate(Measure::Rate.value(rho, delta)) {
            Prediction::Stable => "stable",
            Prediction::Borderline => "borderline",
            Prediction::Unstable => "unstable",
        };
        lines.push(TipLine::toned(format!("ρ = {rho:.3} per period: {verdict}"), verdict == "stable"));
        let rate = format::sig(Measure::Rate.value(rho, delta), 3);
        lines.push(TipLine::plain(format!("ln ρ/δ = {rate} 1/s (per second)")));
    } else {
        lines.push(TipLine::plain("ρ not computed yet"));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tooltip says the verdict's word for the same ρ and δ (trial 4: δ = 0.114 s, ρ = 0.99498
    /// was "stable" here and "borderline" in the verdict).
    #[test]
    fn a_tooltip_judges_as_the_verdict_does() {
        for (rho, delta, word) in [
            (0.99498, 0.114, "borderline"),
            (0.9977, 0.0355, "stable"),
            (1.0239, 0.01, "unstable"),
            (1.0004, 0.01, "borderline"),
        ] {
            let mut lines = Vec::new();
            stability_lines(rho, delta, &mut lines);
            assert!(lines[0].text.ends_with(word), "{rho} at {delta}: {}", lines[0].text);
            assert_eq!(lines[0].tone == "good", word == "stable");
        }
    }
}
