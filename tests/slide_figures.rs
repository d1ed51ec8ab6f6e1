//! Figures for slides (issue 35, item 4): on the page's paper, white or nothing; the text size
//! chosen (every size larger than the last in the pixels a slide shows, the figure about the same
//! size); the caption whole, without the view's keys, or none (the SVG's description keeps the
//! whole state); 16:9 with nothing outside it; the z-plane landscape, at the screen's view when
//! given one, the flexible pair still read outside the unit circle through the figure's axes.

mod common;
#[path = "figure/reading.rs"]
mod reading;

use flexarm::plot::palette;
use flexarm::session::Session;
use flexarm::view::figure::{figure_svg_with, Background, FigureOptions, WIDE_RATIO, WIDE_WIDTH};
use reading::{assert_wellformed, attr, centroid, texts, triangles, Axes};

const STATE: &str = "preset=fig5.3&mode=full&plane=z&speed=2";

fn session() -> Session {
    let mut s = common::visit(STATE).session;
    s.run_to(3.0).unwrap();
    s.refresh();
    s
}

fn figure(s: &Session, panel: &str, options: &str) -> String {
    let options = FigureOptions::parse(options).unwrap();
    let f = figure_svg_with(s, &s.state_string(), panel, &options).unwrap_or_else(|e| panic!("{panel}: {e}"));
    assert_wellformed(&f.svg, panel);
    f.svg
}

/// The figure's size in pixels and pixels per unit of its drawing (width over the viewBox's).
fn size(svg: &str) -> (f64, f64, f64) {
    let head = svg.split('>').next().unwrap();
    let (w, h): (f64, f64) = (attr(head, "width").parse().unwrap(), attr(head, "height").parse().unwrap());
    let view: Vec<f64> = attr(head, "viewBox").split(' ').map(|v| v.parse().unwrap()).collect();
    assert!((w / view[2] - h / view[3]).abs() < 0.01, "one scale both ways: {head}");
    (w, h, w / view[2])
}

/// The smallest tick label's size in the figure's pixels.
fn tick_px(svg: &str) -> f64 {
    let (_, _, scale) = size(svg);
    svg.split("<text class=\"tick\"")
        .skip(1)
        .map(|t| attr(t.split('>').next().unwrap(), "font-size").parse::<f64>().unwrap() * scale)
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn a_figure_is_on_the_pages_paper_on_white_or_transparent() {
    let s = session();
    let rect = |svg: &str| svg.lines().find(|l| l.starts_with("<rect id=\"background\"")).map(str::to_owned);
    let page = rect(&figure(&s, "errors", "background=page")).expect("the page's paper");
    assert!(page.contains(&format!("fill=\"{}\"", palette::BACKGROUND.css())), "{page}");
    let white = rect(&figure(&s, "errors", "background=white")).expect("a white background");
    assert!(white.contains("fill=\"#ffffff\""), "{white}");
    assert_eq!(rect(&figure(&s, "errors", "background=transparent")), None, "no background at all");
    assert_eq!(FigureOptions::default().background, Background::Page);
    let e = FigureOptions::parse("background=beige").unwrap_err().to_string();
    assert!(e.contains("beige") && e.contains("transparent"), "{e}");
}

#[test]
fn each_text_size_is_larger_on_a_figure_of_about_the_same_size() {
    let s = session();
    for panel in ["errors", "zplane", "poles", "rho"] {
        let normal = figure(&s, panel, "");
        let (w0, h0, _) = size(&normal);
        assert!(tick_px(&normal) >= 12.0 - 1e-9, "{panel}: the page's 12-px ticks at normal");
        let mut last = tick_px(&normal);
        for text in ["large", "larger", "largest"] {
            let svg = figure(&s, panel, &format!("text={text}"));
            let (w, h, _) = size(&svg);
            let px = tick_px(&svg);
            assert!(px >= 1.15 * last, "{panel} {text}: ticks {px:.1} px after {last:.1} px");
            // Larger text on a sheet of the same width (the panels shrink as the text grows), not
            // a sheet scaled up; only the key's and caption's lines, wrapped sooner, add height.
            assert!((w / w0 - 1.0).abs() < 0.15, "{panel} {text}: {w} × {h} against {w0} × {h0}");
            assert!(h / h0 < px / 12.0, "{panel} {text}: {w} × {h} against {w0} × {h0}");
            last = px;
        }
    }
    // Without a choice, the page's own text size (text=) is the figure's.
    let mut big = common::visit(&format!("{STATE}&text=larger")).session;
    big.run_to(1.0).unwrap();
    let page_choice = figure(&big, "errors", "");
    assert_eq!(tick_px(&page_choice), tick_px(&figure(&big, "errors", "text=larger")));
}

#[test]
fn the_caption_is_whole_without_the_view_keys_or_none_and_the_description_keeps_the_state() {
    let s = session();
    let state = s.state_string();
    assert!(state.contains("plane=z") && state.contains("mode=full") && state.contains("speed=2"), "{state}");
    let caption = |svg: &str| texts(svg, "state").concat();

    let full = figure(&s, "errors", "caption=full");
    assert_eq!(caption(&full), state, "the whole state string, its lines put together");

    let settings = figure(&s, "errors", "caption=settings");
    let line = caption(&settings);
    assert!(line.contains("delta=0.01") && line.contains("pf=off") && line.contains("alpha=2"), "{line}");
    for view_key in ["plane=", "mode=", "speed="] {
        assert!(!line.contains(view_key), "no {view_key} in {line}");
    }
    assert!(settings.contains("Fig. 5.3"), "what it shows is still said");

    let none = figure(&s, "errors", "caption=none");
    assert!(!none.contains("id=\"caption\"") && texts(&none, "state").is_empty());
    assert!(size(&none).1 < size(&full).1, "the figure is shorter without its caption");
    for svg in [&full, &settings, &none] {
        assert!(svg.contains(&format!("<desc>flexarm state: {}</desc>", state.replace('&', "&amp;"))));
    }
}

#[test]
fn a_wide_figure_is_16_by_9_with_every_panel_inside() {
    let s = session();
    for panel in ["errors", "e1", "zplane", "poles", "rho", "arm"] {
        // On a slide the figure is scaled to the slide's width: what counts is text over width.
        let mut normal_ratio = f64::NAN;
        for (text, caption) in [("normal", "full"), ("largest", "full"), ("normal", "none"), ("large", "settings")] {
            let svg = figure(&s, panel, &format!("shape=wide&text={text}&caption={caption}"));
            let (w, h, scale) = size(&svg);
            // Exactly 16:9, to the pixel: a slide shows no sliver at its edges.
            assert!((w - (h * WIDE_RATIO).round()).abs() <= 1.0, "{panel} {text} {caption}: {w} × {h}");
            assert!(w >= WIDE_WIDTH - 1.0, "{panel} {text}: a slide's {WIDE_WIDTH} px at least, {w}");
            let ratio = tick_px(&svg) / w;
            if text == "normal" && caption == "full" {
                assert!((w - WIDE_WIDTH).abs() <= 1.0, "{panel}: 1280 × 720 at normal text, {w} × {h}");
                normal_ratio = ratio;
            } else if text == "largest" {
                assert!(
                    ratio >= 1.6 * normal_ratio,
                    "{panel}: largest text is {:.2}× normal's on the slide",
                    ratio / normal_ratio
                );
            }
            let (vw, vh) = (w / scale, h / scale);
            // The key's texts: beside the panels (right of every panel) or below them (under every one).
            let key = svg.split("<g id=\"key\">").nth(1).unwrap().split("</g>\n<g id=").next().unwrap();
            let key_xy: Vec<[f64; 2]> = key
                .split("<text class=\"key")
                .skip(1)
                .map(|t| [attr(t, "x").parse().unwrap(), attr(t, "y").parse().unwrap()])
                .collect();
            assert!(!key_xy.is_empty(), "{panel}: a key");
            for tag in svg.split("data-rect=\"").skip(1) {
                let r: Vec<f64> = tag.split('"').next().unwrap().split(' ').map(|v| v.parse().unwrap()).collect();
                assert!(r[2] > 50.0 && r[3] > 50.0, "{panel} {text}: a panel of {r:?}");
                assert!(r[0] >= 0.0 && r[1] >= 0.0 && r[0] + r[2] <= vw && r[1] + r[3] <= vh, "{panel}: {r:?}");
                let clear =
                    key_xy.iter().all(|&[x, _]| x > r[0] + r[2]) || key_xy.iter().all(|&[_, y]| y > r[1] + r[3]);
                assert!(clear, "{panel} {text}: the key overlaps the panel {r:?}");
            }
        }
    }
}

#[test]
fn the_z_plane_is_landscape_at_the_screens_view_with_the_pair_outside_the_circle() {
    let s = session();
    let natural = figure(&s, "zplane", "");
    let (w, h, _) = size(&natural);
    assert!(w > h, "landscape: {w} × {h}");
    // The screen's view: the same span of Im λ on the shorter side, whatever the figure's size.
    let (c, half) = ([0.99, 0.25], 0.06);
    let svg = figure(&s, "zplane", &format!("zview={},{},{half}&shape=wide", c[0], c[1]));
    let axes = Axes::of(&svg, "z-plane");
    assert!((axes.y[1] - axes.y[0] - 2.0 * half).abs() < 1e-9, "Im λ spans {:?}", axes.y);
    assert!(((axes.y[0] + axes.y[1]) / 2.0 - c[1]).abs() < 1e-9 && ((axes.x[0] + axes.x[1]) / 2.0 - c[0]).abs() < 1e-9);
    // Fig. 5.3's flexible pair, |λ| = 1.0239 (ρ), read back through the figure's axes.
    let halo = triangles(&svg, palette::POLE_HALO);
    let upper = halo.iter().map(|t| axes.value(centroid(t))).find(|p| p[1] > 0.0).expect("the pair's halo");
    let r = upper[0].hypot(upper[1]);
    assert!(r > 1.0 && (r - 1.0239).abs() < 0.003, "|λ| = {r}");
}
