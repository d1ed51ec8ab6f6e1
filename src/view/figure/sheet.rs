//! One figure's sheet, the same for every figure flexarm writes (the page's Figure row, `flexarm
//! figure`, `flexarm simulate --svg`, `flexarm map --svg`): the title above, the panels laid out
//! for print below it ([`figure_layout`]), then the key and the caption with the whole state
//! string. Whoever draws a figure lays a [`Scene`] out on the sheet, draws it from what it has (a
//! session, a run's traces, maps on a grid) and hands it back to [`Sheet::write`].

use core::fmt::Write as _;

use super::key::{key, Caption};
use super::layout::{figure_layout, GAP, MARGIN, MIN_WIDTH};
use super::options::{WIDE_RATIO, WIDE_WIDTH};
use super::svg::{wrap, Background, Doc, INK};
use crate::plot::palette;
use crate::schema::PanelKind;
use crate::view::layout::{gutters, Layout};
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
/// panels' bottom edge (the key starts below it), in the figure's units; `scale` px a unit (the
/// text size); the least height (the wide shape's).
#[derive(Clone, Debug)]
pub struct Sheet {
    title: String,
    title_lines: Vec<String>,
    width: f64,
    panels_bottom: f64,
    scale: f64,
    min_height: f64,
    /// Where the key goes when not below the panels: [x, top, width], and whether as its
    /// entries' names alone.
    key_box: Option<([f64; 3], bool)>,
}

/// What a figure's sheet says besides its panels: the caption (what it shows, the state line
/// under it; none for no caption), the whole state string (always in the SVG's description) and
/// how it is painted.
#[derive(Clone, Copy, Debug)]
pub struct Words<'a> {
    pub caption: Option<(&'a str, &'a str)>,
    pub state: &'a str,
    pub dark: bool,
    pub background: Background,
}

impl Sheet {
    /// The sheet of the panels `kinds` under `title`, and the panels' layout on it, for a scene to
    /// draw on ([`Scene::set_layout`]), with text `scale` times larger than the page's normal
    /// (the panels laid out that much smaller, the whole drawn that much larger: the figure keeps
    /// its size). The title is broken for a first guess of the width (the panels go below it),
    /// then again for the width the panels give.
    pub fn new(scene: &Scene, kinds: &[PanelKind], scale: f64) -> (Sheet, Layout) {
        let scale = if scale.is_finite() && scale >= 1.0 { scale } else { 1.0 };
        let title = scene.figure_title(kinds);
        let width_guess = 800.0 / scale;
        let title_lines = wrap(&title, width_guess - 2.0 * MARGIN, TITLE, true);
        let top = MARGIN + title_lines.len() as f64 * TITLE_PITCH + 6.0;
        let (layout, width, panels_bottom) = figure_layout(kinds, top, MIN_WIDTH / scale, |k| {
            let (w, h) = scene.figure_size(k);
            (w / scale, h / scale)
        });
        let title_lines = wrap(&title, width - 2.0 * MARGIN, TITLE, true);
        (Sheet { title, title_lines, width, panels_bottom, scale, min_height: 0.0, key_box: None }, layout)
    }

    /// The same panels on a 16:9 sheet (a slide's shape), knowing the key `groups` and the
    /// caption it will carry: [`WIDE_WIDTH`] px wide at normal text, so that a larger text size
    /// is larger on the slide by its whole factor; the key beside the panels where it fits there
    /// (else below them), the panels filling what the title, key and caption leave. Where that
    /// would squeeze the panels below half their natural height, the sheet grows (still 16:9).
    pub fn widen(&self, kinds: &[PanelKind], groups: &[LegendGroup], caption: Option<(&str, &str)>) -> (Sheet, Layout) {
        let natural = self.panels_bottom - self.top();
        let mut width = WIDE_WIDTH / self.scale;
        let mut tries = 0;
        let (top, title_lines, panels_width, panels_height, key_box) = loop {
            let inner = width - 2.0 * MARGIN;
            let title_lines = wrap(&self.title, inner, TITLE, true);
            let top = MARGIN + title_lines.len() as f64 * TITLE_PITCH + 6.0;
            let caption_height = caption.map_or(0.0, |(h, st)| CAPTION_GAP + Caption::new(h, st, inner).height());
            let bottom = width / WIDE_RATIO - MARGIN - caption_height;
            // The key beside the panels; at a large text size, as its entries' names alone
            // (the compact key's), where the whole entries would not fit beside them.
            let key_width = (0.3 * inner).clamp(200.0, 340.0);
            let fits = |short: bool| key(None, &keyed(groups, short), 0.0, 0.0, key_width) <= bottom - top;
            let beside = if fits(false) { Some(false) } else { fits(true).then_some(true) };
            let (panels_width, panels_height, key_box) = match beside {
                Some(short) => {
                    (inner - key_width - GAP, bottom - top, Some(([MARGIN + inner - key_width, top, key_width], short)))
                }
                None => (inner, bottom - top - KEY_GAP - key(None, groups, 0.0, 0.0, inner), None),
            };
            tries += 1;
            if panels_height >= 0.5 * natural || tries >= 12 {
                break (top, title_lines, panels_width, panels_height.max(40.0), key_box);
            }
            width *= 1.1;
        };
        let n = kinds.len().max(1) as f64;
        let stacked = kinds.iter().all(|k| k.is_time_plot());
        // Laid out across the panels' width (from the left margin), on a sheet of the whole width.
        let (mut layout, _, panels_bottom) = figure_layout(kinds, top, panels_width + 2.0 * MARGIN, |k| {
            let [l, t, r, b] = gutters(k);
            if stacked {
                (panels_width - l - r, (panels_height - GAP * (n - 1.0)) / n - t - b)
            } else {
                ((panels_width - GAP * (n - 1.0)) / n - l - r, panels_height - t - b)
            }
        });
        // Exactly 16:9 (1280 × 720 px at normal text): a slide shows no sliver at its edges.
        layout.css_width = width;
        let min_height = width / WIDE_RATIO;
        let sheet = Sheet {
            title: self.title.clone(),
            title_lines,
            width,
            panels_bottom,
            scale: self.scale,
            min_height,
            key_box,
        };
        (sheet, layout)
    }

    /// The panels' top edge: under the title.
    fn top(&self) -> f64 {
        MARGIN + self.title_lines.len() as f64 * TITLE_PITCH + 6.0
    }

    /// The figure of `scene` (drawn on this sheet's layout): its panels, their labels, the key
    /// `groups` and the caption `words` ask for.
    pub fn write(&self, scene: &Scene, groups: &[LegendGroup], words: Words<'_>) -> Figure {
        let (width, inner) = (self.width, self.width - 2.0 * MARGIN);
        // The key below the panels, or beside them (a wide sheet).
        let ([key_x, key_top, key_width], short) =
            self.key_box.unwrap_or(([MARGIN, self.panels_bottom + KEY_GAP, inner], false));
        let groups = &keyed(groups, short);
        let key_height = key(None, groups, key_x, key_top, key_width);
        let caption = words.caption.map(|(head, state)| Caption::new(head, state, inner));
        let caption_top = (key_top + key_height).max(self.panels_bottom) + CAPTION_GAP;
        // Without a caption, no gap for it either (the wide sheet leaves none).
        let content = match &caption {
            Some(c) => caption_top + c.height() + MARGIN,
            None => caption_top - CAPTION_GAP + MARGIN,
        };
        let height = if self.min_height > 0.0 && content <= self.min_height + 0.5 {
            self.min_height
        } else {
            content.max(self.min_height).ceil()
        };

        let size = [width, height, self.scale];
        let paper = (palette::BACKGROUND, words.background);
        let mut doc = Doc::new(size, &self.title, words.state, paper, words.dark);
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
        key(Some(&mut doc), groups, key_x, key_top, key_width);
        doc.out.push_str("</g>\n");
        if let Some(caption) = caption {
            doc.out.push_str("<g id=\"caption\">\n");
            caption.write(&mut doc, MARGIN, caption_top, inner);
            doc.out.push_str("</g>\n");
        }
        let [w, h] = [width, height].map(|v| (v * self.scale).round());
        Figure { svg: doc.finish(), width: w, height: h }
    }
}

/// Between the panels and the key, the key and the caption, in the figure's units.
const KEY_GAP: f64 = 8.0;
const CAPTION_GAP: f64 = 4.0;

/// A caption's head for a run at simulated time `t` (s): "flexarm at t = 4.138 s — what".
pub fn at_time(t: f64, what: &str) -> String {
    format!("flexarm at t = {} s — {what}", crate::plot::format::significant_trimmed(t, 4))
}

/// The key's groups, with each entry's name alone (`short`) or whole.
fn keyed(groups: &[LegendGroup], short: bool) -> Vec<LegendGroup> {
    let mut out = groups.to_vec();
    if short {
        for item in out.iter_mut().flat_map(|g| g.items.iter_mut()) {
            if !item.short.is_empty() {
                item.text.clone_from(&item.short);
            }
        }
    }
    out
}
