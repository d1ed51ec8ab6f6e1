//! Named starting points that reproduce the paper's figures and its remarks, each a state string
//! (the same text as a URL query). Data only: [`super::settings::Settings::apply_preset`] applies
//! one.

/// A named starting point: the paper's figures and two of its remarks.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Preset {
    /// Short identifier used in URLs (`?preset=fig5.3`) and on the command line.
    pub id: &'static str,
    /// One-line description for a student.
    pub title: &'static str,
    /// The same without what it shows (student mode: the settings only, no verdict).
    pub settings_title: &'static str,
    /// The settings it makes, as a state string.
    pub state: &'static str,
}

/// All presets, in the order a student meets them. Each names every setting the paper's model
/// fixes (the paper's arm, friction compensated continuously, the inner loop continuous, k = 12,
/// ε = δ/8), so a preset restores them and the page names a figure only when they hold.
pub const PRESETS: [Preset; 6] = [
    Preset {
        id: "fig5.1",
        title: "Fig. 5.1: δ = 0.04 s with preliminary feedback (satisfactory errors)",
        settings_title: "Fig. 5.1: δ = 0.04 s with preliminary feedback",
        state: "arm=paper&delta=0.04&alpha=2&pf=paper&friction=continuous&inner=continuous&k=12&eps_ratio=8",
    },
    Preset {
        id: "fig5.2",
        title: "Fig. 5.2: δ = 0.01 s with preliminary feedback (smaller errors)",
        settings_title: "Fig. 5.2: δ = 0.01 s with preliminary feedback",
        state: "arm=paper&delta=0.01&alpha=2&pf=paper&friction=continuous&inner=continuous&k=12&eps_ratio=8",
    },
    Preset {
        id: "fig5.3",
        title: "Fig. 5.3: δ = 0.01 s without preliminary feedback (unstable)",
        settings_title: "Fig. 5.3: δ = 0.01 s without preliminary feedback",
        state: "arm=paper&delta=0.01&alpha=2&pf=off&friction=continuous&inner=continuous&k=12&eps_ratio=8",
    },
    Preset {
        id: "large-delta",
        title: "Large δ works without preliminary feedback (δ = 0.06 s)",
        settings_title: "δ = 0.06 s without preliminary feedback",
        state: "arm=paper&delta=0.06&alpha=2&pf=off&friction=continuous&inner=continuous&k=12&eps_ratio=8",
    },
    Preset {
        id: "small-alpha",
        title: "Smaller α slows the growth (α = 0.5, no preliminary feedback)",
        settings_title: "α = 0.5, no preliminary feedback",
        state: "arm=paper&delta=0.01&alpha=0.5&pf=off&friction=continuous&inner=continuous&k=12&eps_ratio=8",
    },
    Preset {
        id: "real-encoder",
        title: "A real robot: a 1024-count encoder, velocities differenced, torque ≤ 150 N m (δ = 0.01 s, K_pr on)",
        settings_title: "A 1024-count encoder, velocities differenced, torque ≤ 150 N m, δ = 0.01 s",
        state: "arm=paper&delta=0.01&alpha=2&pf=paper&friction=continuous&inner=continuous&k=12&eps_ratio=8\
                &encoder=1024&velocity=difference&torque_limit=150",
    },
];

/// An arm a teacher reaches for: the paper's arm with one part changed.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ArmPreset {
    /// `arm=ID` in a state string, `--arm ID` on the command line.
    pub id: &'static str,
    pub title: &'static str,
    /// The arm parameters it changes from the paper's (schema keys).
    pub set: &'static [(&'static str, f64)],
}

impl ArmPreset {
    /// The arm: the paper's with this preset's changes.
    pub fn plant(&self) -> crate::model::PlantParameters {
        let mut p = crate::model::PlantParameters::default();
        for (key, v) in self.set {
            p.set(key, *v);
        }
        p
    }
}

/// The arm presets (the arm's own keys change an arm further).
pub const ARMS: [ArmPreset; 6] = [
    ArmPreset { id: "paper", title: "The paper's arm", set: &[] },
    ArmPreset { id: "stiffer", title: "Stiffer spring (K1 × 4)", set: &[("k1", 4610.4)] },
    ArmPreset { id: "softer", title: "Softer spring (K1 ÷ 4)", set: &[("k1", 288.15)] },
    ArmPreset { id: "lighter", title: "Lighter motor (I_r1 ÷ 4)", set: &[("ir1", 0.48475)] },
    ArmPreset { id: "heavier", title: "Heavier motor (I_r1 × 4)", set: &[("ir1", 7.756)] },
    // B_v1 > 3 α I_r1 = 11.6 N m s/rad at α = 2 makes Re A4 < 0 (the story's damping_needed).
    ArmPreset { id: "damped", title: "Damped motor (B_v1 = 15 N m s/rad)", set: &[("bv1", 15.0)] },
];

/// The arm preset with identifier `id`.
pub fn arm(id: &str) -> Option<&'static ArmPreset> {
    ARMS.iter().find(|p| p.id == id)
}

/// The preset with identifier `id`.
pub fn preset(id: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.id == id)
}
