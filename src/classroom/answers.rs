//! Answers to hand in: what a student did in a lesson — each prediction (the choice, right or
//! wrong) and each task (done, or shown by "Show me"), with the state string it was made in and
//! the time — as one record a teacher can collect. The page keeps it in the browser as the CSV it
//! downloads (localStorage, under the lesson's hash) and gives it back after a reload
//! ([`Record::from_csv`]); nothing is sent anywhere. Only the lesson's own data goes in: its title, a hash of its text, its steps'
//! titles and choices, the state strings and the times.

use serde::Serialize;

use crate::error::Error;
use crate::lesson::Lesson;

/// One thing the student did.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The step, from 1.
    pub step: usize,
    pub step_title: String,
    /// "prediction", "task" or "answers shown" (student mode lifted by the student).
    pub kind: String,
    /// The choice, from 1 (predictions only).
    pub choice: Option<usize>,
    /// The choice's text (predictions only).
    pub choice_text: String,
    /// "right" or "wrong" (a prediction), "done" or "shown" (a task; "shown": by "Show me"),
    /// "skipped" (left with *Next ▸* before the answer).
    pub result: String,
    /// The settings it was made in (the page's state string).
    pub state: String,
    /// When, ISO 8601 UTC ("" if the page gave no clock).
    pub time: String,
}

/// Everything the student did in one lesson.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The lesson's title.
    pub lesson: String,
    /// A hash of the lesson's text ([`text_hash`]): the answers belong to exactly this text.
    pub lesson_hash: String,
    /// The lesson's number of steps.
    pub steps: usize,
    pub entries: Vec<Entry>,
    /// Who answered, as the student wrote it ("" if not given).
    pub student: String,
}

/// The record as the lesson panel shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AnswersStatus {
    /// "Your predictions: 5 of 7 right. Tasks: 3 of 4 done yourself, 1 shown."
    pub headline: String,
    /// One line per entry, in order.
    pub rows: Vec<AnswerRow>,
    /// The number of entries (the page saves the record when it changes).
    pub count: usize,
    pub lesson_hash: String,
}

/// One entry in words.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AnswerRow {
    /// "Step 3, prediction: “It grows” — right".
    pub text: String,
    /// "right", "wrong", "done", "shown" or "skipped".
    pub result: String,
    /// The state string it was made in.
    pub state: String,
    pub time: String,
}

/// An entry's kind and result when *Next ▸* left a step without its answer or task.
pub const SKIPPED: &str = "skipped";

/// The line that names the student, and the last line, the check over the name and the rows.
pub const STUDENT_PREFIX: &str = "# student: ";
pub const CHECK_PREFIX: &str = "# check: ";

/// What the check line of an answers file says of it ([`check_csv`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Check {
    /// The name and the rows are as the page wrote them.
    Intact,
    /// No check line: cut short, or not written by the page.
    Missing,
    /// A row or the name differs from what the page wrote: edited by hand.
    Edited,
}

/// The check of an answers file's text. It is a hash (FNV-1a, [`text_hash`]), not a signature:
/// it detects a row or the name edited by hand in the file, and a file cut short; it cannot
/// detect a student who computes it again for rows of their own making — the page's code, which
/// every student has, computes it.
pub fn check_csv(text: &str) -> Check {
    let text = text.replace("\r\n", "\n");
    let Some(first_end) = text.find('\n') else { return Check::Missing };
    let rest = &text[first_end + 1..];
    let Some(at) = rest.rfind(CHECK_PREFIX) else { return Check::Missing };
    let (body, line) = rest.split_at(at);
    let claimed = line[CHECK_PREFIX.len()..].trim();
    if (at == 0 || body.ends_with('\n')) && claimed == text_hash(body) {
        Check::Intact
    } else {
        Check::Edited
    }
}

/// The longest name a student can give, characters.
pub const MAX_STUDENT: usize = 80;

/// A student's name as the answers carry it: on one line, trimmed, at most [`MAX_STUDENT`]
/// characters; an error with the reason otherwise.
pub fn student_name(text: &str) -> Result<String, Error> {
    let name = text.split_whitespace().collect::<Vec<_>>().join(" ");
    if name.chars().count() > MAX_STUDENT {
        return Err(Error::Parse(crate::error::ParseError {
            key: "name".into(),
            text: name.chars().take(20).collect::<String>() + "…",
            expected: format!("a name (and student id) of at most {MAX_STUDENT} characters"),
        }));
    }
    Ok(name)
}

/// The CSV columns, in order.
pub const CSV_COLUMNS: [&str; 10] =
    ["lesson", "lesson_hash", "step", "step_title", "kind", "choice", "choice_text", "result", "state", "time"];

/// A hash of a lesson's text: FNV-1a, 64 bits, written `fnv1a64:` and 16 hex digits. Not a
/// security measure: it tells which text the answers were given to (a changed lesson, a new hash).
pub fn text_hash(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("fnv1a64:{h:016x}")
}

/// Milliseconds since 1970 as ISO 8601 UTC to the second ("2026-11-26T05:03:00Z"); "" if not a
/// time the calendar below covers.
pub fn iso_time(ms: f64) -> String {
    if !(ms.is_finite() && (0.0..=253_402_300_799_000.0).contains(&ms)) {
        return String::new();
    }
    let secs = (ms / 1000.0).floor() as i64;
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    // Days since 1970-01-01 to the civil date (proleptic Gregorian), by 400-year eras.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z", rest / 3600, rest / 60 % 60, rest % 60)
}

impl Record {
    /// An empty record for a lesson whose text hashes to `lesson_hash`.
    pub fn new(lesson: &Lesson, lesson_hash: String) -> Self {
        Self {
            lesson: lesson.title.clone(),
            lesson_hash,
            steps: lesson.steps.len(),
            entries: Vec::new(),
            student: String::new(),
        }
    }

    /// A record kept earlier checked against the lesson open now: the same text (hash), steps
    /// and choices that exist. A record of another lesson, or of an older text, is refused.
    pub fn check(&self, lesson: &Lesson, lesson_hash: &str) -> Result<(), Error> {
        let refuse = |m: String| Err(Error::Lesson { line: 0, message: format!("the saved answers: {m}") });
        if self.lesson_hash != lesson_hash || self.steps != lesson.steps.len() {
            return refuse(format!("they were given to another text of the lesson ({})", self.lesson_hash));
        }
        for e in &self.entries {
            let Some(step) = e.step.checked_sub(1).and_then(|i| lesson.steps.get(i)) else {
                return refuse(format!("step {} does not exist", e.step));
            };
            let choices = step.question.as_ref().map_or(0, |q| q.choices.len());
            if e.choice.is_some_and(|c| c == 0 || c > choices) {
                return refuse(format!("step {} has no choice {:?}", e.step, e.choice));
            }
        }
        Ok(())
    }

    /// The record in words: how many predictions were right, how many tasks done, and each entry.
    pub fn status(&self, lesson: &Lesson) -> AnswersStatus {
        let questions = lesson.steps.iter().filter(|s| s.question.is_some()).count();
        let tasks = lesson.steps.iter().filter(|s| s.goal.is_some()).count();
        let count = |kind: &str, result: &str| {
            self.entries.iter().filter(|e| e.kind == kind && (result.is_empty() || e.result == result)).count()
        };
        let answered = count("prediction", "");
        let mut headline = format!("Your predictions: {} of {questions} right", count("prediction", "right"));
        if answered < questions {
            headline += &format!(" ({} not answered yet)", questions - answered);
        }
        headline += ".";
        if tasks > 0 {
            let shown = count("task", "shown");
            headline += &format!(" Tasks: {} of {tasks} done yourself", count("task", "done"));
            if shown > 0 {
                headline += &format!(", {shown} shown by “Show me”");
            }
            headline += ".";
        }
        if count("answers shown", "") > 0 {
            headline += " You showed the hidden answers.";
        }
        let skipped = count(SKIPPED, "");
        if skipped > 0 {
            let s = if skipped == 1 { "" } else { "s" };
            headline += &format!(" {skipped} step{s} left without an answer.");
        }
        let rows = self
            .entries
            .iter()
            .map(|e| AnswerRow {
                text: match e.kind.as_str() {
                    "prediction" => format!("Step {}, prediction: “{}” — {}", e.step, e.choice_text, e.result),
                    "task" if e.result == "shown" => format!("Step {}, task: shown by “Show me”", e.step),
                    "task" => format!("Step {}, task: done", e.step),
                    SKIPPED => format!("Step {}: left with Next, not answered", e.step),
                    _ => format!("Step {}: you showed the hidden answers", e.step),
                },
                result: e.result.clone(),
                state: e.state.clone(),
                time: e.time.clone(),
            })
            .collect();
        AnswersStatus { headline, rows, count: self.entries.len(), lesson_hash: self.lesson_hash.clone() }
    }

    /// The record as CSV: a `#` line naming the lesson and its hash, the header
    /// ([`CSV_COLUMNS`]), one row per entry. Text is quoted wherever it has to be.
    pub fn to_csv(&self) -> String {
        let mut out = format!(
            "# flexarm lesson answers: {} ({}, {} steps); state = the page's settings when it was answered, time in UTC\n",
            one_line(&self.lesson),
            self.lesson_hash,
            self.steps
        );
        let mut body = String::new();
        if !self.student.is_empty() {
            body += &format!("{STUDENT_PREFIX}{}\n", one_line(&self.student));
        }
        body += &CSV_COLUMNS.join(",");
        body.push('\n');
        for e in &self.entries {
            let cells = [
                quote(&self.lesson),
                quote(&self.lesson_hash),
                e.step.to_string(),
                quote(&e.step_title),
                quote(&e.kind),
                e.choice.map_or(String::new(), |c| c.to_string()),
                quote(&e.choice_text),
                quote(&e.result),
                quote(&e.state),
                quote(&e.time),
            ];
            body += &cells.join(",");
            body.push('\n');
        }
        // The check over everything after the first line: the name, the header and every row.
        out += &format!("{body}{CHECK_PREFIX}{}\n", text_hash(&body));
        out
    }
}

impl Record {
    /// Reads back what [`Record::to_csv`] wrote (the page keeps that text): the rows' lesson, hash
    /// and entries. A row that does not read, or that names another lesson text than the others,
    /// is a mistake; the comment line is skipped.
    pub fn from_csv(text: &str, steps: usize) -> Result<Record, Error> {
        let bad = |line: usize, m: &str| Error::Lesson { line, message: format!("the saved answers: {m}") };
        let mut lines = text.lines().enumerate().filter(|(_, l)| !l.starts_with('#') && !l.trim().is_empty());
        match lines.next() {
            Some((_, header)) if header == CSV_COLUMNS.join(",") => {}
            _ => return Err(bad(1, "no header line of the answers' columns")),
        }
        let student = text.lines().find_map(|l| l.strip_prefix(STUDENT_PREFIX)).unwrap_or_default().to_string();
        let mut record =
            Record { lesson: String::new(), lesson_hash: String::new(), steps, entries: Vec::new(), student };
        for (i, line) in lines {
            let c = split_csv(line);
            let [lesson, hash, step, step_title, kind, choice, choice_text, result, state, time] =
                <[String; 10]>::try_from(c).map_err(|_| bad(i + 1, "a row has not 10 cells"))?;
            if record.entries.is_empty() {
                (record.lesson, record.lesson_hash) = (lesson, hash);
            } else if hash != record.lesson_hash {
                return Err(bad(i + 1, "rows of two lesson texts"));
            }
            let number = |t: &str| t.parse::<usize>().map_err(|_| bad(i + 1, "a step or choice is not a number"));
            let choice = if choice.is_empty() { None } else { Some(number(&choice)?) };
            record.entries.push(Entry {
                step: number(&step)?,
                step_title,
                kind,
                choice,
                choice_text,
                result,
                state,
                time,
            });
        }
        Ok(record)
    }
}

/// One CSV line's cells, quotes undone (what [`quote`] wrote).
pub fn split_csv(line: &str) -> Vec<String> {
    let (mut cells, mut cell, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                cell.push('"');
                chars.next();
            }
            '"' => quoted = !quoted,
            ',' if !quoted => cells.push(std::mem::take(&mut cell)),
            _ => cell.push(c),
        }
    }
    cells.push(cell);
    cells
}

/// A CSV cell on one line: quoted (quotes doubled) when it holds a comma or a quote; a line
/// break (none of the lesson's texts has one) becomes a space.
pub(super) fn quote(text: &str) -> String {
    let text = one_line(text);
    if text.contains([',', '"']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text
    }
}

/// Text on one line (for a `#` comment).
fn one_line(text: &str) -> String {
    text.replace(['\n', '\r'], " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_are_utc_calendar_dates() {
        assert_eq!(iso_time(0.0), "1970-01-01T00:00:00Z");
        // 2000-02-29 (a leap day in a century leap year) 12:34:56.
        assert_eq!(iso_time(951_827_696_000.0), "2000-02-29T12:34:56Z");
        assert_eq!(iso_time(1_795_669_380_000.0), "2026-11-26T05:03:00Z");
        assert_eq!(iso_time(f64::NAN), "");
        assert_eq!(iso_time(-1.0), "");
    }

    #[test]
    fn the_hash_is_fnv1a() {
        // The published FNV-1a 64 test vectors.
        assert_eq!(text_hash(""), "fnv1a64:cbf29ce484222325");
        assert_eq!(text_hash("a"), "fnv1a64:af63dc4c8601ec8c");
        assert_ne!(text_hash("# T\n"), text_hash("# T \n"));
    }

    #[test]
    fn cells_are_quoted_only_when_needed() {
        assert_eq!(quote("plain"), "plain");
        assert_eq!(quote("a, b"), "\"a, b\"");
        assert_eq!(quote("say \"hi\""), "\"say \"\"hi\"\"\"");
    }
}
