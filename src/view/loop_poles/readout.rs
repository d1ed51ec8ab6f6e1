//! The loop's eigenvalues read out: a marker's tooltip (what it is, where, how fast it swings and
//! grows, the verdict it gives) and the mark beside run A's flexible pair — the same on the
//! s-plane pole plot and on the z-plane.

use super::{PoleInfo, PoleKind};
use crate::plot::format;
use crate::view::panel_info::{Mark, Probe, TipLine};
use crate::view::rect::Rect;
use crate::view::text_metrics::{bold_width, font};

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
/// What a pole plot's reader needs to know of the frame besides its markers.
#[derive(Clone, Copy, Debug)]
pub struct PoleScene<'a> {
    /// Every marker, both runs', placed on the pole plot shown.
    pub poles: &'a [PoleInfo],
    /// The pole plot's data area, CSS px.
    pub panel: Rect,
    /// The z-plane (λ) rather than the s-plane.
    pub z_plane: bool,
    /// Two runs compared: titles name the run.
    pub pair: bool,
    /// Student mode: the numbers, not the verdict they give.
    pub hide_prediction: bool,
    /// Run A's δ, s (for the Nyquist frequency).
    pub sampling_period: f64,
}

/// The nearest marker within `reach` px of (x, y) (CSS px), read out for a tooltip: what it is, s,
/// its damping and frequency, λ, and the verdict it gives.
pub fn probe_poles(scene: &PoleScene<'_>, x: f64, y: f64, reach: f64) -> Option<Probe> {
    let panel = scene.panel;
    let near_panel = |px: f64, py: f64, m: f64| {
        px >= panel.x - m && px <= panel.right() + m && py >= panel.y - m && py <= panel.bottom() + m
    };
    if !near_panel(x, y, reach / 2.0) {
        return None;
    }
    let poles = scene.poles;
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
        format!("s = {} + jπ/δ 1/s: λ real and negative", format::significant(pole.re, 3))
    } else if im > 1e-9 {
        format!("s = {} ± {}j 1/s", format::significant(pole.re, 3), format::significant(im, 4))
    } else {
        format!("s = {} 1/s", format::significant(pole.re, 3))
    };
    let mut lines = vec![TipLine::plain(s)];
    if let Some(zeta) = pole.zeta {
        lines.push(TipLine::plain(format!("damping ratio ζ = {}", format::significant(zeta, 3))));
    }
    // The damped frequency it swings at and the natural one, named apart.
    lines.push(TipLine::plain(if flips {
        format!(
            "it flips sign every period: a swing at the Nyquist frequency π/δ = {} rad/s",
            format::significant(im, 4)
        )
    } else if im > 1e-9 {
        format!(
            "swings at Im s = {} rad/s = {} Hz (natural frequency |s| = {} rad/s)",
            format::significant(im, 4),
            format::significant(im / core::f64::consts::TAU, 3),
            format::significant(pole.omega, 3)
        )
    } else {
        format!("|s| = {} 1/s (it does not swing)", format::significant(pole.omega, 3))
    }));
    if pole.kind == PoleKind::Loop {
        let [lr, li] = pole.lambda;
        let lambda = if li.abs() > 1e-12 {
            format!("λ = {} ± {}j", format::significant(lr, 3), format::significant(li.abs(), 3))
        } else {
            format!("λ = {}", format::significant(lr, 4))
        };
        lines.push(TipLine::plain(format!(
            "{lambda}: |λ| = {}, angle {} rad per period",
            format::significant(pole.modulus, 4),
            format::significant(pole.angle.abs(), 3)
        )));
        if pole.flexible {
            // One motion, three numbers: say which this is.
            lines.push(TipLine::plain("the flexible pair: the joint's resonance in this loop, at this δ"));
        }
        // Student mode: the numbers to read, not the verdict they give.
        if !scene.hide_prediction {
            lines.push(if pole.unstable {
                TipLine::toned("unstable: |λ| > 1 (Re s > 0), it grows", false)
            } else {
                TipLine::toned("stable: |λ| < 1 (Re s < 0), it decays", true)
            });
        }
    } else if !scene.hide_prediction {
        // A limit, not an eigenvalue of this loop: its sign says what happens as δ → 0.
        if scene.z_plane {
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
            format::significant(core::f64::consts::PI / scene.sampling_period, 3)
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
            let s = format!("{} ± {}j", format::significant(q.re, 3), format::significant(q.im.abs(), 4));
            let line = TipLine::plain(format!("beside it: {} at s = {s} 1/s", pole_name(q.kind)));
            // Both halves of a conjugate pair can sit beside a real pole: name it once.
            if !lines.contains(&line) {
                lines.push(line);
            }
        }
    }
    let mut title = pole_name(pole.kind).to_string();
    if scene.pair {
        title += &format!(" — run {}", pole.run);
    }
    Some(Probe { kind: "pole", title, lines, x: px, y: py, map: None, delta: None, alpha: None })
}

/// "flexible pair" beside run A's upper flexible loop pole, if the pole plot shows it (`panel_width`
/// CSS px wide); on the z-plane with how far it is from the circle (`gap`).
pub fn flexible_mark(poles: &[PoleInfo], panel_width: f64, gap: Option<fn([f64; 2]) -> String>) -> Vec<Mark> {
    let Some(p) = poles.iter().find(|p| p.run == "A" && p.flexible && p.im > 0.0 && p.in_view) else {
        return Vec::new();
    };
    let (Some(x), Some(y)) = (p.x, p.y) else { return Vec::new() };
    // A narrow pole plot gets the short form rather than a cut one ("flexible pair, alia…").
    let room = panel_width - 8.0;
    let fits = |t: &str| bold_width(t, font::NOTE) <= room;
    let forms: &[&str] =
        if p.aliased { &["flexible pair, aliased", "aliased pair", "aliased"] } else { &["flexible pair", "pair"] };
    // The z-plane says how far outside (or inside) the unit circle the pair is.
    if let Some(gap_text) = gap {
        let gap = gap_text(p.lambda);
        let long = format!("{}: {gap}", forms[0]);
        let text = [long.as_str(), gap.as_str()].into_iter().find(|t| fits(t)).unwrap_or(forms[forms.len() - 1]);
        return vec![Mark { x, y, text: text.into() }];
    }
    let text = forms.iter().copied().find(|t| fits(t)).unwrap_or(forms[forms.len() - 1]);
    vec![Mark { x, y, text: text.into() }]
}
