//! The scene as the page sees it: in the page's CSS pixels, which differ from the layout's by the
//! text scale (`text=`, presentation mode; [`crate::view::text_size`]). Everything the page is told
//! (labels, panel rectangles, pole positions, tooltips) is multiplied by it here, and everything it
//! asks about (a pointer's position) divided, so that no JavaScript needs to know the scale.

use super::{PanelInfo, Probe, Scene};
use crate::view::labels::Label;
use crate::view::loop_poles::PoleInfo;

impl Scene {
    /// The height of the whole screen (CSS px; the page's window), which presentation mode sizes
    /// the text for.
    pub fn set_screen_height(&mut self, css_height: f64) {
        if css_height != self.screen_height && !(css_height.is_nan() && self.screen_height.is_nan()) {
            self.screen_height = css_height;
            self.relayout();
        }
    }

    /// Page CSS pixels per layout pixel: the figure's text scale.
    pub fn page_scale(&self) -> f64 {
        self.scale
    }

    /// How much larger than Normal the page's own text in presentation mode is (the bar, its
    /// verdict, the key): the text size chosen, over the screen's floor
    /// ([`crate::view::text_size::page_text_factor`]).
    pub fn page_text_factor(&self) -> f64 {
        let [_, h, _] = self.page;
        let screen = if self.screen_height.is_finite() { self.screen_height } else { h };
        let o = &self.frame.options;
        crate::view::text_size::page_text_factor(o.text, o.present, screen)
    }

    /// [`Scene::labels`] in page CSS pixels: anchors, font sizes and widths scaled.
    pub fn page_labels(&self) -> Vec<Label> {
        let s = self.scale;
        let mut labels = self.labels();
        for l in &mut labels {
            l.x *= s;
            l.y *= s;
            l.size *= s;
            l.width *= s;
        }
        labels
    }

    /// [`Scene::panel_info`] in page CSS pixels.
    pub fn page_panel_info(&self) -> Vec<PanelInfo> {
        let s = self.scale;
        let mut panels = self.panel_info();
        for p in &mut panels {
            p.x *= s;
            p.y *= s;
            p.width *= s;
            p.height *= s;
            for m in &mut p.marks {
                m.x *= s;
                m.y *= s;
            }
        }
        panels
    }

    /// [`Scene::pole_info`] in page CSS pixels.
    pub fn page_pole_info(&self) -> Vec<PoleInfo> {
        let s = self.scale;
        let mut poles = self.pole_info();
        for p in &mut poles {
            p.x = p.x.map(|x| x * s);
            p.y = p.y.map(|y| y * s);
        }
        poles
    }

    /// [`Scene::probe`] at a point of the page (CSS px; `reach` too), answered in page CSS px.
    pub fn page_probe(&self, x: f64, y: f64, reach: f64) -> Option<Probe> {
        let s = self.scale;
        self.probe(x / s, y / s, reach / s).map(|mut p| {
            p.x *= s;
            p.y *= s;
            p
        })
    }

    /// [`Scene::pair_handle_at`] at a point of the page (CSS px).
    pub fn page_pair_handle_at(&self, x: f64, y: f64, reach: f64) -> bool {
        let s = self.scale;
        self.pair_handle_at(x / s, y / s, reach / s)
    }

    /// [`Scene::pole_plot_point`] at a point of the page (CSS px).
    pub fn page_pole_plot_point(&self, x: f64, y: f64) -> Option<[f64; 2]> {
        self.pole_plot_point(x / self.scale, y / self.scale)
    }

    /// [`Scene::time_at`] at a point of the page (CSS px).
    pub fn page_time_at(&self, x: f64, y: f64) -> Option<f64> {
        self.time_at(x / self.scale, y / self.scale)
    }

    /// A point of the page (CSS px) in layout pixels: for what the page forwards (a wheel or a
    /// drag over a panel).
    pub fn page_to_layout(&self, x: f64, y: f64) -> [f64; 2] {
        [x / self.scale, y / self.scale]
    }
}
