//! How a figure is made for a slide or a handout: the page's Figure row and `flexarm figure` ask
//! for the same [`FigureOptions`] — background, text size, caption, shape and, for the z-plane,
//! the view the screen shows.

use super::svg::Background;
use crate::error::{Error, ParseError};
use crate::view::panels::z_plane::view::ZView;
use crate::view::text_size::TextSize;

/// What the caption under a figure says.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CaptionChoice {
    /// What it shows and the whole state string (the view's keys too): the figure can be made
    /// again from it.
    #[default]
    Full,
    /// What it shows and the settings of the runs only (δ, α, K_pr, the arm…), without the
    /// view's keys (`plane=z`, `mode=full`, the zoom…): shorter, for a slide.
    Settings,
    /// No caption: the slide says it.
    None,
}

/// The figure's outline.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shape {
    /// Each panel at its own print size, the key and caption below.
    #[default]
    Natural,
    /// 16:9, a slide's shape: the panels grow to fill it.
    Wide,
}

/// The wide shape's width over height, and its width in px at normal text (1280 × 720: a
/// slide's size; a larger text size lays it out smaller and draws it that much larger).
pub const WIDE_RATIO: f64 = 16.0 / 9.0;
pub const WIDE_WIDTH: f64 = 1280.0;

/// Everything a figure's maker chooses; every field has a default (the page's look).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FigureOptions {
    /// The dark scheme (every colour's lightness inverted, as the canvas's shader does).
    pub dark: bool,
    pub background: Background,
    /// The text size; none: the page's (`text=`). Larger text on a figure of the same size, as
    /// on the canvas ([`crate::view::text_size`]).
    pub text: Option<TextSize>,
    pub caption: CaptionChoice,
    pub shape: Shape,
    /// The z-plane's view as the screen shows it, `[Re λ, Im λ, half-size]` — its default view
    /// depends on the panel's size, so without it a figure's larger panel would zoom less than
    /// the screen does. None: the session's zoom, else the default for the figure's panel.
    pub z_view: Option<[f64; 3]>,
}

impl FigureOptions {
    /// From `key=value` pairs joined by `&`, each key at most once, every key optional:
    /// `dark=1`, `background=page|white|transparent`, `text=normal|large|larger|largest` (absent:
    /// the page's), `caption=full|settings|none`, `shape=natural|wide`, `zview=RE,IM,HALF`. An
    /// unknown key or value is an error naming what it may be.
    pub fn parse(text: &str) -> Result<FigureOptions, Error> {
        let mut o = FigureOptions::default();
        let mut seen: Vec<&str> = Vec::new();
        for pair in text.split('&').filter(|p| !p.trim().is_empty()) {
            let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
            let (key, value) = (key.trim(), value.trim());
            let bad = |expected: &str| {
                Error::Parse(ParseError { key: key.into(), text: value.into(), expected: expected.into() })
            };
            if seen.contains(&key) {
                return Err(bad("once only"));
            }
            seen.push(key);
            match key {
                "dark" => o.dark = pick(value, &[("1", true), ("0", false)]).ok_or_else(|| bad("1 or 0"))?,
                "background" => {
                    let names = [
                        ("page", Background::Page),
                        ("white", Background::White),
                        ("transparent", Background::Transparent),
                    ];
                    o.background = pick(value, &names).ok_or_else(|| bad("page, white or transparent"))?;
                }
                "text" => {
                    let names = [
                        ("normal", TextSize::Normal),
                        ("large", TextSize::Large),
                        ("larger", TextSize::Larger),
                        ("largest", TextSize::Largest),
                    ];
                    o.text = Some(pick(value, &names).ok_or_else(|| bad("normal, large, larger or largest"))?);
                }
                "caption" => {
                    let names = [
                        ("full", CaptionChoice::Full),
                        ("settings", CaptionChoice::Settings),
                        ("none", CaptionChoice::None),
                    ];
                    o.caption = pick(value, &names).ok_or_else(|| bad("full, settings or none"))?;
                }
                "shape" => {
                    o.shape = pick(value, &[("natural", Shape::Natural), ("wide", Shape::Wide)])
                        .ok_or_else(|| bad("natural or wide (16:9)"))?;
                }
                "zview" => {
                    // Every piece a number: "1,x,2,3" is not three numbers.
                    let v: Vec<f64> = value.split(',').map(|n| n.trim().parse().unwrap_or(f64::NAN)).collect();
                    match v[..] {
                        [re, im, half] if v.iter().all(|n| n.is_finite()) && half > 0.0 => {
                            o.z_view = Some([re, im, half])
                        }
                        _ => return Err(bad("three numbers RE,IM,HALF (the view's centre and half-size, HALF > 0)")),
                    }
                }
                _ => {
                    return Err(Error::Parse(ParseError {
                        key: "figure option".into(),
                        text: key.into(),
                        expected: "dark, background, text, caption, shape or zview".into(),
                    }))
                }
            }
        }
        Ok(o)
    }

    /// The text scale of the figure: the chosen size's factor (the screen's presentation floor
    /// does not apply: a slide is scaled to the projector with its figure).
    pub fn text_scale(&self, page: TextSize) -> f64 {
        self.text.unwrap_or(page).factor()
    }

    /// The z-plane's view asked for, within its limits.
    pub fn z_view(&self) -> Option<ZView> {
        self.z_view.map(|[x, y, half]| ZView { center: [x, y], half }.clamped())
    }
}

/// The value named `name` among `names`.
fn pick<T: Copy>(name: &str, names: &[(&str, T)]) -> Option<T> {
    names.iter().find(|(n, _)| *n == name).map(|(_, v)| *v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_asked_is_the_pages_look() {
        assert_eq!(FigureOptions::parse("").unwrap(), FigureOptions::default());
    }

    #[test]
    fn every_option_reads_and_a_typo_is_named() {
        let o =
            FigureOptions::parse("dark=1&background=white&text=largest&caption=settings&shape=wide&zview=0.9,0.3,0.05")
                .unwrap();
        assert!(o.dark);
        assert_eq!(o.text, Some(TextSize::Largest));
        assert_eq!((o.caption, o.shape, o.background), (CaptionChoice::Settings, Shape::Wide, Background::White));
        assert_eq!(o.z_view().unwrap().half, 0.05);
        for (bad, says) in [
            ("text=huge", "largest"),
            ("colour=red", "zview"),
            ("background=beige", "transparent"),
            ("zview=1,2", "RE,IM,HALF"),
            ("zview=1,x,0.05,0.1", "RE,IM,HALF"),
            ("zview=1,2,0", "HALF > 0"),
            ("shape=wide&shape=natural", "once"),
        ] {
            let e = FigureOptions::parse(bad).unwrap_err().to_string();
            assert!(e.contains(says), "{bad}: {e}");
        }
    }
}
