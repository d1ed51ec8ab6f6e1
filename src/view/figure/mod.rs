//! Every figure flexarm writes, for slides and handouts — the one SVG writer: one panel (or the
//! two error plots, or both maps) as a standalone SVG, drawn from the same view geometry as the
//! canvas — a [`Scene`] laid out with only that panel at a figure's size, its triangles written as
//! paths, its labels as texts with the page's sizes and alignments, its key, and a caption with
//! what it shows and the whole state string (never cut: it takes as many lines as it needs), on
//! one sheet for all (`sheet.rs`).
//!
//! The page's figures are drawn from its session ([`figure_svg`]): the page rasterizes the SVG for
//! a PNG at 1×, 2× or 4× (`www/js/export.js`) and `flexarm figure` writes the same SVG. The
//! command line's figures are drawn from what a command has: `flexarm simulate --svg` a run's
//! errors over its whole duration ([`errors_figure`]), `flexarm map --svg` the maps on the user's
//! grid ([`maps_figure`]).
//!
//! Always on the light background unless the dark scheme is asked for (then every colour is
//! inverted in lightness, as the canvas's shader does).
//!
//! In student mode the panels that give the answer away (the pole plots, ρ(δ), the maps) are
//! refused while the answers are hidden, as the page's other downloads are; the error plots follow
//! what the page draws (no log |e| then).

// The command line's figures are not in the page's module: nothing there draws them, and without
// them the sheet's functions have one caller there, inlined as the page's figure was before the
// command line shared them (the module does not grow).
#[cfg(not(target_arch = "wasm32"))]
mod command_line;
mod key;
mod layout;
mod options;
mod sheet;
mod svg;

use crate::error::{Error, ParseError};
use crate::plot::palette;
use crate::session::{MapSide, Session};
use crate::view::layout::PanelKind;
use crate::view::panels::time_plots::figure_curves;
use crate::view::scene::{Scene, ViewOptions};
use key::curve_key;
pub use options::{CaptionChoice, FigureOptions, Shape, WIDE_RATIO, WIDE_WIDTH};
use sheet::{at_time, Sheet, Words};
pub use svg::Background;

#[cfg(not(target_arch = "wasm32"))]
pub use command_line::{errors_figure, maps_figure, ENVELOPE_ROWS};
pub use sheet::Figure;
pub use svg::px;

/// What a figure shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FigurePanel {
    Arm,
    ArmB,
    /// e1 and e2, stacked on one time axis.
    Errors,
    E1,
    E2,
    Torque,
    /// Link 1's velocity, true and as the controller estimated it (the `measured` switch with
    /// digital sensors).
    Velocity,
    /// The pole plot in the s-plane.
    Poles,
    ZPlane,
    Rho,
    MapOff,
    MapOn,
    /// Both maps side by side.
    Maps,
    /// The sensor study's two panels side by side: the error and T1 against δ (the `study`
    /// switch with digital sensors).
    Study,
}

impl FigurePanel {
    pub const ALL: [FigurePanel; 14] = [
        FigurePanel::Arm,
        FigurePanel::ArmB,
        FigurePanel::Errors,
        FigurePanel::E1,
        FigurePanel::E2,
        FigurePanel::Torque,
        FigurePanel::Velocity,
        FigurePanel::Poles,
        FigurePanel::ZPlane,
        FigurePanel::Rho,
        FigurePanel::MapOff,
        FigurePanel::MapOn,
        FigurePanel::Maps,
        FigurePanel::Study,
    ];

    /// The name in `flexarm figure --panel NAME`, the page's choice and the file's name.
    pub fn id(self) -> &'static str {
        match self {
            FigurePanel::Arm => "arm",
            FigurePanel::ArmB => "arm-b",
            FigurePanel::Errors => "errors",
            FigurePanel::E1 => "e1",
            FigurePanel::E2 => "e2",
            FigurePanel::Torque => "torque",
            FigurePanel::Velocity => "velocity",
            FigurePanel::Poles => "poles",
            FigurePanel::ZPlane => "zplane",
            FigurePanel::Rho => "rho",
            FigurePanel::MapOff => "map-off",
            FigurePanel::MapOn => "map-on",
            FigurePanel::Maps => "maps",
            FigurePanel::Study => "study",
        }
    }

    /// Every name, for messages: "arm, arm-b, errors, …".
    pub fn names() -> String {
        FigurePanel::ALL.map(FigurePanel::id).join(", ")
    }

    /// A figure by its name (or by the canvas's panel id: "z-plane", "rho-curve").
    pub fn parse(name: &str) -> Result<FigurePanel, Error> {
        let name = name.trim().to_ascii_lowercase();
        let alias = match name.as_str() {
            "z-plane" | "z" => "zplane",
            "rho-curve" | "ρ" => "rho",
            "s-plane" | "s" | "pole-plot" => "poles",
            "torques" => "torque",
            n => n,
        };
        FigurePanel::ALL.into_iter().find(|p| p.id() == alias).ok_or_else(|| {
            Error::Parse(ParseError { key: "panel".into(), text: name, expected: format!("one of {}", Self::names()) })
        })
    }

    /// The canvas's panels it shows.
    pub fn kinds(self) -> &'static [PanelKind] {
        match self {
            FigurePanel::Arm => &[PanelKind::Arm],
            FigurePanel::ArmB => &[PanelKind::ArmB],
            FigurePanel::Errors => &[PanelKind::Error1, PanelKind::Error2],
            FigurePanel::E1 => &[PanelKind::Error1],
            FigurePanel::E2 => &[PanelKind::Error2],
            FigurePanel::Torque => &[PanelKind::Torque],
            FigurePanel::Velocity => &[PanelKind::Velocity],
            FigurePanel::Poles => &[PanelKind::Poles],
            FigurePanel::ZPlane => &[PanelKind::ZPlane],
            FigurePanel::Rho => &[PanelKind::RhoCurve],
            FigurePanel::MapOff => &[PanelKind::MapOff],
            FigurePanel::MapOn => &[PanelKind::MapOn],
            FigurePanel::Maps => &[PanelKind::MapOff, PanelKind::MapOn],
            FigurePanel::Study => &[PanelKind::StudyError, PanelKind::StudyTorque],
        }
    }

    /// True for the figures of the analysis, which student mode hides until answered.
    pub fn gives_answer_away(self) -> bool {
        self.kinds().iter().any(|k| k.is_analysis())
    }

    fn is_map(self) -> bool {
        self.kinds().iter().any(|k| k.is_map())
    }
}

/// One choice of the page's "Figure" list.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct FigureChoice {
    pub id: &'static str,
    pub label: String,
}

/// The figures of the panels the page shows now (as drawn: student mode leaves the analysis out).
pub fn figure_choices(session: &Session) -> Vec<FigureChoice> {
    let v = session.drawn_view();
    let pair = session.run(1).is_some();
    let e = if v.predict {
        " (zoom on tₙ)"
    } else if v.log {
        " (log |e|)"
    } else {
        ""
    };
    let mut out = Vec::new();
    let mut add = |p: FigurePanel, label: String| out.push(FigureChoice { id: p.id(), label });
    add(FigurePanel::Arm, if pair { "Arm A".into() } else { "Arm".into() });
    if pair {
        add(FigurePanel::ArmB, "Arm B".into());
    }
    add(FigurePanel::Errors, format!("Errors e1 and e2{e}"));
    add(FigurePanel::E1, format!("Error e1{e}"));
    add(FigurePanel::E2, format!("Error e2{e}"));
    if v.torque {
        add(FigurePanel::Torque, "Torques".into());
    }
    if velocity_shown(session) {
        add(FigurePanel::Velocity, "Velocity q̇1, true and estimated".into());
    }
    if v.poles && v.z_plane {
        add(FigurePanel::ZPlane, "z-plane".into());
    } else if v.poles {
        add(FigurePanel::Poles, "Pole plot (s)".into());
    }
    if v.rho {
        add(FigurePanel::Rho, format!("{} along δ", v.measure.symbol()));
    }
    if session.study_drawn() {
        add(FigurePanel::Study, "Error and T1 against δ".into());
    }
    if v.map {
        add(FigurePanel::MapOff, "Map without Kₚᵣ".into());
        add(FigurePanel::MapOn, "Map with Kₚᵣ".into());
        add(FigurePanel::Maps, "Both maps".into());
    }
    out
}

/// True if the session's view draws the velocity panel: the `measured` switch on (not zoomed on
/// one instant) and run A's controller digital.
fn velocity_shown(session: &Session) -> bool {
    let v = session.drawn_view();
    v.measured && !v.predict && session.reads_sensors()
}

/// The figure `panel` of the session as it is now: light, or in the dark scheme if `dark`.
pub fn figure_svg(session: &Session, panel: &str, dark: bool) -> Result<Figure, Error> {
    figure_svg_with(session, &session.state_string(), panel, &FigureOptions { dark, ..FigureOptions::default() })
}

/// [`figure_svg`] captioned with the state string `state` (the session's with the lesson step,
/// where the classroom has one open), made as `options` ask (for a slide: the background, the
/// text size, the caption, 16:9, the screen's z-plane view).
pub fn figure_svg_with(session: &Session, state: &str, panel: &str, options: &FigureOptions) -> Result<Figure, Error> {
    let panel = FigurePanel::parse(panel)?;
    if panel.gives_answer_away() && session.answers_hidden() {
        return Err(Error::NotReady(
            "student mode hides this figure (the pole plots, ρ(δ) and the maps) until you answer",
        ));
    }
    if panel == FigurePanel::ArmB && session.run(1).is_none() {
        return Err(Error::NotReady("there is no run B: compare two runs to draw run B's arm"));
    }
    if panel == FigurePanel::Velocity && !velocity_shown(session) {
        return Err(Error::NotReady(
            "the velocity is drawn with 'What the controller reads' on and a digital controller (an encoder, noise \
             or differenced velocities)",
        ));
    }
    if panel == FigurePanel::Study && !session.reads_sensors() {
        return Err(Error::NotReady(
            "the study against δ needs a real robot's sensors: a digital controller (an encoder, noise or differenced \
             velocities)",
        ));
    }
    if panel.is_map() && !MapSide::BOTH.iter().all(|&s| session.maps().shown(s).is_some_and(|e| e.is_done())) {
        return Err(Error::NotReady(
            "the stability maps are still being computed: show them and wait for the progress bar to fill",
        ));
    }
    // The title, from the panel as the session shows it now (log |e|, the zoom on tₙ, ρ or ln ρ/δ).
    let mut scene = Scene::new(ViewOptions::default(), 800.0, 600.0, 1.0);
    scene.follow_view(&session.drawn_view());
    scene.pin_z_view(options.z_view());
    let kinds = panel.kinds();
    let (sheet, layout) = Sheet::new(&scene, kinds, options.text_scale(scene.options().text));

    // The scene: first as the session's view lays it out (its options, the runs) on a canvas of
    // the figure's size, then on the figure's layout, drawn again.
    scene.resize(layout.css_width, layout.css_height, 1.0);
    scene.draw_session(session);
    scene.set_layout(layout);
    scene.draw_session(session);
    let key = |scene: &Scene| {
        let mut groups = scene.legend();
        if kinds.iter().any(|k| k.is_time_plot()) {
            let pair = scene.is_pair().then_some(palette::RUN_B);
            let ghost = session.ghost().map(|_| palette::GHOST_TRACE);
            groups.insert(0, curve_key(figure_curves(kinds), pair, ghost).expect("curves"));
        }
        groups
    };
    let mut groups = key(&scene);

    let head = caption_head(session);
    let settings = session.settings().runs_query();
    let caption = match options.caption {
        CaptionChoice::Full => Some((head.as_str(), state)),
        CaptionChoice::Settings => Some((head.as_str(), settings.as_str())),
        CaptionChoice::None => None,
    };
    let mut sheet = sheet;
    if options.shape == Shape::Wide {
        // The key and caption are known now: the panels fill what they leave of a 16:9 sheet.
        let (wide, layout) = sheet.widen(kinds, &groups, caption);
        scene.set_layout(layout);
        scene.draw_session(session);
        groups = key(&scene);
        sheet = wide;
    }
    let words = Words { caption, state, dark: options.dark, background: options.background };
    Ok(sheet.write(&scene, &groups, words))
}

/// What a figure of the session shows, as its caption begins: "flexarm at t = 4.138 s — Fig. 5.3:
/// δ = 0.01 s without preliminary feedback (unstable)" (the page's picture says the same).
pub fn caption_head(session: &Session) -> String {
    let t = session.run(0).map_or(0.0, |r| r.closed_loop().time());
    at_time(t, &session.status().showing)
}
