//! The snippet that embeds the page in a course page: an `<iframe>` of the current settings with
//! the panels, size, strip of controls and moment chosen — or of a lesson step, with its own
//! settings (the step is the classroom's).

use super::progress::LessonOrigin;
use super::room::Classroom;
use crate::error::{Error, ParseError};
use crate::plot::format::escape;
use crate::session::query::{encode, split_query};
use crate::session::view::{Strip, ViewSettings};
use crate::session::Session;

/// The embedded page's size, CSS px (a canvas and a strip of controls fit it without scrolling).
pub const EMBED_SIZE: [u32; 2] = [640, 400];

impl Classroom {
    /// The embed builder's choices to start from: what is on screen now
    /// (`views=arm,traces&width=640&height=400&strip=play,pf`, and `lesson=N` in the lesson).
    pub fn embed_defaults(&self, session: &Session) -> String {
        let [w, h] = EMBED_SIZE;
        let v = &session.settings().view;
        let mut q = format!("views={}&width={w}&height={h}&strip={}", v.views_list(), v.strip.text());
        // The size's limits, for the form's number fields (written here once).
        let ([w0, h0], [w1, h1]) = (EMBED_MIN, EMBED_MAX);
        q.push_str(&format!("&min_width={w0}&max_width={w1}&min_height={h0}&max_height={h1}"));
        if let Some(step) = self.lesson.as_ref().and_then(|l| l.open_step()) {
            q.push_str(&format!("&lesson={}", step + 1));
        }
        q
    }

    /// An `<iframe>` for a course page, of the page at `page_url` (its query and fragment
    /// dropped), as the embed builder's `choices` say (a query: see [`EmbedChoices::read`]):
    /// the current settings with exactly the panels chosen, at the size chosen, starting paused
    /// or at t if chosen, with the strip's controls chosen — or a lesson step, with its own
    /// settings. Every choice is checked; the first bad one is the error.
    pub fn embed(&self, session: &Session, page_url: &str, choices: &str) -> Result<Embed, Error> {
        let c = EmbedChoices::read(choices)?;
        let base = page_url.split(['?', '#']).next().unwrap_or(page_url);
        let mut settings = *session.settings();
        settings.view.embed = true;
        // The panels chosen, or those on screen (the intro's arm and errors, not its hidden switches).
        let views = c.views.clone().unwrap_or_else(|| session.settings().view.views_list());
        settings.view.read_views(&views)?;
        if let Some(strip) = c.strip {
            settings.view.strip = strip;
        }
        let mut pairs: Vec<String> = Vec::new();
        // A homework link's lesson travels on in the embed's own fragment.
        let mut fragment = String::new();
        let title = match c.lesson {
            Some(step) => {
                // The step sets the run; the link carries only the figures and the strip over it.
                let (source, lesson) = self.lesson_for_embed()?;
                let Some(s) = lesson.steps.get(step.wrapping_sub(1)) else {
                    return Err(Error::Parse(ParseError {
                        key: "lesson".into(),
                        text: step.to_string(),
                        expected: format!("a step from 1 to {}", lesson.steps.len()),
                    }));
                };
                if let LessonSource::Path(path) = &source {
                    pairs.push(format!("lesson_src={}", encode(path)));
                }
                fragment = match source {
                    LessonSource::Link(f) => format!("#{f}"),
                    _ => String::new(),
                };
                pairs.push(format!("lesson={step}"));
                pairs.push("embed=1".into());
                pairs.push(format!("views={}", encode(&settings.view.views_list())));
                if settings.view.strip != Strip::DEFAULT {
                    pairs.push(format!("strip={}", encode(&settings.view.strip.text())));
                }
                format!("flexarm: lesson step {step}, {}", s.title)
            }
            None => {
                pairs.push(settings.to_query());
                format!("flexarm: {}", session.status().showing)
            }
        };
        if c.paused {
            pairs.push("paused=1".into());
        }
        if c.time > 0.0 {
            pairs.push(format!("t={}", crate::schema::format_number(c.time)));
        }
        let src = format!("{base}?{}{fragment}", pairs.join("&"));
        let [width, height] = c.size;
        let html = format!(
            "<iframe src=\"{}\" width=\"{width}\" height=\"{height}\" title=\"{}\" style=\"border:0\" loading=\"lazy\"></iframe>",
            escape(&src),
            escape(&title)
        );
        Ok(Embed { html, src, width, height, title })
    }

    /// The lesson a link can embed: where a link finds it, and its steps.
    fn lesson_for_embed(&self) -> Result<(LessonSource, crate::lesson::Lesson), Error> {
        let source =
            match (&self.lesson_origin, &self.link_fragment) {
                (LessonOrigin::BuiltIn, _) => LessonSource::BuiltIn,
                (LessonOrigin::Path(path), _) => LessonSource::Path(path.clone()),
                (LessonOrigin::Carried(_), Some(fragment)) => LessonSource::Link(fragment.clone()),
                (LessonOrigin::File(_) | LessonOrigin::Carried(_), _) => return Err(Error::NotReady(
                    "a lesson opened from your disk cannot be embedded: make a homework link of it and open that, or \
                     put the file beside the page and open it with lesson_src=",
                )),
            };
        if let Some(l) = &self.lesson {
            return Ok((source, l.lesson().clone()));
        }
        let text: &str = match &self.lesson_text {
            Some(text) => text,
            #[cfg(not(target_arch = "wasm32"))]
            None => crate::lesson::LESSON_TEXT,
            #[cfg(target_arch = "wasm32")]
            None => return Err(Error::NotReady("the lesson's text did not load (lessons/paper.md, beside the page)")),
        };
        Ok((source, crate::lesson::parse(text)?))
    }
}

/// Where an embed's link finds the lesson: every copy of the page has the built-in one; a
/// teacher's is a file of the site (`lesson_src=`) or travels in the link's fragment.
enum LessonSource {
    BuiltIn,
    Path(String),
    Link(String),
}

/// An embed: the `<iframe>` to paste, and its parts (for the builder's live preview).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Embed {
    /// The `<iframe …></iframe>` element.
    pub html: String,
    /// The embedded page's address.
    pub src: String,
    pub width: u32,
    pub height: u32,
    pub title: String,
}

/// The smallest and largest embed accepted, CSS px (width, height): below the smallest the strip
/// and one panel no longer fit; beyond the largest no course page has room.
pub const EMBED_MIN: [u32; 2] = [320, 260];
pub const EMBED_MAX: [u32; 2] = [2400, 1600];

/// What the embed builder chose.
#[derive(Clone, Debug, PartialEq)]
pub struct EmbedChoices {
    /// The panels, as `views=` names them (None: as on screen).
    pub views: Option<String>,
    /// Width and height of the iframe, CSS px.
    pub size: [u32; 2],
    /// Start paused (`paused=1`).
    pub paused: bool,
    /// Start at this time, s (`t=`; 0: from rest).
    pub time: f64,
    /// The strip's controls (None: as set now).
    pub strip: Option<Strip>,
    /// A lesson step (1-based) instead of the current settings.
    pub lesson: Option<usize>,
}

impl EmbedChoices {
    /// Reads the builder's form as a query: `views=zplane,rho&width=760&height=480&paused=1&t=3
    /// &strip=delta,reset&lesson=4` (every key optional; `lesson=` empty or 0 for none). An
    /// unknown key or a bad value is an error naming it.
    pub fn read(query: &str) -> Result<EmbedChoices, Error> {
        let mut c = EmbedChoices { views: None, size: EMBED_SIZE, paused: false, time: 0.0, strip: None, lesson: None };
        for (key, text) in split_query(query) {
            let bad = |expected: String| Error::Parse(ParseError { key: key.clone(), text: text.clone(), expected });
            match key.as_str() {
                "views" => {
                    // Checked here, so that the error names the list as given.
                    ViewSettings::default().read_views(&text)?;
                    c.views = Some(text.clone());
                }
                "strip" => c.strip = Some(Strip::read(&text)?),
                "width" | "height" => {
                    let i = usize::from(key == "height");
                    let (lo, hi) = (EMBED_MIN[i], EMBED_MAX[i]);
                    c.size[i] = text
                        .trim()
                        .parse::<u32>()
                        .ok()
                        .filter(|v| (lo..=hi).contains(v))
                        .ok_or_else(|| bad(format!("a whole number of CSS px from {lo} to {hi}")))?;
                }
                "paused" => c.paused = crate::schema::PAUSED.parse(&text, true)?.switch().unwrap_or(false),
                "t" if text.trim().is_empty() => c.time = 0.0,
                "t" => c.time = crate::schema::START_TIME.parse(&text, true)?.number().unwrap_or(0.0),
                "lesson" => {
                    let t = text.trim();
                    c.lesson = match t {
                        "" | "0" => None,
                        _ => Some(
                            t.parse::<usize>()
                                .ok()
                                .filter(|s| *s >= 1)
                                .ok_or_else(|| bad("a step number from 1".into()))?,
                        ),
                    };
                }
                _ => return Err(bad("one of views, width, height, paused, t, strip, lesson".into())),
            }
        }
        Ok(c)
    }
}
