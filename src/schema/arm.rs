//! The arm's parameters (the paper's table, eq. (4.1)) as settings like δ: key, symbol, unit, what
//! each means physically, the paper's value as the default, the slider's span (at least a tenth
//! to ten times the paper's value; damping and friction from 0) and the hard limits with why.
//!
//! The limits: an inertia and the stiffness from a thousandth to a thousand times the paper's
//! value (the range over which `tests/arm_range.rs` checks every result against the δ → 0 limit
//! in closed form); damping and friction from 0 (they may vanish) to a thousand times; the
//! coupling A3 from 0 to ten times (the mass matrix bounds it anyway); the presliding lengths
//! above 0 (Dahl's update is exact for any length). Beyond the stiffness's lower limit the link
//! barely feels the motor: the torque the controller asks grows as 1/K1 (10⁴ N m at a thousandth,
//! 10¹⁶ at 1e-12 N m/rad, 10³⁰⁴ at 1e-300, the edge of a float). A lighter part or a stiffer spring
//! makes the arm's fastest motion faster, and the simulation's step follows it (see
//! `Plant::fastest_rate` and `control::linear::inner_loop_rate`): each decade costs about three
//! times the steps per simulated second. Two checks across parameters
//! (`PlantParameters::validate`), each refused with a one-line reason: the three link inertias
//! make a mass matrix positive definite for every q2, and the arm's fastest motion is at most
//! `PlantParameters::FASTEST_RATE_MAX` (every arm with one setting at an end of its range is).

use super::{Choice, Kind, NumberSpec, Param, Scale, Scope};

/// A number of the arm from `min` (inclusive), the paper's value `default`.
const fn spec(
    default: f64,
    control: [f64; 2],
    scale: Scale,
    [min, max]: [f64; 2],
    allowed: &'static str,
) -> NumberSpec {
    NumberSpec {
        min,
        min_inclusive: true,
        max,
        allowed: Some(allowed),
        control,
        scale,
        digits: 3,
        integer: false,
        default,
    }
}

/// A number of the arm above 0 (exclusive), the paper's value `default`.
const fn positive(default: f64, control: [f64; 2], scale: Scale, max: f64, allowed: &'static str) -> NumberSpec {
    NumberSpec { min_inclusive: false, ..spec(default, control, scale, [0.0, max], allowed) }
}

const fn arm(
    key: &'static str,
    label: &'static str,
    symbol: &'static str,
    unit: &'static str,
    name: &'static str,
    spec: NumberSpec,
    help: &'static str,
) -> Param {
    Param { key, label, symbol, unit, name, kind: Kind::Number(spec), scope: Scope::Run, help }
}

/// Why an inertia stops at a thousandth and a thousand times the paper's value.
macro_rules! inertia {
    ($range:literal) => {
        concat!(
            "must be from ",
            $range,
            " kg m² (an inertia, a thousandth to a thousand times the paper's value: a lighter part moves faster, and \
             the simulation's step follows the fastest motion)"
        )
    };
}
const DAMPING: &str = "must be ≥ 0 (damping takes energy out) and at most a thousand times the paper's value";
const COULOMB: &str = "must be ≥ 0 (a friction level) and at most a thousand times the paper's value";
const LENGTH: &str = "must be > 0 (the friction's presliding length) and at most 0.1 rad";

/// A1, kg m².
pub const A1: Param = arm(
    "a1",
    "Link inertia A1",
    "A1",
    "kg m²",
    "a1 (A1)",
    spec(4.984, [0.4, 50.0], Scale::Log, [4.984e-3, 4984.0], inertia!("0.004984 to 4984")),
    "Inertia of both links about joint 1 with link 2 at a right angle (q2 = ±π/2, where cos q2 = 0): the mass matrix's M11 = A1 + 2 A3 cos q2.",
);

/// A2, kg m².
pub const A2: Param = arm(
    "a2",
    "Link-2 inertia A2",
    "A2",
    "kg m²",
    "a2 (A2)",
    spec(0.247, [0.024, 2.5], Scale::Log, [2.47e-4, 247.0], inertia!("0.000247 to 247")),
    "Inertia of link 2 about its own joint.",
);

/// A3, kg m².
pub const A3: Param = arm(
    "a3",
    "Coupling A3",
    "A3",
    "kg m²",
    "a3 (A3)",
    spec(
        0.328,
        [0.0, 3.28],
        Scale::Linear,
        [0.0, 3.28],
        "must be ≥ 0 and at most ten times the paper's value, and A3² < A1·A2 − A2² (the mass matrix positive definite)",
    ),
    "How the links' inertia coupling changes with the elbow angle (A3 cos q2 in the mass matrix): at 0 the cos q2 and Coriolis terms vanish, but the links still push on each other through M12 = A2.",
);

/// Ir1, kg m².
pub const IR1: Param = arm(
    "ir1",
    "Motor inertia I_r1",
    "I_r1",
    "kg m²",
    "ir1 (I_r1)",
    spec(1.939, [0.19, 20.0], Scale::Log, [1.939e-3, 1939.0], inertia!("0.001939 to 1939")),
    "Inertia of the motor (its rotor and gear) on the motor side of the spring.",
);

/// Bv1, N m s/rad.
pub const BV1: Param = arm(
    "bv1",
    "Motor damping B_v1",
    "B_v1",
    "N m s/rad",
    "bv1 (B_v1)",
    spec(1.40, [0.0, 50.0], Scale::Linear, [0.0, 1400.0], DAMPING),
    "Viscous damping of the motor: a torque against its speed. As δ → 0, Re A4 = 3α/2 − B_v1/(2 I_r1) while \
     the motor swings: enough of it damps the swing with no preliminary feedback.",
);

/// Bv2, N m s/rad.
pub const BV2: Param = arm(
    "bv2",
    "Joint-2 damping B_v2",
    "B_v2",
    "N m s/rad",
    "bv2 (B_v2)",
    spec(0.20, [0.0, 2.0], Scale::Linear, [0.0, 200.0], DAMPING),
    "Viscous damping of joint 2.",
);

/// Fc1, N m.
pub const FC1: Param = arm(
    "fc1",
    "Motor friction F_c1",
    "F_c1",
    "N m",
    "fc1 (F_c1)",
    spec(4.82, [0.0, 50.0], Scale::Linear, [0.0, 4820.0], COULOMB),
    "Coulomb level of the motor's Dahl friction: the torque it takes to keep the motor sliding.",
);

/// Fc2, N m.
pub const FC2: Param = arm(
    "fc2",
    "Joint-2 friction F_c2",
    "F_c2",
    "N m",
    "fc2 (F_c2)",
    spec(1.15, [0.0, 12.0], Scale::Linear, [0.0, 1150.0], COULOMB),
    "Coulomb level of joint 2's Dahl friction.",
);

/// ε1, rad.
pub const EPS1: Param = arm(
    "eps1",
    "Motor presliding ε1",
    "ε1",
    "rad",
    "eps1 (ε1)",
    positive(1e-4, [1e-5, 1e-3], Scale::Log, 0.1, LENGTH),
    "How far the motor turns before its friction reaches the Coulomb level (Dahl's presliding).",
);

/// ε2, rad.
pub const EPS2: Param = arm(
    "eps2",
    "Joint-2 presliding ε2",
    "ε2",
    "rad",
    "eps2 (ε2)",
    positive(1e-4, [1e-5, 1e-3], Scale::Log, 0.1, LENGTH),
    "How far joint 2 turns before its friction reaches the Coulomb level.",
);

/// K1, N m/rad.
pub const K1: Param = arm(
    "k1",
    "Joint stiffness K1",
    "K1",
    "N m/rad",
    "k1 (K1)",
    spec(
        1152.6,
        [115.0, 12000.0],
        Scale::Log,
        [1.1526, 1.1526e6],
        "must be from 1.1526 to 1152600 N m/rad (a spring, a thousandth to a thousand times the paper's value: a softer \
         one barely moves the link, the motor torque asked grows as 1/K1, 10⁴ N m at the lower end; a stiffer one \
         makes the simulation's step follow its resonance)",
    ),
    "Stiffness of the spring between the motor and link 1 (the flexible joint).",
);

/// The arm's parameters in the paper's order.
pub const ARM_PARAMS: [&Param; 11] = [&A1, &A2, &A3, &IR1, &BV1, &BV2, &FC1, &FC2, &EPS1, &EPS2, &K1];

/// True if `key` is one of the arm's parameters.
pub fn is_arm(key: &str) -> bool {
    ARM_PARAMS.iter().any(|p| p.key == key)
}

/// The arm the controller assumes: a model error is the next question after "another arm".
pub const MODEL: Param = Param {
    key: "model",
    label: "The controller assumes",
    symbol: "",
    unit: "",
    name: "the controller's model of the arm (model)",
    kind: Kind::Choice {
        options: &[
            Choice { value: "arm", label: "this arm (an exact model)" },
            Choice { value: "paper", label: "the paper's arm (a model error where this arm differs)" },
        ],
        default: "arm",
    },
    scope: Scope::Run,
    help: "What the predictor, the friction observer and the LQ design know: this arm exactly, or the paper's arm \
           while the real one differs. The paper's Kₚᵣ is fixed either way. Is the loop robust to a wrong stiffness?",
};

/// The arm in words, only what differs from the paper's: "the paper's arm", or
/// "B_v1 = 15 N m s/rad (paper: 1.4)" with every changed part, joined by ", ".
pub fn arm_text(values: &[f64; 11]) -> String {
    let changed: Vec<String> = ARM_PARAMS
        .iter()
        .zip(values)
        .filter_map(|(p, &v)| {
            let n = p.number()?;
            (v != n.default).then(|| {
                let f = super::format_number;
                format!("{} = {} {} (paper: {})", p.symbol, f(v), p.unit, f(n.default))
            })
        })
        .collect();
    if changed.is_empty() {
        "the paper's arm".to_string()
    } else {
        changed.join(", ")
    }
}
