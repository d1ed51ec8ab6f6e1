//! `flexarm answers merge`: the teacher's side of the answers (issue 35) — the answer files of a
//! class merged into one table per step, every file that cannot count named with its reason
//! ([`flexarm::classroom::class`]).

use clap::{ArgMatches, Command};
use flexarm::classroom::answers::text_hash;
use flexarm::classroom::class::{merge, AnswerFile};
use flexarm::lesson::parse;

use crate::cli::{self, option, usage_error, Res};

pub fn command() -> Command {
    cli::command("answers", "The answers students hand in: merge a class's files into one table")
        .subcommand_required(true)
        .subcommand(
            cli::command(
                "merge",
                "Merge answer files (the CSV the page downloads) into one table per step: how many answered, the \
                 share right at the first try, the wrong choices most made, tasks done or shown; files that fail \
                 their check (edited by hand, cut short) or answer another lesson text are named and left out",
            )
            .arg(
                clap::Arg::new("files").value_name("FILES").num_args(1..).required(true).help("The answer files (CSV)"),
            )
            .arg(option("out", "FILE.csv", "Where to write the class's table (default: print it)"))
            .arg(option(
                "lesson",
                "FILE.md",
                "The lesson the files answer: every step with a question or a task is a row, even one nobody reached \
                 (used where its text is the one the files answer)",
            ))
            .arg(option(
                "students",
                "FILE.csv",
                "Also write one row per student: questions right at the first try, tasks done or shown, steps skipped",
            )),
        )
}

pub fn run(m: &ArgMatches) -> Res<String> {
    let Some(("merge", m)) = m.subcommand() else {
        return Err(usage_error(
            "use: flexarm answers merge FILES… [--lesson LESSON.md] [--out class.csv] [--students students.csv]",
        ));
    };
    let mut files = Vec::new();
    for path in m.get_many::<String>("files").into_iter().flatten() {
        let text = std::fs::read_to_string(path).map_err(|e| usage_error(format!("could not read '{path}': {e}")))?;
        files.push(AnswerFile { name: path.clone(), text });
    }
    let lesson = match m.get_one::<String>("lesson") {
        Some(path) => {
            let text =
                std::fs::read_to_string(path).map_err(|e| usage_error(format!("could not read '{path}': {e}")))?;
            let parsed = parse(&text).map_err(|e| usage_error(format!("--lesson {path}: {e}")))?;
            Some((parsed, text_hash(&text)))
        }
        None => None,
    };
    let class = merge(&files, lesson.as_ref().map(|(l, h)| (l, h.as_str())));
    if let Some((_, hash)) = &lesson {
        if !class.lesson_hash.is_empty() && *hash != class.lesson_hash {
            return Err(usage_error(format!(
                "--lesson: the files answer another text of the lesson ({}, the file's is {hash})",
                class.lesson_hash
            )));
        }
    }
    let table = class.to_csv();
    let mut said = String::new();
    if let Some(path) = m.get_one::<String>("students") {
        cli::write_file("--students", path, &class.students_csv())?;
        said = format!("wrote one row per student ({}) to {path}\n", class.students.len());
    }
    match m.get_one::<String>("out") {
        Some(out) => {
            cli::write_file("--out", out, &table)?;
            Ok(format!("{}wrote the table to {out}\n{said}", class.summary()))
        }
        None => Ok(format!("{table}\n{}{said}", class.summary())),
    }
}
