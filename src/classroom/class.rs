//! The teacher's side of the answers (issue 35): many students' answer files
//! ([`super::answers::Record::to_csv`]) merged into one table — per step, how many answered, the
//! share right at the first try, the wrong choices most made; tasks done or shown — and one row
//! per student (right at the first try, tasks, skips), with every file that cannot count named
//! and why: unreadable, of another lesson text, without its check line, or edited by hand
//! ([`super::answers::check_csv`]).

use super::answers::{check_csv, Check, Record};
use crate::lesson::Lesson;

/// One answers file: its name and text.
#[derive(Clone, Debug)]
pub struct AnswerFile {
    pub name: String,
    pub text: String,
}

/// One step of the lesson, over the class.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct StepTally {
    pub step: usize,
    pub title: String,
    /// Students who made a prediction here, and of those, right at their first try.
    pub predicted: usize,
    pub right: usize,
    /// The wrong first choices, by text, most made first.
    pub wrong: Vec<(String, usize)>,
    /// Students who did the task themselves, and who had it shown.
    pub done: usize,
    pub shown: usize,
    /// Students who left the step with *Next ▸* and never answered it.
    pub skipped: usize,
    /// Students who counted and left no mark here: not reached, or left unanswered.
    pub unanswered: usize,
}

/// How one student left one step: a question right or wrong at the first try, a task done or
/// shown, or the step skipped with *Next ▸*.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    Right,
    Wrong,
    Done,
    Shown,
    Skipped,
}

impl Mark {
    /// The cell in the page's table: ✓, ✗, done, shown, skipped.
    pub fn symbol(self) -> &'static str {
        match self {
            Mark::Right => "✓",
            Mark::Wrong => "✗",
            Mark::Done => "done",
            Mark::Shown => "shown",
            Mark::Skipped => "skipped",
        }
    }

    /// The cell in the students' CSV: right, wrong, done, shown, skipped.
    pub fn name(self) -> &'static str {
        match self {
            Mark::Right => "right",
            Mark::Wrong => "wrong",
            Mark::Done => "done",
            Mark::Shown => "shown",
            Mark::Skipped => "skipped",
        }
    }
}

/// One student over the lesson, from their file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StudentScore {
    /// The name the file gives, else the file's name.
    pub name: String,
    pub file: String,
    /// Questions answered, and of those right at the first try.
    pub predicted: usize,
    pub right: usize,
    /// Tasks done, and shown; steps left unanswered with *Next ▸*.
    pub done: usize,
    pub shown: usize,
    pub skipped: usize,
    /// Each step they left a mark on, in the lesson's order (a step without one: not reached, or
    /// left unanswered).
    pub marks: Vec<(usize, Mark)>,
}

/// The merged class.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct ClassTable {
    pub lesson: String,
    pub lesson_hash: String,
    /// The files that counted, with the name each gives (or "").
    pub counted: Vec<(String, String)>,
    /// The files that did not, and why.
    pub refused: Vec<(String, String)>,
    pub steps: Vec<StepTally>,
    /// One row per file that counted, by name (the page gets them in words: `student_row`).
    #[serde(skip)]
    pub students: Vec<StudentScore>,
    /// The questions of the lesson (else those anyone answered): each student's score is out of them.
    pub questions: usize,
}

/// The time of a record's last entry (ISO 8601: compared as text), "" for none.
fn last_time(r: &Record) -> &str {
    r.entries.iter().map(|e| e.time.as_str()).max().unwrap_or("")
}

/// Merges the files: the lesson text most of the readable files answer is the class's; files
/// of another text, unreadable, or failing their check are named and left out, and of two files
/// under one student's name the later counts (a redo). `lesson`, the lesson and its text's hash
/// (the teacher's open lesson, `--lesson`): where it is the class's, every step with a question
/// or a task is a row, even one nobody reached.
pub fn merge(files: &[AnswerFile], lesson: Option<(&Lesson, &str)>) -> ClassTable {
    let mut class = ClassTable::default();
    let mut records: Vec<(&AnswerFile, Record)> = Vec::new();
    for (i, f) in files.iter().enumerate() {
        // The same file given twice (a copy under another name) counts once.
        if let Some(first) = files[..i].iter().find(|g| g.text == f.text) {
            class.refused.push((f.name.clone(), format!("the same file as {}", first.name)));
            continue;
        }
        match Record::from_csv(&f.text, 0) {
            Err(e) => class.refused.push((f.name.clone(), format!("not an answers file: {e}"))),
            Ok(r) if r.entries.is_empty() => class.refused.push((f.name.clone(), "no answers in it".into())),
            Ok(r) => match check_csv(&f.text) {
                Check::Intact => records.push((f, r)),
                Check::Missing => {
                    class.refused.push((f.name.clone(), "no check line: cut short, or not written by the page".into()))
                }
                Check::Edited => class
                    .refused
                    .push((f.name.clone(), "its check does not match: a row or the name was edited".into())),
            },
        }
    }
    // The class's lesson text: the one most files answer.
    let mut hashes: Vec<(&str, usize)> = Vec::new();
    for (_, r) in &records {
        match hashes.iter_mut().find(|(h, _)| *h == r.lesson_hash) {
            Some((_, n)) => *n += 1,
            None => hashes.push((&r.lesson_hash, 1)),
        }
    }
    let Some(&(hash, _)) = hashes.iter().max_by_key(|(_, n)| *n) else { return class };
    class.lesson_hash = hash.to_string();
    let mut kept: Vec<(&AnswerFile, &Record)> = Vec::new();
    for (f, r) in &records {
        if r.lesson_hash != class.lesson_hash {
            class.refused.push((f.name.clone(), format!("answers another text of the lesson ({})", r.lesson_hash)));
            continue;
        }
        // One file per student: of two under one name, the later (its last answer's time) counts.
        let named = r.student.trim().to_lowercase();
        let same = kept.iter().position(|(_, k)| !named.is_empty() && k.student.trim().to_lowercase() == named);
        match same {
            Some(at) => {
                let other = kept[at];
                let (later, earlier) =
                    if last_time(r) >= last_time(other.1) { ((*f, r), other) } else { (other, (*f, r)) };
                let why =
                    format!("an earlier file from {} (also {}): the later counts", r.student.trim(), later.0.name);
                class.refused.push((earlier.0.name.clone(), why));
                kept[at] = later;
            }
            None => kept.push((f, r)),
        }
    }
    // The lesson's steps with a question or a task, where the teacher's lesson is the class's.
    let lesson = lesson.filter(|(_, h)| *h == class.lesson_hash).map(|(l, _)| l);
    for (i, step) in lesson.iter().flat_map(|l| l.steps.iter().enumerate()) {
        if step.question.is_some() || step.goal.is_some() {
            class.steps.push(StepTally { step: i + 1, title: step.title.clone(), ..StepTally::default() });
        }
    }
    for (f, r) in kept {
        class.lesson.clone_from(&r.lesson);
        class.counted.push((f.name.clone(), r.student.clone()));
        let name = if r.student.trim().is_empty() { f.name.clone() } else { r.student.clone() };
        class.students.push(StudentScore { name, file: f.name.clone(), ..tally(&mut class.steps, r) });
    }
    class.steps.sort_by_key(|s| s.step);
    class.students.sort_by_key(|s| s.name.to_lowercase());
    for step in &mut class.steps {
        let marked = class.students.iter().filter(|s| s.marks.iter().any(|(n, _)| *n == step.step)).count();
        step.unanswered = class.students.len() - marked;
    }
    // The questions the class was asked: the lesson's, else those anyone answered.
    class.questions = match lesson {
        Some(l) => l.steps.iter().filter(|s| s.question.is_some()).count(),
        None => class.steps.iter().filter(|s| s.predicted > 0).count(),
    };
    for s in &mut class.steps {
        s.wrong.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    }
    class
}

/// Adds one student's record: the first prediction per step, the last task result per step.
/// Returns the student's own counts (without their name).
fn tally(steps: &mut Vec<StepTally>, r: &Record) -> StudentScore {
    let mut score = StudentScore::default();
    let mut predicted: Vec<usize> = Vec::new();
    let mut tasks: Vec<(usize, &str)> = Vec::new();
    let mut skipped: Vec<usize> = Vec::new();
    for e in &r.entries {
        let at = match steps.iter().position(|s| s.step == e.step) {
            Some(i) => i,
            None => {
                steps.push(StepTally { step: e.step, title: e.step_title.clone(), ..StepTally::default() });
                steps.len() - 1
            }
        };
        let s = &mut steps[at];
        match e.kind.as_str() {
            "prediction" if !predicted.contains(&e.step) => {
                predicted.push(e.step);
                s.predicted += 1;
                score.predicted += 1;
                let right = e.result == "right";
                score.marks.push((e.step, if right { Mark::Right } else { Mark::Wrong }));
                if right {
                    s.right += 1;
                    score.right += 1;
                } else {
                    match s.wrong.iter_mut().find(|(t, _)| *t == e.choice_text) {
                        Some((_, n)) => *n += 1,
                        None => s.wrong.push((e.choice_text.clone(), 1)),
                    }
                }
            }
            "task" => match tasks.iter_mut().find(|(step, _)| *step == e.step) {
                Some((_, result)) => *result = &e.result,
                None => tasks.push((e.step, &e.result)),
            },
            super::answers::SKIPPED if !skipped.contains(&e.step) => skipped.push(e.step),
            _ => {}
        }
    }
    // Skipped and never answered later (a student may come back to the step).
    for step in skipped {
        if !predicted.contains(&step) && !tasks.iter().any(|(s, _)| *s == step) {
            if let Some(s) = steps.iter_mut().find(|s| s.step == step) {
                s.skipped += 1;
                score.skipped += 1;
                score.marks.push((step, Mark::Skipped));
            }
        }
    }
    for (step, result) in tasks {
        if let Some(s) = steps.iter_mut().find(|s| s.step == step) {
            match result {
                "done" => {
                    (s.done, score.done) = (s.done + 1, score.done + 1);
                    score.marks.push((step, Mark::Done));
                }
                "shown" => {
                    (s.shown, score.shown) = (s.shown + 1, score.shown + 1);
                    score.marks.push((step, Mark::Shown));
                }
                _ => {}
            }
        }
    }
    score.marks.sort_by_key(|(step, _)| *step);
    score
}

impl ClassTable {
    /// The table as CSV: one row per step, then a `#` line naming the lesson and how many files
    /// counted, and one per file that did not (each line one cell).
    pub fn to_csv(&self) -> String {
        let mut out = format!(
            "{UTF8_BOM}step,step_title,predicted,right,share_right,wrong_choices,task_done,task_shown,skipped,unanswered\n"
        );
        for s in &self.steps {
            let share = share(s.right, s.predicted);
            let wrong: Vec<String> = s.wrong.iter().map(|(t, n)| format!("“{t}” ×{n}")).collect();
            out += &format!(
                "{},{},{},{},{},{},{},{},{},{}\n",
                s.step,
                super::answers::quote(&s.title),
                s.predicted,
                s.right,
                share,
                super::answers::quote(&wrong.join("; ")),
                s.done,
                s.shown,
                s.skipped,
                s.unanswered
            );
        }
        // What the table is and which files it left out, after it and one cell a line: a
        // spreadsheet then finds the columns' names on its first row.
        let about = format!(
            "# flexarm class answers: {} ({}), {} files counted, {} not",
            self.lesson,
            self.lesson_hash,
            self.counted.len(),
            self.refused.len()
        );
        out += &format!("{}\n", super::answers::quote(&about));
        for (name, why) in &self.refused {
            out += &format!("{}\n", super::answers::quote(&format!("# not counted: {name}: {why}")));
        }
        out
    }

    /// One step's row in words, as the page's table shows it: the share right ("47 of 57, 82 %"),
    /// the wrong choices most made, the tasks.
    pub fn row_words(s: &StepTally) -> [String; 3] {
        let right = if s.predicted > 0 {
            // A no-break space: "68 %" stays on one line in a narrow table.
            format!("{} of {}, {:.0}\u{a0}%", s.right, s.predicted, 100.0 * s.right as f64 / s.predicted as f64)
        } else {
            String::new()
        };
        let wrong: Vec<String> = s.wrong.iter().take(3).map(|(t, n)| format!("“{t}” ×{n}")).collect();
        let mut tasks = Vec::new();
        if s.done + s.shown > 0 {
            tasks.push(format!("{} done, {} shown", s.done, s.shown));
        }
        if s.skipped > 0 {
            tasks.push(format!("{} skipped", s.skipped));
        }
        if s.unanswered > 0 {
            tasks.push(format!("{} no answer", s.unanswered));
        }
        [right, wrong.join("; "), tasks.join("; ")]
    }

    /// One row per student as CSV: the name and file, questions answered and right at the first
    /// try, tasks done and shown, steps skipped, then each step's mark (`step_3`: right, wrong,
    /// done, shown, skipped, or empty: no answer); then each file that did not count, with why.
    pub fn students_csv(&self) -> String {
        let mut out = format!("{UTF8_BOM}student,file,predicted,right,share_right,task_done,task_shown,skipped,note");
        for s in &self.steps {
            out += &format!(",step_{}", s.step);
        }
        out.push('\n');
        for s in &self.students {
            out += &format!(
                "{},{},{},{},{},{},{},{},{}",
                super::answers::quote(&s.name),
                super::answers::quote(&s.file),
                s.predicted,
                s.right,
                share(s.right, self.questions),
                s.done,
                s.shown,
                s.skipped,
                super::answers::quote(&self.missing_note(s))
            );
            for step in &self.steps {
                out.push(',');
                out += s.marks.iter().find(|(n, _)| *n == step.step).map_or("", |(_, m)| m.name());
            }
            out.push('\n');
        }
        // The files that did not count: no student's name (a count of names is the class's).
        for (file, why) in &self.refused {
            let note = super::answers::quote(&format!("not counted: {why}"));
            out += &format!(",{},,,,,,,{note}{}\n", super::answers::quote(file), ",".repeat(self.steps.len()));
        }
        out
    }

    /// The steps a student left without a mark ("no answer on steps 3, 4"), "" for none.
    pub fn missing_note(&self, s: &StudentScore) -> String {
        let missing: Vec<String> = self
            .steps
            .iter()
            .filter(|t| !s.marks.iter().any(|(n, _)| *n == t.step))
            .map(|t| t.step.to_string())
            .collect();
        match missing.len() {
            0 => String::new(),
            1 => format!("no answer on step {}", missing[0]),
            _ => format!("no answer on steps {}", missing.join(", ")),
        }
    }

    /// A student's mark on each of the class's steps, as the page's table shows it (— where none).
    pub fn student_cells(&self, s: &StudentScore) -> Vec<String> {
        let mark = |step: usize| s.marks.iter().find(|(n, _)| *n == step).map_or("—", |(_, m)| m.symbol());
        self.steps.iter().map(|t| mark(t.step).to_string()).collect()
    }

    /// One student's row as the page's table shows it: the name, the file, right at the first
    /// try ("3 of 4", "—" for no question answered), then their mark on each step.
    pub fn student_row(&self, s: &StudentScore) -> Vec<String> {
        let right = if self.questions > 0 { format!("{} of {}", s.right, self.questions) } else { "—".into() };
        let mut row = vec![s.name.clone(), s.file.clone(), right];
        row.extend(self.student_cells(s));
        row
    }

    /// In words, for the command line: the lesson, the counts, the files left out and why.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "{}: {} answer files counted, {} not.\n",
            if self.lesson.is_empty() { "no lesson" } else { &self.lesson },
            self.counted.len(),
            self.refused.len()
        );
        for (name, why) in &self.refused {
            s += &format!("  not counted: {name}: {why}\n");
        }
        s
    }
}

/// The byte-order mark the teacher's tables begin with: a spreadsheet (Excel on Windows) then
/// reads them as UTF-8 — δ, ×, “ ” and the students' names — rather than in its local code page.
/// (Nothing reads these tables back; the students' answer files have none.)
const UTF8_BOM: char = '\u{feff}';

/// A share as a fraction with two decimals ("0.67", "1.00"), empty for none answered.
fn share(right: usize, of: usize) -> String {
    if of > 0 {
        format!("{:.2}", right as f64 / of as f64)
    } else {
        String::new()
    }
}
