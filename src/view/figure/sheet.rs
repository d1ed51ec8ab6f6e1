//! One figure's sheet, the same for every figure flexarm writes (the page's Figure row, `flexarm
//! figure`, `flexarm simulate --svg`, `flexarm map --svg`): the title above, the panels laid out
//! for print below it ([`figure_layout`]), then the key and the caption with the whole state
//! string. Whoever draws a figure lays a [`Scene`] out on the sheet, draws it from what it has (a
//! session, a run's traces, maps on a grid) and hands it back to [`Sheet::write`].

use core::fmt::Write as _;

use super::key::{key, Caption};
use super::layout::{figure_layout, MARGIN};
use super::svg::{wrap, Background, Doc, INK};
use crate::plot::palette;
use crate::schema::PanelKind;
use crate::view::layout::Layout;
use crate::view::legend::LegendGroup;
use crate::view::scene::Scene;

/// The title's font size and line pitch, px.
const TITLE: f64 = 16.0;
const TITLE_PITCH: f64 = 21.0;

/// A figure's SVG text and size (px at 1×).
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    pub svg: String,
    pub width: f64,
    pub height: f64,
}

/// Where a figure's parts go around its panels: the title's lines, the figure's width and the
/// panels' bottom edge (the key starts below it).
#[derive(Clone, Debug)]
pub struct Sheet {
    title: String,
    title_lines: Vec<String>,
    width: f64,
    panels_bottom: f64,
}

impl Sheet {
    /// The sheet of the panels `kinds` under `title`, and the panels' layout on it, for a scene to
    /// draw on ([`Scene::set_layout`]). The title is broken for a first guess of the width (the
    /// panels go below it), then again for the width the panels give.
    pub fn new(scene: &Scene, kinds: &[PanelKind]) -> (Sheet, Layout) {
        let title = scene.figure_title(kinds);
        let width_guess = 800.0;
        let title_lines = wrap(&title, width_guess - 2.0 * MARGIN, TITLE, true);
        let top = MARGIN + title_lines.len() as f64 * TITLE_PITCH + 6.0;
        let (layout, width, panels_bottom) = figure_layout(kinds, top, |k| scene.figure_size(k));
        let title_lines = wrap(&title, width - 2.0 * MARGIN, TITLE, true);
        (Sheet { title, title_lines, width, panels_bottom }, layout)
    }

    /// The figure of `scene` (drawn on this sheet's layout): its panels, their labels, the key
    /// `groups` and a caption — `head` (what it shows, in words) and the whole `state` string.
    pub fn write(
        &self,
        scene: &Scene,
        groups: &[LegendGroup],
        head: &str,
        state: &str,
        dark: bool,
        background: Background,
    ) -> Figure {
        let (width, inner) = (self.width, self.width - 2.0 * MARGIN);
        let key_top = self.panels_bottom + 8.0;
        let key_height = key(None, groups, MARGIN, key_top, inner);
        let caption = Caption::new(head, state, inner);
        let caption_top = key_top + key_height + 4.0;
        let height = (caption_top + caption.height() + MARGIN).ceil();

        let mut doc = Doc::new(width, height, &self.title, state, (palette::BACKGROUND, background), dark);
        for (k, line) in self.title_lines.iter().enumerate() {
            let y = MARGIN + TITLE + k as f64 * TITLE_PITCH;
            doc.text(width / 2.0, y, TITLE, "middle", 700, INK, "figure-title", line);
        }
        // Each panel's axes (its data area and what its edges stand for), for whoever reads the
        // figure back: the tests, a script placing annotations.
        // The page's entry points (at text scale 1 on the figure's layout: the layout's pixels), so
        // that the page's module needs no second copy of them.
        for p in scene.page_panel_info() {
            let _ = writeln!(
                doc.out,
                "<g class=\"panel\" data-panel=\"{}\" data-rect=\"{} {} {} {}\" data-x-range=\"{} {}\" \
                 data-y-range=\"{} {}\" data-x-scale=\"{}\" data-y-scale=\"{}\"></g>",
                p.id,
                p.x,
                p.y,
                p.width,
                p.height,
                p.x_range[0],
                p.x_range[1],
                p.y_range[0],
                p.y_range[1],
                p.x_scale,
                p.y_scale
            );
        }
        doc.out.push_str("<g id=\"static\">\n");
        doc.triangles(scene.static_vertices(), 0.4);
        doc.out.push_str("</g>\n<g id=\"frame\">\n");
        doc.triangles(scene.vertices(), 0.0);
        doc.out.push_str("</g>\n<g id=\"labels\">\n");
        for l in scene.page_labels() {
            doc.label(&l);
        }
        doc.out.push_str("</g>\n<g id=\"key\">\n");
        key(Some(&mut doc), groups, MARGIN, key_top, inner);
        doc.out.push_str("</g>\n<g id=\"caption\">\n");
        caption.write(&mut doc, MARGIN, caption_top, inner);
        doc.out.push_str("</g>\n");
        Figure { svg: doc.finish(), width, height }
    }
}

/// A caption's head for a run at simulated time `t` (s): "flexarm at t = 4.138 s — what".
pub fn at_time(t: f64, what: &str) -> String {
    format!("flexarm at t = {} s — {what}", crate::plot::format::significant_trimmed(t, 4))
}
