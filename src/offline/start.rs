//! Where an offline file opens: the state string it starts from when its address holds none (every
//! setting, the view, student mode, the lesson step shown and, when it was paused, the moment) and
//! the teacher's lesson it carries; and that start in words, for the page to show.

use serde::Serialize;

use crate::classroom::moment::moment_text;
use crate::classroom::progress::checked;
use crate::classroom::Classroom;
use crate::error::Error;
use crate::plot::format::significant_trimmed;
use crate::session::query::split_query;
use crate::session::{Session, Settings, Source, PRESETS};

/// A teacher's lesson an offline file carries.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CarriedLesson {
    /// Its file name (or the site path it came from).
    pub name: String,
    /// Its text, checked as the built-in lesson is.
    pub text: String,
}

/// The start an offline file carries.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct OfflineStart {
    /// The state string (without `lesson_src=`: the lesson travels in `lesson`).
    pub query: String,
    /// A teacher's lesson, opened instead of the built-in one.
    pub lesson: Option<CarriedLesson>,
}

impl OfflineStart {
    /// Where an offline file made now opens: the page's state string with the lesson step shown
    /// (`lesson=3`, without `lesson_src=`: the file carries the lesson) and, when `paused`, this
    /// moment; and the teacher's lesson to carry (the built-in one is in every file).
    pub fn of(classroom: &Classroom, session: &Session, paused: bool) -> OfflineStart {
        let mut query = session.state_string();
        if let Some(step) = classroom.lesson_step_shown() {
            query = join(&query, &format!("lesson={}", step + 1));
        }
        if paused {
            query = join(&query, &format!("paused=1&t={}", moment_text(session)));
        }
        let lesson = classroom
            .teacher_lesson()
            .map(|(name, text)| CarriedLesson { name: name.to_string(), text: text.to_string() });
        OfflineStart { query, lesson }
    }

    /// A start from a state string and a lesson file's bytes, both checked as the page would:
    /// a bad value or a lesson's mistake is refused with the reason. A lesson with no `lesson=`
    /// in the state opens at its first step, as a teacher's link does.
    pub fn new(query: &str, lesson: Option<(String, Vec<u8>)>) -> Result<OfflineStart, Error> {
        let mut settings = Settings::page_start();
        settings.read(query, Source::Lesson)?;
        if split_query(query).iter().any(|(k, _)| k == "lesson_src") {
            return Err(Error::Refused(
                "an offline file cannot load a lesson from a path: give the lesson's file itself (--lesson FILE)"
                    .into(),
            ));
        }
        let mut query = query.trim_start_matches('?').to_string();
        let lesson = match lesson {
            None => None,
            Some((name, bytes)) => {
                let (text, _) = checked(&bytes).map_err(|e| Error::Refused(format!("{name}: {e}")))?;
                if !split_query(&query).iter().any(|(k, _)| k == "lesson") {
                    query = join(&query, "lesson=1");
                }
                Some(CarriedLesson { name, text })
            }
        };
        Ok(OfflineStart { query, lesson })
    }

    /// The start as the JSON the offline file holds in a `<script type="application/json">`:
    /// `<` is escaped, so no text can end the script early.
    pub fn to_json(&self) -> String {
        let lesson = match &self.lesson {
            None => "null".to_string(),
            Some(l) => format!("{{\"name\":{},\"text\":{}}}", json_string(&l.name), json_string(&l.text)),
        };
        format!("{{\"query\":{},\"lesson\":{lesson}}}", json_string(&self.query))
    }

    /// The start in words: "δ = 0.01 s …; paused at t = 3 s; the lesson “Homework”, step 2;
    /// student mode".
    pub fn describe(&self) -> String {
        let mut settings = Settings::page_start();
        // Checked when the start was made; a value a later version would not take is skipped.
        let _ = settings.read(&self.query, Source::Page);
        // A paper's figure by its name (its settings only: no verdict, student mode may be on).
        let run = match PRESETS.iter().find(|p| settings.matches(p)) {
            Some(p) if settings.a.repeat => format!("{}, the slew repeating", p.settings_title),
            Some(p) => p.settings_title.to_string(),
            None => crate::words::settings::run(&settings.a.config()),
        };
        let mut parts = vec![run];
        if settings.b.is_some() {
            parts.push("comparing two runs".into());
        }
        let pairs = split_query(&self.query);
        let value = |key: &str| pairs.iter().rev().find(|(k, _)| k == key).map(|(_, v)| v.as_str());
        if settings.start.paused {
            parts.push(format!("paused at t = {} s", significant_trimmed(settings.start.time, 4)));
        }
        let carried = self.lesson.as_ref().map(|l| (l, crate::lesson::parse(&l.text).ok()));
        let title = match &carried {
            Some((_, Some(parsed))) => format!("“{}”", parsed.title),
            Some((l, None)) => l.name.clone(),
            None => "the built-in lesson".into(),
        };
        match value("lesson") {
            Some(step) => parts.push(format!("{title}, step {step}")),
            None if self.lesson.is_some() => parts.push(format!("carries {title}")),
            None => {}
        }
        // Student mode: set by the state (`answers=hidden`) or by the lesson (`answers: hidden`).
        let by_lesson = matches!(&carried, Some((_, Some(parsed))) if parsed.answers_hidden);
        if settings.view.answers_hidden || by_lesson {
            parts.push("student mode".into());
        }
        parts.join("; ")
    }
}

/// `a&b`, either side possibly empty.
pub fn join(a: &str, b: &str) -> String {
    match (a.is_empty(), b.is_empty()) {
        (true, _) => b.to_string(),
        (_, true) => a.to_string(),
        _ => format!("{a}&{b}"),
    }
}

/// `text` as a JSON string, with `<`, `>`, `&` and the JavaScript line separators escaped (safe
/// inside an HTML `<script>`).
pub fn json_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '<' | '>' | '&' | '\u{2028}' | '\u{2029}' => hex_escape(&mut out, c),
            c if (c as u32) < 0x20 => hex_escape(&mut out, c),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// `\uXXXX` for a character of the Basic Multilingual Plane.
fn hex_escape(out: &mut String, c: char) {
    const HEX: &[u8; 16] = b"0123456789abcdef";
    out.push_str("\\u");
    for shift in [12, 8, 4, 0] {
        out.push(HEX[((c as u32 >> shift) & 15) as usize] as char);
    }
}

/// Standard base64 (RFC 4648, with padding): what the browser's `atob` reads.
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    crate::classroom::link::encode_base64(bytes, ALPHABET, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    #[test]
    fn json_cannot_end_the_script() {
        let s = json_string("a\"b\\c\n</script><!-- \u{2028}");
        assert!(!s.contains('<') && !s.contains('\n'));
        assert_eq!(s, "\"a\\\"b\\\\c\\n\\u003c/script\\u003e\\u003c!-- \\u2028\"");
    }
}
