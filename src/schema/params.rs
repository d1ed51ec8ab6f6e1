//! The table: every parameter, once.

use super::{Choice, Kind, NumberSpec, Param, Scale, Scope};

/// The numbers of δ (also the default map and window range).
pub const DELTA_SPEC: NumberSpec = NumberSpec {
    // Below 1e-5 s nothing new can be seen: the loop is at its δ → 0 limit (the pair A4 decides,
    // ρ − 1 ≈ 2.6 δ is under 3e-5), and one simulated second costs over 10⁵ predictions.
    min: 1e-5,
    min_inclusive: true,
    max: 10.0,
    allowed: Some(
        "must be from 1e-5 s to 10 s (below 1e-5 s the loop is at its δ → 0 limit, where the pair A4 decides, \
         and a simulated second needs over 10⁵ predictions)",
    ),
    control: [0.002, 0.25],
    scale: Scale::Log,
    digits: 3,
    integer: false,
    default: 0.01,
};

/// The numbers of α1, α2 (also the default map range).
pub const ALPHA_SPEC: NumberSpec = NumberSpec {
    // Below 1e-3 1/s the law lets an error linger e-fold over more than 1000 s, beyond any run,
    // and the loop's triple eigenvalue e^{−αδ} sits closer to 1 than an eigen-solver resolves a
    // triple root (≈ 1e-5): ρ against 1 means nothing there (from 1e-7 1/s the search for the
    // stable windows flips on rounding alone).
    min: 1e-3,
    min_inclusive: true,
    max: 1000.0,
    allowed: Some(
        "must be from 0.001 to 1000 1/s (below 0.001 1/s an error would take over 1000 s to shrink e-fold, \
         longer than any run, and the loop's triple eigenvalue at −α is closer to 1 than its computation can \
         resolve)",
    ),
    control: [0.1, 5.0],
    scale: Scale::Log,
    digits: 3,
    integer: false,
    default: 2.0,
};

const PF_OPTIONS: &[Choice] = &[
    Choice { value: "off", label: "off (original controller)" },
    Choice { value: "paper", label: "paper K_pr" },
    Choice { value: "lq", label: "LQ design" },
    Choice { value: "twist", label: "twist damper (your own gains)" },
];

/// δ, the sampling period.
pub const DELTA: Param = Param {
    key: "delta",
    label: "Sampling period δ",
    symbol: "δ",
    unit: "s",
    name: "sampling_period (δ)",
    kind: Kind::Number(DELTA_SPEC),
    scope: Scope::Run,
    help: "The controller measures the arm every δ seconds and applies the torque it predicted one period later, \
           held for δ.",
};

/// α1 = α2 at once (a shorthand on the command line and in URLs).
pub const ALPHA: Param = Param {
    key: "alpha",
    label: "Error decay rate α (both links)",
    symbol: "α",
    unit: "1/s",
    name: "alpha (α1 = α2)",
    kind: Kind::Number(ALPHA_SPEC),
    scope: Scope::Run,
    help: "Sets α1 = α2: each link error is asked to obey (d/dt + α)³ e = 0, three poles at −α.",
};

/// α1, the error decay rate of link 1.
pub const ALPHA1: Param = Param {
    key: "alpha1",
    label: "Error decay rate α1 (link 1)",
    symbol: "α1",
    unit: "1/s",
    name: "alpha1 (α1)",
    kind: Kind::Number(ALPHA_SPEC),
    scope: Scope::Run,
    help: "The stabilizing polynomial p(s) = (s + α1)³ of link 1's error, eq. (4.3).",
};

/// α2, the error decay rate of link 2.
pub const ALPHA2: Param = Param {
    key: "alpha2",
    label: "Error decay rate α2 (link 2)",
    symbol: "α2",
    unit: "1/s",
    name: "alpha2 (α2)",
    kind: Kind::Number(ALPHA_SPEC),
    scope: Scope::Run,
    help: "The stabilizing polynomial p(s) = (s + α2)³ of link 2's error, eq. (4.3).",
};

/// The preliminary feedback u = K_pr x + v.
pub const PF: Param = Param {
    key: "pf",
    label: "Preliminary feedback K_pr",
    symbol: "K_pr",
    unit: "",
    name: "preliminary feedback (pf)",
    kind: Kind::Choice { options: PF_OPTIONS, default: "paper" },
    scope: Scope::Run,
    help: "A fixed linear state feedback under the predictive controller: off (Jankowski–Van Brussel), the \
           paper's K_pr, or this program's LQ design.",
};

/// A twist feedback gain: from 0 (no feedback) to 1000, the page's control over [0, `control_max`].
const fn gain_spec(control_max: f64, default: f64) -> NumberSpec {
    NumberSpec {
        min: 0.0,
        min_inclusive: true,
        max: 1000.0,
        allowed: None,
        control: [0.0, control_max],
        scale: Scale::Linear,
        digits: 3,
        integer: false,
        default,
    }
}

/// k_p of the twist feedback (`pf = twist`).
pub const TWIST_STIFFNESS: Param = Param {
    key: "twist_stiffness",
    label: "Twist stiffness k_p",
    symbol: "k_p",
    unit: "N m/rad",
    name: "twist_stiffness (k_p)",
    kind: Kind::Number(gain_spec(400.0, 0.0)),
    scope: Scope::Run,
    help: "With pf = twist: a spring between motor and link 1, applied by the motor, T1 += k_p (q1 − θ). It moves \
           the swing's frequency, not its damping.",
};

/// k_d of the twist feedback (`pf = twist`).
pub const TWIST_DAMPING: Param = Param {
    key: "twist_damping",
    label: "Twist damping k_d",
    symbol: "k_d",
    unit: "N m s/rad",
    name: "twist_damping (k_d)",
    kind: Kind::Number(gain_spec(200.0, 16.0)),
    scope: Scope::Run,
    help: "With pf = twist: a damper between motor and link 1, applied by the motor, T1 += k_d (q̇1 − θ̇). The \
           swing's real part is Re A4 = 3α/2 − (Bv1 + k_d)/(2 Ir1): damped for k_d > 3α Ir1 − Bv1 (as δ → 0); \
           a stronger damper first stops the motor swinging (two real eigenvalues, still stable) and, further up, \
           where det A4 = 0, lets a slow real mode grow.",
};

/// An LQ weight: positive, on a log scale over [`control`] (the limits a decade beyond it each way).
const fn weight_spec(control: [f64; 2], default: f64) -> NumberSpec {
    NumberSpec {
        min: control[0] / 10.0,
        min_inclusive: true,
        max: control[1] * 10.0,
        allowed: None,
        control,
        scale: Scale::Log,
        digits: 2,
        integer: false,
        default,
    }
}

/// Q's weight on the swing's coordinate of the LQ design (`pf = lq`).
pub const LQ_TWIST_WEIGHT: Param = Param {
    key: "lq_q_twist",
    label: "LQ weight on the twist q_z",
    symbol: "q_z",
    unit: "",
    name: "lq_q_twist (Q on the gap z)",
    kind: Kind::Number(weight_spec([1e-6, 1e5], 1e-6)),
    scope: Scope::Run,
    help: "With pf = lq: the LQ design's weight on the motor's gap z from the angle the links' law needs (the \
           pair A4's first coordinate, a twist). Larger pulls the pair further left, with more torque; the \
           default 1e-6 is the paper's minimum-energy design, which only mirrors an unstable pair.",
};

/// Q's weight on the swing's rate.
pub const LQ_RATE_WEIGHT: Param = Param {
    key: "lq_q_rate",
    label: "LQ weight on the twist rate q_y",
    symbol: "q_y",
    unit: "",
    name: "lq_q_rate (Q on its rate)",
    kind: Kind::Number(weight_spec([1e-6, 1e5], 1e-6)),
    scope: Scope::Run,
    help: "With pf = lq: the LQ design's weight on the motor's speed against the law's (the pair A4's second \
           coordinate, a twist rate). Larger damps the swing harder.",
};

/// R's weight on T1 (T2's is 6.7 times it).
pub const LQ_TORQUE_WEIGHT: Param = Param {
    key: "lq_r",
    label: "LQ torque weight r",
    symbol: "r",
    unit: "",
    name: "lq_r (R on T1; T2 6.7×)",
    kind: Kind::Number(weight_spec([1e-3, 1e3], 1.0)),
    scope: Scope::Run,
    help: "With pf = lq: the LQ design's weight on the motor torque T1 (T2's is 6.7 times it, as in the paper's \
           gain). Only its ratio to the state weights counts: larger asks for less torque.",
};

/// The friction compensation T = v + x̂f, eq. (4.4).
pub const FRICTION: Param = Param {
    key: "friction",
    label: "Friction compensation x̂f",
    symbol: "x̂f",
    unit: "",
    name: "friction compensation (friction)",
    kind: Kind::Choice {
        options: &[
            Choice { value: "continuous", label: "continuous (paper)" },
            Choice { value: "held", label: "held over δ" },
            Choice { value: "off", label: "off" },
        ],
        default: "continuous",
    },
    scope: Scope::Run,
    help: "How the observed Dahl friction is fed forward: continuously (cancels it), held over each period, or \
           not at all.",
};

/// Continuous or sampled inner loop.
pub const INNER: Param = Param {
    key: "inner",
    label: "Inner loop u = K_pr x + v",
    symbol: "",
    unit: "",
    name: "inner loop (inner)",
    kind: Kind::Choice {
        options: &[
            Choice { value: "continuous", label: "continuous" },
            Choice { value: "sampled", label: "sampled at δ" },
        ],
        default: "continuous",
    },
    scope: Scope::Run,
    help: "Whether the preliminary feedback acts continuously (analog) or is sampled and held at δ.",
};

/// Where the linear analysis linearizes the loop.
pub const REST: Param = Param {
    key: "rest",
    label: "Linearize at",
    symbol: "",
    unit: "",
    name: "rest point of the analysis (rest)",
    kind: Kind::Choice {
        options: &[
            Choice { value: "end", label: "where the slew ends (q2 = 0 rad)" },
            Choice { value: "arm", label: "where the arm is headed (follows the repeating slew)" },
        ],
        default: "end",
    },
    scope: Scope::Run,
    help: "The analysis (ρ, the poles, the windows of δ, the maps) holds for small motions about one rest point, \
           with the friction cancelled: where the slew ends, or the end of the slew under way, \
           which under the repeating slew alternates between q2 = 0 and 3π/2 rad. Only the analysis moves: \
           the preliminary feedback keeps its fixed gains (the paper's gain scheduling would redesign K_pr at \
           an updated operating point; this setting does not).",
};

/// The repeating there-and-back slew.
pub const REPEAT: Param = Param {
    key: "repeat",
    label: "Repeat the slew (there and back, hold 1.5 s)",
    symbol: "",
    unit: "",
    name: "repeat",
    kind: Kind::Switch { default: false },
    scope: Scope::Run,
    help: "Slew there and back again and again (holding 1.5 s at each end) instead of the paper's single slew.",
};

/// k, the horizon steps.
pub const K: Param = Param {
    key: "k",
    label: "Horizon steps k",
    symbol: "k",
    unit: "",
    name: "k (horizon steps)",
    kind: Kind::Number(NumberSpec {
        min: 1.0,
        min_inclusive: true,
        max: 1000.0,
        allowed: Some(
            "must be an integer from 1 to 1000 (the paper asks k above the DAE's index 3; below it the applied \
             torque keeps the DAE's impulsive start, which you may try)",
        ),
        control: [4.0, 24.0],
        scale: Scale::Linear,
        digits: 2,
        integer: true,
        default: 12.0,
    }),
    scope: Scope::Run,
    help: "The predictor takes k backward-Euler steps of ε = δ/m; δ ≤ kε ≤ 2δ, i.e. k/2 ≤ m ≤ k. The paper asks k \
           above the DAE's index 3: its first two torques are impulsive (the DAE jumps to consistency), and with \
           k = 1 or 2 the applied torque is one of them.",
};

/// m, so that ε = δ/m.
pub const EPS_RATIO: Param = Param {
    key: "eps_ratio",
    label: "Step ratio m = δ/ε",
    symbol: "m",
    unit: "",
    name: "eps_ratio (m = δ/ε)",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: false,
        max: 1000.0,
        allowed: None,
        control: [2.0, 24.0],
        scale: Scale::Linear,
        digits: 3,
        integer: false,
        default: 8.0,
    }),
    scope: Scope::Run,
    help: "The predictor's step is ε = δ/m; with k steps the horizon kε must lie between δ and 2δ.",
};

/// Simulated time of a command-line run.
pub const DURATION: Param = Param {
    key: "duration",
    label: "Duration",
    symbol: "",
    unit: "s",
    name: "duration",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: true,
        max: 1e6,
        allowed: Some("must be a finite number ≥ 0 s (at most 1e6 s)"),
        control: [1.0, 60.0],
        scale: Scale::Log,
        digits: 3,
        integer: false,
        default: 4.0,
    }),
    scope: Scope::Cli,
    help: "Simulated time: by default the 1-s slew and 3 s after it.",
};

/// Spacing of the recorded traces.
pub const OUTPUT_INTERVAL: Param = Param {
    key: "output_interval",
    label: "Trace spacing",
    symbol: "",
    unit: "s",
    name: "output_interval",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: false,
        max: 10.0,
        allowed: None,
        control: [0.001, 0.1],
        scale: Scale::Log,
        digits: 3,
        integer: false,
        default: 0.002,
    }),
    scope: Scope::Cli,
    help: "Spacing of the recorded time series, s (rounded to whole plant steps).",
};

/// The link-2 angle of the rest point of the analysis.
pub const Q2: Param = Param {
    key: "q2",
    label: "Rest angle q2",
    symbol: "q2",
    unit: "rad",
    name: "q2",
    kind: Kind::Number(NumberSpec {
        min: -1e3,
        min_inclusive: true,
        max: 1e3,
        allowed: Some("must be a finite angle in rad"),
        control: [-3.2, 3.2],
        scale: Scale::Linear,
        digits: 4,
        integer: false,
        default: 0.0,
    }),
    scope: Scope::Cli,
    help: "Link-2 angle of the rest point the loop is linearized at, rad (default: the end of the slew, 0).",
};

/// Playback speed of the page.
pub const SPEED: Param = Param {
    key: "speed",
    label: "Playback speed",
    symbol: "",
    unit: "×",
    name: "speed",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: false,
        max: 100.0,
        allowed: None,
        control: [0.1, 4.0],
        scale: Scale::Log,
        digits: 2,
        integer: false,
        default: 1.0,
    }),
    scope: Scope::Page,
    help: "Simulated seconds per wall-clock second.",
};

/// Where a link starts: the run advanced to this time (flat out) before the page shows it.
pub const START_TIME: Param = Param {
    key: "t",
    label: "Start at",
    symbol: "t",
    unit: "s",
    name: "start time",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: true,
        max: 120.0,
        allowed: Some(
            "must be from 0 to 120 s: the run is replayed from rest up to that moment before anything is shown, and \
             a link or a figure should not keep its reader waiting longer",
        ),
        control: [0.0, 120.0],
        scale: Scale::Linear,
        digits: 3,
        integer: false,
        default: 0.0,
    }),
    scope: Scope::Page,
    help: "A link's moment: the run is advanced to t seconds before it is shown (with paused=1 it waits there).",
};

/// A link that starts paused.
pub const PAUSED: Param = Param {
    key: "paused",
    label: "Start paused",
    symbol: "",
    unit: "",
    name: "paused",
    kind: Kind::Switch { default: false },
    scope: Scope::Page,
    help: "A link that opens paused (at t, if it gives one): press Play to run on.",
};

/// Two runs side by side.
pub const COMPARE: Param = Param {
    key: "compare",
    label: "Compare two runs side by side",
    symbol: "",
    unit: "",
    name: "compare",
    kind: Kind::Switch { default: false },
    scope: Scope::Page,
    help: "Run B beside run A: B shares the slew, friction compensation and inner loop, with its own K_pr, δ, α and, if chosen, arm.",
};

/// Run B's preliminary feedback.
pub const B_PF: Param =
    Param { key: "b_pf", label: "B: preliminary feedback", scope: Scope::Compare, name: "b_pf", ..PF };

/// Run B's sampling period.
pub const B_DELTA: Param =
    Param { key: "b_delta", label: "B: sampling period δ", scope: Scope::Compare, name: "b_delta", ..DELTA };

/// Run B's α1 = α2.
pub const B_ALPHA: Param =
    Param { key: "b_alpha", label: "B: error decay rate α1 = α2", scope: Scope::Compare, name: "b_alpha", ..ALPHA };

/// Run B's arm: A's, or one of the arm presets (`session::ARMS`).
pub const B_ARM: Param = Param {
    key: "b_arm",
    label: "B: the arm",
    symbol: "",
    unit: "",
    name: "b_arm",
    kind: Kind::Choice {
        options: &[
            Choice { value: "same", label: "A's arm" },
            Choice { value: "paper", label: "the paper's arm" },
            Choice { value: "stiffer", label: "stiffer spring (K1 × 4)" },
            Choice { value: "softer", label: "softer spring (K1 ÷ 4)" },
            Choice { value: "lighter", label: "lighter motor (I_r1 ÷ 4)" },
            Choice { value: "heavier", label: "heavier motor (I_r1 × 4)" },
            Choice { value: "damped", label: "damped motor (B_v1 = 15 N m s/rad)" },
        ],
        default: "same",
    },
    scope: Scope::Compare,
    help: "Run B on another arm: was it luck that the controller worked on the paper's robot?",
};

/// Every parameter, in the order the page shows them and `--help` lists them.
pub const PARAMS: &[&Param] = &[
    &DELTA,
    &ALPHA,
    &ALPHA1,
    &ALPHA2,
    &PF,
    &TWIST_STIFFNESS,
    &TWIST_DAMPING,
    &LQ_TWIST_WEIGHT,
    &LQ_RATE_WEIGHT,
    &LQ_TORQUE_WEIGHT,
    &FRICTION,
    &INNER,
    &REST,
    &REPEAT,
    &K,
    &EPS_RATIO,
    &super::A1,
    &super::A2,
    &super::A3,
    &super::IR1,
    &super::BV1,
    &super::BV2,
    &super::FC1,
    &super::FC2,
    &super::EPS1,
    &super::EPS2,
    &super::K1,
    &super::MODEL,
    &super::ENCODER,
    &super::NOISE,
    &super::SEED,
    &super::VELOCITY,
    &super::VELOCITY_FILTER,
    &super::TORQUE_LIMIT,
    &DURATION,
    &OUTPUT_INTERVAL,
    &Q2,
    &SPEED,
    &START_TIME,
    &PAUSED,
    &COMPARE,
    &B_PF,
    &B_DELTA,
    &B_ALPHA,
    &B_ARM,
    &super::MODE,
    &super::EMBED,
    &super::TAB,
    &super::WINDOW,
    &super::PICTURE,
    &super::ERRORS,
    &super::POLES,
    &super::PLANE,
    &super::RHO,
    &super::MAP,
    &super::MEASURE,
    &super::TORQUE,
    &super::LOG,
    &super::MEASURED,
    &super::STUDY,
    &super::PREDICT,
    &super::SWING,
    &super::ANSWERS,
    &super::ZSIZE,
    &super::ZRE,
    &super::ZIM,
    &super::PRESENT,
    &super::TEXT,
];
