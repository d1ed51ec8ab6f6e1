//! What the page shows, as parameters like any other: the same key in the URL, the state string
//! and a lesson step, so a link or a step of the lesson sets the figures as well as the physics.
//! Page-only ([`Scope::Page`]): the command line ignores them.

use super::{Choice, Kind, NumberSpec, Param, Scale, Scope, Tab};

/// The intro (a first screen for beginners) or the full view.
pub const MODE: Param = Param {
    key: "mode",
    label: "View",
    symbol: "",
    unit: "",
    name: "mode",
    kind: Kind::Choice {
        options: &[
            Choice { value: "intro", label: "Intro: the arm, δ and the feedback" },
            Choice { value: "full", label: "Full: every control and figure" },
        ],
        default: "intro",
    },
    scope: Scope::Page,
    help:
        "The intro shows the arm, its errors, δ and the preliminary feedback; the full view every control and figure.",
};

/// The view a phone shows (a narrow canvas shows one at a time).
pub const TAB: Param = Param {
    key: "tab",
    label: "Shown on a narrow screen",
    symbol: "",
    unit: "",
    name: "tab",
    kind: Kind::Choice {
        options: &[
            Choice { value: Tab::Run.id(), label: Tab::Run.label() },
            Choice { value: Tab::Poles.id(), label: Tab::Poles.label() },
            Choice { value: Tab::Study.id(), label: Tab::Study.label() },
            Choice { value: Tab::Maps.id(), label: Tab::Maps.label() },
        ],
        default: "run",
    },
    scope: Scope::Page,
    help: "A phone shows one view at a time: the arm and its errors, the poles and ρ(δ), the error against δ \
           (with a real robot's sensors and the study drawn), or the stability maps.",
};

/// The page embedded in another (an iframe in a course page): the canvas and a strip of controls.
pub const EMBED: Param = switch(
    "embed",
    "Embedded: the figure and a strip of controls",
    false,
    "For an iframe: the canvas and a strip of controls, nothing else (the views from `views=…`).",
);

/// The width of the time plots' window.
pub const WINDOW: Param = Param {
    key: "window",
    label: "Time window of the error plots",
    symbol: "",
    unit: "s",
    name: "window",
    kind: Kind::Number(NumberSpec {
        min: 1.0,
        min_inclusive: true,
        max: 60.0,
        allowed: Some("must be from 1 to 60 s (the page keeps 60 s of traces)"),
        control: [2.0, 30.0],
        scale: Scale::Log,
        digits: 2,
        integer: false,
        default: 10.0,
    }),
    scope: Scope::Page,
    help: "How many seconds the error plots show: short to see the oscillation, long to see the envelope.",
};

/// The pole plot.
pub const POLES: Param = switch(
    "poles",
    "Show the pole plot (hover or tap a pole)",
    true,
    "The eigenvalues of the sampled loop, with the δ → 0 pair A4.",
);

/// Which plane the pole plot draws.
pub const PLANE: Param = Param {
    key: "plane",
    label: "Pole plot shows",
    symbol: "",
    unit: "",
    name: "plane",
    kind: Kind::Choice {
        options: &[
            Choice { value: "s", label: "s = ln λ / δ (s-plane: stable left of the axis)" },
            Choice { value: "z", label: "λ (z-plane: stable inside the unit circle)" },
        ],
        default: "s",
    },
    scope: Scope::Page,
    help: "s = ln λ / δ against the imaginary axis, or the eigenvalues λ of one period against the unit circle.",
};

/// ρ(δ) at the current α.
pub const RHO: Param = switch(
    "rho",
    "Show ρ(δ) at this α, with the stable windows (click to pick δ)",
    true,
    "The spectral radius along δ, shaded where it is below 1.",
);

/// The two stability maps.
pub const MAP: Param = switch(
    "map",
    "Show the stability maps ρ(δ, α) (click to run there)",
    true,
    "ρ over δ and α without and with preliminary feedback (computed in the background).",
);

/// What the stability maps and ρ(δ) show: ρ per sampling period, or the rate ln ρ/δ per second.
pub const MEASURE: Param = Param {
    key: "measure",
    label: "Maps and ρ(δ) show",
    symbol: "",
    unit: "",
    name: "measure",
    kind: Kind::Choice {
        options: &[
            Choice { value: "rho", label: "ρ per sampling period" },
            Choice { value: "rate", label: "ln ρ/δ per second" },
        ],
        default: "rho",
    },
    scope: Scope::Page,
    help: "ρ per period tends to 1 as δ → 0 for any loop, while ln ρ/δ, in 1/s, compares across δ; both say stable exactly where ρ < 1 ⇔ ln ρ/δ < 0, so the contour is the same.",
};

/// The torque panel.
pub const TORQUE: Param =
    switch("torque", "Show the torques T1, T2 (N m)", false, "The applied torques under the error plots.");

/// log |e| instead of e.
pub const LOG: Param = switch(
    "log",
    "Errors on a log scale, with the slope ln ρ/δ the analysis predicts",
    false,
    "log |e|: an exponential is a straight line, of slope ln ρ/δ.",
);

/// What the controller reads (issue 36): the measured errors, held over each period, beside the
/// true ones, and link 1's velocity beside its estimate.
pub const MEASURED: Param = switch(
    "measured",
    "What the controller reads: the measured errors and the estimated velocity",
    false,
    "With a real robot's sensors on, the error plots add e1, e2 as the controller read them (m − q_d at the \
     sampling instant, held over the period: steps a count high), light under the true errors, and a velocity \
     panel shows link 1's true velocity q̇1 with the controller's estimate of it (the angle differenced over a \
     period, filtered if τ_v > 0, held: a count over δ is its noise), clipped to the true velocity's scale; with \
     the sensors off the controller reads the true state and there is nothing to compare. The CSV always has the \
     measured errors and the velocity estimates (e1_meas … theta_dot_est).",
);

/// What bounds δ from below with these sensors (issue 36), drawn: the study's curves over δ
/// beside ρ(δ).
pub const STUDY: Param = switch(
    "study",
    "Draw the error and T1's noise against δ, with these sensors and with perfect ones",
    false,
    "Two panels beside ρ(δ) (with a real robot's sensors on): over the same δ axis, the slew's largest error and \
     the error at rest, and T1's noise at rest, its peak and the torque limit — each simulated with the sensors \
     (solid) and with perfect ones (grey), and the linear prediction of the noise (dotted). The best δ is ringed; \
     a δ where ρ ≥ 1 is crossed out. The study simulates the slew at 11 δ, a few at a time.",
);

/// The paper's Fig. 2.1 at one sampling instant: the time plots zoomed on it.
pub const PREDICT: Param = switch(
    "predict",
    "Zoom on one sampling instant: what the controller predicts and holds (Fig. 2.1)",
    false,
    "The time plots show three sampling periods around the instant t_n shown: the state measured at t_n, \
     the prediction X_j, U_j over τ = kε, and the torque U_k held one period later. Step ▸ and ◂ walk it.",
);

/// The flexible pair's shape, animated on the arm.
pub const SWING: Param = switch(
    "swing",
    "Show the swing's shape on the arm (the flexible pair's mode, animated)",
    false,
    "How the motor, link 1 and link 2 move in the flexible pair: its eigenvector at this δ, drawn on the arm \
     at rest and turned at the pair's frequency, slowed down.",
);

/// Student mode: what gives the answer away (the verdict and ρ, the stable windows of δ, ρ(δ), the
/// maps, the predicted slope) stays hidden until the student has answered the lesson step's
/// question, or met its goal.
pub const ANSWERS: Param = Param {
    key: "answers",
    label: "Verdict, ρ and the stable windows",
    symbol: "",
    unit: "",
    name: "answers",
    kind: Kind::Choice {
        options: &[
            Choice { value: "shown", label: "Shown" },
            Choice { value: "hidden", label: "Hidden until answered (student mode)" },
        ],
        default: "shown",
    },
    scope: Scope::Page,
    help: "For homework and exams: `answers=hidden` hides the verdict, ρ, the stable windows, ρ(δ) and the maps \
           until the student has answered the lesson step's question or met its goal.",
};

/// Presentation mode: the figure fills the screen, the verdict sits in a corner and the controls
/// fold into a small bar; the figure's text grows with the screen (see `text`).
pub const PRESENT: Param = switch(
    "present",
    "Presentation mode: the figure fills the screen",
    false,
    "For a projector: the figure alone over the whole screen (full screen where the browser allows), the \
     verdict in a corner, a small bar of controls, and text at least 18 px on a 1080-line screen.",
);

/// How large the figure's text is: every text over the canvas and the gutters it sits in grow
/// together, so the panels lay out as on a smaller screen and nothing overlaps.
pub const TEXT: Param = Param {
    key: "text",
    label: "Figure text",
    symbol: "",
    unit: "",
    name: "text",
    kind: Kind::Choice {
        options: &[
            Choice { value: "normal", label: "Normal (12 px ticks)" },
            Choice { value: "large", label: "Large (×1.25)" },
            Choice { value: "larger", label: "Larger (×1.5)" },
            Choice { value: "largest", label: "Largest (×2)" },
        ],
        default: "normal",
    },
    scope: Scope::Page,
    help: "The size of the figure's labels: larger for the back of a room. In presentation mode Normal is \
           what the screen needs (18 px on a 1080-line screen, 14 px on a 768-line one), each larger size larger \
           again, the bar's text with it.",
};

/// The z-plane's view: half its shorter side in units of λ (0: the default, around the flexible
/// pair), and its centre (`zre`, `zim`). The page's zoom and pan write them, so a link shows the
/// same part of the plane.
pub const ZSIZE: Param = Param {
    key: "zsize",
    label: "z-plane's zoom: half its shorter side",
    symbol: "",
    unit: "",
    name: "zsize",
    kind: Kind::Number(NumberSpec {
        min: 0.0,
        min_inclusive: true,
        max: 1.2,
        allowed: Some(
            "must be 0 (around the flexible pair) or from 0.0001 (the closest zoom) to 1.2 (the whole circle)",
        ),
        control: [0.0, 1.2],
        scale: Scale::Linear,
        digits: 3,
        integer: false,
        default: 0.0,
    }),
    scope: Scope::Page,
    help: "How much of the z-plane shows: 1.2 the whole unit circle, 0.01 a hundredth of it around `zre`, `zim`; \
           0 (the default) zooms around the flexible pair just enough to see how far it is from the circle.",
};

/// The z-plane view's centre, Re λ (with `zsize` > 0).
pub const ZRE: Param = z_center("zre", "z-plane's centre, Re λ");

/// The z-plane view's centre, Im λ (with `zsize` > 0).
pub const ZIM: Param = z_center("zim", "z-plane's centre, Im λ");

/// A coordinate of the z-plane view's centre.
const fn z_center(key: &'static str, label: &'static str) -> Param {
    Param {
        key,
        label,
        symbol: "",
        unit: "",
        name: key,
        kind: Kind::Number(NumberSpec {
            min: -2.0,
            min_inclusive: true,
            max: 2.0,
            allowed: Some("must be from −2 to 2"),
            control: [-2.0, 2.0],
            scale: Scale::Linear,
            digits: 4,
            integer: false,
            default: 0.0,
        }),
        scope: Scope::Page,
        help:
            "The centre of the z-plane's view (Re λ, Im λ), used when `zsize` is not 0; the view is kept within ±1.5.",
    }
}

/// The arm picture. Off only in an embed that shows plots alone (`views=` without `arm`); the
/// page's full view and intro always draw it (they have no control to bring it back).
pub const PICTURE: Param = switch(
    "picture",
    "Show the arm picture",
    true,
    "The arm, its motor and the magnified spring twist, with the reference arm. An embed whose `views=` has no `arm` leaves it out; the page always draws it.",
);

/// The error plots e1, e2 (off only where the figure is to show other panels alone).
pub const ERRORS: Param = switch(
    "errors",
    "Show the tracking errors e1, e2",
    true,
    "The errors of both links against time. An embed whose `views=` has no `traces` leaves them out; the page always draws them.",
);

/// A page-only on/off view parameter.
const fn switch(key: &'static str, label: &'static str, default: bool, help: &'static str) -> Param {
    Param { key, label, symbol: "", unit: "", name: key, kind: Kind::Switch { default }, scope: Scope::Page, help }
}
