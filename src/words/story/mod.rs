//! The explanation's numbers, live: every number the page's "why" text quotes about the current
//! settings, formatted from run A's analysis (the report the verdict and the pole plot show), so
//! the words and the figures cannot disagree. The page puts each into the `data-live` element of
//! the same name.

//!
//! `build.rs` makes the story from the analysis; `phrases.rs` holds the sentences it is made of
//! that need a decision of their own (the phase, the swing's energy, the cure and its reason).

use serde::Serialize;

mod build;
mod phrases;

pub use build::story;
pub use phrases::{gains_fail_because, phase_words};

/// The numbers of the explanation, as text with units.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Story {
    /// "α = 2 1/s", or "α1 = 0.5, α2 = 2 1/s".
    pub alpha: String,
    /// The rest point the analysis is linearized at: "q2 = 0 rad".
    pub rest: String,
    /// The arm's own pair, no controller, the friction cancelled: "−0.29 ± 29.36j 1/s".
    pub arm_pair: String,
    /// √(K1 (1/Ir1 + 1/J_eff)) and √(K1/Ir1): "29.40 rad/s (4.68 Hz)", "24.4 rad/s".
    pub omega_joint: String,
    /// The arm's own ringing, named as such for the explanation's short form: "29.40 rad/s
    /// (4.68 Hz) for the arm alone". The controller moves it a little (A4, [`Story::omega_a4`]),
    /// the sampled loop a little more ([`Story::loop_pair`]): three frequencies, each named.
    pub omega_arm: String,
    /// Where k is below the DAE's index: what of the explanation does not hold then. Empty otherwise.
    pub horizon_note: String,
    /// Which viscous friction damps the arm's own pair, with what each alone would give.
    pub arm_damping: String,
    /// "In short"'s last sentence: why some larger δ work without K_pr (the lag), or, where the
    /// pair dies out as δ → 0 without it, that no lag is needed.
    pub short_lag: String,
    /// "In short"'s disease, for the arm and α shown: whether steering the links feeds the swing,
    /// whether that beats the motor's damping, and where the pair goes as δ → 0.
    pub short_feed: String,
    pub omega_clamped: String,
    /// J_eff: "4.30 kg m²".
    pub j_eff: String,
    /// A4 without preliminary feedback: "2.64 ± 29.58j 1/s"; its trace and determinant.
    pub a4: String,
    pub a4_trace: String,
    pub a4_det: String,
    /// Re A4 and its two parts: the controller's feed 3β/2 and the motor's damping Bv1/(2 Ir1).
    pub re_a4: String,
    pub feed: String,
    pub motor_damping: String,
    /// What the sign of the controller's part and of Re A4 mean, in words.
    pub feed_says: String,
    pub re_a4_says: String,
    /// μ and β = α1 + μ (α1 − α2) at the rest point.
    pub mu: String,
    pub beta: String,
    /// The six poles the limit controller places: "−2 1/s, all six".
    pub six_poles: String,
    /// How much faster link 2's law must be for the controller to drain the resonance:
    /// α2 > α1 (1 + μ)/μ, "4.21 α1".
    pub alpha2_drain: String,
    /// α* = Bv1/(3 Ir1).
    pub alpha_star: String,
    /// What α = 0.2 1/s (the explanation's Try button) does on this arm: below or above α*, and
    /// the pair A4 it leaves as δ → 0.
    pub alpha_small: String,
    /// Run A's δ, ρ, ln ρ/δ and its flexible loop pole at that δ.
    pub delta: String,
    pub rho: String,
    pub growth: String,
    pub loop_pair: String,
    /// What the sampled pair tends to as δ → 0: "A4 — the ring in the pole plot", or with a
    /// preliminary feedback "A4 with K_pr — the diamond in the pole plot".
    pub loop_limit: String,
    /// Which mode sets ρ: "the flexible pair", or "another mode, at s = −1.95 1/s".
    pub rho_set_by: String,
    /// The paper's K_pr on the pair (acting continuously): its shift of the pair's real part, the
    /// parts of it through T1 and T2, the pair it makes, and the largest α (α1 = α2) it keeps
    /// stable.
    pub kpr_shift: String,
    pub kpr_shift_t1: String,
    pub kpr_shift_t2: String,
    pub kpr_pair: String,
    pub kpr_alpha_limit: String,
    /// The paper's K_pr's shift of Re A4 on this arm at the two ends of the rest points: "−5.12 1/s
    /// at q2 = 0, −4.28 1/s at q2 = π".
    pub kpr_shift_rest: String,
    /// What the minimum-energy LQ design does to the pair, with the pair it makes.
    pub lq_says: String,
    /// Whether the paper's K_pr makes every small δ work at these α: what the pair it makes says.
    pub kpr_works: String,
    /// The cure in one sentence for "In short", true on the arm and α shown: where the paper's
    /// K_pr makes every small δ work (α below its bound on this arm), or why it does not here.
    pub kpr_cure: String,
    /// The arm, only what differs from the paper's: "the paper's arm", "K1 = 4610.4 N m/rad (paper: 1152.6)".
    pub arm: String,
    /// The motor damping that makes Re A4 < 0 with no preliminary feedback, B_v1 > 3β I_r1
    /// (3α I_r1 when α1 = α2), and this arm's.
    pub damping_needed: String,
    /// Next to the K_pr control: the paper's gains were designed for the paper's arm at α = 2;
    /// empty where that is what runs.
    pub kpr_note: String,
    /// Where the controller assumes the paper's arm on another arm (`model = paper`): where the
    /// loop goes as δ → 0 instead of A4, which the closed forms describe for a controller that
    /// knows the arm. Empty without a model error.
    pub model_note: String,
    /// Why some larger δ work (the lag law, [`crate::analysis::lag`]): ω = |Im A4| in rad/s and
    /// Hz, how far the swing turns per period (ωδ) and by the time the torque acts (1.5 ωδ),
    /// the growth the law predicts, and its window of δ.
    pub omega_a4: String,
    pub turn: String,
    pub lag: String,
    pub lag_growth: String,
    pub lag_window: String,
    /// How far to trust the lag law: its bias measured over a grid ([`crate::analysis::lag`]'s
    /// constants) and whether this arm at these α lies in the grid's domain.
    pub lag_bias: String,
    /// The loop's own rate beside the law's estimate: the law is made for the loop without K_pr, so
    /// with K_pr on the run's ln ρ/δ is another loop's.
    pub lag_compare: String,
    /// The mechanism at this δ, computed ([`crate::analysis::energy`]): how far the held torque
    /// lags the swing and what share of the swing's energy it, the preliminary feedback and the
    /// arm's damping put in or take out each period. Empty without a flexible pair.
    pub energy: String,
    /// The same numbers as equations (MathML, [`super::equations`]) for the page's `data-math`
    /// elements: the law (4.3), Re A4, ρ, ln ρ/δ and the lag law.
    pub math_constraint: String,
    pub math_re_a4: String,
    pub math_rho: String,
    pub math_growth: String,
    pub math_lag: String,
    pub math_energy: String,
    /// Section 3's structure (V*, the zero dynamics Ā1, the quotient A4, the index, k), one sentence
    /// each ([`super::structure`]); empty until [`Story::with_structure`] fills them.
    pub structure_v_star: String,
    pub structure_zero_dynamics: String,
    pub structure_quotient: String,
    pub structure_index: String,
    pub structure_horizon: String,
}

impl Story {
    /// The story with Section 3's sentences of `words` (computed apart: the structure costs more
    /// than the rest of the story, so the session caches it with the analysis).
    pub fn with_structure(mut self, words: Option<crate::words::structure::StructureWords>) -> Self {
        if let Some(w) = words {
            self.structure_v_star = w.v_star;
            self.structure_zero_dynamics = w.zero_dynamics;
            self.structure_quotient = w.quotient;
            self.structure_index = w.index;
            self.structure_horizon = w.horizon;
        }
        self
    }
}
