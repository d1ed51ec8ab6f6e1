//! The teacher's side of the answers (issue 35): many students' answer files
//! ([`super::answers::Record::to_csv`]) merged into one table — per step, how many answered, the
//! share right at the first try, the wrong choices most made; tasks done or shown — and one row
//! per student (right at the first try, tasks, skips), with every file that cannot count named
//! and why: unreadable, of another lesson text, without its check line, or edited by hand
//! ([`super::answers::check_csv`]).

use super::answers::{check_csv, Check, Record};
use crate::plot::format::significant;

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
    /// One row per file that counted, by name (the page gets them in words: `student_words`).
    #[serde(skip)]
    pub students: Vec<StudentScore>,
}

/// Merges the files: the lesson text most of the readable files answer is the class's; files
/// of another text, unreadable, or failing their check are named and left out.
pub fn merge(files: &[AnswerFile]) -> ClassTable {
    let mut class = ClassTable::default();
    let mut records: Vec<(&AnswerFile, Record)> = Vec::new();
    for f in files {
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
    for (f, r) in &records {
        if r.lesson_hash != class.lesson_hash {
            class.refused.push((f.name.clone(), format!("answers another text of the lesson ({})", r.lesson_hash)));
            continue;
        }
        class.lesson.clone_from(&r.lesson);
        class.counted.push((f.name.clone(), r.student.clone()));
        let name = if r.student.trim().is_empty() { f.name.clone() } else { r.student.clone() };
        class.students.push(StudentScore { name, file: f.name.clone(), ..tally(&mut class.steps, r) });
    }
    class.steps.sort_by_key(|s| s.step);
    class.students.sort_by_key(|s| s.name.to_lowercase());
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
                if e.result == "right" {
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
            }
        }
    }
    for (step, result) in tasks {
        if let Some(s) = steps.iter_mut().find(|s| s.step == step) {
            match result {
                "done" => (s.done, score.done) = (s.done + 1, score.done + 1),
                "shown" => (s.shown, score.shown) = (s.shown + 1, score.shown + 1),
                _ => {}
            }
        }
    }
    score
}

impl ClassTable {
    /// The table as CSV: a `#` line naming the lesson, how many files counted and which did not,
    /// then one row per step.
    pub fn to_csv(&self) -> String {
        let mut out = format!(
            "# flexarm class answers: {} ({}), {} files counted, {} not\n",
            self.lesson,
            self.lesson_hash,
            self.counted.len(),
            self.refused.len()
        );
        for (name, why) in &self.refused {
            out += &format!("# not counted: {name}: {why}\n");
        }
        out += "step,step_title,predicted,right,share_right,wrong_choices,task_done,task_shown,skipped\n";
        for s in &self.steps {
            let share =
                if s.predicted > 0 { significant(s.right as f64 / s.predicted as f64, 2) } else { String::new() };
            let wrong: Vec<String> = s.wrong.iter().map(|(t, n)| format!("“{t}” ×{n}")).collect();
            out += &format!(
                "{},{},{},{},{},{},{},{},{}\n",
                s.step,
                super::answers::quote(&s.title),
                s.predicted,
                s.right,
                share,
                super::answers::quote(&wrong.join("; ")),
                s.done,
                s.shown,
                s.skipped
            );
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
        [right, wrong.join("; "), tasks.join("; ")]
    }

    /// One row per student as CSV: the name and file, questions answered and right at the first
    /// try, tasks done and shown, steps skipped.
    pub fn students_csv(&self) -> String {
        let mut out = String::from("student,file,predicted,right,share_right,task_done,task_shown,skipped\n");
        for s in &self.students {
            let share =
                if s.predicted > 0 { significant(s.right as f64 / s.predicted as f64, 2) } else { String::new() };
            out += &format!(
                "{},{},{},{},{},{},{},{}\n",
                super::answers::quote(&s.name),
                super::answers::quote(&s.file),
                s.predicted,
                s.right,
                share,
                s.done,
                s.shown,
                s.skipped
            );
        }
        out
    }

    /// One student's row in words, as the page's table shows it: the name, the file, right at
    /// the first try ("3 of 4"), and the tasks ("1 done; 1 skipped").
    pub fn student_words(s: &StudentScore) -> [String; 4] {
        let right = if s.predicted > 0 { format!("{} of {}", s.right, s.predicted) } else { "—".into() };
        let mut tasks = Vec::new();
        if s.done + s.shown > 0 {
            tasks.push(format!("{} done, {} shown", s.done, s.shown));
        }
        if s.skipped > 0 {
            tasks.push(format!("{} skipped", s.skipped));
        }
        [s.name.clone(), s.file.clone(), right, tasks.join("; ")]
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
