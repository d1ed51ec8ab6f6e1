//! A figure's layout: only the panels of one figure, each at a size chosen for print and slides
//! (not the canvas's), with the same label gutters as on the canvas ([`gutters`]), so that the
//! labels of [`crate::view::labels`] fall where they fall on the page.

use crate::view::layout::{gutters, Arrangement, Layout, Panel, PanelKind, Rect};

/// Space around the figure's content, px.
pub const MARGIN: f64 = 16.0;
/// Between two panels side by side (the maps) or stacked (the time plots), px.
pub const GAP: f64 = 24.0;
/// A figure is at least this wide (room for its key and caption), px.
pub const MIN_WIDTH: f64 = 600.0;

/// The figure's panels below `top`: time plots stacked, anything else side by side, the whole
/// centred in a figure at least `min_width` wide. Returns the layout (CSS px = figure px, one
/// device pixel each), the figure's width and the panels' bottom edge (gutters included).
pub fn figure_layout(
    kinds: &[PanelKind],
    top: f64,
    min_width: f64,
    data_size: impl Fn(PanelKind) -> (f64, f64),
) -> (Layout, f64, f64) {
    let cell = |kind: PanelKind| {
        let (w, h) = data_size(kind);
        let [l, t, r, b] = gutters(kind);
        (w + l + r, h + t + b)
    };
    let stacked = kinds.iter().all(|k| k.is_time_plot());
    let (mut width, mut height) = (0.0f64, 0.0f64);
    for (i, &k) in kinds.iter().enumerate() {
        let (w, h) = cell(k);
        let gap = if i == 0 { 0.0 } else { GAP };
        if stacked {
            width = width.max(w);
            height += gap + h;
        } else {
            width += gap + w;
            height = height.max(h);
        }
    }
    let figure_width = (width + 2.0 * MARGIN).max(min_width).ceil();
    let (mut x, mut y) = (((figure_width - width) / 2.0).round(), top);
    let mut panels = Vec::with_capacity(kinds.len());
    for &k in kinds {
        let (w, h) = cell(k);
        let [l, t, r, b] = gutters(k);
        panels.push(Panel { kind: k, rect: Rect::new(x, y, w, h).inset(l, t, r, b) });
        if stacked {
            y += h + GAP;
        } else {
            x += w + GAP;
        }
    }
    let bottom = top + height;
    let layout = Layout {
        css_width: figure_width,
        css_height: bottom + MARGIN,
        device_pixel_ratio: 1.0,
        arrangement: if stacked { Arrangement::Stacked } else { Arrangement::SideBySide },
        panels,
        tabs: Vec::new(),
        tab: None,
    };
    (layout, figure_width, bottom)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn panels_keep_their_gutters_inside_the_figure() {
        for kinds in
            [&[PanelKind::Error1, PanelKind::Error2][..], &[PanelKind::MapOff, PanelKind::MapOn], &[PanelKind::Arm]]
        {
            let (layout, width, bottom) =
                figure_layout(kinds, 40.0, MIN_WIDTH, |k| crate::view::panels::Panels::default().figure_size(k));
            for p in &layout.panels {
                let [l, t, r, b] = gutters(p.kind);
                assert!(p.rect.x - l >= 0.0 && p.rect.right() + r <= width, "{p:?}");
                assert!(p.rect.y - t >= 40.0 - 1e-9 && p.rect.bottom() + b <= bottom + 1e-9, "{p:?}");
            }
        }
    }
}
